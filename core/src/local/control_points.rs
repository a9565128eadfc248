//! Control points of a grid path (000 §5.2.4.12, spec §3 step 7).

use crate::map::{Cell, GridMap};

/// The cells of `path` where the step direction changes (000 §5.2.4.12
/// "進行方向が変化する位置"), in order. The first and last cells are never corners.
pub fn corner_cells(path: &[Cell]) -> Vec<Cell> {
    let step = |a: Cell, b: Cell| (b.0 as i64 - a.0 as i64, b.1 as i64 - a.1 as i64);
    path.windows(3)
        .filter(|w| step(w[0], w[1]) != step(w[1], w[2]))
        .map(|w| w[1])
        .collect()
}

/// Whether `b` lies on the segment from `a` to `c`: the three are collinear (up to
/// rounding: `|ab × bc| ≤ 1e-9 · |ab| · |bc|`) and `b` is not a turn back (`ab · bc ≥ 0`).
/// A reversal A → B → back towards A is collinear too, but dropping B would change the
/// path, so it is kept.
fn on_segment(a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> bool {
    let (ux, uy) = (b.0 - a.0, b.1 - a.1);
    let (vx, vy) = (c.0 - b.0, c.1 - b.1);
    let cross = ux * vy - uy * vx;
    let dot = ux * vx + uy * vy;
    let scale = f64::sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy));
    cross.abs() <= 1e-9 * scale && dot >= 0.0
}

/// Drops the middle point of every three consecutive collinear points until none remain
/// (000 §5.2.4.12 "直線部分がある場合は中間の制御点を間引く"); the first and last points
/// always stay. Duplicate consecutive points count as collinear.
pub fn thin_collinear(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = Vec::with_capacity(points.len());
    for &p in points {
        while out.len() >= 2 && on_segment(out[out.len() - 2], out[out.len() - 1], p) {
            out.pop();
        }
        out.push(p);
    }
    out
}

/// The control points of a grid path (000 §5.2.4.12): the current position (exact), the
/// centre of every corner cell, the goal (exact), then collinear points thinned. An empty
/// path gives no points.
pub fn control_points(
    map: &GridMap,
    path: &[Cell],
    current: (f64, f64),
    goal: (f64, f64),
) -> Vec<(f64, f64)> {
    if path.is_empty() {
        return Vec::new();
    }
    let corners = corner_cells(path);
    let mut points = Vec::with_capacity(corners.len() + 2);
    points.push(current);
    points.extend(corners.into_iter().map(|c| map.cell_center(c)));
    points.push(goal);
    thin_collinear(&points)
}
