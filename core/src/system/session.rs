//! [`Session`]: the system as a person drives it from InventGUI (SPEC §5) — the browser page
//! and anything else interactive. The wasm layer is a thin binding over it.
//!
//! What a session adds to the [`System`]:
//! - **A set-up and the planning preview.** After a scenario or a map is loaded the planning
//!   components are Active and the plan is drawn ([`System::preview`]); the robot's components
//!   wait, Inactive, for **Activate**. The execution context runs all the time (as in OpenRTM:
//!   Inactive components are simply not executed). While the robot stands, a new start or
//!   goal, or a changed planning parameter, is planned at once so the drawing follows.
//! - **The scenario's timed events** count from the moment the robot starts
//!   ([`System::set_drive_script`]).
//! - **The clock**: wall time × speed (0.25× to 16×) becomes whole base ticks, the remainder
//!   kept; pause; single ticks.
//! - **The set-up record** ([`Setup`]): start, goal, direction, the map cells edited since the
//!   load and every parameter that differs from the scenario's. It is what a share link
//!   carries ([`Session::share_token`]). **Decision**: replaying a set-up is one function,
//!   [`Session::restart_setup`] — the scenario built afresh, the parameters set, the edits
//!   made, start and goal placed, the preview run — so a link opened in a fresh page and the
//!   page that made it (sharing while the robot stands restarts its set-up the same way) show
//!   the identical first frame.
//! - **Teaching read-outs**: the plot window ([`Session::plot`]).

use std::collections::BTreeMap;

use base64::Engine as _;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use serde::{Deserialize, Serialize};

use super::events::EventKind;
use super::kind::ComponentKind;
use super::rates::Rates;
use super::runtime::System;
use super::scenario::{FileResolver, MapSource, MemoryResolver, Scenario};
use crate::components::MapUpdate;
use crate::errors::SystemError;
use crate::interfaces::{Direction, Pose};
use crate::map::GridMap;
use crate::rtc::{LifecycleState, Time};

/// The most wall time one [`Session::advance`] turns into simulated time \[ms\]: a tab that
/// was in the background resumes where it was instead of catching up in one frame.
pub const MAX_STEP_MS: f64 = 100.0;
/// The slowest speed offered.
pub const MIN_SPEED: f64 = 0.25;
/// The fastest speed offered.
pub const MAX_SPEED: f64 = 16.0;
/// How much simulated time the planning preview may take at most \[s\].
pub const PREVIEW_SECONDS: f64 = 5.0;
/// The longest plot window \[s\].
pub const MAX_PLOT_SECONDS: f64 = 60.0;
/// The version written into share tokens.
const SHARE_VERSION: u32 = 1;

/// The components whose parameters a session shows and a set-up records, in the order the
/// page lists them.
pub const TUNABLE: [ComponentKind; 4] = [
    ComponentKind::LocalPathPlanning,
    ComponentKind::MotorControl,
    ComponentKind::DriveControl,
    ComponentKind::PhysicsSim,
];

/// Where the loaded map came from.
#[derive(Debug, Clone)]
enum Source {
    /// Nothing loaded yet.
    Empty,
    /// A scenario, with the files it names (kept to replay set-ups).
    Scenario {
        scenario: Box<Scenario>,
        files: MemoryResolver,
    },
    /// A map file the user picked.
    MapFile,
}

/// A set-up: what a share link carries (see the module documentation).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Setup {
    /// Version of the encoding.
    pub v: u32,
    /// The scenario's name.
    pub scenario: String,
    /// Where the robot was placed `[x, y, θ]` (m, m, rad), if it was.
    pub start: Option<[f64; 3]>,
    /// The goal `[x, y, θ]`, if one is held.
    pub goal: Option<[f64; 3]>,
    /// Driving backward.
    pub backward: bool,
    /// Map cells edited since the load: `[x, y, value]`, in (x, y) order.
    pub edits: Vec<(i64, i64, i16)>,
    /// Parameters that differ from the scenario's: component → name → value.
    pub params: BTreeMap<String, BTreeMap<String, f64>>,
}

