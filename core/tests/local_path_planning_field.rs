//! The algorithms of LocalPathPlanning (seed 000 §5.2.4.8–12, spec §3 steps 3–7) on small
//! hand-made maps, with exact expectations. Test names carry the seed section they check.

use core::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

use rtnav::errors::LocalPathError;
use rtnav::interfaces::{Direction, Pose};
use rtnav::local::{
    CellState, FieldExtent, FieldRequest, LocalPlanner, PlanParams, PlanRequest, PotentialField,
    TARGET_POTENTIAL, control_points, corner_cells, descend, find_local_target, merge_paths,
    nearest_path_index, step_length, thin_collinear,
};
use rtnav::map::{Cell, GridMap, MapUpdate, NEIGHBOURS};

/// A map from rows drawn top (largest y) first: `#` obstacle, anything else free.
fn ascii(rows: &[&str], g: f64) -> GridMap {
    let h = rows.len();
    let w = rows[0].len();
    let mut cells = vec![0u8; w * h];
    for (r, row) in rows.iter().enumerate() {
        assert_eq!(row.len(), w);
        let y = h - 1 - r;
        for (x, ch) in row.chars().enumerate() {
            cells[x + y * w] = u8::from(ch == '#');
        }
    }
    GridMap::new(w, h, g, (0.0, 0.0), cells).unwrap()
}

fn open_map(w: usize, h: usize, g: f64) -> GridMap {
    GridMap::new(w, h, g, (0.0, 0.0), vec![0; w * h]).unwrap()
}

fn request(target: Cell, current: Cell, dmin: f64) -> FieldRequest {
    FieldRequest {
        target,
        current,
        current_heading: 0.0,
        target_heading: 0.0,
        direction: Direction::Forward,
        dmin,
        posture_consideration_level: 85.0,
        posture: true,
        extent: FieldExtent::Full,
    }
}

fn field(map: &GridMap, req: &FieldRequest) -> PotentialField {
    let mut f = PotentialField::new();
    f.compute(map, req).unwrap();
    f
}

fn all_cells(map: &GridMap) -> impl Iterator<Item = Cell> + '_ {
    (0..map.height()).flat_map(move |y| (0..map.width()).map(move |x| (x, y)))
}

/// Checks that `path` is a valid local path on `map`: 8-connected steps, every cell farther
/// than `dmin` from obstacles, no diagonal cutting the corner of an impassable cell.
fn assert_valid_path(map: &GridMap, path: &[Cell], dmin: f64) {
    for &c in path {
        assert!(map.obstacle_distance(c) > dmin, "{c:?} within dmin");
    }
    for w in path.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (dx, dy) = (b.0 as i64 - a.0 as i64, b.1 as i64 - a.1 as i64);
        assert!(
            dx.abs() <= 1 && dy.abs() <= 1 && (dx, dy) != (0, 0),
            "{a:?}→{b:?}"
        );
        if dx != 0 && dy != 0 {
            assert!(
                map.obstacle_distance((b.0, a.1)) > dmin,
                "{a:?}→{b:?} cuts a corner"
            );
            assert!(
                map.obstacle_distance((a.0, b.1)) > dmin,
                "{a:?}→{b:?} cuts a corner"
            );
        }
    }
}

/// Angle of the vector a→b of cells, radians.
fn dir(a: Cell, b: Cell) -> f64 {
    libm::atan2(b.1 as f64 - a.1 as f64, b.0 as f64 - a.0 as f64)
}

fn angle_diff(a: f64, b: f64) -> f64 {
    let d = libm::fmod((a - b).abs(), 2.0 * PI);
    d.min(2.0 * PI - d)
}

// ----- 000 §5.2.4.9: the potential field -----

/// A 16 × 11 room with a 2 × 3 pillar; with 0.25 m cells and dmin 0.3 every cell
/// 4-adjacent to an obstacle is impassable too, and the rest stays connected.
const ROOM: [&str; 11] = [
    "################",
    "#..............#",
    "#..............#",
    "#..............#",
    "#......##......#",
    "#......##......#",
    "#......##......#",
    "#..............#",
    "#..............#",
    "#..............#",
    "################",
];

