//! [`Replay`]: a run handed in as a file — its set-up ([`Setup`], what a share link carries)
//! and every request made since, each at the simulated time it was made ([`TimedInput`]).
//! The system is deterministic bit for bit, so this is the whole run: a session that loads it
//! ([`Session::load_replay`](crate::system::Session::load_replay)) reproduces the recorded trace hash,
//! natively and in the page.
//!
//! The file is versioned JSON (`*.rtnav.json`):
//!
//! ```json
//! { "format": "rtnav-replay", "version": 2,
//!   "scenario_hash": "5be1…", "behaviour": 1, "package_version": "0.2.0",
//!   "setup": { "v": 1, "scenario": "open_field", "start": null, "goal": null,
//!              "backward": false, "edits": [], "params": {} },
//!   "inputs": [ { "t_ns": 1200000000, "input": { "type": "activate_all" } },
//!               { "t_ns": 3000000000, "input": { "type": "set_param",
//!                 "component": "LocalPathPlanning", "name": "PostureConsiderationLevel",
//!                 "value": 85.0 } } ],
//!   "end_ns": 20000000000, "samples": 1001, "trace_hash": "9f2c…" }
//! ```
//!
//! **Numbers are exact.** JSON numbers are written shortest-round-trip and read back to the
//! same bits (`serde_json`'s `float_roundtrip`). JSON has no NaN or infinity, which an injected
//! port sample may carry: every non-finite number of an input is written as `0` and listed
//! in the entry's `"exact"` by its position among the input's numbers, as its IEEE 754 bits in
//! hexadecimal (`{"0": "0x7ff8000000000000"}`), so a replay reproduces even a NaN's payload.
//!
//! **Hand-ins stay valid** (spec §6, Decision 0.3). A replay carries the content hash of the
//! scenario it was made on ([`Scenario::content_hash`](crate::system::Scenario::content_hash): the
//! scenario and its map files) and the core's [`BEHAVIOUR_VERSION`]; loading it on a scenario
//! whose content has changed, or in a build of another behaviour version, is refused with
//! that reason ([`SessionError::ReplayScenarioChanged`], [`SessionError::ReplayBehaviourChanged`])
//! — never re-judged silently. A file of version 1 carried neither and is refused for its
//! version. It also names the package version of the build that wrote it ([`crate::VERSION`],
//! for people; files written before it was recorded have none and load as before).

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use crate::BEHAVIOUR_VERSION;
use crate::errors::SessionError;
use crate::present::excerpt;
use crate::system::runs::setup::{SETUP_VERSION, Setup};
use crate::system::vocabulary::input::Input;
use crate::system::vocabulary::json_text;
use crate::system::vocabulary::run_limit::beyond_replay_limit;

/// The `format` of a replay file.
pub const REPLAY_FORMAT: &str = "rtnav-replay";
/// The version this build writes and reads (2: the scenario's content hash and the
/// behaviour version recorded).
pub const REPLAY_VERSION: u32 = 2;
/// The largest replay file read \[bytes\] (a recorded hour of steady editing is far less).
pub const MAX_REPLAY_BYTES: usize = 32 << 20;
/// One request and the simulated time it was made at.
#[derive(Debug, Clone, PartialEq)]
pub struct TimedInput {
    /// Simulated time \[ns\] (the session's clock when the request was carried out).
    pub t_ns: u64,
    /// The request.
    pub input: Input,
}

/// A recorded run (module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct Replay {
    /// The content hash of the scenario the run was made on
    /// ([`Scenario::content_hash`](crate::system::Scenario::content_hash), 64 hex digits).
    pub scenario_hash: String,
    /// The core's behaviour version that made the run ([`BEHAVIOUR_VERSION`]).
    pub behaviour: u32,
    /// The package version of the build that wrote the file ([`crate::VERSION`]); `None` in
    /// files written before it was recorded. Not checked on loading.
    pub package_version: Option<String>,
    /// The set-up the run started from.
    pub setup: Setup,
    /// Every request carried out, in the order made (times never decrease).
    pub inputs: Vec<TimedInput>,
    /// Simulated time at the end of the recording \[ns\].
    pub end_ns: u64,
    /// Telemetry samples taken by then.
    pub samples: u64,
    /// The trace hash at `end_ns` (SHA-256 over every telemetry sample, hex).
    pub trace_hash: String,
}

/// One entry of the file: the input with its non-finite numbers zeroed, and those numbers.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct Entry {
    t_ns: u64,
    input: Input,
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    exact: BTreeMap<usize, String>,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    format: String,
    version: u32,
    scenario_hash: String,
    behaviour: u32,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    package_version: Option<String>,
    setup: Setup,
    inputs: Vec<Entry>,
    end_ns: u64,
    samples: u64,
    trace_hash: String,
}

