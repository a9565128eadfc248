//! The execution context: simulated-time ticks drive components through the lifecycle of
//! spec §1's table (seed 003 "実行コンテキスト", "RTCの状態遷移").
//!
//! Time is an integer count of nanoseconds, advanced only by [`ExecutionContext::tick`]: no
//! clock is read (spec §6). The context has a *base rate* (e.g. 1 kHz); each component runs at
//! its own rate, whose period must be a whole number of base ticks ([`super::period_ticks`]).
//!
//! **Order (documented invariant)**: on base tick `k` (time `k · base_period`), every
//! component whose period (in base ticks) divides `k` runs, in the order the components were
//! attached; an Active component runs `on_execute` then `on_state_update` before the next
//! component runs. So with one component at 1 kHz attached first and one at 10 Hz second, base
//! tick 0 runs both (1 kHz first), ticks 1..99 run only the first, tick 100 both again:
//! exactly 100 ticks of the first per tick of the second.
//!
//! Requests from outside (activate, deactivate, reset, …) are carried out at once, between
//! ticks, at the current simulated time. An illegal request returns a [`LifecycleError`]
//! (`InvalidTransition`, `ContextNotRunning`, `ContextAlready`, `UnknownComponent`,
//! `InvalidRate`) and changes nothing: no callback runs, no state, fault or event changes.
//!
//! **Which callbacks need a Running context** (003: "停止状態においては全てのアクションは実行
//! されません"): every callback the context drives — ticks, activate, deactivate, reset,
//! `on_rate_changed`. `on_initialize` and `on_finalize` belong to the component's creation and
//! end (OpenRTM's manager calls them, not the context), so attach, initialize and finalize
//! work in either context state.
//!
//! **Decision (callback failures the table leaves open)**, following spec §1's table and
//! OpenRTM-aist's `RTObjectStateMachine`. Every failure is recorded as a [`LifecycleEvent`]
//! with its reason and kept as [`ExecutionContext::last_error`]; then:
//!
//! | callback fails | result |
//! | --- | --- |
//! | `on_initialize` | stays Created; [`ExecutionContext::initialize`] may retry |
//! | `on_activated` | `on_aborting`, Error |
//! | `on_execute` | `on_aborting`, Error; `on_state_update` does not run |
//! | `on_state_update` | `on_aborting`, Error |
//! | `on_deactivated` | Inactive all the same (the table has no failure branch; OpenRTM ignores it) |
//! | `on_reset` | stays Error |
//! | `on_aborting`, `on_error` | Error all the same |
//! | `on_startup`, `on_shutdown` | the context starts / stops all the same; state unchanged |
//! | `on_rate_changed` | the new rate holds; state unchanged (the table: "unchanged") |
//! | `on_finalize` | Finalized all the same |
//!
//! **Decision (start/shutdown pairing)**: `on_startup` / `on_shutdown` run for *alive*
//! components only (Inactive, Active, Error). A component that becomes alive while the
//! context is Running (attached, or initialized after a failed `on_initialize`) gets its
//! `on_startup` at once, so each `on_shutdown` follows one `on_startup`.

use core::any::Any;

use super::component::{Component, ComponentError, ReturnCode, Tick};
use super::rate::period_ticks;
use super::state::{ContextState, LifecycleState, Request};
use crate::errors::LifecycleError;
use crate::reason::Reason;

const NANOS_PER_SEC: f64 = 1e9;

/// Identifies a component attached to an [`ExecutionContext`] (its attachment index).
pub type ComponentId = usize;

/// What happened to a component: a state change or a failed callback (for event logs).
#[derive(Debug, Clone, PartialEq)]
pub struct LifecycleEvent {
    /// Simulated time in nanoseconds.
    pub time_ns: u64,
    /// The component.
    pub id: ComponentId,
    /// Its instance name.
    pub component: String,
    /// State before.
    pub from: LifecycleState,
    /// State after.
    pub to: LifecycleState,
    /// The callback whose run caused this event.
    pub callback: &'static str,
    /// The callback's failure reason, if it failed.
    pub reason: Option<Reason>,
}

