//! [`ExerciseRun`]: a scenario's exercise done headlessly (`rtnav check`, the tests) — the
//! same set-up as the page ([`setup::build`]), the student's configuration loaded as the
//! page loads a `.conf` ([`Input::LoadConf`]), the drive started with Activate all, the
//! student's timed requests applied, and the [`ExerciseWatch`] fed until the exercise ends.

use super::exercise::{ExerciseStatus, parameter_values};
use super::exercise_watch::ExerciseWatch;
use super::scenario::{FileResolver, Scenario};
use std::collections::BTreeMap;

use super::setup::{self, BuildOptions, PLAN_SECONDS, ScriptText, Setup};
use super::timeline::{Timeline, secs_to_ns};
use crate::errors::ScenarioError;
use crate::system::simulation::robot::System;
use crate::system::vocabulary::input::Input;

/// How many base ticks run between two looks of the watch (it reads time-stamped facts,
/// so this changes nothing but the cost; the record keeps far more than this many).
const LOOK_TICKS: u64 = 100;

/// A request the student makes at a time counted from the drive's start \[s\] (a replay's
/// inputs, once replays exist; the tests' reference solutions).
#[derive(Debug, Clone, PartialEq)]
pub struct DriveInput {
    /// Seconds after the drive's start.
    pub at: f64,
    /// The request.
    pub input: Input,
}

/// An exercise being done headlessly (module documentation).
#[derive(Debug)]
pub struct ExerciseRun {
    system: System,
    timeline: Timeline,
    watch: ExerciseWatch,
    inputs: Vec<(u64, Input)>,
    next_input: usize,
    refused: Vec<String>,
}

impl ExerciseRun {
    /// Builds `scenario` as the page does, loads `conf` (an OpenRTM `.conf` bundle as the
    /// page saves it; parameters not in it keep the scenario's values), plans, and starts
    /// the drive. Errors: a scenario without an exercise, a set-up that fails, a `.conf`
    /// that is refused (all or nothing), a timed input that is not finite or not in order.
    pub fn new(
        scenario: &Scenario,
        resolver: &dyn FileResolver,
        conf: Option<&str>,
        inputs: &[DriveInput],
    ) -> crate::Result<Self> {
        Self::with_scripts(scenario, resolver, &BTreeMap::new(), conf, inputs)
    }

    /// As [`ExerciseRun::new`], with students' scripts in components' places (spec §8:
    /// component → script, loaded as the set-up loads them, [`Setup::scripts`]). A script
    /// that does not load fails the run with its error (line and column).
    pub fn with_scripts(
        scenario: &Scenario,
        resolver: &dyn FileResolver,
        scripts: &BTreeMap<String, ScriptText>,
        conf: Option<&str>,
        inputs: &[DriveInput],
    ) -> crate::Result<Self> {
        let err = |reason: String| ScenarioError::Scenario {
            scenario: scenario.name.clone(),
            reason,
        };
        let exercise = scenario
            .exercise
            .as_ref()
            .ok_or_else(|| err("it has no exercise".to_owned()))?;
        let mut last = 0.0;
        for (i, t) in inputs.iter().enumerate() {
            if !(t.at.is_finite() && t.at >= last) {
                return Err(err(format!(
                    "timed input {i} at {} s: times must be finite, ≥ 0 and in order",
                    t.at
                ))
                .into());
            }
            last = t.at;
        }
        let mut setup = Setup::of(scenario);
        setup.scripts = scripts.clone();
        let mut system = setup::build(scenario, resolver, &setup, BuildOptions::default())?;
        let baseline = parameter_values(&system);
        if let Some(text) = conf {
            system.apply(&Input::LoadConf {
                text: text.to_owned(),
            })?;
            system.run_until_planned(PLAN_SECONDS)?;
        }
        let watch = ExerciseWatch::new(exercise, scenario.time_limit, baseline, &system);
        system.apply(&Input::ActivateAll)?;
        Ok(Self {
            system,
            timeline: Timeline::new(&scenario.events),
            watch,
            inputs: inputs
                .iter()
                .map(|t| (secs_to_ns(t.at), t.input.clone()))
                .collect(),
            next_input: 0,
            refused: Vec::new(),
        })
    }

    /// The system.
    pub fn system(&self) -> &System {
        &self.system
    }

    /// The timed inputs that were refused, with the reason (the run goes on without them).
    pub fn refused(&self) -> &[String] {
        &self.refused
    }

    /// Runs until the exercise has ended and returns how it stands.
    pub fn run_to_end(&mut self) -> ExerciseStatus {
        while !self.watch.ended() {
            self.timeline.run(&mut self.system, 1);
            let origin = self.timeline.origin_ns();
            let mut chunk = LOOK_TICKS;
            if let (Some(origin), Some((at, _))) = (origin, self.inputs.get(self.next_input)) {
                let due = origin.saturating_add(*at);
                let now = self.system.time_ns();
                if due <= now {
                    let input = self.inputs[self.next_input].1.clone();
                    self.next_input += 1;
                    if let Err(e) = self.system.apply(&input) {
                        self.refused.push(format!("{}: {e}", input.describe()));
                    }
                    chunk = 0;
                } else {
                    let base = self.system.wiring().execution_context().base_period_ns();
                    chunk = chunk.min((due - now).div_ceil(base));
                }
            }
            if chunk > 1 {
                self.timeline.run(&mut self.system, chunk - 1);
            }
            let more_to_come = self.timeline.pending() > 0 || self.next_input < self.inputs.len();
            self.watch.observe(&self.system, more_to_come);
        }
        self.watch.status()
    }
}

/// Does `scenario`'s exercise with `conf` and `inputs` ([`ExerciseRun`]) and returns the
/// verdict.
pub fn check_exercise(
    scenario: &Scenario,
    resolver: &dyn FileResolver,
    conf: Option<&str>,
    inputs: &[DriveInput],
) -> crate::Result<ExerciseStatus> {
    Ok(ExerciseRun::new(scenario, resolver, conf, inputs)?.run_to_end())
}
