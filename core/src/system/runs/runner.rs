//! The scenario runner: builds the system from a [`Scenario`], drives it to its outcome and
//! reports what happened (spec §6: the same scenario gives the same trace bit for bit).

use core::fmt;

use serde::Serialize;

use super::scenario::{Expectation, FileResolver, OutcomeKind, Scenario};
use super::setup::{self, BuildOptions, Setup};
use super::timeline::{Timeline, secs_to_ns};
use crate::errors::{ScenarioError, SystemError};
use crate::interfaces::Pose;
use crate::motion::{DrivePhase, angle_diff};
use crate::reason::Reason;
use crate::rtc::LifecycleState;
use crate::system::simulation::rest::{ARRIVAL_HEADING_DEG, Measured};
use crate::system::simulation::robot::System;
use crate::system::simulation::status::{Status, SystemState};
use crate::system::vocabulary::events::EventKind;
use crate::system::vocabulary::input::Input;
use crate::system::vocabulary::kind::ComponentKind;
use crate::system::vocabulary::run_limit::beyond_replay_limit_s;

/// How long the robot must stand still, without a path, after a planning failure (or
/// SafeMode / Clear) for the run to end there \[ns\]: long enough for LocalPathPlanning's
/// retries every second (spec §3 Decision 0.2) to have been tried twice.
pub const STILL_NS: u64 = 2_500_000_000;

/// How a run ended, and why.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Outcome {
    /// The kind.
    pub kind: OutcomeKind,
    /// Why, as data (none for an arrival). The command line says it in the page's English.
    pub reason: Option<EndReason>,
}

/// Why a run ended where it did: the fact that ended it, as data.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum EndReason {
    /// The event that ended it: a bump, a planning failure, a refused request.
    Event {
        /// The event.
        event: EventKind,
    },
    /// The status it came to rest in (stopped off the goal).
    Status {
        /// The status.
        status: Status,
    },
    /// A component went to Error.
    ComponentError {
        /// Its instance name.
        component: &'static str,
        /// Why, if known.
        reason: Option<Reason>,
    },
    /// SafeMode or Clear stopped the robot.
    Halted,
    /// The time limit was reached.
    TimeLimit {
        /// The limit \[s\].
        seconds: f64,
    },
    /// The run has not ended yet.
    Running,
}

impl EndReason {
    /// Whether `planner` (`GlobalPathPlanning`, `LocalPathPlanning`) is the one whose failure
    /// ended the run.
    pub fn is_failure_of(&self, planner: &str) -> bool {
        matches!(self, Self::Event { event: EventKind::PlanningFailed { planner: p, .. } } if p == planner)
    }
}

/// What a run measured (the runner's summary, the tests' checks).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ScenarioReport {
    /// The scenario.
    pub name: String,
    /// How it ended.
    pub outcome: Outcome,
    /// Simulated time at the end \[s\].
    pub sim_time: f64,
    /// Distance the robot's centre drove \[m\].
    pub path_length: f64,
    /// Local (potential-field) plans made.
    pub replans: u64,
    /// Global plans sent.
    pub global_plans: u64,
    /// Smallest distance from the robot's centre to an obstacle cell while driving \[m\]
    /// (infinite if the robot never ran).
    pub min_clearance: f64,
    /// `radiusOfBodyArea` \[m\] (MotorControl's): the clearance must stay at or above it.
    pub body_radius: f64,
    /// Bumps.
    pub bumps: u64,
    /// Planning-failure notices.
    pub planning_failures: u64,
    /// The robot's pose at the end.
    pub final_pose: Pose,
    /// The goal at the end.
    pub goal: Option<Pose>,
    /// Distance from the goal at the end \[m\].
    pub position_error: f64,
    /// Heading error at the end \[°\].
    pub heading_error_deg: f64,
    /// Heading error when the robot reached the goal position, before its final turn \[°\]
    /// (NaN if it never did): what the plan's posture term achieved.
    pub approach_heading_deg: f64,
    /// The map's cell size \[m\].
    pub grid_size: f64,
    /// Telemetry samples taken.
    pub samples: u64,
    /// SHA-256 over every telemetry sample.
    pub trace_hash: String,
    /// The scenario's expectation checked ([`ScenarioReport::check`]): every problem found.
    pub expectation: Result<(), String>,
}

