//! A local plan that starts inside the `dmin` zone (spec §3 Decision 0.2, escape from the
//! margin): the shortest way out ([`escape_route`]), then the plan of seed 000 from the first
//! clear cell ([`EscapeLead::of`] the request to plan, [`EscapeLead::apply`] to its plan).

use super::control_points::control_points;
use super::planner::{LocalPlan, PlanRequest};
use crate::interfaces::Pose;
use crate::map::{Cell, GridMap, escape_route};

/// The way out of the `dmin` zone a plan begins with: the cells before the first clear one
/// (none when the robot stands clear), and the pose the plan was asked for.
#[derive(Debug, Clone, PartialEq)]
pub struct EscapeLead {
    cells: Vec<Cell>,
    current: Pose,
    goal: Pose,
}

impl EscapeLead {
    /// The request to plan from — from the first clear cell when the current cell lies
    /// within `dmin` of an obstacle without being one — and the lead to put before its plan.
    pub fn of<'a>(map: &GridMap, request: &PlanRequest<'a>) -> (PlanRequest<'a>, Self) {
        let current = request.current;
        let mut lead = Self {
            cells: Vec::new(),
            current,
            goal: request.goal,
        };
        let escape: Option<Vec<Cell>> = map
            .world_to_cell(current.x, current.y)
            .and_then(|c| escape_route(map, c, request.params.dmin))
            .filter(|r| r.len() > 1);
        let Some(mut escape) = escape else {
            return (*request, lead);
        };
        let exit = escape.len() - 1;
        let (x, y) = map.cell_center(escape[exit]);
        escape.truncate(exit);
        lead.cells = escape;
        let from_exit = PlanRequest {
            current: Pose::new(x, y, current.theta),
            ..*request
        };
        (from_exit, lead)
    }

    /// `plan` (made from the request [`EscapeLead::of`] gave) with the lead before its paths
    /// and control points made from the whole path; and the number of escape steps.
    pub fn apply(&self, map: &GridMap, mut plan: LocalPlan) -> (LocalPlan, usize) {
        let Some(&first) = self.cells.first() else {
            return (plan, 0);
        };
        let lead = &self.cells;
        plan.local_path.splice(0..0, lead.iter().copied());
        plan.merged_path.splice(0..0, lead.iter().copied());
        plan.control_points = control_points(
            map,
            &plan.merged_path,
            (self.current.x, self.current.y),
            (self.goal.x, self.goal.y),
        );
        plan.current_cell = first;
        (plan, lead.len())
    }
}
