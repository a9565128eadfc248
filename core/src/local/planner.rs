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

/// The local planner: owns the potential field's buffers.
#[derive(Debug, Clone, Default)]
pub struct LocalPlanner {
    field: PotentialField,
    field_fresh: bool,
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
        let computed = self.field.compute(map, &field_request);
        self.field_fresh = !matches!(
            computed,
            Err(LocalPathError::CellOutside { .. }
                | LocalPathError::BadParameter { .. }
                | LocalPathError::NotFinite { .. })
        );
        computed?;
        let local_path = descend(&self.field, current_cell)?;
        let merged_path = merge_paths(
            &local_path,
            request.held_path,
            target.index,
            target.goal_index,
        );
        let control_points = control_points(map, &merged_path, (cur.x, cur.y), (goal.x, goal.y));
        Ok(LocalPlan {
            target,
            current_cell,
            posture,
            direction: request.direction,
            local_path,
            merged_path,
            control_points,
        })
    }
}
