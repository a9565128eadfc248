//! spec §5 "GlobalPathPlanning": the A* planner against an independent reference on random
//! maps (with and without `dmin`), and the RT-component on the framework: services, the
//! `dmin` parameter, the `GlobalPathCourse` and `PlanningFailure` ports, and its errors.

use proptest::prelude::*;
use rtnav::components::{GlobalPathPlanning, PlanReason};
use rtnav::errors::{Error, GlobalPlanningError, MapError};
use rtnav::global::{AStar, OctileCost};
use rtnav::interfaces::{GlobalPathCourse, PlanningFailure, Pose};
use rtnav::map::formats::json;
use rtnav::map::{Cell, GridMap, MapUpdate};
use rtnav::rtc::{ComponentId, ConfigAccess, ExecutionContext, InPort, LifecycleState, Time};

// ------------------------------------------------------------------ planner vs reference

/// Reference: Dijkstra over all cells with exact costs (a plain O(n²) scan, nothing shared
/// with the planner but the rules: 8 moves, no corner cutting, cells with obstacle distance
/// ≤ dmin blocked).
fn reference(map: &GridMap, dmin: f64, s: Cell, t: Cell) -> Option<OctileCost> {
    let (w, h) = (map.width() as i64, map.height() as i64);
    let free = |x: i64, y: i64| {
        x >= 0 && y >= 0 && x < w && y < h && map.obstacle_distance((x as usize, y as usize)) > dmin
    };
    if !free(s.0 as i64, s.1 as i64) || !free(t.0 as i64, t.1 as i64) {
        return None;
    }
    let n = (w * h) as usize;
    let mut best: Vec<Option<OctileCost>> = vec![None; n];
    let mut done = vec![false; n];
    best[s.0 + s.1 * w as usize] = Some(OctileCost::ZERO);
    loop {
        let u = (0..n)
            .filter(|&i| !done[i] && best[i].is_some())
            .min_by_key(|&i| best[i])?;
        if u == t.0 + t.1 * w as usize {
            return best[u];
        }
        done[u] = true;
        let (x, y) = ((u as i64) % w, (u as i64) / w);
        for dx in -1..=1i64 {
            for dy in -1..=1i64 {
                let (nx, ny) = (x + dx, y + dy);
                if (dx, dy) == (0, 0) || !free(nx, ny) {
                    continue;
                }
                if dx != 0 && dy != 0 && !(free(x + dx, y) && free(x, y + dy)) {
                    continue;
                }
                let step = if dx != 0 && dy != 0 {
                    OctileCost::DIAGONAL
                } else {
                    OctileCost::STRAIGHT
                };
                let c = best[u].unwrap_or_default() + step;
                let v = (nx + ny * w) as usize;
                if best[v].is_none_or(|b| c < b) {
                    best[v] = Some(c);
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 150, ..ProptestConfig::default() })]

    #[test]
    fn astar_is_optimal_and_valid_on_random_maps(
        w in 2usize..=20,
        h in 2usize..=20,
        density in 0u32..45,
        seed in any::<u64>(),
        dmin in prop::sample::select(vec![0.0, 0.3, 0.5, 1.0]),
        ends in (0usize..400, 0usize..400),
    ) {
        let mut s = seed;
        let cells = (0..w * h)
            .map(|_| {
                s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                u8::from(((s >> 33) % 100) < u64::from(density))
            })
            .collect();
        let map = GridMap::new(w, h, 0.5, (0.0, 0.0), cells).unwrap();
        let start = (ends.0 % w, (ends.0 / w) % h);
        let goal = (ends.1 % w, (ends.1 / w) % h);
        let mut astar = AStar::new(&map, dmin).unwrap();
        let expected = reference(&map, dmin, start, goal);
        match astar.plan(start, goal) {
            Ok(plan) => {
                prop_assert_eq!(Some(plan.cost), expected);
                prop_assert_eq!(plan.cells.first(), Some(&start));
                prop_assert_eq!(plan.cells.last(), Some(&goal));
                for step in plan.cells.windows(2) {
                    prop_assert!(astar.step_allowed(step[0], step[1]), "{:?}", step);
                }
                // Deterministic: the same request gives the same path.
                prop_assert_eq!(astar.plan(start, goal).unwrap(), plan);
            }
            Err(GlobalPlanningError::Blocked { .. } | GlobalPlanningError::NoPath { .. }) => {
                prop_assert_eq!(expected, None);
            }
            Err(e) => prop_assert!(false, "{}", e),
        }
    }
}

#[test]
fn planner_errors_name_the_problem() {
    let map = room(1.0);
    let mut astar = AStar::new(&map, 0.0).unwrap();
    assert_eq!(
        astar.plan((12, 1), (1, 1)),
        Err(GlobalPlanningError::CellOutside {
            which: "start",
            cell: (12, 1),
            width: 12,
            height: 7
        })
    );
    assert!(matches!(
        astar.plan((1, 1), (0, 0)),
        Err(GlobalPlanningError::Blocked {
            which: "goal",
            cell: (0, 0),
            ..
        })
    ));
    // Inside the closed box on the right.
    assert_eq!(
        astar.plan((1, 1), (10, 5)),
        Err(GlobalPlanningError::NoPath {
            start: (1, 1),
            goal: (10, 5),
            start_at: (1.5, 1.5),
            goal_at: (10.5, 5.5),
        })
    );
    assert_eq!(astar.plan((3, 3), (3, 3)).unwrap().cells, vec![(3, 3)]);
    assert!(matches!(
        AStar::new(&map, -0.1),
        Err(GlobalPlanningError::BadDmin { .. })
    ));
    assert!(matches!(
        AStar::new(&map, f64::NAN),
        Err(GlobalPlanningError::BadDmin { .. })
    ));
}

// ------------------------------------------------------------------ the RT-component

/// A 12 × 7 room (top row first). A 2-cell block in the middle row; a closed 1-cell box at
/// the top right, around cell (10, 5).
fn room(grid_size: f64) -> GridMap {
    let rows = [
        "############",
        "#........#.#",
        "#........###",
        "#....##....#",
        "#..........#",
        "#..........#",
        "############",
    ];
    let text = serde_json::json!({
        "width": 12, "height": 7, "grid_size": grid_size, "rows": rows
    });
    json::load(&text.to_string()).unwrap()
}

/// A 20 × 16 hall at 0.25 m: walls all round and a block at x 9–10, y 4–7.
fn hall() -> GridMap {
    let (w, h) = (20, 16);
    let cells = (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            let wall = x == 0 || y == 0 || x == w - 1 || y == h - 1;
            u8::from(wall || ((9..=10).contains(&x) && (4..=7).contains(&y)))
        })
        .collect();
    GridMap::new(w, h, 0.25, (0.0, 0.0), cells).unwrap()
}

