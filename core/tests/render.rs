//! The renderer (spec §5 InventGUI): golden PNGs compared exactly, the view transform, the
//! caches, and refused input.
//!
//! Goldens live in `fixtures/golden/render/`. `UPDATE_GOLDEN=1 cargo test --test render`
//! rewrites them; on a mismatch the new frame is written next to the golden as `.new.png`.
//! Scenes are built by hand here (a synthetic distance-to-target field): no planner needed.
#![cfg(feature = "render")]

use std::collections::VecDeque;
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};
use std::path::PathBuf;

use rtnav::errors::RenderError;
use rtnav::interfaces::{Direction, Pose};
use rtnav::map::{Cell, GridMap, MapUpdate};
use rtnav::render::{FieldCellState, FieldView, Frame, Layers, Renderer, RobotView, Scene};
use rtnav::rtc::Time;

// ---------------------------------------------------------------------------------------
// Hand-made scene data.

/// A 48 × 32 map of 0.25 m cells (12 m × 8 m): outer walls, a block, an L-shaped wall and a
/// thin one-cell wall.
fn small_map() -> GridMap {
    let (w, h) = (48, 32);
    let mut cells = vec![0u8; w * h];
    let mut set = |x0: usize, y0: usize, x1: usize, y1: usize| {
        for y in y0..y1 {
            for x in x0..x1 {
                cells[x + y * w] = 1;
            }
        }
    };
    set(0, 0, 48, 1);
    set(0, 31, 48, 32);
    set(0, 0, 1, 32);
    set(47, 0, 48, 32);
    set(12, 8, 18, 16); // block
    set(26, 14, 28, 31); // L: vertical
    set(28, 14, 36, 16); // L: horizontal
    set(38, 1, 39, 10); // thin wall
    GridMap::new(w, h, 0.25, (-1.0, -0.5), cells).unwrap()
}

/// An 8-connected wavefront of path lengths [m] from `target` over cells clear of `dmin`
/// (no corner cutting), like the planner's `L(c)`; `None` where unreached.
fn path_lengths(map: &GridMap, dmin: f64, target: Cell, limit: f64) -> Vec<Option<f64>> {
    let (w, h) = (map.width() as i64, map.height() as i64);
    let g = map.grid_size();
    let clear = |x: i64, y: i64| map.contains(x, y) && map.is_clear((x as usize, y as usize), dmin);
    let mut len: Vec<Option<f64>> = vec![None; (w * h) as usize];
    len[map.index(target)] = Some(0.0);
    let mut queue = VecDeque::from([target]);
    // Label-correcting: exact for these small maps, and deterministic.
    while let Some((x, y)) = queue.pop_front() {
        let here = len[map.index((x, y))].unwrap();
        for (dx, dy) in [
            (1, 0),
            (-1, 0),
            (0, 1),
            (0, -1),
            (1, 1),
            (1, -1),
            (-1, 1),
            (-1, -1),
        ] {
            let (nx, ny) = (x as i64 + dx, y as i64 + dy);
            if !clear(nx, ny) {
                continue;
            }
            if dx != 0 && dy != 0 && !(clear(x as i64 + dx, y as i64) && clear(x as i64, ny)) {
                continue;
            }
            let step = if dx != 0 && dy != 0 {
                g * 2f64.sqrt()
            } else {
                g
            };
            let l = here + step;
            if l > limit {
                continue;
            }
            let i = (nx + ny * w) as usize;
            if len[i].is_none_or(|old| l < old - 1e-12) {
                len[i] = Some(l);
                queue.push_back((nx as usize, ny as usize));
            }
        }
    }
    len
}

/// Steepest descent on `len` from `from` to the target (where the length is 0).
fn descend(map: &GridMap, len: &[Option<f64>], from: Cell) -> Vec<Cell> {
    let mut path = vec![from];
    let mut here = from;
    while len[map.index(here)] != Some(0.0) {
        let mut best: Option<(f64, Cell)> = None;
        for dy in -1i64..=1 {
            for dx in -1i64..=1 {
                let (nx, ny) = (here.0 as i64 + dx, here.1 as i64 + dy);
                if (dx, dy) == (0, 0) || !map.contains(nx, ny) {
                    continue;
                }
                let c = (nx as usize, ny as usize);
                if let Some(l) = len[map.index(c)]
                    && best.is_none_or(|b| l < b.0)
                {
                    best = Some((l, c));
                }
            }
        }
        here = best.unwrap().1;
        path.push(here);
    }
    path
}

