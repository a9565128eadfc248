//! # rtnav
//!
//! The deterministic core of a Rust rebuild of the OpenINVENT mobile-robot navigation
//! RT-components: grid maps, the global and local (potential-field) planners, the motor
//! controller, the differential-drive physics, the OpenRTM-style component lifecycle, the
//! whole system and its renderer. It knows nothing of the browser: `rtnav-wasm` wraps it.
//!
//! The specification is `docs/spec.md` in the repository: §0–§6 describe the system and the
//! project's decisions, its second part the three seed documents section by section. Doc
//! comments cite both (`spec §3`, older ones `spec §3`: the same section; `000 §5.2.4.9`).
//!
//! Real maps nobody on the project wrote (the MovingAI benchmark, ROS maps) are external
//! data, found at run time ([`data`]: `$RTNAV_DATA`, else `../shared/data`).
#![warn(missing_docs)]

pub mod components;
pub mod data;
pub mod errors;
pub mod global;
pub mod interfaces;
pub mod local;
pub mod map;
pub mod motion;
pub mod present;
pub mod reason;
#[cfg(feature = "render")]
pub mod render;
pub mod rtc;
pub mod system;

pub use errors::{Error, ErrorDetail, Result};
pub use reason::Reason;
