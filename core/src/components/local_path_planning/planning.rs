//! When LocalPathPlanning makes a plan, and how its result is sent (spec §3 steps 3–8, 000
//! §5.2.4.8–13), including a plan whose field takes more than one execution (spec §3 Decision
//! 0.2, "A local plan over executions").

use super::{LocalPathPlanning, LocalPathPlanningParams, RETRY_NS, plan_params};
use crate::errors::LocalPathError;
use crate::local::{EscapeLead, PlanRequest, Progress, control_points, nearest_path_index};
use crate::map::GridMap;
use crate::rtc::Tick;

/// The field cells one execution finalizes at most (spec §3 Decision 0.2, "A local plan over
/// executions"): a plan whose field needs more goes on in the next executions, so that no
/// execution holds the system up for long on a large map. 2¹⁶ cells is a disc about 29 m
/// across at 0.1 m cells, where the default RouteRemakeDistance of 10 m needs about half of
/// it: the plans of the seeds' maps and of every scenario in `fixtures/` take one execution
/// (at most 23 k cells), as before; the 566 k cells of a default plan on a warehouse map of
/// 0.03 m cells take nine.
pub const FIELD_CELLS_PER_EXECUTION: usize = 1 << 16;

impl LocalPathPlanning {
    /// Whether the held path, from the cell nearest `start` on, reaches the cell of `goal`
    /// on `map`: a new goal that it does not reach waits for its course (spec §3 Decision
    /// 0.4, [`LocalPathPlanning::awaits_course`]).
    pub(super) fn held_path_reaches(
        &self,
        map: &GridMap,
        start: (f64, f64),
        goal: (f64, f64),
    ) -> bool {
        match (
            map.world_to_cell(goal.0, goal.1),
            nearest_path_index(map, &self.held_path, 0, start),
        ) {
            (Some(cell), Some(m)) => self.held_path[m..].contains(&cell),
            _ => false,
        }
    }

    /// Spec §3 steps 3–8, after escaping the `dmin` zone if the robot stands in it.
    pub(super) fn replan(&mut self, tick: &Tick, params: &LocalPathPlanningParams) {
        let (Some(map), Some(goal), Some(current)) = (self.map.as_ref(), self.goal, self.current)
        else {
            return;
        };
        let plan_params = plan_params(params);
        self.planned_with = Some(plan_params);
        self.plan_count += 1;
        let request = PlanRequest {
            held_path: &self.held_path,
            match_from: self.match_index,
            current,
            goal,
            direction: self.direction,
            params: plan_params,
            extent: self.extent,
        };
        // Spec §3 Decision 0.2: from inside the dmin zone, the plan escapes first.
        let (from_exit, lead) = EscapeLead::of(map, &request);
        let progress = self
            .planner
            .begin(map, &from_exit, FIELD_CELLS_PER_EXECUTION);
        self.field_valid = self.planner.field_is_fresh();
        self.conclude(tick, progress, lead, false);
    }

    /// Spec §3 Decision 0.2: the next part of a plan's field; the plan once it is done.
    pub(super) fn go_on(&mut self, tick: &Tick) {
        let (Some(lead), Some(map)) = (self.unfinished.take(), self.map.as_ref()) else {
            return;
        };
        let progress = self
            .planner
            .resume(map, &self.held_path, FIELD_CELLS_PER_EXECUTION);
        self.conclude(tick, progress, lead, true);
    }

    /// Sends a plan that is done (from where the robot is now, if it was begun in an earlier
    /// execution: `late`), or the failure; or keeps the unfinished plan's escape lead for the
    /// next execution.
    fn conclude(
        &mut self,
        tick: &Tick,
        progress: Result<Progress, LocalPathError>,
        lead: EscapeLead,
        late: bool,
    ) {
        match progress {
            Ok(Progress::Continuing) => {
                self.unfinished = Some(lead);
            }
            Ok(Progress::Done(plan)) => {
                let Some(map) = self.map.as_ref() else {
                    return;
                };
                let (plan, escaped) = lead.apply(map, plan);
                let (mut cells, mut points) =
                    (plan.merged_path.clone(), plan.control_points.clone());
                if late
                    && let (Some(cur), Some(goal)) = (self.current, self.goal)
                    && let Some(m) = nearest_path_index(map, &cells, 0, (cur.x, cur.y))
                {
                    // Begun in an earlier execution: the path from the cell nearest the robot.
                    cells.drain(..m);
                    points = control_points(map, &cells, (cur.x, cur.y), (goal.x, goal.y));
                }
                self.escaped = escaped;
                self.retry_at_ns = None;
                self.held_path = cells.clone();
                self.match_index = 0;
                self.send(tick, cells, points);
                self.plan = Some(plan);
            }
            Err(e) => {
                self.escaped = 0;
                self.plan = None;
                // Spec §3 Decision 0.2: try again in 1 s while the goal is held.
                self.retry_at_ns = Some(tick.time_ns.saturating_add(RETRY_NS));
                self.fail(tick, e);
            }
        }
    }
}
