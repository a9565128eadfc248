//! Exercises: a scenario's task in a sentence, the parameters a student may change, and
//! checks the core evaluates while the robot drives — from the record's facts (events) and
//! telemetry samples, each stamped with its simulated time, so the verdict is the same
//! however often it is looked at (every tick in `rtnav check`, once a frame in the page).
//!
//! ```json
//! "exercise": {
//!   "task": "Let the robot cut the corner, but with at most one new local plan.",
//!   "may_change": ["LocalPathPlanning.Deviatinglen"],
//!   "actions": [],
//!   "checks": [
//!     { "check": "arrived", "within_s": 60 },
//!     { "check": "no_bump" },
//!     { "check": "max_replans", "at_most": 1 }
//!   ]
//! }
//! ```
//!
//! **Decision (the drive)**: times count from the start of the drive (the physics made
//! Active, as the timeline's). The exercise ends at arrival, at a bump, when a check has
//! failed (the verdict cannot change any more) or at the scenario's `time_limit` after the
//! start. Then every check still open is settled: a check that waits for something
//! (arrival, a speed, a recovery) fails, a check that forbids something (a bump, too many
//! plans) passes.
//!
//! **Decision (the rules)**: besides its checks, an exercise always checks that only the
//! parameters of `may_change` differ from the scenario's configuration (`dmin` is one value
//! for both planners, spec §3 Decision 0.2). Before the drive this is shown and may be put
//! right; once the robot drives, a difference fails the exercise.

use core::fmt;
use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::events::EventKind;
use super::kind::ComponentKind;
use super::robot::System;
use crate::errors::ScenarioError;
use crate::present::number;

/// An exercise (module documentation).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Exercise {
    /// The task in a sentence.
    pub task: String,
    /// The parameters the student may change, as `Component.Parameter` (seed names).
    #[serde(default)]
    pub may_change: Vec<String>,
    /// The actions the student is expected to take (lifecycle requests, in words such as
    /// `Reset`, `Activate`); shown, not checked — the checks judge what they achieve.
    #[serde(default)]
    pub actions: Vec<String>,
    /// What is checked, in the order shown.
    pub checks: Vec<Check>,
}

/// One check of an exercise.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "check", rename_all = "snake_case", deny_unknown_fields)]
pub enum Check {
    /// DriveControl reached the goal within `within_s` seconds of the drive's start.
    Arrived {
        /// Seconds.
        within_s: f64,
    },
    /// The robot never touched an obstacle.
    NoBump,
    /// On arrival (after DriveControl's final turn), the heading was within `within_deg`
    /// of the goal's.
    ArrivalHeading {
        /// Degrees.
        within_deg: f64,
    },
    /// At the goal position, before the final turn on the spot, the heading was within
    /// `within_deg` of the goal's (the posture the path achieved).
    ApproachHeading {
        /// Degrees.
        within_deg: f64,
    },
    /// The robot's centre stayed at least `at_least_m` from every obstacle cell.
    MinClearance {
        /// Metres.
        at_least_m: f64,
    },
    /// At most this many new local (potential-field) plans while driving.
    MaxReplans {
        /// Plans.
        at_most: u64,
    },
    /// At least this many new local plans while driving.
    MinReplans {
        /// Plans.
        at_least: u64,
    },
    /// At least this many global plans while driving (GlobalPathPlanning planned again).
    MinGlobalPlans {
        /// Plans.
        at_least: u64,
    },
    /// The robot's speed came within `band_percent` of `speed` within `within_s` of
    /// DriveControl's first speed command.
    ReachSpeed {
        /// \[m/s\].
        speed: f64,
        /// Seconds.
        within_s: f64,
        /// Percent of `speed`.
        band_percent: f64,
    },
    /// The robot's speed never went more than `at_most_percent` above `speed`.
    MaxOvershoot {
        /// \[m/s\].
        speed: f64,
        /// Percent of `speed`.
        at_most_percent: f64,
    },
    /// The robot drove at least `at_least_m` backward.
    BackwardDistance {
        /// Metres.
        at_least_m: f64,
    },
    /// A component went to Error while driving, and every component that did was made
    /// Active again (Reset, then Activate).
    Recovered,
    /// Only the parameters the exercise names were changed (always checked; module
    /// documentation).
    OnlyAllowed,
}

