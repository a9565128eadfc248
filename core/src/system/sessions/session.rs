//! [`Session`]: the system as a person drives it from InventGUI (spec §5) — the browser page
//! and anything else interactive. It is the user interface's one boundary: the wasm layer is
//! a thin binding over it.
//!
//! What a session adds to the [`System`] (which knows nothing of it):
//! - **The set-up** ([`Setup`]): a scenario is built by the one set-up builder
//!   ([`setup::build`]) with the whole potential field drawn; the map cells edited since the
//!   load and every parameter that differs from the scenario's are recorded, which is what a
//!   share link carries ([`Session::share_token`]). Replaying a set-up is one function,
//!   [`Session::restart_setup`], so a link opened in a fresh page and the page that made it
//!   show the identical first frame.
//! - **The timeline** of the scenario's timed events ([`Timeline`]: they count from the start
//!   of the drive).
//! - **The clock**: wall time × speed (0.25× to 16×) becomes whole base ticks, the remainder
//!   kept; pause; single ticks.
//! - **Planning at once while the robot stands**: after a request that changes what the
//!   planners plan (start and goal, a map edit, a parameter), the session runs the system until
//!   the planners have settled, so the drawing follows even while paused.
//! - **Read-outs for people**: new events since the last look, the parameter panel's view,
//!   the plot window, the status.
//! - **Its history** ([`History`], `session_replay.rs`): the set-up and every request
//!   carried out with its time — a [`Replay`] to download or to load — checkpoints to seek
//!   back and forth in time, and the timeline's marks. Recorded requests after the time
//!   reached are replayed as time advances; a request made there drops them.
//! - **The restart** ([`Session::restart`]): the run started again from its set-up, with the
//!   parameters as they are now — a new history.

use std::collections::BTreeMap;

use base64::Engine as _;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use serde::Serialize;

use super::history::{History, State};
use crate::errors::SessionError;
use crate::interfaces::Direction;
use crate::map::{GridMap, MapUpdate};
use crate::rtc::LifecycleState;
use crate::system::runs::exercise::{ExerciseStatus, parameter_values};
use crate::system::runs::exercise_watch::ExerciseWatch;
use crate::system::runs::scenario::{FileResolver, MapSource, MemoryResolver, Scenario};
use crate::system::runs::setup::{
    self, BuildOptions, PLAN_SECONDS, SETUP_VERSION, ScriptText, Setup,
};
use crate::system::runs::timeline::Timeline;
use crate::system::simulation::conf_bundle::unknown_parameter;
use crate::system::simulation::parameter_warning::ParameterWarning;
use crate::system::simulation::robot::System;
use crate::system::simulation::status::Status;
use crate::system::vocabulary::events::SystemEvent;
use crate::system::vocabulary::input::Input;
use crate::system::vocabulary::json_text;
use crate::system::vocabulary::kind::ComponentKind;
use crate::system::vocabulary::rates::Rates;

mod session_clock;
mod session_replay;
mod session_view;
pub use session_replay::ReplayCheck;

/// The most wall time one [`Session::advance`] turns into simulated time \[ms\]: a tab that
/// was in the background resumes where it was instead of catching up in one frame.
pub const MAX_STEP_MS: f64 = 100.0;
/// The slowest speed offered.
pub const MIN_SPEED: f64 = 0.25;
/// The fastest speed offered.
pub const MAX_SPEED: f64 = 16.0;
/// The longest plot window \[s\].
pub const MAX_PLOT_SECONDS: f64 = 60.0;

/// The components whose parameters a session shows and a set-up records, in the order the
/// page lists them. GlobalPathPlanning's one parameter, `dmin`, is LocalPathPlanning's
/// (spec §3 Decision 0.2), so it is shown and recorded once, there.
pub const TUNABLE: [ComponentKind; 4] = [
    ComponentKind::LocalPathPlanning,
    ComponentKind::MotorControl,
    ComponentKind::DriveControl,
    ComponentKind::PhysicsSim,
];

/// The drawing options of every set-up a session builds.
const DRAWN: BuildOptions = BuildOptions { full_field: true };

/// Where the loaded map came from.
#[derive(Debug, Clone)]
enum Source {
    /// Nothing loaded yet.
    Empty,
    /// A scenario, with the files it names (kept to replay set-ups) and its content hash
    /// (what a replay records of it).
    Scenario {
        scenario: Box<Scenario>,
        files: MemoryResolver,
        content_hash: String,
    },
    /// A map file the user picked.
    MapFile,
}

