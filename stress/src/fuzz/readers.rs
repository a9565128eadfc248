//! Fuzz targets for every reader of outside text or bytes that does not need a running
//! system: the rtnav JSON map, the ROS map (YAML + PGM/PNG) and its YAML alone, MovingAI
//! `.map` and `.scen`, OpenRTM `.conf` (parsed and applied to real configurations),
//! scenario JSON and replay files.
//!
//! **Allocation bounds** (spec §2 Decision 0.2: a reader checks the size it is told before it
//! allocates): a text reader allocates in proportion to its input —
//! [`BASE`] + [`PER_BYTE`] × input bytes; a ROS image may decode to more than its file (PNG
//! is compressed), but never more than the size its header claims once checked against the
//! map limit — [`BASE`] + [`PER_BYTE`] × input bytes + [`PER_PIXEL`] × the pixels the header
//! claims (0 when it claims more than `MAX_CELLS`, which must be refused before decoding).
//! A map_server YAML costs up to [`PER_YAML_BYTE`] a byte (its parser's state), and one over
//! `ros::MAX_YAML_BYTES` is refused before it is parsed.

use std::path::Path;

use rtnav::components::{DriveControlParams, LocalPathPlanningParams, MotorControlParams};
use rtnav::map::MAX_CELLS;
use rtnav::map::formats::{json, movingai, ros};
use rtnav::rtc::{ConfFile, ConfigAccess, Configuration, ParameterSet};
use rtnav::system::{Replay, Scenario};

use super::{Bytes, Case, INTERESTING_NUMBERS, Target};
use crate::rng::Rng;

/// What any input may allocate besides its share per byte \[bytes\].
pub const BASE: u64 = 256 * 1024;
/// Allocation per input byte allowed to a text reader \[bytes\].
pub const PER_BYTE: u64 = 64;
/// Allocation per claimed pixel allowed to the image reader (a 16-bit RGBA pixel decoded, a
/// copy converted, the classes, the cells, the obstacle distances) \[bytes\].
pub const PER_PIXEL: u64 = 48;

/// Allocation per byte of a map_server YAML allowed to its reader \[bytes\]: the YAML parser
/// keeps about 90 bytes of state per byte of input at worst (collections left open), and the
/// reader refuses a file over [`ros::MAX_YAML_BYTES`] before parsing it.
pub const PER_YAML_BYTE: u64 = 128;

fn text_bound(case: &Case) -> u64 {
    BASE + PER_BYTE * case.len() as u64
}

/// The bound of a map_server YAML of `len` bytes.
fn yaml_bound(len: usize) -> u64 {
    BASE + PER_YAML_BYTE * len.min(ros::MAX_YAML_BYTES) as u64
}

fn read(path: &Path) -> Option<Vec<u8>> {
    std::fs::read(path).ok()
}

