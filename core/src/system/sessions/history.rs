//! [`History`]: what a [`Session`](crate::system::Session) keeps of its run to hand it in and to move
//! through it in time — the set-up it started from, every request carried out with its
//! simulated time (a [`Replay`]'s inputs), checkpoints of the whole state every few seconds,
//! and marks of what happened (the page's timeline).
//!
//! Going back in time restores the nearest checkpoint at or before the time asked for and
//! runs from it, applying the recorded requests at their times; the system being
//! deterministic, the state reached is the one the run had then, bit for bit. Requests after
//! that time stay recorded: playing on replays them. A request made there (a person takes
//! over) drops them, and the checkpoints and marks after it.
//!
//! Checkpoints are taken every [`CHECKPOINT_NS`] of simulated time; past
//! [`MAX_CHECKPOINTS`] every other one is dropped and the spacing doubles, so a long run
//! keeps a bounded number (a 5-minute run: checkpoints 8 s apart at most). A copy of the
//! system holds its map's per-cell data several times over, so a large map keeps fewer:
//! at most [`CHECKPOINT_CELLS`] map cells in all, and never fewer than 4 checkpoints.

use std::collections::BTreeMap;

use serde::Serialize;

use super::replay::{Replay, TimedInput};
use super::views::EventView;
use crate::system::runs::exercise_watch::ExerciseWatch;
use crate::system::runs::setup::Setup;
use crate::system::runs::timeline::Timeline;
use crate::system::simulation::record::Record;
use crate::system::simulation::robot::System;
use crate::system::vocabulary::events::{EventKind, SystemEvent};
use crate::system::vocabulary::input::Input;

/// The first spacing of checkpoints \[ns\] of simulated time.
pub const CHECKPOINT_NS: u64 = 2_000_000_000;
/// The most checkpoints kept (past it, every other one is dropped).
pub const MAX_CHECKPOINTS: usize = 40;
/// The most map cells all checkpoints hold together (the memory bound on large maps).
pub const CHECKPOINT_CELLS: usize = 12_000_000;

/// What a mark on the timeline stands for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
#[serde(rename_all = "snake_case")]
pub enum MarkKind {
    /// A global plan, or a local plan sent to DriveControl.
    Plan,
    /// A planning failure.
    Failure,
    /// A bump.
    Bump,
    /// An injected fault or a component in Error.
    Fault,
    /// Arrival at the goal.
    Arrival,
}

/// Something that happened, marked on the timeline.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct Mark {
    /// Simulated time \[ns\].
    pub t_ns: u64,
    /// What.
    pub kind: MarkKind,
    /// The event marked (its kind and fields, said by the page as its log says it).
    pub event: EventView,
}

impl Mark {
    fn of(e: &SystemEvent) -> Option<Self> {
        let mark = match &e.kind {
            EventKind::GlobalPlan { .. } | EventKind::LocalPlanSent { .. } => MarkKind::Plan,
            EventKind::PlanningFailed { .. } => MarkKind::Failure,
            EventKind::Bump { .. } => MarkKind::Bump,
            EventKind::FaultInjected { .. } | EventKind::ComponentError { .. } => MarkKind::Fault,
            EventKind::Arrived { .. } => MarkKind::Arrival,
            _ => return None,
        };
        Some(Self {
            t_ns: e.time_ns,
            kind: mark,
            event: EventView::of(e),
        })
    }
}

/// Everything of a session that changes as it runs, as one value: what a session holds,
/// what a history starts from and what a checkpoint keeps.
#[derive(Debug)]
pub(in crate::system) struct State {
    pub system: System,
    /// The scenario's timed events.
    pub timeline: Timeline,
    /// Cells edited since the load → their last value.
    pub edits: BTreeMap<(i64, i64), i16>,
    /// The exercise's watch as it was then (a seek back must not keep later verdicts).
    pub exercise: Option<ExerciseWatch>,
}

/// The telemetry samples a checkpoint keeps: the plots' longest window at the default 50 Hz
/// (the trace hash goes on over every sample; older samples are not kept after a seek).
pub const CHECKPOINT_SAMPLES: usize = 3_000;

