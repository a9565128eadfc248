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
//! Active, as the timeline's). The exercise ends when the run ends: at arrival (the
//! system's, at rest within the goal's tolerances, spec §7), at a bump, or at the
//! scenario's `time_limit` after the start. A check that fails on the way does not end it:
//! the others go on being decided, and every measured value goes on being measured, until
//! the run ends. Then every check still open is settled — none is left undecided (spec §7
//! Decision 0.3 "exercise checks"): a check that waits for something (arrival, a speed, a
//! recovery) fails, a check that forbids something (a bump, too many plans) passes.
//!
//! **Decision (the verdict as soon as it is decided, spec §7 Decision 0.4)**: the verdict
//! is [`Verdict::Failed`] while the run goes on as soon as it can no longer pass — a check
//! failed, or, left alone, the robot stands where nothing moves it ([`Stuck`]) and the end
//! would fail a check — and [`ExerciseStatus::decided_by`] names the check.
//!
//! **Decision (values)**: a check's measured value has one meaning and one unit
//! ([`Check::unit`]), decided or not: the time of arrival \[s\], the heading error \[°\],
//! the clearance \[m\], the plans made, the fastest speed within the time a speed must be
//! reached in \[m/s\], the overshoot \[%\], the distance driven backward \[m\]. The heading
//! checks are decided with a value also when the robot came to rest off the goal (spec §7:
//! it has not arrived, and the status says how far off it stopped): the heading error at
//! rest, and the one it came to the goal position with, if it did.
//!
//! **Decision (the rules)**: besides its checks, an exercise always checks that only the
//! parameters of `may_change` differ from the scenario's configuration (`dmin` is one value
//! for both planners, spec §3 Decision 0.2), and that no parameter in use is one the page
//! warns about ([`ParameterWarning`](crate::system::ParameterWarning): a `dmin` at which the body
//! can touch, gains that make a wheel's loop unstable or limp) — spec §7 Decision 0.3: a
//! value the page warns about never passes. Before the drive both are shown and may be put
//! right; once the robot drives, a difference or a warning fails the exercise.

use core::fmt;
use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use crate::errors::ScenarioError;
use crate::present::number;
use crate::system::simulation::robot::System;
use crate::system::vocabulary::kind::ComponentKind;

/// An exercise (module documentation).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
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
    /// In an exercise with code (spec §8), the component the student writes and the
    /// template the student starts from.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub script: Option<ScriptTask>,
}

/// The component a student writes in an exercise with code (spec §8), and where its
/// template is.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct ScriptTask {
    /// DriveControl or MotorControl.
    pub component: ComponentKind,
    /// The template's path, from the repository's root (a `.rhai` file).
    pub template: String,
}

/// One check of an exercise.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
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
    /// DriveControl's first speed command. Measured: the fastest speed in that time
    /// \[m/s\].
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
    /// Localization's position stayed within `at_most_m` of the robot's true position
    /// while driving. Measured: the largest distance between them \[m\].
    MaxLocalizationError {
        /// Metres.
        at_most_m: f64,
    },
    /// Localization's heading stayed within `at_most_deg` of the robot's true heading
    /// while driving. Measured: the largest difference \[°\].
    MaxLocalizationHeadingError {
        /// Degrees.
        at_most_deg: f64,
    },
    /// A component went to Error while driving, and every component that did was made
    /// Active again (Reset, then Activate).
    Recovered,
    /// Only the parameters the exercise names were changed (always checked; module
    /// documentation).
    OnlyAllowed,
    /// No parameter in use is one the page warns about (always checked; module
    /// documentation).
    NoWarning,
}

/// The unit of a check's measured value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub enum Unit {
    /// Seconds.
    #[serde(rename = "s")]
    Seconds,
    /// Degrees.
    #[serde(rename = "deg")]
    Degrees,
    /// Metres.
    #[serde(rename = "m")]
    Metres,
    /// Plans made (a count).
    #[serde(rename = "plans")]
    Plans,
    /// Percent.
    #[serde(rename = "percent")]
    Percent,
    /// Metres per second.
    #[serde(rename = "m/s")]
    MetresPerSecond,
}

impl fmt::Display for Unit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Seconds => " s",
            Self::Degrees => "°",
            Self::Metres => " m",
            Self::Plans => " plans",
            Self::Percent => " %",
            Self::MetresPerSecond => " m/s",
        })
    }
}

