//! Fuzz targets through the whole system's public API (one of the three files of the tools
//! that use `System`; the `script` target, `scripts.rs`, and the soak are the others): the
//! `.conf` bundle (`Input::LoadConf`), share tokens (`Session::decode_token`,
//! `Session::apply_share`), hostile requests — every [`Input`], through [`System::apply`] —
//! and random lifecycle sequences.
//!
//! The calls are checked against a twin system: each operation goes to system A; if A refuses
//! it (`Err`), B never gets it and the two must be identical at once ([`fingerprint`]); if A
//! accepts it, B gets it too and must accept it. At the end both run on for a while and must
//! still be identical, trace hash included.

use std::fmt::Write as _;
use std::path::Path;
use std::sync::OnceLock;

use base64::Engine as _;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use rtnav::components::{
    DriveControlParams, GlobalPathPlanningParams, LocalPathPlanningParams, LocalizationParams,
    MotorControlParams, PhysicsSimParams,
};
use rtnav::errors::ConfigError;
use rtnav::interfaces::{Direction, Pose};
use rtnav::map::GridMap;
use rtnav::rtc::{ParamSpec, ParameterSet};
use rtnav::system::{
    BoxSpec, CONF_BUNDLE_HEADER, ComponentKind, DirectionSpec, Input, MemoryResolver, PoseSpec,
    Rates, Scenario, ScenarioEvent, Session, Setup, System, TOKEN_INFLATE_LIMIT, Timeline,
};

use super::{Bytes, Case, HOSTILE_F64, INTERESTING_NUMBERS, REFUSED, Target};
use crate::rng::Rng;

/// Everything a caller can observe of a system, as text: two systems with equal fingerprints
/// are in the same state (time, lifecycle states, component statuses and errors, the robot,
/// goal and paths, statistics, the map, the whole configuration, the trace hash, the number
/// of events).
pub fn fingerprint(s: &System) -> String {
    let mut out = String::new();
    let _ = write!(out, "t={} state={:?}", s.time_ns(), s.state());
    for info in s.components() {
        let _ = write!(out, "\n{info:?}");
    }
    let _ = write!(
        out,
        "\nrobot={:?} status={:?}\nmission={:?}\nstats={:?}",
        s.robot_pose(),
        s.status(),
        s.mission(),
        s.stats()
    );
    if let Some(map) = s.map() {
        let _ = write!(
            out,
            "\nmap {}×{} version {:?} cells {:016x}",
            map.width(),
            map.height(),
            map.version(),
            crate::rng::name_hash(&String::from_utf8_lossy(map.cells()))
        );
    }
    let record = s.record();
    let _ = write!(
        out,
        "\nrates={:?} events={} samples={} trace={}\n{}",
        s.rates(),
        record.event_count(),
        record.telemetry().total(),
        record.telemetry().trace_hash(),
        s.wiring().to_conf()
    );
    out
}

/// A 24 × 16 map of 0.5 m cells (12 m × 8 m): a border, a wall at x = 12 with a door
/// (y = 6 to 9), a pillar.
pub fn yard() -> GridMap {
    let (w, h) = (24usize, 16usize);
    let mut cells = vec![0u8; w * h];
    for x in 0..w {
        cells[x] = 1;
        cells[x + (h - 1) * w] = 1;
    }
    for y in 0..h {
        cells[y * w] = 1;
        cells[w - 1 + y * w] = 1;
        if !(6..=9).contains(&y) {
            cells[12 + y * w] = 1;
        }
    }
    cells[7 + 11 * w] = 1;
    GridMap::new(w, h, 0.5, (0.0, 0.0), cells).unwrap_or_else(|_| unreachable!("valid"))
}

/// The targets of this module (`root`: the project's root, for the share-token scenario).
pub fn targets(root: &Path) -> Vec<Box<dyn Target>> {
    let mut v: Vec<Box<dyn Target>> = vec![
        Box::new(Calls {
            name: "system-calls",
            lifecycle: false,
        }),
        Box::new(Calls {
            name: "lifecycle",
            lifecycle: true,
        }),
        Box::new(Bundle::new()),
    ];
    if let Some(t) = Tokens::new(root) {
        v.push(Box::new(t));
    }
    if let Some(t) = Tokens::plain(root) {
        v.push(Box::new(t));
    }
    v
}

