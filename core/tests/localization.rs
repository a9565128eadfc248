//! Localization (spec §5): the pose from the simulated pose or from wheel odometry (exact
//! arcs), the start pose, bad input.

use core::f64::consts::PI;

use rtnav::components::{Localization, LocalizationMode, LocalizationParams};
use rtnav::errors::MotionError;
use rtnav::interfaces::Pose;
use rtnav::motion::{DiffDrive, Odometry};
use rtnav::rtc::{
    Component, ConfigAccess, InPort, OutPort, ParameterSet, Reflection, Tick, Time, TimedDoubleSeq,
    TimedPosition,
};

const MS: u64 = 1_000_000;

fn tick(ms: u64) -> Tick {
    Tick {
        time_ns: ms * MS,
        period_ns: MS,
        index: ms,
    }
}

struct Bench {
    l: Localization,
    sim: OutPort<TimedDoubleSeq>,
    wheels: OutPort<TimedDoubleSeq>,
    out: InPort<TimedPosition>,
}

impl Bench {
    fn new(mode: LocalizationMode, start: Pose) -> Self {
        let mut l = Localization::default();
        let m = match mode {
            LocalizationMode::SimulatedPose => 0.0,
            LocalizationMode::Odometry => 1.0,
        };
        l.config_mut().set("LocalizationMode", m).unwrap();
        l.set_start_pose(start).unwrap();
        let mut sim = OutPort::new("OutSimulatedPositionToLocalization");
        let mut wheels = OutPort::new("OutCurrentWheelAngle");
        sim.connect(&l.in_simulated_position);
        wheels.connect(&l.in_current_wheel_angle);
        let out = InPort::new("InCurrentPosition");
        l.out_current_position.connect(&out);
        l.configuration().unwrap().apply_on_activation();
        l.on_activated(&tick(0)).unwrap();
        Self {
            l,
            sim,
            wheels,
            out,
        }
    }

    fn wheels(&mut self, ms: u64, data: &[f64]) {
        self.wheels.write(TimedDoubleSeq {
            tm: Time::from_nanos(ms * MS),
            data: data.to_vec(),
        });
    }

    fn exec(&mut self, ms: u64) -> Pose {
        self.l.on_execute(&tick(ms)).unwrap();
        let p = self.out.read().unwrap();
        assert_eq!(p.tm, Time::from_nanos(ms * MS));
        Pose::new(p.x, p.y, p.theta)
    }
}

fn close(a: Pose, b: Pose, eps: f64) -> bool {
    (a.x - b.x).abs() < eps && (a.y - b.y).abs() < eps && (a.theta - b.theta).abs() < eps
}

#[test]
fn parameters_and_their_reflection() {
    let names: Vec<_> = LocalizationParams::SPECS
        .iter()
        .map(|s| (s.name, s.default, s.reflection))
        .collect();
    assert_eq!(
        names,
        vec![
            ("LocalizationMode", 0.0, Reflection::Always),
            ("leftWheelID", 0.0, Reflection::OnActivation),
            ("rightWheelID", 1.0, Reflection::OnActivation),
            ("radiusOfLeftWheel", 0.1, Reflection::OnActivation),
            ("radiusOfRightWheel", 0.1, Reflection::OnActivation),
            ("lengthOfAxle", 0.441, Reflection::OnActivation),
        ]
    );
    let mut l = Localization::default();
    assert!(l.config_mut().set("LocalizationMode", 2.0).is_err());
}

#[test]
fn simulated_mode_publishes_the_simulated_pose_and_the_start_pose_before_it() {
    let start = Pose::new(1.0, 2.0, 0.5);
    let mut b = Bench::new(LocalizationMode::SimulatedPose, start);
    assert_eq!(b.exec(0), start);
    b.sim.write(TimedDoubleSeq {
        tm: Time::from_nanos(MS),
        data: vec![3.0, -1.0, 0.2, 2.5],
    });
    assert_eq!(b.exec(1), Pose::new(3.0, -1.0, 2.5));
    assert_eq!(b.exec(2), Pose::new(3.0, -1.0, 2.5), "held");
    // Bad input is ignored and reported.
    b.sim.write(TimedDoubleSeq {
        tm: Time::from_nanos(3 * MS),
        data: vec![1.0, 2.0, 3.0],
    });
    assert_eq!(b.exec(3), Pose::new(3.0, -1.0, 2.5));
    assert!(matches!(
        b.l.last_error(),
        Some(MotionError::WrongLength {
            port: "InSimulatedPosition",
            len: 3,
            ..
        })
    ));
    // A non-finite pose is a fault: on_execute fails naming the port and field, and the
    // held pose stays.
    b.sim.write(TimedDoubleSeq {
        tm: Time::from_nanos(4 * MS),
        data: vec![1.0, f64::NAN, 0.0, 0.0],
    });
    let err = b.l.on_execute(&tick(4)).unwrap_err();
    assert_eq!(
        err.to_string(),
        "InSimulatedPosition: data[1] = NaN is not finite"
    );
    assert_eq!(b.l.current_pose(), Pose::new(3.0, -1.0, 2.5));
    assert!(matches!(
        b.l.last_error(),
        Some(MotionError::NonFinite { .. })
    ));
    assert!(
        b.l.set_start_pose(Pose::new(f64::INFINITY, 0.0, 0.0))
            .is_err()
    );
    assert_eq!(b.l.start_pose(), start);
}

