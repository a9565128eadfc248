//! [`System::scene`]: the renderer's plain-data [`Scene`] of the system's current state
//! (map, `dmin`, potential field, paths, control points, local target, robot, trail, start
//! and goal), for PNGs and the browser canvas.

use crate::components::LocalPathPlanning;
use crate::interfaces::Pose;
use crate::local::CellState;
use crate::map::GridMap;
use crate::render::{FieldCellState, FieldView, Layers, RobotView, Scene};

use super::runtime::System;

/// What a [`Scene`] borrows that the components do not hold in the renderer's form: the
/// potential field as `f64` and [`FieldCellState`] slices (converted when the field
/// changes), and the caption.
#[derive(Debug, Clone, Default)]
pub(crate) struct SceneBuffers {
    field_key: Option<u64>,
    potential: Vec<f64>,
    state: Vec<FieldCellState>,
    caption: String,
}

fn field_state(s: CellState) -> FieldCellState {
    match s {
        CellState::Reached => FieldCellState::Reached,
        CellState::Impassable => FieldCellState::Impassable,
        CellState::Unreached => FieldCellState::Unreached,
    }
}

impl System {
    /// The scene of the current state with every layer on; `None` before a map is loaded.
    /// The field's key is LocalPathPlanning's plan count, the map's key [`System::map_key`],
    /// so the renderer recolours its cached layers only when they change.
    pub fn scene(&mut self) -> Option<Scene<'_>> {
        self.refresh_scene_buffers();
        let map: &GridMap = self.map()?;
        let lpp: &LocalPathPlanning = self.local_path_planning();
        let field = (!self.scene_buffers.potential.is_empty()).then(|| FieldView {
            potential: &self.scene_buffers.potential,
            state: &self.scene_buffers.state,
            key: self.scene_buffers.field_key.unwrap_or(0),
        });
        let local_target = lpp.local_target().map(|t| {
            let (x, y) = map.cell_center(t.cell);
            Pose::new(x, y, t.heading)
        });
        let geometry = self.motor_control().geometry();
        let physics = self.physics().physics();
        let robot = RobotView {
            pose: physics.pose(),
            body_radius: geometry.radius_of_body_area,
            axle_length: geometry.drive.axle_length(),
            wheel_radius: geometry.drive.radius_left(),
            bumped: physics.state().in_contact,
        };
        let placed = self.start().is_some() || self.is_driving();
        Some(Scene {
            map,
            map_key: self.map_key(),
            dmin: lpp.params().dmin,
            field,
            global_path: self.global_path(),
            local_path: lpp.merged_path(),
            control_points: lpp.control_points().map_or(&[], |c| &c.points[..]),
            local_target,
            robot: placed.then_some(robot),
            trail: self.trail(),
            start: self.start(),
            goal: self.goal(),
            direction: lpp.direction(),
            caption: &self.scene_buffers.caption,
            layers: Layers::ALL,
        })
    }

    fn refresh_scene_buffers(&mut self) {
        let caption = format!(
            "t = {:.1} s  {}{}",
            self.time(),
            self.state(),
            if self.is_arrived() { "  arrived" } else { "" }
        );
        let mut buffers = core::mem::take(&mut self.scene_buffers);
        buffers.caption = caption;
        let lpp = self.local_path_planning();
        let key = lpp.plan_count();
        let field = lpp.potential_field();
        match field {
            Some(f) if buffers.field_key != Some(key) || buffers.potential.is_empty() => {
                buffers.potential.clear();
                buffers
                    .potential
                    .extend(f.cells().iter().map(|c| c.potential));
                buffers.state.clear();
                buffers.state.extend(
                    f.state_codes()
                        .iter()
                        .map(|&c| field_state(CellState::from_code(c))),
                );
                buffers.field_key = Some(key);
            }
            Some(_) => {}
            None => {
                buffers.potential.clear();
                buffers.state.clear();
                buffers.field_key = None;
            }
        }
        // A field of another map's size (just after a load) is not drawn.
        if let Some(map) = self.map()
            && buffers.potential.len() != map.width() * map.height()
        {
            buffers.potential.clear();
            buffers.state.clear();
        }
        self.scene_buffers = buffers;
    }
}