// ------------------------------------------------------------------ hostile calls

const KINDS: [ComponentKind; 8] = ComponentKind::ALL;

fn kind(b: &mut Bytes<'_>) -> ComponentKind {
    KINDS[b.below(KINDS.len())]
}

fn pose(b: &mut Bytes<'_>) -> Pose {
    Pose::new(b.f64_in(0.0, 12.0), b.f64_in(0.0, 8.0), b.f64_in(-4.0, 4.0))
}

fn direction(b: &mut Bytes<'_>) -> Direction {
    if b.u8() < 200 {
        Direction::Forward
    } else {
        Direction::Backward
    }
}

/// The result of one operation: `Some(accepted)` for a call that can be refused.
pub type Outcome = Option<bool>;
/// One operation on a system.
pub type Op = Box<dyn Fn(&mut System) -> Outcome>;

fn ok<T>(r: rtnav::Result<T>) -> Outcome {
    Some(r.is_ok())
}

/// An operation that is one [`Input`], carried out by [`System::apply`].
fn input(input: Input) -> (String, Op) {
    (
        format!("{input:?}"),
        Box::new(move |sys| ok(sys.apply(&input))),
    )
}

/// A value of the text forms a parameter may be written in, hostile or not.
fn param_text(b: &mut Bytes<'_>) -> &'static str {
    INTERESTING_NUMBERS[b.below(INTERESTING_NUMBERS.len())]
}

/// Hostile scenario events: times, boxes and cells anywhere (NaN, ±∞, huge).
fn scenario_events(b: &mut Bytes<'_>) -> Vec<ScenarioEvent> {
    (0..1 + b.below(4))
        .map(|_| {
            let at = b.f64_in(0.0, 2.0);
            match b.below(4) {
                0 => ScenarioEvent::MapUpdate {
                    at,
                    boxes: (0..b.length(2, 40))
                        .map(|_| BoxSpec {
                            x: [b.f64_in(-1.0, 13.0), b.f64_in(-1.0, 13.0)],
                            y: [b.f64_in(-1.0, 9.0), b.f64_in(-1.0, 9.0)],
                        })
                        .collect(),
                    cells: (0..b.length(3, 40))
                        .map(|_| [b.i64_in(-1, 25), b.i64_in(-1, 17)])
                        .collect(),
                    value: if b.u8() < 240 {
                        i16::from(b.u8() % 2)
                    } else {
                        b.u16() as i16
                    },
                },
                1 => ScenarioEvent::Goal {
                    at,
                    goal: PoseSpec {
                        x: b.f64_in(0.0, 12.0),
                        y: b.f64_in(0.0, 8.0),
                        heading_deg: b.f64_in(-200.0, 200.0),
                    },
                    direction: if b.u8() < 200 {
                        DirectionSpec::Forward
                    } else {
                        DirectionSpec::Backward
                    },
                },
                2 => ScenarioEvent::SafeMode { at },
                _ => ScenarioEvent::Clear { at },
            }
        })
        .collect()
}

/// One operation decoded from `b`; `lifecycle` weights the lifecycle, faults and time. Every
/// request a person can make goes through [`Input`] and [`System::apply`]; the rest are the
/// system's own calls (time, telemetry, the map loaded, a scenario's timeline).
fn decode(b: &mut Bytes<'_>, lifecycle: bool) -> (String, Op) {
    let choice = if lifecycle {
        *[8, 8, 8, 9, 9, 7, 6, 0, 1, 2, 4, 11, 5]
            .get(b.below(13))
            .unwrap_or(&8)
    } else {
        b.below(15)
    };
    match choice {
        0 => input(Input::SetPosition {
            start: pose(b),
            goal: pose(b),
            direction: direction(b),
        }),
        1 => input(Input::SetGoal {
            goal: pose(b),
            direction: direction(b),
        }),
        2 => {
            let n = b.length(5, 3000);
            let cells: Vec<(i64, i64, i16)> = (0..n)
                .map(|_| {
                    (
                        b.i64_in(-1, 25),
                        b.i64_in(-1, 17),
                        if b.u8() < 245 {
                            i16::from(b.u8() % 2)
                        } else {
                            b.u16() as i16
                        },
                    )
                })
                .collect();
            let (what, op) = input(Input::MapUpdate { cells });
            (what.chars().take(120).collect(), op)
        }
        3 => input(Input::SetPdGain {
            p_l: b.f64_in(0.0, 20.0),
            p_r: b.f64_in(0.0, 20.0),
            d_l: b.f64_in(0.0, 20.0),
            d_r: b.f64_in(0.0, 20.0),
        }),
        4 => {
            let component = kind(b);
            let specs = specs_of(component);
            let name = if !specs.is_empty() && b.u8() < 240 {
                specs[b.below(specs.len())].name
            } else {
                "NoSuchParameter"
            };
            if b.u8() < 200 {
                input(Input::SetParam {
                    component,
                    name: name.to_owned(),
                    value: b.f64_in(-10.0, 200.0),
                })
            } else {
                let t = param_text(b);
                (
                    format!("set_param_text({component:?}, {name}, {t:?})"),
                    Box::new(move |sys| ok(set_param_text(sys, component, name, t))),
                )
            }
        }
        5 => {
            let hz = if b.u8() < 128 {
                *[
                    1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 250.0, 500.0, 1000.0, 3.0, 7.0,
                ]
                .get(b.below(12))
                .unwrap_or(&10.0)
            } else {
                HOSTILE_F64[b.below(HOSTILE_F64.len())]
            };
            input(Input::SetRate {
                component: kind(b),
                hz,
            })
        }
        6 => {
            let component = if b.u8() < 200 {
                ComponentKind::Localization
            } else {
                kind(b)
            };
            let port = *["InSimulatedPosition", "InCurrentWheelAngle", "Torque", ""]
                .get(b.below(4))
                .unwrap_or(&"");
            let n = if b.u8() < 200 { 4 } else { b.length(8, 4096) };
            let data: Vec<f64> = (0..n).map(|_| b.f64_in(-1.0, 12.0)).collect();
            let (_, op) = input(Input::InjectInput {
                component,
                port: port.to_owned(),
                data,
            });
            (
                format!("InjectInput({component:?}, {port:?}, {n} values)"),
                op,
            )
        }
        7 => input(Input::InjectFault {
            component: kind(b),
            reason: "fuzz".to_owned(),
        }),
        8 => {
            let component = kind(b);
            input(match b.below(6) {
                0 => Input::Activate { component },
                1 => Input::Deactivate { component },
                2 => Input::Reset { component },
                3 => Input::ActivateAll,
                4 => Input::DeactivateAll,
                _ => Input::ResetAll,
            })
        }
        9 => {
            if b.u8() < 200 {
                let n = u64::from(b.u16() % 700);
                (
                    format!("step({n})"),
                    Box::new(move |sys| {
                        sys.step(n);
                        None
                    }),
                )
            } else {
                // Hostile durations only: a huge finite one is a legal (endless) request.
                let s = *[f64::NAN, -1.0, f64::INFINITY, -0.0, 0.05, 0.2, 5e-324]
                    .get(b.below(7))
                    .unwrap_or(&0.1);
                if b.u8() < 128 {
                    (
                        format!("run_for({s:?})"),
                        Box::new(move |sys| ok(sys.run_for(s))),
                    )
                } else {
                    (
                        format!("run_until({s:?})"),
                        Box::new(move |sys| ok(sys.run_until(s, |s| s.mission().is_arrived()))),
                    )
                }
            }
        }
        10 => {
            let text = garbled_conf(b);
            (
                format!("LoadConf({} bytes)", text.len()),
                Box::new(move |sys| ok(sys.apply(&Input::LoadConf { text: text.clone() }))),
            )
        }
        11 => match b.below(5) {
            0 => input(Input::Clear),
            1 => input(Input::SafeMode),
            pick @ (2 | 3) => {
                // A connection of the system's own description (any kind: those that may
                // not be cut must be refused), or a name it does not have.
                let which = b.below(40);
                let cut = pick == 2;
                (
                    format!(
                        "{}Connection(#{which})",
                        if cut { "Cut" } else { "Restore" }
                    ),
                    Box::new(move |sys| {
                        let connection = sys.wiring().graph().connections.get(which).map_or_else(
                            || format!("No.Such->Connection.{which}"),
                            |c| c.id.clone(),
                        );
                        ok(sys.apply(&if cut {
                            Input::CutConnection { connection }
                        } else {
                            Input::RestoreConnection { connection }
                        }))
                    }),
                )
            }
            _ => {
                let capacity = *[0, 1, 2, 100, 65_536].get(b.below(5)).unwrap_or(&1);
                (
                    format!("set_telemetry_capacity({capacity})"),
                    Box::new(move |sys| ok(sys.set_telemetry_capacity(capacity))),
                )
            }
        },
        12 => {
            let hz = if b.u8() < 128 {
                25.0
            } else {
                HOSTILE_F64[b.below(HOSTILE_F64.len())]
            };
            (
                format!("set_telemetry_rate({hz:?})"),
                Box::new(move |sys| ok(sys.set_telemetry_rate(hz))),
            )
        }
        13 => {
            // A scenario's timed events with hostile values, run by the one interpreter of
            // them (a refused event is logged, never an error).
            let events = scenario_events(b);
            let ticks = u64::from(b.u16() % 2500);
            (
                format!("timeline({events:?}, {ticks} ticks)"),
                Box::new(move |sys| {
                    Timeline::new(&events).run(sys, ticks);
                    None
                }),
            )
        }
        _ => (
            "load_map(yard)".to_owned(),
            Box::new(|sys| {
                sys.load_map(yard());
                None
            }),
        ),
    }
}

/// The parameter declarations of a component (none for MapBuilder and MapMaintenance).
fn specs_of(kind: ComponentKind) -> &'static [ParamSpec] {
    match kind {
        ComponentKind::PhysicsSim => PhysicsSimParams::SPECS,
        ComponentKind::MotorControl => MotorControlParams::SPECS,
        ComponentKind::Localization => LocalizationParams::SPECS,
        ComponentKind::GlobalPathPlanning => GlobalPathPlanningParams::SPECS,
        ComponentKind::LocalPathPlanning => LocalPathPlanningParams::SPECS,
        ComponentKind::DriveControl => DriveControlParams::SPECS,
        ComponentKind::MapBuilder | ComponentKind::MapMaintenance => &[],
    }
}