/// Every reader target. Fixture inputs come from `root` (the project's root); the shared
/// data at `data`, where present, adds real files.
pub fn targets(root: &Path, data: Option<&Path>) -> Vec<Box<dyn Target>> {
    let fixtures = root.join("fixtures");
    let mut json_seeds = Vec::new();
    for dir in [fixtures.join("maps"), fixtures.join("maps/scenarios")] {
        let mut files: Vec<_> = std::fs::read_dir(&dir)
            .into_iter()
            .flatten()
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|e| e == "json"))
            .collect();
        files.sort();
        json_seeds.extend(files.iter().filter_map(|p| read(p)).map(Case::one));
    }
    let mut yaml_seeds = Vec::new();
    let mut ros_seeds = Vec::new();
    if let (Some(y), Some(i)) = (
        read(&fixtures.join("maps/tiny.yaml")),
        read(&fixtures.join("maps/tiny.pgm")),
    ) {
        yaml_seeds.push(Case::one(y.clone()));
        ros_seeds.push(Case { parts: vec![y, i] });
    }
    let tiny_yaml = yaml_seeds
        .first()
        .map(|c| c.part(0).to_vec())
        .unwrap_or_else(|| YAML.as_bytes().to_vec());
    for image in sample_images() {
        ros_seeds.push(Case {
            parts: vec![tiny_yaml.clone(), image],
        });
    }
    let mut map_seeds = vec![Case::one(SMALL_MAP)];
    let mut scen_seeds = vec![Case::one(SMALL_SCEN)];
    if let Some(data) = data {
        let sandbox = data.join("rosmaps/nav2_tb3_sandbox");
        if let (Some(y), Some(i)) = (
            read(&sandbox.join("tb3_sandbox.yaml")),
            read(&sandbox.join("tb3_sandbox.pgm")),
        ) {
            yaml_seeds.push(Case::one(y.clone()));
            ros_seeds.push(Case { parts: vec![y, i] });
        }
        if let Some(y) =
            read(&data.join("rosmaps/turtlebot_willow_garage/willow-2010-02-18-0.10.yaml"))
        {
            yaml_seeds.push(Case::one(y));
        }
        if let Some(m) = read(&data.join("movingai/dao/arena.map")) {
            map_seeds.push(Case::one(m));
        }
        if let Some(s) = read(&data.join("movingai/dao/arena.map.scen")) {
            scen_seeds.push(Case::one(s));
        }
    }
    let mut conf_seeds: Vec<Case> = read(&fixtures.join("conf/LocalPathPlanning.conf"))
        .into_iter()
        .map(Case::one)
        .collect();
    conf_seeds.push(Case::one(
        Configuration::<MotorControlParams>::new().to_conf(),
    ));
    let mut scenario_seeds = Vec::new();
    let mut files: Vec<_> = std::fs::read_dir(fixtures.join("scenarios"))
        .into_iter()
        .flatten()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    scenario_seeds.extend(files.iter().filter_map(|p| read(p)).map(Case::one));
    let mut replay_files: Vec<_> = std::fs::read_dir(fixtures.join("replays"))
        .into_iter()
        .flatten()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.to_string_lossy().ends_with(".rtnav.json"))
        .collect();
    replay_files.sort();
    let replay_seeds = replay_files
        .iter()
        .filter_map(|p| read(p))
        .map(Case::one)
        .collect();
    vec![
        Box::new(JsonMap { seeds: json_seeds }),
        Box::new(RosMap {
            seeds: ros_seeds,
            large: vec![white_png(2048, 1024), white_png(4097, 4096)],
        }),
        Box::new(RosYaml { seeds: yaml_seeds }),
        Box::new(MovingaiMap { seeds: map_seeds }),
        Box::new(MovingaiScen { seeds: scen_seeds }),
        Box::new(Conf { seeds: conf_seeds }),
        Box::new(ScenarioJson {
            seeds: scenario_seeds,
        }),
        Box::new(ReplayJson {
            seeds: replay_seeds,
        }),
    ]
}

fn number(b: &mut Bytes<'_>, plausible: impl FnOnce(&mut Bytes<'_>) -> String) -> String {
    if b.u8() < 40 {
        INTERESTING_NUMBERS[b.below(INTERESTING_NUMBERS.len())].to_owned()
    } else {
        plausible(b)
    }
}

fn random_bytes(rng: &mut Rng, max: usize) -> Vec<u8> {
    let n = rng.index(max + 1);
    (0..n).map(|_| rng.next_u64() as u8).collect()
}

// ------------------------------------------------------------------ rtnav JSON map

struct JsonMap {
    seeds: Vec<Case>,
}

