//! A scenario read as the core reads it, for its author (`rtnav scenario check`): the map
//! loads, the start and the goal are on the map and out of the obstacles, the system sets up
//! and plans as the page does, a route is found (unless the scenario expects a planning
//! failure), and each parameter the exercise lets change is known to its component — and an
//! exercise that no answer can pass (a parameter the Parameters tab warns about, set by the
//! scenario, that the exercise does not let change) is refused.

use std::fmt;

use crate::system::{
    BuildOptions, ComponentKind, EventKind, FileResolver, OutcomeKind, ParameterWarning, Scenario,
    Setup, setup,
};

/// The start or the goal.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum End {
    /// The start.
    Start,
    /// The goal.
    Goal,
}

impl fmt::Display for End {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Start => "start",
            Self::Goal => "goal",
        })
    }
}

/// What the check found, in order; a [`Finding::note`] is worth the author's attention but
/// not wrong.
#[derive(Debug, Clone, PartialEq)]
pub enum Finding {
    /// The map's size.
    Map {
        /// Cells across.
        width: usize,
        /// Cells up.
        height: usize,
        /// Metres per cell.
        grid_size: f64,
    },
    /// The start or the goal nearer an obstacle than the body's radius: the robot touches
    /// it there.
    NearObstacle {
        /// Which.
        end: End,
        /// Its distance from the nearest obstacle \[m\].
        distance: f64,
        /// The body's radius (MotorControl's `radiusOfBodyArea`) \[m\].
        radius: f64,
    },
    /// No plan, as the scenario expects.
    PlanFailsAsExpected {
        /// The planner's reason.
        why: String,
    },
    /// The route found.
    Route {
        /// Its cells.
        cells: usize,
    },
    /// A parameter the Parameters tab warns about as given, which the exercise lets change:
    /// an answer must change it.
    MustChange {
        /// `Component.Name`.
        parameter: String,
    },
    /// The exercise.
    Exercise {
        /// Its checks.
        checks: usize,
        /// What it lets change.
        may_change: Vec<String>,
    },
}

impl Finding {
    /// Whether it is a note (worth the author's attention) rather than a plain fact.
    pub fn is_note(&self) -> bool {
        matches!(self, Self::NearObstacle { .. } | Self::MustChange { .. })
    }
}

impl fmt::Display for Finding {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Map {
                width,
                height,
                grid_size,
            } => write!(f, "{width} × {height} cells of {grid_size} m"),
            Self::NearObstacle {
                end,
                distance,
                radius,
            } => write!(
                f,
                "the {end} is {distance:.2} m from an obstacle, less than the body's radius \
                 ({radius} m, MotorControl.radiusOfBodyArea): the robot touches it there"
            ),
            Self::PlanFailsAsExpected { why } => write!(f, "fails, as expected: {why}"),
            Self::Route { cells } => write!(f, "a route of {cells} cells"),
            Self::MustChange { parameter } => write!(
                f,
                "the Parameters tab warns about {parameter} as given: an answer must change it"
            ),
            Self::Exercise { checks, may_change } => write!(
                f,
                "{checks} check{}; may change {}",
                if *checks == 1 { "" } else { "s" },
                if may_change.is_empty() {
                    "nothing".to_owned()
                } else {
                    may_change.join(", ")
                }
            ),
        }
    }
}

