//! The exact Euclidean distance transform (spec §2) on a 1000 × 1000 map: building a map
//! (validation + full transform), a `MapUpdate` touching many columns (full recompute), and
//! a one-cell `MapUpdate` (incremental: one column and the rows it changed).
//!
//! `cargo bench -p rtnav --bench distance -- --warm-up-time 1 --measurement-time 3`

use criterion::{Criterion, criterion_group, criterion_main};
use rtnav::map::{GridMap, MapUpdate};
use rtnav::rtc::Time;
use std::hint::black_box;

const SIDE: usize = 1000;

/// A deterministic map with about `percent` % obstacle cells, in clumps of 4 × 4.
fn map(percent: u64) -> GridMap {
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut cells = vec![0u8; SIDE * SIDE];
    let clumps = SIDE * SIDE * percent as usize / 100 / 16;
    for _ in 0..clumps {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        let (x, y) = (
            (seed >> 20) as usize % (SIDE - 4),
            (seed >> 40) as usize % (SIDE - 4),
        );
        for dy in 0..4 {
            for dx in 0..4 {
                cells[x + dx + (y + dy) * SIDE] = 1;
            }
        }
    }
    GridMap::new(SIDE, SIDE, 0.05, (0.0, 0.0), cells).unwrap()
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("distance_1000x1000");
    g.sample_size(20);
    for percent in [0, 10, 40] {
        let base = map(percent);
        g.bench_function(format!("GridMap::new/{percent}%"), |b| {
            b.iter_batched(
                || base.cells().to_vec(),
                |cells| black_box(GridMap::new(SIDE, SIDE, 0.05, (0.0, 0.0), cells).unwrap()),
                criterion::BatchSize::LargeInput,
            )
        });
    }
    let mut m = map(10);
    // Every 4th column of one row flips: more than 1/8 of the columns, full recompute.
    let xs: Vec<i32> = (0..SIDE as i32).step_by(4).collect();
    let ys = vec![500; xs.len()];
    let mut flip = 0i16;
    g.bench_function("map_update_full/250 cells", |b| {
        b.iter(|| {
            flip = 1 - flip;
            let vs = vec![flip; xs.len()];
            black_box(
                m.map_update(&MapUpdate {
                    x: xs.to_vec(),
                    y: ys.to_vec(),
                    value: vs.to_vec(),
                    num: xs.len() as i32,
                    tm: Time::default(),
                })
                .unwrap(),
            )
        })
    });
    let mut m = map(10);
    let mut flip = 0i16;
    g.bench_function("map_update_incremental/1 cell", |b| {
        b.iter(|| {
            flip = 1 - flip;
            black_box(
                m.map_update(&MapUpdate {
                    x: vec![321],
                    y: vec![654],
                    value: vec![flip],
                    num: 1,
                    tm: Time::default(),
                })
                .unwrap(),
            )
        })
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