impl Target for JsonMap {
    fn name(&self) -> &'static str {
        "json-map"
    }

    fn seeds(&self) -> &[Case] {
        &self.seeds
    }

    fn generate(&self, rng: &mut Rng) -> Case {
        let raw = random_bytes(rng, 64);
        let mut b = Bytes::new(&raw);
        let w = number(&mut b, |b| (1 + b.below(24)).to_string());
        let h = number(&mut b, |b| (1 + b.below(24)).to_string());
        let g = number(&mut b, |b| format!("{}", 0.05 + b.below(20) as f64 * 0.05));
        let (wn, hn) = (
            w.parse::<usize>().unwrap_or(3).min(64),
            h.parse::<usize>().unwrap_or(3).min(64),
        );
        let body = if rng.chance(0.7) {
            let rows: Vec<String> = (0..hn + usize::from(rng.chance(0.1)))
                .map(|_| {
                    let n = if rng.chance(0.1) {
                        rng.index(wn + 3)
                    } else {
                        wn
                    };
                    (0..n)
                        .map(|_| *rng.pick(&['.', '.', '.', '#', '#', 'x', 'é']))
                        .collect()
                })
                .collect();
            format!(
                r#""rows": {}"#,
                serde_json::to_string(&rows).unwrap_or_default()
            )
        } else {
            let n = if rng.chance(0.8) {
                wn * hn
            } else {
                rng.index(wn * hn + 4)
            };
            let cells: Vec<String> = (0..n)
                .map(|_| rng.pick(&["0", "0", "1", "2", "-1", "256"]).to_string())
                .collect();
            format!(r#""cells": [{}]"#, cells.join(","))
        };
        let origin = if rng.chance(0.5) {
            format!(
                r#", "origin": [{}, {}]"#,
                rng.pick(INTERESTING_NUMBERS),
                rng.pick(&["0", "-1.5", "1e308", "NaN"])
            )
        } else {
            String::new()
        };
        Case::one(format!(
            r#"{{"width": {w}, "height": {h}, "grid_size": {g}{origin}, {body}}}"#
        ))
    }

    fn run(&mut self, case: &Case) -> Result<(), String> {
        if let Ok(map) = json::load(&case.text(0)) {
            let back = json::load(&json::to_string(&map))
                .map_err(|e| format!("a map read could not be read back: {e}"))?;
            if back != map {
                return Err("a map read back differs".to_owned());
            }
        }
        Ok(())
    }

    fn alloc_bound(&self, case: &Case) -> u64 {
        // The read-back doubles what a valid map allocates.
        2 * text_bound(case)
    }

    fn fail_at(&self, _part: usize, bytes: &[u8]) -> Option<usize> {
        super::json_fail_at(bytes)
    }
}

// ------------------------------------------------------------------ ROS map

const YAML: &str = "image: m.pgm\nresolution: 0.25\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n\
                    occupied_thresh: 0.65\nfree_thresh: 0.196\n";

/// Small valid images of every colour type the reader handles: PGM (ASCII and binary,
/// 8 and 16 bits), PNG (grey, grey + alpha, RGB, RGBA, 16-bit grey, palette).
fn sample_images() -> Vec<Vec<u8>> {
    let mut out = vec![
        b"P2\n3 2\n255\n0 128 255\n205 254 1\n".to_vec(),
        [&b"P5\n4 2\n255\n"[..], &[0, 50, 205, 254, 255, 1, 128, 0]].concat(),
        [&b"P5\n2 2\n65535\n"[..], &[0, 0, 255, 255, 128, 0, 0, 1]].concat(),
    ];
    let shapes: [(png::ColorType, png::BitDepth, usize); 6] = [
        (png::ColorType::Grayscale, png::BitDepth::Eight, 1),
        (png::ColorType::GrayscaleAlpha, png::BitDepth::Eight, 2),
        (png::ColorType::Rgb, png::BitDepth::Eight, 3),
        (png::ColorType::Rgba, png::BitDepth::Eight, 4),
        (png::ColorType::Grayscale, png::BitDepth::Sixteen, 2),
        (png::ColorType::Indexed, png::BitDepth::Eight, 1),
    ];
    for (color, depth, bytes_per_pixel) in shapes {
        let (w, h) = (5u32, 3u32);
        let pixels: Vec<u8> = (0..(w * h) as usize * bytes_per_pixel)
            .map(|i| (i * 37 % 256) as u8)
            .collect();
        if let Some(png) = encode_png(w, h, color, depth, &pixels) {
            out.push(png);
        }
    }
    out
}

