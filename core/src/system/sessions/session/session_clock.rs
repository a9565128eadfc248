//! The session's clock (a child of `session.rs`): wall time into whole base ticks, within the
//! caller's budget ([`Session::advance_while`]); the run to a time through the history
//! (requests replayed at their times, checkpoints, marks); the exercise's watch after time
//! ran; pause and speed.

use super::*;
use crate::system::sessions::views::ExerciseView;

impl Session {
    /// Advances simulated time by `elapsed_ms` of wall time × the speed, in whole base ticks
    /// (the remainder kept; nothing while paused; at most [`MAX_STEP_MS`] per call; negative
    /// or non-finite counts as 0). Returns the number of ticks run.
    pub fn advance(&mut self, elapsed_ms: f64) -> u64 {
        self.advance_while(elapsed_ms, || true)
    }

    /// [`advance`](Self::advance) within a budget: the time owed runs tick by tick while
    /// `more()` says so (asked before each tick: a caller whose budget is already spent —
    /// the page after a request that took the frame's time — runs none, and the time stays
    /// owed).
    /// What does not run stays owed for the next call, up to [`MAX_STEP_MS`] of wall time
    /// × the speed: a machine too slow for the speed runs slower instead of falling ever
    /// further behind. The ticks are the same ones, whichever calls run them, so the trace
    /// does not depend on how the time was cut (the page's frame budget).
    pub fn advance_while(&mut self, elapsed_ms: f64, mut more: impl FnMut() -> bool) -> u64 {
        if self.clock.paused {
            return 0;
        }
        let ms = if elapsed_ms.is_finite() {
            elapsed_ms.clamp(0.0, MAX_STEP_MS)
        } else {
            0.0
        };
        let owed_max = libm::round(MAX_STEP_MS * self.clock.speed * 1e6) as u64;
        let owed = self.clock.pending_ns + libm::round(ms * self.clock.speed * 1e6) as u64;
        self.clock.pending_ns = owed.min(owed_max);
        let base = self
            .state
            .system
            .wiring()
            .execution_context()
            .base_period_ns();
        let mut ran = 0;
        while self.clock.pending_ns >= base && more() {
            // One tick (more if a replayed request plans past it), through the history.
            let before = self.state.system.time_ns();
            self.run_to(before.saturating_add(base));
            let done = self.state.system.time_ns().saturating_sub(before).max(base);
            self.clock.pending_ns = self.clock.pending_ns.saturating_sub(done);
            ran += done / base;
        }
        self.look();
        ran
    }

    /// Simulated time owed to the clock and not yet run \[s\] (what a frame budget left for
    /// later; below one base tick when the machine keeps up).
    pub fn behind_s(&self) -> f64 {
        self.clock.pending_ns as f64 * 1e-9
    }

    /// Runs `ticks` base ticks now, paused or not (single step). More ticks than a run goes
    /// (24 h of simulated time) are refused ([`SystemError::RunTooLong`](crate::errors::SystemError::RunTooLong)),
    /// and nothing runs.
    pub fn step_ticks(&mut self, ticks: u64) -> crate::Result<()> {
        let base = self
            .state
            .system
            .wiring()
            .execution_context()
            .base_period_ns();
        let asked = ticks.saturating_mul(base);
        crate::system::vocabulary::run_limit::check_run_length("step_ticks", asked as f64 * 1e-9)?;
        let target = self.state.system.time_ns().saturating_add(asked);
        self.run_to(target);
        self.look();
        Ok(())
    }

    /// Runs to simulated time `target_ns` (a whole number of base ticks; later if a request
    /// replayed on the way plans past it): the scenario's timeline, the requests recorded
    /// for the times passed, checkpoints and marks ([`History`]).
    pub(super) fn run_to(&mut self, target_ns: u64) {
        let base = self
            .state
            .system
            .wiring()
            .execution_context()
            .base_period_ns();
        loop {
            // Each request due now, "now" read again after each: a request that plans runs
            // ticks, and the next one was recorded at the time that left.
            while let Some(input) = {
                let now = self.state.system.time_ns();
                self.history.as_mut().and_then(|h| h.take_due(now))
            } {
                if self.carry_out(&input, false).is_err() {
                    // Refused, nothing changed: refused again, and logged.
                    self.state.system.apply_logged(
                        &input,
                        crate::system::vocabulary::input::RequestSource::Replay,
                    );
                }
            }
            let now = self.state.system.time_ns();
            let mut stop = target_ns;
            if let Some(h) = &mut self.history {
                if h.wants_checkpoint(now) {
                    h.checkpoint(&self.state);
                }
                stop = stop.min(h.next_stop(now));
            }
            if now >= target_ns {
                break;
            }
            let ticks = stop.saturating_sub(now).div_ceil(base).max(1);
            self.state.timeline.run(&mut self.state.system, ticks);
            if let Some(h) = &mut self.history {
                h.collect_marks(self.state.system.record(), self.state.system.time_ns());
            }
        }
    }

    /// The exercise watch reads what happened (after time ran or a request was made).
    pub(super) fn look(&mut self) {
        let more_to_come = self.state.timeline.pending() > 0
            || self.history.as_ref().is_some_and(|h| h.requests_ahead());
        if let Some(w) = &mut self.state.exercise {
            w.observe(&self.state.system, more_to_come);
        }
    }

    /// The scenario's exercise as it stands, if it has one.
    pub fn exercise(&self) -> Option<ExerciseStatus> {
        self.state.exercise.as_ref().map(ExerciseWatch::status)
    }

    /// The scenario's exercise as the page shows it, with the clock's pause (what a frame
    /// reads, [`Session::frame`]).
    pub fn exercise_view(&self) -> Option<ExerciseView> {
        self.exercise().map(|status| ExerciseView {
            status,
            paused: self.paused(),
        })
    }

    /// Pauses or resumes the clock.
    pub fn set_paused(&mut self, paused: bool) {
        self.clock.paused = paused;
    }

    /// Whether the clock is paused.
    pub fn paused(&self) -> bool {
        self.clock.paused
    }

    /// Sets the speed (simulated seconds per wall second), [`MIN_SPEED`] to [`MAX_SPEED`].
    pub fn set_speed(&mut self, speed: f64) -> crate::Result<()> {
        if !(MIN_SPEED..=MAX_SPEED).contains(&speed) {
            return Err(SessionError::BadSpeed {
                speed,
                min: MIN_SPEED,
                max: MAX_SPEED,
            }
            .into());
        }
        self.clock.speed = speed;
        Ok(())
    }

    /// The speed.
    pub fn speed(&self) -> f64 {
        self.clock.speed
    }
}
