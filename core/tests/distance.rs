//! spec §2: the grid map and its obstacle distances.
//! - The exact Euclidean distance transform equals a brute-force distance on random maps
//!   (proptest), also after random `MapUpdate`s (kept current incrementally).
//! - `SetMap` / `MapUpdate` refuse bad input with an error naming the problem, and change
//!   nothing.

use proptest::prelude::*;
use rtnav::errors::MapError;
use rtnav::map::{GridMap, MAX_CELLS, MapUpdate};
use rtnav::rtc::Time;

/// Brute force: metres from each cell centre to the nearest obstacle centre, the ring of
/// cells around the map counting as obstacles (spec §2), as `√d² · GridSize`.
fn brute(map: &GridMap) -> Vec<f64> {
    let (w, h) = (map.width() as i64, map.height() as i64);
    let mut out = Vec::with_capacity((w * h) as usize);
    for y in 0..h {
        for x in 0..w {
            let mut best = i64::MAX;
            for oy in -1..=h {
                for ox in -1..=w {
                    if map.is_obstacle(ox, oy) {
                        best = best.min((x - ox).pow(2) + (y - oy).pow(2));
                    }
                }
            }
            out.push(libm::sqrt(best as f64) * map.grid_size());
        }
    }
    out
}

/// Random maps: mostly up to 24 × 24, and some tall sparse ones (long column distances, so
/// the row phase uses its parabola envelope rather than the short scan).
fn arb_map() -> impl Strategy<Value = GridMap> {
    let size = prop_oneof![
        3 => (1usize..=24, 1usize..=24, 0u32..=100),
        1 => (1usize..=6, 60usize..=110, 0u32..=3),
    ];
    (size, prop::sample::select(vec![0.05, 0.1, 0.25, 1.0])).prop_flat_map(
        |((w, h, density), g)| {
            prop::collection::vec(0u32..100, w * h).prop_map(move |r| {
                let cells = r.iter().map(|&v| u8::from(v < density)).collect();
                GridMap::new(w, h, g, (0.0, 0.0), cells).unwrap()
            })
        },
    )
}

/// Batches of (x, y, value) updates, some with out-of-range indices filtered by the map.
fn arb_updates() -> impl Strategy<Value = Vec<Vec<(u8, u8, bool)>>> {
    prop::collection::vec(
        prop::collection::vec((0u8..24, 0u8..24, any::<bool>()), 1..12),
        1..6,
    )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn distance_transform_equals_brute_force(map in arb_map()) {
        prop_assert_eq!(map.distances(), &brute(&map)[..]);
    }

    #[test]
    fn distances_stay_exact_after_map_updates(map in arb_map(), batches in arb_updates()) {
        let mut map = map;
        for (n, batch) in batches.iter().enumerate() {
            let inside: Vec<_> = batch
                .iter()
                .filter(|(x, y, _)| usize::from(*x) < map.width() && usize::from(*y) < map.height())
                .collect();
            let xs: Vec<i32> = inside.iter().map(|u| i32::from(u.0)).collect();
            let ys: Vec<i32> = inside.iter().map(|u| i32::from(u.1)).collect();
            let vs: Vec<i16> = inside.iter().map(|u| i16::from(u.2)).collect();
            let tm = Time { sec: n as u32 + 1, nsec: 7 };
            map.map_update(&MapUpdate { x: xs.to_vec(), y: ys.to_vec(), value: vs.to_vec(), num: xs.len() as i32, tm }).unwrap();
            prop_assert_eq!(map.version(), tm);
            prop_assert_eq!(map.distances(), &brute(&map)[..]);
            // And equal to a map built afresh from the same cells.
            let fresh = GridMap::new(map.width(), map.height(), map.grid_size(), map.origin(),
                map.cells().to_vec()).unwrap();
            prop_assert_eq!(map.distances(), fresh.distances());
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 60, ..ProptestConfig::default() })]

    /// Wide maps and small batches: the incremental path (a few columns, then only the rows
    /// whose column distances changed).
    #[test]
    fn small_updates_on_wide_maps_stay_exact(
        w in 40usize..=64,
        h in 1usize..=20,
        seed in any::<u64>(),
        updates in prop::collection::vec((0usize..64, 0usize..20, any::<bool>()), 1..=4),
    ) {
        let mut s = seed;
        let cells = (0..w * h)
            .map(|_| {
                s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                u8::from((s >> 33) % 100 < 15)
            })
            .collect();
        let mut map = GridMap::new(w, h, 0.1, (0.0, 0.0), cells).unwrap();
        for (x, y, v) in updates {
            if x < w && y < h {
                map.map_update(&MapUpdate { x: vec![x as i32], y: vec![y as i32], value: vec![i16::from(v)], num: 1, tm: Time::default() })
                    .unwrap();
                prop_assert_eq!(map.distances(), &brute(&map)[..]);
            }
        }
    }
}

