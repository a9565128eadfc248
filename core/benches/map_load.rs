//! Map loading (SPEC §2 formats): the two ROS map_server maps from bytes (YAML + PGM decode,
//! classification, `GridMap` with its distance transform), a MovingAI map, and rtnav JSON.
//!
//! `cargo bench -p rtnav --bench map_load -- --warm-up-time 1 --measurement-time 3`

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use rtnav::map::formats::ros::{self, RosLoadOptions};
use rtnav::map::formats::{json, movingai};

const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../shared/data");

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("map_load");
    g.sample_size(20);
    for (name, dir, yaml, image) in [
        (
            "ros/tb3_sandbox 384x384",
            "nav2_tb3_sandbox",
            "tb3_sandbox.yaml",
            "tb3_sandbox.pgm",
        ),
        (
            "ros/willow 566x608",
            "turtlebot_willow_garage",
            "willow-2010-02-18-0.10.yaml",
            "willow-2010-02-18-0.10.pgm",
        ),
    ] {
        let yaml = std::fs::read_to_string(format!("{DATA}/rosmaps/{dir}/{yaml}")).unwrap();
        let image = std::fs::read(format!("{DATA}/rosmaps/{dir}/{image}")).unwrap();
        let opts = RosLoadOptions::default();
        g.bench_function(name, |b| {
            b.iter(|| black_box(ros::load(&yaml, &image, &opts).unwrap()))
        });
    }
    let text = std::fs::read_to_string(format!("{DATA}/movingai/mazes/maze512-1-0.map")).unwrap();
    g.bench_function("movingai/maze512-1-0 512x512", |b| {
        b.iter(|| black_box(movingai::load_map(&text).unwrap()))
    });
    let map = movingai::load_map(&text).unwrap();
    let saved = json::to_string(&map);
    g.bench_function("json/load 512x512", |b| {
        b.iter(|| black_box(json::load(&saved).unwrap()))
    });
    g.bench_function("json/save 512x512", |b| {
        b.iter(|| black_box(json::to_string(&map)))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
