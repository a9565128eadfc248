//! LocalPathPlanning benchmarks (spec §3 steps 3–7): the potential field and the local path
//! on a 1000 × 1000 map of 0.05 m cells with some obstacles, default parameters (000 §4.2:
//! RouteRemakeDistance 10 m, dmin 0.5 m, PostureConsiderationLevel 85 %).
//!
//! Also the willow garage ROS map (`rosmaps/` of the external data: `$RTNAV_DATA`, else
//! `../shared/data`; 566 × 608 at 0.10 m): a real building, with the held path from
//! GlobalPathPlanning's A*. Without the data that group is skipped, with a line saying so.
//!
//! Run: `cargo bench -p rtnav --bench local`. Goal: field + path ≤ 20 ms natively.

use std::io::Write as _;

use criterion::{Criterion, criterion_group, criterion_main};
use rtnav::global::AStar;
use rtnav::interfaces::{Direction, Pose};
use rtnav::local::{FieldExtent, LocalPlanner, PlanParams, PlanRequest};
use rtnav::map::formats::ros::{self, RosLoadOptions};
use rtnav::map::{Cell, GridMap};

const N: usize = 1000;
const G: f64 = 0.05;

/// A 1000 × 1000 map with 60 rectangular obstacles (a fixed LCG), kept out of the corridor
/// y ∈ [450, 550] where the held path runs, plus a wall across the corridor's upper half
/// at x = 500 so the path has to bend near it.
fn bench_map() -> GridMap {
    let mut cells = vec![0u8; N * N];
    let mut seed: u64 = 0x2545_f491_4f6c_dd1d;
    let mut next = |m: usize| {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((seed >> 33) as usize) % m
    };
    for _ in 0..60 {
        let (x0, y0, w, h) = (next(N), next(N), 5 + next(60), 5 + next(60));
        for y in y0..(y0 + h).min(N) {
            if (430..570).contains(&y) {
                continue;
            }
            for x in x0..(x0 + w).min(N) {
                cells[x + y * N] = 1;
            }
        }
    }
    for y in 520..560 {
        for x in 500..505 {
            cells[x + y * N] = 1;
        }
    }
    GridMap::new(N, N, G, (0.0, 0.0), cells).expect("valid map")
}

fn held_path() -> Vec<Cell> {
    (100..=900).map(|x| (x, 480)).collect()
}

fn request<'a>(path: &'a [Cell], heading: f64, extent: FieldExtent) -> PlanRequest<'a> {
    let (sx, sy) = ((100.0 + 0.5) * G, (480.0 + 0.5) * G);
    PlanRequest {
        held_path: path,
        match_from: 0,
        current: Pose::new(sx, sy, heading),
        goal: Pose::new((900.0 + 0.5) * G, sy, 0.0),
        direction: Direction::Forward,
        params: PlanParams::default(),
        extent,
    }
}

fn bench(c: &mut Criterion) {
    let map = bench_map();
    let path = held_path();
    let mut planner = LocalPlanner::new();
    let mut group = c.benchmark_group("local_1000x1000");
    group.sample_size(10);
    group.measurement_time(std::time::Duration::from_secs(3));
    for (name, heading, extent) in [
        ("field_path_aligned", 0.0, FieldExtent::UntilCurrent),
        (
            "field_path_heading_90deg",
            core::f64::consts::FRAC_PI_2,
            FieldExtent::UntilCurrent,
        ),
        ("full_field_path_aligned", 0.0, FieldExtent::Full),
    ] {
        let req = request(&path, heading, extent);
        group.bench_function(name, |b| {
            b.iter(|| planner.plan(&map, &req).expect("a plan"));
        });
    }
    group.finish();
}

/// The willow garage map with the start and goal of `fixtures/scenarios/willow_garage.json`.
fn bench_willow(c: &mut Criterion) {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let data = match rtnav::data::data_dir(&root) {
        Ok(dir) => dir,
        Err(why) => {
            let _ = writeln!(std::io::stderr(), "SKIPPED local_willow_garage: {why}");
            return;
        }
    };
    let yaml = data.join("rosmaps/turtlebot_willow_garage/willow-2010-02-18-0.10.yaml");
    let map = ros::load_file(yaml, &RosLoadOptions::default())
        .expect("the willow garage map loads")
        .map;
    let params = PlanParams::default();
    let (start, goal) = (
        Pose::new(36.25, 7.95, core::f64::consts::FRAC_PI_2),
        Pose::new(26.05, 5.65, core::f64::consts::PI),
    );
    let cell = |p: &Pose| map.world_to_cell(p.x, p.y).expect("inside the map");
    let path = AStar::new(&map, params.dmin)
        .expect("A* on the map")
        .plan(cell(&start), cell(&goal))
        .expect("a global path")
        .cells;
    let mut planner = LocalPlanner::new();
    let mut group = c.benchmark_group("local_willow_garage");
    group.sample_size(10);
    group.measurement_time(std::time::Duration::from_secs(3));
    for (name, extent) in [
        ("field_path", FieldExtent::UntilCurrent),
        ("full_field_path", FieldExtent::Full),
    ] {
        let req = PlanRequest {
            held_path: &path,
            match_from: 0,
            current: start,
            goal,
            direction: Direction::Forward,
            params,
            extent,
        };
        group.bench_function(name, |b| {
            b.iter(|| planner.plan(&map, &req).expect("a plan"));
        });
    }
    group.finish();
}

criterion_group!(benches, bench, bench_willow);
criterion_main!(benches);
