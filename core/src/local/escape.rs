//! A local plan that starts inside the `dmin` zone (spec §3 Decision 0.2, escape from the
//! margin): the shortest way out ([`escape_route`]), then the plan of seed 000 from the first
//! clear cell.

use super::LocalPathError;
use super::control_points::control_points;
use super::planner::{LocalPlan, LocalPlanner, PlanRequest};
use crate::interfaces::Pose;
use crate::map::{Cell, GridMap, escape_route};

/// [`LocalPlanner::plan`] for `request`, escaping first if the current cell lies within
/// `dmin` of an obstacle without being one: the local and merged paths start with the escape
/// cells, the control points are made from the whole path, and the second value is the
/// number of escape steps (0 when the robot stood clear).
pub fn plan_escaping(
    planner: &mut LocalPlanner,
    map: &GridMap,
    request: &PlanRequest<'_>,
) -> Result<(LocalPlan, usize), LocalPathError> {
    let current = request.current;
    let escape: Option<Vec<Cell>> = map
        .world_to_cell(current.x, current.y)
        .and_then(|c| escape_route(map, c, request.params.dmin))
        .filter(|r| r.len() > 1);
    let Some(escape) = escape else {
        return planner.plan(map, request).map(|p| (p, 0));
    };
    let steps = escape.len() - 1;
    let (x, y) = map.cell_center(escape[steps]);
    let from_exit = PlanRequest {
        current: Pose::new(x, y, current.theta),
        ..*request
    };
    let mut plan = planner.plan(map, &from_exit)?;
    let lead = &escape[..steps];
    plan.local_path.splice(0..0, lead.iter().copied());
    plan.merged_path.splice(0..0, lead.iter().copied());
    let goal = request.goal;
    plan.control_points = control_points(
        map,
        &plan.merged_path,
        (current.x, current.y),
        (goal.x, goal.y),
    );
    plan.current_cell = escape[0];
    Ok((plan, steps))
}
