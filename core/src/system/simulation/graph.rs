//! [`SystemGraph`]: the system's own description of itself — its components, their data
//! and service ports, and the connections between them — read from the wiring as it was
//! connected and as it runs (RT System Editor's picture of a system). The page
//! lays its System view out from it, `rtnav system --dot|--json` prints it.
//!
//! Nothing here is drawn by hand: the data ports are what each component lists
//! ([`Component::ports`](crate::rtc::Component::ports)), the data connections what the
//! wiring connected (`wiring/connections.rs`), the service ports and connections the wiring's table of
//! whom it calls, with the calls it made.

use serde::Serialize;

use super::wiring::Wiring;
use super::wiring::connections::{Peer, connection_id};
use crate::rtc::{PortDirection, PortView, SampleView};
use crate::system::vocabulary::kind::ComponentKind;

/// The whole system as RT System Editor would show it, at one moment.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct SystemGraph {
    /// Simulated time \[s\].
    pub time: f64,
    /// InventGUI first, then the eight RT-components in data-flow order.
    pub components: Vec<GraphComponent>,
    /// Data connections as the wiring made them, then service connections.
    pub connections: Vec<GraphConnection>,
}

/// One box of the picture.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct GraphComponent {
    /// `MotorControl`, or `InventGUI`.
    pub name: &'static str,
    /// `MotorControl0` (InventGUI: `InventGUI`).
    pub instance_name: &'static str,
    /// Whether it is an RT-component (InventGUI is the person's side: the page, the
    /// command line, a scenario's timeline).
    pub rtc: bool,
    /// Its lifecycle state (`Inactive`, `Active`, `Error`); none for InventGUI.
    pub state: Option<String>,
    /// Its execution rate \[Hz\]; none for InventGUI.
    pub rate_hz: Option<f64>,
    /// Its ports: data in, data out, services provided, services required.
    pub ports: Vec<GraphPort>,
    /// The student's script it runs (its name), if one stands in its place (spec §8).
    pub script: Option<String>,
}

/// What a port is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
#[serde(rename_all = "snake_case")]
pub enum PortKind {
    /// A data in-port.
    In,
    /// A data out-port.
    Out,
    /// A service port it provides.
    Provided,
    /// A service port it calls through.
    Required,
}

/// One port marker on a box.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct GraphPort {
    /// Its name (the seeds' where they name it).
    pub name: &'static str,
    /// In, out, provided or required.
    pub kind: PortKind,
    /// The IDL type (data) or the interface (service).
    pub interface: &'static str,
    /// The operations called on a provided port.
    pub operations: &'static [&'static str],
    /// Samples through a data port; calls on a provided port.
    pub count: u64,
    /// The newest sample, or the last call (`SetPDGain(5, 5, 2, 2)`) with its time.
    pub last: Option<SampleView>,
}

/// Data or service.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
#[serde(rename_all = "snake_case")]
pub enum ConnectionKind {
    /// `OutPort → InPort`.
    Data,
    /// A caller's port → a provided service port (the wiring makes the call).
    Service,
}

/// One end of a connection.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct Endpoint {
    /// The component's name.
    pub component: &'static str,
    /// The port's name.
    pub port: &'static str,
}

impl Endpoint {
    fn of((peer, port): (Peer, &'static str)) -> Self {
        Self {
            component: peer.name(),
            port,
        }
    }
}

/// One line of the picture.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct GraphConnection {
    /// `DriveControl.TargetVelocity->MotorControl.TargetVelocity`: what
    /// `Input::CutConnection` names.
    pub id: String,
    /// Data or service.
    pub kind: ConnectionKind,
    /// The out-port or the caller's port.
    pub from: Endpoint,
    /// The in-port or the provided port.
    pub to: Endpoint,
    /// The IDL type or the interface.
    pub interface: &'static str,
    /// Samples it carried, or calls made through it.
    pub carried: u64,
    /// Whether it is cut now.
    pub cut: bool,
    /// Whether it may be cut (a data connection between two components).
    pub cuttable: bool,
}

fn data_port(p: PortView) -> GraphPort {
    GraphPort {
        name: p.name,
        kind: match p.direction {
            PortDirection::In => PortKind::In,
            PortDirection::Out => PortKind::Out,
        },
        interface: p.idl,
        operations: &[],
        count: p.count,
        last: p.last,
    }
}

