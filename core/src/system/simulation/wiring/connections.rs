//! The wiring's connections: every data connection as made and every service
//! port with its calls (`links.rs`), InventGUI's in-ports, and the cut and restore of a data
//! connection between two components.

use super::Wiring;
use crate::components::{
    DriveControl, GlobalPathPlanning, LocalPathPlanning, Localization, MapBuilder, MapMaintenance,
    MotorControl, PhysicsSim,
};
use crate::errors::SystemError;
use crate::interfaces::Pose;
use crate::present::number;
use crate::rtc::{PortView, short};
use crate::system::simulation::links::Peer;
use crate::system::simulation::links::{Links, Services};
use crate::system::vocabulary::events::EventKind;
use crate::system::vocabulary::kind::ComponentKind;

/// A service call the wiring makes (spec §0's service arrows), to record on the ports it
/// reaches with the words the System view shows.
#[derive(Debug, Clone, Copy)]
pub(super) enum Call {
    /// MapBuilder's `SetMap` (width, height, `GridSize`) to every map holder.
    SetMap(usize, usize, f64),
    /// MapMaintenance's `MapUpdate` of so many cells to every map holder.
    MapUpdate(usize),
    /// InventGUI's edit of so many cells, to MapMaintenance.
    EditMap(usize),
    /// InventGUI's map, to MapBuilder (width, height).
    LoadMap(usize, usize),
    /// GlobalPathPlanning's `GlobalPathCourse` of so many cells, to LocalPathPlanning.
    GlobalPathCourse(i32),
    /// InventGUI's `SetPosition(start, goal, direction)`; with `true` the robot is placed.
    SetPosition(Pose, Pose, i16, bool),
    /// InventGUI's `Clear`.
    Clear,
    /// InventGUI's `SafeMode`.
    SafeMode,
    /// InventGUI's `SetPDGain(PGainL, PGainR, DGainL, DGainR)`.
    SetPdGain([f64; 4]),
    /// Bump detection's `Stop`, to MotorControl.
    Stop,
}

const MAP_HOLDERS: [ComponentKind; 5] = [
    ComponentKind::MapMaintenance,
    ComponentKind::GlobalPathPlanning,
    ComponentKind::PhysicsSim,
    ComponentKind::DriveControl,
    ComponentKind::LocalPathPlanning,
];

impl Wiring {
    /// Records `call` on every service port it reaches.
    pub(super) fn record_call(&mut self, call: Call) {
        use ComponentKind as K;
        const GUI: &str = "InventGUIProv";
        let pose = |p: Pose| format!("{}, {}, {}", short(p.x), short(p.y), short(p.theta));
        match call {
            Call::SetMap(w, h, grid) => {
                let text = format!("SetMap({w}×{h} cells, GridSize {} m)", number(grid));
                for kind in MAP_HOLDERS {
                    self.called(kind, "MapBuilderProv", text.clone());
                }
            }
            Call::MapUpdate(cells) => {
                for kind in &MAP_HOLDERS[1..] {
                    self.called(
                        *kind,
                        "MapMaintenanceProv",
                        format!("MapUpdate({cells} cells)"),
                    );
                }
            }
            Call::EditMap(cells) => {
                self.called(K::MapMaintenance, GUI, format!("MapUpdate({cells} cells)"));
            }
            Call::LoadMap(w, h) => {
                self.called(K::MapBuilder, GUI, format!("LoadMap({w}×{h} cells)"))
            }
            Call::GlobalPathCourse(n) => {
                let text = format!("GlobalPathCourse({n} cells)");
                self.called(K::LocalPathPlanning, "GlobalPathProv", text);
            }
            Call::SetPosition(start, goal, dir, place) => {
                let text = format!("SetPosition({}, {}, {dir})", pose(start), pose(goal));
                self.called(K::LocalPathPlanning, GUI, text.clone());
                self.called(K::GlobalPathPlanning, GUI, text);
                if place {
                    self.called(K::PhysicsSim, GUI, format!("SetPose({})", pose(start)));
                    self.called(
                        K::Localization,
                        GUI,
                        format!("SetStartPose({})", pose(start)),
                    );
                }
            }
            Call::Clear => {
                self.called(K::LocalPathPlanning, GUI, "Clear()");
                self.called(K::GlobalPathPlanning, GUI, "Clear()");
            }
            Call::SafeMode => self.called(K::LocalPathPlanning, GUI, "SafeMode()"),
            Call::SetPdGain(g) => {
                let text = format!(
                    "SetPDGain({}, {}, {}, {})",
                    short(g[0]),
                    short(g[1]),
                    short(g[2]),
                    short(g[3])
                );
                self.called(K::MotorControl, "InventGUIProvPort", text);
            }
            Call::Stop => self.called(K::MotorControl, "BumpProvPort", "Stop()"),
        }
    }

    /// Records a call on a service port (the system's description shows the last one).
    pub(in crate::system) fn called(
        &mut self,
        owner: ComponentKind,
        port: &str,
        text: impl Into<String>,
    ) {
        let recorded = self.services.called(owner, port, self.ec.time_ns(), text);
        debug_assert!(
            recorded,
            "{owner}.{port} is not in the service ports' table"
        );
    }

    /// Every data connection, as made.
    pub fn links(&self) -> &Links {
        &self.links
    }

    /// Every service port, with its last call.
    pub fn services(&self) -> &Services {
        &self.services
    }

