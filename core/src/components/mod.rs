//! The RT-components, one per file, named as in the seeds (spec §0).

/// The parts of [`Component`](crate::rtc::Component) every component here writes the same
/// way, inside its `impl Component for …`: `boxed_clone` (a clone: every component is
/// `Clone`) and `instance_name` (the field `name:` names); with `config:`, also
/// `configuration` and `configuration_ref` (that field, the component's `Configuration`).
///
/// ```text
/// impl Component for DriveControl {
///     component_basics!(name: name, config: config);
///     fn ports(&self) -> Vec<PortView> { … }
/// }
/// ```
macro_rules! component_basics {
    (name: $name:ident) => {
        fn boxed_clone(&self) -> Option<Box<dyn $crate::rtc::Component>> {
            Some(Box::new(self.clone()))
        }

        fn instance_name(&self) -> &str {
            &self.$name
        }
    };
    (name: $name:ident, config: $config:ident) => {
        component_basics!(name: $name);

        fn configuration(&mut self) -> Option<&mut dyn $crate::rtc::ConfigAccess> {
            Some(&mut self.$config)
        }

        fn configuration_ref(&self) -> Option<&dyn $crate::rtc::ConfigAccess> {
            Some(&self.$config)
        }
    };
}

/// A component's data ports, in and out, each a field of the component: writes
/// [`Component::ports`](crate::rtc::Component::ports) (the ins, then the outs, in the order
/// given) and the lookups by port name the connections are made with
/// ([`Component::in_port`](crate::rtc::Component::in_port),
/// [`Component::out_port_mut`](crate::rtc::Component::out_port_mut)), and
/// [`Component::disconnect_ports`](crate::rtc::Component::disconnect_ports).
///
/// ```text
/// component_ports!(in: [in_control_points, in_current_position],
///                  out: [target_velocity, out_deviating, safety_stop]);
/// ```
macro_rules! component_ports {
    (in: [$($i:ident),* $(,)?], out: [$($o:ident),* $(,)?]) => {
        fn ports(&self) -> Vec<$crate::rtc::PortView> {
            vec![$(self.$i.view(),)* $(self.$o.view(),)*]
        }

        fn in_port(&self, name: &str) -> Option<&dyn core::any::Any> {
            $(if self.$i.name() == name {
                return Some(&self.$i);
            })*
            let _ = name;
            None
        }

        fn out_port_mut(&mut self, name: &str) -> Option<&mut dyn core::any::Any> {
            $(if self.$o.name() == name {
                return Some(&mut self.$o);
            })*
            let _ = name;
            None
        }

        fn disconnect_ports(&mut self) {
            $(self.$o.disconnect_all();)*
        }
    };
}

mod drive_control;
mod localization;
mod motor_control;
mod physics_sim;

pub use drive_control::{DriveControl, DriveControlParams, DriveStatus};
pub use localization::{Localization, LocalizationMode, LocalizationParams};
pub use motor_control::{
    GainWarning, INPUT_TIMEOUT_NS, MotorControl, MotorControlParams, MotorGeometry, MotorStatus,
    default_geometry,
};
pub use physics_sim::{PhysicsSim, PhysicsSimParams};

pub mod local_path_planning;
pub use local_path_planning::{
    FIELD_CELLS_PER_EXECUTION, LocalPathFlags, LocalPathPlanning, LocalPathPlanningParams, RETRY_NS,
};

mod global_path_planning;
pub use global_path_planning::{GlobalPathPlanning, GlobalPathPlanningParams, PlanReason};

mod map_builder;
mod map_maintenance;
mod samples;
#[cfg(not(feature = "script"))]
mod script_absent;
#[cfg(feature = "script")]
mod script_component;
mod script_place;

#[cfg(not(feature = "script"))]
pub use script_absent::ScriptComponent;
#[cfg(feature = "script")]
pub use script_component::ScriptComponent;
pub use script_place::ScriptPlace;

pub use map_builder::{MapBuilder, SetMapMessage};
pub use map_maintenance::MapMaintenance;
