//! The plain data the renderer draws: a [`Scene`] borrows everything it shows, so the
//! renderer knows no planner, motion or system type (Architecture Invariant: `render` depends
//! only on `map` and `interfaces`).

use serde::{Deserialize, Serialize};

use crate::errors::RenderError;
use crate::interfaces::{Direction, Pose};
use crate::map::{Cell, GridMap};

/// The state of one cell of a potential field (000 §5.2.4.9), as the heat map shows it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[repr(u8)]
pub enum FieldCellState {
    /// Obstacle distance ≤ `dmin`: potential 0, never expanded. Not coloured.
    Impassable = 0,
    /// Passable but not given a potential (yet). Not coloured.
    Unreached = 1,
    /// Has a potential: coloured on the heat map.
    Reached = 2,
}

/// A potential field to show as a heat map: one potential and one state per map cell, x
/// fastest like `MapData`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FieldView<'a> {
    /// Potential per cell; only `Reached` cells are read, and theirs must be finite and > 0
    /// (the local target has 0.1, 000 §5.2.4.9).
    pub potential: &'a [f64],
    /// State per cell.
    pub state: &'a [FieldCellState],
    /// The field's version: the renderer recolours the heat map only when this changes, so
    /// give a new key with every new field.
    pub key: u64,
}

/// The robot as drawn: a body circle with its heading and two wheels (002 §4.2
/// `radiusOfBodyArea`, `lengthOfAxle`, `radiusOfLeftWheel`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RobotView {
    /// Where it is and where it faces.
    pub pose: Pose,
    /// Body radius, metres (`radiusOfBodyArea`).
    pub body_radius: f64,
    /// Distance between the wheels, metres (`lengthOfAxle`).
    pub axle_length: f64,
    /// Wheel radius, metres (`radiusOfLeftWheel` / `radiusOfRightWheel`).
    pub wheel_radius: f64,
    /// The body touches an obstacle (spec §5 Physics: "the GUI shows it"): drawn in red.
    pub bumped: bool,
}

impl RobotView {
    /// The MotorControl defaults (002 §4.2): body radius 0.45 m, axle 0.441 m, wheels 0.1 m.
    pub fn with_defaults(pose: Pose) -> Self {
        Self {
            pose,
            body_radius: 0.45,
            axle_length: 0.441,
            wheel_radius: 0.1,
            bumped: false,
        }
    }
}

/// Which layers to draw. Every layer is on by default; in serde form a missing field is on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
#[serde(default, deny_unknown_fields)]
pub struct Layers {
    /// Obstacle cells.
    pub occupancy: bool,
    /// Cells within `dmin` of an obstacle (000 §5.2.4.2), tinted.
    pub dmin_zone: bool,
    /// The potential field, log scale, with its colour bar.
    pub heat_map: bool,
    /// The global path (GlobalPathPlanning's `GlobalPathCourse`).
    pub global_path: bool,
    /// The merged local path (000 §5.2.4.11).
    pub local_path: bool,
    /// The control points (000 §5.2.4.12).
    pub control_points: bool,
    /// The local target (000 §5.2.4.8).
    pub local_target: bool,
    /// The robot body, heading and wheels.
    pub robot: bool,
    /// Where the robot has been.
    pub trail: bool,
    /// Start and goal arrows (`SetPosition`).
    pub start_goal: bool,
    /// The scale bar.
    pub scale_bar: bool,
    /// The legend of the layers shown.
    pub legend: bool,
    /// The driving direction and the caption text.
    pub caption: bool,
}

impl Layers {
    /// Every layer on.
    pub const ALL: Self = Self {
        occupancy: true,
        dmin_zone: true,
        heat_map: true,
        global_path: true,
        local_path: true,
        control_points: true,
        local_target: true,
        robot: true,
        trail: true,
        start_goal: true,
        scale_bar: true,
        legend: true,
        caption: true,
    };

