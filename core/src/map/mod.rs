//! The grid map every component shares (SPEC §2), its obstacle distances, and the map file
//! formats.

mod distance;
pub mod formats;
mod grid_map;

pub use distance::euclidean_distance_squared;
pub use grid_map::{Cell, GridMap, MAX_CELLS};
