//! The RT-component lifecycle (spec §1, seed 003), the multi-rate execution context, data
//! ports and the IDL types. Every test runs natively and as wasm32 under Node.

use rtnav::errors::LifecycleError;
use rtnav::rtc::ContextState::{self, Running, Stopped};
use rtnav::rtc::LifecycleState::{self, Active, Created, Error, Finalized, Inactive};
use rtnav::rtc::{
    Component, ComponentId, ExecutionContext, InPort, LifecycleEvent, OutPort, Request, ReturnCode,
    Tick, Time, TimedDouble, TimedDoubleSeq, TimedPosition, TimedVelocity,
};
use rtnav_tests::{Call, Callback, Journal, Probe};

// ---------------------------------------------------------------------------------------------
// The lifecycle table, row by row (spec §1).

/// The probe under test.
const P: &str = "Probe0";
/// The one component's id.
const ID: ComponentId = 0;

const F_INIT: &str = "Probe0: on_initialize told to fail";
const F_STARTUP: &str = "Probe0: on_startup told to fail";
const F_SHUTDOWN: &str = "Probe0: on_shutdown told to fail";
const F_ACT: &str = "Probe0: on_activated told to fail";
const F_DEACT: &str = "Probe0: on_deactivated told to fail";
const F_EXEC: &str = "Probe0: on_execute told to fail";
const F_UPDATE: &str = "Probe0: on_state_update told to fail";
const F_ABORT: &str = "Probe0: on_aborting told to fail";
const F_ERROR: &str = "Probe0: on_error told to fail";
const F_RESET: &str = "Probe0: on_reset told to fail";
const F_RATE: &str = "Probe0: on_rate_changed told to fail";
const F_FIN: &str = "Probe0: on_finalize told to fail";
const INJECTED: &str = "injected fault: test";

/// One step of a scenario: a request to the context, or an instruction to the probe.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Op {
    /// Attach the probe at 1 kHz (the base rate: it runs on every tick).
    Attach,
    /// Attach the probe at this rate.
    AttachAt(f64),
    Initialize,
    Start,
    Stop,
    Activate,
    Deactivate,
    Reset,
    Finalize,
    Ticks(u64),
    Rate(f64),
    Inject,
    /// Make the probe's callback fail from now on.
    Fail(Callback),
    /// Make it succeed again.
    Heal(Callback),
}
use Op::*;

/// Started, one probe Inactive.
const UP: &[Op] = &[Attach, Start];
/// Started, the probe Active.
const ACT: &[Op] = &[Attach, Start, Activate];
/// Started, the probe in Error (its `on_execute` failed and still fails).
const ERR: &[Op] = &[Attach, Start, Activate, Fail(Callback::Execute), Ticks(1)];
/// Started, the probe left in Created (`on_initialize` failed and still fails).
const DEAD: &[Op] = &[Fail(Callback::Initialize), Attach, Start];
/// Started, the probe finalized.
const FIN: &[Op] = &[Attach, Start, Finalize];

/// What a request led to: the component's state, the context's, the callbacks the request
/// ran (as [`Journal::counts_text_since`]) and the component's last error.
#[derive(Debug, Clone, PartialEq)]
struct Outcome {
    state: LifecycleState,
    context: ContextState,
    calls: String,
    last_error: Option<String>,
}

fn ok(
    state: LifecycleState,
    context: ContextState,
    calls: &str,
    last_error: Option<&str>,
) -> Result<Outcome, LifecycleError> {
    Ok(Outcome {
        state,
        context,
        calls: calls.to_owned(),
        last_error: last_error.map(str::to_owned),
    })
}

fn invalid(from: LifecycleState, request: Request) -> Result<Outcome, LifecycleError> {
    Err(LifecycleError::InvalidTransition {
        component: P.to_owned(),
        from,
        request,
    })
}

fn not_running(request: Request) -> Result<Outcome, LifecycleError> {
    Err(LifecycleError::ContextNotRunning {
        component: P.to_owned(),
        request,
        context: Stopped,
    })
}

fn already(state: ContextState) -> Result<Outcome, LifecycleError> {
    Err(LifecycleError::ContextAlready { state })
}

fn bad_rate(rate: f64, reason: &str) -> Result<Outcome, LifecycleError> {
    Err(LifecycleError::InvalidRate {
        component: P.to_owned(),
        rate,
        reason: reason.to_owned(),
    })
}

/// Everything a request could change, for "an illegal request changes nothing".
#[derive(Debug, Clone, PartialEq)]
struct Snapshot {
    components: usize,
    state: Option<LifecycleState>,
    context: ContextState,
    ticks: u64,
    calls: usize,
    events: Vec<LifecycleEvent>,
    last_error: Option<String>,
    fault_pending: Option<bool>,
    rate: Option<f64>,
}

struct World {
    ec: ExecutionContext,
    journal: Journal,
}

impl World {
    fn new() -> Self {
        Self {
            ec: ExecutionContext::new(1000.0).unwrap(),
            journal: Journal::new(),
        }
    }