/// Sets a parameter through the system ([`Input::SetParam`]).
pub fn set_param(
    sys: &mut System,
    component: ComponentKind,
    name: &str,
    value: f64,
) -> rtnav::Result<()> {
    sys.apply(&Input::SetParam {
        component,
        name: name.to_owned(),
        value,
    })
}

/// Sets a parameter from text, parsed by its declaration (as the page's text fields do),
/// then through [`Input::SetParam`].
pub fn set_param_text(
    sys: &mut System,
    component: ComponentKind,
    name: &str,
    text: &str,
) -> rtnav::Result<()> {
    let config = sys.wiring().config(component)?;
    let spec = config
        .specs()
        .iter()
        .find(|s| s.name == name)
        .ok_or_else(|| ConfigError::UnknownParameter {
            name: name.to_owned(),
            line: None,
        })?;
    let value = spec.parse(text, None)?;
    set_param(sys, component, name, value)
}

/// The `.conf` bundle of a fresh system (made once).
fn default_bundle() -> &'static str {
    static BUNDLE: OnceLock<String> = OnceLock::new();
    BUNDLE.get_or_init(|| {
        System::new(Rates::default())
            .map(|s| s.wiring().to_conf())
            .unwrap_or_default()
    })
}

/// A `.conf` bundle: the system's own, with a few lines changed, dropped or added.
fn garbled_conf(b: &mut Bytes<'_>) -> String {
    let mut lines: Vec<String> = default_bundle().lines().map(str::to_owned).collect();
    for _ in 0..1 + b.below(4) {
        if lines.is_empty() {
            break;
        }
        let i = b.below(lines.len());
        match b.below(5) {
            0 => {
                lines.remove(i);
            }
            1 => {
                if let Some((k, _)) = lines[i].clone().split_once(':') {
                    lines[i] = format!(
                        "{k}: {}",
                        INTERESTING_NUMBERS[b.below(INTERESTING_NUMBERS.len())]
                    );
                }
            }
            2 => lines.insert(i, "# [LocalPathPlanning0]".to_owned()),
            3 => lines.insert(i, "# [NoSuchComponent]".to_owned()),
            _ => lines.insert(i, "conf.default.dmin: 0.7".to_owned()),
        }
    }
    lines.join("\n")
}

