//! The one set-up builder: a scenario (and a [`Setup`]'s changes to it) made into a system
//! ready to drive. `rtnav run`, `rtnav render`, the page's `Session`, share links and the
//! tests all build through [`build`], so they start from the same state bit for bit.
//!
//! A set-up is built as an operator would: the system at the scenario's rates, its
//! configuration, its map, the set-up's parameter changes, students' scripts and map edits,
//! start and goal
//! (`SetPosition`), then the planning components (MapBuilder, MapMaintenance,
//! GlobalPathPlanning, LocalPathPlanning) activated and run until they have planned — at most
//! [`PLAN_SECONDS`] of simulated time. The robot's own components stay Inactive: the drive
//! starts with an activation.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::scenario::{FileResolver, Scenario};
use crate::errors::ScenarioError;
use crate::interfaces::{Direction, Pose};
use crate::system::simulation::robot::System;
use crate::system::vocabulary::input::Input;
use crate::system::vocabulary::kind::ComponentKind;

/// How much simulated time the planners may take in a set-up at most \[s\].
pub const PLAN_SECONDS: f64 = 5.0;

/// The version written into share tokens and replays.
pub const SETUP_VERSION: u32 = 1;

/// A scenario's set-up as a person changed it: what a share link carries.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Setup {
    /// Version of the encoding.
    pub v: u32,
    /// The scenario's name.
    pub scenario: String,
    /// Where the robot is placed `[x, y, θ]` (m, m, rad); `None`: the scenario's start.
    pub start: Option<[f64; 3]>,
    /// The goal `[x, y, θ]`; `None`: the scenario's goal.
    pub goal: Option<[f64; 3]>,
    /// Driving backward.
    pub backward: bool,
    /// Map cells edited since the load: `[x, y, value]`, in (x, y) order.
    pub edits: Vec<(i64, i64, i16)>,
    /// Parameters that differ from the scenario's: component → name → value.
    pub params: BTreeMap<String, BTreeMap<String, f64>>,
    /// Students' scripts in components' places (spec §8): component → the script. Loaded
    /// after the parameters, so a script starts with the values they give.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub scripts: BTreeMap<String, ScriptText>,
}

/// A student's script as a set-up (and a replay, and a hand-in) carries it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScriptText {
    /// Its name (a file name).
    pub name: String,
    /// Its text.
    pub source: String,
}

impl Setup {
    /// The scenario as written: no change.
    pub fn of(scenario: &Scenario) -> Self {
        Self {
            v: SETUP_VERSION,
            scenario: scenario.name.clone(),
            start: None,
            goal: None,
            backward: scenario.direction.direction() == Direction::Backward,
            edits: Vec::new(),
            params: BTreeMap::new(),
            scripts: BTreeMap::new(),
        }
    }
}

/// How a set-up is drawn (not part of the state: the plans are the same either way).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct BuildOptions {
    /// LocalPathPlanning computes the whole potential field, for the heat map.
    pub full_field: bool,
}

fn pose(p: [f64; 3]) -> Pose {
    Pose::new(p[0], p[1], p[2])
}

/// Builds `scenario` (its files through `resolver`) with `setup`'s changes (module
/// documentation). Errors name the scenario and the step that failed.
pub fn build(
    scenario: &Scenario,
    resolver: &dyn FileResolver,
    setup: &Setup,
    options: BuildOptions,
) -> crate::Result<System> {
    scenario.validate()?;
    let fail = |what: &str, e: crate::Error| -> crate::Error {
        ScenarioError::Scenario {
            scenario: scenario.name.clone(),
            reason: format!("{what}: {e}"),
        }
        .into()
    };
    let mut system = System::new(scenario.rates).map_err(|e| fail("rates", e))?;
    system.set_full_field(options.full_field);
    let params = |config: &BTreeMap<String, BTreeMap<String, f64>>| -> crate::Result<Vec<Input>> {
        let mut inputs = Vec::new();
        for (component, values) in config {
            let component = ComponentKind::from_name(component)?;
            for (name, &value) in values {
                inputs.push(Input::SetParam {
                    component,
                    name: name.clone(),
                    value,
                });
            }
        }
        Ok(inputs)
    };
    for input in params(&scenario.config).map_err(|e| fail("config", e))? {
        system.apply(&input).map_err(|e| fail("config", e))?;
    }
    let map = scenario.load_map(resolver).map_err(|e| fail("map", e))?;
    system.load_map(map);
    for input in params(&setup.params).map_err(|e| fail("set-up parameters", e))? {
        system
            .apply(&input)
            .map_err(|e| fail("set-up parameters", e))?;
    }
    for (component, script) in &setup.scripts {
        let component =
            ComponentKind::from_name(component).map_err(|e| fail("scripts", e.into()))?;
        system
            .apply(&Input::LoadScript {
                component,
                name: script.name.clone(),
                source: script.source.clone(),
            })
            .map_err(|e| fail(&format!("the script {}", script.name), e))?;
    }
    if !setup.edits.is_empty() {
        system
            .apply(&Input::MapUpdate {
                cells: setup.edits.clone(),
            })
            .map_err(|e| fail("set-up map edits", e))?;
    }
    let direction = if setup.backward {
        Direction::Backward
    } else {
        Direction::Forward
    };
    let start = setup.start.map_or(scenario.start.pose(), pose);
    let goal = setup.goal.map_or(scenario.goal.pose(), pose);
    system
        .apply(&Input::SetPosition {
            start,
            goal,
            direction,
        })
        .map_err(|e| fail("start and goal", e))?;
    for component in ComponentKind::PLANNING {
        system
            .apply(&Input::Activate { component })
            .map_err(|e| fail("activating the planners", e))?;
    }
    system
        .run_until_planned(PLAN_SECONDS)
        .map_err(|e| fail("planning", e))?;
    Ok(system)
}