    fn run(&mut self, op: Op) -> Result<(), LifecycleError> {
        let state = match op {
            Attach => return self.run(AttachAt(1000.0)),
            AttachAt(rate) => {
                let id = self.ec.attach(self.journal.probe(P), rate)?;
                assert_eq!(id, ID);
                return Ok(());
            }
            Initialize => self.ec.initialize(ID)?,
            Activate => self.ec.activate(ID)?,
            Deactivate => self.ec.deactivate(ID)?,
            Reset => self.ec.reset(ID)?,
            Finalize => self.ec.finalize(ID)?,
            Start => return self.ec.start(),
            Stop => return self.ec.stop(),
            Rate(rate) => return self.ec.set_rate(ID, rate),
            Inject => return self.ec.inject_fault(ID, "test"),
            Ticks(n) => {
                self.ec.run_ticks(n);
                return Ok(());
            }
            Fail(cb) => {
                self.journal.fail(P, cb);
                return Ok(());
            }
            Heal(cb) => {
                self.journal.heal(P, cb);
                return Ok(());
            }
        };
        // The state a request returns is the state it left the component in.
        assert_eq!(Ok(state), self.ec.state(ID));
        Ok(())
    }

    fn snapshot(&self) -> Snapshot {
        Snapshot {
            components: self.ec.len(),
            state: self.ec.state(ID).ok(),
            context: self.ec.context_state(),
            ticks: self.ec.tick_count(),
            calls: self.journal.len(),
            events: self.ec.events().to_vec(),
            last_error: self
                .ec
                .last_error(ID)
                .ok()
                .flatten()
                .map(ToString::to_string),
            fault_pending: self.ec.fault_pending(ID).ok(),
            rate: self.ec.rate(ID).ok(),
        }
    }
}

/// Runs `setup` (which must succeed), then `request`, and compares with `expect` exactly. An
/// expected error must also leave everything as it was.
fn check(setup: &[Op], request: Op, expect: Result<Outcome, LifecycleError>) {
    let mut w = World::new();
    for op in setup {
        w.run(*op)
            .unwrap_or_else(|e| panic!("setup {setup:?}: {op:?} failed: {e}"));
    }
    let before = w.snapshot();
    let got = w.run(request);
    let row = format!("{setup:?} then {request:?}");
    match expect {
        Ok(want) => {
            assert_eq!(got, Ok(()), "{row}");
            let outcome = Outcome {
                state: w.ec.state(ID).unwrap(),
                context: w.ec.context_state(),
                calls: w.journal.counts_text_since(P, before.calls),
                last_error: w.ec.last_error(ID).unwrap().map(ToString::to_string),
            };
            assert_eq!(outcome, want, "{row}");
        }
        Err(e) => {
            assert_eq!(got, Err(e), "{row}");
            assert_eq!(
                w.snapshot(),
                before,
                "{row}: an illegal request changed something"
            );
        }
    }
}

