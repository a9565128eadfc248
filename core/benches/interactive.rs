//! The large-map rows (`docs/performance.md`): interactive planning on a map the size of
//! Nav2's warehouse (1006 × 1674 cells of 0.03 m, generated: `support/warehouse.rs`), each
//! with its baseline measured in the same run:
//!
//! | group | `rtnav` | baseline |
//! | --- | --- | --- |
//! | `edit` | a 5 × 5 brush across the route + distance update + global replan + local replan | `before`: the same with a fresh cell-by-cell A* and the reference field |
//! | `local_plan` | one default local plan (RouteRemakeDistance 10 m), positions every 4.5 m along the route, in turn | `reference`: the reference field for the same request |
//! | `full_field` | the full potential field on a 1000 × 1000 open map | `reference` |
//! | `route` | GlobalPathPlanning's planner, the 62 m route | `cellwise` (plain A*), `pathfinding` (`pathfinding::astar`) |
//!
//! `cargo bench -p rtnav --bench interactive`; `cargo xtask bench` runs it with the others
//! and prints the table.

#[path = "support/baseline.rs"]
mod baseline;
#[path = "support/warehouse.rs"]
mod warehouse;
#[path = "support/workloads.rs"]
mod workloads;

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use rtnav::global::AStar;
use rtnav::local::{PotentialField, reference};

fn settings<'a>(
    c: &'a mut Criterion,
    name: &str,
) -> criterion::BenchmarkGroup<'a, criterion::measurement::WallTime> {
    let mut g = c.benchmark_group(name);
    g.sample_size(10);
    g.warm_up_time(Duration::from_millis(500));
    g.measurement_time(Duration::from_secs(3));
    g
}

fn edit(c: &mut Criterion) {
    let mut edit = workloads::Edit::new();
    let mut g = settings(c, "edit");
    g.bench_function("rtnav", |b| b.iter(|| black_box(edit.step())));
    g.bench_function("before", |b| b.iter(|| black_box(edit.step_reference())));
    g.finish();
}

fn local_plan(c: &mut Criterion) {
    let mut plans = workloads::LocalPlans::new();
    let mut g = settings(c, "local_plan");
    g.bench_function("rtnav", |b| b.iter(|| black_box(plans.step())));
    g.bench_function("reference", |b| {
        b.iter(|| black_box(plans.step_reference()))
    });
    g.finish();
}

fn full_field(c: &mut Criterion) {
    let (map, request) = workloads::open_field();
    let mut field = PotentialField::new();
    let mut g = settings(c, "full_field");
    g.bench_function("rtnav", |b| {
        b.iter(|| black_box(workloads::full_field(&mut field, &map, &request)))
    });
    g.bench_function("reference", |b| {
        b.iter(|| {
            black_box(
                reference::compute(&map, &request)
                    .expect("a field")
                    .finalized,
            )
        })
    });
    g.finish();
}

fn route(c: &mut Criterion) {
    let map = warehouse::map();
    let mut astar = AStar::new(&map, workloads::DMIN).expect("a planner");
    let (s, t) = (warehouse::LONG_START, warehouse::LONG_GOAL);
    let mut g = settings(c, "route");
    g.bench_function("rtnav", |b| {
        b.iter(|| black_box(astar.plan(s, t).expect("a route").length_cells()))
    });
    g.bench_function("cellwise", |b| {
        b.iter(|| black_box(astar.plan_cellwise(s, t).expect("a route").length_cells()))
    });
    let grid = astar.clone();
    g.bench_function("pathfinding", |b| {
        b.iter(|| black_box(baseline::pathfinding_astar(&grid, s, t)))
    });
    g.finish();
}

criterion_group!(benches, edit, local_plan, full_field, route);
criterion_main!(benches);