/// Data written into a component's input port from outside just before its next
/// `on_execute` ([`ExecutionContext::inject_input`]).
pub type InputInjection = Box<dyn FnOnce(&mut dyn Component)>;

struct Slot {
    component: Box<dyn Component>,
    state: LifecycleState,
    period_ticks: u64,
    fault: Option<String>,
    injections: Vec<InputInjection>,
    last_error: Option<Reason>,
}

/// A periodic execution context in simulated time.
pub struct ExecutionContext {
    base_period_ns: u64,
    state: ContextState,
    next_tick: u64,
    slots: Vec<Slot>,
    events: Vec<LifecycleEvent>,
}

impl core::fmt::Debug for ExecutionContext {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("ExecutionContext")
            .field("base_period_ns", &self.base_period_ns)
            .field("state", &self.state)
            .field("next_tick", &self.next_tick)
            .field(
                "components",
                &self
                    .slots
                    .iter()
                    .map(|s| (s.component.instance_name().to_owned(), s.state))
                    .collect::<Vec<_>>(),
            )
            .finish()
    }
}

impl ExecutionContext {
    /// A Stopped context whose base tick runs at `base_rate_hz` (e.g. 1000.0; at most
    /// [`MAX_BASE_RATE_HZ`](super::MAX_BASE_RATE_HZ)).
    pub fn new(base_rate_hz: f64) -> Result<Self, LifecycleError> {
        Ok(Self {
            base_period_ns: period_ticks("the base tick", base_rate_hz, 1)?,
            state: ContextState::Stopped,
            next_tick: 0,
            slots: Vec::new(),
            events: Vec::new(),
        })
    }

    /// A copy in the same state (every component copied with
    /// [`Component::boxed_clone`]; their ports unconnected). `None` if a component cannot
    /// be copied or a sample injected into a port is still waiting for its component.
    pub fn try_clone(&self) -> Option<Self> {
        let mut slots = Vec::with_capacity(self.slots.len());
        for s in &self.slots {
            if !s.injections.is_empty() {
                return None;
            }
            slots.push(Slot {
                component: s.component.boxed_clone()?,
                state: s.state,
                period_ticks: s.period_ticks,
                fault: s.fault.clone(),
                injections: Vec::new(),
                last_error: s.last_error.clone(),
            });
        }
        Some(Self {
            base_period_ns: self.base_period_ns,
            state: self.state,
            next_tick: self.next_tick,
            slots,
            events: self.events.clone(),
        })
    }

    /// The base period in nanoseconds.
    pub fn base_period_ns(&self) -> u64 {
        self.base_period_ns
    }

    /// Current simulated time in nanoseconds: the time of the next tick.
    pub fn time_ns(&self) -> u64 {
        self.next_tick * self.base_period_ns
    }

    /// Number of base ticks run so far.
    pub fn tick_count(&self) -> u64 {
        self.next_tick
    }

    /// Running or Stopped.
    pub fn context_state(&self) -> ContextState {
        self.state
    }

    /// Creates a component in this context: runs `on_initialize` (Created → Inactive; it stays
    /// Created if that fails, and the failure is in the events), then `on_startup` if the
    /// context is Running. Returns its id; a bad rate attaches nothing.
    pub fn attach(
        &mut self,
        component: Box<dyn Component>,
        rate_hz: f64,
    ) -> Result<ComponentId, LifecycleError> {
        let period_ticks = period_ticks(component.instance_name(), rate_hz, self.base_period_ns)?;
        let id = self.slots.len();
        self.slots.push(Slot {
            component,
            state: LifecycleState::Created,
            period_ticks,
            fault: None,
            injections: Vec::new(),
            last_error: None,
        });
        self.initialize(id)?;
        Ok(id)
    }

    /// Number of attached components.
    pub fn len(&self) -> usize {
        self.slots.len()
    }

    /// Whether no component is attached.
    pub fn is_empty(&self) -> bool {
        self.slots.is_empty()
    }