/// The last seconds of telemetry as one array per series (what the plots draw).
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct PlotWindow {
    /// Simulated time \[s\].
    pub t: Vec<f64>,
    /// MotorControl's target wheel rate, left \[rad/s\].
    pub target_rate_l: Vec<f64>,
    /// MotorControl's target wheel rate, right \[rad/s\].
    pub target_rate_r: Vec<f64>,
    /// The physics' wheel rate, left \[rad/s\].
    pub rate_l: Vec<f64>,
    /// The physics' wheel rate, right \[rad/s\].
    pub rate_r: Vec<f64>,
    /// MotorControl's torque, left \[N·m\].
    pub torque_l: Vec<f64>,
    /// MotorControl's torque, right \[N·m\].
    pub torque_r: Vec<f64>,
    /// The torque the physics applied, left \[N·m\] (saturated at `MaxTorque`).
    pub applied_l: Vec<f64>,
    /// The torque the physics applied, right \[N·m\].
    pub applied_r: Vec<f64>,
    /// PhysicsSim's `MaxTorque` now \[N·m\]: the saturation limit.
    pub max_torque: f64,
    /// DriveControl's commanded speed \[m/s\].
    pub v_cmd: Vec<f64>,
    /// The robot's speed \[m/s\].
    pub v: Vec<f64>,
    /// DriveControl's commanded turn rate \[rad/s\].
    pub w_cmd: Vec<f64>,
    /// The robot's turn rate \[rad/s\].
    pub w: Vec<f64>,
    /// DriveControl's deviation from the path \[m\]; `None` while it has no path.
    pub deviation: Vec<Option<f64>>,
    /// LocalPathPlanning's `Deviatinglen` now \[m\].
    pub deviatinglen: f64,
    /// The times of global and local plans in the window \[s\].
    pub replans: Vec<f64>,
}

/// One component's parameters (the parameter panel's group).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct ComponentParameters {
    /// The component (`LocalPathPlanning`).
    pub component: &'static str,
    /// Its instance name (`LocalPathPlanning0`).
    pub instance_name: &'static str,
    /// Its execution period \[s\] (MotorControl's `Δt` in the note on its gains, spec §4).
    pub period_s: f64,
    /// Its parameters in declaration order.
    pub params: Vec<ParameterView>,
}

/// One parameter: its declaration (spec §1) and its values now.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct ParameterView {
    /// The seed's name.
    pub name: &'static str,
    /// `double` or `int`.
    #[serde(rename = "type")]
    pub kind: &'static str,
    /// Unit.
    pub unit: &'static str,
    /// Default.
    pub default: f64,
    /// Smallest allowed value; `None` for unbounded.
    pub min: Option<f64>,
    /// Largest allowed value; `None` for unbounded.
    pub max: Option<f64>,
    /// The range as text (`[0, 100]`).
    pub range: String,
    /// `always` or `on_activation`.
    pub reflection: String,
    /// What it means, in English.
    pub description: &'static str,
    /// The seed's own (Japanese) words for it, for the parameters of 000 and 002 §4.2.
    pub seed_text: Option<&'static str>,
    /// What the value in use does that a person should know (spec §4 note: gains that make
    /// the wheel loop unstable or limp; spec §3 Decision 0.2: a `dmin` that lets the body
    /// touch obstacles), as data; `None` when nothing.
    pub warning: Option<ParameterWarning>,
    /// The requested value.
    pub value: f64,
    /// The value the component uses.
    pub effective: f64,
    /// Whether the requested value waits for the next activation.
    pub pending: bool,
}

/// The page's clock settings and the time not yet a whole tick.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Clock {
    speed: f64,
    paused: bool,
    pending_ns: u64,
}

/// The system as a person drives it (see the module documentation).
#[derive(Debug)]
pub struct Session {
    /// The system, its timeline, the map edits and the exercise's watch: everything that
    /// changes as the session runs, put in place at once ([`Session::reset`]).
    state: State,
    clock: Clock,
    source: Source,
    /// The parameters as loaded (a set-up records the differences).
    baseline: Parameters,
    /// The map's file name (the scenario's map file, or the file picked).
    map_name: String,
    /// Events handed out so far ([`Session::new_events`]).
    events_seen: u64,
    /// The run's history (a scenario's; `None` for a map file).
    history: Option<History>,
}

