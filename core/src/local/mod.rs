//! Local path planning algorithms of seed 000: local target, potential field, descent,
//! merge, control points (spec §3 steps 3–7). The RT-component that decides when to use
//! them is [`crate::components::LocalPathPlanning`].
//!
//! Architecture invariant: nothing here knows about ports, ticks or flags; every function
//! takes the map and plain values and returns a value or a [`crate::errors::LocalPathError`].

pub mod angle;
mod error;
pub use error::LocalPathError;

mod checks;
mod control_points;
mod escape;
mod field_queue;
mod field_word;
mod local_path;
mod local_target;
mod merge;
mod planner;
mod potential_field;
mod radix_queue;
pub mod reference;

pub use checks::{clear_cell, course_cells};
pub use control_points::{control_points, corner_cells, thin_collinear};
pub use escape::EscapeLead;
pub use local_path::descend;
pub use local_target::{
    LocalTarget, find_local_target, nearest_path_index, step_length, wrap_angle,
};
pub use merge::merge_paths;
pub use planner::{LocalPlan, LocalPlanner, PlanParams, PlanRequest, Progress};
pub use potential_field::{
    CellInfo, CellState, FieldCell, FieldExtent, FieldRequest, PotentialField, TARGET_POTENTIAL,
};
