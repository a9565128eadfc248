//! spec §3 step 4: the fast potential field equals the reference implementation
//! (`rtnav::local::reference`, the field as first written) bit for bit — every cell's
//! potential, parts, length, state, parent and rank, the counts, and the descent — on random
//! maps and requests (proptest), also when one field's buffers are reused across requests
//! and across `MapUpdate`s of the same map (the impassable marks are then kept and redone
//! only where the distances changed).

use proptest::prelude::*;
use rtnav::interfaces::Direction;
use rtnav::local::reference::{self, ReferenceField};
use rtnav::local::{CellState, FieldExtent, FieldRequest, PotentialField, descend};
use rtnav::map::NEIGHBOURS;
use rtnav::map::{Cell, GridMap, MapUpdate};
use rtnav::rtc::Time;

/// The descent as first written: the neighbour with the lowest `(G, rank)` key below the
/// current one, diagonal corners checked, from the reference field.
fn reference_descent(f: &ReferenceField, target: Cell, from: Cell) -> Option<Vec<Cell>> {
    let (w, h) = (f.width as i64, f.height as i64);
    let key = |c: Cell| -> Option<(f64, u32)> {
        let i = c.0 + c.1 * f.width;
        (f.state[i] == CellState::Reached)
            .then(|| (f.cells[i].potential, f.cells[i].rank.unwrap_or(u32::MAX)))
    };
    let state = |x: i64, y: i64| f.state[(x + y * w) as usize];
    let less = |a: (f64, u32), b: (f64, u32)| a.0 < b.0 || (a.0 == b.0 && a.1 < b.1);
    let mut k = key(from)?;
    let mut path = vec![from];
    let mut cell = from;
    while cell != target {
        if path.len() > f.reached {
            return None;
        }
        let (x, y) = (cell.0 as i64, cell.1 as i64);
        let mut best: Option<(Cell, (f64, u32))> = None;
        for (dx, dy) in NEIGHBOURS {
            let (nx, ny) = (x + dx, y + dy);
            if nx < 0 || ny < 0 || nx >= w || ny >= h {
                continue;
            }
            let n = (nx as usize, ny as usize);
            let Some(kn) = key(n) else { continue };
            if dx != 0
                && dy != 0
                && (state(x + dx, y) == CellState::Impassable
                    || state(x, y + dy) == CellState::Impassable)
            {
                continue;
            }
            if less(kn, k) && best.is_none_or(|(_, b)| less(kn, b)) {
                best = Some((n, kn));
            }
        }
        let (n, kn) = best?;
        path.push(n);
        cell = n;
        k = kn;
    }
    Some(path)
}

/// Checks `fast` (just computed for `req` with result `result`) against the reference.
fn same(
    map: &GridMap,
    req: &FieldRequest,
    fast: &PotentialField,
    result: Result<(), rtnav::errors::LocalPathError>,
) -> Result<(), TestCaseError> {
    let reference = reference::compute(map, req);
    let r = match reference {
        Err(e) => {
            prop_assert_eq!(result, Err(e));
            return Ok(());
        }
        Ok(r) => r,
    };
    prop_assert_eq!(result.is_ok(), r.current_reached);
    prop_assert_eq!(fast.finalized_count(), r.finalized);
    prop_assert_eq!(fast.reached_count(), r.reached);
    prop_assert_eq!(fast.is_complete(), r.complete);
    prop_assert_eq!(fast.current_reached(), r.current_reached);
    for y in 0..map.height() {
        for x in 0..map.width() {
            let i = x + y * map.width();
            let (a, b) = (fast.info((x, y)).unwrap(), &r.cells[i]);
            let what = format!("cell ({x}, {y})");
            prop_assert_eq!(a.state, r.state[i], "{}", what);
            prop_assert_eq!(a.potential.to_bits(), b.potential.to_bits(), "{} G", what);
            prop_assert_eq!(a.repulsion.to_bits(), b.repulsion.to_bits(), "{} R", what);
            prop_assert_eq!(a.attraction.to_bits(), b.attraction.to_bits(), "{} A", what);
            prop_assert_eq!(a.posture.to_bits(), b.posture.to_bits(), "{} P", what);
            prop_assert_eq!(a.length.to_bits(), b.length.to_bits(), "{} L", what);
            prop_assert_eq!(a.rank, b.rank, "{} rank", what);
            let parent = b.parent.map(|k| {
                let (dx, dy) = NEIGHBOURS[k as usize];
                ((x as i64 - dx) as usize, (y as i64 - dy) as usize)
            });
            prop_assert_eq!(a.parent, parent, "{} parent", what);
            prop_assert_eq!(fast.state((x, y)) as u8, r.state[i] as u8, "{} code", what);
        }
    }
    let path = descend(fast, req.current).ok();
    prop_assert_eq!(path, reference_descent(&r, req.target, req.current));
    Ok(())
}

