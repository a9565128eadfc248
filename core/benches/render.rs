//! Render time of a 1280 × 800 frame (the browser canvas) of a 1000 × 1000 map with a
//! potential field: the first frame (every layer drawn), a frame after a new field (heat map
//! recoloured, background recomposed: what happens at each 10 Hz replan), a cached frame
//! (background copied, moving things drawn: every animation frame) and a frame after a
//! `MapUpdate` of a 5 × 5 brush (painted and erased in turn; the update's own time included).
//!
//! `cargo bench -p rtnav --bench render`

use std::hint::black_box;
use std::time::Duration;

use criterion::{Criterion, criterion_group, criterion_main};
use rtnav::interfaces::Pose;
use rtnav::map::{GridMap, MapUpdate};
use rtnav::render::{FieldCellState, FieldView, Renderer, RobotView, Scene};
use rtnav::rtc::Time;

const N: usize = 1000;
const G: f64 = 0.05;
const DMIN: f64 = 0.5;

struct Data {
    map: GridMap,
    potential: Vec<f64>,
    state: Vec<FieldCellState>,
    global: Vec<(usize, usize)>,
    control: Vec<(f64, f64)>,
    trail: Vec<(f64, f64)>,
}

/// A 50 m × 50 m map: walls, a grid of pillars and a long wall; a field around a target
/// (straight distance plus repulsion), reached within 30 m.
fn data() -> Data {
    let mut cells = vec![0u8; N * N];
    for y in 0..N {
        for x in 0..N {
            let border = x == 0 || y == 0 || x == N - 1 || y == N - 1;
            let pillar = (x / 50) % 3 == 1 && (y / 50) % 3 == 1;
            let wall = x == 500 && y < 800;
            if border || pillar || wall {
                cells[x + y * N] = 1;
            }
        }
    }
    let map = GridMap::new(N, N, G, (0.0, 0.0), cells).unwrap();
    let target = (700.0, 300.0);
    let mut potential = vec![0.0; N * N];
    let mut state = vec![FieldCellState::Unreached; N * N];
    for y in 0..N {
        for x in 0..N {
            let i = x + y * N;
            let d = map.distances()[i];
            if d <= DMIN {
                state[i] = FieldCellState::Impassable;
                continue;
            }
            let (dx, dy) = ((x as f64 - target.0) * G, (y as f64 - target.1) * G);
            let l = (dx * dx + dy * dy).sqrt();
            if l < 30.0 {
                state[i] = FieldCellState::Reached;
                potential[i] = 0.1 + l + 1.0 / ((d - DMIN) * (d - DMIN));
            }
        }
    }
    let global: Vec<(usize, usize)> = (0..1200).map(|i| (100 + i * 3 / 4, 100 + i / 2)).collect();
    // A control point every fourth cell of the local path, as a staircase path gives.
    let control = global[..400]
        .iter()
        .step_by(4)
        .map(|&(x, y)| ((x as f64 + 0.5) * G, (y as f64 + 0.5) * G))
        .collect();
    let trail = (0..5000)
        .map(|i| (5.0 + i as f64 * 0.002, 5.0 + i as f64 * 0.001))
        .collect();
    Data {
        map,
        potential,
        state,
        global,
        control,
        trail,
    }
}

fn scene(d: &Data, field_key: u64) -> Scene<'_> {
    Scene {
        dmin: DMIN,
        field: Some(FieldView {
            potential: &d.potential,
            state: &d.state,
            key: field_key,
        }),
        global_path: &d.global,
        local_path: &d.global[..400],
        control_points: &d.control,
        local_target: Some(Pose::new(20.0, 12.0, 0.5)),
        robot: Some(RobotView::with_defaults(Pose::new(15.0, 10.0, 0.3))),
        trail: &d.trail,
        start: Some(Pose::new(5.0, 5.0, 0.0)),
        goal: Some(Pose::new(40.0, 35.0, 1.0)),
        caption: "t = 12.30 s",
        ..Scene::new(&d.map, 1)
    }
}

fn bench(c: &mut Criterion) {
    let d = data();
    let mut group = c.benchmark_group("render_1280x800_map1000");
    group.sample_size(10);
    group.warm_up_time(Duration::from_secs(1));
    group.measurement_time(Duration::from_secs(3));

    let mut renderer = Renderer::new(1280, 800).unwrap();
    group.bench_function("first_frame", |b| {
        b.iter(|| {
            renderer.invalidate();
            black_box(renderer.render(&scene(&d, 1)).unwrap().data()[0])
        })
    });
    let mut key = 1;
    group.bench_function("new_field", |b| {
        b.iter(|| {
            key += 1;
            black_box(renderer.render(&scene(&d, key)).unwrap().data()[0])
        })
    });
    renderer.render(&scene(&d, 1)).unwrap();
    group.bench_function("cached_frame", |b| {
        b.iter(|| black_box(renderer.render(&scene(&d, 1)).unwrap().data()[0]))
    });
    let mut map = d.map.clone();
    let mut edits = 0u32;
    group.bench_function("map_update", |b| {
        b.iter(|| {
            edits += 1;
            let value = i16::from(edits % 2 == 1);
            let brush: Vec<(i64, i64, i16)> =
                (0..25).map(|k| (300 + k % 5, 600 + k / 5, value)).collect();
            let at = Time {
                sec: edits,
                nsec: 0,
            };
            map.map_update(&MapUpdate::from_cells(&brush, at)).unwrap();
            let edited = Scene {
                map: &map,
                map_key: u64::from(edits) + 1,
                ..scene(&d, 1)
            };
            black_box(renderer.render(&edited).unwrap().data()[0])
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
