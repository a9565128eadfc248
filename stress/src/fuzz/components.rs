//! Hostile calls to every component directly (its services, its parameters and its input
//! ports), each checked against a twin: the fuzz bytes decode to a sequence of operations; an
//! operation the component refuses (`Err`) is not given to the twin, and the two must then
//! be identical — a refused call changes nothing. Operations accepted are given to both and
//! must be accepted by both (determinism); at the end the two must still be identical.
//!
//! A component's state is compared through its `Debug` text (every field) and what its output
//! ports last sent.

use rtnav::components::{
    DriveControl, GlobalPathPlanning, LocalPathPlanning, Localization, MapMaintenance,
    MotorControl, PhysicsSim,
};
use rtnav::components::{
    DriveControlParams, GlobalPathPlanningParams, LocalPathPlanningParams, LocalizationParams,
    MotorControlParams, PhysicsSimParams,
};
use rtnav::interfaces::{ControlPoints, Direction, GlobalPathCourse, Pose};
use rtnav::map::{GridMap, MapUpdate};
use rtnav::motion::PhysicsParams;
use rtnav::rtc::{
    Component, ConfigAccess, InPort, ParamSpec, ParameterSet, Tick, Time, TimedDouble,
    TimedDoubleSeq, TimedPosition, TimedVelocity,
};

use super::{Bytes, Case, REFUSED, Target};
use crate::rng::Rng;

/// The most operations one input runs.
const MAX_OPS: usize = 160;

/// An operation: `Some(accepted)` for a call that can be refused, `None` for one that cannot
/// (a port write, a tick).
type Op<C> = Box<dyn Fn(&mut C) -> Option<bool>>;

/// A component with the clock it is ticked by and sinks on its outputs.
trait Subject: Sized + 'static {
    /// The period it is executed with \[ns\].
    const PERIOD_NS: u64;
    /// Its parameters (by name, for [`parameter`]).
    const SPECS: &'static [ParamSpec];
    fn make() -> Self;
    /// The component.
    fn component(&mut self) -> &mut dyn Component;
    /// The time of its last execution \[ns\].
    fn clock(&mut self) -> &mut u64;
    fn fingerprint(&self) -> String;
    fn decode(b: &mut Bytes<'_>) -> (&'static str, Op<Self>);
}

// ------------------------------------------------------------------ the lifecycle, once

/// The configuration applied and the component activated at `t_ns`, as an execution context
/// activates it.
fn activate(c: &mut dyn Component, t_ns: u64, period_ns: u64) {
    if let Some(cfg) = c.configuration() {
        cfg.apply_on_activation();
    }
    let _ = c.on_activated(&tick(t_ns, period_ns));
}

/// `n` executions, one period apart.
fn execute<S: Subject>(n: u64) -> (&'static str, Op<S>) {
    (
        "execute",
        Box::new(move |s: &mut S| {
            for _ in 0..n {
                *s.clock() += S::PERIOD_NS;
                let t = *s.clock();
                let _ = s.component().on_execute(&tick(t, S::PERIOD_NS));
            }
            None
        }),
    )
}

/// Deactivated and activated again.
fn reactivate<S: Subject>() -> (&'static str, Op<S>) {
    (
        "re-activate",
        Box::new(|s: &mut S| {
            let t = *s.clock();
            let _ = s.component().on_deactivated(&tick(t, S::PERIOD_NS));
            activate(s.component(), t, S::PERIOD_NS);
            None
        }),
    )
}

/// Reset (from the error state) and activated again.
fn reset<S: Subject>() -> (&'static str, Op<S>) {
    (
        "reset",
        Box::new(|s: &mut S| {
            let t = *s.clock();
            let _ = s.component().on_reset(&tick(t, S::PERIOD_NS));
            activate(s.component(), t, S::PERIOD_NS);
            None
        }),
    )
}

