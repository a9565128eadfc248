//! `rtnav-wasm`: the browser's handle over `rtnav` (no logic of its own).
//!
//! Long-lived state lives here, in Rust memory; JavaScript holds an opaque handle
//! ([`ComponentHost`]), owns the clock (`requestAnimationFrame`) and calls
//! [`ComponentHost::step`] with the elapsed wall time, which becomes whole ticks of simulated
//! time (SPEC §6: components never read a clock). Errors become `JsError`s only here.
//!
//! Panics are bugs (SPEC §1), but a page must show one rather than freeze: the panic hook
//! installed at start-up records the message, which [`has_panicked`] and [`panic_message`]
//! report (the style of egui's `WebHandle`). They are free functions because after a panic
//! the handle that panicked stays borrowed and every further call on it throws.

use std::sync::Mutex;

use rtnav::components::Heartbeat;
use rtnav::rtc::{ComponentId, ConfigAccess, ExecutionContext, LifecycleState, ParamSpec};
use serde::Serialize;
use wasm_bindgen::prelude::*;

/// The context's base rate: 1 kHz, the rate the whole system will run at (SPEC §6).
const BASE_RATE_HZ: f64 = 1000.0;
/// One base tick in microseconds.
const BASE_PERIOD_US: u64 = 1000;
/// The heartbeat's rate (ten executions per simulated second).
const HEARTBEAT_RATE_HZ: f64 = 10.0;
/// The most wall time one [`ComponentHost::step`] turns into simulated time: a tab that was
/// in the background for minutes resumes where it was instead of catching up in one frame.
const MAX_STEP_MS: f64 = 250.0;

/// The first panic's message, recorded by the hook.
static PANIC_MESSAGE: Mutex<Option<String>> = Mutex::new(None);

/// Installs the panic hook (runs once, when the module is instantiated).
#[wasm_bindgen(start)]
pub fn start() {
    std::panic::set_hook(Box::new(|info| {
        let mut slot = PANIC_MESSAGE.lock().unwrap_or_else(|e| e.into_inner());
        if slot.is_none() {
            *slot = Some(info.to_string());
        }
        drop(slot);
        console_error_panic_hook::hook(info);
    }));
}

/// Whether Rust code has panicked; after that the module must not be used any more.
#[wasm_bindgen]
pub fn has_panicked() -> bool {
    PANIC_MESSAGE
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .is_some()
}

/// The first panic's message and location, if Rust code has panicked.
#[wasm_bindgen]
pub fn panic_message() -> Option<String> {
    PANIC_MESSAGE
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .clone()
}

/// A lifecycle event as the page's log shows it.
#[derive(Serialize)]
struct EventView<'a> {
    time_ms: f64,
    component: &'a str,
    from: LifecycleState,
    to: LifecycleState,
    callback: &'a str,
    reason: Option<&'a str>,
}

/// A parameter as the page's configuration panel shows it.
#[derive(Serialize)]
struct ParamView {
    #[serde(flatten)]
    spec: ParamSpec,
    value: f64,
}

fn js_error(e: impl std::fmt::Display) -> JsError {
    JsError::new(&e.to_string())
}

/// An execution context running one demo component (the `Heartbeat`), driven by the page.
#[wasm_bindgen]
#[derive(Debug)]
pub struct ComponentHost {
    ec: ExecutionContext,
    id: ComponentId,
    /// Wall time received but not yet a whole tick, in microseconds.
    pending_us: u64,
}

#[wasm_bindgen]
impl ComponentHost {
    /// A running 1 kHz context with `Heartbeat0` at 10 Hz, Inactive.
    #[wasm_bindgen(constructor)]
    pub fn new() -> Result<ComponentHost, JsError> {
        let mut ec = ExecutionContext::new(BASE_RATE_HZ).map_err(js_error)?;
        let id = ec
            .attach(Box::new(Heartbeat::new("Heartbeat0")), HEARTBEAT_RATE_HZ)
            .map_err(js_error)?;
        ec.start().map_err(js_error)?;
        Ok(Self {
            ec,
            id,
            pending_us: 0,
        })
    }

