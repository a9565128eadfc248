//! The plan of a scenario drawn before it drives (`rtnav render`): the set-up gives the
//! planners [`PLAN_SECONDS`](crate::system::PLAN_SECONDS), and a large map's local plan is
//! spread over more executions of LocalPathPlanning than fit in them (at most
//! [`FIELD_CELLS_PER_EXECUTION`] field cells each). [`finish_plan`] goes on as long as the
//! map's size needs.

use crate::components::FIELD_CELLS_PER_EXECUTION;
use crate::system::System;

/// The simulated time \[s\] the planners may still need to finish the plan of `system`'s
/// map: twice the executions of LocalPathPlanning that a full potential field of the map
/// takes (two more for the route and the descent), at its rate. `None` without a map.
pub fn plan_budget_seconds(system: &System) -> Option<f64> {
    let map = system.map()?;
    let executions = (map.width() * map.height()).div_ceil(FIELD_CELLS_PER_EXECUTION) + 2;
    Some(2.0 * executions as f64 / system.rates().local_path_planning)
}

/// Runs `system` until its planners have nothing left to do, within
/// [`plan_budget_seconds`]; nothing when they have settled already or there is no map.
/// Returns whether a plan was sent (`Mission::plan_sent`).
pub fn finish_plan(system: &mut System) -> crate::Result<bool> {
    if !system.wiring().planning_settled()
        && let Some(seconds) = plan_budget_seconds(system)
    {
        system.run_until_planned(seconds)?;
    }
    Ok(system.mission().plan_sent())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::system::{BuildOptions, MemoryResolver, Scenario, Setup, setup};

    /// A walled `side` × `side` yard of 0.1 m cells whose LocalPathPlanning runs at `hz`.
    fn yard(side: usize, hz: f64) -> System {
        let rows: Vec<String> = (0..side)
            .map(|y| {
                (0..side)
                    .map(|x| {
                        if x == 0 || y == 0 || x == side - 1 || y == side - 1 {
                            '#'
                        } else {
                            '.'
                        }
                    })
                    .collect()
            })
            .collect();
        let map =
            serde_json::json!({"width": side, "height": side, "grid_size": 0.1, "rows": rows});
        let far = side as f64 * 0.1 - 2.0;
        let scenario = serde_json::json!({
            "name": "yard", "description": "", "lesson": "",
            "map": {"format": "json", "path": "yard.json"},
            "start": {"x": 2.0, "y": 2.0}, "goal": {"x": far, "y": far, "heading_deg": 90},
            "rates": {"local_path_planning": hz},
            "time_limit": 600, "expect": {"outcome": "arrived"}
        });
        let scenario = Scenario::from_json(&scenario.to_string()).expect("a valid scenario");
        let files = MemoryResolver::new().with("yard.json", map.to_string().into_bytes());
        let options = BuildOptions { full_field: true };
        setup::build(&scenario, &files, &Setup::of(&scenario), options).expect("it sets up")
    }

    #[test]
    fn the_budget_grows_with_the_map_and_shrinks_with_the_rate() {
        // 700 × 700 = 490 000 cells: 8 executions of the field, 2 more, twice over.
        assert_eq!(plan_budget_seconds(&yard(700, 1.0)), Some(20.0));
        // 40 × 40: one execution.
        assert_eq!(plan_budget_seconds(&yard(40, 10.0)), Some(0.6));
    }

    #[test]
    fn a_large_map_at_a_slow_rate_is_planned_in_the_end() {
        let mut system = yard(700, 1.0);
        // The set-up's planning time is not enough for eight executions at 1 Hz.
        assert!(!system.wiring().planning_settled());
        assert!(finish_plan(&mut system).expect("it runs"));
        assert!(system.wiring().planning_settled());
    }

    #[test]
    fn a_settled_plan_takes_no_more_time() {
        let mut system = yard(40, 10.0);
        let before = system.time_ns();
        assert!(finish_plan(&mut system).expect("it runs"));
        assert_eq!(system.time_ns(), before);
    }
}