/// What is wrong with a scenario: the first thing the check finds.
#[derive(Debug, thiserror::Error)]
pub enum ScenarioProblem {
    /// The map does not load.
    #[error("the map does not load: {0}")]
    MapDoesNotLoad(Box<crate::Error>),
    /// The start or the goal is off the map.
    #[error(
        "the {end} ({x}, {y}) is off the map, which covers x {x0} to {x1} and y {y0} to {y1} m"
    )]
    OffMap {
        /// Which.
        end: End,
        /// Its x \[m\].
        x: f64,
        /// Its y \[m\].
        y: f64,
        /// The map's west edge \[m\].
        x0: f64,
        /// Its east edge \[m\].
        x1: f64,
        /// Its south edge \[m\].
        y0: f64,
        /// Its north edge \[m\].
        y1: f64,
    },
    /// The start or the goal is in an obstacle.
    #[error("the {end} ({x}, {y}) is inside an obstacle (cell {i}, {j})")]
    InObstacle {
        /// Which.
        end: End,
        /// Its x \[m\].
        x: f64,
        /// Its y \[m\].
        y: f64,
        /// Its cell's column.
        i: i64,
        /// Its cell's row.
        j: i64,
    },
    /// The system cannot be set up.
    #[error("the core cannot set it up: {0}")]
    SetUp(Box<crate::Error>),
    /// No plan from the start to the goal, and the scenario expects another outcome.
    #[error("no plan from the start to the goal ({why}); the scenario expects `{expected}`")]
    NoPlan {
        /// The planner's reason.
        why: String,
        /// The outcome expected, as the file writes it.
        expected: String,
    },
    /// The exercise lets a component change that does not exist.
    #[error("{0}")]
    UnknownComponent(crate::system::SystemError),
    /// The exercise lets a parameter change that its component does not have.
    #[error("exercise: may_change `{name}`: {component} has no parameter `{parameter}`")]
    UnknownParameter {
        /// `Component.Name` as written.
        name: String,
        /// The component.
        component: String,
        /// The parameter.
        parameter: String,
    },
    /// A parameter the Parameters tab warns about as the scenario sets it, which the
    /// exercise does not let change: no answer can pass.
    #[error(
        "exercise: the Parameters tab warns about {0} as the scenario sets it, and the \
         exercise does not let it change: no answer can pass"
    )]
    NoAnswerCanPass(String),
}

/// Checks `scenario` with its files from `resolver` (module documentation): what it found,
/// or the first thing wrong.
pub fn check_scenario(
    scenario: &Scenario,
    resolver: &dyn FileResolver,
) -> Result<Vec<Finding>, ScenarioProblem> {
    let map = scenario
        .load_map(resolver)
        .map_err(|e| ScenarioProblem::MapDoesNotLoad(Box::new(e)))?;
    let mut found = vec![Finding::Map {
        width: map.width(),
        height: map.height(),
        grid_size: map.grid_size(),
    }];
    let ends = [(End::Start, scenario.start), (End::Goal, scenario.goal)];
    for (end, pose) in ends {
        let (x, y) = (pose.x, pose.y);
        let cell = map.world_to_cell(x, y).ok_or_else(|| {
            let (x0, y0) = map.origin();
            ScenarioProblem::OffMap {
                end,
                x,
                y,
                x0,
                x1: x0 + map.width() as f64 * map.grid_size(),
                y0,
                y1: y0 + map.height() as f64 * map.grid_size(),
            }
        })?;
        let (i, j) = (cell.0 as i64, cell.1 as i64);
        if map.is_obstacle(i, j) {
            return Err(ScenarioProblem::InObstacle { end, x, y, i, j });
        }
    }
    let system = setup::build(
        scenario,
        resolver,
        &Setup::of(scenario),
        BuildOptions::default(),
    )
    .map_err(|e| ScenarioProblem::SetUp(Box::new(e)))?;
    let radius = system
        .wiring()
        .config(ComponentKind::MotorControl)
        .and_then(|c| Ok(c.value("radiusOfBodyArea")?))
        .unwrap_or(0.0);
    for (end, pose) in ends {
        if let Some(cell) = map.world_to_cell(pose.x, pose.y) {
            let distance = map.obstacle_distance(cell);
            if distance < radius {
                found.push(Finding::NearObstacle {
                    end,
                    distance,
                    radius,
                });
            }
        }
    }
    let failure = system.mission().failure().map(|e| match e {
        EventKind::PlanningFailed { planner, reason } => format!("{planner}: {reason}"),
        other => format!("{other:?}"),
    });
    match (failure, scenario.expect.outcome) {
        (Some(why), OutcomeKind::PlanningFailed) => {
            found.push(Finding::PlanFailsAsExpected { why })
        }
        (Some(why), expected) => {
            return Err(ScenarioProblem::NoPlan {
                why,
                expected: serde_json::to_value(expected)
                    .ok()
                    .and_then(|v| v.as_str().map(str::to_owned))
                    .unwrap_or_default(),
            });
        }
        (None, _) => found.push(Finding::Route {
            cells: system.mission().route().len(),
        }),
    }
    if let Some(exercise) = &scenario.exercise {
        for name in &exercise.may_change {
            let Some((component, parameter)) = name.split_once('.') else {
                continue;
            };
            let kind =
                ComponentKind::from_name(component).map_err(ScenarioProblem::UnknownComponent)?;
            let known = system
                .wiring()
                .config(kind)
                .is_ok_and(|c| c.specs().iter().any(|s| s.name == parameter));
            if !known {
                return Err(ScenarioProblem::UnknownParameter {
                    name: name.clone(),
                    component: component.to_owned(),
                    parameter: parameter.to_owned(),
                });
            }
        }
        // The rule every exercise holds: a value the Parameters tab warns about never
        // passes. One the scenario sets and the student may not change fails every answer.
        for warned in ParameterWarning::warned(system.wiring()) {
            if !exercise.may_change.contains(&warned) {
                return Err(ScenarioProblem::NoAnswerCanPass(warned));
            }
            found.push(Finding::MustChange { parameter: warned });
        }
        found.push(Finding::Exercise {
            checks: exercise.checks.len(),
            may_change: exercise.may_change.clone(),
        });
    }
    Ok(found)
}