/// Control points as 000 §5.2.4.12: direction changes, first the exact current position,
/// last the goal.
fn control_points(
    map: &GridMap,
    path: &[Cell],
    first: (f64, f64),
    last: (f64, f64),
) -> Vec<(f64, f64)> {
    let mut pts = vec![first];
    for i in 1..path.len() - 1 {
        let d0 = (
            path[i].0 as i64 - path[i - 1].0 as i64,
            path[i].1 as i64 - path[i - 1].1 as i64,
        );
        let d1 = (
            path[i + 1].0 as i64 - path[i].0 as i64,
            path[i + 1].1 as i64 - path[i].1 as i64,
        );
        if d0 != d1 {
            pts.push(map.cell_center(path[i]));
        }
    }
    pts.push(last);
    pts
}

/// Everything a full scene borrows.
struct Data {
    map: GridMap,
    dmin: f64,
    potential: Vec<f64>,
    state: Vec<FieldCellState>,
    global: Vec<Cell>,
    local: Vec<Cell>,
    control: Vec<(f64, f64)>,
    trail: Vec<(f64, f64)>,
    start: Pose,
    goal: Pose,
    robot: Pose,
    target: Pose,
}

/// The small map with a synthetic field towards the local target: potential
/// `0.1 + L + 0.02 / (d − dmin)²` (path length plus a repulsion, as 000 §5.2.4.9), reached
/// within 7 m of path length, impassable within `dmin`.
fn small_data() -> Data {
    let map = small_map();
    let dmin = 0.5;
    let start_cell = (4, 4);
    let goal_cell = (43, 27);
    let start = pose_at(&map, start_cell, FRAC_PI_2);
    let goal = pose_at(&map, goal_cell, 0.0);
    let to_goal = path_lengths(&map, dmin, goal_cell, f64::INFINITY);
    let global = descend(&map, &to_goal, start_cell);
    let robot_index = global.len() / 5;
    let robot_cell = global[robot_index];
    let (rx, ry) = map.cell_center(robot_cell);
    let robot = Pose::new(rx + 0.06, ry - 0.04, FRAC_PI_4 * 0.5);
    let target_index = global.len() * 3 / 5;
    let target_cell = global[target_index];
    let next = global[target_index + 1];
    let target_theta = match (
        next.0 as i64 - target_cell.0 as i64,
        next.1 as i64 - target_cell.1 as i64,
    ) {
        (1, 0) => 0.0,
        (1, 1) => FRAC_PI_4,
        (0, 1) => FRAC_PI_2,
        (-1, 1) => 3.0 * FRAC_PI_4,
        (-1, 0) => PI,
        (1, -1) => -FRAC_PI_4,
        (0, -1) => -FRAC_PI_2,
        _ => -3.0 * FRAC_PI_4,
    };
    let target = pose_at(&map, target_cell, target_theta);
    let to_target = path_lengths(&map, dmin, target_cell, 7.0);
    let mut potential = vec![0.0; to_target.len()];
    let mut state = vec![FieldCellState::Unreached; to_target.len()];
    for (i, l) in to_target.iter().enumerate() {
        let d = map.distances()[i];
        if d <= dmin {
            state[i] = FieldCellState::Impassable;
        } else if let Some(l) = l {
            state[i] = FieldCellState::Reached;
            potential[i] = 0.1 + l + 0.02 / ((d - dmin) * (d - dmin));
        }
    }
    let robot_on_field = map.world_to_cell(robot.x, robot.y).unwrap();
    let mut local = descend(&map, &to_target, robot_on_field);
    local.extend_from_slice(&global[target_index + 1..]);
    let control = control_points(&map, &local, (robot.x, robot.y), (goal.x, goal.y));
    // The trail: from the start to the robot along the path, bowed sideways by a parabola.
    let (sx, sy) = (start.x, start.y);
    let n = 40;
    let mut trail = Vec::new();
    for i in 0..=n {
        let t = f64::from(i) / f64::from(n);
        let bow = 0.35 * 4.0 * t * (1.0 - t);
        trail.push((
            sx + (robot.x - sx) * t - bow * 0.3,
            sy + (robot.y - sy) * t + bow,
        ));
    }
    Data {
        map,
        dmin,
        potential,
        state,
        global,
        local,
        control,
        trail,
        start,
        goal,
        robot,
        target,
    }
}

fn pose_at(map: &GridMap, c: Cell, theta: f64) -> Pose {
    let (x, y) = map.cell_center(c);
    Pose::new(x, y, theta)
}

fn full_scene(d: &Data) -> Scene<'_> {
    Scene {
        dmin: d.dmin,
        field: Some(FieldView {
            potential: &d.potential,
            state: &d.state,
            key: 1,
        }),
        global_path: &d.global,
        local_path: &d.local,
        control_points: &d.control,
        local_target: Some(d.target),
        robot: Some(RobotView::with_defaults(d.robot)),
        trail: &d.trail,
        start: Some(d.start),
        goal: Some(d.goal),
        direction: Direction::Forward,
        caption: "t = 12.30 s  planning ok",
        ..Scene::new(&d.map, 1)
    }
}