/// Only the head, read first: a file of another version is refused for its version, not
/// for the fields it has.
#[derive(Deserialize)]
struct Head {
    format: Option<serde_json::Value>,
    version: Option<serde_json::Value>,
}

fn bad(reason: impl Into<String>) -> crate::Error {
    SessionError::BadReplay {
        reason: reason.into(),
    }
    .into()
}

/// Every number of `input`, in a fixed order (the positions of [`Entry::exact`]).
fn numbers_mut(input: &mut Input) -> Vec<&mut f64> {
    match input {
        Input::SetPosition { start, goal, .. } => vec![
            &mut start.x,
            &mut start.y,
            &mut start.theta,
            &mut goal.x,
            &mut goal.y,
            &mut goal.theta,
        ],
        Input::SetGoal { goal, .. } => vec![&mut goal.x, &mut goal.y, &mut goal.theta],
        Input::InjectInput { data, .. } => data.iter_mut().collect(),
        Input::SetParam { value, .. } => vec![value],
        Input::SetPdGain { p_l, p_r, d_l, d_r } => vec![p_l, p_r, d_l, d_r],
        Input::SetRate { hz, .. } => vec![hz],
        Input::MapUpdate { .. }
        | Input::Clear
        | Input::SafeMode
        | Input::Activate { .. }
        | Input::Deactivate { .. }
        | Input::Reset { .. }
        | Input::ActivateAll
        | Input::DeactivateAll
        | Input::ResetAll
        | Input::InjectFault { .. }
        | Input::LoadConf { .. }
        | Input::CutConnection { .. }
        | Input::RestoreConnection { .. }
        | Input::LoadScript { .. }
        | Input::UseBuiltIn { .. } => Vec::new(),
    }
}

impl Entry {
    fn of(timed: &TimedInput) -> Self {
        let mut input = timed.input.clone();
        let mut exact = BTreeMap::new();
        for (i, v) in numbers_mut(&mut input).into_iter().enumerate() {
            if !v.is_finite() {
                exact.insert(i, format!("{:#018x}", v.to_bits()));
                *v = 0.0;
            }
        }
        Self {
            t_ns: timed.t_ns,
            input,
            exact,
        }
    }

    fn into_timed(self, index: usize) -> crate::Result<TimedInput> {
        let Self {
            t_ns,
            mut input,
            exact,
        } = self;
        let mut numbers = numbers_mut(&mut input);
        let count = numbers.len();
        for (position, text) in exact {
            let at = |why: &str| bad(format!("input {index}: exact number {position}: {why}"));
            let slot = numbers
                .get_mut(position)
                .ok_or_else(|| at(&format!("the input has {count} numbers")))?;
            let bits = text
                .strip_prefix("0x")
                .and_then(|h| u64::from_str_radix(h, 16).ok())
                .ok_or_else(|| at(&format!("`{}` is not 0x and 16 hex digits", excerpt(&text))))?;
            let value = f64::from_bits(bits);
            if value.is_finite() {
                return Err(at(&format!(
                    "`{text}` is finite ({value}); only NaN and infinities are listed"
                )));
            }
            **slot = value;
        }
        Ok(TimedInput { t_ns, input })
    }
}

impl Replay {
    /// The file's JSON text (compact: a recording of minutes is a few KiB).
    pub fn to_json(&self) -> crate::Result<String> {
        let file = File {
            format: REPLAY_FORMAT.to_owned(),
            version: REPLAY_VERSION,
            scenario_hash: self.scenario_hash.clone(),
            behaviour: self.behaviour,
            package_version: self.package_version.clone(),
            setup: self.setup.clone(),
            inputs: self.inputs.iter().map(Entry::of).collect(),
            end_ns: self.end_ns,
            samples: self.samples,
            trace_hash: self.trace_hash.clone(),
        };
        serde_json::to_string(&file).map_err(|e| bad(e.to_string()))
    }

