//! The `rtnav` runner's library: the reliability tools behind `rtnav fuzz` and `rtnav soak`
//! (issue 18), kept apart from the binary so that tests can drive them.
//!
//! - [`alloc`]: a counting allocator (a binary installs it) for allocation bounds and memory;
//! - [`rng`]: the tools' seeded random numbers (the core reads none);
//! - [`fuzz`]: the fuzzer — one target per reader and per kind of hostile call;
//! - [`soak`]: hours of simulated closed loop with random goals and map edits;
//! - [`data`]: where the project's fixtures and the shared data are.

pub mod alloc;
pub mod data;
pub mod fuzz;
pub mod rng;
pub mod soak;