/// The world centre of a cell on a map of `g` metres.
fn at(cell: Cell, g: f64) -> Pose {
    Pose::new((cell.0 as f64 + 0.5) * g, (cell.1 as f64 + 0.5) * g, 0.0)
}

struct Rig {
    ec: ExecutionContext,
    id: ComponentId,
    course: InPort<GlobalPathCourse>,
    failure: InPort<PlanningFailure>,
}

impl Rig {
    /// A running 10 Hz context with an active planner whose ports are connected.
    fn new() -> Self {
        let mut gpp = GlobalPathPlanning::new("GlobalPathPlanning0");
        let course = InPort::new("GlobalPathCourse");
        let failure = InPort::new("PlanningFailure");
        assert_eq!(gpp.global_path_course.name(), "GlobalPathCourse");
        assert_eq!(gpp.planning_failure.name(), "PlanningFailure");
        gpp.global_path_course.connect(&course);
        gpp.planning_failure.connect(&failure);
        let mut ec = ExecutionContext::new(10.0).unwrap();
        let id = ec.attach(Box::new(gpp), 10.0).unwrap();
        ec.start().unwrap();
        ec.activate(id).unwrap();
        Self {
            ec,
            id,
            course,
            failure,
        }
    }

    fn gpp(&mut self) -> &mut GlobalPathPlanning {
        self.ec
            .component_mut::<GlobalPathPlanning>(self.id)
            .unwrap()
    }

    fn request(&mut self, start: Pose, goal: Pose) {
        self.gpp().set_position(start, goal).unwrap();
        self.ec.tick();
    }

    fn failure_reason(&self) -> String {
        assert!(self.failure.is_new());
        self.failure.read().unwrap().reason.to_string()
    }
}