#[cfg(test)]
#[cfg(not(target_arch = "wasm32"))]
mod tests {
    use super::*;
    use crate::system::DirResolver;

    fn repo() -> DirResolver {
        DirResolver::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
    }

    /// The fixture `name`, changed by `edit`.
    fn scenario(name: &str, edit: impl FnOnce(&mut serde_json::Value)) -> Scenario {
        let path = format!(
            "{}/../fixtures/scenarios/{name}.json",
            env!("CARGO_MANIFEST_DIR")
        );
        let text = std::fs::read_to_string(path).expect("the fixture");
        let mut json: serde_json::Value = serde_json::from_str(&text).expect("JSON");
        edit(&mut json);
        Scenario::from_json(&json.to_string()).expect("a valid scenario")
    }

    #[test]
    fn an_exercise_as_written_is_found_right() {
        let found = check_scenario(&scenario("ex_door_dmin", |_| {}), &repo()).expect("right");
        assert!(matches!(found[0], Finding::Map { .. }), "{found:?}");
        // Its dmin is too large for the door, as the scenario expects.
        assert!(
            found
                .iter()
                .any(|f| matches!(f, Finding::PlanFailsAsExpected { .. })),
            "{found:?}"
        );
        let open = check_scenario(&scenario("open_field", |_| {}), &repo()).expect("right");
        assert!(
            open.iter()
                .any(|f| matches!(f, Finding::Route { cells } if *cells > 0)),
            "{open:?}"
        );
        let exercise = found.last().expect("findings").to_string();
        assert!(
            exercise.ends_with("may change LocalPathPlanning.dmin"),
            "{exercise}"
        );
    }

    #[test]
    fn a_start_off_the_map_or_in_an_obstacle_is_wrong() {
        let off = scenario("open_field", |j| j["start"]["x"] = serde_json::json!(-5.0));
        let problem = check_scenario(&off, &repo()).expect_err("off the map");
        assert!(matches!(
            problem,
            ScenarioProblem::OffMap {
                end: End::Start,
                ..
            }
        ));
        assert!(
            problem
                .to_string()
                .starts_with("the start (-5, 2.5) is off the map")
        );
        // open_field's fence is its outermost ring of cells.
        let walled = scenario("open_field", |j| j["goal"]["x"] = serde_json::json!(0.1));
        let problem = check_scenario(&walled, &repo()).expect_err("in the fence");
        assert!(
            matches!(problem, ScenarioProblem::InObstacle { end: End::Goal, .. }),
            "{problem}"
        );
    }

    #[test]
    fn an_exercise_no_answer_can_pass_or_with_an_unknown_parameter_is_wrong() {
        let unknown = scenario("ex_door_dmin", |j| {
            j["exercise"]["may_change"] = serde_json::json!(["LocalPathPlanning.nonesuch"]);
        });
        let problem = check_scenario(&unknown, &repo()).expect_err("unknown");
        assert_eq!(
            problem.to_string(),
            "exercise: may_change `LocalPathPlanning.nonesuch`: LocalPathPlanning has no \
             parameter `nonesuch`"
        );
        // A dmin the Parameters tab warns about, which the student may not change.
        let stuck = scenario("ex_door_dmin", |j| {
            j["config"]["LocalPathPlanning"]["dmin"] = serde_json::json!(0.45);
            j["exercise"]["may_change"] = serde_json::json!([]);
        });
        let problem = check_scenario(&stuck, &repo()).expect_err("no answer");
        assert!(
            matches!(problem, ScenarioProblem::NoAnswerCanPass(_)),
            "{problem}"
        );
    }
}