impl Check {
    fn numbers(&self) -> Vec<(&'static str, f64)> {
        match *self {
            Self::Arrived { within_s } => vec![("within_s", within_s)],
            Self::ApproachHeading { within_deg } | Self::ArrivalHeading { within_deg } => {
                vec![("within_deg", within_deg)]
            }
            Self::MinClearance { at_least_m } => vec![("at_least_m", at_least_m)],
            Self::ReachSpeed {
                speed,
                within_s,
                band_percent,
            } => vec![
                ("speed", speed),
                ("within_s", within_s),
                ("band_percent", band_percent),
            ],
            Self::MaxOvershoot {
                speed,
                at_most_percent,
            } => vec![("speed", speed), ("at_most_percent", at_most_percent)],
            Self::BackwardDistance { at_least_m } => vec![("at_least_m", at_least_m)],
            _ => Vec::new(),
        }
    }
}

impl fmt::Display for Check {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Arrived { within_s } => write!(f, "arrive within {} s", number(*within_s)),
            Self::NoBump => write!(f, "no bump"),
            Self::ArrivalHeading { within_deg } => {
                write!(f, "end within {}° of the goal heading", number(*within_deg))
            }
            Self::ApproachHeading { within_deg } => write!(
                f,
                "reach the goal within {}° of its heading before the final turn",
                number(*within_deg)
            ),
            Self::MinClearance { at_least_m } => {
                write!(f, "clearance at least {} m", number(*at_least_m))
            }
            Self::MaxReplans { at_most } => write!(f, "new local plans while driving ≤ {at_most}"),
            Self::MinReplans { at_least } => {
                write!(f, "new local plans while driving ≥ {at_least}")
            }
            Self::MinGlobalPlans { at_least } => {
                write!(f, "global plans while driving ≥ {at_least}")
            }
            Self::ReachSpeed {
                speed,
                within_s,
                band_percent,
            } => write!(
                f,
                "reach {} m/s (within {} %) in {} s",
                number(*speed),
                number(*band_percent),
                number(*within_s)
            ),
            Self::MaxOvershoot {
                speed,
                at_most_percent,
            } => write!(
                f,
                "overshoot {} m/s by at most {} %",
                number(*speed),
                number(*at_most_percent)
            ),
            Self::BackwardDistance { at_least_m } => {
                write!(f, "drive at least {} m backward", number(*at_least_m))
            }
            Self::Recovered => write!(f, "recover from the fault (Reset, then Activate)"),
            Self::OnlyAllowed => write!(f, "change only the parameters named"),
        }
    }
}

impl Exercise {
    /// Checks what serde cannot: a task, at least one check, positive finite numbers,
    /// `Component.Parameter` names of known components.
    pub fn validate(&self, scenario: &str) -> Result<(), ScenarioError> {
        let err = |reason: String| ScenarioError::Scenario {
            scenario: scenario.to_owned(),
            reason: format!("exercise: {reason}"),
        };
        if self.task.trim().is_empty() {
            return Err(err("the task is empty".to_owned()));
        }
        if self.checks.is_empty() {
            return Err(err("no checks".to_owned()));
        }
        for (i, check) in self.checks.iter().enumerate() {
            if matches!(check, Check::OnlyAllowed) {
                return Err(err(format!(
                    "checks[{i}]: only_allowed is always checked; do not list it"
                )));
            }
            for (what, v) in check.numbers() {
                if !(v.is_finite() && v > 0.0) {
                    return Err(err(format!(
                        "checks[{i}].{what} = {v} must be positive and finite"
                    )));
                }
            }
        }
        for name in &self.may_change {
            let (component, param) = name
                .split_once('.')
                .ok_or_else(|| err(format!("may_change `{name}`: expected Component.Parameter")))?;
            ComponentKind::from_name(component)
                .map_err(|e| err(format!("may_change `{name}`: {e}")))?;
            if param.is_empty() {
                return Err(err(format!("may_change `{name}`: no parameter named")));
            }
        }
        Ok(())
    }