#[test]
fn a_big_update_recomputes_everything_exactly() {
    // More than 1/8 of the columns change: the full-recompute path.
    let mut map = GridMap::new(16, 9, 0.5, (0.0, 0.0), vec![0; 16 * 9]).unwrap();
    let xs: Vec<i32> = (0..16).collect();
    let ys = [4; 16];
    let vs: Vec<i16> = (0..16).map(|x| i16::from(x % 3 != 0)).collect();
    assert_eq!(
        map.map_update(&MapUpdate {
            x: xs.to_vec(),
            y: ys.to_vec(),
            value: vs.to_vec(),
            num: 16,
            tm: Time::default()
        }),
        Ok(10)
    );
    assert_eq!(map.distances(), &brute(&map)[..]);
}

#[test]
fn a_cell_listed_twice_takes_its_last_value() {
    let mut map = GridMap::new(3, 3, 1.0, (0.0, 0.0), vec![0; 9]).unwrap();
    // (1, 1) set and cleared again: nothing changed in the end.
    assert_eq!(
        map.map_update(&MapUpdate {
            x: vec![1, 1],
            y: vec![1, 1],
            value: vec![1, 0],
            num: 2,
            tm: Time::default()
        }),
        Ok(0)
    );
    assert_eq!(
        map.map_update(&MapUpdate {
            x: vec![1, 1, 2],
            y: vec![1, 1, 0],
            value: vec![0, 1, 1],
            num: 3,
            tm: Time::default()
        }),
        Ok(2)
    );
    assert!(map.is_obstacle(1, 1) && map.is_obstacle(2, 0));
    assert_eq!(map.distances(), &brute(&map)[..]);
}

/// Checks that `result` is an error whose text contains `needle`, and returns it.
fn refused<T: std::fmt::Debug>(result: Result<T, MapError>, needle: &str) -> MapError {
    let e = result.unwrap_err();
    assert!(
        e.to_string().contains(needle),
        "`{e}` should mention `{needle}`"
    );
    e
}

#[test]
fn set_map_refuses_bad_input_naming_the_problem() {
    refused(
        GridMap::from_map_data(&[0; 5], 2, 3, 1.0),
        "MapData has 5 cells, expected MapLengthX × MapLengthY = 6",
    );
    refused(
        GridMap::from_map_data(&[0, 0, 2, 0], 2, 2, 1.0),
        "MapData[2] = 2",
    );
    refused(
        GridMap::from_map_data(&[0, -1, 0, 0], 2, 2, 1.0),
        "MapData[1] = -1",
    );
    refused(
        GridMap::from_map_data(&[0; 4], 2, 2, 0.0),
        "GridSize 0 m must lie between 0.0001 m and 1000 m",
    );
    refused(GridMap::from_map_data(&[0; 4], 2, 2, -0.5), "GridSize -0.5");
    refused(
        GridMap::from_map_data(&[0; 4], 2, 2, f64::NAN),
        "GridSize NaN",
    );
    refused(
        GridMap::from_map_data(&[0; 4], 2, 2, f64::INFINITY),
        "GridSize inf",
    );
    refused(GridMap::from_map_data(&[], 0, 2, 1.0), "MapLengthX = 0");
    refused(GridMap::from_map_data(&[], 2, -3, 1.0), "MapLengthY = -3");
    refused(
        GridMap::new(2, 2, 1.0, (f64::NAN, 0.0), vec![0; 4]),
        "origin (NaN, 0)",
    );
    let e = refused(
        GridMap::new(4097, 4096, 1.0, (0.0, 0.0), Vec::new()),
        "exceeds the limit of 16777216 cells",
    );
    assert!(matches!(
        e,
        MapError::TooLarge {
            width: 4097,
            height: 4096,
            ..
        }
    ));
    // The largest map is accepted (4096 × 4096 = MAX_CELLS).
    assert_eq!(MAX_CELLS, 4096 * 4096);
}

