//! One local plan, start to finish (spec §3 steps 3–7): local target, potential field,
//! descent, merge, control points. The component decides *when* to plan; this decides
//! *what* the plan is. Buffers (the field) are reused between plans.

use serde::{Deserialize, Serialize};

use super::control_points::control_points;
use super::local_path::descend;
use super::local_target::{LocalTarget, find_local_target};
use super::merge::merge_paths;
use super::potential_field::{FieldExtent, FieldRequest, PotentialField};
use crate::errors::LocalPathError;
use crate::interfaces::{Direction, Pose};
use crate::map::{Cell, GridMap};

/// The configuration parameters a plan uses (000 §4.2).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PlanParams {
    /// `RouteRemakeDistance` \[m\]: path distance from the current position to the target.
    pub route_remake_distance: f64,
    /// `dmin` \[m\]: closest allowed approach to an obstacle.
    pub dmin: f64,
    /// `PostureConsiderationLevel` \[%\].
    pub posture_consideration_level: f64,
    /// `NotPostureDistance` \[m\]: within this straight distance of the goal, no posture part.
    pub not_posture_distance: f64,
}

impl Default for PlanParams {
    /// The defaults of 000 §4.2.
    fn default() -> Self {
        Self {
            route_remake_distance: 10.0,
            dmin: 0.5,
            posture_consideration_level: 85.0,
            not_posture_distance: 1.0,
        }
    }
}

/// What one plan is made from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanRequest<'a> {
    /// The held path (000 §5.2.4.8 "前回までに取得又は作成した経路").
    pub held_path: &'a [Cell],
    /// Where the search for the nearest path cell starts (the last match).
    pub match_from: usize,
    /// The robot's current pose.
    pub current: Pose,
    /// The goal pose of `SetPosition`.
    pub goal: Pose,
    /// The driving direction in effect (spec §3 step 1 may have switched it).
    pub direction: Direction,
    /// The parameters.
    pub params: PlanParams,
    /// How much of the field to compute.
    pub extent: FieldExtent,
}

/// A successful local plan: what the component sends and the GUI draws.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LocalPlan {
    /// The local target (cell and heading).
    pub target: LocalTarget,
    /// The current cell.
    pub current_cell: Cell,
    /// Whether the posture part was used (off within `NotPostureDistance`).
    pub posture: bool,
    /// The driving direction it was made for.
    pub direction: Direction,
    /// The local path, current cell … target (000 §5.2.4.10).
    pub local_path: Vec<Cell>,
    /// Local path + held path after the target up to the goal (000 §5.2.4.11).
    pub merged_path: Vec<Cell>,
    /// Control points of the merged path (000 §5.2.4.12), metres.
    pub control_points: Vec<(f64, f64)>,
}

/// Where a plan stands after [`LocalPlanner::begin`] or [`LocalPlanner::resume`].
#[derive(Debug, Clone, PartialEq)]
pub enum Progress {
    /// The plan is made.
    Done(LocalPlan),
    /// Its field is unfinished: [`LocalPlanner::resume`] goes on.
    Continuing,
}

/// A plan begun whose field is unfinished: what the rest of it is made from.
#[derive(Debug, Clone, PartialEq)]
struct Pending {
    target: LocalTarget,
    current_cell: Cell,
    current: Pose,
    goal: Pose,
    posture: bool,
    direction: Direction,
}

/// The local planner: owns the potential field's buffers.
#[derive(Debug, Clone, Default)]
pub struct LocalPlanner {
    field: PotentialField,
    field_fresh: bool,
    pending: Option<Pending>,
}

impl LocalPlanner {
    /// A planner with empty buffers.
    pub fn new() -> Self {
        Self::default()
    }

    /// The field of the last plan (also after a failed one, for display).
    pub fn field(&self) -> &PotentialField {
        &self.field
    }

    /// Whether the last [`LocalPlanner::plan`] computed the field (it did unless it failed
    /// before: bad current position, no local target).
    pub fn field_is_fresh(&self) -> bool {
        self.field_fresh
    }

    /// Makes a plan (spec §3 steps 3–7).
    ///
    /// Errors: the current position outside the map or within `dmin` of an obstacle; a
    /// parameter out of range; no local target ([`find_local_target`]); no route
    /// ([`LocalPathError::NoRoute`]).
    pub fn plan(
        &mut self,
        map: &GridMap,
        request: &PlanRequest<'_>,
    ) -> Result<LocalPlan, LocalPathError> {
        let mut progress = self.begin(map, request, usize::MAX)?;
        loop {
            match progress {
                Progress::Done(plan) => return Ok(plan),
                // Not with an unbounded budget; went on all the same.
                Progress::Continuing => {
                    progress = self.resume(map, request.held_path, usize::MAX)?;
                }
            }
        }
    }