/// Every [`TUNABLE`] parameter's requested value, by component and name.
type Parameters = BTreeMap<(ComponentKind, String), f64>;

fn parameters_of(system: &System) -> Parameters {
    let mut out = BTreeMap::new();
    for kind in TUNABLE {
        if let Ok(config) = system.wiring().config(kind) {
            for spec in config.specs() {
                if let Ok(v) = config.value(spec.name) {
                    out.insert((kind, spec.name.to_owned()), v);
                }
            }
        }
    }
    out
}

/// The watch of `scenario`'s exercise over `system`, its rules from `base`'s parameters
/// (the scenario as written).
fn watch(scenario: &Scenario, base: &System, system: &System) -> Option<ExerciseWatch> {
    let exercise = scenario.exercise.as_ref()?;
    Some(ExerciseWatch::new(
        exercise,
        scenario.time_limit,
        parameter_values(base),
        system,
    ))
}

/// The most a share token may inflate to \[bytes\] (16 MiB; a set-up is a few KiB).
pub const TOKEN_INFLATE_LIMIT: usize = 1 << 24;

fn bad_token(reason: impl Into<String>) -> crate::Error {
    SessionError::BadShareToken {
        reason: reason.into(),
    }
    .into()
}

impl Session {
    /// An empty system (no map).
    pub fn new() -> crate::Result<Self> {
        let mut system = System::new(Rates::default())?;
        system.set_full_field(DRAWN.full_field);
        Ok(Self {
            state: State {
                system,
                timeline: Timeline::default(),
                edits: BTreeMap::new(),
                exercise: None,
            },
            clock: Clock {
                speed: 1.0,
                paused: false,
                pending_ns: 0,
            },
            source: Source::Empty,
            baseline: BTreeMap::new(),
            map_name: String::new(),
            events_seen: 0,
            history: None,
        })
    }

    /// The system.
    pub fn system(&self) -> &System {
        &self.state.system
    }

    /// What the robot is doing, and why, as data (`Status`).
    pub fn status(&self) -> Status {
        self.state.system.status()
    }

    /// The map's file name: the scenario's map file, or the file the user picked.
    pub fn map_name(&self) -> &str {
        &self.map_name
    }

    /// The scenario loaded, if the map came from one.
    pub fn scenario(&self) -> Option<&Scenario> {
        match &self.source {
            Source::Scenario { scenario, .. } => Some(scenario),
            _ => None,
        }
    }

    /// The timeline of the scenario's timed events.
    pub fn timeline(&self) -> &Timeline {
        &self.state.timeline
    }

    // ------------------------------------------------------------------ loading

    /// Loads `scenario` (its files through `resolver`) as the set-up builder builds it. On an
    /// error the current session stays.
    pub fn load_scenario(
        &mut self,
        scenario: Scenario,
        resolver: &dyn FileResolver,
    ) -> crate::Result<()> {
        // The files the map needs are kept, to replay set-ups without the resolver.
        let mut files = MemoryResolver::new();
        for path in scenario.map_files(resolver)? {
            let bytes = resolver.read(&path)?.into_owned();
            files.insert(&path, bytes);
        }
        let system = setup::build(&scenario, &files, &Setup::of(&scenario), DRAWN)?;
        let content_hash = scenario.content_hash(&files)?;
        self.map_name = match &scenario.map {
            MapSource::Json { path } | MapSource::Movingai { path, .. } => path.clone(),
            MapSource::Ros { yaml, .. } => yaml.clone(),
        };
        let timeline = Timeline::new(&scenario.events);
        self.install(
            system,
            timeline,
            Source::Scenario {
                scenario: Box::new(scenario),
                files,
                content_hash,
            },
        );
        Ok(())
    }

    /// Loads a map the user picked into a fresh system with the planning components active
    /// and no start or goal; `name` is the file's name. On an error the current session
    /// stays.
    pub fn load_map(&mut self, name: &str, map: GridMap) -> crate::Result<()> {
        let mut system = System::new(Rates::default())?;
        system.set_full_field(DRAWN.full_field);
        system.load_map(map);
        for component in ComponentKind::PLANNING {
            system.apply(&Input::Activate { component })?;
        }
        self.map_name = name.to_owned();
        self.install(system, Timeline::default(), Source::MapFile);
        Ok(())
    }

