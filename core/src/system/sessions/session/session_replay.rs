//! The session's replays and its moves in time — seeking, restarting — (a child of
//! `session.rs`; see its module documentation and [`History`]).

use serde::Serialize;

use super::{Session, Source};
use crate::errors::SessionError;
use crate::system::runs::compare::{Comparison, compare};
use crate::system::sessions::history::{History, TimelineView};
use crate::system::sessions::replay::Replay;
use crate::system::vocabulary::kind::ComponentKind;
use crate::system::vocabulary::run_limit::beyond_replay_limit;

/// What loading a replay found: whether the run reproduced the recorded trace.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct ReplayCheck {
    /// The scenario.
    pub scenario: String,
    /// The recorded end \[ns\].
    pub end_ns: u64,
    /// Requests replayed.
    pub inputs: usize,
    /// The trace hash recorded in the file.
    pub expected_hash: String,
    /// The trace hash of the run replayed.
    pub hash: String,
    /// Telemetry samples recorded in the file.
    pub expected_samples: u64,
    /// Telemetry samples of the run replayed.
    pub samples: u64,
    /// Whether the two runs are the same (hash and samples).
    pub matches: bool,
}

fn bad(reason: &str) -> crate::Error {
    SessionError::BadReplay {
        reason: reason.to_owned(),
    }
    .into()
}

fn no_history() -> crate::Error {
    bad("a replay needs a scenario; this map was loaded from a file")
}

impl Session {
    /// The run so far as a replay: the set-up it started from and every request carried
    /// out up to now (not those recorded after now). An error when the map was loaded from
    /// a file.
    pub fn replay(&self) -> crate::Result<Replay> {
        let history = self.history.as_ref().ok_or_else(no_history)?;
        Ok(history.replay(
            &self.state.system,
            self.content_hash().ok_or_else(no_history)?,
        ))
    }

    /// The content hash of the scenario loaded ([`Scenario::content_hash`](crate::system::Scenario::content_hash)),
    /// what a replay records of it; `None` for a map loaded from a file.
    pub fn content_hash(&self) -> Option<&str> {
        match &self.source {
            Source::Scenario { content_hash, .. } => Some(content_hash),
            _ => None,
        }
    }

    /// [`Session::replay`] as the file's JSON text.
    pub fn replay_json(&self) -> crate::Result<String> {
        self.replay()?.to_json()
    }

    /// Loads `replay` on the scenario loaded (it must be the replay's scenario): the set-up
    /// is rebuilt and run to the recorded end with every request at its time (checkpoints
    /// and marks taken on the way); the session stands there, paused or not as it was.
    /// Returns whether the trace hash is the recorded one. On an error nothing changes; a
    /// replay of another scenario, of a scenario whose content has changed since, or of
    /// another behaviour version of the core is refused with that reason
    /// ([`Replay::check_valid_for`]).
    pub fn load_replay(&mut self, replay: &Replay) -> crate::Result<ReplayCheck> {
        let (Some(scenario), Some(hash)) = (self.scenario(), self.content_hash()) else {
            return Err(no_history());
        };
        if scenario.name != replay.setup.scenario {
            return Err(bad(&format!(
                "it was made for scenario `{}`, but `{}` is loaded",
                crate::present::excerpt(&replay.setup.scenario),
                scenario.name
            )));
        }
        replay.check_valid_for(hash)?;
        let end = format!("end_ns {}", replay.end_ns);
        if let Some(reason) = beyond_replay_limit(&end, replay.end_ns) {
            return Err(bad(&reason));
        }
        self.restart_setup(&replay.setup).map_err(|e| match e {
            crate::Error::Session(SessionError::BadShareToken { reason }) => {
                SessionError::BadReplay { reason }.into()
            }
            e => e,
        })?;
        self.history = Some(History::new(
            replay.setup.clone(),
            &self.state,
            replay.inputs.clone(),
            replay.end_ns,
        ));
        self.run_to(replay.end_ns);
        self.look();
        let telemetry = self.state.system.record().telemetry();
        let hash = telemetry.trace_hash();
        let samples = telemetry.total();
        Ok(ReplayCheck {
            scenario: replay.setup.scenario.clone(),
            end_ns: replay.end_ns,
            inputs: replay.inputs.len(),
            matches: hash == replay.trace_hash && samples == replay.samples,
            expected_hash: replay.trace_hash.clone(),
            hash,
            expected_samples: replay.samples,
            samples,
        })
    }

