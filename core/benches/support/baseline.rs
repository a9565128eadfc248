//! The `pathfinding` crate's A* on the same grid and rules as GlobalPathPlanning (8 moves,
//! octile costs, no corner cutting; its costs are integers, straight 2^32 and diagonal
//! round(√2 · 2^32)). For the benches only.

#![allow(dead_code)]

use std::hint::black_box;

use rtnav::global::AStar;
use rtnav::map::Cell;

const STRAIGHT: u64 = 1 << 32;
/// round(√2 · 2^32).
const DIAGONAL: u64 = 6_074_001_000;
const MOVES: [(i32, i32); 8] = [
    (1, 0),
    (0, 1),
    (-1, 0),
    (0, -1),
    (1, 1),
    (-1, 1),
    (-1, -1),
    (1, -1),
];

/// `pathfinding::astar` from `s` to `t` over the cells `grid` says are passable; the path
/// length in cells.
pub fn pathfinding_astar(grid: &AStar, s: Cell, t: Cell) -> f64 {
    let goal = (t.0 as i32, t.1 as i32);
    let free = |x: i32, y: i32| grid.is_passable(i64::from(x), i64::from(y));
    let (path, cost) = pathfinding::prelude::astar(
        &(s.0 as i32, s.1 as i32),
        |&(x, y)| {
            MOVES.iter().filter_map(move |&(dx, dy)| {
                let ok = free(x + dx, y + dy)
                    && (dx == 0 || dy == 0 || (free(x + dx, y) && free(x, y + dy)));
                ok.then(|| {
                    let c = if dx != 0 && dy != 0 {
                        DIAGONAL
                    } else {
                        STRAIGHT
                    };
                    ((x + dx, y + dy), c)
                })
            })
        },
        |&(x, y)| {
            let (dx, dy) = (x.abs_diff(goal.0), y.abs_diff(goal.1));
            u64::from(dx.abs_diff(dy)) * STRAIGHT + u64::from(dx.min(dy)) * DIAGONAL
        },
        |&c| c == goal,
    )
    .expect("solvable");
    black_box(path);
    cost as f64 / STRAIGHT as f64
}
