//! [`Timeline`]: a scenario's timed events, the one interpreter of them for the headless
//! runner, the page and the tests.
//!
//! **Decision**: a scenario's event times count from the moment the robot starts driving (the
//! first tick at which the physics is Active), not from when the scenario was loaded — so the
//! obstacle of `appearing_obstacle` appears while the robot drives, however long a teacher
//! waited before pressing **Activate**. A headless run activates the robot right after the
//! set-up, so there the two coincide. Each event becomes an [`Input`]
//! ([`ScenarioEvent::to_input`]) applied before the tick at its time; a refused one is logged
//! ([`System::apply_logged`]) and the run goes on.

use super::scenario::ScenarioEvent;
use crate::system::simulation::robot::System;
use crate::system::vocabulary::input::{Input, RequestSource};

/// Seconds → nanoseconds as scenario times are rounded.
pub(in crate::system) fn secs_to_ns(s: f64) -> u64 {
    libm::round(s * 1e9) as u64
}

/// A scenario's timed events and how far they have been applied.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Timeline {
    /// Offsets from the start of the drive \[ns\], in time order (stable for equal times).
    events: Vec<(u64, ScenarioEvent)>,
    /// The next event to apply.
    next: usize,
    /// When the drive started \[ns\]; `None` until it does.
    origin: Option<u64>,
}

impl Timeline {
    /// The timeline of `events` (a scenario's), none applied yet.
    pub fn new(events: &[ScenarioEvent]) -> Self {
        let mut events: Vec<(u64, ScenarioEvent)> = events
            .iter()
            .map(|e| (secs_to_ns(e.at()), e.clone()))
            .collect();
        events.sort_by_key(|(at, _)| *at);
        Self {
            events,
            next: 0,
            origin: None,
        }
    }

    /// Events not yet applied.
    pub fn pending(&self) -> usize {
        self.events.len() - self.next
    }

    /// When the drive started \[ns\], once it has.
    pub fn origin_ns(&self) -> Option<u64> {
        self.origin
    }

    /// Notes the start of the drive, then applies every event whose time has come.
    pub fn apply_due(&mut self, system: &mut System) {
        if self.origin.is_none() && system.is_driving() {
            self.origin = Some(system.time_ns());
        }
        let Some(origin) = self.origin else {
            return;
        };
        while let Some((at, event)) = self.events.get(self.next) {
            if origin.saturating_add(*at) > system.time_ns() {
                break;
            }
            let input: Input = event.to_input(system.map());
            self.next += 1;
            system.apply_logged(&input, RequestSource::Timeline);
        }
    }

    /// Base ticks until the next event is due (0: due now); `None` when none is pending or
    /// the drive has not started.
    fn ticks_to_next(&self, system: &System) -> Option<u64> {
        let origin = self.origin?;
        let (at, _) = self.events.get(self.next)?;
        let base = system.wiring().execution_context().base_period_ns();
        let due = origin.saturating_add(*at);
        Some(due.saturating_sub(system.time_ns()).div_ceil(base))
    }

    /// Runs `ticks` base ticks of `system`, applying each event before the tick at its time.
    pub fn run(&mut self, system: &mut System, mut ticks: u64) {
        while ticks > 0 {
            self.apply_due(system);
            // Step to the next event, or to the drive's start (checked every tick).
            let chunk = if self.origin.is_none() && self.pending() > 0 {
                1
            } else {
                self.ticks_to_next(system).unwrap_or(ticks).clamp(1, ticks)
            };
            system.step(chunk);
            ticks -= chunk;
        }
        self.apply_due(system);
    }
}