// ---------------------------------------------------------------------------------------
// Golden PNGs.

fn golden_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../fixtures/golden/render")
}

fn decode_rgb(bytes: &[u8]) -> (u32, u32, Vec<u8>) {
    let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    buf.truncate(info.buffer_size());
    assert_eq!(info.color_type, png::ColorType::Rgb);
    assert_eq!(info.bit_depth, png::BitDepth::Eight);
    (info.width, info.height, buf)
}

/// Compares `frame` with the golden `name.png` pixel for pixel (after checking the frame is
/// opaque and its PNG decodes to the same pixels).
fn check_golden(name: &str, frame: &Frame) {
    assert!(
        frame.data().chunks_exact(4).all(|p| p[3] == 255),
        "{name}: every pixel must be opaque"
    );
    let png = frame.encode_png().unwrap();
    let (w, h, rgb) = decode_rgb(&png);
    assert_eq!((w, h), (frame.width(), frame.height()));
    let expected_rgb: Vec<u8> = frame
        .data()
        .chunks_exact(4)
        .flat_map(|p| [p[0], p[1], p[2]])
        .collect();
    assert!(rgb == expected_rgb, "{name}: PNG round trip changed pixels");

    let dir = golden_dir();
    let path = dir.join(format!("{name}.png"));
    if std::env::var_os("UPDATE_GOLDEN").is_some_and(|v| v == "1") {
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(&path, &png).unwrap();
        return;
    }
    let new_path = dir.join(format!("{name}.new.png"));
    let golden = match std::fs::read(&path) {
        Ok(bytes) => bytes,
        Err(e) => {
            std::fs::create_dir_all(&dir).unwrap();
            std::fs::write(&new_path, &png).unwrap();
            panic!(
                "{name}: no golden at {} ({e}); wrote {}; run with UPDATE_GOLDEN=1 to accept",
                path.display(),
                new_path.display()
            );
        }
    };
    let (gw, gh, golden_rgb) = decode_rgb(&golden);
    let same_size = (gw, gh) == (w, h);
    let differing = if same_size {
        rgb.chunks_exact(3)
            .zip(golden_rgb.chunks_exact(3))
            .filter(|(a, b)| a != b)
            .count()
    } else {
        usize::MAX
    };
    if differing != 0 {
        std::fs::write(&new_path, &png).unwrap();
        panic!(
            "{name}: frame differs from the golden ({}); wrote {}; \
             run with UPDATE_GOLDEN=1 to accept",
            if same_size {
                format!("{differing} pixels differ")
            } else {
                format!("size {w}×{h}, golden {gw}×{gh}")
            },
            new_path.display()
        );
    }
    let _ = std::fs::remove_file(&new_path);
}

fn render(width: u32, height: u32, scene: &Scene<'_>) -> Frame {
    Renderer::new(width, height)
        .unwrap()
        .render(scene)
        .unwrap()
        .clone()
}

#[test]
fn golden_every_layer() {
    let d = small_data();
    check_golden("every_layer", &render(800, 600, &full_scene(&d)));
}

/// One layer alone on the full scene (the map outline and panel frame stay).
fn check_alone(name: &str, layers: Layers) {
    let d = small_data();
    let scene = Scene {
        layers,
        ..full_scene(&d)
    };
    check_golden(name, &render(480, 320, &scene));
}

#[test]
fn golden_occupancy_alone() {
    check_alone(
        "occupancy_alone",
        Layers {
            occupancy: true,
            ..Layers::NONE
        },
    );
}

#[test]
fn golden_dmin_zone_alone() {
    check_alone(
        "dmin_zone_alone",
        Layers {
            dmin_zone: true,
            ..Layers::NONE
        },
    );
}

#[test]
fn golden_heat_map_alone() {
    check_alone(
        "heat_map_alone",
        Layers {
            heat_map: true,
            ..Layers::NONE
        },
    );
}

#[test]
fn golden_paths_alone() {
    check_alone(
        "paths_alone",
        Layers {
            global_path: true,
            local_path: true,
            control_points: true,
            local_target: true,
            ..Layers::NONE
        },
    );
}

#[test]
fn golden_robot_and_arrows_alone() {
    check_alone(
        "robot_and_arrows_alone",
        Layers {
            robot: true,
            trail: true,
            start_goal: true,
            ..Layers::NONE
        },
    );
}

