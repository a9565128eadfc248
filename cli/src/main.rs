//! `rtnav`: the headless runner.
fn main() {}