    /// InventGUI's in-ports: the system's ends of the connections that carry facts to the
    /// person (paths, failures, safety stops, bumps).
    pub fn gui_ports(&self) -> Vec<PortView> {
        let rx = &self.rx;
        vec![
            rx.local_path.view(),
            rx.local_failure.view(),
            rx.global_failure.view(),
            rx.safety_stop.view(),
            rx.bump.view(),
        ]
    }

    /// Cuts (`cut`) or restores the data connection `id` between two components
    /// (`DriveControl.TargetVelocity->MotorControl.TargetVelocity`), as RT System Editor
    /// deletes and re-creates a connector: while cut, the out-port's samples do not reach
    /// the in-port. Refused, changing nothing, for an unknown id, a connection to InventGUI,
    /// or one already in that state.
    pub fn set_connection_cut(&mut self, id: &str, cut: bool) -> crate::Result<()> {
        let link = self
            .links
            .find(id)
            .ok_or_else(|| SystemError::UnknownConnection {
                id: crate::present::excerpt(id),
                known: self
                    .links
                    .all()
                    .iter()
                    .filter(|l| l.cuttable())
                    .map(|l| l.id())
                    .collect::<Vec<_>>()
                    .join(", "),
            })?;
        if !link.cuttable() {
            return Err(SystemError::ConnectionKept { id: id.to_owned() }.into());
        }
        if link.connector.is_cut() == cut {
            return Err(SystemError::ConnectionAlready {
                id: id.to_owned(),
                state: if cut { "cut" } else { "connected" },
            }
            .into());
        }
        link.connector.set_cut(cut);
        let connection = id.replace("->", " → ");
        self.facts.push(if cut {
            EventKind::ConnectionCut { connection }
        } else {
            EventKind::ConnectionRestored { connection }
        });
        Ok(())
    }
}

/// Making the connections: when the wiring is made, and in a copy.
impl Wiring {
    /// Connects the data ports of spec §0 and the system's bridges (`crate::system`'s
    /// tables): when the wiring is made, and in an unconnected copy ([`Wiring::try_clone`]).
    pub(super) fn connect(&mut self) {
        use ComponentKind as K;
        let mut links = Links::default();
        macro_rules! link {
            ($from:ident . $out:ident => system . $rx:ident) => {{
                let port = self.rx.$rx.share();
                let from = self.get_mut::<$from>(K::$from);
                links.connect(Peer::Rtc(K::$from), &mut from.$out, Peer::Gui, &port);
            }};
            ($from:ident . $out:ident => $to:ident . $inp:ident) => {{
                let port = self.get::<$to>(K::$to).$inp.share();
                let from = self.get_mut::<$from>(K::$from);
                links.connect(
                    Peer::Rtc(K::$from),
                    &mut from.$out,
                    Peer::Rtc(K::$to),
                    &port,
                );
            }};
        }
        // Data ports (spec §0), each connection recorded for the system's description.
        link!(PhysicsSim.angle => MotorControl.in_current_wheel_angle);
        link!(PhysicsSim.position => MotorControl.in_simulated_position);
        link!(MotorControl.torque => PhysicsSim.torque);
        link!(MotorControl.out_current_wheel_angle => Localization.in_current_wheel_angle);
        link!(MotorControl.out_simulated_position_to_localization => Localization.in_simulated_position);
        link!(Localization.out_current_position => LocalPathPlanning.in_current_position);
        link!(Localization.out_current_position => DriveControl.in_current_position);
        link!(Localization.out_current_position => GlobalPathPlanning.in_current_position);
        link!(DriveControl.target_velocity => MotorControl.target_velocity);
        link!(DriveControl.out_deviating => LocalPathPlanning.in_deviating);
        link!(LocalPathPlanning.drive_cons => DriveControl.in_control_points);
        // The system's ends: facts for InventGUI.
        link!(GlobalPathPlanning.planning_failure => system.global_failure);
        link!(LocalPathPlanning.invent_gui_cons => system.local_path);
        link!(LocalPathPlanning.invent_gui_failure => system.local_failure);
        link!(PhysicsSim.bump => system.bump);
        link!(DriveControl.safety_stop => system.safety_stop);
        // ... and service calls (`Services`), not data connections of the diagram.
        let port = self.rx.set_map.share();
        self.get_mut::<MapBuilder>(K::MapBuilder)
            .set_map
            .connect(&port);
        let port = self.rx.map_update.share();
        self.get_mut::<MapMaintenance>(K::MapMaintenance)
            .map_update_out
            .connect(&port);
        let port = self.rx.global_path.share();
        self.get_mut::<GlobalPathPlanning>(K::GlobalPathPlanning)
            .global_path_course
            .connect(&port);
        self.links = links;
    }

    /// A copy in the same state, connected alike, sharing nothing (a replay's checkpoint).
    /// `None` while an injected sample waits for its component (a tick later it can be).
    pub fn try_clone(&self) -> Option<Self> {
        let mut copy = Self {
            ec: self.ec.try_clone()?,
            rx: self.rx.clone(),
            map_loads: self.map_loads,
            map_updates: self.map_updates,
            links: Links::default(),
            services: self.services.clone(),
            facts: self.facts.clone(),
            clearance_checked: self.clearance_checked,
        };
        copy.connect();
        copy.links.copy_state_from(&self.links);
        Some(copy)
    }
}
