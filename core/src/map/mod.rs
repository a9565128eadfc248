//! The grid map every component shares (SPEC §2) and its obstacle distances.

mod distance;
mod grid_map;

pub use distance::euclidean_distance_squared;
pub use grid_map::{Cell, GridMap, MAX_CELLS};
