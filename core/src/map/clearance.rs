//! Obstacle clearance: the exact distance from the robot's centre to the nearest obstacle
//! cell (the cell's square, as the physics' bump test uses it; spec §5 "touching an obstacle
//! cell is a bump"), cells outside the map counting as obstacles (spec §2).

use super::GridMap;

/// The squared distance from `(x, y)` to the square with lower-left corner `(lx, ly)` and
/// side `g`.
fn square_d2(x: f64, y: f64, lx: f64, ly: f64, g: f64) -> f64 {
    let dx = x - x.clamp(lx, lx + g);
    let dy = y - y.clamp(ly, ly + g);
    dx * dx + dy * dy
}

/// The distance from `(x, y)` to the nearest obstacle square, exact: the square root of the
/// smallest squared distance, or the distance to the map's edge if that is smaller; 0 inside
/// an obstacle cell or outside the map. (One square root per call.)
///
/// Cells are visited in rings of growing Chebyshev distance `k` around the point's cell; a
/// cell of ring `k ≥ 1` is at least `(k − 1)·g` away, so the search stops once that bound
/// reaches the best distance found. The map's border is an obstacle at the distance to the
/// map's rectangle.
pub fn clearance(map: &GridMap, x: f64, y: f64) -> f64 {
    let g = map.grid_size();
    let (ox, oy) = map.origin();
    let (w, h) = (map.width() as i64, map.height() as i64);
    let Some((cx, cy)) = map.world_to_cell_signed(x, y) else {
        return 0.0;
    };
    if map.is_obstacle(cx, cy) {
        return 0.0;
    }
    // The region outside the map: the distance to the map's edges.
    let border = border_distance(map, x, y);
    let mut best_d2 = f64::INFINITY;
    let mut k: i64 = 1;
    loop {
        let reach = (k - 1) as f64 * g;
        if reach >= border || reach * reach >= best_d2 {
            break;
        }
        let (x0, x1, y0, y1) = (cx - k, cx + k, cy - k, cy + k);
        if x0 < 0 && y0 < 0 && x1 >= w && y1 >= h {
            break;
        }
        let mut visit = |i: i64, j: i64| {
            if (0..w).contains(&i) && (0..h).contains(&j) && map.is_obstacle(i, j) {
                let d2 = square_d2(x, y, ox + i as f64 * g, oy + j as f64 * g, g);
                if d2 < best_d2 {
                    best_d2 = d2;
                }
            }
        };
        for i in x0..=x1 {
            visit(i, y0);
            visit(i, y1);
        }
        for j in y0 + 1..y1 {
            visit(x0, j);
            visit(x1, j);
        }
        k += 1;
    }
    border.min(f64::sqrt(best_d2))
}

/// A lower bound of [`clearance`] from the distance transform alone (one look-up): the
/// point lies `|p − centre|` from its cell's centre, and an obstacle square within `g·√2/2`
/// of its own centre.
pub fn clearance_lower_bound(map: &GridMap, x: f64, y: f64) -> f64 {
    match map.world_to_cell(x, y) {
        Some(c) => {
            let (cx, cy) = map.cell_center(c);
            map.obstacle_distance(c)
                - f64::sqrt((x - cx) * (x - cx) + (y - cy) * (y - cy))
                - map.grid_size() * core::f64::consts::FRAC_1_SQRT_2
        }
        None => 0.0,
    }
}

/// Whether [`clearance_lower_bound`] is below `value`, without a square root: with
/// `a = d(c) − g/√2 − value`, the bound `d(c) − |p − c| − g/√2 < value` holds when `a < 0` or
/// `a² < |p − c|²`.
pub fn could_be_below(map: &GridMap, x: f64, y: f64, value: f64) -> bool {
    match map.world_to_cell(x, y) {
        Some(c) => {
            let (cx, cy) = map.cell_center(c);
            let a = map.obstacle_distance(c)
                - map.grid_size() * core::f64::consts::FRAC_1_SQRT_2
                - value;
            a < 0.0 || a * a < (x - cx) * (x - cx) + (y - cy) * (y - cy)
        }
        None => true,
    }
}

/// [`clearance`] along a path, fast: the obstacle squares near an *anchor* point are
/// collected once, and every point within `margin / 2` of the anchor is measured against
/// them only. The result is the same as [`clearance`]'s, bit for bit: the clearance is
/// 1-Lipschitz, so for a point `p` with `|p − a| ≤ margin/2` the nearest square lies within
/// `clearance(a) + margin` of the anchor `a`, and every square that near was collected.
#[derive(Debug, Clone, Default)]
pub struct ClearanceTracker {
    anchor: Option<(f64, f64)>,
    key: u64,
    /// Lower-left corners of the collected obstacle squares.
    squares: Vec<(f64, f64)>,
}

/// How far \[m\] beyond the anchor's clearance obstacle squares are collected.
const MARGIN: f64 = 0.2;

impl ClearanceTracker {
    /// An empty tracker.
    pub fn new() -> Self {
        Self::default()
    }