#[test]
fn s5_2_4_9_target_has_potential_0_1_and_impassable_cells_0() {
    let map = ascii(&ROOM, 0.25);
    let req = request((12, 5), (3, 5), 0.3);
    let f = field(&map, &req);
    assert_eq!(f.potential((12, 5)), TARGET_POTENTIAL);
    assert_eq!(f.potential((12, 5)), 0.1);
    assert_eq!(f.info((12, 5)).unwrap().length, 0.0);
    assert_eq!(f.parent((12, 5)), None);
    assert_eq!(f.rank((12, 5)), Some(0));
    let mut impassable = 0;
    for c in all_cells(&map) {
        let state = f.state(c);
        if map.obstacle_distance(c) <= 0.3 {
            impassable += 1;
            assert_eq!(state, CellState::Impassable, "{c:?}");
            assert_eq!(f.potential(c), 0.0);
            assert_eq!(f.info(c).unwrap().length, 0.0);
        } else {
            // The room is connected: the full field reaches every passable cell.
            assert_eq!(state, CellState::Reached, "{c:?}");
            assert!(f.potential(c) >= 0.1);
        }
    }
    // The walls (50 cells), the pillar (6) and the cells 4-adjacent to them (d = 0.25 ≤
    // 0.3): the inner ring of the room (42) and around the pillar (10).
    assert_eq!(impassable, 50 + 6 + 42 + 10);
    assert!(f.is_complete());
    assert_eq!(f.reached_count(), 16 * 11 - impassable);
    // Impassable cells are never anyone's parent.
    for c in all_cells(&map) {
        if let Some(p) = f.parent(c) {
            assert_eq!(f.state(p), CellState::Reached);
        }
    }
}