    /// Whether `component`'s parameter `name` may be changed.
    fn allows(&self, component: ComponentKind, name: &str) -> bool {
        self.may_change.iter().any(|m| {
            m.split_once('.').is_some_and(|(c, p)| {
                p == name
                    && (c == component.name()
                        || (name == "dmin"
                            && component.holds_dmin()
                            && ComponentKind::from_name(c).is_ok_and(ComponentKind::holds_dmin)))
            })
        })
    }
}

/// Where a check stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum CheckState {
    /// Not decided yet.
    Open,
    /// Passed.
    Passed,
    /// Failed.
    Failed,
}

/// How the exercise stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// The drive has not started.
    Waiting,
    /// The robot drives; checks are being decided.
    Running,
    /// Ended with every check passed.
    Passed,
    /// Ended with at least one check failed.
    Failed,
}

/// One check as it stands (the page's checklist line, `rtnav check`'s line).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CheckStatus {
    /// The check and its numbers.
    pub check: Check,
    /// Where it stands.
    pub state: CheckState,
    /// What was measured so far, in the check's unit (seconds, degrees, metres, plans,
    /// percent); `None` when nothing yet.
    pub measured: Option<f64>,
    /// For [`Check::OnlyAllowed`]: the parameters changed that may not be
    /// (`Component.Parameter`).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub changed: Vec<String>,
}

impl fmt::Display for CheckStatus {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mark = match self.state {
            CheckState::Open => "[ ]",
            CheckState::Passed => "[x]",
            CheckState::Failed => "[!]",
        };
        write!(f, "{mark} {}", self.check)?;
        if let Some(m) = self.measured {
            write!(f, " (measured {})", number(m))?;
        }
        if !self.changed.is_empty() {
            write!(f, " (changed: {})", self.changed.join(", "))?;
        }
        Ok(())
    }
}

/// The exercise as it stands.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ExerciseStatus {
    /// The task.
    pub task: String,
    /// The parameters that may be changed.
    pub may_change: Vec<String>,
    /// The actions expected.
    pub actions: Vec<String>,
    /// Each check, then the rule [`Check::OnlyAllowed`] last.
    pub checks: Vec<CheckStatus>,
    /// The verdict.
    pub verdict: Verdict,
    /// When the drive started \[s of simulated time\].
    pub started_at: Option<f64>,
    /// When the exercise ended, counted from the drive's start \[s\].
    pub ended_after: Option<f64>,
}

impl fmt::Display for ExerciseStatus {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "task     {}", self.task)?;
        for c in &self.checks {
            writeln!(f, "  {c}")?;
        }
        let verdict = match self.verdict {
            Verdict::Waiting => "waiting for the drive",
            Verdict::Running => "running",
            Verdict::Passed => "PASSED",
            Verdict::Failed => "FAILED",
        };
        write!(f, "verdict  {verdict}")?;
        if let Some(t) = self.ended_after {
            write!(f, " after {} s", number(round3(t)))?;
        }
        Ok(())
    }
}

/// Four decimals: what a person reads (the state is decided on the exact value).
fn round4(v: f64) -> f64 {
    libm::round(v * 1e4) / 1e4
}

fn round3(v: f64) -> f64 {
    libm::round(v * 1000.0) / 1000.0
}

/// Every parameter's requested value, by component and name.
pub type ParameterValues = BTreeMap<(ComponentKind, String), f64>;