impl State {
    /// A copy sharing nothing (its telemetry cut to [`CHECKPOINT_SAMPLES`]), unless a sample
    /// injected into a port is still waiting.
    fn try_clone(&self) -> Option<Self> {
        let mut system = self.system.try_clone()?;
        system.trim_telemetry(CHECKPOINT_SAMPLES);
        Some(Self {
            system,
            timeline: self.timeline.clone(),
            edits: self.edits.clone(),
            exercise: self.exercise.clone(),
        })
    }
}

#[derive(Debug)]
struct Checkpoint {
    time_ns: u64,
    /// The first input not applied yet.
    next: usize,
    state: State,
}

/// The timeline's read-out for the page.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct TimelineView {
    /// Where the history starts (the set-up built) \[ns\].
    pub start_ns: u64,
    /// The session's time \[ns\].
    pub now_ns: u64,
    /// The furthest time known: simulated so far, or a loaded replay's end \[ns\].
    pub end_ns: u64,
    /// Requests recorded (applied and still to replay).
    pub inputs: usize,
    /// Requests still to replay.
    pub pending: usize,
    /// Checkpoints kept.
    pub checkpoints: usize,
    /// Their spacing \[ns\].
    pub checkpoint_ns: u64,
    /// Marks up to the furthest time simulated.
    pub marks: Vec<Mark>,
}

/// A session's record of its run (module documentation).
#[derive(Debug)]
pub(in crate::system) struct History {
    setup: Setup,
    inputs: Vec<TimedInput>,
    next: usize,
    checkpoints: Vec<Checkpoint>,
    /// The most checkpoints kept for this map.
    max_checkpoints: usize,
    interval_ns: u64,
    marks: Vec<Mark>,
    /// Every event before this time is marked, none after.
    horizon_ns: u64,
    /// Events of the record read for marks.
    mark_cursor: u64,
    /// A loaded replay's end.
    end_ns: u64,
}

impl History {
    /// A history starting at `state` (a set-up just built), with `inputs` to replay up to
    /// `end_ns`.
    pub fn new(setup: Setup, state: &State, inputs: Vec<TimedInput>, end_ns: u64) -> Self {
        let system = &state.system;
        let now = system.time_ns();
        let mut h = Self {
            setup,
            inputs,
            next: 0,
            checkpoints: Vec::new(),
            max_checkpoints: system.map().map_or(MAX_CHECKPOINTS, |m| {
                (CHECKPOINT_CELLS / (m.width() * m.height()).max(1)).clamp(4, MAX_CHECKPOINTS)
            }),
            interval_ns: CHECKPOINT_NS,
            marks: Vec::new(),
            horizon_ns: now,
            mark_cursor: system.record().event_count(),
            end_ns,
        };
        h.checkpoint(state);
        h
    }

    /// The set-up the run started from.
    pub fn setup(&self) -> &Setup {
        &self.setup
    }

    /// A request carried out at `t_ns` by a person: what was recorded after it is dropped.
    pub fn record(&mut self, t_ns: u64, input: Input) {
        self.inputs.truncate(self.next);
        self.inputs.push(TimedInput { t_ns, input });
        self.next = self.inputs.len();
        self.checkpoints.retain(|c| c.time_ns < t_ns);
        self.marks.retain(|m| m.t_ns < t_ns);
        self.horizon_ns = self.horizon_ns.min(t_ns);
        self.end_ns = self.end_ns.min(t_ns);
    }

    /// Whether recorded requests are still to be replayed (after a seek back, or in a
    /// loaded replay).
    pub fn requests_ahead(&self) -> bool {
        self.next < self.inputs.len()
    }

    /// The next recorded request due at `now_ns`, taken.
    pub fn take_due(&mut self, now_ns: u64) -> Option<Input> {
        let timed = self.inputs.get(self.next)?;
        if timed.t_ns > now_ns {
            return None;
        }
        self.next += 1;
        Some(timed.input.clone())
    }