/// Hostile GUI calls (or lifecycle sequences) against a twin.
struct Calls {
    name: &'static str,
    lifecycle: bool,
}

fn fresh() -> Result<System, String> {
    let mut s = System::new(Rates::default()).map_err(|e| e.to_string())?;
    s.load_map(yard());
    s.apply(&Input::SetPosition {
        start: Pose::new(2.25, 2.25, 0.0),
        goal: Pose::new(10.25, 3.25, 1.5),
        direction: Direction::Forward,
    })
    .map_err(|e| e.to_string())?;
    Ok(s)
}

/// Runs the operations of `data` on a system and its twin (see the module documentation).
pub fn twin_calls(data: &[u8], lifecycle: bool) -> Result<(), String> {
    let mut bytes = Bytes::new(data);
    let active = bytes.u8() < 128;
    let mut ops = Vec::new();
    while !bytes.is_empty() && ops.len() < 60 {
        ops.push(decode(&mut bytes, lifecycle));
    }
    check_twins(active, &ops)
}

/// Runs `ops` on a fresh system and its twin (every component activated first if `active`):
/// a refused operation is not given to the twin, and the two must then be identical; an
/// accepted one is given to both and must be accepted by both; after 500 more ticks the two
/// must be identical. Returns what went wrong.
pub fn check_twins(active: bool, ops: &[(String, Op)]) -> Result<(), String> {
    let (mut a, mut b) = (fresh()?, fresh()?);
    if active {
        a.apply(&Input::ActivateAll).map_err(|e| e.to_string())?;
        b.apply(&Input::ActivateAll).map_err(|e| e.to_string())?;
    }
    for (n, (what, op)) in ops.iter().enumerate() {
        match op(&mut a) {
            Some(false) => {
                REFUSED.with(|r| r.set(r.get() + 1));
                let (fa, fb) = (fingerprint(&a), fingerprint(&b));
                if fa != fb {
                    return Err(format!(
                        "operation {n} `{what}` was refused but changed the system: {}",
                        first_difference(&fa, &fb)
                    ));
                }
            }
            r => {
                let rb = op(&mut b);
                if rb != r {
                    return Err(format!(
                        "operation {n} `{what}`: {r:?} but {rb:?} on the twin (not deterministic)"
                    ));
                }
            }
        }
    }
    a.step(500);
    b.step(500);
    let (fa, fb) = (fingerprint(&a), fingerprint(&b));
    if fa != fb {
        return Err(format!(
            "after the same accepted operations and 500 ticks the twins differ: {}",
            first_difference(&fa, &fb)
        ));
    }
    Ok(())
}

