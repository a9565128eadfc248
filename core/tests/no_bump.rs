//! No bump with default values on a real map (spec §5 "touching
//! an obstacle cell is a bump"): drives between start/goal pairs spread over the free space of
//! real ROS maps from the shared data, every parameter at its default. The body must stay off
//! the obstacles whatever the map's cell size.

use std::path::PathBuf;

use rtnav::interfaces::Pose;
use rtnav::map::GridMap;
use rtnav::system::{
    DirResolver, DirectionSpec, Expectation, MapSource, OutcomeKind, PoseSpec, Rates, Scenario,
    ScenarioRun, UnknownSpec,
};

/// The external data folder (`$RTNAV_DATA`, else `../shared/data` beside the repository).
fn data_dir() -> Result<PathBuf, rtnav::data::DataMissing> {
    rtnav::data::data_dir(&PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(".."))
}

/// A small deterministic generator (the test's own; the core has no randomness).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        self.0 >> 33
    }
}

/// `n` start/goal pairs on `map`: points of a coarse lattice over the free space that are
/// clear by `dmin`, in the same connected region, at least a third of the map apart.
fn pairs(map: &GridMap, dmin: f64, n: usize, seed: u64) -> Vec<(Pose, Pose)> {
    let g = map.grid_size();
    let (ox, oy) = map.origin();
    let step = ((1.0 / g) as usize).max(1);
    let mut points = Vec::new();
    for y in (step..map.height()).step_by(step) {
        for x in (step..map.width()).step_by(step) {
            // Well inside the free space: clear by dmin plus a cell.
            if map.is_clear((x, y), dmin + g) {
                points.push((x, y));
            }
        }
    }
    // The largest region: flood from each point's cell through clear cells.
    let mut region = vec![usize::MAX; map.width() * map.height()];
    let mut sizes = Vec::new();
    for &p in &points {
        if region[map.index(p)] != usize::MAX {
            continue;
        }
        let id = sizes.len();
        let mut stack = vec![p];
        region[map.index(p)] = id;
        let mut size = 0usize;
        while let Some((x, y)) = stack.pop() {
            size += 1;
            for (dx, dy) in [(1i64, 0i64), (-1, 0), (0, 1), (0, -1)] {
                let (nx, ny) = (x as i64 + dx, y as i64 + dy);
                if !map.contains(nx, ny) {
                    continue;
                }
                let c = (nx as usize, ny as usize);
                if region[map.index(c)] == usize::MAX && map.is_clear(c, dmin) {
                    region[map.index(c)] = id;
                    stack.push(c);
                }
            }
        }
        sizes.push(size);
    }
    let biggest = (0..sizes.len()).max_by_key(|&i| sizes[i]).unwrap();
    let points: Vec<_> = points
        .into_iter()
        .filter(|&p| region[map.index(p)] == biggest)
        .collect();
    // A third of the region's extent (a real map's free space is often a small part of its
    // image, the rest unknown).
    let extent = |axis: fn(&(usize, usize)) -> usize| {
        let lo = points.iter().map(axis).min().unwrap_or(0);
        let hi = points.iter().map(axis).max().unwrap_or(0);
        (hi - lo) as f64 * g
    };
    let span = extent(|p| p.0).max(extent(|p| p.1)) / 3.0;
    let centre = |(x, y): (usize, usize)| (ox + (x as f64 + 0.5) * g, oy + (y as f64 + 0.5) * g);
    let mut rng = Lcg(seed);
    let mut out = Vec::new();
    let mut tries = 0;
    while out.len() < n {
        tries += 1;
        assert!(
            tries < 100_000,
            "no {n} pairs {span:.1} m apart on this map"
        );
        let a = centre(points[rng.next() as usize % points.len()]);
        let b = centre(points[rng.next() as usize % points.len()]);
        if libm::hypot(a.0 - b.0, a.1 - b.1) < span {
            continue;
        }
        let heading = |k: u64| (k % 8) as f64 * core::f64::consts::FRAC_PI_4;
        out.push((
            Pose::new(a.0, a.1, heading(rng.next())),
            Pose::new(b.0, b.1, heading(rng.next())),
        ));
    }
    out
}

fn drive_pairs(yaml: &str, n: usize, seed: u64) {
    let data = match data_dir() {
        Ok(data) => data,
        Err(why) => {
            eprintln!("SKIPPED no bump on {yaml}: {why}");
            return;
        }
    };
    let resolver = DirResolver::new(&data);
    let source = MapSource::Ros {
        yaml: yaml.to_owned(),
        unknown: UnknownSpec::Obstacle,
    };
    let map = source.load(&resolver).unwrap();
    let dmin = 0.5; // LocalPathPlanning's default.
    let mut bumps = Vec::new();
    let mut arrived = 0;
    for (i, (start, goal)) in pairs(&map, dmin, n, seed).into_iter().enumerate() {
        let spec = |p: Pose| PoseSpec {
            x: p.x,
            y: p.y,
            heading_deg: p.theta.to_degrees(),
        };
        let scenario = Scenario {
            name: format!("pair {i}"),
            description: String::new(),
            lesson: String::new(),
            map: source.clone(),
            start: spec(start),
            goal: spec(goal),
            direction: DirectionSpec::Forward,
            config: Default::default(),
            rates: Rates::default(),
            events: Vec::new(),
            time_limit: 600.0,
            expect: Expectation {
                outcome: OutcomeKind::Arrived,
                min_replans: 0,
                planner: None,
            },
            exercise: None,
        };
        let mut run = ScenarioRun::new(&scenario, &resolver).unwrap();
        run.run_to_end();
        let report = run.report();
        println!(
            "{yaml} pair {i}: {:?} in {:.1} s, min clearance {:.3} m, {} local plans",
            report.outcome.kind, report.sim_time, report.min_clearance, report.replans
        );
        if report.outcome.kind == OutcomeKind::Arrived {
            arrived += 1;
        }
        if report.bumps > 0 || report.min_clearance < report.body_radius {
            bumps.push(format!(
                "pair {i} {start:?} → {goal:?}: {:?}",
                report.outcome.reason
            ));
        }
    }
    println!("{yaml}: {arrived} of {n} arrived");
    assert!(bumps.is_empty(), "bumps: {bumps:#?}");
}

#[test]
fn twenty_drives_with_default_values_on_the_turtlebot_sandbox_never_bump() {
    drive_pairs("rosmaps/nav2_tb3_sandbox/tb3_sandbox.yaml", 20, 7);
}

#[test]
fn twenty_drives_with_default_values_on_willow_garage_never_bump() {
    drive_pairs(
        "rosmaps/turtlebot_willow_garage/willow-2010-02-18-0.10.yaml",
        20,
        11,
    );
}
