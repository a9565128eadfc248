//! The data that flows between components besides the seeds' IDL types (`rtc::Timed*`):
//! the LocalPath service's arguments and its consumers' data (000 §3.2), shared by
//! GlobalPathPlanning, LocalPathPlanning, DriveControl and the GUI.

use serde::{Deserialize, Serialize};

use crate::rtc::Time;

/// A pose in the map frame: metres, and radians counter-clockwise from the X axis
/// (000 §5.2.4.2).
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct Pose {
    /// X in metres.
    pub x: f64,
    /// Y in metres.
    pub y: f64,
    /// Heading θ in radians.
    pub theta: f64,
}

impl Pose {
    /// A pose.
    pub const fn new(x: f64, y: f64, theta: f64) -> Self {
        Self { x, y, theta }
    }

    /// Whether all three numbers are finite.
    pub fn is_finite(&self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.theta.is_finite()
    }
}

/// `Direction` of `SetPosition` (000 §3.2.2.1 (1)): 1 forward, 2 backward.
#[derive(
    Debug, Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize,
)]
pub enum Direction {
    /// 「1」: 前進.
    #[default]
    Forward,
    /// 「2」: 後進.
    Backward,
}

impl Direction {
    /// From the seed's `short`: 1 → Forward, 2 → Backward, anything else `None` (spec §3:
    /// "anything else is an error").
    pub fn from_short(value: i16) -> Option<Self> {
        match value {
            1 => Some(Self::Forward),
            2 => Some(Self::Backward),
            _ => None,
        }
    }

    /// The seed's `short`.
    pub fn to_short(self) -> i16 {
        match self {
            Self::Forward => 1,
            Self::Backward => 2,
        }
    }
}

/// `GlobalPathCourse(GridPathX, GridPathY, num)` (000 §3.2.2.1 (6)): a grid path, cell
/// indices of the shared `GridMap`, start first.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct GlobalPathCourse {
    /// `GridPathX`: x indices.
    pub grid_path_x: Vec<i32>,
    /// `GridPathY`: y indices.
    pub grid_path_y: Vec<i32>,
    /// `num`: number of cells.
    pub num: i32,
}

impl GlobalPathCourse {
    /// From cells in order.
    pub fn from_cells(cells: &[(usize, usize)]) -> Self {
        Self {
            grid_path_x: cells.iter().map(|c| c.0 as i32).collect(),
            grid_path_y: cells.iter().map(|c| c.1 as i32).collect(),
            num: cells.len() as i32,
        }
    }
}

/// What LocalPathPlanning sends to DriveControl (`DriveCons` → `LocalPathDrive`, 000 §3.2.1,
/// §5.2.4.12–13): the control points of the merged path, start (current position) first, goal
/// last, and how to drive them. Empty `points` means "no path: stop".
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct ControlPoints {
    /// When it was made.
    pub tm: Time,
    /// Control points in metres, map frame.
    pub points: Vec<(f64, f64)>,
    /// Forward or backward along the points.
    pub direction: Direction,
    /// Heading to take at the last point, radians.
    pub goal_theta: f64,
}

/// What LocalPathPlanning sends to the GUI and bump consumers (`InventGUICons`, `BumpCons`):
/// the merged grid path (000 §5.2.4.13). Empty `cells` means planning failed.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct GridPath {
    /// When it was made.
    pub tm: Time,
    /// Cells from the current position to the goal.
    pub cells: Vec<(usize, usize)>,
}

/// The planning-failure notice of 000 §5.2.4.13 ("経路作成に失敗したことを該当するRTCへ伝える").
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PlanningFailure {
    /// When planning failed.
    pub tm: Time,
    /// Which planner: `GlobalPathPlanning` or `LocalPathPlanning`.
    pub planner: String,
    /// Why, for the GUI (the planner's error).
    pub reason: crate::Reason,
}
