//! Heartbeat: a tiny demo RT-component that counts its executions and beats every
//! `BeatInterval` of them.
//!
//! It is not one of OpenINVENT's components: it gives the browser page (InventGUI, SPEC §5)
//! something real to drive through the lifecycle of SPEC §1 — activate, deactivate, an
//! injected fault, reset — until the whole robot system replaces it. It uses the framework
//! exactly as the real components do: callbacks of [`Component`] and a parameter declared with
//! [`define_parameters!`](crate::define_parameters).

use crate::rtc::{Component, ConfigAccess, Configuration, ReturnCode, Tick};

crate::define_parameters! {
    /// Heartbeat's configuration parameters (SPEC §1 "Configuration parameters").
    pub struct HeartbeatParams {
        /// Executions per beat; `always`: a change counts from the next execution.
        beat_interval: i32 = ("BeatInterval", "-", 10.0, 1.0, 1000.0, Always,
            "a beat every this many executions"),
    }
}

/// The demo component: `on_execute` counts executions and, every `BeatInterval` of them, a
/// beat.
#[derive(Debug, Clone)]
pub struct Heartbeat {
    instance_name: String,
    config: Configuration<HeartbeatParams>,
    executions: u64,
    beats: u64,
    since_beat: u64,
    last_execution_ns: Option<u64>,
}

impl Heartbeat {
    /// A heartbeat named `instance_name` (e.g. `Heartbeat0`), every parameter at its default.
    pub fn new(instance_name: impl Into<String>) -> Self {
        Self {
            instance_name: instance_name.into(),
            config: Configuration::new(),
            executions: 0,
            beats: 0,
            since_beat: 0,
            last_execution_ns: None,
        }
    }

    /// How many times `on_execute` has run since the component was created.
    pub fn executions(&self) -> u64 {
        self.executions
    }

    /// How many beats there have been since the component was created.
    pub fn beats(&self) -> u64 {
        self.beats
    }

    /// Simulated time of the last execution in nanoseconds, if it has run.
    pub fn last_execution_ns(&self) -> Option<u64> {
        self.last_execution_ns
    }

    /// The parameter values in use.
    pub fn params(&self) -> &HeartbeatParams {
        self.config.params()
    }

    /// The configuration (to set `BeatInterval`).
    pub fn config_mut(&mut self) -> &mut Configuration<HeartbeatParams> {
        &mut self.config
    }
}

impl Component for Heartbeat {
    fn instance_name(&self) -> &str {
        &self.instance_name
    }

    fn configuration(&mut self) -> Option<&mut dyn ConfigAccess> {
        Some(&mut self.config)
    }

    fn configuration_ref(&self) -> Option<&dyn ConfigAccess> {
        Some(&self.config)
    }

    /// A new activation starts a new beat period.
    fn on_activated(&mut self, _tick: &Tick) -> ReturnCode {
        self.since_beat = 0;
        Ok(())
    }

    /// Counts the execution and beats every `BeatInterval` executions.
    fn on_execute(&mut self, tick: &Tick) -> ReturnCode {
        self.executions += 1;
        self.last_execution_ns = Some(tick.time_ns);
        self.since_beat += 1;
        // `BeatInterval` is at least 1 (its range), so a beat comes at the latest now.
        if self.since_beat >= u64::try_from(self.params().beat_interval).unwrap_or(1) {
            self.beats += 1;
            self.since_beat = 0;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::errors::{ConfigError, LifecycleError};
    use crate::rtc::{ComponentId, ExecutionContext, LifecycleState, Request};

    /// A running 1 kHz context with a 10 Hz heartbeat (one execution per 100 base ticks).
    fn running() -> (ExecutionContext, ComponentId) {
        let mut ec = ExecutionContext::new(1000.0).unwrap();
        let id = ec
            .attach(Box::new(Heartbeat::new("Heartbeat0")), 10.0)
            .unwrap();
        ec.start().unwrap();
        (ec, id)
    }

    fn hb(ec: &ExecutionContext, id: ComponentId) -> &Heartbeat {
        ec.component::<Heartbeat>(id).unwrap()
    }

    /// (executions, beats, state)
    fn check(ec: &ExecutionContext, id: ComponentId, expect: (u64, u64, LifecycleState)) {
        let h = hb(ec, id);
        assert_eq!((h.executions(), h.beats(), ec.state(id).unwrap()), expect);
    }

    #[test]
    fn counts_only_while_active() {
        let (mut ec, id) = running();
        ec.run_ticks(1000);
        check(&ec, id, (0, 0, LifecycleState::Inactive));
        ec.activate(id).unwrap();
        // Ticks 1000..=1999 hold ten multiples of 100.
        ec.run_ticks(1000);
        check(&ec, id, (10, 1, LifecycleState::Active));
        assert_eq!(hb(&ec, id).last_execution_ns(), Some(1_900_000_000));
        ec.deactivate(id).unwrap();
        ec.run_ticks(1000);
        check(&ec, id, (10, 1, LifecycleState::Inactive));
    }

    #[test]
    fn beat_interval_takes_effect_at_the_next_execution() {
        let (mut ec, id) = running();
        ec.activate(id).unwrap();
        ec.run_ticks(300);
        check(&ec, id, (3, 0, LifecycleState::Active));
        ec.component_mut::<Heartbeat>(id)
            .unwrap()
            .config_mut()
            .set("BeatInterval", 2.0)
            .unwrap();
        assert_eq!(hb(&ec, id).params().beat_interval, 2);
        // Execution 4 completes a beat of 2 (3 since the last beat ≥ 2), then 6, 8, 10.
        ec.run_ticks(700);
        check(&ec, id, (10, 4, LifecycleState::Active));
    }

    #[test]
    fn out_of_range_beat_interval_is_refused_and_changes_nothing() {
        let mut h = Heartbeat::new("Heartbeat0");
        for bad in [0.0, 1001.0, 2.5, f64::NAN] {
            let e = h.config_mut().set("BeatInterval", bad).unwrap_err();
            assert!(
                matches!(
                    e,
                    ConfigError::OutOfRange { .. } | ConfigError::BadValue { .. }
                ),
                "{bad}: {e:?}"
            );
            assert_eq!(h.params().beat_interval, 10);
        }
    }

    #[test]
    fn injected_fault_then_reset_then_activate_again() {
        let (mut ec, id) = running();
        ec.activate(id).unwrap();
        ec.run_ticks(200);
        check(&ec, id, (2, 0, LifecycleState::Active));
        ec.inject_fault(id, "demo").unwrap();
        // The next execution (tick 200) fails instead of running `on_execute`.
        ec.run_ticks(100);
        check(&ec, id, (2, 0, LifecycleState::Error));
        assert_eq!(ec.last_error(id).unwrap(), Some("injected fault: demo"));
        ec.run_ticks(500);
        check(&ec, id, (2, 0, LifecycleState::Error));
        assert_eq!(
            ec.activate(id).unwrap_err(),
            LifecycleError::InvalidTransition {
                component: "Heartbeat0".into(),
                from: LifecycleState::Error,
                request: Request::Activate,
            }
        );
        assert_eq!(ec.reset(id).unwrap(), LifecycleState::Inactive);
        assert_eq!(ec.last_error(id).unwrap(), None);
        assert_eq!(ec.activate(id).unwrap(), LifecycleState::Active);
        ec.run_ticks(1000);
        check(&ec, id, (12, 1, LifecycleState::Active));
    }
}
