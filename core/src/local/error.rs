//! Errors of LocalPathPlanning (seed 000, spec §3).

use crate::present::number;

/// Errors of the LocalPathPlanning component (seed 000, spec §3): a `LocalPath` service call
/// refused (nothing held changes), or the reason a local plan could not be made (sent to the
/// GUI as the planning-failure notice of 000 §5.2.4.13).
#[derive(Debug, Clone, PartialEq, thiserror::Error, serde::Serialize, strum::VariantNames)]
#[serde(tag = "kind")]
#[non_exhaustive]
pub enum LocalPathError {
    /// A number that must be finite is NaN or infinite.
    #[error("{call}: {argument} = {value} is not finite")]
    NotFinite {
        /// The service call, e.g. `SetPosition`.
        call: &'static str,
        /// The argument, e.g. `StartX`.
        argument: &'static str,
        /// The value given.
        value: f64,
    },
    /// `Direction` other than 1 (forward) or 2 (backward) (000 §3.2.2.1 (1)).
    #[error("SetPosition: Direction = {value} must be 1 (forward) or 2 (backward)")]
    BadDirection {
        /// The value given.
        value: i16,
    },
    /// A call that needs the map before `SetMap` (000 §5.2.4.1).
    #[error("{call}: no map has been set (SetMap first)")]
    NoMap {
        /// The service call.
        call: &'static str,
    },
    /// A position outside the map (outside counts as obstacle, spec §2).
    #[error("{what} ({}, {}) is outside the map", number(*x), number(*y))]
    OutsideMap {
        /// `start`, `goal` or `current position`.
        what: &'static str,
        /// X \[m\].
        x: f64,
        /// Y \[m\].
        y: f64,
    },
    /// A position whose cell, or a cell within `dmin` of it, is an obstacle (000 §5.2.4.2,
    /// §5.2.4.4).
    #[error(
        "{what} ({}, {}) in cell ({}, {}) is too close to an obstacle: obstacle distance {} m ≤ dmin = {} m",
        number(*x), number(*y), cell.0, cell.1, number(*distance), number(*dmin)
    )]
    NotClear {
        /// `start`, `goal` or `current position`.
        what: &'static str,
        /// X \[m\].
        x: f64,
        /// Y \[m\].
        y: f64,
        /// Its cell.
        cell: (usize, usize),
        /// The cell's obstacle distance \[m\].
        distance: f64,
        /// `dmin` \[m\].
        dmin: f64,
    },
    /// A `MapUpdate` timestamp with `nsec` ≥ 10⁹.
    #[error("MapUpdate: nsec = {nsec} must be below 1000000000")]
    BadTimestamp {
        /// The value given.
        nsec: u32,
    },
    /// `GlobalPathCourse` arrays whose length differs from `num`.
    #[error("GlobalPathCourse: {array} has {len} entries, but num = {num}")]
    PathLength {
        /// `GridPathX` or `GridPathY`.
        array: &'static str,
        /// Its length.
        len: usize,
        /// `num` as given.
        num: i32,
    },
    /// `GlobalPathCourse` with no cell.
    #[error("GlobalPathCourse: the path is empty")]
    EmptyPath,
    /// A path cell outside the map.
    #[error("GlobalPathCourse: cell {index} = ({x}, {y}) is outside the {width}×{height} map")]
    PathCellOutside {
        /// Index in the path.
        index: usize,
        /// x index.
        x: i64,
        /// y index.
        y: i64,
        /// Map width.
        width: usize,
        /// Map height.
        height: usize,
    },
    /// Consecutive path cells that are not 8-neighbours (spec §3 Decision).
    #[error(
        "GlobalPathCourse: cells {} = ({}, {}) and {} = ({}, {}) are not 8-neighbours",
        index - 1, from.0, from.1, index, to.0, to.1
    )]
    PathNotAdjacent {
        /// Index of the second cell.
        index: usize,
        /// The cell before.
        from: (i64, i64),
        /// The cell at `index`.
        to: (i64, i64),
    },
    /// The held path does not pass the goal cell after the current position, so there is
    /// no local target (000 §5.2.4.8).
    #[error("the held path does not reach the goal cell ({}, {})", goal.0, goal.1)]
    GoalNotOnPath {
        /// The goal's cell.
        goal: (usize, usize),
    },
    /// Every held-path cell from the local target to the goal is within `dmin` of an
    /// obstacle, so no target for the field is left (000 §5.2.4.9).
    #[error("the held path is blocked from cell ({}, {}) to the goal: no passable local target", from.0, from.1)]
    TargetBlocked {
        /// The local target found by distance.
        from: (usize, usize),
    },
    /// The potential field never reached the current cell: no passable route between the
    /// current position and the local target (000 §5.2.4.9).
    #[error(
        "no route: the potential field from the local target ({}, {}) does not reach the current cell ({}, {})",
        target.0, target.1, current.0, current.1
    )]
    NoRoute {
        /// The local target.
        target: (usize, usize),
        /// The current cell.
        current: (usize, usize),
    },
    /// A cell of a field request that is not in the field's map.
    #[error("{what} cell ({x}, {y}) is outside the {width}×{height} map")]
    CellOutside {
        /// `target` or `current`.
        what: &'static str,
        /// x index.
        x: usize,
        /// y index.
        y: usize,
        /// Map width.
        width: usize,
        /// Map height.
        height: usize,
    },
    /// A planner parameter outside its range (000 §4.2).
    #[error("{name} = {value} is out of range {range}")]
    BadParameter {
        /// The parameter's seed name.
        name: &'static str,
        /// The value.
        value: f64,
        /// The allowed range.
        range: &'static str,
    },
}