/// The requested value of every parameter of every configured component of `system`.
pub fn parameter_values(system: &System) -> ParameterValues {
    let mut out = BTreeMap::new();
    for kind in ComponentKind::ALL {
        if let Ok(config) = system.wiring().config(kind) {
            for spec in config.specs() {
                if let Ok(v) = config.value(spec.name) {
                    out.insert((kind, spec.name.to_owned()), v);
                }
            }
        }
    }
    out
}

/// What a check has seen so far.
#[derive(Debug, Clone, PartialEq)]
struct Progress {
    state: CheckState,
    measured: Option<f64>,
}

/// An exercise being watched: fed the system after any number of ticks, it reads the facts
/// and samples since it last looked (module documentation).
#[derive(Debug, Clone)]
pub struct ExerciseWatch {
    exercise: Exercise,
    time_limit_ns: u64,
    baseline: ParameterValues,
    progress: Vec<Progress>,
    rule: Progress,
    changed: Vec<String>,
    events_seen: u64,
    samples_seen: u64,
    started_ns: Option<u64>,
    ended_ns: Option<u64>,
    /// Time of the previous sample while driving \[ns\].
    last_sample_ns: Option<u64>,
    /// DriveControl's first speed command \[ns\].
    command_ns: Option<u64>,
    replans: u64,
    global_plans: u64,
    backward_m: f64,
    max_speed: f64,
    faulted: Vec<String>,
    fault_seen: bool,
}

impl ExerciseWatch {
    /// Watches `exercise` on a system built with the scenario's own configuration,
    /// `baseline` ([`parameter_values`] of it); the exercise ends at the latest
    /// `time_limit_s` after the drive's start. Events and samples already in the record
    /// are not the exercise's.
    pub fn new(
        exercise: &Exercise,
        time_limit_s: f64,
        baseline: ParameterValues,
        system: &System,
    ) -> Self {
        let open = Progress {
            state: CheckState::Open,
            measured: None,
        };
        let mut watch = Self {
            exercise: exercise.clone(),
            time_limit_ns: libm::round(time_limit_s * 1e9) as u64,
            baseline,
            progress: vec![open.clone(); exercise.checks.len()],
            rule: open,
            changed: Vec::new(),
            events_seen: system.record().event_count(),
            samples_seen: system.record().telemetry().total(),
            started_ns: None,
            ended_ns: None,
            last_sample_ns: None,
            command_ns: None,
            replans: 0,
            global_plans: 0,
            backward_m: 0.0,
            max_speed: 0.0,
            faulted: Vec::new(),
            fault_seen: false,
        };
        if system.is_driving() {
            watch.started_ns = Some(system.time_ns());
        }
        watch.check_rule(system);
        watch
    }

    /// The exercise.
    pub fn exercise(&self) -> &Exercise {
        &self.exercise
    }

    /// Whether the exercise has ended.
    pub fn ended(&self) -> bool {
        self.ended_ns.is_some()
    }

