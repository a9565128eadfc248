//! The `Component` trait: the callbacks of seed 003's table, each with a default.

use core::any::Any;
use core::fmt;

use super::config::ConfigAccess;
use super::idl::Time;
use super::sample::PortView;
use crate::reason::Reason;

/// Why a callback failed; the GUI shows `reason` (spec §1: "A callback fails by returning an
/// error value (with a reason that the GUI shows)"), as data ([`Reason`]).
#[derive(Debug, Clone, PartialEq)]
pub struct ComponentError {
    /// Why (boxed: a callback's `Result` stays small).
    pub reason: Box<Reason>,
}

impl ComponentError {
    /// A failure for this reason.
    pub fn new(reason: Reason) -> Self {
        Self {
            reason: Box::new(reason),
        }
    }

    /// A failure a component the core does not know gives in its own words.
    pub fn words(words: impl Into<String>) -> Self {
        Self::new(Reason::Words(words.into()))
    }
}

impl fmt::Display for ComponentError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.reason, f)
    }
}

impl std::error::Error for ComponentError {}

impl From<crate::Error> for ComponentError {
    fn from(e: crate::Error) -> Self {
        Self::new(Reason::Error(e))
    }
}

/// What every callback returns: OpenRTM's `ReturnCode_t` as a `Result`.
pub type ReturnCode = Result<(), ComponentError>;

/// What the execution context tells a callback about the moment it runs.
///
/// Time is simulated: integer nanoseconds since the context was created, advanced only by
/// ticks (spec §6). No component reads a clock.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Tick {
    /// Simulated time of this tick in nanoseconds.
    pub time_ns: u64,
    /// This component's period in nanoseconds (1 / its rate).
    pub period_ns: u64,
    /// The context's base tick counter (0 for the first tick).
    pub index: u64,
}

impl Tick {
    /// Simulated time in seconds (correctly rounded: `0.1 s` is `0.1`; exact up to 2⁵³ ns).
    pub fn seconds(&self) -> f64 {
        self.time_ns as f64 / 1e9
    }

    /// The period in seconds (correctly rounded, as [`Tick::seconds`]).
    pub fn period(&self) -> f64 {
        self.period_ns as f64 / 1e9
    }

    /// The timestamp of this tick, as the IDL's `RTC::Time`.
    pub fn tm(&self) -> Time {
        Time::from_nanos(self.time_ns)
    }
}

/// An RT-component: the actions of seed 003's table ("アクションのまとめ").
///
/// Every callback has a default that succeeds and does nothing, so a component overrides
/// only what it needs — as an OpenRTM component overrides only its `on???` functions.
/// A callback fails by returning [`ComponentError`]; what happens then is the execution
/// context's business ([`super::ExecutionContext`], spec §1's table).
pub trait Component: Any {
    /// The instance name (e.g. `LocalPathPlanning0`).
    fn instance_name(&self) -> &str;

    /// A copy of this component in the state it is in (its ports unconnected: see
    /// [`super::OutPort`]'s `Clone`), for a system's checkpoints; `None` (the default) for a
    /// component that cannot be copied.
    fn boxed_clone(&self) -> Option<Box<dyn Component>> {
        None
    }

    /// This component's configuration, if it has parameters (spec §1 "Configuration
    /// parameters"). The context applies `on_activation` parameters just before
    /// [`Component::on_activated`].
    fn configuration(&mut self) -> Option<&mut dyn ConfigAccess> {
        None
    }

    /// The same configuration, to read (the GUI's parameter panel, `.conf` export).
    fn configuration_ref(&self) -> Option<&dyn ConfigAccess> {
        None
    }

    /// Its data ports, in and out, with their newest samples (RT System Editor's view of
    /// the component; the system's description, `crate::system::SystemGraph`).
    fn ports(&self) -> Vec<PortView> {
        Vec::new()
    }

    /// Its in-port named `name` (an [`InPort<T>`](super::InPort) of the port's IDL type), for
    /// whoever connects an out-port to it: connections are made by port name, so whatever
    /// component stands in a place of the system (a built-in one or a student's script, spec
    /// §8) is connected the same way.
    fn in_port(&self, _name: &str) -> Option<&dyn Any> {
        None
    }

    /// Its out-port named `name` (an [`OutPort<T>`](super::OutPort)), to connect it.
    fn out_port_mut(&mut self, _name: &str) -> Option<&mut dyn Any> {
        None
    }

    /// Drops the connections of every out-port (the component at the other end is being
    /// replaced; the system connects them again).
    fn disconnect_ports(&mut self) {}

    /// The name of the student's script this component runs, if it is one (spec §8: the
    /// System tab and the component's card say so); `None` for a built-in component.
    fn script_name(&self) -> Option<&str> {
        None
    }

    /// Once, when the component is created.
    fn on_initialize(&mut self) -> ReturnCode {
        Ok(())
    }
    /// Once, when the component is finalized.
    fn on_finalize(&mut self) -> ReturnCode {
        Ok(())
    }
    /// Once, when the execution context starts running.
    fn on_startup(&mut self, _tick: &Tick) -> ReturnCode {
        Ok(())
    }
    /// Once, when the execution context stops.
    fn on_shutdown(&mut self, _tick: &Tick) -> ReturnCode {
        Ok(())
    }
    /// Once, on Inactive → Active.
    fn on_activated(&mut self, _tick: &Tick) -> ReturnCode {
        Ok(())
    }
    /// Once, on Active → Inactive.
    fn on_deactivated(&mut self, _tick: &Tick) -> ReturnCode {
        Ok(())
    }
    /// Every period while Active.
    fn on_execute(&mut self, _tick: &Tick) -> ReturnCode {
        Ok(())
    }
    /// Every period while Active, right after `on_execute`.
    fn on_state_update(&mut self, _tick: &Tick) -> ReturnCode {
        Ok(())
    }
    /// Once, before entering Error.
    fn on_aborting(&mut self, _tick: &Tick) -> ReturnCode {
        Ok(())
    }
    /// Every period while in Error.
    fn on_error(&mut self, _tick: &Tick) -> ReturnCode {
        Ok(())
    }
    /// Once, when reset from Error; success leads to Inactive, failure stays in Error.
    fn on_reset(&mut self, _tick: &Tick) -> ReturnCode {
        Ok(())
    }
    /// When the component's rate changes.
    fn on_rate_changed(&mut self, _tick: &Tick) -> ReturnCode {
        Ok(())
    }
}