/// A PNG of `pixels` (`None` if the encoder refuses).
pub fn encode_png(
    w: u32,
    h: u32,
    color: png::ColorType,
    depth: png::BitDepth,
    pixels: &[u8],
) -> Option<Vec<u8>> {
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, w, h);
    encoder.set_color(color);
    encoder.set_depth(depth);
    if color == png::ColorType::Indexed {
        encoder.set_palette((0..=255u8).flat_map(|v| [v, v, v]).collect::<Vec<u8>>());
    }
    let mut writer = encoder.write_header().ok()?;
    writer.write_image_data(pixels).ok()?;
    writer.finish().ok()?;
    Some(out)
}

/// The pixels an image's header claims, if it can be read (PNG's IHDR, a PNM header).
fn claimed_pixels(image: &[u8]) -> u64 {
    let reader = image::ImageReader::new(std::io::Cursor::new(image)).with_guessed_format();
    match reader.ok().and_then(|r| r.into_dimensions().ok()) {
        Some((w, h)) => {
            let n = u64::from(w) * u64::from(h);
            if n <= MAX_CELLS as u64 { n } else { 0 }
        }
        None => 0,
    }
}

struct RosMap {
    seeds: Vec<Case>,
    /// Large valid PNGs (made once): 2048 × 1024, and 4097 × 4096 (over the limit).
    large: Vec<Vec<u8>>,
}

/// A white 8-bit grey PNG of `w × h` pixels.
fn white_png(w: u32, h: u32) -> Vec<u8> {
    let pixels = vec![255u8; (w * h) as usize];
    encode_png(
        w,
        h,
        png::ColorType::Grayscale,
        png::BitDepth::Eight,
        &pixels,
    )
    .unwrap_or_default()
}

impl Target for RosMap {
    fn name(&self) -> &'static str {
        "ros-map"
    }

    fn seeds(&self) -> &[Case] {
        &self.seeds
    }

    fn generate(&self, rng: &mut Rng) -> Case {
        let raw = random_bytes(rng, 64);
        let mut b = Bytes::new(&raw);
        let yaml = if rng.chance(0.8) {
            YAML.to_owned()
        } else {
            format!(
                "image: m.pgm\nresolution: {}\norigin: [{}, 0, 0]\nnegate: {}\n\
                 occupied_thresh: {}\nfree_thresh: {}\nmode: {}\n",
                number(&mut b, |_| "0.1".into()),
                number(&mut b, |_| "-3".into()),
                rng.pick(&["0", "1", "true", "2", "x"]),
                rng.pick(&["0.65", "1", "0", "1.5", "NaN"]),
                rng.pick(&["0.196", "0", "0.7", "-1"]),
                rng.pick(&["trinary", "scale", "raw", "other"]),
            )
        };
        // Header numbers small or hostile; pixel data of the claimed size or not.
        let w = number(&mut b, |b| (1 + b.below(16)).to_string());
        let h = number(&mut b, |b| (1 + b.below(16)).to_string());
        let (wn, hn) = (
            w.parse::<usize>().unwrap_or(2).min(64),
            h.parse::<usize>().unwrap_or(2).min(64),
        );
        let n = if rng.chance(0.8) {
            wn * hn
        } else {
            rng.index(wn * hn + 8)
        };
        let image = match rng.below(4) {
            0 => {
                let max = rng.pick(&["255", "65535", "1", "0", "70000"]);
                let data: Vec<String> = (0..n).map(|_| rng.below(256).to_string()).collect();
                format!("P2\n{w} {h}\n{max}\n{}\n", data.join(" ")).into_bytes()
            }
            1 => {
                let mut v = format!("P5\n{w} {h}\n255\n").into_bytes();
                v.extend((0..n).map(|_| rng.next_u64() as u8));
                v
            }
            2 => {
                let (color, depth, bpp) = *rng.pick(&[
                    (png::ColorType::Grayscale, png::BitDepth::Eight, 1),
                    (png::ColorType::Rgba, png::BitDepth::Eight, 4),
                    (png::ColorType::GrayscaleAlpha, png::BitDepth::Sixteen, 4),
                    (png::ColorType::Rgb, png::BitDepth::Sixteen, 6),
                ]);
                let (pw, ph) = (1 + rng.below(24) as u32, 1 + rng.below(24) as u32);
                let pixels: Vec<u8> = (0..(pw * ph) as usize * bpp)
                    .map(|_| rng.next_u64() as u8)
                    .collect();
                encode_png(pw, ph, color, depth, &pixels).unwrap_or_default()
            }
            _ => {
                // A valid PNG of 2 Mi pixels, or one just over the map limit (both compressed
                // to a few kilobytes): the size check decides before the decoder allocates.
                rng.pick(&self.large).clone()
            }
        };
        Case {
            parts: vec![yaml.into_bytes(), image],
        }
    }

    fn run(&mut self, case: &Case) -> Result<(), String> {
        if let Ok(r) = ros::load(&case.text(0), case.part(1), &ros::RosLoadOptions::default()) {
            let cells = r.map.width() * r.map.height();
            if r.free + r.occupied + r.unknown != cells {
                return Err(format!(
                    "free {} + occupied {} + unknown {} ≠ {cells} cells",
                    r.free, r.occupied, r.unknown
                ));
            }
        }
        Ok(())
    }

    fn alloc_bound(&self, case: &Case) -> u64 {
        yaml_bound(case.part(0).len())
            + PER_BYTE * case.part(1).len() as u64
            + PER_PIXEL * claimed_pixels(case.part(1))
    }
}