impl ScenarioReport {
    /// Checks the run against `expect` and the rules every run keeps: arrival within one
    /// cell and [`ARRIVAL_HEADING_DEG`], no bump and clearance never below
    /// `radiusOfBodyArea` (unless a bump is expected), at least `min_replans` local plans,
    /// the failing planner named. Returns every problem found.
    pub fn check(&self, expect: &Expectation) -> Result<(), String> {
        let mut problems = Vec::new();
        if self.outcome.kind != expect.outcome {
            problems.push(format!(
                "outcome {:?} ({:?}), expected {:?}",
                self.outcome.kind, self.outcome.reason, expect.outcome
            ));
        }
        if self.replans < expect.min_replans {
            problems.push(format!(
                "{} local plans, expected at least {}",
                self.replans, expect.min_replans
            ));
        }
        if expect.outcome == OutcomeKind::Arrived {
            if self.position_error.is_nan() || self.position_error > self.grid_size {
                problems.push(format!(
                    "{:.4} m from the goal, more than one cell ({} m)",
                    self.position_error, self.grid_size
                ));
            }
            if self.heading_error_deg.is_nan() || self.heading_error_deg > ARRIVAL_HEADING_DEG {
                problems.push(format!(
                    "heading {:.2}° off the goal's, more than {ARRIVAL_HEADING_DEG}°",
                    self.heading_error_deg
                ));
            }
        }
        if expect.outcome != OutcomeKind::Bumped {
            if self.bumps > 0 {
                problems.push(format!("{} bumps", self.bumps));
            }
            if self.min_clearance < self.body_radius {
                problems.push(format!(
                    "clearance went down to {:.4} m, below radiusOfBodyArea {} m",
                    self.min_clearance, self.body_radius
                ));
            }
        }
        if expect.outcome == OutcomeKind::PlanningFailed
            && let Some(p) = &expect.planner
            && !self
                .outcome
                .reason
                .as_ref()
                .is_some_and(|r| r.is_failure_of(p))
        {
            problems.push(format!(
                "the failure came from {:?}, expected {p}",
                self.outcome.reason
            ));
        }
        if problems.is_empty() {
            Ok(())
        } else {
            Err(problems.join("; "))
        }
    }
}

impl fmt::Display for ScenarioReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "scenario        {}", self.name)?;
        writeln!(f, "outcome         {:?}", self.outcome.kind)?;
        writeln!(f, "simulated time  {:.3} s", self.sim_time)?;
        writeln!(f, "path length     {:.3} m", self.path_length)?;
        writeln!(
            f,
            "replans         {} local, {} global",
            self.replans, self.global_plans
        )?;
        if self.min_clearance.is_finite() {
            writeln!(
                f,
                "min clearance   {:.4} m (radiusOfBodyArea {} m)",
                self.min_clearance, self.body_radius
            )?;
        } else {
            writeln!(f, "min clearance   - (the robot did not run)")?;
        }
        if self.approach_heading_deg.is_finite() {
            writeln!(
                f,
                "approach        {:.2}° off the goal heading before the final turn",
                self.approach_heading_deg
            )?;
        }
        writeln!(
            f,
            "final pose      ({:.3}, {:.3}, {:.2}°), {:.4} m and {:.2}° from the goal",
            self.final_pose.x,
            self.final_pose.y,
            self.final_pose.theta.to_degrees(),
            self.position_error,
            self.heading_error_deg
        )?;
        write!(f, "trace hash      {}", self.trace_hash)
    }
}

/// A scenario being run: the system, its timeline, the outcome once known.
#[derive(Debug)]
pub struct ScenarioRun {
    scenario: Scenario,
    system: System,
    timeline: Timeline,
    limit_ns: u64,
    outcome: Option<Outcome>,
    event_cursor: u64,
    refused: Option<EventKind>,
    still_since: Option<u64>,
}

impl ScenarioRun {
    /// Builds the set-up of `scenario` ([`setup::build`], files through `resolver`), then
    /// activates every component: the drive starts, and with it the scenario's timeline.
    pub fn new(scenario: &Scenario, resolver: &dyn FileResolver) -> crate::Result<Self> {
        Self::with_setup(scenario, resolver, &Setup::of(scenario))
    }

