//! The reliability tools (`rtnav-stress fuzz`, `rtnav-stress soak`), a crate of their own so
//! that the `rtnav` runner carries neither their counting allocator nor the dependencies only
//! the fuzzer needs (its PNG encoder and decoder, the share links' base64 and deflate).
//!
//! - [`alloc`]: a counting allocator (a binary installs it) for allocation bounds and memory;
//! - [`rng`]: the tools' seeded random numbers (the core reads none);
//! - [`fuzz`]: the fuzzer — one target per reader and per kind of hostile call;
//! - [`soak`]: hours of simulated closed loop with random goals and map edits.
//!
//! The external data (`../shared/data`, or `$RTNAV_DATA`) is found by `rtnav::data`.

pub mod alloc;
pub mod fuzz;
pub mod rng;
pub mod soak;
