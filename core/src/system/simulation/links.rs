//! The wiring's record of its connections (spec §0): every data connection as it is made
//! ([`Links::connect`]), with its [`Connector`], and every service port with the calls made
//! on it ([`Services`]). The system's description ([`SystemGraph`](crate::system::SystemGraph)) is
//! read from here, so what it shows is what the wiring connected and called.

use serde::Serialize;

use crate::rtc::{Connector, InPort, OutPort, Sample};
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
