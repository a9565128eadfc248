//! Property test of the potential field and descent (000 §5.2.4.9–10, spec §3 steps 4–5)
//! on random maps: whenever a path exists in the `dmin`-inflated grid (8-connected, no
//! corner cutting) between two cells, the planner finds one, and it is valid; when none
//! exists, it reports no route.

use std::collections::VecDeque;

use proptest::prelude::*;
use rtnav::errors::LocalPathError;
use rtnav::interfaces::Direction;
use rtnav::local::{FieldExtent, FieldRequest, PotentialField, descend};
use rtnav::map::{Cell, GridMap};

/// Breadth-first search on the inflated grid, written independently of the planner.
fn reachable(map: &GridMap, dmin: f64, from: Cell, to: Cell) -> bool {
    let (w, h) = (map.width() as i64, map.height() as i64);
    let free = |x: i64, y: i64| {
        x >= 0 && y >= 0 && x < w && y < h && map.obstacle_distance((x as usize, y as usize)) > dmin
    };
    if !free(from.0 as i64, from.1 as i64) || !free(to.0 as i64, to.1 as i64) {
        return false;
    }
    let mut seen = vec![false; (w * h) as usize];
    let mut queue = VecDeque::from([from]);
    seen[from.0 + from.1 * w as usize] = true;
    while let Some((x, y)) = queue.pop_front() {
        if (x, y) == to {
            return true;
        }
        let (x, y) = (x as i64, y as i64);
        for dx in -1..=1 {
            for dy in -1..=1 {
                let (nx, ny) = (x + dx, y + dy);
                if (dx, dy) == (0, 0) || !free(nx, ny) {
                    continue;
                }
                if dx != 0 && dy != 0 && !(free(nx, y) && free(x, ny)) {
                    continue;
                }
                let i = (nx + ny * w) as usize;
                if !seen[i] {
                    seen[i] = true;
                    queue.push_back((nx as usize, ny as usize));
                }
            }
        }
    }
    false
}

fn valid(map: &GridMap, dmin: f64, path: &[Cell], from: Cell, to: Cell) -> Result<(), String> {
    if path.first() != Some(&from) || path.last() != Some(&to) {
        return Err(format!("ends {:?} {:?}", path.first(), path.last()));
    }
    for &c in path {
        if map.obstacle_distance(c) <= dmin {
            return Err(format!("{c:?} within dmin"));
        }
    }
    for w in path.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (dx, dy) = (b.0 as i64 - a.0 as i64, b.1 as i64 - a.1 as i64);
        if dx.abs() > 1 || dy.abs() > 1 || (dx, dy) == (0, 0) {
            return Err(format!("{a:?}→{b:?} is not a step"));
        }
        if dx != 0
            && dy != 0
            && (map.obstacle_distance((b.0, a.1)) <= dmin
                || map.obstacle_distance((a.0, b.1)) <= dmin)
        {
            return Err(format!("{a:?}→{b:?} cuts a corner"));
        }
    }
    let mut seen = path.to_vec();
    seen.sort_unstable();
    seen.dedup();
    if seen.len() != path.len() {
        return Err("a cell repeats".to_owned());
    }
    Ok(())
}

#[derive(Debug, Clone)]
struct Case {
    w: usize,
    h: usize,
    cells: Vec<u8>,
    g: f64,
    dmin_cells: f64,
    from: Cell,
    to: Cell,
    hs: f64,
    ht: f64,
    pcl: f64,
    posture: bool,
    backward: bool,
}

fn case() -> impl Strategy<Value = Case> {
    (
        4usize..18,
        4usize..18,
        prop::sample::select(vec![1.0, 0.5, 0.05]),
        prop::sample::select(vec![0.15, 0.25, 0.35]),
    )
        .prop_flat_map(|(w, h, g, density)| {
            (
                prop::collection::vec(prop::bool::weighted(density), w * h),
                prop::sample::select(vec![0.0, 1.0, 1.5]),
                (0..w, 0..h, 0..w, 0..h),
                (-4.0f64..4.0, -4.0f64..4.0, 0.0f64..=100.0),
                (any::<bool>(), any::<bool>()),
            )
                .prop_map(
                    move |(
                        obst,
                        dmin_cells,
                        (fx, fy, tx, ty),
                        (hs, ht, pcl),
                        (posture, backward),
                    )| {
                        // Free the 5 × 5 squares around the two cells, so that most cases have
                        // both passable and the interesting question is the route between them.
                        let mut cells: Vec<u8> = obst.into_iter().map(u8::from).collect();
                        for (cx, cy) in [(fx, fy), (tx, ty)] {
                            for y in cy.saturating_sub(2)..(cy + 3).min(h) {
                                for x in cx.saturating_sub(2)..(cx + 3).min(w) {
                                    cells[x + y * w] = 0;
                                }
                            }
                        }
                        Case {
                            w,
                            h,
                            cells,
                            g,
                            dmin_cells,
                            from: (fx, fy),
                            to: (tx, ty),
                            hs,
                            ht,
                            pcl,
                            posture,
                            backward,
                        }
                    },
                )
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn s5_2_4_9_a_path_is_found_whenever_one_exists_and_it_is_valid(c in case()) {
        let map = GridMap::new(c.w, c.h, c.g, (0.0, 0.0), c.cells.clone()).unwrap();
        let dmin = c.dmin_cells * c.g;
        let request = FieldRequest {
            target: c.to,
            current: c.from,
            current_heading: c.hs,
            target_heading: c.ht,
            direction: if c.backward { Direction::Backward } else { Direction::Forward },
            dmin,
            posture_consideration_level: c.pcl,
            posture: c.posture,
            extent: FieldExtent::Full,
        };
        let mut full = PotentialField::new();
        let result = full.compute(&map, &request);
        let exists = reachable(&map, dmin, c.from, c.to);
        if map.obstacle_distance(c.to) <= dmin {
            prop_assert_eq!(result, Err(LocalPathError::TargetBlocked { from: c.to }));
        } else if !exists {
            prop_assert_eq!(result, Err(LocalPathError::NoRoute { target: c.to, current: c.from }));
        } else {
            prop_assert_eq!(result, Ok(()));
            let path = descend(&full, c.from).unwrap();
            if let Err(e) = valid(&map, dmin, &path, c.from, c.to) {
                return Err(TestCaseError::fail(format!("{e}: {path:?}")));
            }
            // Stopping at the current cell gives the same path.
            let mut part = PotentialField::new();
            part.compute(&map, &FieldRequest { extent: FieldExtent::UntilCurrent, ..request }).unwrap();
            prop_assert_eq!(descend(&part, c.from).unwrap(), path);
        }
    }
}