struct RosYaml {
    seeds: Vec<Case>,
}

impl Target for RosYaml {
    fn name(&self) -> &'static str {
        "ros-yaml"
    }

    fn seeds(&self) -> &[Case] {
        &self.seeds
    }

    fn generate(&self, rng: &mut Rng) -> Case {
        let keys = [
            "image",
            "resolution",
            "origin",
            "negate",
            "occupied_thresh",
            "free_thresh",
            "mode",
            "unknown_key",
        ];
        let mut text = String::new();
        for _ in 0..rng.below(10) {
            let key = rng.pick(&keys);
            let value = match rng.below(5) {
                0 => format!("[{}, {}, {}]", rng.pick(INTERESTING_NUMBERS), 0, 0),
                1 => rng.pick(INTERESTING_NUMBERS).to_string(),
                2 => "&a [*a, *a]".to_owned(),
                3 => "{a: [1, [2, [3]]]}".to_owned(),
                _ => "m.pgm".to_owned(),
            };
            text.push_str(&format!("{key}: {value}\n"));
        }
        Case::one(text)
    }

    fn run(&mut self, case: &Case) -> Result<(), String> {
        let _ = ros::parse_yaml(&case.text(0));
        Ok(())
    }

    fn alloc_bound(&self, case: &Case) -> u64 {
        yaml_bound(case.len())
    }
}

// ------------------------------------------------------------------ MovingAI

const SMALL_MAP: &str = "type octile\nheight 4\nwidth 5\nmap\n.....\n.@@T.\n..W..\nGS.O.\n";
const SMALL_SCEN: &str = "version 1\n0\tm.map\t5\t4\t0\t0\t4\t3\t5.24264069\n\
                          1 m.map 5 4 4 0 0 3 5.2\n";

struct MovingaiMap {
    seeds: Vec<Case>,
}

