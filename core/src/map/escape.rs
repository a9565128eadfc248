//! Escape from the margin (spec §3 Decision 0.2): the shortest way out of the `dmin` zone for
//! a robot that stands inside it without standing on an obstacle.
//!
//! Tracking, a `MapUpdate` or rounding can leave the robot's cell within `dmin` of an
//! obstacle. The planners treat such cells as impassable, so without a way out the robot
//! would refuse every plan for good. Both planners start their route with the step sequence
//! this module finds, then plan from its last cell as usual.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use super::{Cell, GridMap, ORTHOGONAL_FIRST};

/// The shortest route in metres (octile steps) from `from` to the nearest cell that is not
/// within `dmin` of an obstacle, through cells that are not obstacles, never cutting the
/// corner of an obstacle cell: `[from, …, exit]`. `Some(vec![from])` if `from` is already
/// clear; `None` if `from` is an obstacle or outside the map, or no clear cell can be
/// reached. Ties go to the cell found first (neighbours in a fixed order), so the result is
/// deterministic.
pub fn escape_route(map: &GridMap, from: Cell, dmin: f64) -> Option<Vec<Cell>> {
    let (fx, fy) = (from.0 as i64, from.1 as i64);
    if !map.contains(fx, fy) || map.is_obstacle(fx, fy) {
        return None;
    }
    if map.is_clear(from, dmin) {
        return Some(vec![from]);
    }
    let g = map.grid_size();
    // Cells settled or queued: index → (cost, parent). The zone within dmin is small (a band
    // around obstacles), so an ordered map of what is touched is enough.
    let mut seen: std::collections::BTreeMap<usize, (f64, Option<Cell>)> = Default::default();
    // (cost bits, insertion order, cell): costs are non-negative, so their bits order them.
    let mut queue: BinaryHeap<Reverse<(u64, u64, Cell)>> = BinaryHeap::new();
    let mut order = 0u64;
    seen.insert(map.index(from), (0.0, None));
    queue.push(Reverse((0f64.to_bits(), order, from)));
    while let Some(Reverse((bits, _, cell))) = queue.pop() {
        let cost = f64::from_bits(bits);
        if seen.get(&map.index(cell)).is_some_and(|&(c, _)| c < cost) {
            continue;
        }
        if map.is_clear(cell, dmin) {
            let mut route = vec![cell];
            let mut at = cell;
            while let Some(&(_, Some(parent))) = seen.get(&map.index(at)) {
                route.push(parent);
                at = parent;
            }
            route.reverse();
            return Some(route);
        }
        let (cx, cy) = (cell.0 as i64, cell.1 as i64);
        for (dx, dy) in ORTHOGONAL_FIRST {
            let (nx, ny) = (cx + dx, cy + dy);
            if !map.contains(nx, ny) || map.is_obstacle(nx, ny) {
                continue;
            }
            let diagonal = dx != 0 && dy != 0;
            if diagonal && (map.is_obstacle(cx + dx, cy) || map.is_obstacle(cx, cy + dy)) {
                continue;
            }
            let next = (nx as usize, ny as usize);
            let step = if diagonal {
                core::f64::consts::SQRT_2 * g
            } else {
                g
            };
            let c = cost + step;
            let better = seen.get(&map.index(next)).is_none_or(|&(old, _)| c < old);
            if better {
                seen.insert(map.index(next), (c, Some(cell)));
                order += 1;
                queue.push(Reverse((c.to_bits(), order, next)));
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn map(rows: &[&str]) -> GridMap {
        // Row 0 of `rows` is the top (largest y).
        let h = rows.len();
        let w = rows[0].len();
        let mut data = vec![0i16; w * h];
        for (r, row) in rows.iter().enumerate() {
            for (x, ch) in row.bytes().enumerate() {
                if ch == b'#' {
                    data[x + (h - 1 - r) * w] = 1;
                }
            }
        }
        GridMap::from_map_data(&data, w as i32, h as i32, 1.0).unwrap()
    }

    /// A 9 × 9 room of free cells with one obstacle at `(3, 4)`; beyond the room's edge
    /// counts as obstacle (spec §2), 4 cells from the obstacle.
    fn room() -> GridMap {
        let mut rows = vec![".........".to_owned(); 9];
        rows[4] = "...#.....".to_owned();
        let rows: Vec<&str> = rows.iter().map(String::as_str).collect();
        map(&rows)
    }

    #[test]
    fn a_clear_cell_needs_no_escape_and_an_obstacle_has_none() {
        let m = room();
        assert!(m.is_clear((6, 4), 1.5));
        assert_eq!(escape_route(&m, (6, 4), 1.5), Some(vec![(6, 4)]));
        assert_eq!(escape_route(&m, (3, 4), 1.5), None);
        assert_eq!(escape_route(&m, (20, 4), 1.5), None, "outside the map");
    }

    #[test]
    fn the_route_leads_to_the_nearest_clear_cell() {
        // dmin 1.5: within it are the obstacle's 8 neighbours; (4, 4) is one, and the
        // nearest clear cell from it is one straight step east, (5, 4).
        let m = room();
        assert!(!m.is_clear((4, 4), 1.5));
        assert_eq!(escape_route(&m, (4, 4), 1.5), Some(vec![(4, 4), (5, 4)]));
        // From a diagonal neighbour the way out ends on a clear cell, through the zone only.
        let r = escape_route(&m, (2, 3), 1.5).unwrap();
        assert_eq!(r.first(), Some(&(2, 3)));
        assert!(m.is_clear(*r.last().unwrap(), 1.5));
        assert!(r[..r.len() - 1].iter().all(|&c| !m.is_clear(c, 1.5)));
        assert!(r.len() <= 3);
    }

    #[test]
    fn no_clear_cell_means_no_escape() {
        let m = map(&["#.#", "...", "#.#"]);
        assert_eq!(escape_route(&m, (1, 1), 5.0), None);
    }
}