    fn slot(&self, id: ComponentId) -> Result<&Slot, LifecycleError> {
        self.slots
            .get(id)
            .ok_or(LifecycleError::UnknownComponent { id })
    }

    /// A component's lifecycle state.
    pub fn state(&self, id: ComponentId) -> Result<LifecycleState, LifecycleError> {
        Ok(self.slot(id)?.state)
    }

    /// A component's instance name.
    pub fn name(&self, id: ComponentId) -> Result<&str, LifecycleError> {
        Ok(self.slot(id)?.component.instance_name())
    }

    /// The reason of the component's most recent callback failure, kept until a reset (or a
    /// retried `on_initialize`) succeeds.
    pub fn last_error(&self, id: ComponentId) -> Result<Option<&Reason>, LifecycleError> {
        Ok(self.slot(id)?.last_error.as_ref())
    }

    /// The component's period in base ticks (it runs at the ticks whose index it divides).
    pub fn period_of(&self, id: ComponentId) -> Result<u64, LifecycleError> {
        Ok(self.slot(id)?.period_ticks)
    }

    /// The component's rate \[Hz\].
    pub fn rate(&self, id: ComponentId) -> Result<f64, LifecycleError> {
        let s = self.slot(id)?;
        Ok(NANOS_PER_SEC / (s.period_ticks * self.base_period_ns) as f64)
    }

    /// The component, as its concrete type.
    pub fn component<T: Component>(&self, id: ComponentId) -> Option<&T> {
        let c: &dyn Any = self.slots.get(id)?.component.as_ref();
        c.downcast_ref::<T>()
    }

    /// The component, as its concrete type, mutably (for service calls).
    pub fn component_mut<T: Component>(&mut self, id: ComponentId) -> Option<&mut T> {
        let c: &mut dyn Any = self.slots.get_mut(id)?.component.as_mut();
        c.downcast_mut::<T>()
    }

    /// The component as a trait object (e.g. for its configuration).
    pub fn component_dyn(&self, id: ComponentId) -> Result<&dyn Component, LifecycleError> {
        Ok(self
            .slots
            .get(id)
            .ok_or(LifecycleError::UnknownComponent { id })?
            .component
            .as_ref())
    }

    /// The component as a mutable trait object (e.g. for its configuration).
    pub fn component_dyn_mut(
        &mut self,
        id: ComponentId,
    ) -> Result<&mut dyn Component, LifecycleError> {
        Ok(self
            .slots
            .get_mut(id)
            .ok_or(LifecycleError::UnknownComponent { id })?
            .component
            .as_mut())
    }

    /// Takes the events recorded since the last call.
    pub fn drain_events(&mut self) -> Vec<LifecycleEvent> {
        core::mem::take(&mut self.events)
    }

    /// The events recorded and not yet drained.
    pub fn events(&self) -> &[LifecycleEvent] {
        &self.events
    }

    /// The tick component `id` would be handed now (its period, the current time).
    pub fn tick_now(&self, id: ComponentId) -> Result<Tick, LifecycleError> {
        self.slot(id)?;
        Ok(self.tick_for(id))
    }

    fn tick_for(&self, id: ComponentId) -> Tick {
        Tick {
            time_ns: self.time_ns(),
            period_ns: self.slots[id].period_ticks * self.base_period_ns,
            index: self.next_tick,
        }
    }

    fn record(
        &mut self,
        id: ComponentId,
        from: LifecycleState,
        callback: &'static str,
        reason: Option<Reason>,
    ) {
        let to = self.slots[id].state;
        if let Some(r) = &reason {
            self.slots[id].last_error = Some(r.clone());
        }
        if from != to || reason.is_some() {
            self.events.push(LifecycleEvent {
                time_ns: self.time_ns(),
                id,
                component: self.slots[id].component.instance_name().to_owned(),
                from,
                to,
                callback,
                reason,
            });
        }
    }