    /// Advances simulated time by `elapsed_ms` of wall time, in whole ticks (the remainder is
    /// kept for the next call; at most 250 ms per call; negative or non-finite counts as 0).
    /// Returns the number of ticks run.
    pub fn step(&mut self, elapsed_ms: f64) -> u32 {
        let ms = if elapsed_ms.is_finite() {
            elapsed_ms.clamp(0.0, MAX_STEP_MS)
        } else {
            0.0
        };
        self.pending_us += (ms * 1000.0).round() as u64;
        let ticks = self.pending_us / BASE_PERIOD_US;
        self.pending_us %= BASE_PERIOD_US;
        self.ec.run_ticks(ticks);
        // At most 250 ticks: fits.
        ticks as u32
    }

    /// Inactive → Active. Returns the state reached.
    pub fn activate(&mut self) -> Result<String, JsError> {
        Ok(self.ec.activate(self.id).map_err(js_error)?.to_string())
    }

    /// Active → Inactive. Returns the state reached.
    pub fn deactivate(&mut self) -> Result<String, JsError> {
        Ok(self.ec.deactivate(self.id).map_err(js_error)?.to_string())
    }

    /// Error → Inactive (stays Error if `on_reset` fails). Returns the state reached.
    pub fn reset(&mut self) -> Result<String, JsError> {
        Ok(self.ec.reset(self.id).map_err(js_error)?.to_string())
    }

    /// Makes the next `on_execute` fail, which takes the component to Error.
    pub fn inject_fault(&mut self) -> Result<(), JsError> {
        self.ec
            .inject_fault(self.id, "requested from the page")
            .map_err(js_error)
    }

    /// Whether an injected fault waits for the next execution.
    pub fn fault_pending(&self) -> bool {
        self.ec.fault_pending(self.id).unwrap_or(false)
    }

    /// The lifecycle state: `Created`, `Inactive`, `Active`, `Error` or `Finalized`.
    pub fn state(&self) -> String {
        self.lifecycle_state().to_string()
    }

    /// The RT System Editor's colour for the state, as `#rrggbb`.
    pub fn state_colour(&self) -> String {
        self.lifecycle_state().editor_colour().to_owned()
    }

    /// Why the last callback failed (kept until a reset succeeds).
    pub fn last_error(&self) -> Option<String> {
        self.ec
            .last_error(self.id)
            .ok()
            .flatten()
            .map(str::to_owned)
    }

    /// The component's instance name.
    pub fn name(&self) -> String {
        self.ec.name(self.id).unwrap_or_default().to_owned()
    }

    /// How many times `on_execute` has run.
    pub fn execution_count(&self) -> f64 {
        self.heartbeat().map_or(0.0, |h| h.executions() as f64)
    }

    /// How many beats there have been.
    pub fn beats(&self) -> f64 {
        self.heartbeat().map_or(0.0, |h| h.beats() as f64)
    }

    /// Simulated time in milliseconds.
    pub fn time_ms(&self) -> f64 {
        self.ec.time_ns() as f64 * 1e-6
    }

    /// The component's rate in Hz.
    pub fn rate_hz(&self) -> f64 {
        self.ec.rate(self.id).unwrap_or(0.0)
    }

    /// The configuration parameters as JSON: `[{name, kind, unit, default, min, max,
    /// reflection, description, value}]` (an unbounded range is `null`).
    pub fn parameters_json(&mut self) -> Result<String, JsError> {
        let cfg = self.config()?;
        let views = cfg
            .specs()
            .iter()
            .map(|s| {
                Ok(ParamView {
                    spec: *s,
                    value: cfg.value(s.name)?,
                })
            })
            .collect::<Result<Vec<_>, rtnav::errors::ConfigError>>()
            .map_err(js_error)?;
        serde_json::to_string(&views).map_err(js_error)
    }

    /// Sets a configuration parameter; an out-of-range value is refused and the old one stays.
    pub fn set_parameter(&mut self, name: &str, value: f64) -> Result<(), JsError> {
        self.config()?.set(name, value).map_err(js_error)
    }