#[test]
fn a_request_is_planned_at_the_next_tick_and_sent() {
    let mut rig = Rig::new();
    let g = 0.5;
    rig.gpp().set_map(room(g));
    rig.gpp().config_mut().set("dmin", 0.0).unwrap();
    rig.gpp()
        .set_position(at((1, 3), g), at((10, 3), g))
        .unwrap();
    assert!(rig.gpp().is_requested() && !rig.course.is_new());
    rig.ec.tick();
    assert!(rig.course.is_new() && !rig.failure.is_new());
    let course = rig.course.read().unwrap();
    let plan = rig.gpp().last_plan().unwrap().clone();
    assert_eq!(course, GlobalPathCourse::from_cells(&plan.cells));
    assert_eq!(course.num as usize, course.grid_path_x.len());
    assert_eq!((course.grid_path_x[0], course.grid_path_y[0]), (1, 3));
    let reference = reference(&room(g), 0.0, (1, 3), (10, 3)).unwrap();
    assert_eq!(plan.cost, reference);
    assert_eq!(rig.gpp().path_length(), Some(reference.cells() * g));
    assert!(rig.gpp().last_error().is_none() && !rig.gpp().is_requested());
    // Nothing more is sent without a new request.
    rig.ec.tick();
    assert!(!rig.course.is_new());
}

#[test]
fn dmin_blocks_cells_near_obstacles_and_takes_effect_at_the_next_plan() {
    let mut rig = Rig::new();
    let g = 0.5;
    rig.gpp().set_map(room(g));
    assert_eq!(rig.gpp().params().dmin, 0.5);
    // (1, 3) and (10, 3) are next to the walls: distance 0.5 m ≤ dmin 0.5 → blocked. Spec §3
    // Decision 0.2 "escape from the margin": the start escapes; the goal is checked strictly.
    rig.request(at((1, 3), g), at((10, 3), g));
    assert!(!rig.course.is_new());
    let reason = rig.failure_reason();
    assert!(reason.contains("(cell 10, 3) is blocked"), "{reason}");
    assert!(matches!(
        rig.gpp().last_error(),
        Some(GlobalPlanningError::Blocked {
            which: "goal",
            dmin: 0.5,
            ..
        })
    ));
    assert_eq!(rig.gpp().path_length(), None);
    // A planning failure is a result, not a component failure.
    assert_eq!(rig.ec.state(rig.id).unwrap(), LifecycleState::Active);
    // On a finer, larger map the detour keeps more than dmin from every obstacle.
    let fine = hall();
    rig.gpp().set_map(fine.clone());
    rig.request(at((3, 5), 0.25), at((16, 5), 0.25));
    let with_dmin = rig.gpp().last_plan().unwrap().clone();
    for &c in &with_dmin.cells {
        assert!(fine.obstacle_distance(c) > 0.5, "{c:?}");
    }
    assert!(
        with_dmin.cells.iter().any(|&(_, y)| y >= 10),
        "goes round above the block"
    );
    assert_eq!(Some(with_dmin.cost), reference(&fine, 0.5, (3, 5), (16, 5)));
    rig.gpp().set_map(room(g));
    // Out of range refused, old value kept; a new value is used by the next plan.
    assert!(rig.gpp().config_mut().set("dmin", -1.0).is_err());
    assert_eq!(rig.gpp().params().dmin, 0.5);
    rig.gpp().config_mut().set("dmin", 0.0).unwrap();
    rig.request(at((1, 3), g), at((10, 3), g));
    assert!(rig.course.is_new());
}

#[test]
fn outside_and_unreachable_goals_are_reported_on_the_failure_port() {
    let mut rig = Rig::new();
    // No map yet.
    rig.request(at((1, 1), 1.0), at((2, 2), 1.0));
    assert_eq!(rig.failure_reason(), "no map has been set");
    rig.gpp().set_map(room(1.0));
    rig.gpp().config_mut().set("dmin", 0.0).unwrap();
    rig.request(at((1, 1), 1.0), Pose::new(12.5, 1.5, 0.0));
    assert_eq!(
        rig.failure_reason(),
        "goal (12.5, 1.5) m is outside the map"
    );
    rig.request(Pose::new(-0.1, 1.5, 0.0), at((1, 1), 1.0));
    assert!(
        rig.failure_reason()
            .starts_with("start (-0.1, 1.5) m is outside")
    );
    rig.request(at((1, 1), 1.0), at((10, 5), 1.0));
    assert_eq!(
        rig.failure_reason(),
        "no path from (1.5 m, 1.5 m) (cell 1, 1) to (10.5 m, 5.5 m) (cell 10, 5)"
    );
    let failure = rig.failure.peek().unwrap();
    assert_eq!(failure.planner, "GlobalPathPlanning");
    assert_eq!(failure.tm, Time::from_nanos(rig.ec.time_ns() - 100_000_000));
    assert!(!rig.course.is_new());
}