/// The last seconds of telemetry as one array per series (what the plots draw).
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
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
pub struct ComponentParameters {
    /// The component (`LocalPathPlanning`).
    pub component: &'static str,
    /// Its instance name (`LocalPathPlanning0`).
    pub instance_name: &'static str,
    /// Its parameters in declaration order.
    pub params: Vec<ParameterView>,
}

/// One parameter: its declaration (SPEC §1) and its values now.
#[derive(Debug, Clone, PartialEq, Serialize)]
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
    /// What it means.
    pub description: &'static str,
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
    system: System,
    clock: Clock,
    source: Source,
    /// The parameters as loaded (a set-up records the differences).
    baseline: Parameters,
    /// Cells edited since the load → their last value.
    edits: BTreeMap<(i64, i64), i16>,
    /// The map's file name (the scenario's map file, or the file picked).
    map_name: String,
}

/// Every [`TUNABLE`] parameter's requested value, by component and name.
type Parameters = BTreeMap<(ComponentKind, String), f64>;

fn parameters_of(system: &System) -> Parameters {
    let mut out = BTreeMap::new();
    for kind in TUNABLE {
        if let Ok(config) = system.config(kind) {
            for spec in config.specs() {
                if let Ok(v) = config.value(spec.name) {
                    out.insert((kind, spec.name.to_owned()), v);
                }
            }
        }
    }
    out
}

fn encoded(p: Pose) -> [f64; 3] {
    [p.x, p.y, p.theta]
}

fn decoded(p: [f64; 3]) -> Pose {
    Pose::new(p[0], p[1], p[2])
}

fn direction_of(backward: bool) -> Direction {
    if backward {
        Direction::Backward
    } else {
        Direction::Forward
    }
}

fn bad_token(reason: impl Into<String>) -> crate::Error {
    SystemError::BadShareToken {
        reason: reason.into(),
    }
    .into()
}

impl Session {
    /// An empty system (no map), drawing the whole potential field.
    pub fn new() -> crate::Result<Self> {
        let mut system = System::new(Rates::default())?;
        system.set_full_field(true);
        Ok(Self {
            system,
            clock: Clock {
                speed: 1.0,
                paused: false,
                pending_ns: 0,
            },
            source: Source::Empty,
            baseline: BTreeMap::new(),
            edits: BTreeMap::new(),
            map_name: String::new(),
        })
    }

    /// The system.
    pub fn system(&self) -> &System {
        &self.system
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

    // ------------------------------------------------------------------ loading

    /// Loads `scenario` (its files through `files`): rates, configuration, map, start and
    /// goal; the planning preview; its timed events held for the drive. On an error the
    /// current session stays.
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
        let setup = Setup {
            v: SHARE_VERSION,
            scenario: scenario.name.clone(),
            start: None,
            goal: None,
            backward: false,
            edits: Vec::new(),
            params: BTreeMap::new(),
        };
        let (system, baseline) = Self::build(&scenario, &files, &setup)?;
        self.map_name = match &scenario.map {
            MapSource::Json { path } | MapSource::Movingai { path, .. } => path.clone(),
            MapSource::Ros { yaml, .. } => yaml.clone(),
        };
        self.install(
            system,
            baseline,
            Source::Scenario {
                scenario: Box::new(scenario),
                files,
            },
        );
        Ok(())
    }

    /// Replaces the whole configuration from one `.conf` text ([`System::load_conf`]);
    /// all-or-nothing. A changed planning parameter is planned at once while the robot
    /// stands.
    pub fn load_conf(&mut self, text: &str) -> crate::Result<()> {
        self.system.load_conf(text)?;
        self.replan_after_parameters(&ComponentKind::PLANNING)
    }

    /// Loads a map the user picked into a fresh system with the planning components active
    /// and no start or goal; `name` is the file's name. On an error the current session
    /// stays.
    pub fn load_map(&mut self, name: &str, map: GridMap) -> crate::Result<()> {
        let mut system = System::new(Rates::default())?;
        system.set_full_field(true);
        system.load_map(map);
        for kind in ComponentKind::PLANNING {
            system.activate(kind)?;
        }
        self.map_name = name.to_owned();
        let baseline = parameters_of(&system);
        self.install(system, baseline, Source::MapFile);
        Ok(())
    }