/// A parameter change with a hostile value ([`param_op`]).
fn parameter<S: Subject>(b: &mut Bytes<'_>) -> (&'static str, Op<S>) {
    (
        "parameter",
        param_op(
            b,
            |s: &mut S| {
                s.component()
                    .configuration()
                    .unwrap_or_else(|| unreachable!("a subject with parameters"))
            },
            S::SPECS,
        ),
    )
}

// ------------------------------------------------------------------ hostile values

/// A subject's state as the twins compare it.
/// (`GridMap` and its cache stamp print without their ids: a map value's id tells only
/// whether a cache is reused, and a twin's maps have other ids by construction.)
fn state<C: Subject>(c: &C) -> String {
    c.fingerprint()
}

/// Runs the operations of `data` on a subject and its twin.
fn twins<C: Subject>(data: &[u8]) -> Result<(), String> {
    let (mut a, mut b) = (C::make(), C::make());
    let mut bytes = Bytes::new(data);
    let mut n = 0;
    while !bytes.is_empty() && n < MAX_OPS {
        let (what, op) = C::decode(&mut bytes);
        match op(&mut a) {
            Some(false) => {
                REFUSED.with(|r| r.set(r.get() + 1));
                let (sa, sb) = (state(&a), state(&b));
                if sa != sb {
                    return Err(format!(
                        "operation {n} `{what}` was refused but changed the component:\n  \
                         {sa}\n  vs the twin\n  {sb}"
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
        n += 1;
    }
    if state(&a) != state(&b) {
        return Err("the twins differ after the same accepted operations".to_owned());
    }
    Ok(())
}

fn ok<T, E>(r: Result<T, E>) -> Option<bool> {
    Some(r.is_ok())
}

fn tick(t_ns: u64, period_ns: u64) -> Tick {
    Tick {
        time_ns: t_ns,
        period_ns,
        index: t_ns / 1_000_000,
    }
}

/// A timestamp near `t_ns`: mostly valid, sometimes `nsec ≥ 10⁹`, sometimes from the past.
fn time(b: &mut Bytes<'_>, t_ns: u64) -> Time {
    match b.u8() {
        0..=199 => Time::from_nanos(t_ns),
        200..=219 => Time {
            sec: (t_ns / 1_000_000_000) as u32,
            nsec: 1_000_000_000 + b.u32() % 3_294_967_295,
        },
        220..=229 => Time::from_nanos(t_ns.saturating_sub(u64::from(b.u32()))),
        230..=239 => Time {
            sec: u32::MAX,
            nsec: u32::MAX,
        },
        _ => Time {
            sec: b.u32(),
            nsec: b.u32(),
        },
    }
}

fn seq(b: &mut Bytes<'_>, t_ns: u64, usual: usize, lo: f64, hi: f64) -> TimedDoubleSeq {
    let tm = time(b, t_ns);
    let n = if b.u8() < 220 {
        usual
    } else {
        b.length(usual + 2, 4096)
    };
    TimedDoubleSeq {
        tm,
        data: (0..n).map(|_| b.f64_in(lo, hi)).collect(),
    }
}

fn cells(b: &mut Bytes<'_>, w: i64, h: i64) -> (Vec<i32>, Vec<i32>, Vec<i16>, i32) {
    let n = b.length(6, 2048);
    let mut x = Vec::with_capacity(n);
    let mut y = Vec::with_capacity(n);
    let mut v = Vec::with_capacity(n);
    for _ in 0..n {
        x.push(b.i64_in(-1, w + 1) as i32);
        y.push(b.i64_in(-1, h + 1) as i32);
        v.push(if b.u8() < 240 {
            i16::from(b.u8() % 2)
        } else {
            b.u16() as i16
        });
    }
    let mut num = n as i32;
    match b.u8() {
        0..=9 => num = -1,
        10..=19 => num = num.wrapping_add(1),
        20..=24 => {
            x.pop();
        }
        25..=29 => num = i32::MAX,
        _ => {}
    }
    (x, y, v, num)
}

/// A `MapUpdate` of hostile cells ([`cells`]) and a hostile timestamp ([`time`]).
fn update(b: &mut Bytes<'_>) -> MapUpdate {
    let (x, y, value, num) = cells(b, 20, 12);
    MapUpdate {
        x,
        y,
        value,
        num,
        tm: time(b, 0),
    }
}

/// A parameter change with a hostile value (by name from the component's own specs, or an
/// unknown name), as a number or as text.
fn param_op<C: 'static>(
    b: &mut Bytes<'_>,
    config: fn(&mut C) -> &mut dyn ConfigAccess,
    specs: &'static [ParamSpec],
) -> Op<C> {
    let name = if b.u8() < 240 && !specs.is_empty() {
        specs[b.below(specs.len())].name
    } else {
        "NoSuchParameter"
    };
    if b.u8() < 200 {
        let v = b.f64_in(-10.0, 200.0);
        Box::new(move |c: &mut C| ok(config(c).set(name, v)))
    } else {
        let text = *[
            "",
            "1e999",
            "nan",
            "-0",
            "0x1",
            "1.5",
            "12345678901234567890",
            "2 3",
            "inf",
        ]
        .get(b.below(9))
        .unwrap_or(&"");
        Box::new(move |c: &mut C| ok(config(c).set_text(name, text)))
    }
}

fn small_map() -> GridMap {
    let (w, h) = (20, 12);
    let mut cells = vec![0u8; w * h];
    for x in 0..w {
        cells[x] = 1;
        cells[x + (h - 1) * w] = 1;
    }
    for y in 3..9 {
        cells[10 + y * w] = 1;
    }
    GridMap::new(w, h, 0.5, (0.0, 0.0), cells).unwrap_or_else(|_| unreachable!("valid"))
}

// ------------------------------------------------------------------ LocalPathPlanning

struct Lpp {
    c: LocalPathPlanning,
    t: u64,
    gui: InPort<rtnav::interfaces::GridPath>,
    drive: InPort<ControlPoints>,
}

impl Subject for Lpp {
    const PERIOD_NS: u64 = 100_000_000;
    const SPECS: &'static [ParamSpec] = <LocalPathPlanningParams as ParameterSet>::SPECS;

    fn make() -> Self {
        let mut c = LocalPathPlanning::new("LocalPathPlanning0");
        let gui = InPort::new("gui");
        let drive = InPort::new("drive");
        c.invent_gui_cons.connect(&gui);
        c.drive_cons.connect(&drive);
        c.set_grid_map(small_map());
        activate(&mut c, 0, Self::PERIOD_NS);
        Self {
            c,
            t: 0,
            gui,
            drive,
        }
    }

    fn component(&mut self) -> &mut dyn Component {
        &mut self.c
    }

    fn clock(&mut self) -> &mut u64 {
        &mut self.t
    }

    fn fingerprint(&self) -> String {
        format!("{:?} {:?} {:?}", self.c, self.gui.peek(), self.drive.peek())
    }

    fn decode(b: &mut Bytes<'_>) -> (&'static str, Op<Self>) {
        match b.below(10) {
            0 => {
                let a: Vec<f64> = (0..6).map(|_| b.f64_in(-1.0, 11.0)).collect();
                let dir = if b.u8() < 230 {
                    1 + i16::from(b.u8() % 2)
                } else {
                    b.u16() as i16
                };
                (
                    "SetPosition",
                    Box::new(move |s: &mut Self| {
                        ok(s.c.set_position(a[0], a[1], a[2], a[3], a[4], a[5], dir))
                    }),
                )
            }
            1 => {
                let (x, y, value, num) = cells(b, 20, 12);
                let tm = if b.u8() < 220 {
                    Time { sec: 1, nsec: 0 }
                } else {
                    Time {
                        sec: b.u32(),
                        nsec: b.u32(),
                    }
                };
                let u = MapUpdate {
                    x,
                    y,
                    value,
                    num,
                    tm,
                };
                (
                    "MapUpdate",
                    Box::new(move |s: &mut Self| ok(s.c.map_update(&u))),
                )
            }
            2 => {
                let n = b.length(30, 5000);
                let (mut px, mut py) = (Vec::new(), Vec::new());
                let (mut x, mut y) = (b.i64_in(0, 20), b.i64_in(0, 12));
                for _ in 0..n {
                    px.push(x as i32);
                    py.push(y as i32);
                    if b.u8() < 240 {
                        x = x.saturating_add(i64::from(b.u8() % 3) - 1);
                        y = y.saturating_add(i64::from(b.u8() % 3) - 1);
                    } else {
                        x = b.i64_in(-2, 30);
                    }
                }
                let num = if b.u8() < 230 {
                    n as i32
                } else {
                    b.u32() as i32
                };
                let course = GlobalPathCourse {
                    grid_path_x: px,
                    grid_path_y: py,
                    num,
                };
                (
                    "GlobalPathCourse",
                    Box::new(move |s: &mut Self| ok(s.c.set_global_path(&course))),
                )
            }
            3 => {
                let (lx, ly) = (b.i64_in(-1, 30) as i32, b.i64_in(-1, 30) as i32);
                let n = if b.u8() < 200 {
                    (lx.max(0) as usize)
                        .saturating_mul(ly.max(0) as usize)
                        .min(4096)
                } else {
                    b.length(10, 4096)
                };
                let data: Vec<i16> = (0..n)
                    .map(|_| {
                        if b.u8() < 250 {
                            i16::from(b.u8() % 2)
                        } else {
                            7
                        }
                    })
                    .collect();
                let g = b.f64_in(0.05, 1.0);
                (
                    "SetMap",
                    Box::new(move |s: &mut Self| ok(s.c.set_map(&data, lx, ly, g))),
                )
            }
            4 => (
                "Clear",
                Box::new(|s: &mut Self| {
                    s.c.clear();
                    None
                }),
            ),
            5 => (
                "SafeMode",
                Box::new(|s: &mut Self| {
                    s.c.safe_mode();
                    None
                }),
            ),
            6 => parameter(b),
            7 => {
                let p: Vec<f64> = (0..3).map(|_| b.f64_in(-1.0, 11.0)).collect();
                let d = b.f64_in(0.0, 1.0);
                let tm = time(b, 0);
                (
                    "ports",
                    Box::new(move |s: &mut Self| {
                        s.c.in_current_position.put(TimedPosition {
                            tm,
                            x: p[0],
                            y: p[1],
                            theta: p[2],
                            ..TimedPosition::default()
                        });
                        s.c.in_deviating.put(TimedDouble { tm, data: d });
                        None
                    }),
                )
            }
            8 => (
                "RequestReplan",
                Box::new(|s: &mut Self| {
                    s.c.request_replan();
                    None
                }),
            ),
            _ => execute(1 + b.below(5) as u64),
        }
    }
}

// ------------------------------------------------------------------ GlobalPathPlanning

struct Gpp {
    c: GlobalPathPlanning,
    t: u64,
    out: InPort<GlobalPathCourse>,
}

impl Subject for Gpp {
    const PERIOD_NS: u64 = 100_000_000;
    const SPECS: &'static [ParamSpec] = <GlobalPathPlanningParams as ParameterSet>::SPECS;

    fn make() -> Self {
        let mut c = GlobalPathPlanning::new("GlobalPathPlanning0");
        let out = InPort::new("course");
        c.global_path_course.connect(&out);
        c.set_map(small_map());
        activate(&mut c, 0, Self::PERIOD_NS);
        Self { c, t: 0, out }
    }

    fn component(&mut self) -> &mut dyn Component {
        &mut self.c
    }

    fn clock(&mut self) -> &mut u64 {
        &mut self.t
    }

    fn fingerprint(&self) -> String {
        format!("{:?} {:?}", self.c, self.out.peek())
    }

    fn decode(b: &mut Bytes<'_>) -> (&'static str, Op<Self>) {
        match b.below(6) {
            0 => {
                let a: Vec<f64> = (0..6).map(|_| b.f64_in(-1.0, 11.0)).collect();
                (
                    "SetPosition",
                    Box::new(move |s: &mut Self| {
                        ok(s.c
                            .set_position(Pose::new(a[0], a[1], a[2]), Pose::new(a[3], a[4], a[5])))
                    }),
                )
            }
            1 => {
                let u = update(b);
                (
                    "MapUpdate",
                    Box::new(move |s: &mut Self| ok(s.c.map_update(&u))),
                )
            }
            2 => {
                let (lx, ly) = (b.i64_in(-1, 30) as i32, b.i64_in(-1, 30) as i32);
                let n = b.length(400, 4096);
                let data: Vec<i16> = (0..n).map(|_| i16::from(b.u8() % 3 / 2)).collect();
                let g = b.f64_in(0.05, 1.0);
                (
                    "SetMap",
                    Box::new(move |s: &mut Self| {
                        // `SetMap`'s data becomes a map only if it is valid (`GridMap` is
                        // checked when built); the component takes the map.
                        ok(GridMap::from_map_data(&data, lx, ly, g).map(|m| s.c.set_map(m)))
                    }),
                )
            }
            3 => parameter(b),
            _ => execute(1),
        }
    }
}

// ------------------------------------------------------------------ MotorControl

struct Motor {
    c: MotorControl,
    t: u64,
    torque: InPort<TimedDoubleSeq>,
    pose: InPort<TimedDoubleSeq>,
}

impl Subject for Motor {
    const PERIOD_NS: u64 = 1_000_000;
    const SPECS: &'static [ParamSpec] = <MotorControlParams as ParameterSet>::SPECS;

    fn make() -> Self {
        let mut c = MotorControl::default();
        let torque = InPort::new("torque");
        let pose = InPort::new("pose");
        c.torque.connect(&torque);
        c.out_simulated_position_to_localization.connect(&pose);
        activate(&mut c, 0, Self::PERIOD_NS);
        Self {
            c,
            t: 0,
            torque,
            pose,
        }
    }

    fn component(&mut self) -> &mut dyn Component {
        &mut self.c
    }

    fn clock(&mut self) -> &mut u64 {
        &mut self.t
    }

    fn fingerprint(&self) -> String {
        format!(
            "{:?} {:?} {:?}",
            self.c,
            self.torque.peek(),
            self.pose.peek()
        )
    }

    fn decode(b: &mut Bytes<'_>) -> (&'static str, Op<Self>) {
        match b.below(9) {
            0 => {
                let g: Vec<f64> = (0..4).map(|_| b.f64_in(0.0, 20.0)).collect();
                (
                    "SetPDGain",
                    Box::new(move |s: &mut Self| ok(s.c.set_pd_gain(g[0], g[1], g[2], g[3]))),
                )
            }
            1 => {
                let which = b.below(4);
                (
                    "Start/Finish/Clear/Stop",
                    Box::new(move |s: &mut Self| {
                        match which {
                            0 => s.c.start(),
                            1 => s.c.finish(),
                            2 => s.c.clear(),
                            _ => s.c.stop(),
                        }
                        None
                    }),
                )
            }
            2 => parameter(b),
            3 | 4 => {
                let msg = seq(b, 0, 2, -10.0, 10.0);
                let relative = msg.tm == Time::from_nanos(0);
                (
                    "InCurrentWheelAngle",
                    Box::new(move |s: &mut Self| {
                        let mut m = msg.clone();
                        if relative {
                            m.tm = Time::from_nanos(s.t);
                        }
                        s.c.in_current_wheel_angle.put(m);
                        None
                    }),
                )
            }
            5 => {
                let tm = time(b, 0);
                let (v, w) = (b.f64_in(-1.0, 1.0), b.f64_in(-2.0, 2.0));
                (
                    "TargetVelocity",
                    Box::new(move |s: &mut Self| {
                        let tm = if tm == Time::from_nanos(0) {
                            Time::from_nanos(s.t)
                        } else {
                            tm
                        };
                        s.c.target_velocity.put(TimedVelocity {
                            tm,
                            vx: v,
                            w,
                            ..TimedVelocity::default()
                        });
                        None
                    }),
                )
            }
            6 => {
                let msg = seq(b, 0, 12, -2.0, 2.0);
                (
                    "InSimulatedPosition",
                    Box::new(move |s: &mut Self| {
                        s.c.in_simulated_position.put(msg.clone());
                        None
                    }),
                )
            }
            7 => reactivate(),
            _ => execute(1 + b.below(40) as u64),
        }
    }
}

// ------------------------------------------------------------------ Localization

struct Loc {
    c: Localization,
    t: u64,
    out: InPort<TimedPosition>,
}

impl Subject for Loc {
    const PERIOD_NS: u64 = 1_000_000;
    const SPECS: &'static [ParamSpec] = <LocalizationParams as ParameterSet>::SPECS;

    fn make() -> Self {
        let mut c = Localization::default();
        let out = InPort::new("pose");
        c.out_current_position.connect(&out);
        activate(&mut c, 0, Self::PERIOD_NS);
        Self { c, t: 0, out }
    }

    fn component(&mut self) -> &mut dyn Component {
        &mut self.c
    }

    fn clock(&mut self) -> &mut u64 {
        &mut self.t
    }

    fn fingerprint(&self) -> String {
        format!("{:?} {:?}", self.c, self.out.peek())
    }

    fn decode(b: &mut Bytes<'_>) -> (&'static str, Op<Self>) {
        match b.below(6) {
            0 => {
                let p: Vec<f64> = (0..3).map(|_| b.f64_in(-5.0, 5.0)).collect();
                (
                    "SetStartPose",
                    Box::new(move |s: &mut Self| {
                        ok(s.c.set_start_pose(Pose::new(p[0], p[1], p[2])))
                    }),
                )
            }
            1 => parameter(b),
            2 => {
                let msg = seq(b, 0, 4, -5.0, 5.0);
                (
                    "InSimulatedPosition",
                    Box::new(move |s: &mut Self| {
                        s.c.in_simulated_position.put(msg.clone());
                        None
                    }),
                )
            }
            3 => {
                let msg = seq(b, 0, 2, -5.0, 5.0);
                (
                    "InCurrentWheelAngle",
                    Box::new(move |s: &mut Self| {
                        let mut m = msg.clone();
                        if m.tm == Time::from_nanos(0) {
                            m.tm = Time::from_nanos(s.t);
                        }
                        s.c.in_current_wheel_angle.put(m);
                        None
                    }),
                )
            }
            4 => reset(),
            _ => execute(1 + b.below(20) as u64),
        }
    }
}

// ------------------------------------------------------------------ PhysicsSim

struct Phys {
    c: PhysicsSim,
    t: u64,
    angle: InPort<TimedDoubleSeq>,
}

impl Subject for Phys {
    const PERIOD_NS: u64 = 1_000_000;
    const SPECS: &'static [ParamSpec] = <PhysicsSimParams as ParameterSet>::SPECS;

    fn make() -> Self {
        let mut c = PhysicsSim::new("PhysicsSim0", PhysicsParams::default())
            .unwrap_or_else(|_| unreachable!("the default model is valid"));
        let angle = InPort::new("angle");
        c.angle.connect(&angle);
        c.set_map(Some(small_map()));
        let _ = c.set_pose(Pose::new(2.25, 2.25, 0.0));
        activate(&mut c, 0, Self::PERIOD_NS);
        Self { c, t: 0, angle }
    }

    fn component(&mut self) -> &mut dyn Component {
        &mut self.c
    }

    fn clock(&mut self) -> &mut u64 {
        &mut self.t
    }

    fn fingerprint(&self) -> String {
        format!("{:?} {:?}", self.c, self.angle.peek())
    }

    fn decode(b: &mut Bytes<'_>) -> (&'static str, Op<Self>) {
        match b.below(7) {
            0 => {
                let p: Vec<f64> = (0..3).map(|_| b.f64_in(-1.0, 11.0)).collect();
                (
                    "SetPose",
                    Box::new(move |s: &mut Self| ok(s.c.set_pose(Pose::new(p[0], p[1], p[2])))),
                )
            }
            1 => {
                let u = update(b);
                (
                    "MapUpdate",
                    Box::new(move |s: &mut Self| ok(s.c.map_update(&u))),
                )
            }
            2 => parameter(b),
            3 | 4 => {
                let msg = seq(b, 0, 2, -5.0, 5.0);
                (
                    "torque",
                    Box::new(move |s: &mut Self| {
                        s.c.torque.put(msg.clone());
                        None
                    }),
                )
            }
            5 => {
                let none = b.u8() < 40;
                (
                    "SetMap",
                    Box::new(move |s: &mut Self| {
                        s.c.set_map(if none { None } else { Some(small_map()) });
                        None
                    }),
                )
            }
            _ => execute(1 + b.below(40) as u64),
        }
    }
}

// ------------------------------------------------------------------ DriveControl

struct Drive {
    c: DriveControl,
    t: u64,
    vel: InPort<TimedVelocity>,
    stop: InPort<TimedDouble>,
}

impl Subject for Drive {
    const PERIOD_NS: u64 = 20_000_000;
    const SPECS: &'static [ParamSpec] = <DriveControlParams as ParameterSet>::SPECS;

    fn make() -> Self {
        let mut c = DriveControl::default();
        let vel = InPort::new("velocity");
        c.target_velocity.connect(&vel);
        let stop = InPort::new("safety stop");
        c.safety_stop.connect(&stop);
        activate(&mut c, 0, Self::PERIOD_NS);
        Self { c, t: 0, vel, stop }
    }

    fn component(&mut self) -> &mut dyn Component {
        &mut self.c
    }

    fn clock(&mut self) -> &mut u64 {
        &mut self.t
    }

    fn fingerprint(&self) -> String {
        format!("{:?} {:?} {:?}", self.c, self.vel.peek(), self.stop.peek())
    }

    fn decode(b: &mut Bytes<'_>) -> (&'static str, Op<Self>) {
        match b.below(8) {
            // The map of the clearance check, its updates and the body's radius.
            5 => (
                "SetMap",
                Box::new(|s: &mut Self| {
                    s.c.set_map(small_map());
                    None
                }),
            ),
            6 => {
                let u = update(b);
                (
                    "MapUpdate",
                    Box::new(move |s: &mut Self| ok(s.c.map_update(&u))),
                )
            }
            7 => {
                let r = b.f64_in(0.0, 1.0);
                (
                    "radiusOfBodyArea",
                    Box::new(move |s: &mut Self| ok(s.c.set_body_radius(r))),
                )
            }
            0 => parameter(b),
            1 => {
                let n = b.length(6, 2000);
                let points: Vec<(f64, f64)> = (0..n)
                    .map(|_| (b.f64_in(-1.0, 10.0), b.f64_in(-1.0, 10.0)))
                    .collect();
                let cp = ControlPoints {
                    tm: time(b, 0),
                    points,
                    direction: if b.u8() < 128 {
                        Direction::Forward
                    } else {
                        Direction::Backward
                    },
                    goal_theta: b.f64_in(-4.0, 4.0),
                };
                (
                    "InControlPoints",
                    Box::new(move |s: &mut Self| {
                        s.c.in_control_points.put(cp.clone());
                        None
                    }),
                )
            }
            2 | 3 => {
                let p: Vec<f64> = (0..3).map(|_| b.f64_in(-1.0, 10.0)).collect();
                let tm = time(b, 0);
                (
                    "InCurrentPosition",
                    Box::new(move |s: &mut Self| {
                        s.c.in_current_position.put(TimedPosition {
                            tm,
                            x: p[0],
                            y: p[1],
                            theta: p[2],
                            ..TimedPosition::default()
                        });
                        None
                    }),
                )
            }
            _ => execute(1 + b.below(20) as u64),
        }
    }
}

// ------------------------------------------------------------------ MapMaintenance

struct Maint {
    c: MapMaintenance,
    t: u64,
    out: InPort<MapUpdate>,
}

impl Subject for Maint {
    const PERIOD_NS: u64 = 100_000_000;
    const SPECS: &'static [ParamSpec] = &[];

    fn make() -> Self {
        let mut c = MapMaintenance::new("MapMaintenance0");
        let out = InPort::new("update");
        c.map_update_out.connect(&out);
        c.set_map(small_map());
        activate(&mut c, 0, Self::PERIOD_NS);
        Self { c, t: 0, out }
    }

    fn component(&mut self) -> &mut dyn Component {
        &mut self.c
    }

    fn clock(&mut self) -> &mut u64 {
        &mut self.t
    }

    fn fingerprint(&self) -> String {
        format!("{:?} {:?}", self.c, self.out.peek())
    }

    fn decode(b: &mut Bytes<'_>) -> (&'static str, Op<Self>) {
        match b.below(3) {
            0 => {
                let u = update(b);
                (
                    "MapUpdate",
                    Box::new(move |s: &mut Self| ok(s.c.map_update(u.clone()))),
                )
            }
            1 => (
                "SetMap",
                Box::new(|s: &mut Self| {
                    s.c.set_map(small_map());
                    None
                }),
            ),
            _ => execute(1 + b.below(10) as u64),
        }
    }
}

// ------------------------------------------------------------------ the target

/// The subjects by name; an input's first byte chooses one.
type Twins = fn(&[u8]) -> Result<(), String>;
const SUBJECTS: [(&str, Twins); 7] = [
    ("LocalPathPlanning", twins::<Lpp>),
    ("GlobalPathPlanning", twins::<Gpp>),
    ("MotorControl", twins::<Motor>),
    ("Localization", twins::<Loc>),
    ("PhysicsSim", twins::<Phys>),
    ("DriveControl", twins::<Drive>),
    ("MapMaintenance", twins::<Maint>),
];

/// Every component's services, parameters and ports with hostile values, against a twin.
#[derive(Debug)]
pub struct Components;

/// The targets of this module.
pub fn targets() -> Vec<Box<dyn Target>> {
    vec![Box::new(Components)]
}

impl Target for Components {
    fn name(&self) -> &'static str {
        "components"
    }

    fn seeds(&self) -> &[Case] {
        &[]
    }

    fn generate(&self, rng: &mut Rng) -> Case {
        let n = 16 + rng.index(900);
        Case::one((0..n).map(|_| rng.next_u64() as u8).collect::<Vec<u8>>())
    }

    fn run(&mut self, case: &Case) -> Result<(), String> {
        let data = case.part(0);
        let (which, rest) = match data.split_first() {
            Some((w, rest)) => (*w, rest),
            None => (0, &[][..]),
        };
        let (name, run) = SUBJECTS[usize::from(which) % SUBJECTS.len()];
        run(rest).map_err(|e| format!("{name}: {e}"))
    }

    fn alloc_bound(&self, _case: &Case) -> u64 {
        // Small maps, at most 160 operations of at most a few thousand values each.
        64 << 20
    }
}