#[test]
fn odometry_integrates_hand_made_moves_exactly() {
    let start = Pose::new(1.0, 2.0, PI / 2.0);
    let mut b = Bench::new(LocalizationMode::Odometry, start);
    b.wheels(0, &[10.0, 20.0]); // the reference: absolute angles need not start at 0
    assert_eq!(b.exec(0), start);
    // Both wheels +1 rad: 0.1 m straight ahead (+y).
    b.wheels(10, &[11.0, 21.0]);
    assert!(close(b.exec(10), Pose::new(1.0, 2.1, PI / 2.0), 1e-15));
    // Left −1, right +1: on the spot, Δθ = 0.2 / 0.441.
    b.wheels(20, &[10.0, 22.0]);
    let p = b.exec(20);
    assert!(
        close(p, Pose::new(1.0, 2.1, PI / 2.0 + 0.2 / 0.441), 1e-15),
        "{p:?}"
    );
    // Left +1, right +2 from heading θ0: an arc of Δs = 0.15, Δθ = 0.1/0.441, radius Δs/Δθ.
    let th0 = p.theta;
    b.wheels(30, &[11.0, 24.0]);
    let q = b.exec(30);
    let (ds, dth) = (0.15, 0.1 / 0.441);
    let rho = ds / dth;
    let want = Pose::new(
        p.x + rho * ((th0 + dth).sin() - th0.sin()),
        p.y - rho * ((th0 + dth).cos() - th0.cos()),
        th0 + dth, // 2.25 rad: still inside (−π, π]
    );
    assert!(close(q, want, 1e-12), "{q:?} vs {want:?}");
    assert!((b.l.odometry().distance() - (0.1 + 0.0 + 0.15)).abs() < 1e-15);
}

#[test]
fn odometry_of_constant_wheel_rates_is_an_exact_circle() {
    // 1000 samples of constant rates: the pose stays on the analytic circle.
    let d = DiffDrive::default();
    let mut o = Odometry::new(d, Pose::default());
    let (wl, wr) = (3.0, 5.0);
    let (v, w) = d.body_velocity([wl, wr]);
    let rho = v / w;
    for k in 0..=1000u64 {
        let t = k as f64 * 0.01;
        o.update(Time::from_nanos(k * 10 * MS), [wl * t, wr * t], "test")
            .unwrap();
    }
    let t = 10.0;
    let p = o.pose();
    let th = w * t;
    assert!((p.x - rho * th.sin()).abs() < 1e-9, "{p:?}");
    assert!((p.y - rho * (1.0 - th.cos())).abs() < 1e-9, "{p:?}");
    assert!((rtnav::motion::angle_diff(p.theta, th)).abs() < 1e-12);
}

#[test]
fn bad_wheel_angles_are_reported_and_non_finite_ones_fail() {
    let mut b = Bench::new(LocalizationMode::Odometry, Pose::default());
    b.wheels(0, &[0.0, 0.0]);
    b.exec(0);
    b.wheels(1, &[1.0]);
    assert_eq!(b.exec(1), Pose::default());
    assert!(matches!(
        b.l.last_error(),
        Some(MotionError::WrongLength {
            port: "InCurrentWheelAngle",
            len: 1,
            ..
        })
    ));
    b.wheels(2, &[f64::NAN, 1.0]);
    assert!(
        b.l.on_execute(&tick(2)).is_err(),
        "a non-finite angle is a fault"
    );
    assert_eq!(b.l.current_pose(), Pose::default());
    assert!(matches!(
        b.l.last_error(),
        Some(MotionError::NonFinite { .. })
    ));
    b.wheels(0, &[1.0, 1.0]);
    assert_eq!(b.exec(3), Pose::default());
    assert!(matches!(
        b.l.last_error(),
        Some(MotionError::TimeWentBackwards { .. })
    ));
    // Nothing was lost: the next good sample carries the whole motion.
    b.wheels(4, &[1.0, 1.0]);
    assert!(close(b.exec(4), Pose::new(0.1, 0.0, 0.0), 1e-15));
}

#[test]
fn the_mode_switches_at_the_next_tick_and_wrong_wheels_drift() {
    // Odometry with a left wheel 1 % too large: driving "straight" curves.
    let mut b = Bench::new(LocalizationMode::SimulatedPose, Pose::default());
    b.l.config_mut().set("radiusOfLeftWheel", 0.101).unwrap();
    b.l.configuration().unwrap().apply_on_activation();
    b.l.on_activated(&tick(0)).unwrap();
    b.wheels(0, &[0.0, 0.0]);
    b.exec(0);
    b.wheels(1, &[10.0, 10.0]);
    b.sim.write(TimedDoubleSeq {
        tm: Time::from_nanos(MS),
        data: vec![1.0, 0.0, 0.0, 0.0],
    });
    assert_eq!(b.exec(1), Pose::new(1.0, 0.0, 0.0));
    b.l.config_mut().set("LocalizationMode", 1.0).unwrap();
    assert_eq!(b.l.config().params().mode(), LocalizationMode::Odometry);
    let p = b.exec(2);
    assert!(
        p.theta < -0.002 && (p.x - 1.005).abs() < 1e-3,
        "drifted: {p:?}"
    );
}