    fn install(&mut self, system: System, timeline: Timeline, source: Source) {
        self.baseline = parameters_of(&system);
        let exercise = match &source {
            Source::Scenario { scenario, .. } => watch(scenario, &system, &system),
            _ => None,
        };
        self.source = source;
        self.reset(State {
            system,
            timeline,
            edits: BTreeMap::new(),
            exercise,
        });
        self.history = self
            .scenario()
            .map(Setup::of)
            .map(|setup| History::new(setup, &self.state, Vec::new(), 0));
    }

    /// Puts `state` in place of the session's (a load, a restart, a seek back): the clock
    /// owes no time and the event log is handed out again from the start. The one place the
    /// session's state is replaced.
    fn reset(&mut self, state: State) {
        self.state = state;
        self.clock.pending_ns = 0;
        self.events_seen = 0;
    }

    // ------------------------------------------------------------------ set-up and sharing

    /// The current set-up (see [`Setup`]). An error when the map did not come from a
    /// scenario (a link cannot carry a whole map file).
    pub fn setup(&self) -> crate::Result<Setup> {
        let name = match &self.source {
            Source::Scenario { scenario, .. } => scenario.name.clone(),
            _ => {
                return Err(bad_token(
                    "a share link needs a scenario; this map was loaded from a file",
                ));
            }
        };
        let mut params: BTreeMap<String, BTreeMap<String, f64>> = BTreeMap::new();
        for ((kind, pname), value) in parameters_of(&self.state.system) {
            let same = self
                .baseline
                .get(&(kind, pname.clone()))
                .is_some_and(|b| b.to_bits() == value.to_bits());
            if !same {
                params
                    .entry(kind.name().to_owned())
                    .or_default()
                    .insert(pname, value);
            }
        }
        let m = self.state.system.mission();
        Ok(Setup {
            v: SETUP_VERSION,
            scenario: name,
            start: m.start().map(|p| [p.x, p.y, p.theta]),
            goal: m.goal().map(|p| [p.x, p.y, p.theta]),
            backward: m.direction() == Direction::Backward,
            edits: self
                .state
                .edits
                .iter()
                .map(|(&(x, y), &v)| (x, y, v))
                .collect(),
            params,
            scripts: scripts_of(&self.state.system),
        })
    }