impl Check {
    /// The unit of the value measured for this check (`None`: it measures none).
    pub fn unit(&self) -> Option<Unit> {
        match self {
            Self::Arrived { .. } => Some(Unit::Seconds),
            Self::ReachSpeed { .. } => Some(Unit::MetresPerSecond),
            Self::ArrivalHeading { .. }
            | Self::ApproachHeading { .. }
            | Self::MaxLocalizationHeadingError { .. } => Some(Unit::Degrees),
            Self::MinClearance { .. }
            | Self::BackwardDistance { .. }
            | Self::MaxLocalizationError { .. } => Some(Unit::Metres),
            Self::MaxReplans { .. } | Self::MinReplans { .. } | Self::MinGlobalPlans { .. } => {
                Some(Unit::Plans)
            }
            Self::MaxOvershoot { .. } => Some(Unit::Percent),
            Self::NoBump | Self::Recovered | Self::OnlyAllowed | Self::NoWarning => None,
        }
    }

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
            Self::MaxLocalizationError { at_most_m } => vec![("at_most_m", at_most_m)],
            Self::MaxLocalizationHeadingError { at_most_deg } => {
                vec![("at_most_deg", at_most_deg)]
            }
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
            Self::MaxLocalizationError { at_most_m } => write!(
                f,
                "Localization's position within {} m of the robot's",
                number(*at_most_m)
            ),
            Self::MaxLocalizationHeadingError { at_most_deg } => write!(
                f,
                "Localization's heading within {}° of the robot's",
                number(*at_most_deg)
            ),
            Self::Recovered => write!(f, "recover from the fault (Reset, then Activate)"),
            Self::OnlyAllowed => write!(f, "change only the parameters named"),
            Self::NoWarning => write!(f, "no parameter the page warns about"),
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
            if let Check::OnlyAllowed | Check::NoWarning = check {
                let name = if matches!(check, Check::OnlyAllowed) {
                    "only_allowed"
                } else {
                    "no_warning"
                };
                return Err(err(format!(
                    "checks[{i}]: {name} is always checked; do not list it"
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
    pub(in crate::system) fn allows(&self, component: ComponentKind, name: &str) -> bool {
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
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
#[serde(rename_all = "snake_case")]
pub enum CheckState {
    /// Not decided yet (only while the run goes on).
    Open,
    /// Passed.
    Passed,
    /// Failed.
    Failed,
}

/// How the exercise stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// The drive has not started.
    Waiting,
    /// The robot drives; checks are being decided.
    Running,
    /// Ended with every check passed.
    Passed,
    /// The run can no longer pass (spec §7 Decision 0.4, the verdict as soon as it is
    /// decided): a check failed for good, or — left alone — the robot stands where nothing
    /// will move it ([`Stuck`]); [`ExerciseStatus::decided_by`] names the check. Also the
    /// verdict of an exercise that ended with a check failed.
    Failed,
}

/// Why a run, left alone (nothing more asked of it than its scenario's timeline and
/// recorded requests), can no longer pass: the robot stands and nothing the system does on
/// its own moves it again (spec §7 Decision 0.4).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Stuck {
    /// A component is in Error: only a Reset recovers it.
    ComponentError {
        /// Its instance name.
        component: String,
    },
    /// A component the drive needs is Inactive: only an Activate starts it.
    Inactive {
        /// Its instance name.
        component: String,
    },
    /// GlobalPathPlanning found no route; it tries again only when the map or `dmin`
    /// changes.
    NoRoute,
    /// The robot came to rest off the goal with the path driven.
    StoppedOffGoal,
    /// SafeMode or Clear halted it until the next goal.
    Halted,
}

/// What decided an exercise's verdict (spec §7 Decision 0.4).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct DecidedBy {
    /// The check that decided it: its index in [`ExerciseStatus::checks`].
    pub check: usize,
    /// Why the run, left alone, cannot pass while that check is still open; `None` when
    /// the check failed for good.
    pub stuck: Option<Stuck>,
}

/// One check as it stands (the page's checklist line, `rtnav check`'s line).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct CheckStatus {
    /// The check and its numbers.
    pub check: Check,
    /// Where it stands.
    pub state: CheckState,
    /// What was measured so far, in [`CheckStatus::unit`]; `None` when nothing yet.
    pub measured: Option<f64>,
    /// The unit of `measured` ([`Check::unit`]).
    pub unit: Option<Unit>,
    /// For [`Check::OnlyAllowed`]: the parameters changed that may not be
    /// (`Component.Parameter`).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub changed: Vec<String>,
    /// For [`Check::NoWarning`]: the parameters in use that the page warns about
    /// (`Component.Parameter`).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warned: Vec<String>,
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
            match self.unit {
                Some(u) => write!(f, " (measured {}{u})", number(m))?,
                None => write!(f, " (measured {})", number(m))?,
            }
        }
        if !self.changed.is_empty() {
            write!(f, " (changed: {})", self.changed.join(", "))?;
        }
        if !self.warned.is_empty() {
            write!(f, " (warned: {})", self.warned.join(", "))?;
        }
        Ok(())
    }
}

/// The exercise as it stands.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct ExerciseStatus {
    /// The task.
    pub task: String,
    /// The parameters that may be changed.
    pub may_change: Vec<String>,
    /// The actions expected.
    pub actions: Vec<String>,
    /// Each check, then the rules [`Check::OnlyAllowed`] and [`Check::NoWarning`] last.
    pub checks: Vec<CheckStatus>,
    /// The verdict.
    pub verdict: Verdict,
    /// What decided a `Failed` verdict: the check that failed first, or the check that a
    /// run left alone cannot pass and why; `None` otherwise.
    pub decided_by: Option<DecidedBy>,
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
