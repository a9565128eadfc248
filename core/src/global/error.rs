//! Errors of the global planner (spec §5 "GlobalPathPlanning"). Positions are said in
//! metres with the cell in parentheses ([`crate::present::place`], spec §7).

use crate::present::{number, place};

/// Errors of the global planner (spec §5 "GlobalPathPlanning"). Each is also sent as a
/// `PlanningFailure` notice by the component.
#[derive(Debug, Clone, PartialEq, thiserror::Error, serde::Serialize, strum::VariantNames)]
#[serde(tag = "kind")]
#[non_exhaustive]
pub enum GlobalPlanningError {
    /// Planning was requested before any map was set.
    #[error("no map has been set")]
    NoMap,
    /// A start or goal pose with a NaN or infinite coordinate.
    #[error("{which} pose ({x}, {y}, {theta}) is not finite")]
    NonFinitePose {
        /// `start` or `goal`.
        which: &'static str,
        /// x (m).
        x: f64,
        /// y (m).
        y: f64,
        /// θ (rad).
        theta: f64,
    },
    /// A start or goal outside the map.
    #[error("{which} ({}, {}) m is outside the map", number(*x), number(*y))]
    OutsideMap {
        /// `start` or `goal`.
        which: &'static str,
        /// x (m).
        x: f64,
        /// y (m).
        y: f64,
    },
    /// A start or goal cell outside the planning grid.
    #[error("{which} cell ({}, {}) is outside the {width}×{height} map", cell.0, cell.1)]
    CellOutside {
        /// `start` or `goal`.
        which: &'static str,
        /// The cell.
        cell: (usize, usize),
        /// Map width.
        width: usize,
        /// Map height.
        height: usize,
    },
    /// A start or goal cell that is an obstacle or lies within `dmin` of one (its obstacle
    /// distance is ≤ `dmin`).
    #[error(
        "{which} {} is blocked: it is an obstacle or within dmin = {dmin} m of one",
        place(*at, *cell)
    )]
    Blocked {
        /// `start` or `goal`.
        which: &'static str,
        /// The cell.
        cell: (usize, usize),
        /// The cell's centre (m).
        at: (f64, f64),
        /// The `dmin` in force (m).
        dmin: f64,
    },
    /// No path joins start and goal.
    #[error("no path from {} to {}", place(*start_at, *start), place(*goal_at, *goal))]
    NoPath {
        /// The start cell.
        start: (usize, usize),
        /// The goal cell.
        goal: (usize, usize),
        /// The start cell's centre (m).
        start_at: (f64, f64),
        /// The goal cell's centre (m).
        goal_at: (f64, f64),
    },
    /// A `dmin` that is negative or not finite.
    #[error("dmin {value} m must be finite and ≥ 0")]
    BadDmin {
        /// The value given.
        value: f64,
    },
}
