//! What the fuzzer and the soak found, kept as regression tests (spec §2 and §4 Decisions
//! 0.2):
//!
//! 1. the rtnav JSON map reader allocated `rows × width` before it checked the size: the exact
//!    inputs of the report are refused with `MapError::TooLarge`, allocating almost nothing
//!    (counted by this test binary's own allocator);
//! 2. MotorControl panicked on `{0 s, 1.5e9 ns}` then `{1 s, 0 ns}`: the first is refused,
//!    the second accepted, nothing panics;
//! 3. timestamps are checked the same way where a sample enters every component
//!    ([`Time::checked`]), and time differences never underflow ([`Time::nanos_since`]).
//!
//! Reproduction 4 (the dmin boundary), the planners' and MapMaintenance's `MapUpdate`
//! timestamps and the share-token deflate bomb are in `margin_and_map_updates.rs`.

// A test binary may have its own allocator: this one counts, per thread, what the code under
// test asks for. Its `unsafe` is the `GlobalAlloc` contract, passed straight to `System`.
#![allow(unsafe_code)]

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

use proptest::prelude::*;
use rtnav::components::{DriveControl, Localization, MotorControl, MotorStatus, PhysicsSim};
use rtnav::errors::{MapError, MotionError};
use rtnav::interfaces::ControlPoints;
use rtnav::map::formats::{json, movingai, ros};
use rtnav::map::{GridMap, MAX_CELLS, MapUpdate};
use rtnav::motion::PhysicsParams;
use rtnav::rtc::{
    Component, InPort, OutPort, Tick, Time, TimedDoubleSeq, TimedPosition, TimedVelocity,
    TimestampError,
};

// ------------------------------------------------------------------ counting allocator

thread_local! {
    static LIVE: Cell<i64> = const { Cell::new(0) };
    static PEAK: Cell<i64> = const { Cell::new(0) };
    static LARGEST: Cell<usize> = const { Cell::new(0) };
}

struct Counting;

fn note_alloc(size: usize) {
    let _ = LARGEST.try_with(|l| l.set(l.get().max(size)));
    let _ = LIVE.try_with(|live| {
        let now = live.get() + size as i64;
        live.set(now);
        let _ = PEAK.try_with(|p| p.set(p.get().max(now)));
    });
}

fn note_free(size: usize) {
    let _ = LIVE.try_with(|live| live.set(live.get() - size as i64));
}

