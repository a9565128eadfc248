//! Global path planning: A* on the 8-connected grid (spec §5 "GlobalPathPlanning").
//!
//! [`AStar`] is the planner for one map and `dmin`: cells whose obstacle distance exceeds
//! `dmin` may be entered, and it finds the optimal path between two cells with exact octile
//! costs ([`OctileCost`]) and no corner cutting. The RT-component around them is
//! [`GlobalPathPlanning`](crate::components::GlobalPathPlanning).

mod error;
pub use error::GlobalPlanningError;

mod astar;
mod cost;
mod heap;

pub use astar::{AStar, GridPlan};
pub use cost::OctileCost;