#[test]
fn s5_2_4_9_every_reached_cell_is_above_its_parent_by_its_three_parts() {
    let map = ascii(&ROOM, 0.25);
    for (heading, direction, pcl) in [
        (0.0, Direction::Forward, 85.0),
        (FRAC_PI_2, Direction::Backward, 40.0),
        (PI, Direction::Forward, 0.0),
    ] {
        let req = FieldRequest {
            current_heading: heading,
            target_heading: -heading,
            direction,
            posture_consideration_level: pcl,
            ..request((12, 2), (2, 8), 0.3)
        };
        let f = field(&map, &req);
        let dmin = 0.3;
        for c in all_cells(&map) {
            let Some(p) = f.parent(c) else { continue };
            let (cell, parent) = (f.info(c).unwrap(), f.info(p).unwrap());
            assert!(cell.potential > parent.potential, "{c:?} not above {p:?}");
            assert!(cell.rank > parent.rank);
            // G(c) = G(p) + R(c) + A(c) + P(c), L(c) = L(p) + step (000 §5.2.4.9).
            assert_eq!(
                cell.potential,
                parent.potential + cell.repulsion + cell.attraction + cell.posture
            );
            assert_eq!(cell.length, parent.length + step_length(p, c, 0.25));
            let d = map.obstacle_distance(c);
            assert_eq!(cell.repulsion, 1.0 / ((d - dmin) * (d - dmin)));
            // 000 §5.2.4.9 (1-2): distance × "姿勢考慮レベルの反転値" (100 − PCL) / 100.
            assert_eq!(cell.attraction, cell.length * ((100.0 - pcl) / 100.0));
            // The parent is the 8-neighbour with the lowest potential.
            for (dx, dy) in NEIGHBOURS {
                let n = ((c.0 as i64 + dx) as usize, (c.1 as i64 + dy) as usize);
                if f.state(n) == CellState::Reached && n != p {
                    let corner_free = dx == 0
                        || dy == 0
                        || (f.state((n.0, c.1)) != CellState::Impassable
                            && f.state((c.0, n.1)) != CellState::Impassable);
                    if corner_free {
                        assert!(
                            f.key(n).unwrap() > f.key(p).unwrap(),
                            "{c:?}: {n:?} < {p:?}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn s5_2_4_9_posture_part_follows_the_formula() {
    // spec §3 step 4: P = (G_Angle·SL/GL + S_Angle·(GL/SL)·L)·PCL/100, computed here from
    // angle differences instead of the implementation's atan2(|v×h|, v·h).
    let map = open_map(30, 30, 0.1);
    let (current, target) = ((5, 10), (22, 18));
    let (hs, ht) = (0.3, -2.0);
    for direction in [Direction::Forward, Direction::Backward] {
        let req = FieldRequest {
            current_heading: hs,
            target_heading: ht,
            direction,
            dmin: 0.2,
            ..request(target, current, 0.2)
        };
        let f = field(&map, &req);
        let turn = if direction == Direction::Backward {
            PI
        } else {
            0.0
        };
        let mut checked = 0;
        for c in all_cells(&map) {
            let Some(info) = f.info(c) else { continue };
            if info.state != CellState::Reached || c == target {
                continue;
            }
            let sl = libm::hypot(c.0 as f64 - 5.0, c.1 as f64 - 10.0) * 0.1;
            let gl = libm::hypot(22.0 - c.0 as f64, 18.0 - c.1 as f64) * 0.1;
            let expected = if sl == 0.0 {
                0.0
            } else {
                let s_angle = angle_diff(dir(current, c), hs + turn);
                let g_angle = angle_diff(dir(c, target), ht + turn);
                (g_angle * sl / gl + s_angle * (gl / sl) * info.length) * 0.85
            };
            assert!(
                (info.posture - expected).abs() <= 1e-9 * expected.max(1.0),
                "{c:?}: {} vs {expected}",
                info.posture
            );
            checked += 1;
        }
        assert!(checked > 500);
    }
}

#[test]
fn s5_2_4_9_backward_turns_both_headings_by_pi() {
    let map = ascii(&ROOM, 0.25);
    let (hs, ht) = (0.7, -1.2);
    let backward = field(
        &map,
        &FieldRequest {
            current_heading: hs,
            target_heading: ht,
            direction: Direction::Backward,
            ..request((12, 2), (2, 8), 0.3)
        },
    );
    let forward_turned = field(
        &map,
        &FieldRequest {
            current_heading: hs + PI,
            target_heading: ht + PI,
            direction: Direction::Forward,
            ..request((12, 2), (2, 8), 0.3)
        },
    );
    let forward = field(
        &map,
        &FieldRequest {
            current_heading: hs,
            target_heading: ht,
            ..request((12, 2), (2, 8), 0.3)
        },
    );
    assert_eq!(backward.cells(), forward_turned.cells());
    assert_ne!(backward.cells(), forward.cells());
}

#[test]
fn s5_2_4_9_no_route_when_the_target_is_walled_off() {
    let map = ascii(
        &[
            "..........",
            "......###.",
            "......#.#.",
            "......###.",
            "..........",
        ],
        1.0,
    );
    let mut f = PotentialField::new();
    let err = f.compute(&map, &request((7, 2), (1, 2), 0.0)).unwrap_err();
    assert_eq!(
        err,
        LocalPathError::NoRoute {
            target: (7, 2),
            current: (1, 2)
        }
    );
    assert!(!f.current_reached());
    assert_eq!(f.state((1, 2)), CellState::Unreached);
    assert_eq!(f.reached_count(), 1);
    // A target within dmin has no field at all.
    let err = f.compute(&map, &request((7, 2), (1, 2), 1.0)).unwrap_err();
    assert_eq!(err, LocalPathError::TargetBlocked { from: (7, 2) });
    // Bad requests are refused before anything is computed.
    let err = f.compute(&map, &request((10, 2), (1, 2), 0.0)).unwrap_err();
    assert!(matches!(
        err,
        LocalPathError::CellOutside { what: "target", .. }
    ));
    let bad = FieldRequest {
        posture_consideration_level: 101.0,
        ..request((1, 1), (1, 2), 0.0)
    };
    assert!(matches!(
        f.compute(&map, &bad).unwrap_err(),
        LocalPathError::BadParameter {
            name: "PostureConsiderationLevel",
            ..
        }
    ));
}

#[test]
fn s5_2_4_9_stopping_at_the_current_cell_gives_the_full_fields_path() {
    // FieldExtent::UntilCurrent stops once the current cell is finalized: every cell it
    // reached has the full field's values, and the descent is the same.
    let map = ascii(
        &[
            "####################",
            "#..................#",
            "#....#.............#",
            "#....#......###....#",
            "#....#......#......#",
            "#....####...#......#",
            "#...........#...#..#",
            "#...............#..#",
            "#..................#",
            "####################",
        ],
        0.2,
    );
    let mut cases = 0;
    for (target, current) in [((10, 7), (2, 7)), ((3, 2), (10, 6)), ((7, 2), (10, 3))] {
        for (heading, direction, posture) in [
            (0.0, Direction::Forward, true),
            (2.5, Direction::Backward, true),
            (-1.0, Direction::Forward, false),
        ] {
            let base = FieldRequest {
                current_heading: heading,
                target_heading: heading - 1.0,
                direction,
                posture,
                ..request(target, current, 0.2)
            };
            let full = field(&map, &base);
            let part = field(
                &map,
                &FieldRequest {
                    extent: FieldExtent::UntilCurrent,
                    ..base
                },
            );
            assert!(full.is_complete());
            assert!(part.reached_count() <= full.reached_count());
            assert_eq!(descend(&part, current), descend(&full, current));
            for c in all_cells(&map) {
                if part.state(c) == CellState::Reached {
                    let (a, b) = (part.info(c).unwrap(), full.info(c).unwrap());
                    assert_eq!(
                        (a.potential, a.repulsion, a.attraction, a.posture, a.length),
                        (b.potential, b.repulsion, b.attraction, b.posture, b.length)
                    );
                    assert_eq!(a.parent, b.parent);
                    if let Some(r) = a.rank {
                        assert_eq!(Some(r), b.rank);
                    }
                }
            }
            cases += 1;
        }
    }
    assert_eq!(cases, 9);
}

#[test]
fn s5_2_4_9_buffers_are_reused_without_leftovers() {
    // A field computed after another on the same buffers equals a fresh one.
    let map = ascii(&ROOM, 0.25);
    let mut reused = PotentialField::new();
    reused
        .compute(&map, &request((2, 2), (12, 8), 0.3))
        .unwrap();
    let req = FieldRequest {
        extent: FieldExtent::UntilCurrent,
        ..request((11, 4), (3, 4), 0.3)
    };
    reused.compute(&map, &req).unwrap();
    let fresh = field(&map, &req);
    assert_eq!(reused.cells(), fresh.cells());
    assert!(reused.states().eq(fresh.states()));
}

// ----- 000 §5.2.4.10: the local path by descent -----

#[test]
fn s5_2_4_10_descent_reaches_the_target_from_every_reached_cell() {
    let map = ascii(&ROOM, 0.25);
    let f = field(&map, &request((12, 5), (3, 5), 0.3));
    let mut n = 0;
    for c in all_cells(&map) {
        if f.state(c) != CellState::Reached {
            assert!(descend(&f, c).is_err());
            continue;
        }
        let path = descend(&f, c).unwrap();
        assert_eq!(path.first(), Some(&c));
        assert_eq!(path.last(), Some(&(12, 5)));
        assert_valid_path(&map, &path, 0.3);
        // The descent is the chain of parents.
        for w in path.windows(2) {
            assert_eq!(f.parent(w[0]), Some(w[1]));
        }
        n += 1;
    }
    assert_eq!(n, f.reached_count());
}

#[test]
fn s5_2_4_10_path_keeps_dmin_and_never_cuts_an_impassable_corner() {
    // A diagonal gap between two blocks: with dmin = 0 the cells (4,3)/(5,2) touch only at a
    // corner, so the path may not squeeze through it diagonally.
    let map = ascii(
        &[
            "..........",
            "..........",
            "....#.....",
            ".....#....",
            "..........",
            "..........",
        ],
        1.0,
    );
    // (4,3) and (5,2) are obstacles; going (4,2)→(5,3) would cut both corners.
    let f = field(&map, &request((5, 3), (4, 2), 0.0));
    let path = descend(&f, (4, 2)).unwrap();
    assert_valid_path(&map, &path, 0.0);
    assert!(path.len() > 2, "{path:?}");
    // With dmin = 1.0 every cell next to an obstacle is impassable too.
    let map = ascii(&ROOM, 0.25);
    let f = field(&map, &request((12, 8), (2, 2), 0.3));
    let path = descend(&f, (2, 2)).unwrap();
    assert_valid_path(&map, &path, 0.3);
}

// ----- posture (000 §5.2.4.9 (1-3)) -----

/// The local path on an open 6 m × 4 m map from (1.5, 2.0) to (4.5, 2.0), 0.05 m cells.
fn open_path(pcl: f64, start_heading: f64, goal_heading: f64, posture: bool) -> Vec<Cell> {
    let map = open_map(120, 81, 0.05);
    let req = FieldRequest {
        target: (90, 40),
        current: (30, 40),
        current_heading: start_heading,
        target_heading: goal_heading,
        direction: Direction::Forward,
        dmin: 0.5,
        posture_consideration_level: pcl,
        posture,
        extent: FieldExtent::UntilCurrent,
    };
    let f = field(&map, &req);
    let path = descend(&f, (30, 40)).unwrap();
    assert_valid_path(&map, &path, 0.5);
    path
}

/// The index of the first path cell at least `d` metres along the path from its start.
fn index_at(path: &[Cell], d: f64) -> usize {
    let mut s = 0.0;
    for (i, w) in path.windows(2).enumerate() {
        if s >= d {
            return i;
        }
        s += step_length(w[0], w[1], 0.05);
    }
    path.len() - 1
}

#[test]
fn s5_2_4_9_posture_85_leaves_along_the_start_and_arrives_along_the_goal_heading() {
    // The start heading is 90° away from the straight line to the goal.
    for goal_heading in [FRAC_PI_2, 0.0, -FRAC_PI_2] {
        let path = open_path(85.0, FRAC_PI_2, goal_heading, true);
        let first = path[index_at(&path, 0.5)];
        let rev: Vec<Cell> = path.iter().rev().copied().collect();
        let last = rev[index_at(&rev, 0.5)];
        let leave = angle_diff(dir(path[0], first), FRAC_PI_2);
        let arrive = angle_diff(dir(last, *path.last().unwrap()), goal_heading);
        assert!(leave <= FRAC_PI_4, "leaves at {leave} rad: {path:?}");
        assert!(arrive <= FRAC_PI_4, "arrives at {arrive} rad: {path:?}");
    }
    // Without posture the same start leaves towards the goal.
    let path = open_path(85.0, FRAC_PI_2, FRAC_PI_2, false);
    assert!(angle_diff(dir(path[0], path[index_at(&path, 0.5)]), 0.0) <= FRAC_PI_4);
}

#[test]
fn s5_2_4_9_posture_level_0_gives_the_straight_line() {
    let path = open_path(0.0, FRAC_PI_2, FRAC_PI_2, true);
    let straight: Vec<Cell> = (30..=90).map(|x| (x, 40)).collect();
    assert_eq!(path, straight);
}

#[test]
fn s5_2_4_9_no_posture_part_within_not_posture_distance() {
    // The planner turns the posture part off when the straight distance from the current
    // position to the goal is ≤ NotPostureDistance.
    let map = open_map(60, 40, 0.1);
    let held: Vec<Cell> = (10..=40).map(|x| (x, 20)).collect();
    let goal = Pose::new(4.05, 2.05, FRAC_PI_2);
    let mut planner = LocalPlanner::new();
    for (npd, posture) in [(3.0, false), (2.99, true)] {
        let req = PlanRequest {
            held_path: &held,
            match_from: 0,
            current: Pose::new(1.05, 2.05, -FRAC_PI_2),
            goal,
            direction: Direction::Forward,
            params: PlanParams {
                not_posture_distance: npd,
                dmin: 0.3,
                ..PlanParams::default()
            },
            extent: FieldExtent::Full,
        };
        let plan = planner.plan(&map, &req).unwrap();
        assert_eq!(plan.posture, posture);
        let f = planner.field();
        let nonzero = all_cells(&map)
            .filter(|&c| f.info(c).unwrap().posture != 0.0)
            .count();
        if posture {
            assert!(nonzero > 1000);
        } else {
            assert_eq!(nonzero, 0);
        }
    }
}

// ----- 000 §5.2.4.8: the local target -----

/// Cells (2..=12, 2) then up to (12, 6): 10 straight steps east, 4 north.
fn l_path() -> Vec<Cell> {
    let mut p: Vec<Cell> = (2..=12).map(|x| (x, 2)).collect();
    p.extend((3..=6).map(|y| (12, y)));
    p
}

#[test]
fn s5_2_4_8_local_target_is_route_remake_distance_along_the_path() {
    let map = open_map(20, 10, 0.5);
    let path = l_path();
    let goal = Pose::new(6.25, 3.25, 1.0); // cell (12, 6)
    // Current position near cell (4, 2); 2.0 m = 4 steps of 0.5 m → cell (8, 2).
    let t = find_local_target(
        &map,
        &path,
        0,
        (2.3, 1.4),
        goal,
        Direction::Forward,
        2.0,
        0.0,
    )
    .unwrap();
    assert_eq!((t.match_index, t.index, t.cell), (2, 6, (8, 2)));
    assert_eq!(t.goal_index, 14);
    assert_eq!(t.path_distance, 2.0);
    assert!(!t.is_goal);
    // Heading: the direction of the path at the target (east), turned by π backward.
    assert_eq!(t.heading, 0.0);
    let b = find_local_target(
        &map,
        &path,
        0,
        (2.3, 1.4),
        goal,
        Direction::Backward,
        2.0,
        0.0,
    )
    .unwrap();
    assert_eq!(b.heading, PI);
    // 2.1 m is reached only after 5 steps; at the corner the path turns north.
    let t = find_local_target(
        &map,
        &path,
        0,
        (2.3, 1.4),
        goal,
        Direction::Forward,
        4.0,
        0.0,
    )
    .unwrap();
    assert_eq!((t.index, t.cell), (10, (12, 2)));
    assert_eq!(t.heading, FRAC_PI_2);
    // 0 m: the matched cell itself.
    let t = find_local_target(
        &map,
        &path,
        0,
        (2.3, 1.4),
        goal,
        Direction::Forward,
        0.0,
        0.0,
    )
    .unwrap();
    assert_eq!(t.index, 2);
}

#[test]
fn s5_2_4_8_goal_cell_first_is_the_target_with_the_goal_heading() {
    let map = open_map(20, 10, 0.5);
    let path = l_path();
    let goal = Pose::new(6.25, 3.25, 1.0);
    let t = find_local_target(
        &map,
        &path,
        0,
        (5.2, 1.2),
        goal,
        Direction::Forward,
        10.0,
        0.0,
    )
    .unwrap();
    assert_eq!((t.index, t.cell, t.is_goal), (14, (12, 6), true));
    assert_eq!(t.heading, 1.0);
    assert_eq!(t.path_distance, 1.0 + 2.0);
    // A goal before the end of the path ends the walk there.
    let goal_mid = Pose::new(4.25, 1.25, -0.5); // cell (8, 2)
    let t = find_local_target(
        &map,
        &path,
        0,
        (1.2, 1.2),
        goal_mid,
        Direction::Forward,
        10.0,
        0.0,
    )
    .unwrap();
    assert_eq!(
        (t.index, t.goal_index, t.is_goal, t.heading),
        (6, 6, true, -0.5)
    );
    // A goal not on the path: no target.
    let off = Pose::new(0.25, 4.25, 0.0);
    assert_eq!(
        find_local_target(
            &map,
            &path,
            0,
            (1.2, 1.2),
            off,
            Direction::Forward,
            1.0,
            0.0
        ),
        Err(LocalPathError::GoalNotOnPath { goal: (0, 8) })
    );
}

#[test]
fn s5_2_4_8_nearest_cell_is_searched_forward_from_the_last_match() {
    // A path that loops back: east along y = 2, up to y = 3, west back along y = 3.
    let map = open_map(14, 6, 1.0);
    let mut path: Vec<Cell> = (1..=10).map(|x| (x, 2)).collect();
    path.extend((1..=10).rev().map(|x| (x, 3)));
    // The robot on the way back at (2.5, 2.9): nearer to (2, 2) of the first leg.
    let p = (2.5, 2.9);
    assert_eq!(path[nearest_path_index(&map, &path, 0, p).unwrap()], (2, 2));
    // Searched from the last match (index 12, on the way back): the return leg.
    assert_eq!(nearest_path_index(&map, &path, 12, p), Some(18));
    assert_eq!(path[18], (2, 3));
    let goal = Pose::new(1.5, 3.5, PI);
    let t = find_local_target(&map, &path, 12, p, goal, Direction::Forward, 5.0, 0.0).unwrap();
    assert_eq!((t.match_index, t.index, t.is_goal), (18, 19, true));
    // Ties go to the earliest cell.
    assert_eq!(nearest_path_index(&map, &path, 0, (1.5, 3.0)), Some(0));
    assert_eq!(nearest_path_index(&map, &path, 20, p), None);
}

#[test]
fn s5_2_4_8_a_blocked_target_moves_on_along_the_path() {
    let mut map = open_map(20, 10, 0.5);
    let path = l_path();
    let goal = Pose::new(6.25, 3.25, 1.0);
    // Block (8, 2), the target by distance.
    map.map_update(&MapUpdate {
        x: vec![8],
        y: vec![2],
        value: vec![1],
        num: 1,
        tm: Default::default(),
    })
    .unwrap();
    let t = find_local_target(
        &map,
        &path,
        0,
        (2.3, 1.4),
        goal,
        Direction::Forward,
        2.0,
        0.0,
    )
    .unwrap();
    assert_eq!((t.index, t.cell), (7, (9, 2)));
    // With dmin = 0.5 its neighbours are blocked as well.
    let t = find_local_target(
        &map,
        &path,
        0,
        (2.3, 1.4),
        goal,
        Direction::Forward,
        2.0,
        0.5,
    )
    .unwrap();
    assert_eq!((t.index, t.cell), (8, (10, 2)));
    // Block the goal: nothing left.
    map.map_update(&MapUpdate {
        x: vec![12],
        y: vec![6],
        value: vec![1],
        num: 1,
        tm: Default::default(),
    })
    .unwrap();
    assert_eq!(
        find_local_target(
            &map,
            &path,
            0,
            (5.7, 1.2),
            goal,
            Direction::Forward,
            5.0,
            0.0
        ),
        Err(LocalPathError::TargetBlocked { from: (12, 6) })
    );
}

// ----- 000 §5.2.4.11: merge -----

#[test]
fn s5_2_4_11_merge_is_local_path_then_held_path_after_the_target() {
    let held: Vec<Cell> = (0..8).map(|x| (x, 0)).collect();
    let local = vec![(1, 1), (2, 2), (3, 1), (4, 0)];
    assert_eq!(
        merge_paths(&local, &held, 4, 7),
        vec![(1, 1), (2, 2), (3, 1), (4, 0), (5, 0), (6, 0), (7, 0)]
    );
    // The goal before the end of the held path ends the merged path.
    assert_eq!(
        merge_paths(&local, &held, 4, 5),
        vec![(1, 1), (2, 2), (3, 1), (4, 0), (5, 0)]
    );
    // The target is the goal: the local path alone.
    assert_eq!(merge_paths(&local, &held, 7, 7), local);
}

// ----- 000 §5.2.4.12: control points -----

#[test]
fn s5_2_4_12_l_shaped_path_gives_current_corner_goal() {
    let map = open_map(10, 10, 0.5);
    let path = vec![(1, 1), (2, 1), (3, 1), (4, 1), (4, 2), (4, 3), (4, 4)];
    assert_eq!(corner_cells(&path), vec![(4, 1)]);
    let cp = control_points(&map, &path, (0.6, 0.8), (2.2, 2.3));
    assert_eq!(cp, vec![(0.6, 0.8), (2.25, 0.75), (2.2, 2.3)]);
}

#[test]
fn s5_2_4_12_straight_path_gives_current_and_goal() {
    let map = open_map(10, 10, 0.5);
    let path: Vec<Cell> = (1..=7).map(|i| (i, i)).collect();
    assert!(corner_cells(&path).is_empty());
    assert_eq!(
        control_points(&map, &path, (0.7, 0.7), (3.8, 3.9)),
        vec![(0.7, 0.7), (3.8, 3.9)]
    );
    // One cell: current and goal.
    assert_eq!(
        control_points(&map, &[(3, 3)], (1.6, 1.7), (1.8, 1.9)),
        vec![(1.6, 1.7), (1.8, 1.9)]
    );
    assert!(control_points(&map, &[], (1.0, 1.0), (2.0, 2.0)).is_empty());
}

#[test]
fn s5_2_4_12_collinear_points_thinned_only_where_truly_collinear() {
    let map = open_map(10, 10, 1.0);
    // A staircase of alternating diagonal / straight steps: every cell is a corner and no
    // three consecutive points are collinear, so nothing is thinned.
    let stairs = vec![(0, 0), (1, 1), (2, 1), (3, 2), (4, 2), (5, 3)];
    assert_eq!(corner_cells(&stairs), vec![(1, 1), (2, 1), (3, 2), (4, 2)]);
    assert_eq!(
        control_points(&map, &stairs, (0.5, 0.5), (5.5, 3.5)),
        vec![
            (0.5, 0.5),
            (1.5, 1.5),
            (2.5, 1.5),
            (3.5, 2.5),
            (4.5, 2.5),
            (5.5, 3.5)
        ]
    );
    // Collinear runs are thinned until none remain; near-collinear points stay.
    assert_eq!(
        thin_collinear(&[
            (0.0, 0.0),
            (1.0, 1.0),
            (2.0, 2.0),
            (3.0, 3.0),
            (4.0, 3.0),
            (6.0, 3.0)
        ]),
        vec![(0.0, 0.0), (3.0, 3.0), (6.0, 3.0)]
    );
    assert_eq!(
        thin_collinear(&[(0.0, 0.0), (1.0, 1.0 + 1e-6), (2.0, 2.0)]),
        vec![(0.0, 0.0), (1.0, 1.0 + 1e-6), (2.0, 2.0)]
    );
    // Cell centres in metres (0.1 m cells) are collinear up to rounding only.
    let m = open_map(10, 10, 0.1);
    let pts: Vec<(f64, f64)> = [(0, 0), (3, 1), (6, 2), (9, 3)]
        .iter()
        .map(|&c| m.cell_center(c))
        .collect();
    assert_eq!(thin_collinear(&pts), vec![pts[0], pts[3]]);
    // A turn back along the same line is collinear but not a straight part: kept.
    assert_eq!(
        thin_collinear(&[(0.0, 0.0), (3.0, 0.0), (1.0, 0.0)]),
        vec![(0.0, 0.0), (3.0, 0.0), (1.0, 0.0)]
    );
    // Duplicates go.
    assert_eq!(
        thin_collinear(&[(0.0, 0.0), (0.0, 0.0), (1.0, 2.0)]),
        vec![(0.0, 0.0), (1.0, 2.0)]
    );
}

// ----- spec §3 steps 3–7 together -----

#[test]
fn s5_2_4_planner_replans_around_an_obstacle_on_the_held_path() {
    let map = ascii(
        &[
            "....................",
            "....................",
            "....................",
            "........###.........",
            "........###.........",
            "........###.........",
            "....................",
            "....................",
        ],
        0.25,
    );
    // The held path runs straight through the block along y = 3.
    let held: Vec<Cell> = (1..=18).map(|x| (x, 3)).collect();
    let mut planner = LocalPlanner::new();
    let req = PlanRequest {
        held_path: &held,
        match_from: 0,
        current: Pose::new(0.375, 0.875, 0.0),
        goal: Pose::new(4.625, 0.875, 0.0),
        direction: Direction::Forward,
        params: PlanParams {
            route_remake_distance: 3.0,
            dmin: 0.25,
            ..PlanParams::default()
        },
        extent: FieldExtent::UntilCurrent,
    };
    let plan = planner.plan(&map, &req).unwrap();
    // 3.0 m = 12 steps of 0.25 m from (1, 3): the target is (13, 3).
    assert_eq!(plan.target.cell, (13, 3));
    assert_eq!(plan.local_path.first(), Some(&(1, 3)));
    assert_eq!(plan.local_path.last(), Some(&(13, 3)));
    assert_valid_path(&map, &plan.local_path, 0.25);
    let mut merged = plan.local_path.clone();
    merged.extend((14..=18).map(|x| (x, 3)));
    assert_eq!(plan.merged_path, merged);
    assert_eq!(plan.control_points.first(), Some(&(0.375, 0.875)));
    assert_eq!(plan.control_points.last(), Some(&(4.625, 0.875)));
    // A current position within dmin is refused with the reason.
    let err = planner
        .plan(
            &map,
            &PlanRequest {
                current: Pose::new(1.875, 1.125, 0.0),
                ..req
            },
        )
        .unwrap_err();
    assert!(matches!(
        err,
        LocalPathError::NotClear {
            what: "current position",
            cell: (7, 4),
            ..
        }
    ));
}

#[test]
fn s5_2_4_field_reaches_directions_in_the_documented_order() {
    // NEIGHBOURS is counter-clockwise from +x; on an open map the target's 8 neighbours get
    // equal repulsion-free ties broken in that order when their potentials are equal.
    assert_eq!(NEIGHBOURS[0], (1, 0));
    assert_eq!(NEIGHBOURS[2], (0, 1));
    let map = open_map(21, 21, 1.0);
    let f = field(
        &map,
        &FieldRequest {
            posture: false,
            ..request((10, 10), (0, 0), 0.0)
        },
    );
    // (11,10) and (10,11) are symmetric: equal potential, east first.
    assert_eq!(f.potential((11, 10)), f.potential((10, 11)));
    assert!(f.rank((11, 10)) < f.rank((10, 11)));
    assert!(f.rank((10, 11)) < f.rank((9, 10)));
}