/// A 160 × 120 map of 0.1 m cells in a 640 × 480 frame (cells smaller than pixels, so
/// averaged), the heat map with its colour bar and decades, driving backward, bumped.
#[test]
fn golden_heat_map_scene() {
    let (w, h) = (160usize, 120usize);
    let mut cells = vec![0u8; w * h];
    for y in 0..h {
        for x in 0..w {
            let border = x == 0 || y == 0 || x == w - 1 || y == h - 1;
            let pillar = (x / 20) % 2 == 1 && (y / 20) % 2 == 1 && x % 20 < 6 && y % 20 < 6;
            let wall = x == 80 && (10..100).contains(&y);
            if border || pillar || wall {
                cells[x + y * w] = 1;
            }
        }
    }
    let map = GridMap::new(w, h, 0.1, (0.0, 0.0), cells).unwrap();
    let dmin = 0.25;
    let target = (120, 60);
    let len = path_lengths(&map, dmin, target, f64::INFINITY);
    let mut potential = vec![0.0; w * h];
    let mut state = vec![FieldCellState::Unreached; w * h];
    for (i, l) in len.iter().enumerate() {
        let d = map.distances()[i];
        if d <= dmin {
            state[i] = FieldCellState::Impassable;
        } else if let Some(l) = l {
            state[i] = FieldCellState::Reached;
            potential[i] = 0.1 + 3.0 * l + 0.05 / ((d - dmin) * (d - dmin));
        }
    }
    let robot_cell = (30, 40);
    let local = descend(&map, &len, robot_cell);
    let robot = pose_at(&map, robot_cell, PI);
    let goal = pose_at(&map, target, PI);
    let scene = Scene {
        dmin,
        field: Some(FieldView {
            potential: &potential,
            state: &state,
            key: 7,
        }),
        local_path: &local,
        local_target: Some(goal),
        robot: Some(RobotView {
            bumped: true,
            ..RobotView::with_defaults(robot)
        }),
        goal: Some(goal),
        direction: Direction::Backward,
        caption: "bump! robot stopped",
        ..Scene::new(&map, 3)
    };
    check_golden("heat_map_scene", &render(640, 480, &scene));
}

// ---------------------------------------------------------------------------------------
// Caches: a cached frame equals a fresh one; keys decide what is redrawn.

#[test]
fn a_cached_frame_equals_a_fresh_one() {
    let d = small_data();
    let mut renderer = Renderer::new(640, 400).unwrap();
    renderer.render(&full_scene(&d)).unwrap();
    // The robot moves, the path changes, the caption changes: the background stays cached.
    let moved = Pose::new(d.robot.x + 0.3, d.robot.y + 0.1, -1.0);
    let shorter = &d.local[3..];
    let scene = Scene {
        robot: Some(RobotView::with_defaults(moved)),
        local_path: shorter,
        caption: "t = 12.40 s",
        direction: Direction::Backward,
        ..full_scene(&d)
    };
    let cached = renderer.render(&scene).unwrap().clone();
    assert_eq!(cached, render(640, 400, &scene));
    // Toggling a layer and resizing also match a fresh renderer.
    let no_heat = Scene {
        layers: Layers {
            heat_map: false,
            ..Layers::ALL
        },
        ..scene
    };
    assert_eq!(
        renderer.render(&no_heat).unwrap(),
        &render(640, 400, &no_heat)
    );
    renderer.resize(500, 500).unwrap();
    assert_eq!(renderer.render(&scene).unwrap(), &render(500, 500, &scene));
}

#[test]
fn a_frame_after_map_updates_equals_a_fresh_one() {
    // The renderer recolours and redraws only the cells a MapUpdate changed (when the map can
    // tell which, inside the picture and clear of its border): the frame must be what a
    // fresh renderer draws, with the heat map and without, with the side panel and without,
    // grid lines (big cells) and not, cells bigger and smaller than a pixel.
    let d = small_data();
    let at = |sec| Time { sec, nsec: 0 };
    let sizes = [
        (640, 400, false),
        (640, 400, true),
        (200, 130, false),
        (40, 30, false),
    ];
    for (width, height, side_panel) in sizes {
        for heat_map in [true, false] {
            let mut map = d.map.clone();
            let layers = Layers {
                heat_map,
                ..Layers::ALL
            };
            let fresh = |map: &GridMap| {
                let mut r = Renderer::new(width, height).unwrap();
                r.set_side_panel(side_panel);
                r.render(&Scene {
                    map,
                    layers,
                    ..full_scene(&d)
                })
                .unwrap()
                .clone()
            };
            let mut renderer = Renderer::new(width, height).unwrap();
            renderer.set_side_panel(side_panel);
            let strokes: [&[(i64, i64, i16)]; 4] = [
                // Painted inside, then erased; two at once between frames; at the map's edge.
                &[(20, 12, 1), (21, 12, 1), (21, 13, 1)],
                &[(21, 12, 0)],
                &[(30, 20, 1), (8, 9, 1)],
                &[(0, 5, 0), (47, 31, 0), (1, 1, 1)],
            ];
            for (k, stroke) in strokes.iter().enumerate() {
                renderer
                    .render(&Scene {
                        map: &map,
                        map_key: k as u64 + 9,
                        layers,
                        ..full_scene(&d)
                    })
                    .unwrap();
                map.map_update(&MapUpdate::from_cells(stroke, at(k as u32 + 1)))
                    .unwrap();
                if k == 2 {
                    // A second update before the next frame.
                    map.map_update(&MapUpdate::from_cells(&[(9, 9, 1)], at(10)))
                        .unwrap();
                }
                // As the page does: a new map key with each update.
                let cached = renderer
                    .render(&Scene {
                        map: &map,
                        map_key: k as u64 + 10,
                        layers,
                        ..full_scene(&d)
                    })
                    .unwrap()
                    .clone();
                assert_eq!(
                    cached,
                    fresh(&map),
                    "{width}×{height}, panel {side_panel}, heat {heat_map}, stroke {k}"
                );
            }
        }
    }
}