fn arb_map() -> impl Strategy<Value = GridMap> {
    (
        4usize..=40,
        4usize..=40,
        0u32..=35,
        prop::sample::select(vec![0.05, 0.1, 0.25]),
        any::<u64>(),
    )
        .prop_map(|(w, h, density, g, seed)| {
            let mut s = seed;
            let cells = (0..w * h)
                .map(|_| {
                    s = s
                        .wrapping_mul(6_364_136_223_846_793_005)
                        .wrapping_add(1_442_695_040_888_963_407);
                    u8::from((s >> 33) % 100 < u64::from(density))
                })
                .collect();
            GridMap::new(w, h, g, (0.0, 0.0), cells).unwrap()
        })
}

#[derive(Debug, Clone)]
struct Knobs {
    target: (f64, f64),
    current: (f64, f64),
    current_heading: f64,
    target_heading: f64,
    backward: bool,
    dmin: f64,
    pcl: f64,
    posture: bool,
    full: bool,
}

fn arb_knobs() -> impl Strategy<Value = Knobs> {
    (
        (0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64),
        (-7.0..7.0f64, -7.0..7.0f64),
        any::<bool>(),
        prop_oneof![Just(0.0), Just(0.1), Just(0.3), 0.0..0.6f64],
        prop_oneof![Just(0.0), Just(85.0), Just(100.0), 0.0..=100.0f64],
        any::<bool>(),
        any::<bool>(),
    )
        .prop_map(
            |((tx, ty, cx, cy), (hc, ht), backward, dmin, pcl, posture, full)| Knobs {
                target: (tx, ty),
                current: (cx, cy),
                current_heading: hc,
                target_heading: ht,
                backward,
                dmin,
                pcl,
                posture,
                full,
            },
        )
}

fn request(map: &GridMap, k: &Knobs) -> FieldRequest {
    let cell = |(fx, fy): (f64, f64)| {
        (
            ((fx * map.width() as f64) as usize).min(map.width() - 1),
            ((fy * map.height() as f64) as usize).min(map.height() - 1),
        )
    };
    FieldRequest {
        target: cell(k.target),
        current: cell(k.current),
        current_heading: k.current_heading,
        target_heading: k.target_heading,
        direction: if k.backward {
            Direction::Backward
        } else {
            Direction::Forward
        },
        dmin: k.dmin,
        posture_consideration_level: k.pcl,
        posture: k.posture,
        extent: if k.full {
            FieldExtent::Full
        } else {
            FieldExtent::UntilCurrent
        },
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// One fresh field per request.
    #[test]
    fn a_fresh_field_equals_the_reference(map in arb_map(), k in arb_knobs()) {
        let req = request(&map, &k);
        let mut f = PotentialField::new();
        let result = f.compute(&map, &req);
        same(&map, &req, &f, result)?;
    }

    /// One field reused: several requests, with `MapUpdate`s (brushes, set and cleared)
    /// and `dmin` changes in between.
    #[test]
    fn a_reused_field_equals_the_reference(
        map in arb_map(),
        steps in prop::collection::vec(
            (arb_knobs(), prop::collection::vec((0.0..1.0f64, 0.0..1.0f64, 0u8..3, any::<bool>()), 0..4)),
            1..6,
        ),
    ) {
        let mut map = map;
        let mut f = PotentialField::new();
        for (n, (k, brushes)) in steps.iter().enumerate() {
            for &(bx, by, r, v) in brushes {
                let (cx, cy) = ((bx * map.width() as f64) as i32, (by * map.height() as f64) as i32);
                let (mut xs, mut ys) = (Vec::new(), Vec::new());
                for dy in -i32::from(r)..=i32::from(r) {
                    for dx in -i32::from(r)..=i32::from(r) {
                        let (x, y) = (cx + dx, cy + dy);
                        if x >= 0 && y >= 0 && (x as usize) < map.width() && (y as usize) < map.height() {
                            xs.push(x);
                            ys.push(y);
                        }
                    }
                }
                let value = vec![i16::from(v); xs.len()];
                let num = xs.len() as i32;
                let tm = Time { sec: n as u32, nsec: 0 };
                map.map_update(&MapUpdate { x: xs, y: ys, value, num, tm })
                    .unwrap();
            }
            let req = request(&map, k);
            let result = f.compute(&map, &req);
            same(&map, &req, &f, result)?;
        }
    }
}

/// A map replaced by another of the same size, and a clone updated apart from its original:
/// the marks never come from the wrong map.
#[test]
fn marks_follow_the_map_not_its_size() {
    let open = GridMap::new(20, 20, 0.1, (0.0, 0.0), vec![0; 400]).unwrap();
    let mut walled = open.clone();
    walled
        .map_update(&MapUpdate {
            x: (0..20).collect(),
            y: vec![10; 20],
            value: vec![1; 20],
            num: 20,
            tm: Time::default(),
        })
        .unwrap();
    let req = FieldRequest {
        target: (10, 3),
        current: (10, 17),
        current_heading: 0.0,
        target_heading: 0.0,
        direction: Direction::Forward,
        dmin: 0.1,
        posture_consideration_level: 50.0,
        posture: true,
        extent: FieldExtent::Full,
    };
    let mut f = PotentialField::new();
    assert!(f.compute(&open, &req).is_ok());
    assert!(f.compute(&walled, &req).is_err(), "the wall separates them");
    assert!(f.compute(&open, &req).is_ok());
    assert_eq!(f.state((10, 10)), CellState::Reached);
}