    /// The lifecycle events since the last call, as JSON: `[{time_ms, component, from, to,
    /// callback, reason}]`.
    pub fn take_events(&mut self) -> Result<String, JsError> {
        let events = self.ec.drain_events();
        let views: Vec<EventView<'_>> = events
            .iter()
            .map(|e| EventView {
                time_ms: e.time_ns as f64 * 1e-6,
                component: &e.component,
                from: e.from,
                to: e.to,
                callback: e.callback,
                reason: e.reason.as_deref(),
            })
            .collect();
        serde_json::to_string(&views).map_err(js_error)
    }

    /// Panics on purpose, so the end-to-end test can prove the page shows a crash.
    pub fn debug_panic(&mut self) {
        panic!("debug_panic: deliberate panic requested by the page");
    }
}

impl ComponentHost {
    fn lifecycle_state(&self) -> LifecycleState {
        self.ec.state(self.id).unwrap_or(LifecycleState::Finalized)
    }

    fn heartbeat(&self) -> Option<&Heartbeat> {
        self.ec.component::<Heartbeat>(self.id)
    }

    fn config(&mut self) -> Result<&mut dyn ConfigAccess, JsError> {
        self.ec
            .component_dyn_mut(self.id)
            .map_err(js_error)?
            .configuration()
            .ok_or_else(|| JsError::new("the component has no configuration"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn step_turns_wall_time_into_whole_ticks() {
        let mut host = ComponentHost::new().unwrap();
        // 16.7 ms → 16 ticks, 0.7 ms kept; 0.4 ms more → 1.1 ms → 1 tick, 0.1 kept.
        assert_eq!(
            [16.7, 0.4, 0.9, -5.0, f64::NAN, 1000.0].map(|ms| host.step(ms)),
            [16, 1, 1, 0, 0, 250]
        );
        assert_eq!(host.time_ms(), 268.0);
    }

    #[test]
    fn lifecycle_through_the_handle() {
        let mut host = ComponentHost::new().unwrap();
        assert_eq!(
            (host.state(), host.state_colour()),
            ("Inactive".into(), "#0000ff".into())
        );
        assert_eq!(host.activate().unwrap(), "Active");
        // 10 Hz: executions at 0 ms, 100 ms, …, 900 ms.
        for _ in 0..10 {
            host.step(100.0);
        }
        assert_eq!((host.execution_count(), host.beats()), (10.0, 1.0));
        host.inject_fault().unwrap();
        host.step(100.0);
        assert_eq!(
            (host.state(), host.last_error()),
            (
                "Error".into(),
                Some("injected fault: requested from the page".into())
            )
        );
        assert_eq!(host.reset().unwrap(), "Inactive");
        assert_eq!(host.last_error(), None);
        let events = host.take_events().unwrap();
        assert_eq!(
            events,
            concat!(
                r#"[{"time_ms":0.0,"component":"Heartbeat0","from":"Created","to":"Inactive","callback":"on_initialize","reason":null},"#,
                r#"{"time_ms":0.0,"component":"Heartbeat0","from":"Inactive","to":"Active","callback":"on_activated","reason":null},"#,
                r#"{"time_ms":1000.0,"component":"Heartbeat0","from":"Active","to":"Error","callback":"on_execute","reason":"injected fault: requested from the page"},"#,
                r#"{"time_ms":1100.0,"component":"Heartbeat0","from":"Error","to":"Inactive","callback":"on_reset","reason":null}]"#
            )
        );
    }

    #[test]
    fn parameters_are_listed_and_set() {
        let mut host = ComponentHost::new().unwrap();
        host.set_parameter("BeatInterval", 3.0).unwrap();
        assert_eq!(
            host.parameters_json().unwrap(),
            r#"[{"name":"BeatInterval","kind":"Int","unit":"-","default":10.0,"min":1.0,"max":1000.0,"reflection":"Always","description":"a beat every this many executions","value":3.0}]"#
        );
    }
}