    /// Every layer off (a blank map area and an empty panel).
    pub const NONE: Self = Self {
        occupancy: false,
        dmin_zone: false,
        heat_map: false,
        global_path: false,
        local_path: false,
        control_points: false,
        local_target: false,
        robot: false,
        trail: false,
        start_goal: false,
        scale_bar: false,
        legend: false,
        caption: false,
    };
}

impl Layers {
    /// Every layer's name (as serialized) and where its switch is.
    fn switches(&mut self) -> [(&'static str, &mut bool); 13] {
        [
            ("occupancy", &mut self.occupancy),
            ("dmin_zone", &mut self.dmin_zone),
            ("heat_map", &mut self.heat_map),
            ("global_path", &mut self.global_path),
            ("local_path", &mut self.local_path),
            ("control_points", &mut self.control_points),
            ("local_target", &mut self.local_target),
            ("robot", &mut self.robot),
            ("trail", &mut self.trail),
            ("start_goal", &mut self.start_goal),
            ("scale_bar", &mut self.scale_bar),
            ("legend", &mut self.legend),
            ("caption", &mut self.caption),
        ]
    }

    /// Shows (`on`) or hides the layer `name` (`heat_map`, `trail`, …); an unknown name is
    /// refused and nothing changes.
    pub fn set(&mut self, name: &str, on: bool) -> Result<(), crate::errors::RenderError> {
        let mut switches = self.switches();
        let known: Vec<&str> = switches.iter().map(|(n, _)| *n).collect();
        let known = known.join(", ");
        match switches.iter_mut().find(|(n, _)| *n == name) {
            Some((_, switch)) => {
                **switch = on;
                Ok(())
            }
            None => Err(crate::errors::RenderError::UnknownLayer {
                name: name.to_owned(),
                known,
            }),
        }
    }
}

impl Default for Layers {
    fn default() -> Self {
        Self::ALL
    }
}

/// A second robot drawn faintly over the scene, with its trail: the compare view's run B.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ghost<'a> {
    /// Where it is, its size.
    pub robot: RobotView,
    /// Its past positions, metres, oldest first.
    pub trail: &'a [(f64, f64)],
}

/// Everything one frame shows, borrowed from its owners. Empty slices and `None` draw
/// nothing. Build one with [`Scene::new`] and struct update syntax.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scene<'a> {
    /// The map.
    pub map: &'a GridMap,
    /// The map's version: the renderer redraws the occupancy and `dmin` layers only when this
    /// (or the map's size, origin, grid size or `version()`, or `dmin`) changes, so give a new
    /// key whenever the map's cells change.
    pub map_key: u64,
    /// `dmin`, metres (000 §4.2): the closest allowed approach to an obstacle.
    pub dmin: f64,
    /// The potential field, if any.
    pub field: Option<FieldView<'a>>,
    /// The global path, cells, start first.
    pub global_path: &'a [Cell],
    /// The merged local path, cells, current position first.
    pub local_path: &'a [Cell],
    /// Control points, metres, current position first, goal last.
    pub control_points: &'a [(f64, f64)],
    /// The local target.
    pub local_target: Option<Pose>,
    /// The robot.
    pub robot: Option<RobotView>,
    /// Past robot positions, metres, oldest first.
    pub trail: &'a [(f64, f64)],
    /// A second robot drawn as a ghost (drawn with the robot and trail layers).
    pub ghost: Option<Ghost<'a>>,
    /// The start pose of `SetPosition`.
    pub start: Option<Pose>,
    /// The goal pose of `SetPosition`.
    pub goal: Option<Pose>,
    /// Forward or backward driving (000 §5.2.4.4).
    pub direction: Direction,
    /// A short text for the panel (e.g. time and status); printable ASCII, others drawn as `?`.
    pub caption: &'a str,
    /// Which layers to draw.
    pub layers: Layers,
}