impl Target for MovingaiMap {
    fn name(&self) -> &'static str {
        "movingai-map"
    }

    fn seeds(&self) -> &[Case] {
        &self.seeds
    }

    fn generate(&self, rng: &mut Rng) -> Case {
        let raw = random_bytes(rng, 32);
        let mut b = Bytes::new(&raw);
        let w = number(&mut b, |b| (1 + b.below(20)).to_string());
        let h = number(&mut b, |b| (1 + b.below(20)).to_string());
        let (wn, hn) = (
            w.parse::<usize>().unwrap_or(3).min(64),
            h.parse::<usize>().unwrap_or(3).min(64),
        );
        let mut text = if rng.chance(0.5) {
            format!("type octile\nheight {h}\nwidth {w}\nmap\n")
        } else {
            format!(
                "width\t{w}\r\nheight {h}\r\ntype {}\r\nmap\r\n",
                rng.pick(&["octile", "tile"])
            )
        };
        let rows = if rng.chance(0.9) {
            hn
        } else {
            rng.index(hn + 3)
        };
        for _ in 0..rows {
            let n = if rng.chance(0.9) {
                wn
            } else {
                rng.index(wn + 3)
            };
            let row: String = (0..n)
                .map(|_| *rng.pick(&['.', '@', 'T', 'W', 'G', 'S', 'O', '.', '.', '?']))
                .collect();
            text.push_str(&row);
            text.push('\n');
        }
        Case::one(text)
    }

    fn run(&mut self, case: &Case) -> Result<(), String> {
        let _ = movingai::load_map(&case.text(0));
        Ok(())
    }

    fn alloc_bound(&self, case: &Case) -> u64 {
        text_bound(case)
    }
}

struct MovingaiScen {
    seeds: Vec<Case>,
}

impl Target for MovingaiScen {
    fn name(&self) -> &'static str {
        "movingai-scen"
    }

    fn seeds(&self) -> &[Case] {
        &self.seeds
    }

    fn generate(&self, rng: &mut Rng) -> Case {
        let mut text = String::from(*rng.pick(&["version 1\n", "version 1.0\n", "version 2\n"]));
        for _ in 0..rng.below(8) {
            let f: Vec<String> = (0..9 + usize::from(rng.chance(0.1)))
                .map(|i| {
                    if i == 1 {
                        "maps/x y.map".to_owned()
                    } else if rng.chance(0.3) {
                        rng.pick(INTERESTING_NUMBERS).to_string()
                    } else {
                        rng.below(30).to_string()
                    }
                })
                .collect();
            text.push_str(&f.join(if rng.chance(0.5) { "\t" } else { " " }));
            text.push('\n');
        }
        Case::one(text)
    }

    fn run(&mut self, case: &Case) -> Result<(), String> {
        if let Ok(problems) = movingai::load_scen(&case.text(0)) {
            for p in problems {
                // Checked on reading: the cells are inside the map size given.
                let (Ok(s), Ok(g)) = (p.start_cell(), p.goal_cell()) else {
                    return Err(format!("a problem read lies outside its map: {p:?}"));
                };
                if s.0 >= p.map_width || g.1 >= p.map_height {
                    return Err(format!("problem outside its map: {p:?}"));
                }
            }
        }
        Ok(())
    }

    fn alloc_bound(&self, case: &Case) -> u64 {
        text_bound(case)
    }
}

// ------------------------------------------------------------------ OpenRTM .conf

struct Conf {
    seeds: Vec<Case>,
}

/// Applies `conf` to a fresh configuration of `P`: on an error nothing may have changed.
fn apply<P: ParameterSet>(conf: &ConfFile) -> Result<(), String> {
    let fresh = Configuration::<P>::new();
    let mut c = fresh.clone();
    if c.load_conf(conf).is_err() && c != fresh {
        return Err(format!(
            "a refused .conf changed the configuration of {}",
            core::any::type_name::<P>()
        ));
    }
    Ok(())
}