#[test]
fn map_update_is_all_or_nothing() {
    let mut map = GridMap::from_map_data(&[0, 0, 0, 0, 1, 0], 3, 2, 0.5).unwrap();
    let before = map.clone();
    let tm = Time { sec: 9, nsec: 1 };
    refused(
        map.map_update(&MapUpdate {
            x: vec![0, 1],
            y: vec![0],
            value: vec![1, 1],
            num: 2,
            tm,
        }),
        "MapUpdate: Y has 1 entries, but num = 2",
    );
    refused(
        map.map_update(&MapUpdate {
            x: vec![0, 1],
            y: vec![0, 1],
            value: vec![1],
            num: 2,
            tm,
        }),
        "value has 1 entries, but num = 2",
    );
    refused(
        map.map_update(&MapUpdate {
            x: vec![0],
            y: vec![0],
            value: vec![1],
            num: 2,
            tm,
        }),
        "X has 1 entries, but num = 2",
    );
    refused(
        map.map_update(&MapUpdate {
            x: vec![],
            y: vec![],
            value: vec![],
            num: -1,
            tm,
        }),
        "num = -1",
    );
    // The first entries are fine; the last is outside: nothing is applied.
    refused(
        map.map_update(&MapUpdate {
            x: vec![0, 1, 3],
            y: vec![0, 0, 0],
            value: vec![1, 1, 1],
            num: 3,
            tm,
        }),
        "cell (3, 0) is outside the 3×2 map",
    );
    refused(
        map.map_update(&MapUpdate {
            x: vec![0, -1],
            y: vec![0, 0],
            value: vec![1, 1],
            num: 2,
            tm,
        }),
        "cell (-1, 0) is outside",
    );
    refused(
        map.map_update(&MapUpdate {
            x: vec![0, 1],
            y: vec![0, 2],
            value: vec![1, 1],
            num: 2,
            tm,
        }),
        "cell (1, 2) is outside",
    );
    refused(
        map.map_update(&MapUpdate {
            x: vec![0, 1],
            y: vec![0, 0],
            value: vec![1, 2],
            num: 2,
            tm,
        }),
        "value[1] = 2",
    );
    assert_eq!(map, before);
    assert_eq!(map.version(), Time::default());
    // A valid update applies and stamps the version.
    assert_eq!(
        map.map_update(&MapUpdate {
            x: vec![2],
            y: vec![1],
            value: vec![1],
            num: 1,
            tm
        }),
        Ok(1)
    );
    assert_eq!(map.version(), tm);
    assert!(map.is_obstacle(2, 1));
}

#[test]
fn world_and_cells_follow_the_origin() {
    let map = GridMap::new(4, 2, 0.5, (-1.0, 2.0), vec![0; 8]).unwrap();
    assert_eq!(map.cell_center((0, 0)), (-0.75, 2.25));
    assert_eq!(map.world_to_cell(-1.0, 2.0), Some((0, 0)));
    assert_eq!(map.world_to_cell(0.99, 2.99), Some((3, 1)));
    assert_eq!(map.world_to_cell(1.0, 2.0), None);
    assert_eq!(map.world_to_cell(-1.01, 2.0), None);
    assert_eq!(map.world_to_cell_signed(-1.01, 1.99), Some((-1, -1)));
    assert_eq!(map.world_to_cell(f64::NAN, 2.0), None);
    // Outside counts as obstacle, so border cells are 1 cell (0.5 m) from one.
    assert_eq!(map.obstacle_distance((0, 0)), 0.5);
    assert_eq!(map.obstacle_distance((9, 9)), 0.0);
    assert!(map.is_clear((1, 1), 0.49) && !map.is_clear((1, 1), 0.5));
}
