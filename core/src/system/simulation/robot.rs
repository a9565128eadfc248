//! [`System`]: the wiring, the mission and the record composed — the whole robot, stepped in
//! simulated time, taking [`Input`]s.
//!
//! **Architecture invariant**: nothing of a user interface lives here — no clock, no script,
//! no preview, no drawing buffers. The page, the runner and the tests drive this same value
//! through [`System::apply`] and [`System::step`]; drawing reads `&System`.

use core::fmt;

use super::mission::Mission;
use super::record::{Record, RunStats};
use super::status::{ComponentInfo, Status, SystemState};
use super::wiring::{Report, Wiring};
use crate::errors::LocalPathError;
use crate::interfaces::Pose;
use crate::map::{GridMap, MapUpdate};
use crate::reason::Reason;
use crate::rtc::{LifecycleState, Time, period_ticks};
use crate::system::vocabulary::error::SystemError;
use crate::system::vocabulary::events::EventKind;
use crate::system::vocabulary::input::{Input, RequestSource};
use crate::system::vocabulary::kind::ComponentKind;
use crate::system::vocabulary::rates::Rates;
use crate::system::vocabulary::run_limit::check_run_length;

/// The whole robot (module documentation; the wiring is listed in `crate::system`).
pub struct System {
    wiring: Wiring,
    mission: Mission,
    record: Record,
    rates: Rates,
}

impl fmt::Debug for System {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("System")
            .field("time_ns", &self.time_ns())
            .field("state", &self.state())
            .field("mission", &self.mission)
            .field("stats", &self.record.stats())
            .finish()
    }
}

impl System {
    /// The system at `rates`: every component created (Inactive), ports connected, the
    /// execution context Running, no map.
    pub fn new(rates: Rates) -> crate::Result<Self> {
        let wiring = Wiring::new(rates)?;
        let base = wiring.execution_context().base_period_ns();
        let telemetry = period_ticks("telemetry", rates.telemetry, base)?;
        let mut system = Self {
            wiring,
            mission: Mission::new(),
            record: Record::new(telemetry),
            rates,
        };
        system.settle();
        Ok(system)
    }

    /// A copy in the same state that shares nothing with this one (a replay's checkpoint):
    /// stepped with the same inputs, the two stay identical bit for bit. `None` while an
    /// injected sample waits for its component ([`Wiring::try_clone`]).
    pub fn try_clone(&self) -> Option<Self> {
        Some(Self {
            wiring: self.wiring.try_clone()?,
            mission: self.mission.clone(),
            record: self.record.clone(),
            rates: self.rates,
        })
    }

    /// Keeps only the newest `keep` telemetry samples (a checkpoint's copy; the trace hash
    /// goes on over every sample).
    pub(in crate::system) fn trim_telemetry(&mut self, keep: usize) {
        self.record.trim_telemetry(keep);
    }

