//! spec §2 map formats: rtnav JSON, ROS map_server (YAML + PGM/PNG) and MovingAI
//! `.map`/`.scen`. Real data from the external data folder (`$RTNAV_DATA`, else
//! `../shared/data`; read in place, and skipped with a line when absent), small hand-made
//! inputs, and bad inputs that must be refused with an error naming the problem.

use std::io::Write as _;
use std::path::{Path, PathBuf};

use rtnav::errors::MapError;
use rtnav::map::GridMap;
use rtnav::map::formats::ros::{self, RosLoadOptions, RosMapMode, UnknownCells};
use rtnav::map::formats::{json, movingai};

/// The external data's ROS maps, or `None` after one line saying `test` is skipped.
fn ros_maps(test: &str) -> Option<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    match rtnav::data::data_dir(&root) {
        Ok(dir) => Some(dir.join("rosmaps")),
        Err(why) => {
            let _ = writeln!(std::io::stderr(), "SKIPPED {test}: {why}");
            None
        }
    }
}
const FIXTURES: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../fixtures/maps");

/// The error's text, for checking that it names the problem.
fn text(e: MapError) -> String {
    e.to_string()
}

fn obstacles(map: &GridMap) -> usize {
    map.cells().iter().filter(|&&c| c == 1).count()
}

// ---------------------------------------------------------------- ROS map_server

/// One ROS map and what loading it must give.
struct RosCase {
    yaml: &'static str,
    size: (usize, usize),
    resolution: f64,
    origin: (f64, f64),
    /// (free, occupied, unknown) pixels.
    counts: (usize, usize, usize),
}

/// The counts follow the data README's rule; the willow figures were cross-checked once by an
/// independent Python reading of the PGM (`p = (255 − v)/255`, `p ≥ 0.65` occupied,
/// `p ≤ 0.196` free): 109 207 + 544 + 234 377 = 566 × 608.
const ROS_MAPS: [RosCase; 2] = [
    RosCase {
        yaml: "nav2_tb3_sandbox/tb3_sandbox.yaml",
        size: (384, 384),
        resolution: 0.05,
        origin: (-10.0, -10.0),
        counts: (7903, 870, 138_683),
    },
    RosCase {
        yaml: "turtlebot_willow_garage/willow-2010-02-18-0.10.yaml",
        size: (566, 608),
        resolution: 0.10,
        origin: (0.0, 0.0),
        counts: (109_207, 544, 234_377),
    },
];

#[test]
fn both_ros_maps_load_with_their_yaml_geometry_and_map_server_counts() {
    let Some(dir) = ros_maps("the ROS maps of the external data") else {
        return;
    };
    for case in ROS_MAPS {
        let yaml = case.yaml;
        let (free, occupied, unknown) = case.counts;
        let path = dir.join(yaml);
        let r = ros::load_file(&path, &RosLoadOptions::default()).unwrap();
        assert_eq!((r.map.width(), r.map.height()), case.size, "{yaml}");
        assert_eq!(r.map.grid_size(), case.resolution, "{yaml}");
        assert_eq!(r.map.origin(), case.origin, "{yaml}");
        assert_eq!(r.yaml.origin[2], 0.0, "{yaml}");
        assert_eq!(r.yaml.mode, RosMapMode::Trinary);
        assert!(!r.yaml.negate);
        assert_eq!((r.free, r.occupied, r.unknown), case.counts, "{yaml}");
        // Unknown cells are obstacles by default ...
        assert_eq!(obstacles(&r.map), occupied + unknown, "{yaml}");
        // ... or free if asked.
        let opts = RosLoadOptions {
            unknown: UnknownCells::Free,
        };
        let r2 = ros::load_file(&path, &opts).unwrap();
        assert_eq!(obstacles(&r2.map), occupied, "{yaml}");
        assert_eq!(
            (r2.free, r2.occupied, r2.unknown),
            (free, occupied, unknown)
        );
        // The bytes API gives the same map.
        let yaml_text = std::fs::read_to_string(&path).unwrap();
        let image = std::fs::read(path.parent().unwrap().join(&r.yaml.image)).unwrap();
        assert_eq!(
            ros::load(&yaml_text, &image, &RosLoadOptions::default()).unwrap(),
            r
        );
    }
}

const YAML: &str = "image: m.pgm\nresolution: 0.5\norigin: [1.0, 2.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";

