//! The grid map every component shares (SPEC §2), its obstacle distances, and the map file
//! formats.

mod distance;
pub mod formats;
mod grid_map;

pub use distance::euclidean_distance_squared;
pub(crate) use distance::to_metres;
pub(crate) use grid_map::MapStamp;
pub use grid_map::{Cell, DMIN_TOLERANCE, GridMap, MAX_CELLS, within_dmin};