    // ------------------------------------------------------------------ inputs
    /// Carries out one request (the one interpreter of [`Input`]); a refused one changes nothing.
    pub fn apply(&mut self, input: &Input) -> crate::Result<()> {
        super::placement::check(input, &self.wiring, &self.mission)?;
        let w = &mut self.wiring;
        let result = match input {
            Input::SetPosition {
                start,
                goal,
                direction,
            } => {
                if w.is_driving() {
                    Err(SystemError::Driving {
                        call: "SetPosition",
                    }
                    .into())
                } else {
                    w.set_position(*start, *goal, *direction, true)
                }
            }
            Input::SetGoal { goal, direction } => {
                // Planned from where the robot is: what it believes while driving, its pose
                // otherwise (e.g. after a bump and a reset, where it is placed again).
                let not_finite = [
                    ("GoalX", goal.x),
                    ("GoalY", goal.y),
                    ("GoalAngle", goal.theta),
                ]
                .into_iter()
                .find(|(_, v)| !v.is_finite());
                if self.mission.start().is_none() {
                    Err(SystemError::NoStart { call: "SetGoal" }.into())
                } else if let Some((argument, value)) = not_finite {
                    // Said as the request made, not as the SetPosition it becomes.
                    Err(LocalPathError::NotFinite {
                        call: "SetGoal",
                        argument,
                        value,
                    }
                    .into())
                } else if w.is_driving() {
                    let start = w.localization().current_pose();
                    w.set_position(start, *goal, *direction, false)
                } else {
                    let start = w.robot_pose();
                    w.set_position(start, *goal, *direction, true)
                }
            }
            Input::MapUpdate { cells } => {
                // A cell beyond i32 (no map has one) is refused as sent, before the
                // service's i32 arrays would clamp it.
                let huge = cells
                    .iter()
                    .find(|c| i32::try_from(c.0).is_err() || i32::try_from(c.1).is_err());
                match (w.map(), huge) {
                    (Some(map), Some(&(x, y, _))) => Err(SystemError::CellOutsideMap {
                        x,
                        y,
                        width: map.width(),
                        height: map.height(),
                    }
                    .into()),
                    _ => w
                        .map_update(MapUpdate::from_cells(cells, Time::default()))
                        .map(drop),
                }
            }
            Input::Clear => {
                w.clear();
                Ok(())
            }
            Input::SafeMode => {
                w.safe_mode();
                Ok(())
            }
            Input::Activate { component } => w.activate(*component).map(drop),
            Input::Deactivate { component } => w.deactivate(*component).map(drop),
            Input::Reset { component } => w.reset(*component).map(drop),
            Input::ActivateAll => {
                w.activate_set(&ComponentKind::ALL);
                Ok(())
            }
            Input::DeactivateAll => {
                w.deactivate_all();
                Ok(())
            }
            Input::ResetAll => {
                w.reset_all();
                Ok(())
            }
            Input::InjectFault { component, reason } => w.inject_fault(*component, reason),
            Input::InjectInput {
                component,
                port,
                data,
            } => w.inject_input(*component, port, data.clone()),
            Input::SetParam {
                component,
                name,
                value,
            } => w.set_param(*component, name, *value),
            Input::SetPdGain { p_l, p_r, d_l, d_r } => w.set_pd_gain(*p_l, *p_r, *d_l, *d_r),
            Input::LoadConf { text } => w.load_conf(text),
            Input::SetRate { component, hz } => match w.set_rate(*component, *hz) {
                Ok(()) => {
                    self.rates.set(*component, *hz);
                    Ok(())
                }
                Err(e) => Err(e.into()),
            },
            Input::CutConnection { connection } => w.set_connection_cut(connection, true),
            Input::RestoreConnection { connection } => w.set_connection_cut(connection, false),
            Input::LoadScript { .. } | Input::UseBuiltIn { .. } => w.replace_in_place(input),
        };
        self.settle();
        result
    }

    /// [`System::apply`] for a request the system is given on someone's behalf (a
    /// scenario's timeline, a replay): a refusal is logged as
    /// [`EventKind::RequestRefused`] naming `source`. Returns whether it was carried out.
    pub fn apply_logged(&mut self, input: &Input, source: RequestSource) -> bool {
        match self.apply(input) {
            Ok(()) => true,
            Err(e) => {
                let report = Report {
                    time_ns: self.time_ns(),
                    tick: None,
                    facts: vec![EventKind::RequestRefused {
                        source,
                        request: input.summary(),
                        reason: Reason::Error(e),
                    }],
                };
                self.record.observe(&report, &self.wiring);
                false
            }
        }
    }

    /// Loads `map` (MapBuilder's `SetMap` reaches every component at once). The goal and the
    /// paths are dropped (they belong to the old map); the robot is not moved. A map that
    /// cannot be read never gets here (`GridMap` is valid by construction).
    pub fn load_map(&mut self, map: GridMap) {
        self.wiring.load_map(map);
        self.settle();
    }

    /// Whether LocalPathPlanning computes the whole potential field (for the heat map) or
    /// stops at the robot's cell (faster; the same path).
    pub fn set_full_field(&mut self, full: bool) {
        self.wiring.set_full_field(full);
    }

    /// Samples telemetry at `hz` (its period a whole number of base ticks).
    pub fn set_telemetry_rate(&mut self, hz: f64) -> crate::Result<()> {
        let base = self.wiring.execution_context().base_period_ns();
        self.record
            .set_telemetry_period(period_ticks("telemetry", hz, base)?);
        self.rates.telemetry = hz;
        Ok(())
    }

    /// Keeps the newest `capacity` telemetry samples (the trace hash covers all of them).
    pub fn set_telemetry_capacity(&mut self, capacity: usize) -> crate::Result<()> {
        Ok(self.record.set_telemetry_capacity(capacity)?)
    }

    /// The facts of the requests since the last tick, to the mission and the record.
    fn settle(&mut self) {
        let facts = self.wiring.take_facts();
        if facts.is_empty() {
            return;
        }
        let mut report = Report {
            time_ns: self.time_ns(),
            tick: None,
            facts,
        };
        self.mission.observe(&mut report, &self.wiring);
        self.record.observe(&report, &self.wiring);
    }

