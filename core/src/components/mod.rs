//! The RT-components, one per file, named as in the seeds (SPEC §0).

// --- LocalPathPlanning (branch `local`) ---
pub mod local_path_planning;
pub use local_path_planning::{LocalPathFlags, LocalPathPlanning, LocalPathPlanningParams};