/// A 3 × 2 P5 image: top row black, white, grey 205; bottom row white, white, black.
fn tiny_pgm() -> Vec<u8> {
    let mut b = b"P5\n# hand-made\n3 2\n255\n".to_vec();
    b.extend_from_slice(&[0, 254, 205, 254, 254, 0]);
    b
}

#[test]
fn image_row_zero_is_the_top_of_the_map() {
    let r = ros::load(YAML, &tiny_pgm(), &RosLoadOptions::default()).unwrap();
    let m = &r.map;
    assert_eq!(
        (m.width(), m.height(), m.grid_size(), m.origin()),
        (3, 2, 0.5, (1.0, 2.0))
    );
    // Cells x fastest from the bottom row (y = 0) = the image's last row.
    assert_eq!(m.cells(), &[0, 0, 1, 1, 0, 1]);
    // Grey 205: p = 50/255 = 0.19608 > 0.196, unknown (the README's edge case) → obstacle.
    assert_eq!((r.free, r.occupied, r.unknown), (3, 2, 1));
    // World ↔ cell with the origin: the top-left cell's centre.
    assert_eq!(m.cell_center((0, 1)), (1.25, 2.75));
    assert_eq!(m.world_to_cell(1.1, 2.9), Some((0, 1)));
}

#[test]
fn negate_swaps_black_and_white() {
    let yaml = YAML.replace("negate: 0", "negate: 1");
    let r = ros::load(&yaml, &tiny_pgm(), &RosLoadOptions::default()).unwrap();
    // p = v/255: black free, white (254 → 0.996) occupied, 205 → 0.804 occupied.
    assert_eq!(r.map.cells(), &[1, 1, 0, 0, 1, 1]);
    assert_eq!((r.free, r.occupied, r.unknown), (2, 4, 0));
    let yaml = YAML.replace("negate: 0", "negate: true");
    assert!(
        ros::load(&yaml, &tiny_pgm(), &RosLoadOptions::default())
            .unwrap()
            .yaml
            .negate
    );
}

/// A 2 × 1 RGBA PNG: an opaque dark pixel and a transparent white one.
fn tiny_png() -> Vec<u8> {
    let img = image::RgbaImage::from_raw(2, 1, vec![10, 20, 30, 255, 255, 255, 255, 0]).unwrap();
    let mut out = Vec::new();
    img.write_to(&mut std::io::Cursor::new(&mut out), image::ImageFormat::Png)
        .unwrap();
    out
}

#[test]
fn png_colour_and_alpha_follow_map_server() {
    let yaml = YAML.replace("m.pgm", "m.png");
    // Trinary: alpha is averaged in. (10+20+30+255)/4 = 78.75 → p = 0.691 occupied;
    // (255·3 + 0)/4 = 191.25 → p = 0.25: unknown.
    let r = ros::load(&yaml, &tiny_png(), &RosLoadOptions::default()).unwrap();
    assert_eq!((r.free, r.occupied, r.unknown), (0, 1, 1));
    // Scale: colour only (20 → p = 0.92 occupied), and a transparent pixel is unknown.
    let yaml = format!("{yaml}mode: scale\n");
    let r = ros::load(&yaml, &tiny_png(), &RosLoadOptions::default()).unwrap();
    assert_eq!(r.yaml.mode, RosMapMode::Scale);
    assert_eq!((r.free, r.occupied, r.unknown), (0, 1, 1));
}

#[test]
fn native_loader_reads_the_image_beside_the_yaml() {
    let r = ros::load_file(format!("{FIXTURES}/tiny.yaml"), &RosLoadOptions::default()).unwrap();
    assert_eq!((r.map.width(), r.map.height()), (4, 3));
    assert_eq!((r.free, r.occupied, r.unknown), (9, 2, 1));
}

fn ros_err(yaml: &str, image: &[u8]) -> String {
    text(ros::load(yaml, image, &RosLoadOptions::default()).unwrap_err())
}