    /// The set-up as a URL-safe token (deflated JSON in base64url, no padding). While the
    /// robot stands, the session's own set-up is restarted from it first
    /// ([`Session::restart_setup`]), so this page shows what the link will open with.
    pub fn share_token(&mut self) -> crate::Result<String> {
        let setup = self.setup()?;
        let json = serde_json::to_vec(&setup).map_err(|e| bad_token(e.to_string()))?;
        let token = URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(&json, 9));
        if !self.state.system.is_driving() {
            self.restart_setup(&setup)?;
        }
        Ok(token)
    }

    /// Reads a token (version, JSON, numbers checked).
    pub fn decode_token(token: &str) -> crate::Result<Setup> {
        let bytes = URL_SAFE_NO_PAD
            .decode(token.trim())
            .map_err(|e| bad_token(format!("not base64url: {e}")))?;
        // The error names the inflate status only: its partial output (up to the limit)
        // would make a message of megabytes (a deflate bomb).
        let json = miniz_oxide::inflate::decompress_to_vec_with_limit(&bytes, TOKEN_INFLATE_LIMIT)
            .map_err(|e| {
                bad_token(match e.status {
                    miniz_oxide::inflate::TINFLStatus::HasMoreOutput => {
                        format!("it inflates to more than {TOKEN_INFLATE_LIMIT} bytes")
                    }
                    status => format!("not deflated data ({status:?})"),
                })
            })?;
        let json = core::str::from_utf8(&json)
            .map_err(|e| bad_token(format!("bad set-up: not UTF-8 text: {e}")))?;
        let setup: Setup =
            json_text::parse(json).map_err(|e| bad_token(format!("bad set-up: {e}")))?;
        if setup.v != SETUP_VERSION {
            return Err(bad_token(format!(
                "version {} (this page reads version {SETUP_VERSION})",
                setup.v
            )));
        }
        let poses = setup.start.iter().chain(setup.goal.iter());
        if poses.flatten().any(|v| !v.is_finite()) {
            return Err(bad_token("a pose is not finite"));
        }
        Ok(setup)
    }

    /// The scenario a token was made for (the page loads it first).
    pub fn share_scenario(token: &str) -> crate::Result<String> {
        Ok(Self::decode_token(token)?.scenario)
    }

    /// Replays a token's set-up on the scenario loaded (it must be the token's scenario).
    /// On an error nothing changes.
    pub fn apply_share(&mut self, token: &str) -> crate::Result<()> {
        let setup = Self::decode_token(token)?;
        self.restart_setup(&setup)
    }

    /// Rebuilds the scenario loaded with `setup` replayed ([`setup::build`]). On an error
    /// nothing changes.
    pub fn restart_setup(&mut self, setup: &Setup) -> crate::Result<()> {
        let Source::Scenario {
            scenario, files, ..
        } = &self.source
        else {
            return Err(bad_token("no scenario is loaded to replay the set-up on"));
        };
        if scenario.name != setup.scenario {
            return Err(bad_token(format!(
                "it was made for scenario `{}`, but `{}` is loaded",
                setup.scenario, scenario.name
            )));
        }
        let system = setup::build(scenario, files, &Setup::of(scenario), DRAWN)
            .and_then(|base| Ok((base, setup::build(scenario, files, setup, DRAWN)?)))?;
        let (base, system) = system;
        self.baseline = parameters_of(&base);
        let exercise = watch(scenario, &base, &system);
        let timeline = Timeline::new(&scenario.events);
        self.reset(State {
            system,
            timeline,
            edits: setup.edits.iter().map(|&(x, y, v)| ((x, y), v)).collect(),
            exercise,
        });
        self.history = Some(History::new(setup.clone(), &self.state, Vec::new(), 0));
        Ok(())
    }

    // ------------------------------------------------------------------ requests

    /// Carries out `input` ([`System::apply`]); map edits are recorded in the set-up. While
    /// the robot stands with the planners Active, a request that changes what they plan is
    /// planned at once (module documentation). Refused requests change nothing.
    ///
    /// A map edit is sent as what it amounts to ([`MapUpdate::net_changes`]): each cell once,
    /// only if its value changes; an edit that changes nothing sends nothing (no update, no
    /// log line, no plan).
    pub fn apply(&mut self, input: &Input) -> crate::Result<()> {
        self.carry_out(input, true)
    }

    /// [`Session::apply`]; a request carried out is recorded in the history if `record`
    /// (a person's), not when it is one replayed from it.
    fn carry_out(&mut self, input: &Input, record: bool) -> crate::Result<()> {
        if let (Input::MapUpdate { cells }, Some(map)) = (input, self.state.system.map()) {
            let net = MapUpdate::net_changes(cells, map);
            if net.is_empty() {
                return Ok(());
            }
            if net.len() != cells.len() {
                return self.carry_out(&Input::MapUpdate { cells: net }, record);
            }
        }
        let t_ns = self.state.system.time_ns();
        self.state.system.apply(input)?;
        if let (true, Some(h)) = (record, &mut self.history) {
            h.record(t_ns, input.clone());
        }
        let replans = match input {
            Input::MapUpdate { cells } => {
                for &(x, y, v) in cells {
                    self.state.edits.insert((x, y), v);
                }
                true
            }
            Input::SetPosition { .. } | Input::SetGoal { .. } | Input::LoadConf { .. } => true,
            Input::SetParam { component, .. } => ComponentKind::PLANNING.contains(component),
            _ => false,
        };
        let planners_active = ComponentKind::PLANNING
            .iter()
            .all(|&k| self.state.system.component_state(k) == LifecycleState::Active);
        if replans && planners_active && !self.state.system.is_driving() {
            self.state.system.run_until_planned(PLAN_SECONDS)?;
        }
        self.look();
        Ok(())
    }

    /// `text` as a value of `component`'s parameter `name`, parsed by its declaration
    /// (spec §1): named, a number of its type.
    fn parse_param(&self, component: ComponentKind, name: &str, text: &str) -> crate::Result<f64> {
        let config = self.state.system.wiring().config(component)?;
        let spec = config
            .specs()
            .iter()
            .find(|s| s.name == name)
            .ok_or_else(|| unknown_parameter(component, name))?;
        Ok(spec.parse(text, None)?)
    }

    /// Sets a parameter from text, parsed by its declaration (spec §1).
    pub fn set_param_text(
        &mut self,
        component: ComponentKind,
        name: &str,
        text: &str,
    ) -> crate::Result<()> {
        let value = self.parse_param(component, name, text)?;
        self.apply(&Input::SetParam {
            component,
            name: name.to_owned(),
            value,
        })
    }

    // ------------------------------------------------------------------ read-outs

    /// The events since the last call (those still kept), oldest first.
    pub fn new_events(&mut self) -> Vec<SystemEvent> {
        let record = self.state.system.record();
        let events = record.events_since(self.events_seen).cloned().collect();
        self.events_seen = record.event_count();
        events
    }

    /// Every parameter of the [`TUNABLE`] components, as the parameter panel lists them.
    pub fn parameters_view(&self) -> Vec<ComponentParameters> {
        let wiring = self.state.system.wiring();
        let ec = wiring.execution_context();
        let mut out = Vec::new();
        for kind in TUNABLE {
            let Ok(config) = wiring.config(kind) else {
                continue;
            };
            let period_s = ec.period_of(kind.index()).map_or(f64::NAN, |ticks| {
                (ticks * ec.base_period_ns()) as f64 * 1e-9
            });
            let params = config
                .specs()
                .iter()
                .map(|spec| ParameterView {
                    name: spec.name,
                    kind: spec.kind.name(),
                    unit: spec.unit,
                    default: spec.default,
                    min: spec.min.is_finite().then_some(spec.min),
                    max: spec.max.is_finite().then_some(spec.max),
                    range: spec.range_text(),
                    reflection: spec.reflection.to_string(),
                    description: spec.description,
                    seed_text: spec.seed_text,
                    warning: self.warning(kind, spec.name),
                    value: config.value(spec.name).unwrap_or(f64::NAN),
                    effective: config.effective_value(spec.name).unwrap_or(f64::NAN),
                    pending: config.is_pending(spec.name).unwrap_or(false),
                })
                .collect();
            out.push(ComponentParameters {
                component: kind.name(),
                instance_name: kind.instance_name(),
                period_s,
                params,
            });
        }
        out
    }

    /// The warning shown beside parameter `name` of `kind` (see [`ParameterView::warning`]
    /// and [`ParameterWarning::of`], which an exercise's rule reads too).
    fn warning(&self, kind: ComponentKind, name: &str) -> Option<ParameterWarning> {
        ParameterWarning::of(self.state.system.wiring(), kind, name)
    }

    /// The last `seconds` (at most [`MAX_PLOT_SECONDS`]) of telemetry, one array per series.
    pub fn plot(&self, seconds: f64) -> PlotWindow {
        let seconds = if seconds.is_finite() {
            seconds.clamp(0.0, MAX_PLOT_SECONDS)
        } else {
            0.0
        };
        let s = &self.state.system;
        let now = s.time_ns();
        let from = now.saturating_sub(libm::round(seconds * 1e9) as u64);
        let mut w = PlotWindow {
            deviatinglen: s.wiring().local_path_planning().params().deviatinglen,
            max_torque: s.wiring().physics().physics().params().max_torque,
            ..PlotWindow::default()
        };
        // The window is at the end of a long history: find its start from the back.
        let samples = s.record().telemetry().samples();
        let inside = samples
            .iter()
            .rev()
            .take_while(|x| x.time_ns >= from)
            .count();
        for sample in samples.iter().skip(samples.len() - inside) {
            w.t.push(sample.time_ns as f64 * 1e-9);
            w.target_rate_l.push(sample.target_wheel_rate[0]);
            w.target_rate_r.push(sample.target_wheel_rate[1]);
            w.rate_l.push(sample.wheel_rate[0]);
            w.rate_r.push(sample.wheel_rate[1]);
            w.torque_l.push(sample.torque[0]);
            w.torque_r.push(sample.torque[1]);
            w.applied_l.push(sample.applied_torque[0]);
            w.applied_r.push(sample.applied_torque[1]);
            w.v_cmd.push(sample.v_cmd);
            w.v.push(sample.v);
            w.w_cmd.push(sample.w_cmd);
            w.w.push(sample.w);
            w.deviation
                .push(sample.deviation.is_finite().then_some(sample.deviation));
        }
        w.replans = s
            .record()
            .plan_times()
            .filter(|&t| t >= from)
            .map(|t| t as f64 * 1e-9)
            .collect();
        w
    }
}

/// The students' scripts in the system's places, as a set-up carries them.
fn scripts_of(system: &System) -> BTreeMap<String, ScriptText> {
    ComponentKind::ALL
        .into_iter()
        .filter_map(|kind| {
            let program = system.wiring().script(kind)?.program();
            Some((
                kind.name().to_owned(),
                ScriptText {
                    name: program.name().to_owned(),
                    source: program.source().to_owned(),
                },
            ))
        })
        .collect()
}
