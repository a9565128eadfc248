//! Every exercise discriminates (spec §7 Decision 0.3, exercise checks): for each parameter
//! an exercise lets the student change, a sweep over the parameter's legal range — coarse
//! across it, fine on each side of the boundary its lesson states — done as `rtnav check`
//! does it ([`check_exercise`]), with the other parameters at the reference solution's
//! values. The values that pass are exactly the range the lesson states (and quotes: each
//! sweep names the words of the lesson that state it). Each sweep prints its table — value,
//! verdict, each check's state and measured value with its unit (`--nocapture`).

// 1.5708 is RH0's SimulatedOffsetAngle as a student types it (and the reference solution
// has it), not an approximation of π/2 made by mistake.
#![allow(clippy::approx_constant)]

use std::fmt::Write as _;

use rtnav::data::RepoResolver;
use rtnav::system::{CheckState, ExerciseStatus, Scenario, Verdict, check_exercise};

/// One sweep: `param` (`Component.Parameter`) over `values`, the others at `base`.
struct Sweep {
    scenario: &'static str,
    param: &'static str,
    base: &'static [(&'static str, f64)],
    values: &'static [f64],
    /// The range the lesson calls right.
    right: fn(f64) -> bool,
    /// The lesson's words that state it (the test fails if the lesson does not say them).
    lesson_says: &'static str,
}