    /// As [`ScenarioRun::new`], with `setup`'s changes to the scenario.
    pub fn with_setup(
        scenario: &Scenario,
        resolver: &dyn FileResolver,
        setup: &Setup,
    ) -> crate::Result<Self> {
        let mut system = setup::build(scenario, resolver, setup, BuildOptions::default())?;
        let start_ns = system.time_ns();
        system.apply(&Input::ActivateAll)?;
        Ok(Self {
            scenario: scenario.clone(),
            system,
            timeline: Timeline::new(&scenario.events),
            limit_ns: start_ns + secs_to_ns(scenario.time_limit),
            outcome: None,
            event_cursor: 0,
            refused: None,
            still_since: None,
        })
    }

    /// Stops the run at `seconds` of simulated time instead of the scenario's limit (the
    /// runner's `--until`).
    pub fn set_limit(&mut self, seconds: f64) -> crate::Result<()> {
        if !(seconds.is_finite() && seconds >= 0.0) {
            return Err(SystemError::BadNumber {
                what: "until seconds",
                value: seconds,
                non_negative: true,
            }
            .into());
        }
        if let Some(reason) = beyond_replay_limit_s(&format!("until {seconds} s"), seconds) {
            return Err(ScenarioError::Scenario {
                scenario: self.scenario.name.clone(),
                reason,
            }
            .into());
        }
        self.limit_ns = secs_to_ns(seconds);
        Ok(())
    }

    /// The time limit \[s\].
    pub fn limit(&self) -> f64 {
        self.limit_ns as f64 * 1e-9
    }

    /// The scenario.
    pub fn scenario(&self) -> &Scenario {
        &self.scenario
    }

    /// The system.
    pub fn system(&self) -> &System {
        &self.system
    }

    /// The system, the run left behind.
    pub fn into_system(self) -> System {
        self.system
    }

    /// Carries out a request during the run, as a person would ([`System::apply`]); a
    /// refused one changes nothing.
    pub fn apply(&mut self, input: &Input) -> crate::Result<()> {
        self.system.apply(input)
    }

    /// The outcome, once the run has ended.
    pub fn outcome(&self) -> Option<&Outcome> {
        self.outcome.as_ref()
    }

    /// Runs at most `max_ticks` base ticks, fewer if the run ends. Returns the outcome once
    /// it is known.
    pub fn advance(&mut self, max_ticks: u64) -> Option<&Outcome> {
        for _ in 0..max_ticks {
            if self.outcome.is_some() {
                break;
            }
            self.timeline.run(&mut self.system, 1);
            self.outcome = judge(
                &self.system,
                self.timeline.pending() > 0,
                &mut self.event_cursor,
                &mut self.refused,
                &mut self.still_since,
                self.limit_ns,
            );
        }
        self.outcome.as_ref()
    }

    /// Runs to the end.
    pub fn run_to_end(&mut self) -> &Outcome {
        loop {
            if self.advance(1_000).is_some() {
                break;
            }
        }
        match &self.outcome {
            Some(o) => o,
            None => unreachable!("the loop ends with an outcome"),
        }
    }

    /// What the run measured so far (the outcome is `TimeLimit` "running" until it ends).
    pub fn report(&self) -> ScenarioReport {
        let s = &self.system;
        let stats = s.stats();
        let pose = s.robot_pose();
        let goal = s.mission().goal();
        let (position_error, heading_error_deg) = goal.map_or((f64::NAN, f64::NAN), |g| {
            (
                libm::hypot(pose.x - g.x, pose.y - g.y),
                angle_diff(pose.theta, g.theta).abs().to_degrees(),
            )
        });
        let mut report = ScenarioReport {
            name: self.scenario.name.clone(),
            outcome: self.outcome.clone().unwrap_or(Outcome {
                kind: OutcomeKind::TimeLimit,
                reason: Some(EndReason::Running),
            }),
            sim_time: s.time(),
            path_length: stats.path_length,
            replans: stats.local_plans,
            global_plans: stats.global_plans,
            min_clearance: stats.min_clearance,
            body_radius: s.wiring().motor_geometry().radius_of_body_area,
            bumps: stats.bumps,
            planning_failures: stats.planning_failures,
            final_pose: pose,
            goal,
            position_error,
            heading_error_deg,
            approach_heading_deg: s
                .mission()
                .approach_heading_error()
                .map_or(f64::NAN, f64::to_degrees),
            grid_size: s.map().map_or(f64::NAN, |m| m.grid_size()),
            samples: s.record().telemetry().total(),
            trace_hash: s.record().telemetry().trace_hash(),
            expectation: Ok(()),
        };
        report.expectation = report.check(&self.scenario.expect);
        report
    }
}

