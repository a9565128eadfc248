//! # rtnav
//!
//! The deterministic core of a Rust rebuild of the OpenINVENT mobile-robot navigation
//! RT-components: grid maps, the global and local (potential-field) planners, the motor
//! controller, the differential-drive physics, the OpenRTM-style component lifecycle, the
//! whole system and its renderer. It knows nothing of the browser: `rtnav-wasm` wraps it.
//!
//! The working specification is `SPEC.md` (in the project's shared folder); doc comments
//! cite its sections and the seed documents' sections (e.g. `000 §5.2.4.9`).
#![warn(missing_docs)]

pub mod components;
pub mod errors;
pub mod global;
pub mod interfaces;
pub mod local;
pub mod map;
pub mod motion;
#[cfg(feature = "render")]
pub mod render;
pub mod rtc;
pub mod system;

pub use errors::{Error, Result};