#[test]
fn the_map_and_field_keys_decide_when_static_layers_are_redrawn() {
    let d = small_data();
    let mut renderer = Renderer::new(400, 300).unwrap();
    let before = renderer.render(&full_scene(&d)).unwrap().clone();

    // Same key, different cells: the cached map is shown (the caller promised no change).
    let mut cells = d.map.cells().to_vec();
    for c in &mut cells[20 * 48 + 2..20 * 48 + 10] {
        *c = 1;
    }
    let changed = GridMap::new(48, 32, 0.25, (-1.0, -0.5), cells).unwrap();
    let same_key = Scene {
        map: &changed,
        ..full_scene(&d)
    };
    assert_eq!(renderer.render(&same_key).unwrap(), &before);
    // A new key redraws it.
    let new_key = Scene {
        map_key: 2,
        ..same_key
    };
    let redrawn = renderer.render(&new_key).unwrap().clone();
    assert_ne!(redrawn, before);
    assert_eq!(redrawn, render(400, 300, &new_key));

    // The field likewise: new potentials under the old key are not looked at...
    let doubled: Vec<f64> = d.potential.iter().map(|p| p * 2.0 + 1.0).collect();
    let field = |potential, key| FieldView {
        potential,
        state: &d.state,
        key,
    };
    let old_key = Scene {
        field: Some(field(&doubled, 1)),
        ..new_key
    };
    assert_eq!(renderer.render(&old_key).unwrap(), &redrawn);
    // ...and are under a new one.
    let fresh_key = Scene {
        field: Some(field(&doubled, 2)),
        ..new_key
    };
    let recoloured = renderer.render(&fresh_key).unwrap().clone();
    assert_ne!(recoloured, redrawn);
    assert_eq!(recoloured, render(400, 300, &fresh_key));
}

// ---------------------------------------------------------------------------------------
// View transform.

#[test]
fn the_view_maps_world_to_pixels_and_back() {
    let map = small_map();
    let renderer = Renderer::new(800, 600).unwrap();
    let view = renderer.view(&map);
    let s = view.pixels_per_metre();
    let (l, t, r, b) = view.map_rect();
    // The map (12 m × 8 m, origin (−1, −0.5)) fills the rectangle, aspect kept.
    assert_eq!(view.world_to_pixel(-1.0, -0.5), (l, b));
    assert_eq!(view.world_to_pixel(11.0, 7.5), (r, t));
    assert_eq!((r - l) / (b - t), 1.5);
    assert_eq!(l.fract(), 0.0);
    assert_eq!(t.fract(), 0.0);
    assert!(s > 20.0);
    for (x, y) in [(0.0, 0.0), (3.3, -0.25), (10.9, 7.4)] {
        let (px, py) = view.world_to_pixel(x, y);
        let (wx, wy) = view.pixel_to_world(px, py);
        assert!((wx - x).abs() < 1e-12 && (wy - y).abs() < 1e-12);
    }
    // A click on a cell's centre pixel finds that cell; outside the map, none.
    let (cx, cy) = map.cell_center((13, 9));
    let (px, py) = view.world_to_pixel(cx, cy);
    assert_eq!(view.pixel_to_cell(&map, px, py), Some((13, 9)));
    assert_eq!(view.pixel_to_cell(&map, 1.0, 1.0), None);
    // The same view without a renderer.
    assert_eq!(
        rtnav::render::ViewTransform::fit(800, 600, &map).unwrap(),
        view
    );
}