    /// Reads what happened since the last look: the record's new events, then its new
    /// telemetry samples, then the time limit. Does nothing once ended.
    pub fn observe(&mut self, system: &System) {
        if self.ended() {
            return;
        }
        let record = system.record();
        let events: Vec<_> = record.events_since(self.events_seen).cloned().collect();
        self.events_seen = record.event_count();
        let samples: Vec<_> = record
            .telemetry()
            .since(self.samples_seen)
            .copied()
            .collect();
        self.samples_seen = record.telemetry().total();
        // Both in time order, merged (a sample before an event of the same time).
        let (mut e, mut s) = (events.iter().peekable(), samples.iter().peekable());
        loop {
            let time_ns = match (e.peek(), s.peek()) {
                (Some(ev), Some(sa)) if sa.time_ns <= ev.time_ns => {
                    let sa = s.next().copied();
                    sa.map(|sa| {
                        self.on_sample(sa.time_ns, sa.v_cmd, sa.v);
                        sa.time_ns
                    })
                }
                (Some(_), _) => e.next().map(|ev| {
                    self.on_event(ev.time_ns, &ev.kind, system);
                    ev.time_ns
                }),
                (None, Some(_)) => s.next().map(|sa| {
                    self.on_sample(sa.time_ns, sa.v_cmd, sa.v);
                    sa.time_ns
                }),
                (None, None) => None,
            };
            let Some(time_ns) = time_ns else { break };
            if self.started_ns.is_some() && self.any_failed() {
                self.end_early(time_ns);
            }
            if self.ended() {
                return;
            }
        }
        self.check_rule(system);
        let clearance = system.stats().min_clearance;
        if let Some(start) = self.started_ns {
            self.on_clearance(clearance);
            let now = system.time_ns();
            if now.saturating_sub(start) >= self.time_limit_ns {
                self.end(start.saturating_add(self.time_limit_ns));
            } else {
                self.deadlines(now);
            }
        }
    }

    fn on_event(&mut self, time_ns: u64, kind: &EventKind, system: &System) {
        let physics = ComponentKind::PhysicsSim.instance_name();
        if self.started_ns.is_none() {
            if let EventKind::StateChanged { component, to, .. } = kind
                && component == physics
                && *to == crate::rtc::LifecycleState::Active
            {
                self.started_ns = Some(time_ns);
            }
            return;
        }
        match kind {
            EventKind::LocalPlanSent { replanned, .. } if *replanned => {
                self.replans += 1;
                self.set_count(
                    |c| matches!(c, Check::MaxReplans { .. } | Check::MinReplans { .. }),
                    self.replans,
                );
            }
            EventKind::GlobalPlan { .. } => {
                self.global_plans += 1;
                self.set_count(
                    |c| matches!(c, Check::MinGlobalPlans { .. }),
                    self.global_plans,
                );
            }
            EventKind::ComponentError { component, .. } => {
                self.fault_seen = true;
                if !self.faulted.contains(component) {
                    self.faulted.push(component.clone());
                }
            }
            EventKind::StateChanged { component, to, .. }
                if *to == crate::rtc::LifecycleState::Active =>
            {
                self.faulted.retain(|c| c != component);
                if self.fault_seen && self.faulted.is_empty() {
                    self.decide(|c| matches!(c, Check::Recovered), CheckState::Passed, None);
                }
            }
            EventKind::Bump { .. } => {
                self.decide(|c| matches!(c, Check::NoBump), CheckState::Failed, None);
                self.on_clearance(system.stats().min_clearance);
                self.end(time_ns);
            }
            EventKind::Arrived {
                approach_heading_error,
                heading_error,
                ..
            } => {
                let after = self.since_start(time_ns);
                for (check, p) in self.exercise.checks.iter().zip(&mut self.progress) {
                    match check {
                        Check::Arrived { within_s } if p.state == CheckState::Open => {
                            p.measured = Some(after);
                            p.state = pass_if(after <= *within_s);
                        }
                        Check::ArrivalHeading { within_deg } => {
                            let deg = heading_error.abs().to_degrees();
                            p.measured = Some(deg);
                            p.state = pass_if(deg <= *within_deg);
                        }
                        Check::ApproachHeading { within_deg } => {
                            let deg = approach_heading_error.to_degrees();
                            p.measured = deg.is_finite().then_some(deg);
                            p.state = pass_if(deg.is_finite() && deg <= *within_deg);
                        }
                        _ => {}
                    }
                }
                self.on_clearance(system.stats().min_clearance);
                self.end(time_ns);
            }
            _ => {}
        }
    }