    fn install(&mut self, system: System, baseline: Parameters, source: Source) {
        self.system = system;
        self.source = source;
        self.clock.pending_ns = 0;
        self.edits.clear();
        self.baseline = baseline;
    }

    /// The system of `scenario` with `setup` replayed (see the module documentation): the
    /// one function both a fresh load and a shared link go through. Also returns the
    /// scenario's own parameters (before the set-up's), which a set-up is measured against.
    fn build(
        scenario: &Scenario,
        files: &MemoryResolver,
        setup: &Setup,
    ) -> crate::Result<(System, Parameters)> {
        let timeless = Scenario {
            events: Vec::new(),
            ..scenario.clone()
        };
        let mut system = System::from_scenario(&timeless, files)?;
        system.set_full_field(true);
        let baseline = parameters_of(&system);
        for (component, params) in &setup.params {
            let kind = ComponentKind::from_name(component)?;
            let config = system.config_mut(kind)?;
            for (name, &value) in params {
                config.set(name, value)?;
            }
        }
        if !setup.edits.is_empty() {
            system.map_update(MapUpdate::from_cells(&setup.edits, Time::default()))?;
        }
        if let (Some(start), Some(goal)) = (setup.start, setup.goal) {
            system.set_position(decoded(start), decoded(goal), direction_of(setup.backward))?;
        }
        system
            .preview(PREVIEW_SECONDS)
            .map_err(|e| SystemError::Scenario {
                scenario: scenario.name.clone(),
                reason: format!("preview: {e}"),
            })?;
        system.set_drive_script(&scenario.events);
        Ok((system, baseline))
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
        for ((kind, pname), value) in parameters_of(&self.system) {
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
        let s = &self.system;
        Ok(Setup {
            v: SHARE_VERSION,
            scenario: name,
            start: s.start().map(encoded),
            goal: s.goal().map(encoded),
            backward: s.direction() == Direction::Backward,
            edits: self.edits.iter().map(|(&(x, y), &v)| (x, y, v)).collect(),
            params,
        })
    }

    /// The set-up as a URL-safe token (deflated JSON in base64url, no padding). While the
    /// robot stands, the session's own set-up is restarted from it first
    /// ([`Session::restart_setup`]), so this page shows what the link will open with.
    pub fn share_token(&mut self) -> crate::Result<String> {
        let setup = self.setup()?;
        let json = serde_json::to_vec(&setup).map_err(|e| bad_token(e.to_string()))?;
        let token = URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(&json, 9));
        if !self.system.is_driving() {
            self.restart_setup(&setup)?;
        }
        Ok(token)
    }