    fn check(
        &self,
        id: ComponentId,
        request: Request,
        allowed: &[LifecycleState],
        needs_running: bool,
    ) -> Result<(), LifecycleError> {
        let s = self.slot(id)?;
        if !allowed.contains(&s.state) {
            return Err(LifecycleError::InvalidTransition {
                component: s.component.instance_name().to_owned(),
                from: s.state,
                request,
            });
        }
        if needs_running && self.state != ContextState::Running {
            return Err(LifecycleError::ContextNotRunning {
                component: s.component.instance_name().to_owned(),
                request,
                context: self.state,
            });
        }
        Ok(())
    }

    /// Active → Error through `on_aborting` (its own failure is recorded, the state is Error
    /// all the same).
    fn abort(&mut self, id: ComponentId, failed: &'static str, e: ComponentError) {
        let from = self.slots[id].state;
        let tick = self.tick_for(id);
        let aborting = self.slots[id].component.on_aborting(&tick);
        self.slots[id].state = LifecycleState::Error;
        self.record(id, from, failed, Some(*e.reason));
        if let Err(e2) = aborting {
            self.record(id, LifecycleState::Error, "on_aborting", Some(*e2.reason));
        }
    }

    /// Runs `on_initialize` for a component in Created (at attach, or again after it failed):
    /// Inactive on success, then `on_startup` if the context is Running; Created on failure.
    pub fn initialize(&mut self, id: ComponentId) -> Result<LifecycleState, LifecycleError> {
        self.check(id, Request::Initialize, &[LifecycleState::Created], false)?;
        if let Err(e) = self.slots[id].component.on_initialize() {
            self.record(
                id,
                LifecycleState::Created,
                "on_initialize",
                Some(*e.reason),
            );
            return Ok(LifecycleState::Created);
        }
        self.slots[id].state = LifecycleState::Inactive;
        self.slots[id].last_error = None;
        self.record(id, LifecycleState::Created, "on_initialize", None);
        if self.state == ContextState::Running {
            self.start_or_stop(id, ContextState::Running);
        }
        Ok(LifecycleState::Inactive)
    }

    /// Inactive → Active (`on_activated`; on failure `on_aborting` → Error). `on_activation`
    /// parameters are applied first. Returns the state reached.
    pub fn activate(&mut self, id: ComponentId) -> Result<LifecycleState, LifecycleError> {
        self.check(id, Request::Activate, &[LifecycleState::Inactive], true)?;
        // `on_activation` values take effect for `on_activated`, and stay only if it succeeds
        // (spec §1 Decision 0.2).
        let before = self.slots[id].component.configuration().map(|cfg| {
            let before = cfg.effective_values();
            cfg.apply_on_activation();
            before
        });
        let tick = self.tick_for(id);
        match self.slots[id].component.on_activated(&tick) {
            Ok(()) => {
                self.slots[id].state = LifecycleState::Active;
                self.record(id, LifecycleState::Inactive, "on_activated", None);
            }
            Err(e) => {
                if let (Some(before), Some(cfg)) =
                    (before, self.slots[id].component.configuration())
                {
                    cfg.restore_effective(&before);
                }
                self.abort(id, "on_activated", e);
            }
        }
        Ok(self.slots[id].state)
    }

    /// Active → Inactive (`on_deactivated`). A failing `on_deactivated` is recorded and the
    /// component is Inactive all the same (module doc, Decision).
    pub fn deactivate(&mut self, id: ComponentId) -> Result<LifecycleState, LifecycleError> {
        self.check(id, Request::Deactivate, &[LifecycleState::Active], true)?;
        let tick = self.tick_for(id);
        let r = self.slots[id].component.on_deactivated(&tick);
        self.slots[id].state = LifecycleState::Inactive;
        self.record(
            id,
            LifecycleState::Active,
            "on_deactivated",
            r.err().map(|e| *e.reason),
        );
        Ok(LifecycleState::Inactive)
    }

    /// Error → Inactive if `on_reset` succeeds; stays in Error if it fails.
    pub fn reset(&mut self, id: ComponentId) -> Result<LifecycleState, LifecycleError> {
        self.check(id, Request::Reset, &[LifecycleState::Error], true)?;
        let tick = self.tick_for(id);
        match self.slots[id].component.on_reset(&tick) {
            Ok(()) => {
                let s = &mut self.slots[id];
                s.state = LifecycleState::Inactive;
                s.fault = None;
                s.last_error = None;
                self.record(id, LifecycleState::Error, "on_reset", None);
            }
            Err(e) => self.record(id, LifecycleState::Error, "on_reset", Some(*e.reason)),
        }
        Ok(self.slots[id].state)
    }