#[test]
fn services_refuse_bad_input_and_keep_what_they_hold() {
    let mut rig = Rig::new();
    let gpp = rig.gpp();
    assert!(matches!(
        gpp.map_update(&MapUpdate {
            x: vec![1],
            y: vec![1],
            value: vec![1],
            num: 1,
            tm: Time::default()
        }),
        Err(Error::GlobalPlanning(GlobalPlanningError::NoMap))
    ));
    gpp.set_map(room(1.0));
    let before = gpp.map().unwrap().clone();
    // `SetMap` takes a `GridMap`, valid by construction: bad map data is refused before it
    // can reach the component.
    assert!(matches!(
        GridMap::from_map_data(&[0, 1, 2], 3, 1, 1.0),
        Err(MapError::BadCellValue {
            index: 2,
            value: 2,
            ..
        })
    ));
    assert!(matches!(
        GridMap::from_map_data(&[0; 3], 3, 1, 0.0),
        Err(MapError::BadGridSize { .. })
    ));
    assert_eq!(gpp.map(), Some(&before));
    assert!(matches!(
        gpp.map_update(&MapUpdate {
            x: vec![1, 2],
            y: vec![1],
            value: vec![1, 1],
            num: 2,
            tm: Time::default()
        }),
        Err(Error::Map(MapError::UpdateLength { array: "Y", .. }))
    ));
    assert!(matches!(
        gpp.map_update(&MapUpdate {
            x: vec![12],
            y: vec![1],
            value: vec![1],
            num: 1,
            tm: Time::default()
        }),
        Err(Error::Map(MapError::CellOutside { .. }))
    ));
    assert_eq!(gpp.map(), Some(&before));
    assert!(matches!(
        gpp.set_position(Pose::new(f64::NAN, 1.0, 0.0), Pose::new(1.0, 1.0, 0.0)),
        Err(GlobalPlanningError::NonFinitePose { which: "start", x, y: 1.0, .. }) if x.is_nan()
    ));
    assert!(!gpp.is_requested());
    assert!(
        gpp.set_position(Pose::new(1.5, 1.5, 0.0), Pose::new(1.5, 1.5, f64::INFINITY))
            .is_err()
    );
    assert!(!gpp.is_requested());
}

#[test]
fn a_map_update_that_blocks_the_route_replans_around_it() {
    let mut rig = Rig::new();
    rig.gpp().set_map(room(1.0));
    rig.gpp().config_mut().set("dmin", 0.0).unwrap();
    rig.request(at((1, 1), 1.0), at((10, 1), 1.0));
    assert_eq!(rig.gpp().path_length(), Some(9.0));
    rig.course.read();
    // A cell away from the route: the route stands.
    assert_eq!(
        rig.gpp()
            .map_update(&MapUpdate::from_cells(&[(3, 5, 1)], Time::default())),
        Ok(1)
    );
    assert!(!rig.gpp().is_requested());
    // A wall across the bottom rows at x = 7, leaving only y = 4, 5 open.
    let changed = rig
        .gpp()
        .map_update(&MapUpdate {
            x: vec![7, 7, 7],
            y: vec![1, 2, 3],
            value: vec![1, 1, 1],
            num: 3,
            tm: Time { sec: 5, nsec: 0 },
        })
        .unwrap();
    assert_eq!(changed, 3);
    assert_eq!(rig.gpp().map().unwrap().version(), Time { sec: 5, nsec: 0 });
    // Spec §5 Decision 0.2: an update that blocks the route replans it, from where the robot
    // is (here the start: no pose has come in).
    assert!(rig.gpp().is_requested(), "the wall blocks the route");
    rig.ec.tick();
    assert!(rig.course.is_new());
    assert_eq!(rig.gpp().last_reason(), Some(PlanReason::MapChanged));
    let plan = rig.gpp().last_plan().unwrap();
    assert!(plan.cells.iter().all(|&(x, y)| x != 7 || y >= 4));
    assert_eq!(
        Some(plan.cost),
        reference(rig.gpp().map().unwrap(), 0.0, (1, 1), (10, 1))
    );
    assert!(rig.gpp().path_length().unwrap() > 9.0);
}