    /// The clearance of `(x, y)` on `map`; `key` must change whenever the map's cells do.
    pub fn clearance(&mut self, map: &GridMap, key: u64, x: f64, y: f64) -> f64 {
        let g = map.grid_size();
        let near = self.anchor.is_some_and(|(ax, ay)| {
            (x - ax) * (x - ax) + (y - ay) * (y - ay) <= (MARGIN / 2.0) * (MARGIN / 2.0)
        });
        if !near || key != self.key {
            let c = clearance(map, x, y);
            self.collect(map, x, y, c + MARGIN);
            self.anchor = Some((x, y));
            self.key = key;
            return c;
        }
        let Some((cx, cy)) = map.world_to_cell_signed(x, y) else {
            return 0.0;
        };
        if map.is_obstacle(cx, cy) {
            return 0.0;
        }
        let mut best_d2 = f64::INFINITY;
        for &(lx, ly) in &self.squares {
            let d2 = square_d2(x, y, lx, ly, g);
            if d2 < best_d2 {
                best_d2 = d2;
            }
        }
        border_distance(map, x, y).min(f64::sqrt(best_d2))
    }

    /// Collects every in-map obstacle square within `radius` of `(x, y)`.
    fn collect(&mut self, map: &GridMap, x: f64, y: f64, radius: f64) {
        self.squares.clear();
        let g = map.grid_size();
        let (ox, oy) = map.origin();
        let (Some((x0, y0)), Some((x1, y1))) = (
            map.world_to_cell_signed(x - radius, y - radius),
            map.world_to_cell_signed(x + radius, y + radius),
        ) else {
            return;
        };
        let (w, h) = (map.width() as i64, map.height() as i64);
        for j in y0.max(0)..=y1.min(h - 1) {
            for i in x0.max(0)..=x1.min(w - 1) {
                if map.is_obstacle(i, j) {
                    let (lx, ly) = (ox + i as f64 * g, oy + j as f64 * g);
                    if square_d2(x, y, lx, ly, g) <= radius * radius {
                        self.squares.push((lx, ly));
                    }
                }
            }
        }
    }
}

/// Distance from a point inside the map to the map's edges (outside counts as obstacle).
fn border_distance(map: &GridMap, x: f64, y: f64) -> f64 {
    let g = map.grid_size();
    let (ox, oy) = map.origin();
    (x - ox)
        .min(ox + map.width() as f64 * g - x)
        .min(y - oy)
        .min(oy + map.height() as f64 * g - y)
        .max(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Brute force over every cell, and the map's edges.
    fn brute(map: &GridMap, x: f64, y: f64) -> f64 {
        let g = map.grid_size();
        let (ox, oy) = map.origin();
        let (w, h) = (map.width() as f64, map.height() as f64);
        let border = (x - ox)
            .min(ox + w * g - x)
            .min(y - oy)
            .min(oy + h * g - y)
            .max(0.0);
        let mut best_d2 = f64::INFINITY;
        for j in 0..map.height() as i64 {
            for i in 0..map.width() as i64 {
                if map.is_obstacle(i, j) {
                    let (lx, ly) = (ox + i as f64 * g, oy + j as f64 * g);
                    best_d2 = best_d2.min(square_d2(x, y, lx, ly, g));
                }
            }
        }
        border.min(f64::sqrt(best_d2))
    }

    #[test]
    fn ring_search_equals_brute_force() {
        let mut cells = vec![0i16; 30 * 20];
        for (x, y) in [(5, 5), (6, 5), (20, 3), (12, 15), (29, 10)] {
            cells[x + y * 30] = 1;
        }
        let map = GridMap::from_map_data(&cells, 30, 20, 0.1).unwrap();
        let mut k = 0u32;
        for j in 0..40 {
            for i in 0..60 {
                let (x, y) = (0.003 + i as f64 * 0.05, 0.007 + j as f64 * 0.05);
                let c = clearance(&map, x, y);
                assert_eq!(c, brute(&map, x, y), "({x}, {y})");
                let lb = clearance_lower_bound(&map, x, y);
                assert!(lb <= c + 1e-12);
                for v in [lb - 1e-9, lb + 1e-9, c, f64::INFINITY] {
                    assert_eq!(
                        could_be_below(&map, x, y, v),
                        lb < v || (lb - v).abs() < 1e-12
                    );
                }
                k += 1;
            }
        }
        assert_eq!(k, 2400);
        assert_eq!(clearance(&map, 0.55, 0.55), 0.0, "inside an obstacle");
        assert_eq!(clearance(&map, -1.0, 0.5), 0.0, "outside the map");
        // Beside the obstacle at (5, 5): its square spans x ∈ [0.5, 0.6].
        assert!((clearance(&map, 0.45, 0.55) - 0.05).abs() < 1e-12);
    }

    #[test]
    fn the_tracker_equals_the_ring_search_along_a_path() {
        let mut cells = vec![0i16; 40 * 30];
        for k in 0..40 {
            cells[k + 12 * 40] = i16::from(k % 7 != 3);
        }
        cells[20 + 20 * 40] = 1;
        let map = GridMap::from_map_data(&cells, 40, 30, 0.1).unwrap();
        let mut t = ClearanceTracker::new();
        for k in 0..4000 {
            let s = k as f64 * 0.001;
            let (x, y) = (0.2 + s * 0.9, 0.3 + 2.4 * libm::sin(s));
            assert_eq!(
                t.clearance(&map, 1, x, y),
                clearance(&map, x, y),
                "({x}, {y})"
            );
        }
    }
}