impl Target for Conf {
    fn name(&self) -> &'static str {
        "conf"
    }

    fn seeds(&self) -> &[Case] {
        &self.seeds
    }

    fn generate(&self, rng: &mut Rng) -> Case {
        let names = LocalPathPlanningParams::SPECS
            .iter()
            .chain(MotorControlParams::SPECS)
            .map(|s| s.name)
            .collect::<Vec<_>>();
        let mut text = String::new();
        for _ in 0..rng.below(16) {
            let line = match rng.below(8) {
                0 => format!(
                    "configuration.active_config: {}",
                    rng.pick(&["default", "mode1", "", "x.y"])
                ),
                1 => format!("exec_cxt.periodic.rate: {}", rng.pick(INTERESTING_NUMBERS)),
                2 => format!("conf.__widget__.{}: slider.0.1", rng.pick(&names)),
                3 => format!("conf.__constraints__.{}: 0<=x<=1", rng.pick(&names)),
                4 => "# comment".to_owned(),
                5 => format!(
                    "conf.{}.{}= {}",
                    rng.pick(&["default", "mode1", "a b"]),
                    rng.pick(&names),
                    rng.pick(INTERESTING_NUMBERS)
                ),
                _ => format!(
                    "conf.{}.{}: {}",
                    rng.pick(&["default", "mode1", "mode2", ""]),
                    rng.pick(&names),
                    rng.pick(INTERESTING_NUMBERS)
                ),
            };
            text.push_str(&line);
            text.push('\n');
        }
        Case::one(text)
    }

    fn run(&mut self, case: &Case) -> Result<(), String> {
        if let Ok(conf) = ConfFile::parse(&case.text(0)) {
            apply::<LocalPathPlanningParams>(&conf)?;
            apply::<MotorControlParams>(&conf)?;
            apply::<DriveControlParams>(&conf)?;
        }
        Ok(())
    }

    fn alloc_bound(&self, case: &Case) -> u64 {
        text_bound(case)
    }
}

// ------------------------------------------------------------------ scenario JSON

struct ScenarioJson {
    seeds: Vec<Case>,
}

impl Target for ScenarioJson {
    fn name(&self) -> &'static str {
        "scenario"
    }

    fn seeds(&self) -> &[Case] {
        &self.seeds
    }

    fn generate(&self, rng: &mut Rng) -> Case {
        let n = |rng: &mut Rng| rng.pick(INTERESTING_NUMBERS).to_string();
        let num = |rng: &mut Rng| {
            let s = n(rng);
            if s.parse::<f64>().is_ok() && !s.is_empty() && !s.contains('_') {
                s
            } else {
                "1".to_owned()
            }
        };
        let mut events = Vec::new();
        for _ in 0..rng.below(4) {
            events.push(match rng.below(4) {
                0 => format!(
                    r#"{{"at": {}, "type": "map_update", "boxes": [{{"x": [{}, {}], "y": [0, 1]}}], "cells": [[{}, 2]], "value": {}}}"#,
                    num(rng),
                    num(rng),
                    num(rng),
                    num(rng),
                    rng.pick(&["0", "1", "2", "-1"])
                ),
                1 => format!(
                    r#"{{"at": {}, "type": "goal", "goal": {{"x": {}, "y": 1}}}}"#,
                    num(rng),
                    num(rng)
                ),
                2 => format!(r#"{{"at": {}, "type": "safe_mode"}}"#, num(rng)),
                _ => format!(r#"{{"at": {}, "type": "clear", "extra": 1}}"#, num(rng)),
            });
        }
        let map = match rng.below(3) {
            0 => r#"{"format": "json", "path": "m.json"}"#.to_owned(),
            1 => format!(
                r#"{{"format": "movingai", "path": "a.map", "grid_size": {}}}"#,
                num(rng)
            ),
            _ => r#"{"format": "ros", "yaml": "m.yaml", "unknown": "free"}"#.to_owned(),
        };
        Case::one(format!(
            r#"{{"name": "f", "description": "", "lesson": "", "map": {map},
            "start": {{"x": {}, "y": 1}}, "goal": {{"x": 2, "y": {}, "heading_deg": {}}},
            "config": {{"{}": {{"dmin": {}}}}}, "rates": {{"physics": {}}},
            "events": [{}], "time_limit": {}, "expect": {{"outcome": "arrived"}}}}"#,
            num(rng),
            num(rng),
            num(rng),
            rng.pick(&["LocalPathPlanning", "Planner", "MotorControl"]),
            num(rng),
            num(rng),
            events.join(","),
            num(rng),
        ))
    }

    fn run(&mut self, case: &Case) -> Result<(), String> {
        if let Ok(s) = Scenario::from_json(&case.text(0)) {
            let text = serde_json::to_string(&s).map_err(|e| e.to_string())?;
            let back = Scenario::from_json(&text)
                .map_err(|e| format!("a scenario read could not be read back: {e}"))?;
            if back != s {
                return Err("a scenario read back differs".to_owned());
            }
        }
        Ok(())
    }

    fn alloc_bound(&self, case: &Case) -> u64 {
        2 * text_bound(case)
    }

    fn fail_at(&self, _part: usize, bytes: &[u8]) -> Option<usize> {
        super::json_fail_at(bytes)
    }
}

