//! spec §2 and §5 after `MapUpdate`s, as the page paints them: brushes set and cleared on
//! maps with long distances (sparse obstacles, so a change reaches far).
//! - The obstacle distances, updated only where a change can reach, equal a map built
//!   afresh from the same cells (proptest).
//! - GlobalPathPlanning's planner brought up to date with `AStar::sync` plans exactly as
//!   a planner made afresh: same length, same path.

use proptest::prelude::*;
use rtnav::global::AStar;
use rtnav::map::{GridMap, MapUpdate};
use rtnav::rtc::Time;

fn sparse_map(w: usize, h: usize, seed: u64, per_mille: u64) -> GridMap {
    let mut s = seed;
    let cells = (0..w * h)
        .map(|_| {
            s = s
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            u8::from((s >> 33) % 1000 < per_mille)
        })
        .collect();
    GridMap::new(w, h, 0.05, (0.0, 0.0), cells).unwrap()
}

/// A square brush of radius `r` at `(cx, cy)` (clipped), all cells set to `v`.
fn brush(map: &mut GridMap, cx: usize, cy: usize, r: usize, v: bool, n: u32) {
    let (mut xs, mut ys) = (Vec::new(), Vec::new());
    for y in cy.saturating_sub(r)..=(cy + r).min(map.height() - 1) {
        for x in cx.saturating_sub(r)..=(cx + r).min(map.width() - 1) {
            xs.push(x as i32);
            ys.push(y as i32);
        }
    }
    let value = vec![i16::from(v); xs.len()];
    let num = xs.len() as i32;
    let tm = Time { sec: n, nsec: 0 };
    map.map_update(&MapUpdate {
        x: xs,
        y: ys,
        value,
        num,
        tm,
    })
    .unwrap();
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(60))]

    #[test]
    fn distances_after_brushes_equal_a_fresh_map(
        w in 20usize..160,
        h in 20usize..160,
        seed in any::<u64>(),
        per_mille in 0u64..30,
        strokes in prop::collection::vec((0.0..1.0f64, 0.0..1.0f64, 0usize..4, any::<bool>()), 1..12),
    ) {
        let mut map = sparse_map(w, h, seed, per_mille);
        for (n, &(fx, fy, r, v)) in strokes.iter().enumerate() {
            let (cx, cy) = ((fx * w as f64) as usize, (fy * h as f64) as usize);
            brush(&mut map, cx.min(w - 1), cy.min(h - 1), r, v, n as u32);
            let fresh = GridMap::new(w, h, 0.05, (0.0, 0.0), map.cells().to_vec()).unwrap();
            prop_assert_eq!(map.distances(), fresh.distances());
        }
    }

    #[test]
    fn a_synced_planner_plans_as_a_fresh_one(
        w in 20usize..120,
        h in 20usize..120,
        seed in any::<u64>(),
        strokes in prop::collection::vec((0.0..1.0f64, 0.0..1.0f64, 0usize..4, any::<bool>()), 1..6),
        ends in prop::collection::vec((0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64), 4),
        dmin in prop_oneof![Just(0.0), Just(0.05), Just(0.12)],
    ) {
        let mut map = sparse_map(w, h, seed, 60);
        let mut kept = AStar::new(&map, dmin).unwrap();
        let cell = |fx: f64, fy: f64| (((fx * w as f64) as usize).min(w - 1), ((fy * h as f64) as usize).min(h - 1));
        for (n, &(fx, fy, r, v)) in strokes.iter().enumerate() {
            let (cx, cy) = cell(fx, fy);
            brush(&mut map, cx, cy, r, v, n as u32);
            kept.sync(&map);
            let mut fresh = AStar::new(&map, dmin).unwrap();
            prop_assert_eq!(kept.passable_count(), fresh.passable_count());
            for &(a, b, c, d) in &ends {
                let (s, t) = (cell(a, b), cell(c, d));
                prop_assert_eq!(kept.plan(s, t), fresh.plan(s, t));
            }
        }
    }
}

/// A planner synced with another map of the same size is that map's planner.
#[test]
fn sync_with_another_map_of_the_same_size_starts_over() {
    let open = GridMap::new(30, 30, 0.1, (0.0, 0.0), vec![0; 900]).unwrap();
    let mut walled_cells = vec![0u8; 900];
    for x in 0..30 {
        walled_cells[x + 15 * 30] = 1;
    }
    let walled = GridMap::new(30, 30, 0.1, (0.0, 0.0), walled_cells).unwrap();
    let mut a = AStar::new(&open, 0.0).unwrap();
    assert!(a.plan((5, 5), (5, 25)).is_ok());
    a.sync(&walled);
    assert!(a.plan((5, 5), (5, 25)).is_err());
    a.sync(&open);
    assert!(a.plan((5, 5), (5, 25)).is_ok());
}