    fn on_sample(&mut self, time_ns: u64, v_cmd: f64, v: f64) {
        let Some(start) = self.started_ns else {
            return;
        };
        if time_ns < start {
            return;
        }
        if let Some(last) = self.last_sample_ns
            && v < 0.0
        {
            self.backward_m += -v * (time_ns - last) as f64 * 1e-9;
        }
        self.last_sample_ns = Some(time_ns);
        if self.command_ns.is_none() && v_cmd > 0.0 {
            self.command_ns = Some(time_ns);
        }
        self.max_speed = self.max_speed.max(v);
        let (command, backward, max_speed) = (self.command_ns, self.backward_m, self.max_speed);
        for (check, p) in self.exercise.checks.iter().zip(&mut self.progress) {
            if p.state != CheckState::Open {
                continue;
            }
            match *check {
                Check::ReachSpeed {
                    speed,
                    within_s,
                    band_percent,
                } => {
                    let Some(c) = command else { continue };
                    let after = (time_ns - c) as f64 * 1e-9;
                    if v >= speed * (1.0 - band_percent / 100.0) && after <= within_s {
                        p.measured = Some(after);
                        p.state = CheckState::Passed;
                    } else if after > within_s {
                        p.measured = Some(max_speed);
                        p.state = CheckState::Failed;
                    }
                }
                Check::MaxOvershoot {
                    speed,
                    at_most_percent,
                } => {
                    let over = (max_speed / speed - 1.0) * 100.0;
                    p.measured = Some(over.max(0.0));
                    if over > at_most_percent {
                        p.state = CheckState::Failed;
                    }
                }
                Check::BackwardDistance { at_least_m } => {
                    p.measured = Some(backward);
                    if backward >= at_least_m {
                        p.state = CheckState::Passed;
                    }
                }
                _ => {}
            }
        }
    }

    fn on_clearance(&mut self, clearance: f64) {
        for (check, p) in self.exercise.checks.iter().zip(&mut self.progress) {
            if let Check::MinClearance { at_least_m } = *check
                && p.state == CheckState::Open
            {
                p.measured = clearance.is_finite().then_some(clearance);
                if clearance < at_least_m {
                    p.state = CheckState::Failed;
                }
            }
        }
    }

    /// Fails `arrived` checks whose time is up.
    fn deadlines(&mut self, now: u64) {
        let after = self.since_start(now);
        for (check, p) in self.exercise.checks.iter().zip(&mut self.progress) {
            if let Check::Arrived { within_s } = *check
                && p.state == CheckState::Open
                && after > within_s
            {
                p.state = CheckState::Failed;
            }
        }
        if self.any_failed() {
            self.end_early(now);
        }
    }

    fn set_count(&mut self, which: impl Fn(&Check) -> bool, count: u64) {
        for (check, p) in self.exercise.checks.iter().zip(&mut self.progress) {
            if !which(check) || p.state != CheckState::Open {
                continue;
            }
            p.measured = Some(count as f64);
            match *check {
                Check::MaxReplans { at_most } if count > at_most => p.state = CheckState::Failed,
                Check::MinReplans { at_least } | Check::MinGlobalPlans { at_least }
                    if count >= at_least =>
                {
                    p.state = CheckState::Passed;
                }
                _ => {}
            }
        }
    }

    fn decide(&mut self, which: impl Fn(&Check) -> bool, state: CheckState, measured: Option<f64>) {
        for (check, p) in self.exercise.checks.iter().zip(&mut self.progress) {
            if which(check) && p.state == CheckState::Open {
                p.state = state;
                if measured.is_some() {
                    p.measured = measured;
                }
            }
        }
    }

    fn check_rule(&mut self, system: &System) {
        let now = parameter_values(system);
        let mut changed = Vec::new();
        for ((kind, name), value) in &now {
            let same = self
                .baseline
                .get(&(*kind, name.clone()))
                .is_some_and(|b| b.to_bits() == value.to_bits());
            if !same && !self.exercise.allows(*kind, name) {
                changed.push(format!("{}.{name}", kind.name()));
            }
        }
        if self.rule.state == CheckState::Failed && self.started_ns.is_some() {
            // Sticky once the drive has started: keep what was first found.
            return;
        }
        self.rule.state = if changed.is_empty() {
            CheckState::Passed
        } else {
            CheckState::Failed
        };
        self.changed = changed;
        if self.started_ns.is_some() && self.rule.state == CheckState::Failed {
            self.end_early(system.time_ns());
        }
    }

