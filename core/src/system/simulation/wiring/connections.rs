//! The wiring's connections (spec §0), all in one place: the record of every data
//! connection as it is made ([`Links::connect`], the only way the wiring connects two
//! components), with its [`Connector`], and of every service port with the calls made on it
//! ([`Services`]); the making of the connections ([`Wiring::connect`], also in a copy),
//! the recording of each service call where the wiring makes it ([`ServiceCall`]),
//! InventGUI's in-ports, and the cut and restore of a data connection between two
//! components. The system's description ([`SystemGraph`](crate::system::SystemGraph)) is
//! read from here, so what it shows is what the wiring connected and called.

use serde::Serialize;

use super::Wiring;
use crate::errors::SystemError;
use crate::interfaces::Pose;
use crate::present::number;
use crate::rtc::{Connector, InPort, OutPort, PortView, Sample, short};
use crate::system::vocabulary::events::EventKind;
use crate::system::vocabulary::kind::ComponentKind;

/// Who is at one end of a connection: one of the eight RT-components, or InventGUI (the
/// person's side: the page, the command line, a scenario's timeline — whoever makes
/// requests and reads the log).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
pub enum Peer {
    /// An RT-component.
    Rtc(ComponentKind),
    /// InventGUI.
    Gui,
}

impl Peer {
    /// The name the diagram shows (`MotorControl`, `InventGUI`).
    pub fn name(self) -> &'static str {
        match self {
            Self::Rtc(kind) => kind.name(),
            Self::Gui => "InventGUI",
        }
    }
}

/// A connection's id: `DriveControl.TargetVelocity->MotorControl.TargetVelocity`.
pub fn connection_id(from: (Peer, &str), to: (Peer, &str)) -> String {
    format!("{}.{}->{}.{}", from.0.name(), from.1, to.0.name(), to.1)
}

