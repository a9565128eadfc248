//! `cargo xtask`: the steps cargo alone cannot do.
fn main() {}
