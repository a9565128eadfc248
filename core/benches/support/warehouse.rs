//! A generated warehouse the size of Nav2's warehouse map (1006 × 1674 cells of 0.03 m,
//! 30.18 m × 50.22 m, 1.68 M cells): outer walls, six double racks of shelves cut by cross
//! aisles, a walled office with a door, pillars and scattered pallets. Deterministic (a fixed
//! LCG), no files: benches and tests include this module by path
//! (`#[path = ".../core/benches/support/warehouse.rs"] mod warehouse;`).
//!
//! Everything is in cells; [`GRID`] is the cell size. The aisles are 2.7 m wide and the cross
//! aisles 2.4 m, so the default `dmin` (0.5 m) leaves a 1.7 m lane through each.

#![allow(dead_code)]

use rtnav::interfaces::Pose;
use rtnav::map::{Cell, GridMap};

/// Cells in x.
pub const WIDTH: usize = 1006;
/// Cells in y.
pub const HEIGHT: usize = 1674;
/// Cell size \[m\].
pub const GRID: f64 = 0.03;

/// The cells, x fastest, 1 = obstacle.
pub fn cells() -> Vec<u8> {
    let mut cells = vec![0u8; WIDTH * HEIGHT];
    let c = &mut cells[..];
    // Outer walls, 0.15 m.
    fill(c, 0, 0, WIDTH, 5);
    fill(c, 0, HEIGHT - 5, WIDTH, HEIGHT);
    fill(c, 0, 0, 5, HEIGHT);
    fill(c, WIDTH - 5, 0, WIDTH, HEIGHT);
    // Racks: 1.05 m deep, 2.7 m aisles, from x = 4.5 m; four blocks along y with 2.4 m
    // cross aisles between them (the last block shorter).
    for k in 0..6 {
        let x0 = 150 + k * 125;
        for (y0, y1) in [(200, 500), (580, 880), (960, 1260), (1340, 1480)] {
            fill(c, x0, y0, x0 + 35, y1);
            // A gap of 1.2 m in the middle of every other rack of the second block:
            // a short cut that a brush can close.
            if k % 2 == 1 && y0 == 580 {
                set(c, x0, 710, x0 + 35, 750, 0);
            }
        }
    }
    // The office, top left: a wall at y = 1540 from the left wall to x = 300, with a 1.5 m
    // door, and a wall at x = 300 up to the top wall.
    fill(c, 5, 1540, 130, 1545);
    fill(c, 180, 1540, 305, 1545);
    fill(c, 300, 1540, 305, HEIGHT - 5);
    // Pillars (0.39 m) every 6 m along the right-hand open zone and the loading zone.
    for y in (100..HEIGHT - 100).step_by(200) {
        fill(c, 900, y, 913, y + 13);
    }
    for x in (200..WIDTH - 100).step_by(200) {
        fill(c, x, 120, x + 13, 133);
    }
    // Pallets (0.9–1.2 m) in the loading zone and the top zone, a fixed LCG.
    let mut seed: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut next = |m: usize| {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((seed >> 33) as usize) % m
    };
    for _ in 0..14 {
        let (w, h) = (30 + next(11), 30 + next(11));
        let x = 330 + next(WIDTH - 330 - 60);
        let y = if next(2) == 0 {
            20 + next(40)
        } else {
            1500 + next(120)
        };
        fill(c, x, y, x + w, y + h);
    }
    cells
}

/// Sets the cells `[x0, x1) × [y0, y1)` (clipped to the map) to `v`.
fn set(c: &mut [u8], x0: usize, y0: usize, x1: usize, y1: usize, v: u8) {
    for y in y0..y1.min(HEIGHT) {
        c[y * WIDTH + x0.min(WIDTH)..y * WIDTH + x1.min(WIDTH)].fill(v);
    }
}

fn fill(c: &mut [u8], x0: usize, y0: usize, x1: usize, y1: usize) {
    set(c, x0, y0, x1, y1, 1);
}

/// The map, origin (0, 0).
pub fn map() -> GridMap {
    GridMap::new(WIDTH, HEIGHT, GRID, (0.0, 0.0), cells()).expect("a valid map")
}

/// Centre of a cell \[m\].
pub fn centre((x, y): Cell) -> (f64, f64) {
    ((x as f64 + 0.5) * GRID, (y as f64 + 0.5) * GRID)
}

/// The long route: from the office (top left) out of its door and through the racks to the
/// far corner of the loading zone (bottom right): about 62 m.
pub const LONG_START: Cell = (250, 1650);
/// Goal of the long route.
pub const LONG_GOAL: Cell = (975, 25);

/// A robot in the second rack aisle, heading up (+y), with a goal in the top zone: the
/// default local plan's situation.
pub fn aisle_start() -> Pose {
    let (x, y) = centre((230, 300));
    Pose::new(x, y, core::f64::consts::FRAC_PI_2)
}

/// The goal of [`aisle_start`].
pub fn aisle_goal() -> Pose {
    let (x, y) = centre((230, 1510));
    Pose::new(x, y, 0.0)
}
