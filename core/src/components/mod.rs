//! The RT-components, one per file, named as in the seeds (SPEC §0).

// --- maps: GlobalPathPlanning ---
mod global_path_planning;
pub use global_path_planning::{GlobalPathPlanning, GlobalPathPlanningParams};
