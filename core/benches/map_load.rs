//! Map loading (spec §2 formats): the two ROS map_server maps from bytes (YAML + PGM decode,
//! classification, `GridMap` with its distance transform), a MovingAI map, and rtnav JSON.
//! The ROS and MovingAI maps are external data (`$RTNAV_DATA`, else `../shared/data`): without
//! it their benchmarks are skipped, with a line saying so, and the JSON ones use the
//! repository's largest scenario map instead of the MovingAI maze.
//!
//! `cargo bench -p rtnav --bench map_load -- --warm-up-time 1 --measurement-time 3`

use std::hint::black_box;
use std::io::Write as _;
use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use rtnav::map::formats::ros::{self, RosLoadOptions};
use rtnav::map::formats::{json, movingai};

fn bench(c: &mut Criterion) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut g = c.benchmark_group("map_load");
    g.sample_size(20);
    let data = match rtnav::data::data_dir(&root) {
        Ok(dir) => dir,
        Err(why) => {
            let _ = writeln!(
                std::io::stderr(),
                "SKIPPED map_load/ros, map_load/movingai: {why}"
            );
            let name = "appearing_obstacle";
            let text =
                std::fs::read_to_string(root.join(format!("fixtures/maps/scenarios/{name}.json")))
                    .unwrap();
            let map = json::load(&text).unwrap();
            bench_json(
                &mut g,
                &map,
                &format!("{name} {}x{}", map.width(), map.height()),
            );
            g.finish();
            return;
        }
    };
    let data = data.to_string_lossy();
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
        let yaml = std::fs::read_to_string(format!("{data}/rosmaps/{dir}/{yaml}")).unwrap();
        let image = std::fs::read(format!("{data}/rosmaps/{dir}/{image}")).unwrap();
        let opts = RosLoadOptions::default();
        g.bench_function(name, |b| {
            b.iter(|| black_box(ros::load(&yaml, &image, &opts).unwrap()))
        });
    }
    let text = std::fs::read_to_string(format!("{data}/movingai/mazes/maze512-1-0.map")).unwrap();
    g.bench_function("movingai/maze512-1-0 512x512", |b| {
        b.iter(|| black_box(movingai::load_map(&text).unwrap()))
    });
    let map = movingai::load_map(&text).unwrap();
    bench_json(&mut g, &map, "512x512");
    g.finish();
}

/// rtnav JSON: `map` written, then read back.
fn bench_json(
    g: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    map: &rtnav::map::GridMap,
    what: &str,
) {
    let saved = json::to_string(map);
    g.bench_function(format!("json/load {what}"), |b| {
        b.iter(|| black_box(json::load(&saved).unwrap()))
    });
    g.bench_function(format!("json/save {what}"), |b| {
        b.iter(|| black_box(json::to_string(map)))
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
