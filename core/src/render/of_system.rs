//! Drawing a [`System`]: its plain-data [`Scene`] (map, `dmin`, potential field, paths,
//! control points, local target, robot, trail, start and goal) and
//! [`Renderer::render_system`](super::Renderer::render_system), for PNGs and the browser
//! canvas. Drawing only reads the system.

use crate::components::LocalPathPlanning;
use crate::interfaces::Pose;
use crate::local::{CellState, PotentialField};
use crate::system::System;

use super::scene::{FieldCellState, FieldView, Ghost, Layers, RobotView, Scene};

/// The potential field in the renderer's form (`f64` and [`FieldCellState`] per cell),
/// converted when LocalPathPlanning's plan count changes: a drawing cache, kept by the
/// renderer.
#[derive(Debug, Clone, Default)]
pub struct FieldBuffers {
    key: Option<u64>,
    potential: Vec<f64>,
    state: Vec<FieldCellState>,
}

fn field_state(s: CellState) -> FieldCellState {
    match s {
        CellState::Reached => FieldCellState::Reached,
        CellState::Impassable => FieldCellState::Impassable,
        CellState::Unreached => FieldCellState::Unreached,
    }
}

impl FieldBuffers {
    /// Converts `field` (with its key) if the key differs from the last one converted;
    /// drops what it holds if there is no field.
    fn refresh(&mut self, field: Option<(&PotentialField, u64)>) {
        match field {
            Some((f, key)) => {
                if self.key != Some(key) || self.potential.len() != f.cells().len() {
                    self.potential.clear();
                    self.potential.extend(f.cells().iter().map(|c| c.potential));
                    self.state.clear();
                    self.state.extend(f.states().map(field_state));
                    self.key = Some(key);
                }
            }
            None => {
                self.potential.clear();
                self.state.clear();
                self.key = None;
            }
        }
    }

    fn view(&self) -> Option<FieldView<'_>> {
        let key = self.key?;
        Some(FieldView {
            potential: &self.potential,
            state: &self.state,
            key,
        })
    }
}

/// `system`'s robot and trail as a [`Ghost`] (the compare view's run B); `None` before it
/// was placed.
pub fn ghost_of(system: &System) -> Option<Ghost<'_>> {
    let wiring = system.wiring();
    let geometry = wiring.motor_geometry();
    let physics = wiring.physics().physics();
    let placed = system.mission().start().is_some() || system.is_driving();
    placed.then(|| Ghost {
        robot: RobotView {
            pose: physics.pose(),
            body_radius: geometry.radius_of_body_area,
            axle_length: geometry.drive.axle_length(),
            wheel_radius: geometry.drive.radius_left(),
            bumped: physics.state().in_contact,
        },
        trail: system.record().trail(),
    })
}

/// The caption under the picture: simulated time and what the robot is doing.
pub fn caption(system: &System) -> String {
    format!("t = {:.1} s  {}", system.time(), system.status())
}

/// The potential field `system` shows with `layers`, with its key (LocalPathPlanning's
/// plan count): none with the heat map off, before a plan, or when it does not have a cell
/// per map cell (a field of another map, just after a load).
pub(super) fn shown_field(system: &System, layers: Layers) -> Option<(&PotentialField, u64)> {
    if !layers.heat_map {
        return None;
    }
    let wiring = system.wiring();
    let cells = wiring.map().map(|m| m.width() * m.height())?;
    let lpp = wiring.local_path_planning();
    let field = lpp.potential_field().filter(|f| f.cells().len() == cells)?;
    Some((field, lpp.plan_count()))
}

/// The scene of `system` now with `layers` and `caption`; `None` before a map is loaded.
/// The field's key is LocalPathPlanning's plan count, the map's key the wiring's, so the
/// renderer recolours its cached layers only when they change. The field is converted only
/// when the heat map shows it.
pub fn scene_of<'a>(
    system: &'a System,
    buffers: &'a mut FieldBuffers,
    caption: &'a str,
    layers: Layers,
) -> Option<Scene<'a>> {
    buffers.refresh(shown_field(system, layers));
    let buffers: &'a FieldBuffers = buffers;
    scene_with(system, buffers.view(), caption, layers)
}

/// [`scene_of`] with `field` as the potential field.
pub(super) fn scene_with<'a>(
    system: &'a System,
    field: Option<FieldView<'a>>,
    caption: &'a str,
    layers: Layers,
) -> Option<Scene<'a>> {
    let wiring = system.wiring();
    let map = wiring.map()?;
    let lpp: &LocalPathPlanning = wiring.local_path_planning();
    let local_target = lpp.local_target().map(|t| {
        let (x, y) = map.cell_center(t.cell);
        Pose::new(x, y, t.heading)
    });
    let geometry = wiring.motor_geometry();
    let physics = wiring.physics().physics();
    let robot = RobotView {
        pose: physics.pose(),
        body_radius: geometry.radius_of_body_area,
        axle_length: geometry.drive.axle_length(),
        wheel_radius: geometry.drive.radius_left(),
        bumped: physics.state().in_contact,
    };
    let mission = system.mission();
    let placed = mission.start().is_some() || system.is_driving();
    Some(Scene {
        map,
        map_key: wiring.map_key(),
        dmin: lpp.params().dmin,
        field,
        global_path: mission.route(),
        local_path: lpp.merged_path(),
        control_points: lpp.control_points().map_or(&[], |c| &c.points[..]),
        local_target,
        robot: placed.then_some(robot),
        trail: system.record().trail(),
        ghost: None,
        start: mission.start(),
        goal: mission.goal(),
        // The direction LocalPathPlanning drives in; once arrived nothing drives, and the
        // direction asked for is shown (inside TargetArea the planner's choice at the goal
        // depends only on which side of the robot the goal's centre lies).
        direction: if mission.is_arrived() {
            mission.direction()
        } else {
            lpp.direction()
        },
        caption,
        layers,
    })
}