/// The first line where two fingerprints differ.
pub fn first_difference(a: &str, b: &str) -> String {
    for (la, lb) in a.lines().zip(b.lines()) {
        if la != lb {
            return format!("`{la}` vs the twin's `{lb}`");
        }
    }
    "(lengths differ)".to_owned()
}

impl Target for Calls {
    fn name(&self) -> &'static str {
        self.name
    }

    fn seeds(&self) -> &[Case] {
        &[]
    }

    fn generate(&self, rng: &mut Rng) -> Case {
        let n = 8 + rng.index(400);
        Case::one((0..n).map(|_| rng.next_u64() as u8).collect::<Vec<u8>>())
    }

    fn run(&mut self, case: &Case) -> Result<(), String> {
        twin_calls(case.part(0), self.lifecycle)
    }

    fn alloc_bound(&self, _case: &Case) -> u64 {
        // Two small systems and their telemetry.
        96 << 20
    }
}

// ------------------------------------------------------------------ .conf bundle

struct Bundle {
    seeds: Vec<Case>,
}

impl Bundle {
    fn new() -> Self {
        let mut seeds = Vec::new();
        seeds.push(Case::one(default_bundle()));
        seeds.push(Case::one(format!(
            "{CONF_BUNDLE_HEADER}\n# [LocalPathPlanning0]\nconfiguration.active_config: mode1\n\
             conf.mode1.dmin: 0.6\n\n# [GlobalPathPlanning0]\nconf.default.dmin: 0.6\n"
        )));
        Self { seeds }
    }
}