/// The outcome of the run after a tick, if it has ended: arrival (the mission's `Arrived`,
/// at rest within the goal's tolerances), a bump, a component in Error, resting for
/// [`STILL_NS`] off the goal after DriveControl finished ([`Status::StoppedOffGoal`]) or
/// after a planning failure, a refused request or a halt, or the time limit. `cursor` counts the events read, `refused` holds the last refused
/// request, `still_since` when the robot came to stand. While `events_to_come` (the
/// scenario's timeline has events still to come: an operator's Reset, say), a component in
/// Error does not end the run.
pub fn judge(
    system: &System,
    events_to_come: bool,
    cursor: &mut u64,
    refused: &mut Option<EventKind>,
    still_since: &mut Option<u64>,
    limit_ns: u64,
) -> Option<Outcome> {
    let mut end = None;
    for e in system.record().events_since(*cursor) {
        match &e.kind {
            EventKind::Arrived { .. } => {
                end.get_or_insert(Outcome {
                    kind: OutcomeKind::Arrived,
                    reason: None,
                });
            }
            EventKind::Bump { .. } => {
                end = Some(Outcome {
                    kind: OutcomeKind::Bumped,
                    reason: Some(EndReason::Event {
                        event: e.kind.clone(),
                    }),
                });
            }
            EventKind::RequestRefused { .. } => *refused = Some(e.kind.clone()),
            EventKind::GoalSet { .. } => *refused = None,
            _ => {}
        }
    }
    *cursor = system.record().event_count();
    if end.is_some() {
        return end;
    }
    if system.state() == SystemState::Error && !events_to_come {
        let ec = system.wiring().execution_context();
        let reason = ComponentKind::ALL
            .into_iter()
            .find(|k| ec.state(k.index()).ok() == Some(LifecycleState::Error))
            .map(|k| EndReason::ComponentError {
                component: k.instance_name(),
                reason: ec.last_error(k.index()).ok().flatten().cloned(),
            });
        return Some(Outcome {
            kind: OutcomeKind::ComponentError,
            reason,
        });
    }
    let now = system.time_ns();
    let wiring = system.wiring();
    let resting = Measured::of(wiring).at_rest();
    // A script in DriveControl's place has no phase: it is idle while it commands nothing.
    let idle = match wiring.drive_phase() {
        Some(phase) => phase == DrivePhase::Idle,
        None => wiring.drive_stands(),
    };
    let failure = system.mission().failure().or(refused.as_ref()).cloned();
    let off_goal = match system.status() {
        s @ Status::StoppedOffGoal { .. } => Some(s),
        _ => None,
    };
    let stopped = idle && (failure.is_some() || system.mission().is_halted());
    if resting && (stopped || off_goal.is_some()) {
        let since = *still_since.get_or_insert(now);
        if now - since >= STILL_NS {
            return Some(match (off_goal, failure) {
                (Some(status), _) => Outcome {
                    kind: OutcomeKind::StoppedOffGoal,
                    reason: Some(EndReason::Status { status }),
                },
                (None, Some(event)) => Outcome {
                    kind: OutcomeKind::PlanningFailed,
                    reason: Some(EndReason::Event { event }),
                },
                (None, None) => Outcome {
                    kind: OutcomeKind::Halted,
                    reason: Some(EndReason::Halted),
                },
            });
        }
    } else {
        *still_since = None;
    }
    (now >= limit_ns).then_some(Outcome {
        kind: OutcomeKind::TimeLimit,
        reason: Some(EndReason::TimeLimit {
            seconds: limit_ns as f64 * 1e-9,
        }),
    })
}

/// Runs `scenario` to its outcome (files through `resolver`) and reports, the expectation
/// checked ([`ScenarioReport::expectation`]).
pub fn run_scenario(
    scenario: &Scenario,
    resolver: &dyn FileResolver,
) -> crate::Result<ScenarioReport> {
    let mut run = ScenarioRun::new(scenario, resolver)?;
    run.run_to_end();
    Ok(run.report())
}
