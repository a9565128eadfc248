//! The local target ("局所経路作成目標位置", 000 §5.2.4.8, spec §3 step 3).

use serde::{Deserialize, Serialize};

use crate::errors::LocalPathError;
use crate::interfaces::{Direction, Pose};
use crate::map::{Cell, GridMap};

/// Where the local path must lead, found on the held path.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct LocalTarget {
    /// The target cell.
    pub cell: Cell,
    /// Its index in the held path.
    pub index: usize,
    /// Index of the held-path cell nearest the current position (where the walk started).
    pub match_index: usize,
    /// Index of the goal cell in the held path (the end of the merged path).
    pub goal_index: usize,
    /// The robot heading wanted at the target \[rad\], in (−π, π]: the goal heading at the
    /// goal, else the direction of the path at the target (turned by π when driving
    /// backward, since the robot then faces against its motion).
    pub heading: f64,
    /// Whether the target is the goal cell.
    pub is_goal: bool,
    /// Distance walked along the path from the match to the target \[m\].
    pub path_distance: f64,
}

/// Wraps an angle to (−π, π].
pub fn wrap_angle(a: f64) -> f64 {
    let two_pi = 2.0 * core::f64::consts::PI;
    let mut r = libm::fmod(a, two_pi);
    if r > core::f64::consts::PI {
        r -= two_pi;
    } else if r <= -core::f64::consts::PI {
        r += two_pi;
    }
    r
}

/// Length of one path step \[m\]: `g` straight, `√2·g` diagonal (any other step: its
/// straight length).
pub fn step_length(a: Cell, b: Cell, grid_size: f64) -> f64 {
    let dx = a.0.abs_diff(b.0) as f64;
    let dy = a.1.abs_diff(b.1) as f64;
    f64::sqrt(dx * dx + dy * dy) * grid_size
}

/// The index of the held-path cell nearest `position` (cell centre, straight distance),
/// searched from `from` to the end; ties go to the earliest. **Decision (spec §3 step 3)**:
/// searching forward from the last match means a path that loops back past the robot is
/// not cut short. `None` if `from` is past the end.
pub fn nearest_path_index(
    map: &GridMap,
    path: &[Cell],
    from: usize,
    position: (f64, f64),
) -> Option<usize> {
    let mut best: Option<(usize, f64)> = None;
    for (i, &c) in path.iter().enumerate().skip(from) {
        let (cx, cy) = map.cell_center(c);
        let d2 = (cx - position.0) * (cx - position.0) + (cy - position.1) * (cy - position.1);
        if best.is_none_or(|(_, b)| d2 < b) {
            best = Some((i, d2));
        }
    }
    best.map(|(i, _)| i)
}

/// The local target (000 §5.2.4.8): from the held-path cell nearest the current position
/// (searched from `from`), walk along the path summing step lengths until the sum reaches
/// `route_remake_distance`; that cell is the target, unless the goal cell comes first, then
/// the goal cell is. **Decision**: a target cell within `dmin` of an obstacle (the path was
/// blocked by a MapUpdate) is moved on along the path to the first passable cell before the
/// goal; if there is none, [`LocalPathError::TargetBlocked`].
///
/// Errors also: [`LocalPathError::GoalNotOnPath`] if the goal's cell does not appear on the
/// path at or after the match; [`LocalPathError::OutsideMap`] for a goal outside the map.
#[allow(clippy::too_many_arguments)]
pub fn find_local_target(
    map: &GridMap,
    path: &[Cell],
    from: usize,
    position: (f64, f64),
    goal: Pose,
    direction: Direction,
    route_remake_distance: f64,
    dmin: f64,
) -> Result<LocalTarget, LocalPathError> {
    let goal_cell = map
        .world_to_cell(goal.x, goal.y)
        .ok_or(LocalPathError::OutsideMap {
            what: "goal",
            x: goal.x,
            y: goal.y,
        })?;
    let not_on_path = LocalPathError::GoalNotOnPath { goal: goal_cell };
    let match_index = nearest_path_index(map, path, from, position).ok_or(not_on_path.clone())?;
    let goal_index = path[match_index..]
        .iter()
        .position(|&c| c == goal_cell)
        .map(|k| k + match_index)
        .ok_or(not_on_path)?;
    let g = map.grid_size();
    let mut index = match_index;
    let mut walked = 0.0;
    while index < goal_index && walked < route_remake_distance {
        walked += step_length(path[index], path[index + 1], g);
        index += 1;
    }
    let by_distance = path[index];
    while index < goal_index && !map.is_clear(path[index], dmin) {
        walked += step_length(path[index], path[index + 1], g);
        index += 1;
    }
    if !map.is_clear(path[index], dmin) {
        return Err(LocalPathError::TargetBlocked { from: by_distance });
    }
    let is_goal = index == goal_index;
    let heading = if is_goal {
        goal.theta
    } else {
        let (a, b) = (path[index], path[index + 1]);
        let motion = libm::atan2(b.1 as f64 - a.1 as f64, b.0 as f64 - a.0 as f64);
        match direction {
            Direction::Forward => motion,
            Direction::Backward => motion + core::f64::consts::PI,
        }
    };
    Ok(LocalTarget {
        cell: path[index],
        index,
        match_index,
        goal_index,
        heading: wrap_angle(heading),
        is_goal,
        path_distance: walked,
    })
}