    /// The next time the run must stop at after `now_ns`: a recorded request, a checkpoint
    /// due.
    pub fn next_stop(&self, now_ns: u64) -> u64 {
        let input = self.inputs.get(self.next).map(|t| t.t_ns);
        let last = self.checkpoints.last().map_or(0, |c| c.time_ns);
        let checkpoint = last.saturating_add(self.interval_ns).max(now_ns + 1);
        input.map_or(checkpoint, |i| i.min(checkpoint))
    }

    /// Whether a checkpoint is due at `now_ns`.
    pub fn wants_checkpoint(&self, now_ns: u64) -> bool {
        self.checkpoints
            .last()
            .is_none_or(|c| now_ns >= c.time_ns.saturating_add(self.interval_ns))
    }

    /// Keeps a checkpoint of the session's state if it can be copied now; returns whether
    /// it could.
    pub fn checkpoint(&mut self, state: &State) -> bool {
        let Some(copy) = state.try_clone() else {
            return false;
        };
        self.checkpoints.push(Checkpoint {
            time_ns: state.system.time_ns(),
            next: self.next,
            state: copy,
        });
        if self.checkpoints.len() > self.max_checkpoints {
            let mut i = 0;
            self.checkpoints.retain(|_| {
                i += 1;
                i % 2 == 1
            });
            self.interval_ns = self.interval_ns.saturating_mul(2);
        }
        true
    }

    /// Marks the events of `record` between the horizon and `now_ns`.
    pub fn collect_marks(&mut self, record: &Record, now_ns: u64) {
        for e in record.events_since(self.mark_cursor) {
            if e.time_ns >= now_ns {
                break;
            }
            self.mark_cursor += 1;
            if e.time_ns >= self.horizon_ns
                && let Some(mark) = Mark::of(e)
            {
                self.marks.push(mark);
            }
        }
        // Events dropped from a full log are counted as read.
        let kept = record.events().len() as u64;
        self.mark_cursor = self
            .mark_cursor
            .max(record.event_count().saturating_sub(kept));
        self.horizon_ns = self.horizon_ns.max(now_ns);
        self.end_ns = self.end_ns.max(now_ns);
    }

    /// The state of the last checkpoint at or before `t_ns` (the first one if `t_ns` is
    /// before it), copied, with the time it was taken; the history continues from there.
    pub fn restore(&mut self, t_ns: u64) -> Option<State> {
        let i = self
            .checkpoints
            .iter()
            .rposition(|c| c.time_ns <= t_ns)
            .unwrap_or(0);
        let c = self.checkpoints.get(i)?;
        let state = c.state.try_clone()?;
        self.next = c.next;
        self.mark_cursor = state.system.record().event_count();
        Some(state)
    }

    /// The time of the last checkpoint at or before `t_ns`.
    pub fn checkpoint_before(&self, t_ns: u64) -> Option<u64> {
        self.checkpoints
            .iter()
            .rev()
            .map(|c| c.time_ns)
            .find(|&t| t <= t_ns)
    }

    /// The run up to `system`'s time as a replay (the requests recorded after it are left
    /// out), made on the scenario of content hash `scenario_hash` by this build.
    pub fn replay(&self, system: &System, scenario_hash: &str) -> Replay {
        let telemetry = system.record().telemetry();
        Replay {
            scenario_hash: scenario_hash.to_owned(),
            behaviour: crate::BEHAVIOUR_VERSION,
            package_version: Some(crate::VERSION.to_owned()),
            setup: self.setup.clone(),
            inputs: self.inputs[..self.next].to_vec(),
            end_ns: system.time_ns(),
            samples: telemetry.total(),
            trace_hash: telemetry.trace_hash(),
        }
    }

    /// The timeline's read-out at `now_ns`.
    pub fn view(&self, now_ns: u64) -> TimelineView {
        TimelineView {
            start_ns: self.checkpoints.first().map_or(0, |c| c.time_ns),
            now_ns,
            end_ns: self.end_ns.max(now_ns),
            inputs: self.inputs.len(),
            pending: self.inputs.len() - self.next,
            checkpoints: self.checkpoints.len(),
            checkpoint_ns: self.interval_ns,
            marks: self.marks.clone(),
        }
    }
}