impl Target for Bundle {
    fn name(&self) -> &'static str {
        "conf-bundle"
    }

    fn seeds(&self) -> &[Case] {
        &self.seeds
    }

    fn generate(&self, rng: &mut Rng) -> Case {
        let raw: Vec<u8> = (0..32).map(|_| rng.next_u64() as u8).collect();
        Case::one(garbled_conf(&mut Bytes::new(&raw)))
    }

    fn run(&mut self, case: &Case) -> Result<(), String> {
        let text = case.text(0);
        let mut s = System::new(Rates::default()).map_err(|e| e.to_string())?;
        let before = fingerprint(&s);
        match s.apply(&Input::LoadConf { text }) {
            Err(_) => {
                let after = fingerprint(&s);
                if after != before {
                    return Err(format!(
                        "a refused bundle changed the system: {}",
                        first_difference(&after, &before)
                    ));
                }
            }
            Ok(()) => {
                // What was applied writes out and reads back to the same configuration.
                let written = s.wiring().to_conf();
                s.apply(&Input::LoadConf {
                    text: written.clone(),
                })
                .map_err(|e| format!("the system's own bundle is refused: {e}"))?;
                if s.wiring().to_conf() != written {
                    return Err("the bundle written does not read back the same".to_owned());
                }
            }
        }
        Ok(())
    }

    fn alloc_bound(&self, case: &Case) -> u64 {
        // A system, and in proportion to the text (each block is parsed on its own).
        (16 << 20) + 128 * case.len() as u64
    }
}

// ------------------------------------------------------------------ share tokens

/// The limit `Session::decode_token` inflates to \[bytes\].
const INFLATE_LIMIT: u64 = TOKEN_INFLATE_LIMIT as u64;

/// Share links: the token as pasted (`share-token`), or the set-up's JSON that a token
/// carries, deflated and encoded by the target (`share-json`: mutations then reach the JSON
/// reader behind the link, as a link made by hand does).
struct Tokens {
    session: Session,
    seeds: Vec<Case>,
    /// The inputs are the JSON a token carries, not tokens.
    plain: bool,
}

impl Tokens {
    /// A session with the open_field scenario loaded (`None` if the fixture is missing).
    fn new(root: &Path) -> Option<Self> {
        let text = std::fs::read_to_string(root.join("fixtures/scenarios/open_field.json")).ok()?;
        let scenario = Scenario::from_json(&text).ok()?;
        let mut files = MemoryResolver::new();
        let map = "fixtures/maps/scenarios/open_field.json";
        files.insert(map, std::fs::read(root.join(map)).ok()?);
        let mut session = Session::new().ok()?;
        session.load_scenario(scenario, &files).ok()?;
        let mut seeds = vec![Case::one(session.share_token().ok()?)];
        session
            .apply(&Input::MapUpdate {
                cells: vec![(30, 30, 1), (31, 30, 1)],
            })
            .ok()?;
        session
            .set_param_text(ComponentKind::LocalPathPlanning, "dmin", "0.7")
            .ok()?;
        seeds.push(Case::one(session.share_token().ok()?));
        Some(Self {
            session,
            seeds,
            plain: false,
        })
    }

    /// The same session, its inputs the set-ups' JSON.
    fn plain(root: &Path) -> Option<Self> {
        let mut t = Self::new(root)?;
        t.plain = true;
        t.seeds = t
            .seeds
            .iter()
            .filter_map(|c| {
                let bytes = URL_SAFE_NO_PAD.decode(c.part(0)).ok()?;
                miniz_oxide::inflate::decompress_to_vec(&bytes).ok()
            })
            .map(Case::one)
            .collect();
        Some(t)
    }