    /// Reads a replay file. Refused, with the reason: a file that is not JSON or not a
    /// replay, another version, a malformed field, times that go back or past the end, a
    /// set-up of another version, a pose that is not finite, a trace hash that is not 64
    /// hex digits.
    pub fn from_json(text: &str) -> crate::Result<Self> {
        if text.len() > MAX_REPLAY_BYTES {
            return Err(bad(format!(
                "{} bytes, more than the {MAX_REPLAY_BYTES} read",
                text.len()
            )));
        }
        let head: Head =
            json_text::parse(text).map_err(|e| bad(format!("not a JSON object: {e}")))?;
        match head.format {
            Some(serde_json::Value::String(f)) if f == REPLAY_FORMAT => {}
            other => {
                return Err(bad(format!(
                    "not an rtnav replay (`format` is {}, expected \"{REPLAY_FORMAT}\")",
                    other.map_or("missing".to_owned(), |v| excerpt(&v.to_string()))
                )));
            }
        }
        match head.version {
            Some(serde_json::Value::Number(n)) if n.as_u64() == Some(u64::from(REPLAY_VERSION)) => {
            }
            other => {
                return Err(SessionError::ReplayVersion {
                    found: other.map_or("missing".to_owned(), |v| excerpt(&v.to_string())),
                    reads: REPLAY_VERSION,
                }
                .into());
            }
        }
        let file: File = json_text::parse(text).map_err(|e| bad(format!("malformed: {e}")))?;
        if file.setup.v != SETUP_VERSION {
            return Err(bad(format!(
                "set-up version {} (this build reads version {SETUP_VERSION})",
                file.setup.v
            )));
        }
        let poses = file.setup.start.iter().chain(file.setup.goal.iter());
        if poses.flatten().any(|v| !v.is_finite()) {
            return Err(bad("a pose of the set-up is not finite"));
        }
        for (what, hash) in [
            ("trace hash", &file.trace_hash),
            ("scenario hash", &file.scenario_hash),
        ] {
            if hash.len() != 64 || !hash.bytes().all(|b| b.is_ascii_hexdigit()) {
                return Err(bad(format!(
                    "{what} `{}` is not 64 hex digits",
                    excerpt(hash)
                )));
            }
        }
        if let Some(reason) = beyond_replay_limit(&format!("end_ns {}", file.end_ns), file.end_ns) {
            return Err(bad(reason));
        }
        let mut inputs = Vec::with_capacity(file.inputs.len());
        let mut last = 0;
        for (i, entry) in file.inputs.into_iter().enumerate() {
            if entry.t_ns < last {
                return Err(bad(format!(
                    "input {i} at {} ns comes after one at {last} ns",
                    entry.t_ns
                )));
            }
            if entry.t_ns > file.end_ns {
                return Err(bad(format!(
                    "input {i} at {} ns is after the end ({} ns)",
                    entry.t_ns, file.end_ns
                )));
            }
            last = entry.t_ns;
            inputs.push(entry.into_timed(i)?);
        }
        Ok(Self {
            scenario_hash: file.scenario_hash,
            behaviour: file.behaviour,
            package_version: file.package_version,
            setup: file.setup,
            inputs,
            end_ns: file.end_ns,
            samples: file.samples,
            trace_hash: file.trace_hash,
        })
    }

    /// The scenario a replay file was made on (the page loads it first), the file checked.
    pub fn scenario_of(text: &str) -> crate::Result<String> {
        Ok(Self::from_json(text)?.setup.scenario)
    }