#[test]
fn bad_ros_input_is_refused_with_a_reason() {
    let mut truncated = tiny_pgm();
    truncated.truncate(truncated.len() - 2);
    let e = ros::load(YAML, &truncated, &RosLoadOptions::default()).unwrap_err();
    assert!(
        matches!(
            &e,
            MapError::Format {
                format: "ROS map image",
                ..
            }
        ),
        "{e:?}"
    );
    assert!(text(e).contains("`m.pgm` is truncated"));
    let no_resolution = YAML.replace("resolution: 0.5\n", "");
    assert!(ros_err(&no_resolution, &tiny_pgm()).contains("missing field `resolution`"));
    let zero = YAML.replace("resolution: 0.5", "resolution: 0");
    assert!(ros_err(&zero, &tiny_pgm()).starts_with("GridSize 0 m must lie between"));
    let origin2 = YAML.replace("[1.0, 2.0, 0.0]", "[1.0, 2.0]");
    assert!(ros_err(&origin2, &tiny_pgm()).contains("`origin` must have 3 elements"));
    let no_negate = YAML.replace("negate: 0\n", "");
    assert!(ros_err(&no_negate, &tiny_pgm()).contains("negate"));
    let inverted = YAML.replace("free_thresh: 0.196", "free_thresh: 0.7");
    assert!(ros_err(&inverted, &tiny_pgm()).contains("`free_thresh` 0.7 must be below"));
    let raw = format!("{YAML}mode: raw\n");
    assert!(ros_err(&raw, &tiny_pgm()).contains("mode: raw"));
    let empty_image = YAML.replace("image: m.pgm", "image: ''");
    assert!(ros_err(&empty_image, &tiny_pgm()).contains("`image` is empty"));
    assert_eq!(
        ros_err(YAML, b"GIF89a...."),
        "ROS map image: `m.pgm` is neither a PGM nor a PNG image"
    );
    let not_negate = YAML.replace("negate: 0", "negate: maybe");
    assert!(ros_err(&not_negate, &tiny_pgm()).contains("0, 1, true or false"));
    assert!(matches!(
        ros::load_file("/nonexistent/map.yaml", &RosLoadOptions::default()),
        Err(MapError::Io { .. })
    ));
}

// ---------------------------------------------------------------- rtnav JSON

#[test]
fn json_fixture_reads_top_row_first() {
    let m = json::load_file(format!("{FIXTURES}/corridor.json")).unwrap();
    assert_eq!((m.width(), m.height(), m.grid_size()), (10, 5, 0.5));
    assert_eq!(m.origin(), (-1.0, 0.0));
    // The first row of the file is the top (y = 4): all wall; the '#' at row 2, column 4
    // is cell (4, 2).
    assert!((0..10).all(|x| m.is_obstacle(x, 4)));
    assert!(m.is_obstacle(4, 2) && !m.is_obstacle(4, 1) && !m.is_obstacle(1, 2));
}

#[test]
fn json_round_trips_and_accepts_setmap_order() {
    let m = GridMap::new(
        4,
        3,
        0.25,
        (0.5, -2.0),
        vec![0, 1, 0, 0, 1, 1, 0, 1, 0, 0, 0, 1],
    )
    .unwrap();
    let text = json::to_string(&m);
    assert!(text.contains("\"...#\""), "{text}"); // top row (y = 2) first
    assert_eq!(json::load(&text).unwrap(), m);
    let flat = r#"{"width": 4, "height": 3, "grid_size": 0.25, "origin": [0.5, -2.0],
                   "cells": [0,1,0,0, 1,1,0,1, 0,0,0,1]}"#;
    assert_eq!(json::load(flat).unwrap(), m);
}

