//! The soak engine (`rtnav_stress::soak`): a few simulated minutes on open_field count goals,
//! arrivals and edits and find nothing wrong; a robot that stops while holding a goal is
//! reported as a stuck period. (The one-hour soak is a stage of `cargo xtask test`.)

use std::path::PathBuf;

use rtnav::data::RepoResolver;
use rtnav::system::{BuildOptions, ComponentKind, Input, Scenario, Setup, System, setup};
use rtnav_stress::alloc::Counting;
use rtnav_stress::soak::{Soak, SoakOptions};

#[global_allocator]
static ALLOCATOR: Counting = Counting;

fn open_field() -> (System, Scenario) {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    let text = std::fs::read_to_string(root.join("fixtures/scenarios/open_field.json")).unwrap();
    let scenario = Scenario::from_json(&text).unwrap();
    let system = setup::build(
        &scenario,
        &RepoResolver::new(&root),
        &Setup::of(&scenario),
        BuildOptions::default(),
    )
    .unwrap();
    (system, scenario)
}

fn options(minutes: f64) -> SoakOptions {
    let mut o = SoakOptions::new(minutes / 60.0, 7);
    o.dmin = 0.6;
    o
}

#[test]
fn a_short_soak_drives_to_goals_around_edits_and_finds_nothing_wrong() {
    let (system, scenario) = open_field();
    let soak = Soak::new(system, Some(scenario.goal.pose()), options(6.0));
    let r = soak.run(|_, _| {});
    println!("{}", r.text());
    // `Arrived` facts, each checked by spec §7 (at rest, within the tolerances of the goal
    // held): counted as arrivals or as false arrivals.
    assert!(r.goals >= 3 && r.arrivals + r.false_arrivals >= 2, "{r:#?}");
    assert!(r.edits_added >= 5, "{r:#?}");
    // False arrivals — `Arrived` facts the check refuses — are the system's arrival decision
    // (spec §7, Decision 0.3), reported by the soak, which fails on them (`rtnav-stress soak`, the
    // soak stage); they are printed above and left out here, where the soak engine is tested.
    let problems: Vec<String> = r
        .problems()
        .into_iter()
        .filter(|p| !p.contains("false arrivals"))
        .collect();
    assert_eq!(problems, Vec::<String>::new());
    assert_eq!(
        r.problems().len(),
        usize::from(r.false_arrivals > 0),
        "a false arrival is a problem of the soak"
    );
    assert!((r.sim_hours - 0.1).abs() < 1e-3);
}

#[test]
fn a_robot_that_stops_with_a_goal_held_is_a_stuck_period() {
    let (system, scenario) = open_field();
    let mut soak = Soak::new(system, Some(scenario.goal.pose()), options(10.0));
    soak.run_for(3.0);
    // DriveControl stops commanding: MotorControl brakes, the robot stands with its goal.
    soak.system_mut()
        .apply(&Input::Deactivate {
            component: ComponentKind::DriveControl,
        })
        .unwrap();
    soak.run_for(70.0);
    let r = soak.finish();
    assert_eq!(r.stuck.len(), 1, "{r:#?}");
    assert!(r.stuck[0].reason.contains("no motion for 60 s"), "{r:#?}");
    assert!(
        r.stuck[0].lasted_s >= 60.0 && r.stuck[0].cell_distance.is_some(),
        "{r:#?}"
    );
    assert!(r.problems().iter().any(|p| p.contains("1 stuck periods")));
}