impl SystemGraph {
    /// The description of `wiring` now.
    pub fn of(wiring: &Wiring) -> Self {
        let ec = wiring.execution_context();
        let services = wiring.services().all();
        let links = wiring.links().all();

        let mut connections: Vec<GraphConnection> = links
            .iter()
            .map(|l| GraphConnection {
                id: l.id(),
                kind: ConnectionKind::Data,
                from: Endpoint::of(l.from),
                to: Endpoint::of(l.to),
                interface: l.idl,
                carried: l.connector.carried(),
                cut: l.connector.is_cut(),
                cuttable: l.cuttable(),
            })
            .collect();
        connections.extend(services.iter().map(|s| {
            let to = (Peer::Rtc(s.owner), s.name);
            GraphConnection {
                id: connection_id(s.caller, to),
                kind: ConnectionKind::Service,
                from: Endpoint::of(s.caller),
                to: Endpoint::of(to),
                interface: s.interface,
                carried: s.calls,
                cut: false,
                cuttable: false,
            }
        }));

        // InventGUI: the facts it is told, and the services it calls (one port per
        // interface).
        let mut gui_ports: Vec<GraphPort> = wiring.gui_ports().into_iter().map(data_port).collect();
        for s in services.iter().filter(|s| s.caller.0 == Peer::Gui) {
            let port = gui_ports
                .iter()
                .position(|p| p.kind == PortKind::Required && p.name == s.caller.1);
            let port = match port {
                Some(i) => &mut gui_ports[i],
                None => {
                    gui_ports.push(GraphPort {
                        name: s.caller.1,
                        kind: PortKind::Required,
                        interface: s.interface,
                        operations: &[],
                        count: 0,
                        last: None,
                    });
                    let last = gui_ports.len() - 1;
                    &mut gui_ports[last]
                }
            };
            port.count += s.calls;
            if let Some(call) = &s.last
                && port
                    .last
                    .as_ref()
                    .is_none_or(|l| l.tm.unwrap_or(0.0) <= call.time_ns as f64 * 1e-9)
            {
                port.last = Some(SampleView {
                    tm: Some(call.time_ns as f64 * 1e-9),
                    text: call.text.clone(),
                });
            }
        }
        let mut components = vec![GraphComponent {
            name: Peer::Gui.name(),
            instance_name: Peer::Gui.name(),
            rtc: false,
            state: None,
            rate_hz: None,
            ports: gui_ports,
            script: None,
        }];

        for kind in ComponentKind::ALL {
            let id = kind.index();
            let mut ports: Vec<GraphPort> = ec
                .component_dyn(id)
                .map(|c| c.ports())
                .unwrap_or_default()
                .into_iter()
                .map(data_port)
                .collect();
            ports.extend(
                services
                    .iter()
                    .filter(|s| s.owner == kind)
                    .map(|s| GraphPort {
                        name: s.name,
                        kind: PortKind::Provided,
                        interface: s.interface,
                        operations: s.operations,
                        count: s.calls,
                        last: s.last.as_ref().map(|c| SampleView {
                            tm: Some(c.time_ns as f64 * 1e-9),
                            text: c.text.clone(),
                        }),
                    }),
            );
            components.push(GraphComponent {
                name: kind.name(),
                instance_name: kind.instance_name(),
                rtc: true,
                state: ec.state(id).ok().map(|s| s.to_string()),
                rate_hz: ec.rate(id).ok(),
                ports,
                script: ec
                    .component_dyn(id)
                    .ok()
                    .and_then(|c| c.script_name())
                    .map(str::to_owned),
            });
        }
        Self {
            time: ec.time_ns() as f64 * 1e-9,
            components,
            connections,
        }
    }

    /// The connection `id`.
    pub fn connection(&self, id: &str) -> Option<&GraphConnection> {
        self.connections.iter().find(|c| c.id == id)
    }

    /// The component `name`.
    pub fn component(&self, name: &str) -> Option<&GraphComponent> {
        self.components.iter().find(|c| c.name == name)
    }

    /// The description as Graphviz `dot`: one record per component (in-ports and provided
    /// services on the left, out-ports and required services on the right), data
    /// connections solid, service connections dashed, cut ones red and dotted.
    pub fn to_dot(&self) -> String {
        let mut s = String::from(
            "digraph rtnav {\n  rankdir=LR;\n  node [shape=record, fontname=\"Helvetica\", fontsize=10];\n  edge [fontname=\"Helvetica\", fontsize=8];\n",
        );
        for c in &self.components {
            let side = |kinds: &[PortKind]| {
                c.ports
                    .iter()
                    .filter(|p| kinds.contains(&p.kind))
                    .map(|p| format!("<{0}> {0}", p.name))
                    .collect::<Vec<_>>()
                    .join("|")
            };
            let left = side(&[PortKind::In, PortKind::Provided]);
            let right = side(&[PortKind::Out, PortKind::Required]);
            let title = match &c.state {
                Some(state) => match &c.script {
                    Some(script) => format!("{}\\n{state}\\nscript {script}", c.instance_name),
                    None => format!("{}\\n{state}", c.instance_name),
                },
                None => c.instance_name.to_owned(),
            };
            let colour = match c.state.as_deref() {
                Some("Active") => "#8fe88f",
                Some("Error") => "#ff9c9c",
                Some("Inactive") => "#9cb8ff",
                _ => "#dddddd",
            };
            s.push_str(&format!(
                "  \"{}\" [label=\"{{{{{left}}}|{title}|{{{right}}}}}\", style=filled, fillcolor=\"{colour}\"];\n",
                c.name
            ));
        }
        for e in &self.connections {
            let mut attrs = vec![format!("label=\"{}\"", e.interface)];
            if e.kind == ConnectionKind::Service {
                attrs.push("style=dashed".to_owned());
            }
            if e.cut {
                attrs.push("style=dotted, color=red".to_owned());
            }
            s.push_str(&format!(
                "  \"{}\":\"{}\":e -> \"{}\":\"{}\":w [{}];\n",
                e.from.component,
                e.from.port,
                e.to.component,
                e.to.port,
                attrs.join(", ")
            ));
        }
        s.push_str("}\n");
        s
    }
}

impl Wiring {
    /// The system's description now ([`SystemGraph`]).
    pub fn graph(&self) -> SystemGraph {
        SystemGraph::of(self)
    }
}
