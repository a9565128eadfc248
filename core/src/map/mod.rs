//! The grid map every component shares (spec §2), its obstacle distances, and the map file
//! formats.

mod error;
pub use error::MapError;

mod clearance;
mod distance;
mod escape;
pub mod formats;
mod grid_map;
mod map_update;
mod neighbours;

pub use clearance::{ClearanceTracker, clearance, clearance_lower_bound, could_be_below};
pub use distance::euclidean_distance_squared;
pub(crate) use distance::to_metres;
pub use escape::escape_route;
pub use grid_map::{
    Cell, DMIN_TOLERANCE, GridMap, MAX_CELLS, MAX_COORDINATE, MAX_GRID_SIZE, MIN_GRID_SIZE,
    within_dmin,
};
pub(crate) use grid_map::{CellRect, MapStamp};
pub use map_update::MapUpdate;
pub use neighbours::{NEIGHBOURS, ORTHOGONAL_FIRST};
