//! The RT-components, one per file, named as in the seeds (SPEC §0).

// Demo component for the browser page until the robot system exists (tooling issue).
pub mod heartbeat;
pub use heartbeat::{Heartbeat, HeartbeatParams};