#[test]
fn the_camera_zooms_about_a_point_pans_and_fits() {
    let map = small_map();
    let mut renderer = Renderer::new(800, 600).unwrap();
    let fit = renderer.view(&map);
    // The point under a pixel stays there as the view zooms about it.
    let (px, py) = (230.0, 410.0);
    let under = fit.pixel_to_world(px, py);
    renderer.zoom_at(&map, px, py, 2.5);
    let zoomed = renderer.view(&map);
    assert_eq!(renderer.camera().unwrap().zoom, 2.5);
    assert!((zoomed.pixels_per_metre() / fit.pixels_per_metre() - 2.5).abs() < 1e-12);
    let (wx, wy) = zoomed.pixel_to_world(px, py);
    assert!((wx - under.0).abs() < 1e-9 && (wy - under.1).abs() < 1e-9);
    // A pan moves the picture with the mouse.
    let before = zoomed.pixel_to_world(300.0, 300.0);
    renderer.pan_by(&map, 40.0, -25.0);
    let panned = renderer.view(&map);
    let after = panned.pixel_to_world(340.0, 275.0);
    assert!((after.0 - before.0).abs() < 1e-9 && (after.1 - before.1).abs() < 1e-9);
    // The centre stays on the map however far it is dragged (right and up: the picture's
    // middle reaches the map's bottom-left corner); the zoom stays within bounds.
    renderer.pan_by(&map, 1e6, -1e6);
    let c = renderer.camera().unwrap();
    assert_eq!(c.centre, (-1.0, -0.5));
    renderer.zoom_at(&map, 400.0, 300.0, 1e9);
    assert_eq!(renderer.camera().unwrap().zoom, rtnav::render::MAX_ZOOM);
    // Back to 1× (or below): the fitted view, exactly.
    renderer.zoom_at(&map, 400.0, 300.0, 1e-9);
    assert_eq!(renderer.camera(), None);
    assert_eq!(renderer.view(&map), fit);
    // Nonsense changes nothing.
    renderer.zoom_at(&map, f64::NAN, 1.0, 2.0);
    renderer.pan_by(&map, 5.0, 5.0);
    assert_eq!(renderer.camera(), None);
}

#[test]
fn without_the_side_panel_the_map_takes_the_frame_and_a_zoomed_frame_draws() {
    let d = small_data();
    let scene = full_scene(&d);
    // A square frame: the map's width decides its scale.
    let mut renderer = Renderer::new(600, 600).unwrap();
    let with_panel = renderer.view(&d.map).pixels_per_metre();
    renderer.set_side_panel(false);
    let without = renderer.view(&d.map).pixels_per_metre();
    assert!(without > with_panel, "{without} > {with_panel}");
    renderer.render(&scene).unwrap();
    // Zoomed in on the robot: it is drawn where the view puts it, and bigger.
    renderer.zoom_at(&d.map, 300.0, 300.0, 1.0);
    let (rx, ry) = renderer.view(&d.map).world_to_pixel(d.robot.x, d.robot.y);
    renderer.zoom_at(&d.map, rx, ry, 4.0);
    let (qx, qy) = renderer.view(&d.map).world_to_pixel(d.robot.x, d.robot.y);
    let frame = renderer.render(&scene).unwrap();
    assert!((qx - rx).abs() < 1e-9 && (qy - ry).abs() < 1e-9);
    // The robot's body (light grey-blue, 0.45 m: about 86 px at this zoom) fills the
    // pixels behind its centre, between the wheels.
    let (hx, hy) = (
        libm::cos(d.robot.theta) * 30.0,
        -libm::sin(d.robot.theta) * 30.0,
    );
    let body = frame.pixel((qx - hx) as u32, (qy - hy) as u32).unwrap();
    assert!(body[2] > 180 && body[0] > 150, "{body:?}");
}

#[test]
fn the_trail_is_drawn_over_the_paths() {
    // The trail runs along the local path: where they overlap, the trail shows.
    let d = small_data();
    let along: Vec<(f64, f64)> = d.local[..d.local.len() / 2]
        .iter()
        .map(|&c| d.map.cell_center(c))
        .collect();
    let scene = Scene {
        trail: &along,
        layers: Layers {
            heat_map: false,
            control_points: false,
            robot: false,
            local_target: false,
            start_goal: false,
            ..Layers::ALL
        },
        ..full_scene(&d)
    };
    let frame = render(800, 600, &scene);
    let view = Renderer::new(800, 600).unwrap().view(&d.map);
    let teal = along
        .iter()
        .filter(|&&(x, y)| {
            let (px, py) = view.world_to_pixel(x, y);
            let [r, g, b, _] = frame.pixel(px as u32, py as u32).unwrap();
            g > r + 60 && b > r + 50
        })
        .count();
    assert!(
        teal * 10 >= along.len() * 9,
        "{teal} of {} trail points show",
        along.len()
    );
}

// ---------------------------------------------------------------------------------------
// Refused input: a clear error, the frame unchanged.