    fn any_failed(&self) -> bool {
        self.progress.iter().any(|p| p.state == CheckState::Failed)
    }

    fn since_start(&self, time_ns: u64) -> f64 {
        self.started_ns
            .map_or(0.0, |s| time_ns.saturating_sub(s) as f64 * 1e-9)
    }

    /// Ends the exercise at `time_ns` because a check failed: the verdict cannot change; the
    /// checks still open stay open (nothing decided them).
    fn end_early(&mut self, time_ns: u64) {
        if !self.ended() {
            self.ended_ns = Some(time_ns);
        }
    }

    /// Ends the exercise at `time_ns` (arrival, a bump, the time limit): every open check is
    /// settled (module documentation).
    fn end(&mut self, time_ns: u64) {
        if self.ended() {
            return;
        }
        self.ended_ns = Some(time_ns);
        let (replans, global_plans) = (self.replans, self.global_plans);
        for (check, p) in self.exercise.checks.iter().zip(&mut self.progress) {
            match check {
                Check::MaxReplans { .. } | Check::MinReplans { .. } if p.measured.is_none() => {
                    p.measured = Some(replans as f64);
                }
                Check::MinGlobalPlans { .. } if p.measured.is_none() => {
                    p.measured = Some(global_plans as f64);
                }
                _ => {}
            }
        }
        let faulted = self.fault_seen && self.faulted.is_empty();
        for (check, p) in self.exercise.checks.iter().zip(&mut self.progress) {
            if p.state != CheckState::Open {
                continue;
            }
            p.state = match check {
                Check::NoBump
                | Check::MinClearance { .. }
                | Check::MaxReplans { .. }
                | Check::MaxOvershoot { .. } => CheckState::Passed,
                Check::Recovered => pass_if(faulted),
                Check::Arrived { .. }
                | Check::ApproachHeading { .. }
                | Check::ArrivalHeading { .. }
                | Check::MinReplans { .. }
                | Check::MinGlobalPlans { .. }
                | Check::ReachSpeed { .. }
                | Check::BackwardDistance { .. }
                | Check::OnlyAllowed => CheckState::Failed,
            };
        }
    }

    /// The exercise as it stands.
    pub fn status(&self) -> ExerciseStatus {
        let mut checks: Vec<CheckStatus> = self
            .exercise
            .checks
            .iter()
            .zip(&self.progress)
            .map(|(check, p)| CheckStatus {
                check: check.clone(),
                state: p.state,
                measured: p.measured.map(round4),
                changed: Vec::new(),
            })
            .collect();
        checks.push(CheckStatus {
            check: Check::OnlyAllowed,
            state: self.rule.state,
            measured: None,
            changed: self.changed.clone(),
        });
        let verdict = match (self.started_ns, self.ended_ns) {
            (None, _) => Verdict::Waiting,
            (Some(_), None) => Verdict::Running,
            (Some(_), Some(_)) if checks.iter().all(|c| c.state == CheckState::Passed) => {
                Verdict::Passed
            }
            _ => Verdict::Failed,
        };
        ExerciseStatus {
            task: self.exercise.task.clone(),
            may_change: self.exercise.may_change.clone(),
            actions: self.exercise.actions.clone(),
            checks,
            verdict,
            started_at: self.started_ns.map(|s| s as f64 * 1e-9),
            ended_after: self.ended_ns.map(|e| self.since_start(e)),
        }
    }
}

fn pass_if(ok: bool) -> CheckState {
    if ok {
        CheckState::Passed
    } else {
        CheckState::Failed
    }
}