fn scenario(name: &str) -> Scenario {
    let path = format!("../fixtures/scenarios/{name}.json");
    Scenario::from_json(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The `.conf` the page saves with these values (one section per component).
fn conf(values: &[(&str, f64)]) -> String {
    let mut by_component: Vec<(&str, Vec<(&str, f64)>)> = Vec::new();
    for (name, v) in values {
        let (component, param) = name.split_once('.').unwrap();
        match by_component.iter_mut().find(|(c, _)| *c == component) {
            Some((_, list)) => list.push((param, *v)),
            None => by_component.push((component, vec![(param, *v)])),
        }
    }
    let mut text = String::new();
    for (component, list) in by_component {
        writeln!(text, "# [{component}0]").unwrap();
        for (param, v) in list {
            writeln!(text, "conf.default.{param}: {v}").unwrap();
        }
        text.push('\n');
    }
    text
}

/// A checklist as one table row: each check's state and measured value with its unit.
fn row(status: &ExerciseStatus) -> String {
    let verdict = match status.verdict {
        Verdict::Passed => "PASSED",
        Verdict::Failed => "FAILED",
        Verdict::Waiting | Verdict::Running => "UNDECIDED",
    };
    let mut out = verdict.to_owned();
    for c in &status.checks {
        let mark = match c.state {
            CheckState::Passed => "ok",
            CheckState::Failed => "FAIL",
            CheckState::Open => "OPEN",
        };
        let name = serde_json::to_value(&c.check).unwrap()["check"]
            .as_str()
            .unwrap()
            .to_owned();
        write!(out, " | {name} {mark}").unwrap();
        if let Some(m) = c.measured {
            let unit = c.unit.map_or(String::new(), |u| u.to_string());
            write!(out, " {m}{unit}").unwrap();
        }
        if !c.warned.is_empty() {
            write!(out, " ({})", c.warned.join(", ")).unwrap();
        }
    }
    out
}

fn sweep(s: &Sweep) {
    let sc = scenario(s.scenario);
    assert!(
        sc.lesson.contains(s.lesson_says),
        "{}: the lesson does not say {:?}:\n{}",
        s.scenario,
        s.lesson_says,
        sc.lesson
    );
    let exercise = sc.exercise.as_ref().unwrap();
    assert!(
        exercise.may_change.iter().any(|m| m == s.param),
        "{}: {} is not among the parameters it lets change",
        s.scenario,
        s.param
    );
    let resolver = RepoResolver::new("..");
    let mut table = format!(
        "{} — {} (others: {:?}); the lesson: \"{}\"\n",
        s.scenario, s.param, s.base, s.lesson_says
    );
    let mut wrong = Vec::new();
    for &v in s.values {
        let mut values: Vec<(&str, f64)> = s
            .base
            .iter()
            .copied()
            .filter(|(n, _)| *n != s.param)
            .collect();
        values.push((s.param, v));
        let status = check_exercise(&sc, &resolver, Some(&conf(&values)), &[]).unwrap();
        assert!(
            status.checks.iter().all(|c| c.state != CheckState::Open),
            "{} {}={v}: a check left undecided:\n{status}",
            s.scenario,
            s.param
        );
        let passed = status.verdict == Verdict::Passed;
        let right = (s.right)(v);
        writeln!(
            table,
            "  {v:>10} {} {}",
            if passed == right { " " } else { "✗" },
            row(&status)
        )
        .unwrap();
        if passed != right {
            wrong.push(v);
        }
    }
    println!("{table}");
    assert!(
        wrong.is_empty(),
        "{}: {} = {wrong:?} pass where the lesson says they fail, or fail where it says they \
         pass:\n{table}",
        s.scenario,
        s.param
    );
    // The sweep crosses the boundary: some values pass, some fail.
    assert!(
        s.values.iter().any(|v| (s.right)(*v)) && s.values.iter().any(|v| !(s.right)(*v)),
        "{}: the sweep of {} does not cross the boundary",
        s.scenario,
        s.param
    );
}

#[test]
fn door_dmin_passes_from_the_body_s_reach_to_half_the_door() {
    sweep(&Sweep {
        scenario: "ex_door_dmin",
        param: "LocalPathPlanning.dmin",
        base: &[],
        values: &[
            0.0, 0.1, 0.2, 0.3, 0.4, 0.45, 0.49, 0.5, 0.52, 0.55, 0.58, 0.59, 0.6, 0.61, 0.7, 1.0,
            5.0,
        ],
        right: |v| (0.5..0.6).contains(&v),
        lesson_says: "So dmin from 0.5 m up to, not including, 0.6 m.",
    });
}

#[test]
fn route_remake_passes_with_the_local_target_beyond_the_trolley() {
    sweep(&Sweep {
        scenario: "ex_route_remake",
        param: "LocalPathPlanning.RouteRemakeDistance",
        base: &[],
        values: &[
            0.0, 1.0, 3.0, 5.0, 7.0, 8.0, 8.5, 8.7, 8.8, 8.9, 9.0, 10.0, 12.0, 15.0, 20.0, 50.0,
            100.0,
        ],
        right: |v| v >= 8.8,
        lesson_says: "RouteRemakeDistance 8.8 m or more",
    });
}

const PARKING: &[(&str, f64)] = &[
    ("LocalPathPlanning.PostureConsiderationLevel", 85.0),
    ("DriveControl.GoalAngleTolerance", 0.05),
];

#[test]
fn parking_posture_passes_with_any_posture_level_above_zero() {
    sweep(&Sweep {
        scenario: "ex_parking_posture",
        param: "LocalPathPlanning.PostureConsiderationLevel",
        base: PARKING,
        values: &[0.0, 0.5, 1.0, 5.0, 10.0, 25.0, 50.0, 85.0, 100.0],
        right: |v| v >= 1.0,
        lesson_says: "PostureConsiderationLevel 1 or more",
    });
}

#[test]
fn parking_posture_passes_while_the_headings_count_from_the_start() {
    sweep(&Sweep {
        scenario: "ex_parking_posture",
        param: "LocalPathPlanning.NotPostureDistance",
        base: PARKING,
        values: &[
            0.0, 0.5, 1.0, 2.0, 4.0, 8.0, 8.2, 8.3, 8.5, 10.0, 20.0, 100.0,
        ],
        // The start lies hypot(3, 7.7) = 8.26 m from the goal.
        right: |v| v < 8.26,
        lesson_says: "NotPostureDistance below 8.3 m",
    });
}

#[test]
fn parking_posture_passes_with_a_goal_angle_tolerance_that_rests_within_ten_degrees() {
    sweep(&Sweep {
        scenario: "ex_parking_posture",
        param: "DriveControl.GoalAngleTolerance",
        base: PARKING,
        values: &[
            0.001, 0.01, 0.05, 0.1, 0.2, 0.3, 0.31, 0.32, 0.33, 0.4, 0.6, 1.0,
        ],
        right: |v| v <= 0.31,
        lesson_says: "GoalAngleTolerance up to 0.31 rad",
    });
}

#[test]
fn corner_deviation_passes_above_the_robot_s_straying() {
    sweep(&Sweep {
        scenario: "ex_corner_deviation",
        param: "LocalPathPlanning.Deviatinglen",
        base: &[],
        values: &[
            0.0, 0.05, 0.1, 0.11, 0.12, 0.13, 0.15, 0.2, 0.5, 1.0, 5.0, 20.0,
        ],
        right: |v| v >= 0.12,
        lesson_says: "from 0.12 m up it plans at most once",
    });
}

#[test]
fn backward_dock_passes_with_the_dock_within_target_area() {
    sweep(&Sweep {
        scenario: "ex_backward_dock",
        param: "LocalPathPlanning.TargetArea",
        base: &[],
        values: &[
            0.0, 0.5, 1.0, 1.5, 1.55, 1.59, 1.6, 1.61, 1.7, 2.0, 5.0, 20.0,
        ],
        right: |v| v >= 1.6,
        lesson_says: "from 1.6 m up the goal is within TargetArea",
    });
}

const GAINS: &[(&str, f64)] = &[
    ("MotorControl.PGainL", 5.0),
    ("MotorControl.PGainR", 5.0),
    ("MotorControl.DGainL", 5.0),
    ("MotorControl.DGainR", 5.0),
];
const D_VALUES: &[f64] = &[
    0.0, 0.5, 1.0, 1.4, 1.5, 1.6, 2.0, 5.0, 20.0, 100.0, 1e4, 1e6,
];
const P_VALUES_L: &[f64] = &[
    0.0, 1.0, 5.0, 50.0, 100.0, 300.0, 390.0, 400.0, 410.0, 500.0, 1000.0, 1e4, 1e6,
];
const P_VALUES_R: &[f64] = &[
    0.0, 1.0, 5.0, 50.0, 100.0, 300.0, 370.0, 375.0, 390.0, 500.0, 1000.0, 1e4, 1e6,
];

#[test]
fn pd_gains_pass_with_enough_d_on_each_wheel() {
    for param in ["MotorControl.DGainL", "MotorControl.DGainR"] {
        sweep(&Sweep {
            scenario: "ex_pd_gains",
            param,
            base: GAINS,
            values: D_VALUES,
            right: |v| v >= 1.5,
            lesson_says: "a D gain of 1.5 or more on each wheel",
        });
    }
}

#[test]
fn pd_gains_pass_with_p_that_does_not_overshoot() {
    let says = "a P gain up to 400 on the left wheel and 375 on the right";
    sweep(&Sweep {
        scenario: "ex_pd_gains",
        param: "MotorControl.PGainL",
        base: GAINS,
        values: P_VALUES_L,
        right: |v| v <= 400.0,
        lesson_says: says,
    });
    sweep(&Sweep {
        scenario: "ex_pd_gains",
        param: "MotorControl.PGainR",
        base: GAINS,
        values: P_VALUES_R,
        right: |v| v <= 375.0,
        lesson_says: says,
    });
}

const RH0: &[(&str, f64)] = &[
    ("MotorControl.SimulatedOffsetX", 0.0),
    ("MotorControl.SimulatedOffsetY", 0.045795),
    ("MotorControl.SimulatedOffsetAngle", 1.5708),
];

#[test]
fn model_offset_passes_within_two_centimetres_and_one_degree() {
    sweep(&Sweep {
        scenario: "ex_model_offset",
        param: "MotorControl.SimulatedOffsetX",
        base: RH0,
        values: &[
            -100.0, -1.0, -0.1, -0.021, -0.019, 0.0, 0.019, 0.021, 0.1, 1.0, 100.0,
        ],
        right: |v| v.abs() <= 0.02,
        lesson_says: "within 2 cm and 1° of them",
    });
    sweep(&Sweep {
        scenario: "ex_model_offset",
        param: "MotorControl.SimulatedOffsetY",
        base: RH0,
        values: &[
            -100.0, -1.0, -0.1, 0.0, 0.024795, 0.026795, 0.045795, 0.064795, 0.066795, 0.1, 1.0,
            100.0,
        ],
        right: |v| (v - 0.045795).abs() <= 0.02,
        lesson_says: "Y 0.045795 m",
    });
    sweep(&Sweep {
        scenario: "ex_model_offset",
        param: "MotorControl.SimulatedOffsetAngle",
        base: RH0,
        values: &[
            -std::f64::consts::PI,
            -1.5708,
            0.0,
            1.5,
            1.552,
            1.554,
            1.5708,
            1.587,
            1.589,
            2.0,
            std::f64::consts::PI,
        ],
        right: |v| (v - std::f64::consts::FRAC_PI_2).abs() <= 1f64.to_radians(),
        lesson_says: "Angle π/2 (1.5708 rad)",
    });
}

#[test]
fn speed_limit_passes_between_in_time_and_within_the_limit() {
    sweep(&Sweep {
        scenario: "ex_speed_limit",
        param: "DriveControl.MaxVelocity",
        base: &[],
        values: &[
            0.1, 0.2, 0.29, 0.3, 0.31, 0.45, 0.59, 0.6, 0.61, 0.7, 1.0, 1.5,
        ],
        right: |v| (0.3..=0.6).contains(&v),
        lesson_says: "Any MaxVelocity from 0.3 to 0.6 m/s is right",
    });
}