    /// Any state → Finalized (`on_finalize`, once), with the context Running or Stopped. Only
    /// `on_finalize` runs (spec §1's table). Afterwards every request about the component is
    /// illegal and no callback of it runs again.
    pub fn finalize(&mut self, id: ComponentId) -> Result<LifecycleState, LifecycleError> {
        use LifecycleState::*;
        self.check(
            id,
            Request::Finalize,
            &[Created, Inactive, Active, Error],
            false,
        )?;
        let from = self.slots[id].state;
        let r = self.slots[id].component.on_finalize();
        self.slots[id].state = Finalized;
        self.record(id, from, "on_finalize", r.err().map(|e| *e.reason));
        Ok(Finalized)
    }

    /// Puts `component` in the place of component `id` (spec §8: a student's script in the
    /// place of a built-in component, or the built-in one back), as if the old one were
    /// finalized and the new one created there: the new one's `on_initialize` runs first,
    /// and if it fails nothing changes (the error names it); then the old one's
    /// `on_finalize`, and the new one is Inactive (then `on_startup` if the context is
    /// Running), with no fault pending and no error kept. Refused while the component is
    /// Active. Returns the old component (its ports still connected: the owner reconnects).
    pub fn replace(
        &mut self,
        id: ComponentId,
        mut component: Box<dyn Component>,
    ) -> Result<Box<dyn Component>, LifecycleError> {
        use LifecycleState::*;
        self.check(id, Request::Replace, &[Created, Inactive, Error], false)?;
        if let Err(e) = component.on_initialize() {
            return Err(LifecycleError::CallbackFailed {
                component: component.instance_name().to_owned(),
                callback: "on_initialize",
                reason: e.to_string(),
            });
        }
        let from = self.slots[id].state;
        let slot = &mut self.slots[id];
        let mut old = core::mem::replace(&mut slot.component, component);
        slot.state = Inactive;
        slot.fault = None;
        slot.injections.clear();
        slot.last_error = None;
        if let Err(e) = old.on_finalize() {
            // Said in the events; not kept as the new component's error.
            self.record(id, from, "on_finalize", Some(*e.reason));
            self.slots[id].last_error = None;
        }
        self.record(id, from, "on_initialize", None);
        if self.state == ContextState::Running {
            self.start_or_stop(id, ContextState::Running);
        }
        Ok(old)
    }

    /// Changes a component's rate; `on_rate_changed` runs if the context is Running and the
    /// component is alive (no callback runs while the context is Stopped). The new period is
    /// in every later [`Tick`]; the component runs on base ticks that are multiples of it.
    pub fn set_rate(&mut self, id: ComponentId, rate_hz: f64) -> Result<(), LifecycleError> {
        use LifecycleState::*;
        self.check(
            id,
            Request::ChangeRate,
            &[Created, Inactive, Active, Error],
            false,
        )?;
        let who = self.slots[id].component.instance_name();
        let p = period_ticks(who, rate_hz, self.base_period_ns)?;
        self.slots[id].period_ticks = p;
        if self.state == ContextState::Running && self.slots[id].state.is_alive() {
            let tick = self.tick_for(id);
            if let Err(e) = self.slots[id].component.on_rate_changed(&tick) {
                let st = self.slots[id].state;
                self.record(id, st, "on_rate_changed", Some(*e.reason));
            }
        }
        Ok(())
    }

    /// Makes the component's next `on_execute` fail with `injected fault: {reason}` (the page's
    /// "Inject fault"). The fault stands in for that `on_execute`: the component's own code does
    /// not run on that tick, and the failure takes the usual path (`on_aborting`, Error). Legal
    /// while Inactive or Active; a pending fault survives deactivation and is dropped by a
    /// successful reset.
    pub fn inject_fault(&mut self, id: ComponentId, reason: &str) -> Result<(), LifecycleError> {
        use LifecycleState::*;
        self.check(id, Request::InjectFault, &[Inactive, Active], false)?;
        self.slots[id].fault = Some(reason.to_owned());
        Ok(())
    }