    /// Whether a plan is begun and unfinished.
    pub fn is_pending(&self) -> bool {
        self.pending.is_some()
    }

    /// Drops an unfinished plan (the field keeps what it computed, for display).
    pub fn cancel(&mut self) {
        self.pending = None;
    }

    /// [`LocalPlanner::plan`], its field finalizing at most `budget` cells now (spec §3
    /// Decision 0.2, "A local plan over executions"). [`Progress::Continuing`]: the rest
    /// comes from [`LocalPlanner::resume`], with the same held path; the plan is then the
    /// one `plan` would have made now. Errors as `plan`'s, the unfinished plan dropped.
    pub fn begin(
        &mut self,
        map: &GridMap,
        request: &PlanRequest<'_>,
        budget: usize,
    ) -> Result<Progress, LocalPathError> {
        self.pending = None;
        self.field_fresh = false;
        let p = request.params;
        for (name, value) in [
            ("RouteRemakeDistance", p.route_remake_distance),
            ("NotPostureDistance", p.not_posture_distance),
            ("dmin", p.dmin),
        ] {
            if value.is_nan() || value < 0.0 {
                return Err(LocalPathError::BadParameter {
                    name,
                    value,
                    range: "[0, ∞)",
                });
            }
        }
        let cur = request.current;
        let goal = request.goal;
        if !cur.is_finite() {
            return Err(LocalPathError::NotFinite {
                call: "plan",
                argument: "current position",
                value: if cur.x.is_finite() { cur.y } else { cur.x },
            });
        }
        let current_cell = map
            .world_to_cell(cur.x, cur.y)
            .ok_or(LocalPathError::OutsideMap {
                what: "current position",
                x: cur.x,
                y: cur.y,
            })?;
        if !map.is_clear(current_cell, p.dmin) {
            return Err(LocalPathError::NotClear {
                what: "current position",
                x: cur.x,
                y: cur.y,
                cell: current_cell,
                distance: map.obstacle_distance(current_cell),
                dmin: p.dmin,
            });
        }
        let target = find_local_target(
            map,
            request.held_path,
            request.match_from,
            (cur.x, cur.y),
            goal,
            request.direction,
            p.route_remake_distance,
            p.dmin,
        )?;
        // 000 §5.2.4.9: no posture part within NotPostureDistance (straight) of the goal.
        let posture = libm::hypot(goal.x - cur.x, goal.y - cur.y) > p.not_posture_distance;
        let field_request = FieldRequest {
            target: target.cell,
            current: current_cell,
            current_heading: cur.theta,
            target_heading: target.heading,
            direction: request.direction,
            dmin: p.dmin,
            posture_consideration_level: p.posture_consideration_level,
            posture,
            extent: request.extent,
        };
        let computed = self.field.compute_within(map, &field_request, budget);
        self.field_fresh = !matches!(
            computed,
            Err(LocalPathError::CellOutside { .. }
                | LocalPathError::BadParameter { .. }
                | LocalPathError::NotFinite { .. })
        );
        let pending = Pending {
            target,
            current_cell,
            current: cur,
            goal,
            posture,
            direction: request.direction,
        };
        if !computed? {
            self.pending = Some(pending);
            return Ok(Progress::Continuing);
        }
        self.finish(map, request.held_path, pending)
            .map(Progress::Done)
    }

    /// Goes on with the plan [`LocalPlanner::begin`] left unfinished, for at most `budget`
    /// more field cells. `held_path` is the path the plan was begun with. With no plan
    /// pending: [`Progress::Continuing`] (nothing to make). Errors as `plan`'s (no route),
    /// the plan dropped.
    pub fn resume(
        &mut self,
        map: &GridMap,
        held_path: &[Cell],
        budget: usize,
    ) -> Result<Progress, LocalPathError> {
        let Some(pending) = self.pending.take() else {
            return Ok(Progress::Continuing);
        };
        if !self.field.resume(map, budget)? {
            self.pending = Some(pending);
            return Ok(Progress::Continuing);
        }
        self.finish(map, held_path, pending).map(Progress::Done)
    }

    /// Steps 5–7 on the finished field: descent, merge, control points.
    fn finish(
        &self,
        map: &GridMap,
        held_path: &[Cell],
        p: Pending,
    ) -> Result<LocalPlan, LocalPathError> {
        let local_path = descend(&self.field, p.current_cell)?;
        let merged_path = merge_paths(&local_path, held_path, p.target.index, p.target.goal_index);
        let control_points = control_points(
            map,
            &merged_path,
            (p.current.x, p.current.y),
            (p.goal.x, p.goal.y),
        );
        Ok(LocalPlan {
            target: p.target,
            current_cell: p.current_cell,
            posture: p.posture,
            direction: p.direction,
            local_path,
            merged_path,
            control_points,
        })
    }
}
