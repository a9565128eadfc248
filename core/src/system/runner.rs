//! The scenario runner: builds the system from a [`Scenario`], drives it to its outcome and
//! reports what happened (SPEC §6: the same scenario gives the same trace bit for bit).

use core::fmt;

use serde::Serialize;

use super::events::EventKind;
use super::kind::ComponentKind;
use super::runtime::{System, SystemState};
use super::scenario::{Expectation, FileResolver, OutcomeKind, Scenario, ScenarioEvent};
use crate::errors::SystemError;
use crate::interfaces::Pose;
use crate::motion::{DrivePhase, angle_diff};

/// How long the robot must stand still, without a path, after a planning failure (or
/// SafeMode / Clear) for the run to end there \[ns\].
pub const STILL_NS: u64 = 1_000_000_000;
/// Below this speed \[m/s\] and turn rate \[rad/s\] the robot stands still.
const STILL_SPEED: f64 = 1e-3;
/// Arrival: the heading within this many degrees of the goal's.
pub const ARRIVAL_HEADING_DEG: f64 = 10.0;

/// How a run ended, and why.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Outcome {
    /// The kind.
    pub kind: OutcomeKind,
    /// The reason in words (the failure, the bump, …).
    pub reason: String,
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
                "outcome {:?} ({}), expected {:?}",
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
            && !self.outcome.reason.starts_with(p.as_str())
        {
            problems.push(format!(
                "the failure came from `{}`, expected {p}",
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
        writeln!(
            f,
            "outcome         {:?}{}",
            self.outcome.kind,
            if self.outcome.reason.is_empty() {
                String::new()
            } else {
                format!(": {}", self.outcome.reason)
            }
        )?;
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

/// A scenario being run: the system, the events still to come, the outcome once known.
#[derive(Debug)]
pub struct ScenarioRun {
    scenario: Scenario,
    system: System,
    /// Non-map events still to apply, with their times \[ns\].
    pending: Vec<(u64, ScenarioEvent)>,
    limit_ns: u64,
    outcome: Option<Outcome>,
    event_cursor: u64,
    failure: Option<String>,
    still_since: Option<u64>,
}

fn secs_to_ns(s: f64) -> u64 {
    libm::round(s * 1e9) as u64
}

impl ScenarioRun {
    /// Builds the system for `scenario`: rates, configuration overrides, the map (through
    /// `resolver`), start and goal, the timed map updates queued on MapMaintenance; then
    /// activates every component.
    pub fn new(scenario: &Scenario, resolver: &dyn FileResolver) -> crate::Result<Self> {
        let mut system = System::from_scenario(scenario, resolver)?;
        let pending = scenario
            .events
            .iter()
            .filter(|e| !matches!(e, ScenarioEvent::MapUpdate { .. }))
            .map(|e| (secs_to_ns(e.at()), e.clone()))
            .collect();
        system.activate_all();
        Ok(Self {
            scenario: scenario.clone(),
            system,
            pending,
            limit_ns: secs_to_ns(scenario.time_limit),
            outcome: None,
            event_cursor: 0,
            failure: None,
            still_since: None,
        })
    }

    /// Stops the run at `seconds` of simulated time instead of the scenario's limit (the
    /// runner's `--until`).
    pub fn set_limit(&mut self, seconds: f64) -> Result<(), SystemError> {
        if !(seconds.is_finite() && seconds >= 0.0) {
            return Err(SystemError::BadNumber {
                what: "until seconds",
                value: seconds,
                non_negative: true,
            });
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

    /// The system, mutably (e.g. to change the telemetry capacity).
    pub fn system_mut(&mut self) -> &mut System {
        &mut self.system
    }

    /// The outcome, once the run has ended.
    pub fn outcome(&self) -> Option<&Outcome> {
        self.outcome.as_ref()
    }

    /// Runs at most `max_ticks` base ticks, fewer if the run ends. Returns the outcome once
    /// it is known.
    pub fn advance(&mut self, max_ticks: u64) -> crate::Result<Option<&Outcome>> {
        for _ in 0..max_ticks {
            if self.outcome.is_some() {
                break;
            }
            self.apply_due_events()?;
            self.system.step(1);
            self.observe();
        }
        Ok(self.outcome.as_ref())
    }

    /// Runs to the end.
    pub fn run_to_end(&mut self) -> crate::Result<&Outcome> {
        while self.outcome.is_none() {
            self.advance(1_000)?;
        }
        match &self.outcome {
            Some(o) => Ok(o),
            None => unreachable!("the loop ends with an outcome"),
        }
    }

    fn apply_due_events(&mut self) -> crate::Result<()> {
        let now = self.system.time_ns();
        while let Some((at, _)) = self.pending.first()
            && *at <= now
        {
            let (_, e) = self.pending.remove(0);
            match e {
                ScenarioEvent::Goal {
                    goal, direction, ..
                } => {
                    // A refused goal is part of the story (an event), not an abort.
                    if let Err(err) = self.system.set_goal(goal.pose(), direction.direction()) {
                        self.failure = Some(format!("SetPosition: {err}"));
                    } else {
                        self.failure = None;
                    }
                }
                ScenarioEvent::SafeMode { .. } => self.system.safe_mode(),
                ScenarioEvent::Clear { .. } => self.system.clear(),
                ScenarioEvent::MapUpdate { .. } => {}
            }
        }
        Ok(())
    }

    /// After a tick: what the new events say, and whether the run has ended.
    fn observe(&mut self) {
        let count = self.system.event_count();
        if count != self.event_cursor {
            let n = (count - self.event_cursor).min(self.system.events().len() as u64) as usize;
            let events = self.system.events();
            let new = events.iter().skip(events.len() - n);
            let mut end = None;
            for e in new {
                match &e.kind {
                    EventKind::Arrived { .. } => {
                        end.get_or_insert(Outcome {
                            kind: OutcomeKind::Arrived,
                            reason: String::new(),
                        });
                    }
                    EventKind::Bump { report } => {
                        end = Some(Outcome {
                            kind: OutcomeKind::Bumped,
                            reason: report.to_string(),
                        });
                    }
                    EventKind::PlanningFailed { planner, reason } => {
                        self.failure = Some(format!("{planner}: {reason}"));
                    }
                    EventKind::LocalPlanSent { cells, .. } if *cells > 0 => {
                        self.failure = None;
                    }
                    EventKind::GoalSet { .. } => self.failure = None,
                    _ => {}
                }
            }
            self.event_cursor = count;
            if end.is_some() {
                self.outcome = end;
                return;
            }
        }
        if self.system.state() == SystemState::Error {
            let reason = ComponentKind::ALL
                .into_iter()
                .find_map(|k| {
                    self.system
                        .component_info(k)
                        .last_error
                        .map(|e| format!("{k}: {e}"))
                })
                .unwrap_or_default();
            self.outcome = Some(Outcome {
                kind: OutcomeKind::ComponentError,
                reason,
            });
            return;
        }
        let now = self.system.time_ns();
        let (v, w) = self.system.physics().physics().body_velocity();
        let idle = matches!(
            self.system.drive_control().pursuit().phase(),
            DrivePhase::Idle
        );
        let still = v.abs() < STILL_SPEED && w.abs() < STILL_SPEED && idle;
        if still && (self.failure.is_some() || self.system.is_halted()) {
            let since = *self.still_since.get_or_insert(now);
            if now - since >= STILL_NS {
                self.outcome = Some(match &self.failure {
                    Some(reason) => Outcome {
                        kind: OutcomeKind::PlanningFailed,
                        reason: reason.clone(),
                    },
                    None => Outcome {
                        kind: OutcomeKind::Halted,
                        reason: "SafeMode or Clear".to_owned(),
                    },
                });
                return;
            }
        } else {
            self.still_since = None;
        }
        if now >= self.limit_ns {
            self.outcome = Some(Outcome {
                kind: OutcomeKind::TimeLimit,
                reason: format!("stopped at {} s", self.limit()),
            });
        }
    }

    /// What the run measured so far (the outcome is `TimeLimit` "running" until it ends).
    pub fn report(&self) -> ScenarioReport {
        let s = &self.system;
        let stats = s.stats();
        let pose = s.robot_pose();
        let goal = s.goal();
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
                reason: "still running".to_owned(),
            }),
            sim_time: s.time(),
            path_length: stats.path_length,
            replans: stats.local_plans,
            global_plans: stats.global_plans,
            min_clearance: stats.min_clearance,
            body_radius: s.motor_control().geometry().radius_of_body_area,
            bumps: stats.bumps,
            planning_failures: stats.planning_failures,
            final_pose: pose,
            goal,
            position_error,
            heading_error_deg,
            grid_size: s.map().map_or(f64::NAN, |m| m.grid_size()),
            samples: s.telemetry().total(),
            trace_hash: s.telemetry().trace_hash(),
            expectation: Ok(()),
        };
        report.expectation = report.check(&self.scenario.expect);
        report
    }
}

impl System {
    /// The system of `scenario`, ready to run: built with its rates, its configuration
    /// overrides applied, its map loaded (through `resolver`), start and goal set (the robot
    /// placed at the start), its map updates queued on MapMaintenance. Every component is
    /// still Inactive; the other timed events are the runner's ([`ScenarioRun`]).
    pub fn from_scenario(scenario: &Scenario, resolver: &dyn FileResolver) -> crate::Result<Self> {
        scenario.validate()?;
        let fail = |what: &str, e: crate::Error| SystemError::Scenario {
            scenario: scenario.name.clone(),
            reason: format!("{what}: {e}"),
        };
        let mut system = System::new(scenario.rates).map_err(|e| fail("rates", e))?;
        for (component, params) in &scenario.config {
            let kind = ComponentKind::from_name(component)?;
            let cfg = system.config_mut(kind).map_err(|e| fail("config", e))?;
            for (name, &value) in params {
                cfg.set(name, value)
                    .map_err(|e| fail(&format!("config {component}"), e.into()))?;
            }
        }
        let map = scenario.load_map(resolver).map_err(|e| fail("map", e))?;
        system.load_map(map);
        system
            .set_position(
                scenario.start.pose(),
                scenario.goal.pose(),
                scenario.direction.direction(),
            )
            .map_err(|e| fail("start and goal", e))?;
        for (i, e) in scenario.events.iter().enumerate() {
            if let ScenarioEvent::MapUpdate {
                boxes,
                cells,
                value,
                at,
            } = e
            {
                let Some(map) = system.map() else {
                    return Err(SystemError::NoMap { call: "MapUpdate" }.into());
                };
                let update = Scenario::map_update(map, boxes, cells, *value);
                system
                    .schedule_map_update(secs_to_ns(*at), update)
                    .map_err(|e| fail(&format!("events[{i}]"), e))?;
            }
        }
        Ok(system)
    }

    /// Loads the map of `source` through `resolver`; on any error the held map stays and
    /// nothing changes (SPEC §2: "the previously held map stays").
    pub fn load_map_from(
        &mut self,
        source: &super::scenario::MapSource,
        resolver: &dyn FileResolver,
    ) -> crate::Result<()> {
        let map = source.load(resolver)?;
        self.load_map(map);
        Ok(())
    }
}

/// Runs `scenario` to its outcome (files through `resolver`) and reports, the expectation
/// checked ([`ScenarioReport::expectation`]).
pub fn run_scenario(
    scenario: &Scenario,
    resolver: &dyn FileResolver,
) -> crate::Result<ScenarioReport> {
    let mut run = ScenarioRun::new(scenario, resolver)?;
    run.run_to_end()?;
    Ok(run.report())
}