// SAFETY: every call is passed to the system allocator with the caller's arguments; the
// counters are thread-local `Cell`s with const initialisers, which never allocate.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        note_alloc(layout.size());
        unsafe { System.alloc(layout) }
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        note_alloc(layout.size());
        unsafe { System.alloc_zeroed(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        note_free(layout.size());
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        note_free(layout.size());
        note_alloc(new_size);
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Runs `f` and returns its result with the largest single request and the peak of live
/// bytes above the start, both on this thread.
fn measured<T>(f: impl FnOnce() -> T) -> (T, usize, i64) {
    let base = LIVE.with(Cell::get);
    PEAK.with(|p| p.set(base));
    LARGEST.with(|l| l.set(0));
    let out = f();
    (out, LARGEST.with(Cell::get), PEAK.with(Cell::get) - base)
}

const MIB: usize = 1 << 20;

// ------------------------------------------------------------------ 1. map readers

/// The report's inputs: 2³¹ cells asked 2 GiB of `rows × width`; a larger width aborted the
/// process ("memory allocation … failed"); `u64::MAX` panicked with "capacity overflow".
#[test]
fn json_map_with_a_huge_width_is_refused_before_anything_is_allocated() {
    let widths: [(&str, u64); 3] = [
        ("2147483648", 2_147_483_648),
        ("1099511627776", 1 << 40),
        ("18446744073709551615", u64::MAX),
    ];
    for (text, width) in widths {
        let input = format!(r#"{{"width": {text}, "height": 1, "grid_size": 1, "rows": ["."]}}"#);
        let (result, largest, peak) = measured(|| json::load(&input));
        match result {
            Err(MapError::TooLarge { cells, limit, .. }) => {
                assert_eq!(limit, MAX_CELLS);
                assert_eq!(cells, width.to_string(), "width {text}: cells as asked");
            }
            other => panic!("width {text}: expected TooLarge, got {other:?}"),
        }
        assert!(
            largest < MIB && peak < MIB as i64,
            "width {text}: asked for {largest} bytes at once, {peak} at the peak"
        );
    }
}

#[test]
fn json_map_rows_are_checked_before_the_cells_are_allocated() {
    // Within the limit, but the rows do not hold what the header claims: refused without
    // allocating the 16 Mi cells.
    let input = r#"{"width": 16777216, "height": 1, "grid_size": 1, "rows": ["."]}"#;
    let (result, largest, _) = measured(|| json::load(input));
    assert!(
        matches!(&result, Err(MapError::Format { reason, .. }) if reason.contains("expected width 16777216")),
        "{result:?}"
    );
    assert!(largest < MIB, "asked for {largest} bytes at once");
    let zero = r#"{"width": 0, "height": 1, "grid_size": 1, "rows": [""]}"#;
    assert!(matches!(
        json::load(zero),
        Err(MapError::BadDimension {
            axis: "MapLengthX",
            ..
        })
    ));
}

#[test]
fn movingai_and_ros_headers_that_claim_more_than_the_file_holds_allocate_little() {
    // A `.map` header within the limit with no rows: the rows are gathered as they come.
    let text = "type octile\nheight 4096\nwidth 4096\nmap\n";
    let (result, largest, _) = measured(|| movingai::load_map(text));
    assert!(result.is_err());
    assert!(largest < MIB, "asked for {largest} bytes at once");
    // Beyond the limit, with overflow.
    let text = format!(
        "type octile\nheight {}\nwidth {}\nmap\n",
        u64::MAX,
        u64::MAX
    );
    assert!(matches!(
        movingai::load_map(&text),
        Err(MapError::TooLarge { .. })
    ));
    // A PGM header of 4096 × 4096 pixels in 20 bytes: refused before decoding.
    let yaml = "image: m.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\n\
                occupied_thresh: 0.65\nfree_thresh: 0.196\n";
    let pgm = b"P5\n4096 4096\n255\n\x00\x00";
    let (result, largest, _) = measured(|| ros::load(yaml, pgm, &ros::RosLoadOptions::default()));
    assert!(
        matches!(&result, Err(MapError::Format { reason, .. }) if reason.contains("claims 4096×4096")),
        "{result:?}"
    );
    assert!(largest < MIB, "asked for {largest} bytes at once");
    // Beyond the limit: the size check comes first.
    let pgm = b"P5\n65535 65535\n255\n\x00";
    assert!(matches!(
        ros::load(yaml, pgm, &ros::RosLoadOptions::default()),
        Err(MapError::TooLarge { .. })
    ));
}

#[test]
fn check_size_is_the_one_size_check_of_every_reader() {
    assert_eq!(GridMap::check_size(4096, 4096), Ok(MAX_CELLS));
    assert!(matches!(
        GridMap::check_size(4097, 4096),
        Err(MapError::TooLarge { .. })
    ));
    assert!(matches!(
        GridMap::check_size(u64::MAX, 2),
        Err(MapError::TooLarge { cells, .. }) if cells == "36893488147419103230"
    ));
    assert!(matches!(
        GridMap::check_size(3, 0),
        Err(MapError::BadDimension {
            axis: "MapLengthY",
            value: 0
        })
    ));
}

/// Found by the fuzzer after the ROS reader moved to saphyr-parser's events (seed
/// 1796172591, target `ros-yaml`, case 747813): flow collections left open after a scalar
/// (`{000]` over and over) cost the parser about 90 bytes of state per byte of input — 35 MiB
/// for 384 KB. A map_server YAML is a few lines: a file over `MAX_YAML_BYTES` is refused
/// before it is parsed, and one within costs at most 128 bytes a byte.
#[test]
fn a_ros_yaml_of_open_flow_collections_costs_little_and_a_huge_one_is_refused() {
    let head = "image: willow-2010-02-4294967295-0.10.pgm\nresolution: 0.100000\n\
                origin: [1, s.000000, 0.00";
    let within = format!("{head}{}", "{000]\n".repeat(3000));
    assert!(within.len() <= ros::MAX_YAML_BYTES);
    let (result, largest, peak) = measured(|| ros::parse_yaml(&within));
    assert!(result.is_err());
    let bound = 256 * 1024 + 128 * within.len() as i64;
    assert!(
        (largest as i64) <= bound && peak <= bound,
        "{} bytes: asked {largest} at once, {peak} at the peak",
        within.len()
    );
    let huge = format!("{head}{}", "{000]\n".repeat(200_000));
    let (result, largest, _) = measured(|| ros::parse_yaml(&huge));
    assert!(
        matches!(&result, Err(MapError::Format { reason, .. }) if reason.contains("at most 65536 bytes")),
        "{result:?}"
    );
    assert!(largest < MIB, "asked for {largest} bytes at once");
}

// ------------------------------------------------------------------ 2. MotorControl

const MS: u64 = 1_000_000;

fn tick(ms: u64) -> Tick {
    Tick {
        time_ns: ms * MS,
        period_ns: MS,
        index: ms,
    }
}

fn bad_time(what: &'static str) -> MotionError {
    MotionError::BadTimestamp(TimestampError {
        what,
        sec: 0,
        nsec: 1_500_000_000,
    })
}

/// The exact sequence of the report: `{0 s, 1.5e9 ns}` then `{1 s, 0 ns}` on
/// `InCurrentWheelAngle`. The first passed the ordering check (`(0, 1.5e9) < (1, 0)`) and the
/// rate's `as_nanos()` subtraction underflowed (a panic in debug, a wrong rate in release).
#[test]
fn motor_control_refuses_nsec_of_a_second_or_more_and_never_underflows() {
    let mut m = MotorControl::default();
    let mut ang = OutPort::new("angle");
    let mut vel = OutPort::new("velocity");
    let torque = InPort::new("torque");
    ang.connect(&m.in_current_wheel_angle);
    vel.connect(&m.target_velocity);
    m.torque.connect(&torque);
    m.configuration().unwrap().apply_on_activation();
    m.on_activated(&tick(0)).unwrap();

    vel.write(TimedVelocity {
        tm: Time { sec: 0, nsec: 0 },
        vx: 0.2,
        ..TimedVelocity::default()
    });
    ang.write(TimedDoubleSeq {
        tm: Time {
            sec: 0,
            nsec: 1_500_000_000,
        },
        data: vec![0.0, 0.0],
    });
    m.on_execute(&tick(1)).unwrap();
    assert_eq!(m.last_error(), Some(&bad_time("InCurrentWheelAngle")));
    assert_eq!(
        m.status(),
        &MotorStatus::SafeStop(bad_time("InCurrentWheelAngle"))
    );
    assert_eq!(torque.read().unwrap().data, vec![0.0, 0.0]);
    assert!(
        m.last_error()
            .unwrap()
            .to_string()
            .contains("InCurrentWheelAngle: timestamp {sec: 0, nsec: 1500000000}"),
        "{}",
        m.last_error().unwrap()
    );

    ang.write(TimedDoubleSeq {
        tm: Time { sec: 1, nsec: 0 },
        data: vec![0.5, 0.5],
    });
    m.on_execute(&tick(2)).unwrap();
    // The refused sample was never kept: this is the first, so its rate is 0.
    assert_eq!(m.wheel_rates(), [0.0, 0.0]);
    assert_eq!(m.status(), &MotorStatus::Running);

    // The same timestamp on the other two ports.
    vel.write(TimedVelocity {
        tm: Time {
            sec: 0,
            nsec: 1_500_000_000,
        },
        ..TimedVelocity::default()
    });
    m.on_execute(&tick(3)).unwrap();
    assert_eq!(m.last_error(), Some(&bad_time("TargetVelocity")));
    m.in_simulated_position.put(TimedDoubleSeq {
        tm: Time {
            sec: 0,
            nsec: 1_500_000_000,
        },
        data: vec![0.0; 12],
    });
    m.on_execute(&tick(4)).unwrap();
    assert_eq!(m.last_error(), Some(&bad_time("InSimulatedPosition")));
    assert_eq!(m.simulated_pose(), None);
}

// ------------------------------------------------------------------ 3. one timestamp check

fn bad(what: &'static str) -> TimestampError {
    TimestampError {
        what,
        sec: 7,
        nsec: 1_000_000_000,
    }
}

const BAD: Time = Time {
    sec: 7,
    nsec: 1_000_000_000,
};

#[test]
fn localization_drive_control_and_physics_refuse_the_same_timestamps() {
    // Localization: ignored and reported, as a wrong length is; it stays Active.
    let mut l = Localization::default();
    l.configuration().unwrap().apply_on_activation();
    l.on_activated(&tick(0)).unwrap();
    for port in ["InSimulatedPosition", "InCurrentWheelAngle"] {
        let msg = TimedDoubleSeq {
            tm: BAD,
            data: vec![1.0, 2.0, 0.0, 0.5],
        };
        if port == "InSimulatedPosition" {
            l.in_simulated_position.put(msg);
        } else {
            l.in_current_wheel_angle.put(msg);
        }
        l.on_execute(&tick(1)).unwrap();
        assert_eq!(
            l.last_error(),
            Some(&MotionError::BadTimestamp(bad(port))),
            "{port}"
        );
    }
    assert_eq!(l.simulated_pose(), None);

    // DriveControl: a pose with a bad timestamp is a pose fault (zero velocity); control
    // points with one are refused and the held path stays.
    let mut d = DriveControl::default();
    d.configuration().unwrap().apply_on_activation();
    d.on_activated(&tick(0)).unwrap();
    d.in_control_points.put(ControlPoints {
        tm: BAD,
        points: vec![(0.0, 0.0), (1.0, 0.0)],
        ..ControlPoints::default()
    });
    d.on_execute(&tick(20)).unwrap();
    assert_eq!(
        d.last_error(),
        Some(&MotionError::BadTimestamp(bad("InControlPoints")))
    );
    assert!(d.pursuit().polyline().is_none());
    d.in_current_position.put(TimedPosition {
        tm: BAD,
        ..TimedPosition::default()
    });
    d.on_execute(&tick(40)).unwrap();
    assert_eq!(
        d.last_error(),
        Some(&MotionError::BadTimestamp(bad("InCurrentPosition")))
    );

    // PhysicsSim: a torque with a bad timestamp is refused (zero torque), and so is a
    // MapUpdate.
    let mut p = PhysicsSim::new("PhysicsSim0", PhysicsParams::default()).unwrap();
    p.configuration().unwrap().apply_on_activation();
    p.on_activated(&tick(0)).unwrap();
    p.torque.put(TimedDoubleSeq {
        tm: BAD,
        data: vec![1.0, 1.0],
    });
    p.on_execute(&tick(1)).unwrap();
    assert_eq!(p.applied_torque(), [0.0, 0.0]);
    assert_eq!(
        p.last_error(),
        Some(&MotionError::BadTimestamp(bad("torque")))
    );
    p.set_map(Some(GridMap::from_map_data(&[0; 4], 2, 2, 1.0).unwrap()));
    let before = format!("{:?}", p.physics());
    let e = p
        .map_update(&MapUpdate::from_cells(&[(0, 0, 1)], BAD))
        .unwrap_err();
    assert_eq!(
        e,
        rtnav::Error::Map(MapError::BadTimestamp {
            what: "MapUpdate",
            nsec: BAD.nsec
        })
    );
    assert_eq!(format!("{:?}", p.physics()), before, "nothing changed");
}

#[test]
fn time_checked_and_nanos_since_at_the_edges() {
    let max = Time {
        sec: u32::MAX,
        nsec: u32::MAX,
    };
    assert_eq!(max.checked("x"), Err(bad_with("x", u32::MAX, u32::MAX)));
    assert_eq!(
        Time {
            sec: 0,
            nsec: 999_999_999
        }
        .checked("x"),
        Ok(Time {
            sec: 0,
            nsec: 999_999_999
        })
    );
    // {1 s, 0} after {0 s, 1.5e9 ns}: the report's underflow, now 0.
    let early = Time {
        sec: 0,
        nsec: 1_500_000_000,
    };
    assert_eq!(Time { sec: 1, nsec: 0 }.nanos_since(early), 0);
    assert_eq!(max.nanos_since(Time::default()), max.as_nanos());
    assert_eq!(Time::default().nanos_since(max), 0);
}

fn bad_with(what: &'static str, sec: u32, nsec: u32) -> TimestampError {
    TimestampError { what, sec, nsec }
}

proptest! {
    /// `checked` accepts exactly `nsec < 10⁹`; on valid times the derived order is the order
    /// of `as_nanos`, and `nanos_since` is the exact non-negative difference.
    #[test]
    fn valid_times_order_and_subtract_exactly(a in any::<(u32, u32)>(), b in any::<(u32, u32)>()) {
        let (ta, tb) = (Time { sec: a.0, nsec: a.1 }, Time { sec: b.0, nsec: b.1 });
        prop_assert_eq!(ta.checked("p").is_ok(), a.1 < 1_000_000_000);
        let diff = i128::from(ta.as_nanos()) - i128::from(tb.as_nanos());
        prop_assert_eq!(i128::from(ta.nanos_since(tb)), diff.max(0));
        if ta.is_valid() && tb.is_valid() {
            prop_assert_eq!(ta.cmp(&tb), ta.as_nanos().cmp(&tb.as_nanos()));
        }
    }
}

// ------------------------------------------------------------------ found by the fuzzer

/// Found by the fuzzer (target `components`, DriveControl): control points with huge finite
/// coordinates made the pure-pursuit command NaN (∞ − ∞ on the way); the NaN was kept as the
/// last command, and the next tick's rate limit `clamp(NaN − step, NaN + step)` panicked
/// ("min > max, or either was NaN"). A path whose length is not finite is now refused, and a
/// command that is not finite is never sent or kept: DriveControl stops and says why.
#[test]
fn drive_control_survives_control_points_at_the_edge_of_f64() {
    use rtnav::interfaces::Direction;
    let paths: [Vec<(f64, f64)>; 5] = [
        // The fuzzer's input (seed 1796158401, case 680), driven backward from
        // (5.601342793926909, -0.4771496147096972, -0.9805294880598153).
        vec![
            (0.3214770733196002, f64::MAX),
            (0.6998092622262915, -7.324211918620598e137),
            (0.0, 7.916249414072893e-153),
            (-0.09478904402227817, -0.0),
        ],
        vec![(0.0, 0.0), (f64::MAX, 0.0), (-f64::MAX, 0.0)],
        vec![(0.0, 0.0), (f64::MAX, f64::MAX)],
        vec![(-1e300, 1e300), (1e300, -1e300), (0.5, 0.5)],
        vec![(0.0, 0.0), (1e308, 0.0)],
    ];
    for points in paths {
        for (pose, direction) in [
            (
                (5.601342793926909, -0.4771496147096972, -0.9805294880598153),
                Direction::Backward,
            ),
            ((0.0, 0.0, 0.0), Direction::Forward),
            ((1e300, -1e300, 3.0), Direction::Backward),
            ((f64::MAX, 0.0, -3.0), Direction::Forward),
        ] {
            let mut d = DriveControl::default();
            let vel = InPort::new("velocity");
            d.target_velocity.connect(&vel);
            d.configuration().unwrap().apply_on_activation();
            d.on_activated(&tick(0)).unwrap();
            d.in_control_points.put(ControlPoints {
                tm: Time::default(),
                points: points.clone(),
                direction,
                goal_theta: 1.4438086518654156,
            });
            for k in 1..=5 {
                d.in_current_position.put(TimedPosition {
                    tm: Time::from_nanos(k * 20 * MS),
                    x: pose.0,
                    y: pose.1,
                    theta: pose.2,
                    ..TimedPosition::default()
                });
                let t = Tick {
                    time_ns: k * 20 * MS,
                    period_ns: 20 * MS,
                    index: k * 20,
                };
                d.on_execute(&t).unwrap();
                let v = vel.read().unwrap();
                assert!(
                    v.vx.is_finite() && v.w.is_finite(),
                    "{points:?} from {pose:?}: sent {v:?}"
                );
            }
        }
    }
}

// ------------------------------------------------------------------ 4. the dmin boundary

mod margin {
    //! Reproduction 4 (spec §3 Decision 0.2, escape from the margin): a robot whose cell is
    //! within `dmin` only by rounding (obstacle distance `0.6000000000000001`, `dmin = 0.6`),
    //! or a hair inside it, refused every local plan, goal and global plan for good. Now the
    //! local plan steps out of the zone first and the robot reaches its goal.

    use rtnav::interfaces::{Direction, Pose};
    use rtnav::map::GridMap;
    use rtnav::system::{ComponentKind, EventKind, Input, Rates, System};

    /// 20 m × 10 m of open floor at 0.1 m (outside the map counts as obstacle).
    fn open_floor() -> GridMap {
        GridMap::from_map_data(&[0; 200 * 100], 200, 100, 0.1).unwrap()
    }

    fn apply(s: &mut System, input: Input) {
        s.apply(&input).unwrap_or_else(|e| panic!("{input:?}: {e}"));
    }

    /// What a drive from the margin did.
    struct Drive {
        /// The robot cell's obstacle distance once the obstacle is there \[m\].
        distance: f64,
        /// Escape steps of the local plans sent (0: none started in the zone).
        escaped: usize,
        arrived: bool,
        bumps: u64,
    }

    /// The robot at the centre of cell (50, 50), the goal 10 m east, `dmin` 0.6 m (one value
    /// for both planners); then a `MapUpdate` puts an obstacle at `obstacle`, so that the
    /// robot's own cell is within `dmin`; then the drive, at most 120 s of simulated time.
    fn drive_from_the_margin(obstacle: (i64, i64)) -> Drive {
        let mut s = System::new(Rates::default()).unwrap();
        apply(
            &mut s,
            Input::SetParam {
                component: ComponentKind::LocalPathPlanning,
                name: "dmin".to_owned(),
                value: 0.6,
            },
        );
        s.load_map(open_floor());
        apply(
            &mut s,
            Input::SetPosition {
                start: Pose::new(5.05, 5.05, 0.0),
                goal: Pose::new(15.05, 5.05, 0.0),
                direction: Direction::Forward,
            },
        );
        apply(
            &mut s,
            Input::MapUpdate {
                cells: vec![(obstacle.0, obstacle.1, 1)],
            },
        );
        let distance = s.map().unwrap().obstacle_distance((50, 50));
        let seen = s.record().event_count();
        apply(&mut s, Input::ActivateAll);
        let arrived = s.run_until(120.0, |s| s.mission().is_arrived()).unwrap();
        let escaped = s
            .record()
            .events_since(seen)
            .filter_map(|e| match e.kind {
                EventKind::LocalPlanSent { escaped, .. } => Some(escaped),
                _ => None,
            })
            .max()
            .unwrap_or(0);
        Drive {
            distance,
            escaped,
            arrived,
            bumps: s.stats().bumps,
        }
    }

    #[test]
    fn a_robot_within_dmin_by_rounding_only_still_reaches_its_goal() {
        // Six cells below: 6 × 0.1 = 0.6000000000000001 ≤ dmin = 0.6 (with DMIN_TOLERANCE),
        // the report's value.
        let d = drive_from_the_margin((50, 44));
        assert_eq!(
            d.distance, 0.6000000000000001,
            "the report's boundary value"
        );
        assert!(rtnav::map::within_dmin(d.distance, 0.6));
        assert!(d.escaped > 0, "the first local plan steps out of the zone");
        assert!(d.arrived, "stuck at the dmin boundary");
        assert_eq!(d.bumps, 0);
    }

    #[test]
    fn a_robot_a_hair_inside_dmin_still_reaches_its_goal() {
        // (47, 45): √(3² + 5²) × 0.1 ≈ 0.583 m < dmin; the cell's edge is 0.515 m away, more
        // than radiusOfBodyArea 0.45 m, so nothing touches.
        let d = drive_from_the_margin((47, 45));
        assert!(d.distance < 0.6 && d.distance > 0.58, "{}", d.distance);
        assert!(d.escaped > 0, "the first local plan steps out of the zone");
        assert!(d.arrived, "stuck inside the dmin margin");
        assert_eq!(d.bumps, 0);
    }

    /// The control: the same drive with the obstacle 1 m away arrives without escaping, so
    /// the two tests above test the margin and nothing else.
    #[test]
    fn control_the_same_drive_with_the_obstacle_clear_of_dmin_arrives() {
        let d = drive_from_the_margin((50, 40));
        assert!(d.distance > 0.99, "{}", d.distance);
        assert_eq!(d.escaped, 0);
        assert!(d.arrived);
        assert_eq!(d.bumps, 0);
    }
}

// ------------------------------------------------------------------ 3. every MapUpdate

/// Reproduction 3 for the map updates: GlobalPathPlanning kept `nsec ≥ 10⁹` as its map
/// version while LocalPathPlanning refused it. Every component that takes a `MapUpdate`
/// (MapMaintenance, both planners, the physics, DriveControl's clearance map) refuses it the
/// same way ([`MapUpdate::check`], which calls [`Time::checked`]) and changes nothing; the
/// planners also ignore a current position stamped so.
#[test]
fn every_map_update_refuses_nsec_of_a_second_or_more_the_same_way() {
    use rtnav::components::{GlobalPathPlanning, LocalPathPlanning, MapMaintenance};
    let map = GridMap::from_map_data(&[0; 16], 4, 4, 1.0).unwrap();
    let update = MapUpdate::from_cells(&[(1, 1, 1)], BAD);
    let refusal = rtnav::Error::Map(MapError::BadTimestamp {
        what: "MapUpdate",
        nsec: BAD.nsec,
    });

    let mut g = GlobalPathPlanning::new("GlobalPathPlanning0");
    g.set_map(map.clone());
    assert_eq!(
        g.map_update(&update),
        Err(refusal.clone()),
        "GlobalPathPlanning"
    );
    assert_eq!(
        g.map(),
        Some(&map),
        "GlobalPathPlanning: map and version unchanged"
    );

    let mut l = LocalPathPlanning::new("LocalPathPlanning0");
    l.set_grid_map(map.clone());
    assert_eq!(
        l.map_update(&update),
        Err(refusal.clone()),
        "LocalPathPlanning"
    );
    assert_eq!(l.map(), Some(&map), "LocalPathPlanning: map unchanged");

    let mut m = MapMaintenance::new("MapMaintenance0");
    m.set_map(map.clone());
    assert_eq!(
        m.map_update(update.clone()),
        Err(refusal.clone()),
        "MapMaintenance"
    );
    assert_eq!(m.map(), Some(&map), "MapMaintenance: map unchanged");

    let mut d = DriveControl::default();
    d.set_map(map.clone());
    let before = format!("{d:?}");
    assert_eq!(d.map_update(&update), Err(refusal), "DriveControl");
    assert_eq!(format!("{d:?}"), before, "DriveControl: nothing changed");
}

/// GlobalPathPlanning's `InCurrentPosition`: a sample stamped `nsec ≥ 10⁹` is not a current
/// position (like a pose that is not finite), so a replan does not start from it.
#[test]
fn global_path_planning_ignores_a_current_position_with_a_bad_timestamp() {
    use rtnav::components::GlobalPathPlanning;
    use rtnav::interfaces::Pose;
    let map = GridMap::from_map_data(&[0; 400], 20, 20, 0.5).unwrap();
    let (a, b) = ((4, 4), (4, 14));
    for (tm, from) in [(BAD, a), (Time::from_nanos(150 * MS), b)] {
        let mut g = GlobalPathPlanning::new("GlobalPathPlanning0");
        g.set_map(map.clone());
        g.configuration().unwrap().apply_on_activation();
        g.on_activated(&tick(0)).unwrap();
        g.set_position(Pose::new(2.25, 2.25, 0.0), Pose::new(7.25, 7.25, 0.0))
            .unwrap();
        g.on_execute(&tick(100)).unwrap();
        assert_eq!(g.last_plan().unwrap().cells[0], a);
        // The robot reports itself at (2.25, 7.25); then an obstacle on the route asks for a
        // new one from the current position.
        g.in_current_position.put(TimedPosition {
            tm,
            x: 2.25,
            y: 7.25,
            theta: 0.0,
            ..TimedPosition::default()
        });
        g.on_execute(&tick(200)).unwrap();
        g.map_update(&MapUpdate::from_cells(&[(9, 9, 1)], Time::default()))
            .unwrap();
        g.on_execute(&tick(300)).unwrap();
        assert_eq!(g.last_plan().unwrap().cells[0], from, "{tm:?}");
    }
}

/// LocalPathPlanning's `InCurrentPosition` and `InDeviating`: a sample stamped
/// `nsec ≥ 10⁹` is ignored (no current position, no deviation), a valid one is taken.
#[test]
fn local_path_planning_ignores_port_samples_with_a_bad_timestamp() {
    use rtnav::components::LocalPathPlanning;
    use rtnav::rtc::TimedDouble;
    for (tm, taken) in [(BAD, false), (Time::from_nanos(50 * MS), true)] {
        let mut l = LocalPathPlanning::new("LocalPathPlanning0");
        l.set_grid_map(GridMap::from_map_data(&[0; 400], 20, 20, 0.5).unwrap());
        l.configuration().unwrap().apply_on_activation();
        l.on_activated(&tick(0)).unwrap();
        l.in_current_position.put(TimedPosition {
            tm,
            x: 2.25,
            y: 2.25,
            theta: 0.0,
            ..TimedPosition::default()
        });
        l.in_deviating.put(TimedDouble { tm, data: 0.01 });
        l.on_execute(&tick(100)).unwrap();
        assert_eq!(l.current_position().is_some(), taken, "{tm:?}");
        assert_eq!(l.deviation().is_some(), taken, "{tm:?}");
    }
}

// ------------------------------------------------------------------ share tokens

/// Found by the fuzzer (target `share-token`): a 22 KB token that inflates past the 16 MiB
/// limit was refused with `format!("{e:?}")` of miniz_oxide's `DecompressError`, which holds
/// the whole partial output — a 67 MB message, 76 MiB asked at once, about a second. Now the
/// message names the limit, and the refusal costs the inflated bytes and little more.
#[test]
fn a_share_token_that_inflates_past_the_limit_is_refused_with_a_short_message() {
    use base64::Engine as _;
    use rtnav::system::{Session, TOKEN_INFLATE_LIMIT};
    let mut json = String::from("{\"v\":1,\"scenario\":\"open_field\"");
    json.push_str(&" ".repeat(TOKEN_INFLATE_LIMIT + 1));
    json.push('}');
    let token = base64::engine::general_purpose::URL_SAFE_NO_PAD
        .encode(miniz_oxide::deflate::compress_to_vec(json.as_bytes(), 6));
    drop(json);
    assert!(token.len() < 32_000, "a small token: {} bytes", token.len());
    let (r, largest, peak) = measured(|| Session::decode_token(&token));
    let e = r.unwrap_err().to_string();
    assert!(e.len() < 200, "a {} byte message: {}…", e.len(), &e[..200]);
    assert!(e.contains("inflates to more than 16777216 bytes"), "{e}");
    let limit = TOKEN_INFLATE_LIMIT as i64;
    assert!(
        largest as i64 <= 2 * limit && peak <= 2 * limit,
        "asked {largest} B at once, {peak} B at the peak"
    );
}