impl<'a> Scene<'a> {
    /// A scene showing only `map` (key `map_key`), `dmin` 0.5 m (000 §4.2 default), all
    /// layers on.
    pub fn new(map: &'a GridMap, map_key: u64) -> Self {
        Self {
            map,
            map_key,
            dmin: 0.5,
            field: None,
            global_path: &[],
            local_path: &[],
            control_points: &[],
            local_target: None,
            robot: None,
            trail: &[],
            ghost: None,
            start: None,
            goal: None,
            direction: Direction::Forward,
            caption: "",
            layers: Layers::ALL,
        }
    }

    /// Checks everything but the field's potentials (those are checked when the heat map is
    /// recoloured): finite numbers, lengths, cells inside the map.
    pub(crate) fn validate(&self) -> Result<(), RenderError> {
        check(
            "dmin",
            None,
            self.dmin,
            self.dmin.is_finite() && self.dmin >= 0.0,
            FINITE_NON_NEGATIVE,
        )?;
        let cells = self.map.width() * self.map.height();
        if let Some(field) = &self.field {
            for (what, len) in [
                ("field.potential", field.potential.len()),
                ("field.state", field.state.len()),
            ] {
                if len != cells {
                    return Err(RenderError::FieldLength {
                        what,
                        len,
                        expected: cells,
                    });
                }
            }
        }
        for (what, path) in [
            ("global_path", self.global_path),
            ("local_path", self.local_path),
        ] {
            let (w, h) = (self.map.width(), self.map.height());
            if let Some((index, &(x, y))) =
                path.iter().enumerate().find(|(_, c)| c.0 >= w || c.1 >= h)
            {
                return Err(RenderError::CellOutside {
                    what,
                    index,
                    x,
                    y,
                    width: w,
                    height: h,
                });
            }
        }
        check_points("control_points", self.control_points)?;
        check_points("trail", self.trail)?;
        if let Some(g) = &self.ghost {
            check_points("ghost.trail", g.trail)?;
            check_pose(
                ["ghost.pose.x", "ghost.pose.y", "ghost.pose.theta"],
                &g.robot.pose,
            )?;
            let r = g.robot.body_radius;
            check(
                "ghost.body_radius",
                None,
                r,
                r.is_finite() && r >= 0.0,
                FINITE_NON_NEGATIVE,
            )?;
        }
        if let Some(p) = &self.local_target {
            check_pose(
                ["local_target.x", "local_target.y", "local_target.theta"],
                p,
            )?;
        }
        if let Some(p) = &self.start {
            check_pose(["start.x", "start.y", "start.theta"], p)?;
        }
        if let Some(p) = &self.goal {
            check_pose(["goal.x", "goal.y", "goal.theta"], p)?;
        }
        if let Some(r) = &self.robot {
            check_pose(
                ["robot.pose.x", "robot.pose.y", "robot.pose.theta"],
                &r.pose,
            )?;
            for (what, v) in [
                ("robot.body_radius", r.body_radius),
                ("robot.axle_length", r.axle_length),
                ("robot.wheel_radius", r.wheel_radius),
            ] {
                check(
                    what,
                    None,
                    v,
                    v.is_finite() && v >= 0.0,
                    FINITE_NON_NEGATIVE,
                )?;
            }
        }
        Ok(())
    }
}

const FINITE: &str = "finite";
const FINITE_NON_NEGATIVE: &str = "finite and ≥ 0";

fn check(
    what: &'static str,
    index: Option<usize>,
    value: f64,
    ok: bool,
    expected: &'static str,
) -> Result<(), RenderError> {
    if ok {
        Ok(())
    } else {
        Err(RenderError::BadNumber {
            what,
            index,
            value,
            expected,
        })
    }
}

fn check_pose(names: [&'static str; 3], p: &Pose) -> Result<(), RenderError> {
    for (name, v) in names.into_iter().zip([p.x, p.y, p.theta]) {
        check(name, None, v, v.is_finite(), FINITE)?;
    }
    Ok(())
}

fn check_points(what: &'static str, points: &[(f64, f64)]) -> Result<(), RenderError> {
    for (i, &(x, y)) in points.iter().enumerate() {
        for v in [x, y] {
            check(what, Some(i), v, v.is_finite(), FINITE)?;
        }
    }
    Ok(())
}