#[test]
fn bad_input_is_refused_and_the_frame_unchanged() {
    assert_eq!(
        Renderer::new(0, 10).unwrap_err(),
        RenderError::FrameSize {
            width: 0,
            height: 10,
            max: rtnav::render::MAX_FRAME_SIDE
        }
    );
    assert!(matches!(
        Renderer::new(10, 100_000),
        Err(RenderError::FrameSize { .. })
    ));
    let d = small_data();
    let mut renderer = Renderer::new(320, 200).unwrap();
    let good = renderer.render(&full_scene(&d)).unwrap().clone();
    assert!(matches!(
        renderer.resize(0, 0),
        Err(RenderError::FrameSize { .. })
    ));

    let nan_robot = Scene {
        robot: Some(RobotView::with_defaults(Pose::new(1.0, f64::NAN, 0.0))),
        ..full_scene(&d)
    };
    let e = renderer.render(&nan_robot).unwrap_err();
    assert!(matches!(
        e,
        RenderError::BadNumber {
            what: "robot.pose.y",
            index: None,
            ..
        }
    ));
    assert_eq!(e.to_string(), "scene robot.pose.y: NaN must be finite");

    let bad_radius = Scene {
        robot: Some(RobotView {
            body_radius: -1.0,
            ..RobotView::with_defaults(d.robot)
        }),
        ..full_scene(&d)
    };
    assert!(matches!(
        renderer.render(&bad_radius),
        Err(RenderError::BadNumber {
            what: "robot.body_radius",
            ..
        })
    ));
    let bad_dmin = Scene {
        dmin: f64::INFINITY,
        ..full_scene(&d)
    };
    assert!(matches!(
        renderer.render(&bad_dmin),
        Err(RenderError::BadNumber { what: "dmin", .. })
    ));
    let trail = [(0.0, 0.0), (f64::INFINITY, 1.0)];
    let bad_trail = Scene {
        trail: &trail,
        ..full_scene(&d)
    };
    assert!(matches!(
        renderer.render(&bad_trail),
        Err(RenderError::BadNumber {
            what: "trail",
            index: Some(1),
            ..
        })
    ));
    let outside = [(3, 3), (48, 2)];
    let bad_path = Scene {
        local_path: &outside,
        ..full_scene(&d)
    };
    assert_eq!(
        renderer.render(&bad_path).unwrap_err(),
        RenderError::CellOutside {
            what: "local_path",
            index: 1,
            x: 48,
            y: 2,
            width: 48,
            height: 32
        }
    );
    let short = Scene {
        field: Some(FieldView {
            potential: &d.potential[1..],
            state: &d.state,
            key: 1,
        }),
        ..full_scene(&d)
    };
    assert_eq!(
        renderer.render(&short).unwrap_err(),
        RenderError::FieldLength {
            what: "field.potential",
            len: 48 * 32 - 1,
            expected: 48 * 32
        }
    );
    let mut potential = d.potential.clone();
    let reached = d
        .state
        .iter()
        .position(|&s| s == FieldCellState::Reached)
        .unwrap();
    potential[reached] = f64::NAN;
    let nan_field = Scene {
        field: Some(FieldView {
            potential: &potential,
            state: &d.state,
            key: 99,
        }),
        ..full_scene(&d)
    };
    assert!(matches!(
        renderer.render(&nan_field),
        Err(RenderError::BadNumber {
            what: "field.potential",
            index: Some(i),
            ..
        }) if i == reached
    ));
    // Through all that the frame kept the last good drawing, and the renderer still works.
    assert_eq!(renderer.frame(), &good);
    assert_eq!(renderer.render(&full_scene(&d)).unwrap(), &good);
    // A scene error converts into the crate's error.
    let e: rtnav::Error = renderer.render(&bad_dmin).unwrap_err().into();
    assert!(matches!(e, rtnav::Error::Render(_)));
}

#[test]
fn far_away_things_and_tiny_frames_draw_without_error() {
    let d = small_data();
    let far = Pose::new(1e30, -1e30, 1e20);
    let trail = [(1e300, 0.0), (-1e300, 5.0), (0.0, 0.0)];
    let scene = Scene {
        robot: Some(RobotView::with_defaults(far)),
        start: Some(far),
        local_target: Some(far),
        trail: &trail,
        ..full_scene(&d)
    };
    for (w, h) in [(1, 1), (3, 200), (200, 3), (64, 48), (1000, 90)] {
        let frame = render(w, h, &scene);
        assert!(frame.data().chunks_exact(4).all(|p| p[3] == 255));
    }
}

// ---------------------------------------------------------------------------------------
// Layers as configuration.