    /// Moves to simulated time `t_ns` (rounded up to a whole base tick), back or forth:
    /// from the nearest checkpoint at or before it (or from now, if that is nearer), with
    /// the recorded requests replayed on the way. The event log starts again from the
    /// events kept then ([`Session::new_events`] hands them all out).
    pub fn seek(&mut self, t_ns: u64) -> crate::Result<()> {
        if let Some(reason) = beyond_replay_limit(&format!("seeking to {t_ns} ns"), t_ns) {
            return Err(bad(&reason));
        }
        let base = self
            .state
            .system
            .wiring()
            .execution_context()
            .base_period_ns();
        let target = t_ns.div_ceil(base).saturating_mul(base);
        let now = self.state.system.time_ns();
        let history = self.history.as_mut().ok_or_else(no_history)?;
        let nearer = history.checkpoint_before(target).is_some_and(|at| at > now);
        if target < now || nearer {
            let state = history
                .restore(target)
                .ok_or_else(|| bad("no checkpoint to go back to"))?;
            self.reset(state);
        }
        self.run_to(target);
        self.look();
        Ok(())
    }

    /// Starts the run again (the exercise panel's Restart): the set-up the run started from
    /// — the scenario as loaded, or the share link or replay it was opened with — with the
    /// parameters as they are now (every tunable parameter a person changed, however:
    /// typed, imported from a `.conf`), at time 0, with the clock running and the
    /// exercise's checklist afresh. The poses, map edits and other requests made during the
    /// run are not kept.
    ///
    /// A restart begins a new run: its history starts at the restarted set-up, so a replay
    /// made after it is that set-up and the requests made since, and replays to the same
    /// trace hash and verdict. [`SessionError::NothingToRestart`] when no scenario is loaded;
    /// on an error nothing changes.
    pub fn restart(&mut self) -> crate::Result<()> {
        let history = self
            .history
            .as_ref()
            .ok_or(SessionError::NothingToRestart)?;
        let mut setup = history.setup().clone();
        setup.params = self.setup()?.params;
        self.restart_setup(&setup)?;
        self.clock.paused = false;
        self.look();
        Ok(())
    }

    /// The timeline's read-out: where the history starts and ends, now, the marks.
    pub fn timeline_view(&self) -> crate::Result<TimelineView> {
        let history = self.history.as_ref().ok_or_else(no_history)?;
        Ok(history.view(self.state.system.time_ns()))
    }

    /// The scenario run from the activation to its outcome twice, side by side: with the
    /// current set-up ([`Session::setup`]: start, goal, map edits, changed parameters) as
    /// run A, and with `component`'s parameter `name` set to `text` (parsed by its
    /// declaration) as run B (the page's "compare with…"). The session does not change.
    pub fn compare_with(
        &self,
        component: ComponentKind,
        name: &str,
        text: &str,
    ) -> crate::Result<Comparison> {
        let Source::Scenario {
            scenario, files, ..
        } = &self.source
        else {
            return Err(bad(
                "a comparison needs a scenario; this map was loaded from a file",
            ));
        };
        let value = self.parse_param(component, name, text)?;
        let a = self.setup()?;
        let mut b = a.clone();
        b.params
            .entry(component.name().to_owned())
            .or_default()
            .insert(name.to_owned(), value);
        compare(scenario, files, &a, &b)
    }

    /// [`Session::compare_with`] the component named `component`.
    pub fn compare_named(
        &self,
        component: &str,
        name: &str,
        text: &str,
    ) -> crate::Result<Comparison> {
        self.compare_with(ComponentKind::from_name(component)?, name, text)
    }

    /// Reads a replay file's text and loads it ([`Session::load_replay`]).
    pub fn load_replay_text(&mut self, text: &str) -> crate::Result<ReplayCheck> {
        let replay = Replay::from_json(text)?;
        self.load_replay(&replay)
    }

    /// [`Session::seek`] to `t_s` seconds (a time before 0 or not finite is 0).
    pub fn seek_s(&mut self, t_s: f64) -> crate::Result<()> {
        let t = if t_s.is_finite() { t_s.max(0.0) } else { 0.0 };
        self.seek(libm::round(t * 1e9) as u64)
    }
}
