//! [`Mission`]: what the robot is asked to do and how far it got — start, goal, direction,
//! the route, arrival, halt — followed from the facts the wiring reports.
//!
//! **Architecture invariant**: the mission learns only from facts ([`Report`]) and from
//! reading the components; it never calls a component. It knows nothing of the record (the
//! log, telemetry, statistics) or of any user interface.

use serde::Serialize;

use super::events::EventKind;
use super::kind::ComponentKind;
use super::wiring::{Report, Wiring};
use crate::interfaces::{Direction, Pose};
use crate::map::Cell;
use crate::motion::{DrivePhase, angle_diff};

/// The robot's task and its progress.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Mission {
    start: Option<Pose>,
    goal: Option<Pose>,
    direction: Direction,
    route: Vec<Cell>,
    /// Goals set so far: each `SetPosition` starts an epoch.
    goal_epoch: u64,
    /// The epoch whose plan was last sent (a non-empty path reached DriveControl).
    sent_epoch: u64,
    /// The newest planning failure not yet followed by a sent plan.
    failure: Option<String>,
    arrived: bool,
    halted: bool,
    /// The heading error \[rad\] when the robot reached the goal position, before it turned
    /// to the goal heading: what the planner's posture term achieved.
    approach_heading_error: Option<f64>,
}

impl Mission {
    /// No goal.
    pub fn new() -> Self {
        Self::default()
    }

    /// Follows `report`'s facts; after a tick in which DriveControl ran, adds an `Arrived`
    /// fact when DriveControl has just reached the goal.
    pub fn observe(&mut self, report: &mut Report, wiring: &Wiring) {
        for fact in &report.facts {
            match fact {
                EventKind::MapLoaded { .. } => {
                    self.goal = None;
                    self.route.clear();
                    self.arrived = false;
                    self.failure = None;
                }
                EventKind::GoalSet {
                    start,
                    goal,
                    direction,
                    ..
                } => {
                    self.start = Some(*start);
                    self.goal = Some(*goal);
                    self.direction = *direction;
                    self.route.clear();
                    self.arrived = false;
                    self.halted = false;
                    self.failure = None;
                    self.approach_heading_error = None;
                    self.goal_epoch += 1;
                }
                EventKind::GlobalPlan { .. } => {
                    self.route = wiring
                        .global_path_planning()
                        .last_plan()
                        .map(|p| p.cells.clone())
                        .unwrap_or_default();
                }
                EventKind::LocalPlanSent { cells, .. } if *cells > 0 => {
                    self.sent_epoch = self.goal_epoch;
                    self.failure = None;
                }
                EventKind::PlanningFailed { planner, reason } => {
                    self.failure = Some(format!("{planner}: {reason}"));
                }
                EventKind::Cleared => {
                    self.goal = None;
                    self.route.clear();
                    self.halted = true;
                }
                EventKind::SafeMode => self.halted = true,
                _ => {}
            }
        }
        let Some(index) = report.tick else {
            return;
        };
        if wiring.runs_at(ComponentKind::DriveControl, index) {
            let at_goal = matches!(
                wiring.drive_control().pursuit().phase(),
                DrivePhase::FinalTurn | DrivePhase::Arrived
            );
            if at_goal
                && self.approach_heading_error.is_none()
                && let Some(g) = self.goal
            {
                let theta = wiring.robot_pose().theta;
                self.approach_heading_error = Some(angle_diff(theta, g.theta).abs());
            }
            let arrived = wiring.drive_control().is_arrived();
            if arrived && !self.arrived {
                let pose = wiring.robot_pose();
                let (position_error, heading_error) = match self.goal {
                    Some(g) => (
                        libm::hypot(pose.x - g.x, pose.y - g.y),
                        angle_diff(pose.theta, g.theta).abs(),
                    ),
                    None => (f64::NAN, f64::NAN),
                };
                report.facts.push(EventKind::Arrived {
                    pose,
                    position_error,
                    heading_error,
                    approach_heading_error: self.approach_heading_error.unwrap_or(f64::NAN),
                });
            }
            self.arrived = arrived;
        }
    }

    /// Where the robot was last placed (or the start of the last new goal).
    pub fn start(&self) -> Option<Pose> {
        self.start
    }

    /// The goal held.
    pub fn goal(&self) -> Option<Pose> {
        self.goal
    }

    /// The commanded direction.
    pub fn direction(&self) -> Direction {
        self.direction
    }

    /// The route GlobalPathPlanning sent last (cells, start first).
    pub fn route(&self) -> &[Cell] {
        &self.route
    }

    /// Whether a plan for the current goal has reached DriveControl.
    pub fn plan_sent(&self) -> bool {
        self.goal_epoch > 0 && self.sent_epoch == self.goal_epoch
    }

    /// The newest planning failure not yet followed by a plan (`planner: reason`).
    pub fn failure(&self) -> Option<&str> {
        self.failure.as_deref()
    }

    /// The heading error \[rad\] when the robot reached the goal position, before it turned
    /// on the spot to the goal heading (`None` until then).
    pub fn approach_heading_error(&self) -> Option<f64> {
        self.approach_heading_error
    }

    /// Whether DriveControl has reached the current goal.
    pub fn is_arrived(&self) -> bool {
        self.arrived
    }

    /// Whether SafeMode or Clear halted the robot (until the next goal).
    pub fn is_halted(&self) -> bool {
        self.halted
    }
}