/// Concatenates setups.
fn then(a: &[Op], b: &[Op]) -> Vec<Op> {
    a.iter().chain(b).copied().collect()
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn legal_transitions_follow_the_table() {
    use Callback as C;
    #[rustfmt::skip]
    let rows: Vec<(Vec<Op>, Op, Result<Outcome, LifecycleError>)> = vec![
        // create: on_initialize once → Inactive (Created if it fails).
        (vec![], Attach, ok(Inactive, Stopped, "on_initialize=1", None)),
        (vec![Fail(C::Initialize)], Attach, ok(Created, Stopped, "on_initialize=1", Some(F_INIT))),
        (vec![Fail(C::Initialize), Attach], Initialize, ok(Created, Stopped, "on_initialize=1", Some(F_INIT))),
        (vec![Fail(C::Initialize), Attach, Heal(C::Initialize)], Initialize, ok(Inactive, Stopped, "on_initialize=1", None)),
        // Decision: becoming alive in a Running context brings on_startup at once.
        (vec![Start], Attach, ok(Inactive, Running, "on_initialize=1 on_startup=1", None)),
        (then(DEAD, &[Heal(C::Initialize)]), Initialize, ok(Inactive, Running, "on_initialize=1 on_startup=1", None)),
        // EC start / stop: on_startup / on_shutdown once each, for alive components only.
        (vec![Attach], Start, ok(Inactive, Running, "on_startup=1", None)),
        (UP.to_vec(), Stop, ok(Inactive, Stopped, "on_shutdown=1", None)),
        (ACT.to_vec(), Stop, ok(Active, Stopped, "on_shutdown=1", None)),
        (ERR.to_vec(), Stop, ok(Error, Stopped, "on_shutdown=1", Some(F_EXEC))),
        (vec![Attach, Start, Stop], Start, ok(Inactive, Running, "on_startup=1", None)),
        (vec![Attach, Fail(C::Startup)], Start, ok(Inactive, Running, "on_startup=1", Some(F_STARTUP))),
        (then(UP, &[Fail(C::Shutdown)]), Stop, ok(Inactive, Stopped, "on_shutdown=1", Some(F_SHUTDOWN))),
        (vec![Fail(C::Initialize), Attach], Start, ok(Created, Running, "", Some(F_INIT))),
        (vec![Attach, Finalize], Start, ok(Finalized, Running, "", None)),
        (FIN.to_vec(), Stop, ok(Finalized, Stopped, "", None)),
        // activate: Inactive → Active; if on_activated fails → on_aborting → Error.
        (UP.to_vec(), Activate, ok(Active, Running, "on_activated=1", None)),
        (then(UP, &[Fail(C::Activated)]), Activate, ok(Error, Running, "on_activated=1 on_aborting=1", Some(F_ACT))),
        (then(UP, &[Fail(C::Activated), Fail(C::Aborting)]), Activate, ok(Error, Running, "on_activated=1 on_aborting=1", Some(F_ABORT))),
        (then(ACT, &[Deactivate]), Activate, ok(Active, Running, "on_activated=1", None)),
        // every tick while Active: on_execute then on_state_update; a failure → on_aborting → Error.
        (ACT.to_vec(), Ticks(1), ok(Active, Running, "on_execute=1 on_state_update=1", None)),
        (ACT.to_vec(), Ticks(5), ok(Active, Running, "on_execute=5 on_state_update=5", None)),
        (then(ACT, &[Fail(C::Execute)]), Ticks(1), ok(Error, Running, "on_execute=1 on_aborting=1", Some(F_EXEC))),
        (then(ACT, &[Fail(C::StateUpdate)]), Ticks(1), ok(Error, Running, "on_execute=1 on_state_update=1 on_aborting=1", Some(F_UPDATE))),
        (then(ACT, &[Fail(C::Execute), Fail(C::Aborting)]), Ticks(1), ok(Error, Running, "on_execute=1 on_aborting=1", Some(F_ABORT))),
        // ... exactly one on_aborting, then only on_error
        (then(ACT, &[Fail(C::Execute)]), Ticks(4), ok(Error, Running, "on_execute=1 on_aborting=1 on_error=3", Some(F_EXEC))),
        // every tick while Error: on_error once, and nothing else (healed or not)
        (ERR.to_vec(), Ticks(1), ok(Error, Running, "on_error=1", Some(F_EXEC))),
        (ERR.to_vec(), Ticks(7), ok(Error, Running, "on_error=7", Some(F_EXEC))),
        (then(ERR, &[Heal(C::Execute)]), Ticks(3), ok(Error, Running, "on_error=3", Some(F_EXEC))),
        (then(ERR, &[Fail(C::Error)]), Ticks(2), ok(Error, Running, "on_error=2", Some(F_ERROR))),
        // ticks run nothing for Inactive, Created and Finalized components
        (UP.to_vec(), Ticks(5), ok(Inactive, Running, "", None)),
        (DEAD.to_vec(), Ticks(5), ok(Created, Running, "", Some(F_INIT))),
        (FIN.to_vec(), Ticks(5), ok(Finalized, Running, "", None)),
        // deactivate: Active → Inactive (Decision: also when on_deactivated fails).
        (ACT.to_vec(), Deactivate, ok(Inactive, Running, "on_deactivated=1", None)),
        (then(ACT, &[Fail(C::Deactivated)]), Deactivate, ok(Inactive, Running, "on_deactivated=1", Some(F_DEACT))),
        // reset: Error → Inactive if on_reset succeeds, stays in Error if it fails.
        (ERR.to_vec(), Reset, ok(Inactive, Running, "on_reset=1", None)),
        (then(ERR, &[Fail(C::Reset)]), Reset, ok(Error, Running, "on_reset=1", Some(F_RESET))),
        (then(ERR, &[Fail(C::Reset), Reset, Heal(C::Reset)]), Reset, ok(Inactive, Running, "on_reset=1", None)),
        (then(UP, &[Fail(C::Activated), Activate, Heal(C::Activated)]), Reset, ok(Inactive, Running, "on_reset=1", None)),
        (then(ERR, &[Heal(C::Execute), Reset]), Activate, ok(Active, Running, "on_activated=1", None)),
        (then(ERR, &[Heal(C::Execute), Reset, Activate]), Ticks(2), ok(Active, Running, "on_execute=2 on_state_update=2", None)),
        // rate change: on_rate_changed, state unchanged (also when it fails).
        (UP.to_vec(), Rate(500.0), ok(Inactive, Running, "on_rate_changed=1", None)),
        (ACT.to_vec(), Rate(500.0), ok(Active, Running, "on_rate_changed=1", None)),
        (ERR.to_vec(), Rate(500.0), ok(Error, Running, "on_rate_changed=1", Some(F_EXEC))),
        (then(ACT, &[Fail(C::RateChanged)]), Rate(500.0), ok(Active, Running, "on_rate_changed=1", Some(F_RATE))),
        (DEAD.to_vec(), Rate(500.0), ok(Created, Running, "", Some(F_INIT))),
        (vec![Attach], Rate(500.0), ok(Inactive, Stopped, "", None)),
        // ... and the new rate holds: every second base tick (0, 2, 4)
        (then(ACT, &[Rate(500.0)]), Ticks(5), ok(Active, Running, "on_execute=3 on_state_update=3", None)),
        // finalize: from any state, on_finalize once (also when it fails), Running or Stopped.
        (vec![Fail(C::Initialize), Attach], Finalize, ok(Finalized, Stopped, "on_finalize=1", Some(F_INIT))),
        (vec![Attach], Finalize, ok(Finalized, Stopped, "on_finalize=1", None)),
        (UP.to_vec(), Finalize, ok(Finalized, Running, "on_finalize=1", None)),
        (ACT.to_vec(), Finalize, ok(Finalized, Running, "on_finalize=1", None)),
        (ERR.to_vec(), Finalize, ok(Finalized, Running, "on_finalize=1", Some(F_EXEC))),
        (then(ACT, &[Stop]), Finalize, ok(Finalized, Stopped, "on_finalize=1", None)),
        (vec![Attach, Fail(C::Finalize)], Finalize, ok(Finalized, Stopped, "on_finalize=1", Some(F_FIN))),
        // no callback runs while the context is Stopped
        (then(ACT, &[Stop]), Ticks(10), ok(Active, Stopped, "", None)),
        (then(ERR, &[Stop]), Ticks(10), ok(Error, Stopped, "", Some(F_EXEC))),
        (then(ACT, &[Stop, Start]), Ticks(1), ok(Active, Running, "on_execute=1 on_state_update=1", None)),
        // inject fault: exactly the next on_execute fails (it stands in for the component's own).
        (ACT.to_vec(), Inject, ok(Active, Running, "", None)),
        (then(ACT, &[Inject]), Ticks(1), ok(Error, Running, "on_aborting=1", Some(INJECTED))),
        (then(ACT, &[Inject, Ticks(1)]), Ticks(1), ok(Error, Running, "on_error=1", Some(INJECTED))),
        (then(ACT, &[Inject, Ticks(1), Reset, Activate]), Ticks(3), ok(Active, Running, "on_execute=3 on_state_update=3", None)),
        (then(ACT, &[Inject, Inject, Ticks(1), Reset, Activate]), Ticks(1), ok(Active, Running, "on_execute=1 on_state_update=1", None)),
        (then(ACT, &[Ticks(2), Inject]), Ticks(2), ok(Error, Running, "on_aborting=1 on_error=1", Some(INJECTED))),
        (then(UP, &[Inject, Activate]), Ticks(1), ok(Error, Running, "on_aborting=1", Some(INJECTED))),
        (then(ACT, &[Inject, Deactivate, Activate]), Ticks(1), ok(Error, Running, "on_aborting=1", Some(INJECTED))),
        (then(ACT, &[Inject, Stop]), Ticks(3), ok(Active, Stopped, "", None)),
    ];
    for (setup, request, expect) in rows {
        check(&setup, request, expect);
    }
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn illegal_requests_are_refused_and_change_nothing() {
    use Request as R;
    let after_finalize = [
        (Activate, R::Activate),
        (Deactivate, R::Deactivate),
        (Reset, R::Reset),
        (Initialize, R::Initialize),
        (Finalize, R::Finalize),
        (Rate(500.0), R::ChangeRate),
        (Inject, R::InjectFault),
    ];
    #[rustfmt::skip]
    let mut rows: Vec<(Vec<Op>, Op, Result<Outcome, LifecycleError>)> = vec![
        // activate only from Inactive
        (ACT.to_vec(), Activate, invalid(Active, R::Activate)),
        (ERR.to_vec(), Activate, invalid(Error, R::Activate)),
        (DEAD.to_vec(), Activate, invalid(Created, R::Activate)),
        // deactivate only from Active
        (UP.to_vec(), Deactivate, invalid(Inactive, R::Deactivate)),
        (ERR.to_vec(), Deactivate, invalid(Error, R::Deactivate)),
        (DEAD.to_vec(), Deactivate, invalid(Created, R::Deactivate)),
        // reset only from Error
        (UP.to_vec(), Reset, invalid(Inactive, R::Reset)),
        (ACT.to_vec(), Reset, invalid(Active, R::Reset)),
        (DEAD.to_vec(), Reset, invalid(Created, R::Reset)),
        // initialize only from Created
        (UP.to_vec(), Initialize, invalid(Inactive, R::Initialize)),
        (ACT.to_vec(), Initialize, invalid(Active, R::Initialize)),
        (ERR.to_vec(), Initialize, invalid(Error, R::Initialize)),
        // inject a fault only while Inactive or Active
        (ERR.to_vec(), Inject, invalid(Error, R::InjectFault)),
        (DEAD.to_vec(), Inject, invalid(Created, R::InjectFault)),
        // activate / deactivate / reset need a Running context
        (vec![Attach], Activate, not_running(R::Activate)),
        (then(ACT, &[Stop]), Deactivate, not_running(R::Deactivate)),
        (then(ERR, &[Stop]), Reset, not_running(R::Reset)),
        // ... but an illegal transition is reported as such even then
        (vec![Attach], Reset, invalid(Inactive, R::Reset)),
        // start while Running, stop while Stopped
        (UP.to_vec(), Start, already(Running)),
        (ACT.to_vec(), Start, already(Running)),
        (vec![Attach], Stop, already(Stopped)),
        (vec![], Stop, already(Stopped)),
        (then(UP, &[Stop]), Stop, already(Stopped)),
        // rates: positive, finite, at most 1 kHz, a whole number of nanoseconds and of base
        // ticks
        (UP.to_vec(), Rate(0.0), bad_rate(0.0, "it must be positive and finite")),
        (UP.to_vec(), Rate(-10.0), bad_rate(-10.0, "it must be positive and finite")),
        (UP.to_vec(), Rate(f64::INFINITY), bad_rate(f64::INFINITY, "it must be positive and finite")),
        (UP.to_vec(), Rate(3.0), bad_rate(3.0, "its period is not a whole number of nanoseconds")),
        (UP.to_vec(), Rate(999.0), bad_rate(999.0, "its period is not a whole number of nanoseconds")),
        (UP.to_vec(), Rate(2000.0), bad_rate(2000.0, "it is above the highest rate, 1000 Hz (the physics' 1 ms step)")),
        (UP.to_vec(), Rate(1e9), bad_rate(1e9, "it is above the highest rate, 1000 Hz (the physics' 1 ms step)")),
        (vec![Start], AttachAt(400.0), bad_rate(400.0, "its period of 2500000 ns is not a whole number of base ticks (1000000 ns)")),
    ];
    // anything after finalize, from every state finalize can come from
    for fin in [
        vec![Attach, Finalize],
        then(FIN, &[]),
        then(ACT, &[Finalize]),
        then(ERR, &[Finalize]),
        then(DEAD, &[Finalize]),
    ] {
        for (op, request) in after_finalize {
            rows.push((fin.clone(), op, invalid(Finalized, request)));
        }
    }
    for (setup, request, expect) in rows {
        check(&setup, request, expect);
    }
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn requests_for_an_unknown_component_are_refused() {
    let mut w = World::new();
    w.run(Attach).unwrap();
    w.run(Start).unwrap();
    let before = w.snapshot();
    let unknown = Err(LifecycleError::UnknownComponent { id: 1 });
    let ec = &mut w.ec;
    assert_eq!(ec.activate(1), unknown.clone().map(|()| Active));
    assert_eq!(ec.deactivate(1), unknown.clone().map(|()| Active));
    assert_eq!(ec.reset(1), unknown.clone().map(|()| Active));
    assert_eq!(ec.initialize(1), unknown.clone().map(|()| Active));
    assert_eq!(ec.finalize(1), unknown.clone().map(|()| Active));
    assert_eq!(ec.set_rate(1, 10.0), unknown.clone());
    assert_eq!(ec.inject_fault(1, "x"), unknown.clone());
    assert_eq!(ec.state(1), unknown.clone().map(|()| Active));
    assert_eq!(ec.last_error(1), unknown.clone().map(|()| None));
    assert_eq!(ec.rate(1), unknown.clone().map(|()| 0.0));
    assert!(ec.component::<Probe>(1).is_none());
    assert_eq!(w.snapshot(), before);
}

/// A component that is not a [`Probe`], to show `component::<T>` checks the type.
struct Silent;

impl Component for Silent {
    fn instance_name(&self) -> &str {
        "Silent0"
    }
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn components_are_reached_by_id_and_type() {
    let journal = Journal::new();
    let mut ec = ExecutionContext::new(100.0).unwrap();
    assert_eq!(ec.attach(journal.probe(P), 100.0), Ok(0));
    assert_eq!(ec.attach(Box::new(Silent), 50.0), Ok(1));
    assert_eq!((ec.len(), ec.is_empty()), (2, false));
    assert_eq!(ec.name(1), Ok("Silent0"));
    assert_eq!(ec.component::<Probe>(0).map(|p| p.instance_name()), Some(P));
    assert!(ec.component::<Silent>(0).is_none());
    assert!(ec.component::<Silent>(1).is_some());
    assert!(ec.component_mut::<Probe>(1).is_none());
    assert_eq!((ec.rate(0), ec.rate(1)), (Ok(100.0), Ok(50.0)));
    assert_eq!(ec.base_period_ns(), 10_000_000);
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn events_record_every_state_change_and_failure() {
    let mut w = World::new();
    for op in [
        Attach,
        Start,
        Activate,
        Ticks(2),
        Fail(Callback::Execute),
        Ticks(1),
    ] {
        w.run(op).unwrap();
    }
    w.run(Fail(Callback::Reset)).unwrap();
    w.run(Reset).unwrap();
    w.run(Heal(Callback::Reset)).unwrap();
    w.run(Reset).unwrap();
    w.run(Inject).unwrap();
    w.run(Activate).unwrap();
    w.run(Ticks(1)).unwrap();
    assert_eq!(w.ec.fault_pending(ID), Ok(false));
    // The events with their reasons in words.
    let ev = |time_ms: u64, from, to, callback, reason: Option<&str>| {
        (
            LifecycleEvent {
                time_ns: time_ms * 1_000_000,
                id: ID,
                component: P.to_owned(),
                from,
                to,
                callback,
                reason: None,
            },
            reason.map(str::to_owned),
        )
    };
    let said = |events: Vec<LifecycleEvent>| -> Vec<(LifecycleEvent, Option<String>)> {
        events
            .into_iter()
            .map(|mut e| {
                let reason = e.reason.take().map(|r| r.to_string());
                (e, reason)
            })
            .collect()
    };
    assert_eq!(
        said(w.ec.drain_events()),
        vec![
            ev(0, Created, Inactive, "on_initialize", None),
            ev(0, Inactive, Active, "on_activated", None),
            ev(2, Active, Error, "on_execute", Some(F_EXEC)),
            ev(3, Error, Error, "on_reset", Some(F_RESET)),
            ev(3, Error, Inactive, "on_reset", None),
            ev(3, Inactive, Active, "on_activated", None),
            ev(3, Active, Error, "on_execute", Some(INJECTED)),
        ]
    );
    assert_eq!(w.ec.drain_events(), vec![]);
    assert_eq!(
        w.ec.last_error(ID).map(|r| r.map(ToString::to_string)),
        Ok(Some(INJECTED.to_owned()))
    );
    assert_eq!(w.ec.time_ns(), 4_000_000);
}

// ---------------------------------------------------------------------------------------------
// Multi-rate execution in simulated time (spec §6, the documented order).

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn one_khz_and_ten_hz_interleave_exactly() {
    const MS: u64 = 1_000_000;
    let journal = Journal::new();
    let mut ec = ExecutionContext::new(1000.0).unwrap();
    let fast = ec.attach(journal.probe("Fast"), 1000.0).unwrap();
    let slow = ec.attach(journal.probe("Slow"), 10.0).unwrap();
    ec.start().unwrap();
    ec.activate(fast).unwrap();
    ec.activate(slow).unwrap();
    let mark = journal.len();
    // 1 s of simulated time, both ends included: base ticks 0..=1000.
    ec.run_ticks(1001);
    assert_eq!(ec.time_ns(), 1_001 * MS);
    assert_eq!(ec.tick_count(), 1001);
    let calls = &journal.calls()[mark..];

    // Literal figures first (short messages on failure), then the whole interleaving.
    let execs: Vec<(&str, u64)> = calls
        .iter()
        .filter(|c| c.callback == Callback::Execute)
        .map(|c| (c.component.as_str(), c.tick.unwrap().time_ns))
        .collect();
    assert_eq!(execs.len(), 1001 + 11);
    assert_eq!(
        &execs[..6],
        &[
            ("Fast", 0),
            ("Slow", 0),
            ("Fast", MS),
            ("Fast", 2 * MS),
            ("Fast", 3 * MS),
            ("Fast", 4 * MS)
        ]
    );
    let slow_at: Vec<usize> = (0..execs.len()).filter(|&i| execs[i].0 == "Slow").collect();
    assert_eq!(
        slow_at,
        [1, 102, 203, 304, 405, 506, 607, 708, 809, 910, 1011]
    );
    // exactly 100 ticks of the 1 kHz component per tick of the 10 Hz one
    let fast_between: Vec<usize> = slow_at.windows(2).map(|w| w[1] - w[0] - 1).collect();
    assert_eq!(fast_between, [100; 10]);
    let slow_times: Vec<u64> = slow_at.iter().map(|&i| execs[i].1).collect();
    assert_eq!(
        slow_times,
        [0, 100, 200, 300, 400, 500, 600, 700, 800, 900, 1000].map(|t| t * MS)
    );
    let last_slow = calls.iter().rev().find(|c| c.component == "Slow").unwrap();
    assert_eq!(last_slow.tick.unwrap().tm(), Time { sec: 1, nsec: 0 });
    assert_eq!(last_slow.tick.unwrap().seconds(), 1.0);
    assert_eq!(last_slow.tick.unwrap().period(), 0.1);
    assert_eq!(
        journal.counts_text_since("Slow", mark),
        "on_execute=11 on_state_update=11"
    );
    assert_eq!(
        journal.counts_text_since("Fast", mark),
        "on_execute=1001 on_state_update=1001"
    );

    // The documented order, written out: on tick k the 1 kHz component, then (if 100 | k)
    // the 10 Hz one; each runs on_execute then on_state_update.
    let call = |name: &str, callback, k: u64, period_ms: u64| Call {
        component: name.to_owned(),
        callback,
        tick: Some(Tick {
            time_ns: k * MS,
            period_ns: period_ms * MS,
            index: k,
        }),
    };
    let mut want = Vec::new();
    for k in 0..=1000 {
        want.push(call("Fast", Callback::Execute, k, 1));
        want.push(call("Fast", Callback::StateUpdate, k, 1));
        if k % 100 == 0 {
            want.push(call("Slow", Callback::Execute, k, 100));
            want.push(call("Slow", Callback::StateUpdate, k, 100));
        }
    }
    assert_eq!(calls, want.as_slice());
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn simulated_time_is_exact_in_integer_nanoseconds() {
    // A base rate whose period is not a whole number of nanoseconds is refused ...
    assert_eq!(
        ExecutionContext::new(999.0).unwrap_err(),
        LifecycleError::InvalidRate {
            component: "the base tick".to_owned(),
            rate: 999.0,
            reason: "its period is not a whole number of nanoseconds".to_owned()
        }
    );
    // ... and so is one above 1 kHz (a 1 GHz base would make a second a billion ticks).
    assert_eq!(
        ExecutionContext::new(1e9).unwrap_err().to_string(),
        "the base tick: rate 1000000000 Hz is not usable: it is above the highest rate, \
         1000 Hz (the physics' 1 ms step)"
    );
    // ... and a usable one never drifts: 10^6 ticks of 1 ms are exactly 1000 s.
    let mut ec = ExecutionContext::new(1000.0).unwrap();
    ec.run_ticks(1_000_000);
    assert_eq!(ec.time_ns(), 1_000_000_000_000);
    assert_eq!(Time::from_nanos(ec.time_ns()), Time { sec: 1000, nsec: 0 });
    let t = Time::from_nanos(1_234_567_890_123);
    assert_eq!(
        t,
        Time {
            sec: 1234,
            nsec: 567_890_123
        }
    );
    assert_eq!(t.as_nanos(), 1_234_567_890_123);
}

// ---------------------------------------------------------------------------------------------
// Data ports (spec §1 "InPort<T> / OutPort<T>").

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn ports_is_new_and_read() {
    #[derive(Debug, Clone, Copy)]
    enum Step {
        Write(i32),
        ConnectA,
        ConnectB,
        ReadA,
        ReadB,
        PeekA,
        ClearA,
    }
    use Step::*;
    let mut out = OutPort::new("Out");
    let a = InPort::new("InA");
    let b = InPort::new("InB");
    // Each step: what it returned (a read or peek), then a.is_new(), b.is_new().
    let script: [(Step, Option<i32>, bool, bool); 16] = [
        (ReadA, None, false, false),
        (Write(1), None, false, false), // not connected: goes nowhere
        (ConnectA, None, false, false), // an earlier write is not delivered
        (ReadA, None, false, false),
        (Write(2), None, true, false),
        (ConnectB, None, true, false),
        (ConnectA, None, true, false), // connecting twice is one connection
        (Write(3), None, true, true),  // the newest value overwrites
        (PeekA, Some(3), true, true),  // peek does not mark it read
        (ReadA, Some(3), false, true),
        (ReadA, Some(3), false, true), // read again: the same value, still not new
        (Write(4), None, true, true),
        (ReadB, Some(4), true, false),
        (ReadA, Some(4), false, false),
        (ClearA, None, false, false),
        (ReadA, None, false, false),
    ];
    for (i, (step, want, a_new, b_new)) in script.into_iter().enumerate() {
        let got = match step {
            Write(v) => {
                out.write(v);
                None
            }
            ConnectA => {
                out.connect(&a);
                None
            }
            ConnectB => {
                out.connect(&b);
                None
            }
            ReadA => a.read(),
            ReadB => b.read(),
            PeekA => a.peek(),
            ClearA => {
                a.clear();
                None
            }
        };
        assert_eq!(
            (got, a.is_new(), b.is_new()),
            (want, a_new, b_new),
            "step {i}: {step:?}"
        );
    }
    assert_eq!((out.name(), a.name(), b.name()), ("Out", "InA", "InB"));
    assert_eq!(
        (out.connection_count(), out.write_count(), out.last()),
        (2, 4, Some(&4))
    );
}

/// Writes the tick index on `Out` every tick.
struct Writer {
    out: OutPort<TimedDouble>,
}

impl Component for Writer {
    fn instance_name(&self) -> &str {
        "Writer0"
    }
    fn on_execute(&mut self, tick: &Tick) -> ReturnCode {
        self.out.write(TimedDouble {
            tm: tick.tm(),
            data: tick.index as f64,
        });
        Ok(())
    }
}

/// On each tick records `(is_new, read(), is_new after the read)` of `In`.
struct Reader {
    input: InPort<TimedDouble>,
    seen: Vec<(bool, Option<f64>, bool)>,
}

impl Component for Reader {
    fn instance_name(&self) -> &str {
        "Reader0"
    }
    fn on_execute(&mut self, _tick: &Tick) -> ReturnCode {
        let new = self.input.is_new();
        let value = self.input.read().map(|d| d.data);
        self.seen.push((new, value, self.input.is_new()));
        Ok(())
    }
}

/// A 1 kHz writer and a 10 Hz reader in one context; `writer_first` is the attach order.
fn run_connection(writer_first: bool) -> Vec<(bool, Option<f64>, bool)> {
    let input = InPort::new("In");
    let mut out = OutPort::new("Out");
    out.connect(&input);
    let writer = Box::new(Writer { out });
    let reader = Box::new(Reader {
        input,
        seen: Vec::new(),
    });
    let mut ec = ExecutionContext::new(1000.0).unwrap();
    let (w, r) = if writer_first {
        (
            ec.attach(writer, 1000.0).unwrap(),
            ec.attach(reader, 10.0).unwrap(),
        )
    } else {
        let r = ec.attach(reader, 10.0).unwrap();
        (ec.attach(writer, 1000.0).unwrap(), r)
    };
    ec.start().unwrap();
    ec.activate(w).unwrap();
    ec.activate(r).unwrap();
    ec.run_ticks(301);
    // the writer stops: the reader sees nothing new
    ec.deactivate(w).unwrap();
    ec.run_ticks(100);
    ec.component::<Reader>(r).unwrap().seen.clone()
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn ports_carry_the_newest_value_across_a_connection() {
    // Writer attached first: on ticks 0, 100, 200, 300 it has just written that tick's value.
    assert_eq!(
        run_connection(true),
        vec![
            (true, Some(0.0), false),
            (true, Some(100.0), false),
            (true, Some(200.0), false),
            (true, Some(300.0), false),
            (false, Some(300.0), false),
        ]
    );
    // Reader first: it sees nothing at tick 0, then the value of the tick before.
    assert_eq!(
        run_connection(false),
        vec![
            (false, None, false),
            (true, Some(99.0), false),
            (true, Some(199.0), false),
            (true, Some(299.0), false),
            (true, Some(300.0), false),
        ]
    );
}

// ---------------------------------------------------------------------------------------------
// IDL types: serde round trips (spec §1 "Data types follow the IDL").

/// Serializes `value` to `json` exactly, and back to an equal value that serializes the same.
fn round_trip<T>(value: &T, json: &str)
where
    T: serde::Serialize + serde::de::DeserializeOwned + PartialEq + std::fmt::Debug,
{
    assert_eq!(serde_json::to_string(value).unwrap(), json);
    let back: T = serde_json::from_str(json).unwrap();
    assert_eq!(&back, value);
    assert_eq!(serde_json::to_string(&back).unwrap(), json);
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn idl_types_round_trip_through_serde() {
    let tm = Time {
        sec: 12,
        nsec: 345_000_678,
    };
    round_trip(&tm, r#"{"sec":12,"nsec":345000678}"#);
    round_trip(
        &Time {
            sec: u32::MAX,
            nsec: 999_999_999,
        },
        r#"{"sec":4294967295,"nsec":999999999}"#,
    );
    round_trip(
        &TimedPosition {
            tm,
            id: vec![1, -2],
            x: 0.1,
            y: -2.5e-300,
            theta: std::f64::consts::PI,
            error: vec![],
        },
        r#"{"tm":{"sec":12,"nsec":345000678},"id":[1,-2],"x":0.1,"y":-2.5e-300,"theta":3.141592653589793,"error":[]}"#,
    );
    round_trip(
        &TimedVelocity {
            tm,
            id: vec![],
            vx: 0.3,
            vy: -0.0,
            w: -1.0 / 3.0,
            error: vec![0.5],
        },
        r#"{"tm":{"sec":12,"nsec":345000678},"id":[],"vx":0.3,"vy":-0.0,"w":-0.3333333333333333,"error":[0.5]}"#,
    );
    round_trip(
        &TimedDouble {
            tm: Time::default(),
            data: 1e21,
        },
        r#"{"tm":{"sec":0,"nsec":0},"data":1e+21}"#,
    );
    round_trip(
        &TimedDoubleSeq {
            tm,
            data: vec![
                0.0,
                1.0,
                2.0,
                0.1,
                0.2,
                0.30000000000000004,
                1.7976931348623157e308,
            ],
        },
        r#"{"tm":{"sec":12,"nsec":345000678},"data":[0.0,1.0,2.0,0.1,0.2,0.30000000000000004,1.7976931348623157e+308]}"#,
    );
    // -0.0 keeps its sign bit through the round trip
    let back: TimedVelocity = serde_json::from_str(
        r#"{"tm":{"sec":0,"nsec":0},"id":[],"vx":0.0,"vy":-0.0,"w":0.0,"error":[]}"#,
    )
    .unwrap();
    assert_eq!(back.vy.to_bits(), (-0.0f64).to_bits());
}
