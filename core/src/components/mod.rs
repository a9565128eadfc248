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

mod drive_control;
mod localization;
mod motor_control;
mod physics_sim;

pub use drive_control::{DriveControl, DriveControlParams, DriveStatus};
pub use localization::{Localization, LocalizationMode, LocalizationParams};
pub use motor_control::{
    GainWarning, INPUT_TIMEOUT_NS, MotorControl, MotorControlParams, MotorGeometry, MotorStatus,
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

pub use map_builder::{MapBuilder, SetMapMessage};
pub use map_maintenance::MapMaintenance;