    /// Queues `write` to run on the component just before its next `on_execute`, after every
    /// component before it in the tick has written its outputs — so the sample it puts into
    /// an input port is the one the component reads (OpenRTM rtshell's `rtinject`, whose
    /// sample arrives between two executions). Legal while Inactive or Active.
    pub fn inject_input(
        &mut self,
        id: ComponentId,
        write: InputInjection,
    ) -> Result<(), LifecycleError> {
        use LifecycleState::*;
        self.check(id, Request::InjectFault, &[Inactive, Active], false)?;
        self.slots[id].injections.push(write);
        Ok(())
    }

    /// Whether a fault is waiting for the component's next `on_execute`.
    pub fn fault_pending(&self, id: ComponentId) -> Result<bool, LifecycleError> {
        Ok(self.slot(id)?.fault.is_some())
    }

    /// Stopped → Running: `on_startup` for every alive component, in attachment order.
    pub fn start(&mut self) -> Result<(), LifecycleError> {
        self.switch(ContextState::Running)
    }

    /// Running → Stopped: `on_shutdown` for every alive component, in attachment order.
    pub fn stop(&mut self) -> Result<(), LifecycleError> {
        self.switch(ContextState::Stopped)
    }

    fn switch(&mut self, to: ContextState) -> Result<(), LifecycleError> {
        if self.state == to {
            return Err(LifecycleError::ContextAlready { state: to });
        }
        self.state = to;
        for id in 0..self.slots.len() {
            if self.slots[id].state.is_alive() {
                self.start_or_stop(id, to);
            }
        }
        Ok(())
    }

    /// `on_startup` (`to` = Running) or `on_shutdown` for one component; a failure is recorded.
    fn start_or_stop(&mut self, id: ComponentId, to: ContextState) {
        let tick = self.tick_for(id);
        let c = &mut self.slots[id].component;
        let (name, r) = match to {
            ContextState::Running => ("on_startup", c.on_startup(&tick)),
            ContextState::Stopped => ("on_shutdown", c.on_shutdown(&tick)),
        };
        if let Err(e) = r {
            let st = self.slots[id].state;
            self.record(id, st, name, Some(*e.reason));
        }
    }

    /// Runs one base tick (if Running; a Stopped context runs no callback, but time still
    /// advances so a host's clock stays in step).
    pub fn tick(&mut self) {
        if self.state == ContextState::Running {
            for id in 0..self.slots.len() {
                if self.next_tick.is_multiple_of(self.slots[id].period_ticks) {
                    self.run_slot(id);
                }
            }
        }
        self.next_tick += 1;
    }

    /// Runs `n` base ticks.
    pub fn run_ticks(&mut self, n: u64) {
        for _ in 0..n {
            self.tick();
        }
    }

    fn run_slot(&mut self, id: ComponentId) {
        let tick = self.tick_for(id);
        match self.slots[id].state {
            LifecycleState::Active => {
                for write in core::mem::take(&mut self.slots[id].injections) {
                    write(self.slots[id].component.as_mut());
                }
                let r: ReturnCode = match self.slots[id].fault.take() {
                    Some(words) => Err(ComponentError::new(Reason::InjectedFault(words))),
                    None => self.slots[id].component.on_execute(&tick),
                };
                match r {
                    Ok(()) => {
                        if let Err(e) = self.slots[id].component.on_state_update(&tick) {
                            self.abort(id, "on_state_update", e);
                        }
                    }
                    Err(e) => self.abort(id, "on_execute", e),
                }
            }
            LifecycleState::Error => {
                if let Err(e) = self.slots[id].component.on_error(&tick) {
                    self.record(id, LifecycleState::Error, "on_error", Some(*e.reason));
                }
            }
            _ => {}
        }
    }
}