    /// The token of input `case`.
    fn token(&self, case: &Case) -> String {
        if self.plain {
            token_of(case.part(0))
        } else {
            case.text(0)
        }
    }
}

fn token_of(json: &[u8]) -> String {
    URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(json, 6))
}

impl Target for Tokens {
    fn name(&self) -> &'static str {
        if self.plain {
            "share-json"
        } else {
            "share-token"
        }
    }

    fn fail_at(&self, _part: usize, bytes: &[u8]) -> Option<usize> {
        self.plain.then(|| super::json_fail_at(bytes)).flatten()
    }

    fn seeds(&self) -> &[Case] {
        &self.seeds
    }

    fn generate(&self, rng: &mut Rng) -> Case {
        let num = |rng: &mut Rng| {
            let s = rng.pick(INTERESTING_NUMBERS).to_string();
            if s.parse::<f64>().is_ok() && !s.contains('_') && !s.contains('x') {
                s
            } else {
                "3".to_owned()
            }
        };
        let json = match (self.plain, rng.below(4)) {
            (false, 0) => {
                // Over the inflate limit: whitespace deflates to almost nothing.
                let mut j = String::from("{\"v\":1,\"scenario\":\"open_field\"");
                j.push_str(&" ".repeat(INFLATE_LIMIT as usize + 1));
                j.push('}');
                j
            }
            _ => {
                let edits: Vec<String> = (0..rng.below(40))
                    .map(|_| {
                        format!(
                            "[{},{},{}]",
                            num(rng),
                            num(rng),
                            rng.pick(&["0", "1", "2", "-1", "32767", "32768"])
                        )
                    })
                    .collect();
                format!(
                    r#"{{"v":{},"scenario":"{}","start":[{},{},0],"goal":[23,15.5,{}],"backward":{},"edits":[{}],"params":{{"{}":{{"{}":{}}}}}}}"#,
                    rng.pick(&["1", "2", "0"]),
                    rng.pick(&["open_field", "arena", ""]),
                    num(rng),
                    num(rng),
                    num(rng),
                    rng.pick(&["false", "true"]),
                    edits.join(","),
                    rng.pick(&["LocalPathPlanning", "MotorControl", "Nobody"]),
                    rng.pick(&["dmin", "PGainL", "Nothing"]),
                    num(rng),
                )
            }
        };
        if self.plain {
            Case::one(json)
        } else {
            Case::one(token_of(json.as_bytes()))
        }
    }

    fn run(&mut self, case: &Case) -> Result<(), String> {
        let token = self.token(case);
        if Session::decode_token(&token).is_err() {
            return Ok(());
        }
        let before = (
            self.session.setup().ok(),
            fingerprint(self.session.system()),
        );
        if self.session.apply_share(&token).is_err() {
            let after = (
                self.session.setup().ok(),
                fingerprint(self.session.system()),
            );
            if after != before {
                return Err(format!(
                    "a refused share link changed the session: {}",
                    first_difference(&after.1, &before.1)
                ));
            }
        }
        Ok(())
    }

    fn alloc_bound(&self, case: &Case) -> u64 {
        // A token that does not inflate within the reader's own limit, or is not a set-up,
        // costs its inflated bytes (the output grows by doubling) and nothing more; one that
        // is a set-up is parsed and a system rebuilt from it.
        let token = self.token(case);
        let base = (1 << 20) + 64 * token.len() as u64 + 8 * case.len() as u64;
        let inflated = URL_SAFE_NO_PAD
            .decode(token.as_bytes().trim_ascii())
            .ok()
            .and_then(|b| {
                miniz_oxide::inflate::decompress_to_vec_with_limit(&b, INFLATE_LIMIT as usize).ok()
            });
        // The reader skips a byte-order mark before the JSON, as every text reader does.
        let set_up = |json: &[u8]| {
            let body = json.strip_prefix("\u{feff}".as_bytes()).unwrap_or(json);
            serde_json::from_slice::<Setup>(body).is_ok()
        };
        match inflated {
            Some(json) if set_up(&json) => (64 << 20) + base + 8 * json.len() as u64,
            Some(json) => base + 4 * json.len() as u64,
            None => base + 2 * INFLATE_LIMIT,
        }
    }
}