    /// Whether this replay can be replayed on a scenario of content hash `scenario_hash` by
    /// this build: refused if it was recorded by another behaviour version, or on a scenario
    /// whose content has changed since, with the reason (spec §6, Decision 0.3).
    pub fn check_valid_for(&self, scenario_hash: &str) -> crate::Result<()> {
        if self.behaviour != BEHAVIOUR_VERSION {
            return Err(SessionError::ReplayBehaviourChanged {
                recorded: self.behaviour,
                this_build: BEHAVIOUR_VERSION,
            }
            .into());
        }
        if self.scenario_hash != scenario_hash {
            return Err(SessionError::ReplayScenarioChanged {
                scenario: excerpt(&self.setup.scenario),
                recorded: self.scenario_hash.clone(),
                found: scenario_hash.to_owned(),
            }
            .into());
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::interfaces::{Direction, Pose};
    use crate::system::vocabulary::kind::ComponentKind;
    use crate::system::vocabulary::run_limit::MAX_REPLAY_NS;

    fn sample() -> Replay {
        let setup = Setup {
            v: SETUP_VERSION,
            scenario: "open_field".to_owned(),
            start: None,
            goal: Some([1.0, 2.0, 0.5]),
            backward: false,
            edits: vec![(1, 2, 1)],
            params: BTreeMap::new(),
            scripts: BTreeMap::new(),
        };
        let inputs = vec![
            TimedInput {
                t_ns: 5,
                input: Input::InjectInput {
                    component: ComponentKind::MotorControl,
                    port: "TargetVelocity".to_owned(),
                    data: vec![
                        f64::NAN,
                        f64::from_bits(0x7ff0_0000_0000_0001),
                        f64::INFINITY,
                        -0.0,
                        0.1 + 0.2,
                        f64::MIN_POSITIVE / 3.0,
                    ],
                },
            },
            TimedInput {
                t_ns: 7,
                input: Input::SetGoal {
                    goal: Pose::new(core::f64::consts::PI, 1e-300, -f64::INFINITY),
                    direction: Direction::Backward,
                },
            },
        ];
        Replay {
            scenario_hash: "a".repeat(64),
            behaviour: BEHAVIOUR_VERSION,
            package_version: Some(crate::VERSION.to_owned()),
            setup,
            inputs,
            end_ns: 9,
            samples: 0,
            trace_hash: "0".repeat(64),
        }
    }

    fn bits(r: &mut Replay) -> Vec<u64> {
        r.inputs
            .iter_mut()
            .flat_map(|t| {
                numbers_mut(&mut t.input)
                    .into_iter()
                    .map(|v| v.to_bits())
                    .collect::<Vec<_>>()
            })
            .collect()
    }

    #[test]
    fn every_number_comes_back_bit_for_bit() {
        let mut r = sample();
        let text = r.to_json().unwrap();
        let mut back = Replay::from_json(&text).unwrap();
        assert_eq!(bits(&mut r), bits(&mut back));
        let bom = Replay::from_json(&format!("\u{feff}{text}")).unwrap();
        assert_eq!(bom.to_json().unwrap(), text);
        assert_eq!(back.to_json().unwrap(), text);
    }

    #[test]
    fn the_package_version_is_written_and_a_file_without_it_loads() {
        let r = sample();
        let text = r.to_json().unwrap();
        let field = format!(",\"package_version\":\"{}\"", crate::VERSION);
        assert!(text.contains(&field), "{text}");
        let older_text = text.replace(&field, "");
        let older = Replay::from_json(&older_text).unwrap();
        assert_eq!(older.package_version, None);
        // Everything else as written (the text, since NaN is not equal to itself).
        assert_eq!(older.to_json().unwrap(), older_text);
    }

    #[test]
    fn other_versions_and_malformed_files_are_refused_with_a_reason() {
        let text = sample().to_json().unwrap();
        let refuse = |t: &str| Replay::from_json(t).unwrap_err().to_string();
        let e = refuse(&text.replace("\"version\":2", "\"version\":1"));
        assert!(
            e.contains("version 1") && e.contains("reads version 2"),
            "{e}"
        );
        let e = refuse(&text.replace(&"a".repeat(64), "abc"));
        assert!(
            e.contains("scenario hash `abc` is not 64 hex digits"),
            "{e}"
        );
        let e = refuse(&text.replace("rtnav-replay", "something"));
        assert!(e.contains("not an rtnav replay"), "{e}");
        assert!(refuse("[1, 2").contains("not a JSON object"));
        let e = refuse(&text.replace("\"t_ns\":7", "\"t_ns\":3"));
        assert!(e.contains("comes after"), "{e}");
        let e = refuse(&text.replace("\"end_ns\":9", "\"end_ns\":6"));
        assert!(e.contains("after the end"), "{e}");
        let e = refuse(&text.replace("\"t_ns\":7", "\"t_ns\":\"7\""));
        assert!(e.contains("malformed"), "{e}");
        let e = refuse(&text.replace("0x7ff8000000000000", "0x3ff0000000000000"));
        assert!(e.contains("is finite"), "{e}");
        let e = refuse(&text.replace("\"t_ns\":7", "\"t_ns\":7e999"));
        assert!(e.contains("(a JSON number must fit a 64-bit float"), "{e}");
    }

    #[test]
    fn a_replay_of_another_behaviour_or_a_changed_scenario_is_refused_with_which() {
        let mut r = sample();
        let same = "a".repeat(64);
        assert!(r.check_valid_for(&same).is_ok());
        let e = r.check_valid_for(&"b".repeat(64)).unwrap_err();
        assert!(
            matches!(&e, crate::Error::Session(SessionError::ReplayScenarioChanged { scenario, recorded, found })
                if scenario == "open_field" && *recorded == same && *found == "b".repeat(64)),
            "{e:?}"
        );
        assert!(
            e.to_string().contains("scenario `open_field` has changed"),
            "{e}"
        );
        r.behaviour = BEHAVIOUR_VERSION + 1;
        let e = r.check_valid_for(&same).unwrap_err();
        assert_eq!(
            e.to_string(),
            format!(
                "replay: recorded by behaviour version {} of the core; this build is behaviour \
                 version {BEHAVIOUR_VERSION}, whose runs differ",
                BEHAVIOUR_VERSION + 1
            )
        );
    }

    #[test]
    fn an_end_past_a_day_is_refused() {
        let text = sample().to_json().unwrap();
        let e = Replay::from_json(&text.replace("\"end_ns\":9", "\"end_ns\":1000000000000000000"))
            .unwrap_err()
            .to_string();
        assert_eq!(
            e,
            "replay: end_ns 1000000000000000000 is later than 86400000000000 ns (24 h of \
             simulated time), the longest a run or a replay goes"
        );
        let day = format!("\"end_ns\":{MAX_REPLAY_NS}");
        assert!(Replay::from_json(&text.replace("\"end_ns\":9", &day)).is_ok());
    }
}