// ------------------------------------------------------------------ replay files

struct ReplayJson {
    seeds: Vec<Case>,
}

impl Target for ReplayJson {
    fn name(&self) -> &'static str {
        "replay"
    }

    fn seeds(&self) -> &[Case] {
        &self.seeds
    }

    fn generate(&self, rng: &mut Rng) -> Case {
        let n = |rng: &mut Rng| {
            let s = rng.pick(INTERESTING_NUMBERS).to_string();
            if s.parse::<u64>().is_ok() {
                s
            } else {
                "7".to_owned()
            }
        };
        let inputs: Vec<String> = (0..rng.below(5))
            .map(|_| {
                let input = match rng.below(4) {
                    0 => r#"{"type": "activate_all"}"#.to_owned(),
                    1 => format!(
                        r#"{{"type": "set_param", "component": "{}", "name": "dmin", "value": {}}}"#,
                        rng.pick(&["LocalPathPlanning", "Nobody", "é"]),
                        n(rng)
                    ),
                    2 => r#"{"type": "inject_input", "component": "MotorControl", "port": "TargetVelocity", "data": [0, 1]}"#.to_owned(),
                    _ => r##"{"type": "load_conf", "text": "# [LocalPathPlanning0]\nconf.default.dmin: 0.7\n"}"##.to_owned(),
                };
                let exact = if rng.chance(0.2) {
                    format!(r#", "exact": {{"{}": "{}"}}"#, rng.below(3), rng.pick(&["0x7ff8000000000000", "0x3ff0000000000000", "x", "0x"]))
                } else {
                    String::new()
                };
                format!(r#"{{"t_ns": {}, "input": {input}{exact}}}"#, n(rng))
            })
            .collect();
        let hash = |rng: &mut Rng| match rng.below(4) {
            0 => "ab".to_owned(),
            1 => "é".repeat(32),
            _ => "0123456789abcdef".repeat(4),
        };
        Case::one(format!(
            r#"{{"format": "rtnav-replay", "version": {}, "scenario_hash": "{}", "behaviour": {},
            "setup": {{"v": 1, "scenario": "{}", "start": null, "goal": [1, 2, {}], "backward": false, "edits": [], "params": {{}}}},
            "inputs": [{}], "end_ns": {}, "samples": {}, "trace_hash": "{}"}}"#,
            rng.pick(&["2", "1", "3", "\"2\""]),
            hash(rng),
            rng.pick(&["1", "0", "4294967296"]),
            rng.pick(&["open_field", "", "é"]),
            n(rng),
            inputs.join(","),
            n(rng),
            n(rng),
            hash(rng),
        ))
    }

    fn run(&mut self, case: &Case) -> Result<(), String> {
        let text = case.text(0);
        if let Ok(r) = Replay::from_json(&text) {
            let back = Replay::from_json(&r.to_json().map_err(|e| e.to_string())?)
                .map_err(|e| format!("a replay read could not be read back: {e}"))?;
            if back.to_json().ok() != r.to_json().ok() {
                return Err("a replay read back differs".to_owned());
            }
        }
        let _ = Replay::scenario_of(&text);
        Ok(())
    }

    fn alloc_bound(&self, case: &Case) -> u64 {
        // Read, written and read back.
        4 * text_bound(case)
    }

    fn fail_at(&self, _part: usize, bytes: &[u8]) -> Option<usize> {
        super::json_fail_at(bytes)
    }
}
