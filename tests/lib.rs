//! Shared helpers for the whole-system tests (native and wasm32).
//!
//! - [`Journal`] and [`Probe`]: a component that records every callback it gets (with its
//!   [`Tick`]) and fails any callback it is told to, for the lifecycle tests (spec §1).
//! - [`data`]: the external data, read at run time on both targets, and the one-line
//!   notice of a test skipped without it.

use std::cell::RefCell;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::rc::Rc;

use rtnav::rtc::{Component, ComponentError, ReturnCode, Tick};

pub mod data;
pub mod fixtures;

/// The callbacks of seed 003's table ("アクションのまとめ"), in the trait's order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Callback {
    /// `on_initialize`.
    Initialize,
    /// `on_finalize`.
    Finalize,
    /// `on_startup`.
    Startup,
    /// `on_shutdown`.
    Shutdown,
    /// `on_activated`.
    Activated,
    /// `on_deactivated`.
    Deactivated,
    /// `on_execute`.
    Execute,
    /// `on_state_update`.
    StateUpdate,
    /// `on_aborting`.
    Aborting,
    /// `on_error`.
    Error,
    /// `on_reset`.
    Reset,
    /// `on_rate_changed`.
    RateChanged,
}

impl Callback {
    /// The trait method's name, e.g. `on_execute` (as in `LifecycleEvent::callback`).
    pub fn name(self) -> &'static str {
        match self {
            Self::Initialize => "on_initialize",
            Self::Finalize => "on_finalize",
            Self::Startup => "on_startup",
            Self::Shutdown => "on_shutdown",
            Self::Activated => "on_activated",
            Self::Deactivated => "on_deactivated",
            Self::Execute => "on_execute",
            Self::StateUpdate => "on_state_update",
            Self::Aborting => "on_aborting",
            Self::Error => "on_error",
            Self::Reset => "on_reset",
            Self::RateChanged => "on_rate_changed",
        }
    }
}

/// One callback run, as a probe saw it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Call {
    /// The probe's instance name.
    pub component: String,
    /// The callback.
    pub callback: Callback,
    /// The tick it was given (`None` for `on_initialize` / `on_finalize`).
    pub tick: Option<Tick>,
}

#[derive(Debug, Default)]
struct JournalData {
    calls: Vec<Call>,
    failing: BTreeSet<(String, Callback)>,
}

/// What every probe of a test saw, in order, and which callbacks they are told to fail.
/// Cloning gives another handle to the same journal.
#[derive(Debug, Clone, Default)]
pub struct Journal(Rc<RefCell<JournalData>>);

impl Journal {
    /// An empty journal.
    pub fn new() -> Self {
        Self::default()
    }

    /// A probe named `name` that writes to this journal.
    pub fn probe(&self, name: &str) -> Box<Probe> {
        Box::new(Probe {
            name: name.to_owned(),
            journal: self.clone(),
        })
    }

    /// Makes `component`'s `callback` fail from now on (until [`Journal::heal`]).
    pub fn fail(&self, component: &str, callback: Callback) {
        self.0
            .borrow_mut()
            .failing
            .insert((component.to_owned(), callback));
    }

    /// Makes `component`'s `callback` succeed again.
    pub fn heal(&self, component: &str, callback: Callback) {
        self.0
            .borrow_mut()
            .failing
            .remove(&(component.to_owned(), callback));
    }

    /// Every call so far, in order.
    pub fn calls(&self) -> Vec<Call> {
        self.0.borrow().calls.clone()
    }

    /// Number of calls so far (a mark for [`Journal::counts_since`]).
    pub fn len(&self) -> usize {
        self.0.borrow().calls.len()
    }

    /// Whether no callback ran yet.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// How often each callback of `component` ran since call number `mark`.
    pub fn counts_since(&self, component: &str, mark: usize) -> BTreeMap<Callback, u64> {
        let mut counts = BTreeMap::new();
        for c in &self.0.borrow().calls[mark..] {
            if c.component == component {
                *counts.entry(c.callback).or_insert(0) += 1;
            }
        }
        counts
    }

    /// [`Journal::counts_since`] as text, e.g. `on_execute=2 on_state_update=2` (callbacks in
    /// the trait's order, those that did not run left out; empty if none ran).
    pub fn counts_text_since(&self, component: &str, mark: usize) -> String {
        let mut s = String::new();
        for (cb, n) in self.counts_since(component, mark) {
            if !s.is_empty() {
                s.push(' ');
            }
            let _ = write!(s, "{}={n}", cb.name());
        }
        s
    }

    /// How often each callback of `component` ran, as text (see [`Journal::counts_text_since`]).
    pub fn counts_text(&self, component: &str) -> String {
        self.counts_text_since(component, 0)
    }

    fn run(&self, component: &str, callback: Callback, tick: Option<Tick>) -> ReturnCode {
        let mut d = self.0.borrow_mut();
        d.calls.push(Call {
            component: component.to_owned(),
            callback,
            tick,
        });
        if d.failing.contains(&(component.to_owned(), callback)) {
            return Err(ComponentError::words(format!(
                "{component}: {} told to fail",
                callback.name()
            )));
        }
        Ok(())
    }
}

/// A component that records every callback in its [`Journal`] and fails those it is told to.
#[derive(Debug)]
pub struct Probe {
    name: String,
    journal: Journal,
}

impl Component for Probe {
    fn instance_name(&self) -> &str {
        &self.name
    }
    fn on_initialize(&mut self) -> ReturnCode {
        self.journal.run(&self.name, Callback::Initialize, None)
    }
    fn on_finalize(&mut self) -> ReturnCode {
        self.journal.run(&self.name, Callback::Finalize, None)
    }
    fn on_startup(&mut self, tick: &Tick) -> ReturnCode {
        self.journal.run(&self.name, Callback::Startup, Some(*tick))
    }
    fn on_shutdown(&mut self, tick: &Tick) -> ReturnCode {
        self.journal
            .run(&self.name, Callback::Shutdown, Some(*tick))
    }
    fn on_activated(&mut self, tick: &Tick) -> ReturnCode {
        self.journal
            .run(&self.name, Callback::Activated, Some(*tick))
    }
    fn on_deactivated(&mut self, tick: &Tick) -> ReturnCode {
        self.journal
            .run(&self.name, Callback::Deactivated, Some(*tick))
    }
    fn on_execute(&mut self, tick: &Tick) -> ReturnCode {
        self.journal.run(&self.name, Callback::Execute, Some(*tick))
    }
    fn on_state_update(&mut self, tick: &Tick) -> ReturnCode {
        self.journal
            .run(&self.name, Callback::StateUpdate, Some(*tick))
    }
    fn on_aborting(&mut self, tick: &Tick) -> ReturnCode {
        self.journal
            .run(&self.name, Callback::Aborting, Some(*tick))
    }
    fn on_error(&mut self, tick: &Tick) -> ReturnCode {
        self.journal.run(&self.name, Callback::Error, Some(*tick))
    }
    fn on_reset(&mut self, tick: &Tick) -> ReturnCode {
        self.journal.run(&self.name, Callback::Reset, Some(*tick))
    }
    fn on_rate_changed(&mut self, tick: &Tick) -> ReturnCode {
        self.journal
            .run(&self.name, Callback::RateChanged, Some(*tick))
    }
}