#[test]
fn bad_json_is_refused_with_a_reason() {
    let e = |s: &str| text(json::load(s).unwrap_err());
    assert!(
        e(r#"{"width": 3, "height": 1, "grid_size": 1, "rows": ["..#."]}"#)
            .contains("rows[0] (y = 0) has 4 cells, expected width 3")
    );
    assert!(
        e(r#"{"width": 2, "height": 1, "grid_size": 1, "rows": [".x"]}"#).contains("column 1: 'x'")
    );
    assert!(
        e(r#"{"width": 2, "height": 2, "grid_size": 1, "rows": [".."]}"#)
            .contains("`rows` has 1 rows, expected height 2")
    );
    assert!(
        e(r#"{"width": 1, "height": 1, "grid_size": 1, "rows": ["."], "cells": [0]}"#)
            .contains("not both")
    );
    assert!(e(r#"{"width": 1, "height": 1, "grid_size": 1}"#).contains("missing `rows`"));
    assert!(
        e(r#"{"width": 1, "height": 1, "grid_size": 1, "rows": ["."], "gridsize": 2}"#)
            .contains("unknown field `gridsize`")
    );
    assert!(
        e(r#"{"width": 1, "height": 1, "grid_size": 0, "rows": ["."]}"#).contains("GridSize 0")
    );
    assert!(
        e(r#"{"width": 2, "height": 1, "grid_size": 1, "cells": [0]}"#)
            .contains("MapData has 1 cells, expected")
    );
    assert!(
        e(r#"{"width": 2, "height": 1, "grid_size": 1, "cells": [0, 2]}"#)
            .contains("MapData[1] = 2")
    );
    assert!(matches!(
        json::load("{\n\"width\": 1,\n oops"),
        Err(MapError::Format { line: Some(3), .. })
    ));
}

// ---------------------------------------------------------------- MovingAI

#[test]
fn movingai_rows_are_flipped_so_the_map_looks_the_same_way_up() {
    let m = movingai::load_map("type octile\nheight 2\nwidth 3\nmap\n@.T\n..S\n").unwrap();
    assert_eq!(
        (m.width(), m.height(), m.grid_size(), m.origin()),
        (3, 2, 1.0, (0.0, 0.0))
    );
    // MovingAI (0, 0) = '@' is the top-left: GridMap cell (0, 1).
    assert_eq!(movingai::to_cell(0, 0, 2), Some((0, 1)));
    assert_eq!(movingai::to_cell(0, 2, 2), None);
    assert!(m.is_obstacle(0, 1) && m.is_obstacle(2, 1) && !m.is_obstacle(1, 1));
    assert!((0..3).all(|x| !m.is_obstacle(x, 0)));
}

#[test]
fn movingai_map_tolerates_crlf_tabs_blank_lines_and_header_order() {
    let plain = movingai::load_map("type octile\nheight 2\nwidth 3\nmap\n@.G\nOTW\n").unwrap();
    let messy = "\r\ntype\toctile\r\nwidth  3\r\n\r\nheight\t2\r\nmap\r\n@.G\r\n\r\nOTW\r\n\r\n";
    assert_eq!(movingai::load_map(messy).unwrap(), plain);
}

#[test]
fn bad_movingai_input_is_refused_with_line_numbers() {
    let e = |s: &str| text(movingai::load_map(s).unwrap_err());
    assert_eq!(
        e("type octile\nheight 2\nwidth 3\nmap\n...\n..\n"),
        "MovingAI .map (line 6): row 1 has 2 cells, expected width 3"
    );
    assert!(e("type octile\nheight 2\nwidth 3\nmap\n...\n....\n").contains("row 1 has 4 cells"));
    assert!(e("type octile\nheight 2\nwidth 3\nmap\n...\n").contains("only 1 rows"));
    assert!(e("type octile\nheight 1\nwidth 3\nmap\n...\n...\n").contains("more than the 1 rows"));
    assert!(e("type octile\nheight 1\nwidth 3\nmap\n.x.\n").contains("(line 5): column 1: 'x'"));
    assert!(e("type octile\nheight 0\nwidth 3\nmap\n").contains("height must be"));
    assert!(e("type octile\nwidth 3\nmap\n...\n").contains("missing `height`"));
    assert!(e("type tile\nheight 1\nwidth 1\nmap\n.\n").contains("`tile` is not `octile`"));
    assert!(e("height 1\nwidth 1\n.\n").contains("unexpected header line `.`"));
    assert!(matches!(
        movingai::load_map("type octile\nheight 5000\nwidth 5000\nmap\n"),
        Err(MapError::TooLarge { .. })
    ));
}

#[test]
fn movingai_scen_reads_both_versions_tabs_and_spaces() {
    let tabs = "version 1\n0\tmaps/dao/arena.map\t49\t49\t1\t11\t1\t12\t1\n";
    let spaces = "version 1.0\r\n\r\n3 arena.map 49 49 1 11 1 12 1.5\r\n";
    let a = movingai::load_scen(tabs).unwrap();
    let b = movingai::load_scen(spaces).unwrap();
    assert_eq!(a.len(), 1);
    assert_eq!(a[0].map, "maps/dao/arena.map");
    assert_eq!(
        (a[0].start, a[0].goal, a[0].optimal_length),
        ((1, 11), (1, 12), 1.0)
    );
    // Converted like the map: y counted from the bottom.
    assert_eq!(
        (a[0].start_cell().unwrap(), a[0].goal_cell().unwrap()),
        ((1, 37), (1, 36))
    );
    // A problem built by hand outside its map is refused, never an underflow.
    let mut outside = a[0].clone();
    outside.map_height = 0;
    assert!(matches!(
        outside.start_cell(),
        Err(MapError::CellOutside {
            what: "ScenProblem start",
            ..
        })
    ));
    outside.map_height = 10;
    outside.goal = (1, 10);
    assert!(outside.goal_cell().is_err());
    outside.goal = (99, 0);
    assert!(outside.goal_cell().is_err());
    assert_eq!((b[0].bucket, b[0].optimal_length), (3, 1.5));
    let e = |s: &str| text(movingai::load_scen(s).unwrap_err());
    assert!(e("version 2\n").contains("expected `version 1`"));
    assert!(e("version 1\n0 a.map 4 4 1 1 1\n").contains("(line 2): expected 9 fields, found 7"));
    assert!(e("version 1\n0 a.map 4 4 4 1 1 1 1\n").contains("start (4, 1) is outside"));
    assert!(e("version 1\n0 a.map 4 4 1 1 1 1 x\n").contains("optimal length `x`"));
}

// ---------------------------------------------------------------- what every reader checks

/// spec §2 Decision (geometry): `GridSize` within 1e-4 ..= 1e3 m; the origin and the far
/// corner (origin + size · GridSize) finite and within ±1e9 m. One check,
/// [`GridMap::check_geometry`], made by the constructors and every reader; the error names
/// the value and the limits.
#[test]
fn a_map_geometry_outside_the_limits_is_refused_by_every_way_a_map_is_made() {
    // The limits themselves are accepted.
    for g in [1e-4, 0.05, 1e3] {
        assert_eq!(GridMap::check_geometry(4, 3, g, (0.0, 0.0)), Ok(()), "{g}");
    }
    assert_eq!(
        GridMap::check_geometry(1, 1, 1.0, (-1e9, 1e9 - 1.0)),
        Ok(())
    );
    for g in [
        1e-12,
        9.9e-5,
        1000.5,
        1e9,
        0.0,
        -1.0,
        f64::NAN,
        f64::INFINITY,
    ] {
        let e = GridMap::check_geometry(4, 3, g, (0.0, 0.0)).unwrap_err();
        assert!(matches!(e, MapError::BadGridSize { value, .. } if value.to_bits() == g.to_bits()));
    }
    assert_eq!(
        text(GridMap::check_geometry(4, 3, 1e-12, (0.0, 0.0)).unwrap_err()),
        "GridSize 1e-12 m must lie between 0.0001 m and 1000 m"
    );
    assert_eq!(
        text(GridMap::check_geometry(4, 3, 1e9, (0.0, 0.0)).unwrap_err()),
        "GridSize 1000000000 m must lie between 0.0001 m and 1000 m"
    );
    // The origin, or the far corner, too far out or not finite.
    let origin = |w, h, g, o| GridMap::check_geometry(w, h, g, o).unwrap_err();
    assert_eq!(
        text(origin(4, 3, 0.5, (1e300, 0.0))),
        "map origin (1e300, 0) and far corner (1e300, 1.5) must be finite and within ±1000000000 m"
    );
    assert!(matches!(
        origin(4, 3, 0.5, (0.0, f64::NAN)),
        MapError::BadOrigin { x, y, limit, .. } if x == 0.0 && y.is_nan() && limit == 1e9
    ));
    // Origin within the limit, far corner beyond it: 10 cells of 1 m from 1e9 − 5.
    assert!(matches!(
        origin(10, 1, 1.0, (1e9 - 5.0, 0.0)),
        MapError::BadOrigin { far_x, far_y, .. } if far_x == 1e9 + 5.0 && far_y == 1.0
    ));
    assert!(matches!(
        origin(1, 1, 1.0, (f64::NEG_INFINITY, 0.0)),
        MapError::BadOrigin { .. }
    ));

    // The constructors.
    assert!(matches!(
        GridMap::new(2, 2, 1e-12, (0.0, 0.0), vec![0; 4]),
        Err(MapError::BadGridSize { .. })
    ));
    assert!(matches!(
        GridMap::from_map_data(&[0; 4], 2, 2, 1e9),
        Err(MapError::BadGridSize { .. })
    ));
    assert!(matches!(
        GridMap::new(2, 2, 1.0, (1e300, 0.0), vec![0; 4]),
        Err(MapError::BadOrigin { .. })
    ));
    // The ROS YAML (before the image is read) and the image's size with it.
    let ros = |yaml: &str| ros::load(yaml, &tiny_pgm(), &RosLoadOptions::default());
    for resolution in ["1e-12", "1e9", ".inf", "0"] {
        let yaml = YAML.replace("resolution: 0.5", &format!("resolution: {resolution}"));
        assert!(
            matches!(ros(&yaml), Err(MapError::BadGridSize { .. })),
            "{resolution}: {:?}",
            ros(&yaml)
        );
        assert!(matches!(
            ros::parse_yaml(&yaml),
            Err(MapError::BadGridSize { .. })
        ));
    }
    for o in [
        "[1e300, 0, 0]",
        "[0, -1e10, 0]",
        "[.nan, 0, 0]",
        "[1e400, 0, 0]",
    ] {
        let yaml = YAML.replace("[1.0, 2.0, 0.0]", o);
        assert!(matches!(ros(&yaml), Err(MapError::BadOrigin { .. })), "{o}");
    }
    // A yaw that is not finite is the YAML's own problem.
    let yaw = YAML.replace("[1.0, 2.0, 0.0]", "[1.0, 2.0, .inf]");
    assert!(ros_err(&yaw, &tiny_pgm()).contains("yaw"));
    // Far corner beyond the limit once the image's size is known: 3 × 2 pixels of 1000 m.
    let far = YAML
        .replace("resolution: 0.5", "resolution: 1000")
        .replace("[1.0, 2.0, 0.0]", "[999998000, 0, 0]");
    assert!(ros::parse_yaml(&far).is_ok());
    assert!(matches!(
        ros(&far),
        Err(MapError::BadOrigin { far_x, .. }) if far_x == 1_000_001_000.0
    ));
    // The JSON map.
    let json = |g: &str, o: &str| {
        json::load(&format!(
            r#"{{"width": 1, "height": 1, "grid_size": {g}, "origin": {o}, "rows": ["."]}}"#
        ))
    };
    assert!(json("0.5", "[0, 0]").is_ok());
    assert!(matches!(
        json("1e-12", "[0, 0]"),
        Err(MapError::BadGridSize { .. })
    ));
    assert!(matches!(
        json("1e9", "[0, 0]"),
        Err(MapError::BadGridSize { .. })
    ));
    assert!(matches!(
        json("1", "[1e300, 0]"),
        Err(MapError::BadOrigin { .. })
    ));
    // The geometry is checked before the rows are: a bad grid size is reported as such.
    assert!(matches!(
        json::load(r#"{"width": 2, "height": 1, "grid_size": 1e-12, "rows": ["?"]}"#),
        Err(MapError::BadGridSize { .. })
    ));
}

/// A text file saved by Windows Notepad starts with a UTF-8 byte-order mark (EF BB BF):
/// every text format reads it as without.
#[test]
fn a_leading_byte_order_mark_is_skipped_by_every_text_reader() {
    let bom = |s: &str| format!("\u{feff}{s}");
    let map = "type octile\nheight 2\nwidth 3\nmap\n@.T\n..S\n";
    assert_eq!(
        movingai::load_map(&bom(map)).unwrap(),
        movingai::load_map(map).unwrap()
    );
    let scen = "version 1\n0\tarena.map\t49\t49\t1\t11\t1\t12\t1\n";
    assert_eq!(
        movingai::load_scen(&bom(scen)).unwrap(),
        movingai::load_scen(scen).unwrap()
    );
    let json_map = r#"{"width": 2, "height": 1, "grid_size": 0.5, "rows": [".#"]}"#;
    assert_eq!(
        json::load(&bom(json_map)).unwrap(),
        json::load(json_map).unwrap()
    );
    assert_eq!(
        ros::parse_yaml(&bom(YAML)).unwrap(),
        ros::parse_yaml(YAML).unwrap()
    );
    let r = ros::load(&bom(YAML), &tiny_pgm(), &RosLoadOptions::default()).unwrap();
    assert_eq!(r.map.cells(), &[0, 0, 1, 1, 0, 1]);
    // One mark only: a second is the file's content, refused as such.
    assert!(movingai::load_map(&bom(&bom(map))).is_err());
}

/// The native loaders read a file with a byte-order mark as the text readers do.
#[test]
fn files_with_a_byte_order_mark_load() {
    let dir = std::env::temp_dir().join(format!("rtnav-bom-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let write = |name: &str, text: &str| {
        let path = dir.join(name);
        std::fs::write(&path, format!("\u{feff}{text}")).unwrap();
        path
    };
    let m = movingai::load_map_file(write("a.map", "type octile\nheight 1\nwidth 2\nmap\n.@\n"));
    assert_eq!(m.unwrap().cells(), &[0, 1]);
    let s = movingai::load_scen_file(write("a.scen", "version 1\n0 a.map 2 1 0 0 0 0 0\n"));
    assert_eq!(s.unwrap().len(), 1);
    let j = json::load_file(write(
        "a.json",
        r##"{"width": 1, "height": 1, "grid_size": 1, "rows": ["#"]}"##,
    ));
    assert_eq!(j.unwrap().cells(), &[1]);
    std::fs::write(dir.join("m.pgm"), tiny_pgm()).unwrap();
    let r = ros::load_file(write("m.yaml", YAML), &RosLoadOptions::default());
    assert_eq!(r.unwrap().map.width(), 3);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// An image shorter than its header says is reported as truncated, naming the file (the
/// YAML's `image`) and, for a binary PGM, the bytes of pixel data expected and found.
#[test]
fn a_truncated_image_is_reported_as_truncated() {
    let mut pgm = tiny_pgm();
    pgm.truncate(pgm.len() - 2);
    assert_eq!(
        ros_err(YAML, &pgm),
        "ROS map image: `m.pgm` is truncated: its header gives 3×2 pixels, \
         6 bytes of pixel data, but the file holds 4"
    );
    // 16-bit samples: two bytes each.
    let mut wide = b"P5\n2 1\n65535\n".to_vec();
    wide.extend_from_slice(&[0, 0, 255]);
    assert!(
        ros_err(YAML, &wide).ends_with("2×1 pixels, 4 bytes of pixel data, but the file holds 3"),
        "{}",
        ros_err(YAML, &wide)
    );
    // A P4 bitmap packs 8 pixels a byte: 9 × 2 pixels are 2 bytes a row.
    let bitmap = b"P4\n9 2\n\x00\x00\x00";
    assert!(
        ros_err(YAML, bitmap).ends_with("9×2 pixels, 4 bytes of pixel data, but the file holds 3"),
        "{}",
        ros_err(YAML, bitmap)
    );
    // Bytes beyond the pixel data are not a truncation.
    let mut longer = tiny_pgm();
    longer.push(0);
    assert!(ros::load(YAML, &longer, &RosLoadOptions::default()).is_ok());
    // An ASCII PGM or PBM that ends early: samples counted.
    let ascii = b"P2\n3 2\n255\n0 254 205\n254\n";
    assert!(
        ros_err(YAML, ascii).ends_with(
            "`m.pgm` is truncated: its header gives 3×2 pixels, 6 samples, but the file holds 4"
        ),
        "{}",
        ros_err(YAML, ascii)
    );
    let plain_bitmap = b"P1\n3 2\n010\n1";
    assert!(ros_err(YAML, plain_bitmap).ends_with("3×2 pixels, 6 samples, but the file holds 4"));
    // A header cut short.
    for cut in [&b"P5\n3 2\n"[..], b"P5\n3", b"P5"] {
        let e = ros_err(YAML, cut);
        assert!(
            e.starts_with("ROS map image: `m.pgm` is truncated"),
            "{cut:?}: {e}"
        );
    }
    // A PNG cut short, in its pixel data and in its header.
    let png = tiny_png();
    let png_yaml = YAML.replace("m.pgm", "m.png");
    for cut in [png.len() - 20, 40, 20] {
        assert_eq!(
            ros_err(&png_yaml, &png[..cut]),
            "ROS map image: `m.png` is truncated: the file ends before the image does",
            "{cut}"
        );
    }
}

/// A MovingAI scenario's `grid_size` and `origin` are checked when the scenario is read, by
/// the map's one rule ([`GridMap::check_geometry`]), before its map is loaded.
#[test]
fn a_movingai_scenario_geometry_is_checked_by_the_map_rule() {
    let arena = include_str!("../../fixtures/scenarios/arena.json");
    let read = |from: &str, to: &str| {
        rtnav::system::Scenario::from_json(&arena.replace(from, to)).map(|_| ())
    };
    assert_eq!(read("", ""), Ok(()));
    let reason = |r: Result<(), rtnav::errors::ScenarioError>| match r {
        Err(rtnav::errors::ScenarioError::Scenario { reason, .. }) => reason,
        other => panic!("{other:?}"),
    };
    assert_eq!(
        reason(read("\"grid_size\": 0.5", "\"grid_size\": 1e-12")),
        "map: GridSize 1e-12 m must lie between 0.0001 m and 1000 m"
    );
    assert!(reason(read("\"grid_size\": 0.5", "\"grid_size\": 5000")).contains("GridSize 5000 m"));
    assert!(
        reason(read(
            "\"grid_size\": 0.5",
            "\"grid_size\": 0.5, \"origin\": [1e300, 0]"
        ))
        .starts_with("map: map origin (1e300, 0)")
    );
}

/// A `.map` header that gives a key twice is refused (which one the file means cannot be
/// told), and a size beyond the platform's word is the size error on every target.
#[test]
fn a_movingai_header_with_a_key_twice_or_a_huge_size_is_refused() {
    let e = |s: &str| text(movingai::load_map(s).unwrap_err());
    assert_eq!(
        e("type octile\nheight 1\nwidth 2\nheight 2\nmap\n..\n..\n"),
        "MovingAI .map (line 4): `height` is given twice in the header"
    );
    assert!(
        e("type octile\ntype octile\nheight 1\nwidth 1\nmap\n.\n")
            .contains("`type` is given twice")
    );
    assert!(e("width 1\ntype octile\nheight 1\nwidth 1\nmap\n.\n").contains("(line 4): `width`"));
    assert!(matches!(
        movingai::load_map("type octile\nheight 1\nwidth 5000000000\nmap\n"),
        Err(MapError::TooLarge {
            width: 5_000_000_000,
            ..
        })
    ));
}

/// A MovingAI file that is not one (one enormous line, numbers beyond any size) gives a
/// short message naming the problem: quoted text is cut at 40 characters, and digits too
/// many for a size are "too large", not "not a whole number".
#[test]
fn movingai_errors_quote_little_and_say_too_large() {
    let garbage = "x".repeat(100_000);
    let e = text(movingai::load_map(&format!("{garbage} 1 2\n")).unwrap_err());
    assert_eq!(
        e,
        format!(
            "MovingAI .map (line 1): cannot read header line `{}…`",
            "x".repeat(40)
        )
    );
    let e = text(movingai::load_scen(&format!("{garbage}\n")).unwrap_err());
    assert!(e.len() < 100, "{e}");
    let e = text(
        movingai::load_map(&format!("type {garbage}\nheight 1\nwidth 1\nmap\n.\n")).unwrap_err(),
    );
    assert!(e.len() < 100, "{e}");
    assert_eq!(
        text(
            movingai::load_map("type octile\nheight 1\nwidth 99999999999999999999999\nmap\n")
                .unwrap_err()
        ),
        "MovingAI .map (line 3): `width 99999999999999999999999`: width is too large"
    );
    let scen = |field: &str| {
        text(movingai::load_scen(&format!("version 1\n0 a.map 4 4 {field} 1 1 1 1\n")).unwrap_err())
    };
    assert!(
        scen("99999999999999999999999").ends_with("start x `99999999999999999999999` is too large")
    );
    assert!(scen("-1").ends_with("start x `-1` is not a whole number ≥ 0"));
    let opt = format!("version 1\n0 a.map 4 4 1 1 1 1 {garbage}\n");
    assert!(text(movingai::load_scen(&opt).unwrap_err()).len() < 120);
}

/// A ROS YAML value that is not what it should be is quoted short.
#[test]
fn ros_yaml_errors_quote_little() {
    // A long value, and a long key given twice (an implicit key has at most 1024 characters).
    let (long, key) = ("x".repeat(30_000), "x".repeat(1000));
    for yaml in [
        YAML.replace("resolution: 0.5", &format!("resolution: {long}")),
        format!("{YAML}mode: {long}\n"),
        format!("{YAML}{key}: 1\n{key}: 2\n"),
    ] {
        let e = text(ros::parse_yaml(&yaml).unwrap_err());
        assert!(
            e.len() < 120 && e.contains(&format!("{}…", "x".repeat(40))),
            "{e}"
        );
    }
}