/// One data connection `OutPort → InPort`.
#[derive(Debug, Clone)]
pub struct DataLink {
    /// The out-port's owner and name.
    pub from: (Peer, &'static str),
    /// The in-port's owner and name.
    pub to: (Peer, &'static str),
    /// The IDL type it carries.
    pub idl: &'static str,
    /// Its handle: samples carried, cut or not.
    pub connector: Connector,
}

impl DataLink {
    /// Its id ([`connection_id`]).
    pub fn id(&self) -> String {
        connection_id(self.from, self.to)
    }

    /// Whether it may be cut: it joins two RT-components. The connections to InventGUI
    /// carry the facts the log and the mission are made of, and stay.
    pub fn cuttable(&self) -> bool {
        matches!((self.from.0, self.to.0), (Peer::Rtc(_), Peer::Rtc(_)))
    }
}

/// Every data connection, in the order the wiring made them.
#[derive(Debug, Clone, Default)]
pub struct Links(Vec<DataLink>);

impl Links {
    /// Takes over `other`'s counts and cuts, connection by connection (a copied wiring, made
    /// by the same connections in the same order).
    pub fn copy_state_from(&self, other: &Links) {
        for (mine, theirs) in self.0.iter().zip(&other.0) {
            debug_assert_eq!(mine.id(), theirs.id());
            mine.connector.copy_state_from(&theirs.connector);
        }
    }

    /// Connects `out` (of `from`) to `input` (of `to`) and records the connection.
    pub fn connect<T: Clone + Sample>(
        &mut self,
        from: Peer,
        out: &mut OutPort<T>,
        to: Peer,
        input: &InPort<T>,
    ) {
        let connector = out.connect(input);
        self.0.push(DataLink {
            from: (from, out.name()),
            to: (to, input.name()),
            idl: T::IDL,
            connector,
        });
    }

    /// Every connection.
    pub fn all(&self) -> &[DataLink] {
        &self.0
    }

    /// The connection `id`.
    pub fn find(&self, id: &str) -> Option<&DataLink> {
        self.0.iter().find(|l| l.id() == id)
    }
}

/// The last call made on a service port.
#[derive(Debug, Clone, PartialEq)]
pub struct Call {
    /// Simulated time \[ns\].
    pub time_ns: u64,
    /// `SetPDGain(5, 5, 2, 2)`.
    pub text: String,
}

/// A service port a component provides, who calls it, and the calls made on it.
#[derive(Debug, Clone, PartialEq)]
pub struct ServicePort {
    /// Whose port.
    pub owner: ComponentKind,
    /// The port's name (the seeds' where they name it: `InventGUIProv`, `MapBuilderProv`,
    /// `MapMaintenanceProv`, `GlobalPathProv`, `InventGUIProvPort`, `BumpProvPort`).
    pub name: &'static str,
    /// The interface (`LocalPath`, `Motor`, …).
    pub interface: &'static str,
    /// The operations the system calls on it.
    pub operations: &'static [&'static str],
    /// Who calls it, from which port.
    pub caller: (Peer, &'static str),
    /// Calls so far.
    pub calls: u64,
    /// The last call.
    pub last: Option<Call>,
}

type PortSpec = (
    ComponentKind,
    &'static str,
    &'static str,
    &'static [&'static str],
    (Peer, &'static str),
);

/// The service ports of the system (spec §0's service arrows): whom the wiring calls
/// between ticks, on whose behalf. Providers of the seeds: LocalPathPlanning's `LocalPath`
/// ports (000 §3.2.1) and MotorControl's `Motor` ports (002 §3.2); the other components'
/// ports are named the same way.
const SERVICE_PORTS: [PortSpec; 18] = {
    use ComponentKind::*;
    use Peer::{Gui, Rtc};
    const SET_MAP: (Peer, &str) = (Rtc(MapBuilder), "SetMap");
    const MAP_UPDATE: (Peer, &str) = (Rtc(MapMaintenance), "MapUpdate");
    [
        (
            MapBuilder,
            "InventGUIProv",
            "MapBuilder",
            &["LoadMap"],
            (Gui, "MapBuilder"),
        ),
        (
            MapMaintenance,
            "InventGUIProv",
            "MapMaintenance",
            &["MapUpdate"],
            (Gui, "MapMaintenance"),
        ),
        (
            MapMaintenance,
            "MapBuilderProv",
            "Map",
            &["SetMap"],
            SET_MAP,
        ),
        (
            PhysicsSim,
            "InventGUIProv",
            "Simulator",
            &["SetPose"],
            (Gui, "Simulator"),
        ),
        (PhysicsSim, "MapBuilderProv", "Map", &["SetMap"], SET_MAP),
        (
            PhysicsSim,
            "MapMaintenanceProv",
            "Map",
            &["MapUpdate"],
            MAP_UPDATE,
        ),
        (
            MotorControl,
            "InventGUIProvPort",
            "Motor",
            &["SetPDGain"],
            (Gui, "Motor"),
        ),
        (
            MotorControl,
            "BumpProvPort",
            "Motor",
            &["Stop"],
            (Rtc(PhysicsSim), "bump"),
        ),
        (
            Localization,
            "InventGUIProv",
            "Localization",
            &["SetStartPose"],
            (Gui, "Localization"),
        ),
        (
            GlobalPathPlanning,
            "InventGUIProv",
            "LocalPath",
            &["SetPosition", "Clear"],
            (Gui, "LocalPath"),
        ),
        (
            GlobalPathPlanning,
            "MapBuilderProv",
            "LocalPath",
            &["SetMap"],
            SET_MAP,
        ),
        (
            GlobalPathPlanning,
            "MapMaintenanceProv",
            "LocalPath",
            &["MapUpdate"],
            MAP_UPDATE,
        ),
        (
            LocalPathPlanning,
            "InventGUIProv",
            "LocalPath",
            &["SetPosition", "Clear", "SafeMode"],
            (Gui, "LocalPath"),
        ),
        (
            LocalPathPlanning,
            "MapBuilderProv",
            "LocalPath",
            &["SetMap"],
            SET_MAP,
        ),
        (
            LocalPathPlanning,
            "MapMaintenanceProv",
            "LocalPath",
            &["MapUpdate"],
            MAP_UPDATE,
        ),
        (
            LocalPathPlanning,
            "GlobalPathProv",
            "LocalPath",
            &["GlobalPathCourse"],
            (Rtc(GlobalPathPlanning), "GlobalPathCourse"),
        ),
        (DriveControl, "MapBuilderProv", "Map", &["SetMap"], SET_MAP),
        (
            DriveControl,
            "MapMaintenanceProv",
            "Map",
            &["MapUpdate"],
            MAP_UPDATE,
        ),
    ]
};

/// Every service port, with the calls made on it.
#[derive(Debug, Clone, PartialEq)]
pub struct Services(Vec<ServicePort>);

impl Default for Services {
    fn default() -> Self {
        Self(
            SERVICE_PORTS
                .iter()
                .map(
                    |&(owner, name, interface, operations, caller)| ServicePort {
                        owner,
                        name,
                        interface,
                        operations,
                        caller,
                        calls: 0,
                        last: None,
                    },
                )
                .collect(),
        )
    }
}

impl Services {
    /// Records a call on `owner`'s port `port` at `time_ns`. A port not in the table is not
    /// recorded (returns false; the description's test catches it).
    pub fn called(
        &mut self,
        owner: ComponentKind,
        port: &str,
        time_ns: u64,
        text: impl Into<String>,
    ) -> bool {
        match self
            .0
            .iter_mut()
            .find(|p| p.owner == owner && p.name == port)
        {
            Some(p) => {
                p.calls += 1;
                p.last = Some(Call {
                    time_ns,
                    text: text.into(),
                });
                true
            }
            None => false,
        }
    }

    /// Every service port.
    pub fn all(&self) -> &[ServicePort] {
        &self.0
    }
}

/// A service call the wiring makes (spec §0's service arrows), to record on the ports it
/// reaches with the words the System view shows.
#[derive(Debug, Clone, Copy)]
pub(super) enum ServiceCall {
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
    pub(super) fn record_call(&mut self, call: ServiceCall) {
        use ComponentKind as K;
        const GUI: &str = "InventGUIProv";
        let pose = |p: Pose| format!("{}, {}, {}", short(p.x), short(p.y), short(p.theta));
        match call {
            ServiceCall::SetMap(w, h, grid) => {
                let text = format!("SetMap({w}×{h} cells, GridSize {} m)", number(grid));
                for kind in MAP_HOLDERS {
                    self.called(kind, "MapBuilderProv", text.clone());
                }
            }
            ServiceCall::MapUpdate(cells) => {
                for kind in &MAP_HOLDERS[1..] {
                    self.called(
                        *kind,
                        "MapMaintenanceProv",
                        format!("MapUpdate({cells} cells)"),
                    );
                }
            }
            ServiceCall::EditMap(cells) => {
                self.called(K::MapMaintenance, GUI, format!("MapUpdate({cells} cells)"));
            }
            ServiceCall::LoadMap(w, h) => {
                self.called(K::MapBuilder, GUI, format!("LoadMap({w}×{h} cells)"))
            }
            ServiceCall::GlobalPathCourse(n) => {
                let text = format!("GlobalPathCourse({n} cells)");
                self.called(K::LocalPathPlanning, "GlobalPathProv", text);
            }
            ServiceCall::SetPosition(start, goal, dir, place) => {
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
            ServiceCall::Clear => {
                self.called(K::LocalPathPlanning, GUI, "Clear()");
                self.called(K::GlobalPathPlanning, GUI, "Clear()");
            }
            ServiceCall::SafeMode => self.called(K::LocalPathPlanning, GUI, "SafeMode()"),
            ServiceCall::SetPdGain(g) => {
                let text = format!(
                    "SetPDGain({}, {}, {}, {})",
                    short(g[0]),
                    short(g[1]),
                    short(g[2]),
                    short(g[3])
                );
                self.called(K::MotorControl, "InventGUIProvPort", text);
            }
            ServiceCall::Stop => self.called(K::MotorControl, "BumpProvPort", "Stop()"),
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

/// Making the connections: when the wiring is made, in a copy, and when a component is put
/// in another's place. Every connection is made by port name ([`Component::in_port`],
/// [`Component::out_port_mut`]), so whatever stands in a place is connected the same way.
impl Wiring {
    /// Connects the data ports of spec §0 and the system's bridges (`crate::system`'s
    /// tables): when the wiring is made, and in an unconnected copy ([`Wiring::try_clone`]).
    /// Fails, naming the port, if a component lacks one the table names.
    pub(super) fn connect(&mut self) -> crate::Result<()> {
        self.connect_handing_over(None)
    }

    /// [`Wiring::connect`]; the in-ports of `fresh` (a component just put in its place) are
    /// handed each connected out-port's newest sample, as the component it replaced had
    /// received it (the planners do not send a path again for a new DriveControl).
    fn connect_handing_over(&mut self, fresh: Option<ComponentKind>) -> crate::Result<()> {
        use crate::components::SetMapMessage;
        use crate::interfaces::{ControlPoints, GlobalPathCourse, GridPath, PlanningFailure};
        use crate::map::MapUpdate;
        use crate::motion::BumpReport;
        use crate::rtc::{TimedDouble, TimedDoubleSeq, TimedPosition, TimedVelocity};
        use ComponentKind as K;
        let mut links = Links::default();
        macro_rules! link {
            ($from:ident . $out:literal => system . $rx:ident : $t:ty) => {{
                let port = self.rx.$rx.share();
                let out = self.out_port::<$t>(K::$from, $out)?;
                links.connect(Peer::Rtc(K::$from), out, Peer::Gui, &port);
            }};
            ($from:ident . $out:literal => $to:ident . $inp:literal : $t:ty) => {{
                let port = self.in_port::<$t>(K::$to, $inp)?;
                let out = self.out_port::<$t>(K::$from, $out)?;
                if fresh == Some(K::$to)
                    && let Some(last) = out.last()
                {
                    port.put(last.clone());
                }
                links.connect(Peer::Rtc(K::$from), out, Peer::Rtc(K::$to), &port);
            }};
        }
        // Data ports (spec §0), each connection recorded for the system's description.
        link!(PhysicsSim."angle" => MotorControl."InCurrentWheelAngle": TimedDoubleSeq);
        link!(PhysicsSim."position" => MotorControl."InSimulatedPosition": TimedDoubleSeq);
        link!(MotorControl."Torque" => PhysicsSim."torque": TimedDoubleSeq);
        link!(MotorControl."OutCurrentWheelAngle" => Localization."InCurrentWheelAngle": TimedDoubleSeq);
        link!(MotorControl."OutSimulatedPositionToLocalization" => Localization."InSimulatedPosition": TimedDoubleSeq);
        link!(Localization."OutCurrentPosition" => LocalPathPlanning."InCurrentPosition": TimedPosition);
        link!(Localization."OutCurrentPosition" => DriveControl."InCurrentPosition": TimedPosition);
        link!(Localization."OutCurrentPosition" => GlobalPathPlanning."InCurrentPosition": TimedPosition);
        link!(DriveControl."TargetVelocity" => MotorControl."TargetVelocity": TimedVelocity);
        link!(DriveControl."OutDeviating" => LocalPathPlanning."InDeviating": TimedDouble);
        link!(LocalPathPlanning."DriveCons" => DriveControl."InControlPoints": ControlPoints);
        // The system's ends: facts for InventGUI.
        link!(GlobalPathPlanning."PlanningFailure" => system.global_failure: PlanningFailure);
        link!(LocalPathPlanning."InventGUICons" => system.local_path: GridPath);
        link!(LocalPathPlanning."InventGUIConsFailure" => system.local_failure: PlanningFailure);
        link!(PhysicsSim."bump" => system.bump: BumpReport);
        link!(DriveControl."SafetyStop" => system.safety_stop: TimedDouble);
        // ... and service calls (`Services`), not data connections of the diagram.
        let port = self.rx.set_map.share();
        self.out_port::<SetMapMessage>(K::MapBuilder, "SetMap")?
            .connect(&port);
        let port = self.rx.map_update.share();
        self.out_port::<MapUpdate>(K::MapMaintenance, "MapUpdate")?
            .connect(&port);
        let port = self.rx.global_path.share();
        self.out_port::<GlobalPathCourse>(K::GlobalPathPlanning, "GlobalPathCourse")?
            .connect(&port);
        self.links = links;
        Ok(())
    }

    /// Connects everything again after `fresh` was put in another's place: every out-port's
    /// connections dropped, then made afresh, each keeping its count and cut; `fresh`'s
    /// in-ports get the newest samples the replaced component had been sent.
    pub(super) fn reconnect(&mut self, fresh: ComponentKind) -> crate::Result<()> {
        for kind in ComponentKind::ALL {
            if let Ok(c) = self.ec.component_dyn_mut(kind.index()) {
                c.disconnect_ports();
            }
        }
        let old = core::mem::take(&mut self.links);
        self.connect_handing_over(Some(fresh))?;
        self.links.copy_state_from(&old);
        Ok(())
    }

    /// In-port `name` of the component in `kind`'s place, shared (to connect to it).
    fn in_port<T: Clone + Sample + 'static>(
        &self,
        kind: ComponentKind,
        name: &'static str,
    ) -> crate::Result<InPort<T>> {
        self.ec
            .component_dyn(kind.index())?
            .in_port(name)
            .and_then(|p| p.downcast_ref::<InPort<T>>())
            .map(InPort::share)
            .ok_or_else(|| missing::<T>(kind, "in", name))
    }

    /// Out-port `name` of the component in `kind`'s place.
    fn out_port<T: Clone + Sample + 'static>(
        &mut self,
        kind: ComponentKind,
        name: &'static str,
    ) -> crate::Result<&mut OutPort<T>> {
        self.ec
            .component_dyn_mut(kind.index())?
            .out_port_mut(name)
            .and_then(|p| p.downcast_mut::<OutPort<T>>())
            .ok_or_else(|| missing::<T>(kind, "out", name))
    }
}

fn missing<T: Sample>(
    kind: ComponentKind,
    direction: &'static str,
    port: &'static str,
) -> crate::Error {
    SystemError::PortMissing {
        component: kind.instance_name().to_owned(),
        direction,
        port,
        idl: T::IDL,
    }
    .into()
}

impl Wiring {
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
        copy.connect().ok()?;
        copy.links.copy_state_from(&self.links);
        Some(copy)
    }
}