    // ------------------------------------------------------------------ running

    fn tick(&mut self) {
        let mut report = self.wiring.tick();
        self.mission.observe(&mut report, &self.wiring);
        self.record.observe(&report, &self.wiring);
    }

    /// Runs `ticks` base ticks.
    pub fn step(&mut self, ticks: u64) {
        for _ in 0..ticks {
            self.tick();
        }
    }

    fn ticks_in(&self, seconds: f64, what: &'static str) -> Result<u64, SystemError> {
        if !(seconds.is_finite() && seconds >= 0.0) {
            return Err(SystemError::BadNumber {
                what,
                value: seconds,
                non_negative: true,
            });
        }
        check_run_length(what, seconds)?;
        let base = self.wiring.execution_context().base_period_ns();
        Ok((seconds * 1e9 / base as f64) as u64)
    }

    /// Runs for `seconds` of simulated time (rounded down to whole base ticks); more than a
    /// run goes ([`MAX_REPLAY_NS`](crate::system::MAX_REPLAY_NS), 24 h) is refused
    /// ([`SystemError::RunTooLong`]).
    pub fn run_for(&mut self, seconds: f64) -> crate::Result<()> {
        let ticks = self.ticks_in(seconds, "run_for seconds")?;
        self.step(ticks);
        Ok(())
    }

    /// Runs until `stop(self)` is true (checked after every tick) or `max_seconds` of
    /// simulated time have passed (at most 24 h, as [`System::run_for`]). Returns whether
    /// `stop` said so.
    pub fn run_until(
        &mut self,
        max_seconds: f64,
        mut stop: impl FnMut(&System) -> bool,
    ) -> crate::Result<bool> {
        let ticks = self.ticks_in(max_seconds, "run_until max_seconds")?;
        for _ in 0..ticks {
            self.tick();
            if stop(self) {
                return Ok(true);
            }
        }
        Ok(false)
    }

    /// Runs until the planners have nothing left to do ([`Wiring::planning_settled`]), at
    /// least one tick and at most `max_seconds`. Returns whether they settled.
    pub fn run_until_planned(&mut self, max_seconds: f64) -> crate::Result<bool> {
        self.run_until(max_seconds, |s| s.wiring.planning_settled())
    }

    // ------------------------------------------------------------------ read-outs

    /// The components, their ports and services.
    pub fn wiring(&self) -> &Wiring {
        &self.wiring
    }

    /// The task and its progress.
    pub fn mission(&self) -> &Mission {
        &self.mission
    }

    /// The log, totals, trail and telemetry.
    pub fn record(&self) -> &Record {
        &self.record
    }

    /// Simulated time \[ns\] (the time of the next tick).
    pub fn time_ns(&self) -> u64 {
        self.wiring.execution_context().time_ns()
    }

    /// Simulated time \[s\].
    pub fn time(&self) -> f64 {
        self.time_ns() as f64 * 1e-9
    }

    /// The rates in use.
    pub fn rates(&self) -> Rates {
        self.rates
    }

    /// The whole system's state, from its components' states.
    pub fn state(&self) -> SystemState {
        SystemState::of(&self.wiring)
    }

    /// What the robot is doing, from the facts.
    pub fn status(&self) -> Status {
        Status::of(&self.wiring, &self.mission)
    }

    /// A component's lifecycle state.
    pub fn component_state(&self, kind: ComponentKind) -> LifecycleState {
        self.wiring.component_state(kind)
    }

    /// Whether the robot moves: the physics is Active.
    pub fn is_driving(&self) -> bool {
        self.wiring.is_driving()
    }

    /// The current map: the one loaded, with every `MapUpdate` since.
    pub fn map(&self) -> Option<&GridMap> {
        self.wiring.map()
    }

    /// The robot's true pose (the physics).
    pub fn robot_pose(&self) -> Pose {
        self.wiring.robot_pose()
    }

    /// Running totals.
    pub fn stats(&self) -> RunStats {
        self.record.stats()
    }

    /// Component `kind` as the RTC panel shows it.
    pub fn component(&self, kind: ComponentKind) -> ComponentInfo {
        ComponentInfo::of(&self.wiring, &self.record.stats(), kind)
    }

    /// Every component as the RTC panel shows it, in attachment order.
    pub fn components(&self) -> Vec<ComponentInfo> {
        ComponentInfo::all(&self.wiring, &self.record.stats())
    }
}