#[test]
fn layers_default_to_all_on_and_refuse_unknown_names() {
    assert_eq!(Layers::default(), Layers::ALL);
    let l: Layers = serde_json::from_str(r#"{"heat_map": false, "trail": false}"#).unwrap();
    assert_eq!(
        l,
        Layers {
            heat_map: false,
            trail: false,
            ..Layers::ALL
        }
    );
    assert_eq!(serde_json::from_str::<Layers>("{}").unwrap(), Layers::ALL);
    let e = serde_json::from_str::<Layers>(r#"{"heatmap": false}"#).unwrap_err();
    assert!(e.to_string().contains("unknown field `heatmap`"), "{e}");
}

#[test]
fn after_arrival_the_drawn_direction_is_the_one_asked_for() {
    // open_field drives forward; inside TargetArea at the goal LocalPathPlanning picks the
    // direction by which side of the robot the goal's centre lies — after arrival that says
    // nothing about the drive, and the picture shows the direction asked for.
    use rtnav::data::RepoResolver;
    use rtnav::render::{FieldBuffers, scene_of};
    use rtnav::system::{OutcomeKind, Scenario, ScenarioRun};
    let text = std::fs::read_to_string("../fixtures/scenarios/open_field.json").unwrap();
    let scenario = Scenario::from_json(&text).unwrap();
    let mut run = ScenarioRun::new(&scenario, &RepoResolver::new("..")).unwrap();
    let mut backward_near_the_goal = false;
    while run.advance(20).is_none() {
        let s = run.system();
        if s.wiring().local_path_planning().direction() == Direction::Backward {
            backward_near_the_goal = true;
        }
    }
    assert_eq!(run.report().outcome.kind, OutcomeKind::Arrived);
    assert!(
        backward_near_the_goal,
        "the planner chose backward near the goal"
    );
    let s = run.system();
    assert!(s.mission().is_arrived());
    let mut buffers = FieldBuffers::default();
    let scene = scene_of(s, &mut buffers, "", Layers::ALL).unwrap();
    assert_eq!(s.mission().direction(), Direction::Forward);
    assert_eq!(scene.direction, Direction::Forward);
}

#[test]
fn the_renderer_says_when_a_frame_draws_from_its_cache() {
    // `draws_from_cache` is what the page asks before drawing after an expensive step: true
    // exactly when the map, the plan (field, route, local path, control points), the layers
    // and the view are those of the last frame.
    use rtnav::data::RepoResolver;
    use rtnav::system::{Input, Scenario, ScenarioRun, System};
    let text = std::fs::read_to_string("../fixtures/scenarios/appearing_obstacle.json").unwrap();
    let scenario = Scenario::from_json(&text).unwrap();
    let mut run = ScenarioRun::new(&scenario, &RepoResolver::new("..")).unwrap();
    let mut r = Renderer::new(320, 200).unwrap();
    assert!(
        !r.draws_from_cache(run.system(), Layers::ALL),
        "no frame yet"
    );
    type Drawn = (Time, u64, Vec<Cell>, Vec<Cell>, usize);
    let drawn_of = |s: &System| -> Drawn {
        let lpp = s.wiring().local_path_planning();
        (
            s.map().unwrap().version(),
            lpp.plan_count(),
            s.mission().route().to_vec(),
            lpp.merged_path().to_vec(),
            lpp.control_points().map_or(0, |c| c.points.len()),
        )
    };
    let (mut last, mut cached, mut redrawn) = (None::<Drawn>, 0, 0);
    // A frame every 50 ticks (the page's ~60 Hz at 3×); the obstacle that appears makes
    // the planners plan again.
    while run.advance(50).is_none() {
        let s = run.system();
        let now = drawn_of(s);
        let same = last.as_ref() == Some(&now);
        assert_eq!(
            r.draws_from_cache(s, Layers::ALL),
            same,
            "at {} s",
            s.time()
        );
        if same {
            cached += 1;
        } else {
            redrawn += 1;
        }
        r.render_system(s, "", Layers::ALL).unwrap();
        assert!(r.draws_from_cache(s, Layers::ALL));
        last = Some(now);
    }
    assert!(
        cached > 100 && redrawn >= 3,
        "{cached} cached, {redrawn} redrawn"
    );
    let mut s = run.into_system();
    r.render_system(&s, "", Layers::ALL).unwrap();
    assert!(r.draws_from_cache(&s, Layers::ALL));
    // Another layer set, another view, an edit of the map: the static layers are redrawn.
    let no_heat = Layers {
        heat_map: false,
        ..Layers::ALL
    };
    assert!(!r.draws_from_cache(&s, no_heat));
    s.apply(&Input::MapUpdate {
        cells: vec![(1, 1, 1)],
    })
    .unwrap();
    assert!(!r.draws_from_cache(&s, Layers::ALL), "after a MapUpdate");
    r.render_system(&s, "", Layers::ALL).unwrap();
    assert!(r.draws_from_cache(&s, Layers::ALL));
    let map = s.map().unwrap().clone();
    r.zoom_at(&map, 160.0, 100.0, 2.0);
    assert!(!r.draws_from_cache(&s, Layers::ALL), "after a zoom");
}