    /// Reads a token (version, JSON, numbers checked).
    pub fn decode_token(token: &str) -> crate::Result<Setup> {
        let bytes = URL_SAFE_NO_PAD
            .decode(token.trim())
            .map_err(|e| bad_token(format!("not base64url: {e}")))?;
        let json = miniz_oxide::inflate::decompress_to_vec_with_limit(&bytes, 1 << 24)
            .map_err(|e| bad_token(format!("not deflated data: {e:?}")))?;
        let setup: Setup =
            serde_json::from_slice(&json).map_err(|e| bad_token(format!("bad set-up: {e}")))?;
        if setup.v != SHARE_VERSION {
            return Err(bad_token(format!(
                "version {} (this page reads version {SHARE_VERSION})",
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

    /// Rebuilds the scenario loaded with `setup` replayed (see the module documentation).
    /// On an error nothing changes.
    pub fn restart_setup(&mut self, setup: &Setup) -> crate::Result<()> {
        let Source::Scenario { scenario, files } = &self.source else {
            return Err(bad_token("no scenario is loaded to replay the set-up on"));
        };
        if scenario.name != setup.scenario {
            return Err(bad_token(format!(
                "it was made for scenario `{}`, but `{}` is loaded",
                setup.scenario, scenario.name
            )));
        }
        let (system, baseline) = Self::build(scenario, files, setup)?;
        self.system = system;
        self.baseline = baseline;
        self.clock.pending_ns = 0;
        self.edits = setup.edits.iter().map(|&(x, y, v)| ((x, y), v)).collect();
        Ok(())
    }

    // ------------------------------------------------------------------ time

    /// Advances simulated time by `elapsed_ms` of wall time × the speed, in whole base ticks
    /// (the remainder kept; nothing while paused; at most [`MAX_STEP_MS`] per call; negative
    /// or non-finite counts as 0). Returns the number of ticks run.
    pub fn advance(&mut self, elapsed_ms: f64) -> u64 {
        if self.clock.paused {
            return 0;
        }
        let ms = if elapsed_ms.is_finite() {
            elapsed_ms.clamp(0.0, MAX_STEP_MS)
        } else {
            0.0
        };
        self.clock.pending_ns += libm::round(ms * self.clock.speed * 1e6) as u64;
        let base = self.system.execution_context().base_period_ns();
        let ticks = self.clock.pending_ns / base;
        self.clock.pending_ns %= base;
        self.system.step(ticks);
        ticks
    }

    /// Runs `ticks` base ticks now, paused or not (single step).
    pub fn step_ticks(&mut self, ticks: u64) {
        self.system.step(ticks);
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
            return Err(SystemError::BadSpeed {
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

    // ------------------------------------------------------------------ lifecycle

    /// Activates one component.
    pub fn activate(&mut self, kind: ComponentKind) -> crate::Result<LifecycleState> {
        self.system.activate(kind)
    }

    /// Deactivates one component.
    pub fn deactivate(&mut self, kind: ComponentKind) -> crate::Result<LifecycleState> {
        self.system.deactivate(kind)
    }

    /// Resets one component in Error.
    pub fn reset(&mut self, kind: ComponentKind) -> crate::Result<LifecycleState> {
        self.system.reset(kind)
    }

    /// Makes the component's next execution fail with `injected fault: {reason}`.
    pub fn inject_fault(&mut self, kind: ComponentKind, reason: &str) -> crate::Result<()> {
        self.system.inject_fault(kind, reason)
    }

    /// Writes one sample into a component's input port ([`System::inject_input`]).
    pub fn inject_input(
        &mut self,
        kind: ComponentKind,
        port: &str,
        data: Vec<f64>,
    ) -> crate::Result<()> {
        self.system.inject_input(kind, port, data)
    }

    /// Activates every Inactive component.
    pub fn activate_all(&mut self) -> super::SystemState {
        self.system.activate_all()
    }

    /// Deactivates every Active component.
    pub fn deactivate_all(&mut self) -> super::SystemState {
        self.system.deactivate_all()
    }

    /// Resets every component in Error and deactivates the Active ones.
    pub fn reset_all(&mut self) -> super::SystemState {
        self.system.reset_all()
    }

    // ------------------------------------------------------------------ inputs

    /// Whether the robot stands with every planning component Active: then a change of the
    /// set-up is planned at once.
    fn plans_now(&self) -> bool {
        !self.system.is_driving()
            && ComponentKind::PLANNING
                .iter()
                .all(|&k| self.system.component_state(k) == LifecycleState::Active)
    }

    fn preview_if_standing(&mut self) -> crate::Result<()> {
        if self.plans_now() {
            self.system.preview(PREVIEW_SECONDS)?;
        }
        Ok(())
    }

    /// `SetPosition`: places the robot at `start` and sets the goal; planned at once while
    /// the robot stands. Refused (nothing changes) as [`System::set_position`].
    pub fn set_position(
        &mut self,
        start: Pose,
        goal: Pose,
        direction: Direction,
    ) -> crate::Result<()> {
        self.system.set_position(start, goal, direction)?;
        self.preview_if_standing()
    }

    /// A new goal from where the robot is ([`System::set_goal`]); planned at once while the
    /// robot stands.
    pub fn set_goal(&mut self, goal: Pose, direction: Direction) -> crate::Result<()> {
        self.system.set_goal(goal, direction)?;
        self.preview_if_standing()
    }

    /// `MapUpdate` of `cells` `(x, y, value)`, recorded in the set-up. Returns how many
    /// changed; refused as a whole (nothing changes) for a cell outside the map.
    pub fn set_cells(&mut self, cells: &[(i64, i64, i16)]) -> crate::Result<usize> {
        let changed = self
            .system
            .map_update(MapUpdate::from_cells(cells, Time::default()))?;
        for &(x, y, v) in cells {
            self.edits.insert((x, y), v);
        }
        Ok(changed)
    }

    /// `Clear`.
    pub fn clear(&mut self) {
        self.system.clear();
    }

    /// `SafeMode`.
    pub fn safe_mode(&mut self) {
        self.system.safe_mode();
    }

    // ------------------------------------------------------------------ parameters

    /// Sets a parameter from text (SPEC §1: `always` at once, `on_activation` pending until
    /// the next activation; out of range refused, the old value stays). A changed planning
    /// parameter is planned at once while the robot stands (the goal sent again).
    pub fn set_param(&mut self, kind: ComponentKind, name: &str, text: &str) -> crate::Result<()> {
        self.system.config_mut(kind)?.set_text(name, text)?;
        self.replan_after_parameters(&[kind])
    }

    /// MotorControl's `SetPDGain` (002 §3.2.2.1 (1)); all four checked first.
    pub fn set_pd_gain(&mut self, p_l: f64, p_r: f64, d_l: f64, d_r: f64) -> crate::Result<()> {
        self.system.set_pd_gain(p_l, p_r, d_l, d_r)
    }

    fn replan_after_parameters(&mut self, kinds: &[ComponentKind]) -> crate::Result<()> {
        let planning = kinds.iter().any(|k| ComponentKind::PLANNING.contains(k));
        if !(planning && self.plans_now()) {
            return Ok(());
        }
        let Some(goal) = self.system.goal() else {
            return Ok(());
        };
        let direction = self.system.direction();
        // The plan the parameter shapes is made from where the robot stands; a goal the new
        // parameter refuses (e.g. a larger dmin) stays with its old path, and says why.
        match self.system.set_goal(goal, direction) {
            Ok(()) => self.system.preview(PREVIEW_SECONDS).map(|_| ()),
            Err(e) => {
                self.system.push_event(EventKind::RequestRefused {
                    request: "planning again with the new parameters".to_owned(),
                    reason: e.to_string(),
                });
                Ok(())
            }
        }
    }

    // ------------------------------------------------------------------ read-outs

    /// The state to draw (feature `render`).
    #[cfg(feature = "render")]
    pub fn scene(&mut self) -> Option<crate::render::Scene<'_>> {
        self.system.scene()
    }

    /// Takes the events kept ([`System::drain_events`]).
    pub fn drain_events(&mut self) -> Vec<super::SystemEvent> {
        self.system.drain_events()
    }

    /// Every parameter of the [`TUNABLE`] components, as the parameter panel lists them.
    pub fn parameters_view(&self) -> Vec<ComponentParameters> {
        let mut out = Vec::new();
        for kind in TUNABLE {
            let Ok(config) = self.system.config(kind) else {
                continue;
            };
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
                    value: config.value(spec.name).unwrap_or(f64::NAN),
                    effective: config.effective_value(spec.name).unwrap_or(f64::NAN),
                    pending: config.is_pending(spec.name).unwrap_or(false),
                })
                .collect();
            out.push(ComponentParameters {
                component: kind.name(),
                instance_name: kind.instance_name(),
                params,
            });
        }
        out
    }

    /// The last `seconds` (at most [`MAX_PLOT_SECONDS`]) of telemetry, one array per series.
    pub fn plot(&self, seconds: f64) -> PlotWindow {
        let seconds = if seconds.is_finite() {
            seconds.clamp(0.0, MAX_PLOT_SECONDS)
        } else {
            0.0
        };
        let s = &self.system;
        let now = s.time_ns();
        let from = now.saturating_sub(libm::round(seconds * 1e9) as u64);
        let mut w = PlotWindow {
            deviatinglen: s.local_path_planning().params().deviatinglen,
            ..PlotWindow::default()
        };
        // The window is at the end of a long history: find its start from the back.
        let samples = s.telemetry().samples();
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
            w.v_cmd.push(sample.v_cmd);
            w.v.push(sample.v);
            w.w_cmd.push(sample.w_cmd);
            w.w.push(sample.w);
            w.deviation
                .push(sample.deviation.is_finite().then_some(sample.deviation));
        }
        w.replans = s
            .plan_times()
            .filter(|&t| t >= from)
            .map(|t| t as f64 * 1e-9)
            .collect();
        w
    }
}
