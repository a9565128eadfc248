//! [`Mission`]: what the robot is asked to do and how far it got — start, goal, direction,
//! the route, arrival, halt — followed from the facts the wiring reports.
//!
//! **Arrival** (spec §7 Decision 0.3) is decided here and nowhere else: after every tick the
//! system has arrived when, for the goal it holds and a plan sent for that goal, the robot
//! is at rest ([`Measured::at_rest`]), DriveControl commands no motion, and its pose is
//! within the goal's [`Tolerances`]. DriveControl's and LocalPathPlanning's own flags are
//! not consulted for it. The first tick of an arrival logs `Arrived` (once per goal) with
//! the pose at rest. A robot that comes to rest outside the tolerances after DriveControl
//! finished the path to this goal has stopped off the goal ([`Mission::off_goal`]).
//!
//! **Architecture invariant**: the mission learns only from facts ([`Report`]) and from
//! reading the components; it never calls a component. It knows nothing of the record (the
//! log, telemetry, statistics) or of any user interface.

use serde::Serialize;

use super::wiring::{Report, Wiring};
use crate::interfaces::{Direction, Pose};
use crate::map::Cell;
use crate::motion::{DrivePhase, angle_diff};
use crate::rtc::LifecycleState;
use crate::system::vocabulary::events::EventKind;
use crate::system::vocabulary::kind::ComponentKind;

use super::rest::{Measured, Offset, Tolerances, commanded};

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
    failure: Option<EventKind>,
    /// At rest within the tolerances of the goal, after the last tick.
    arrived: bool,
    /// The epoch whose `Arrived` was logged (one per goal).
    arrival_epoch: u64,
    /// At rest outside the tolerances, DriveControl done: how far off, after the last tick.
    off_goal: Option<Offset>,
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

    /// Follows `report`'s facts; after a tick, decides the arrival (module documentation)
    /// and adds an `Arrived` fact when the robot has just arrived at the goal.
    pub fn observe(&mut self, report: &mut Report, wiring: &Wiring) {
        for fact in &report.facts {
            match fact {
                EventKind::MapLoaded { .. } => {
                    self.goal = None;
                    self.route.clear();
                    self.arrived = false;
                    self.off_goal = None;
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
                    self.off_goal = None;
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
                failed @ EventKind::PlanningFailed { .. } => {
                    self.failure = Some(failed.clone());
                }
                EventKind::Cleared => {
                    self.goal = None;
                    self.route.clear();
                    self.halted = true;
                    self.arrived = false;
                    self.off_goal = None;
                }
                EventKind::SafeMode => {
                    self.halted = true;
                    self.arrived = false;
                    self.off_goal = None;
                }
                _ => {}
            }
        }
        let Some(index) = report.tick else {
            return;
        };
        if wiring.runs_at(ComponentKind::DriveControl, index) {
            let at_goal = match wiring.drive_phase() {
                Some(phase) => matches!(phase, DrivePhase::FinalTurn | DrivePhase::Arrived),
                // A script in DriveControl's place: at the goal once it commands nothing.
                None => wiring.drive_stands(),
            };
            if at_goal
                && self.approach_heading_error.is_none()
                && let Some(g) = self.goal
                && path_ends_at(wiring, g)
            {
                let theta = wiring.robot_pose().theta;
                self.approach_heading_error = Some(angle_diff(theta, g.theta).abs());
            }
        }
        self.decide_arrival(report, wiring);
    }

    /// Decides the arrival after a tick (module documentation).
    fn decide_arrival(&mut self, report: &mut Report, wiring: &Wiring) {
        self.arrived = false;
        self.off_goal = None;
        let Some(goal) = self.goal else { return };
        let resting = wiring.component_state(ComponentKind::PhysicsSim) == LifecycleState::Active
            && Measured::of(wiring).at_rest()
            && !commanded(wiring);
        if self.halted || !self.plan_sent() || !resting {
            return;
        }
        let Some(tolerances) = Tolerances::of(wiring) else {
            return;
        };
        let pose = wiring.robot_pose();
        let offset = Offset::between(pose, goal);
        if offset.within(tolerances) {
            self.arrived = true;
            if self.arrival_epoch != self.goal_epoch {
                self.arrival_epoch = self.goal_epoch;
                report.facts.push(EventKind::Arrived {
                    pose,
                    position_error: offset.distance,
                    heading_error: offset.heading_error,
                    approach_heading_error: self.approach_heading_error.unwrap_or(f64::NAN),
                });
            }
        } else if drive_done_for(wiring, goal) {
            self.off_goal = Some(offset);
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

    /// The newest planning failure not yet followed by a plan: its
    /// [`EventKind::PlanningFailed`].
    pub fn failure(&self) -> Option<&EventKind> {
        self.failure.as_ref()
    }

    /// The heading error \[rad\] when the robot reached the goal position, before it turned
    /// on the spot to the goal heading (`None` until then).
    pub fn approach_heading_error(&self) -> Option<f64> {
        self.approach_heading_error
    }

    /// Whether the system has arrived at the current goal: the robot at rest within its
    /// tolerances, for a plan made for it (module documentation).
    pub fn is_arrived(&self) -> bool {
        self.arrived
    }

    /// How far off the goal the robot rests, when it has come to rest outside the arrival
    /// tolerances after DriveControl finished the path to the current goal.
    pub fn off_goal(&self) -> Option<Offset> {
        self.off_goal
    }

    /// Whether SafeMode or Clear halted the robot (until the next goal).
    pub fn is_halted(&self) -> bool {
        self.halted
    }
}

/// Whether DriveControl has finished a path that ends at `goal`: its phase is `Arrived` (a
/// script in its place: it commands nothing) and its path's last point is the goal (not a
/// path to an earlier goal).
fn drive_done_for(wiring: &Wiring, goal: Pose) -> bool {
    let done = match wiring.drive_phase() {
        Some(phase) => phase == DrivePhase::Arrived,
        // A script in DriveControl's place has no phase: it is done once it commands nothing
        // (the arrival itself is the system's fact: at rest, within the tolerances).
        None => wiring.drive_stands(),
    };
    done && path_ends_at(wiring, goal)
}

/// Whether DriveControl's path ends at `goal` (the control points' last is the goal, exact).
fn path_ends_at(wiring: &Wiring, goal: Pose) -> bool {
    wiring
        .drive_path_end()
        .is_some_and(|(x, y)| libm::hypot(x - goal.x, y - goal.y) <= 1e-9)
}
