//! [`System`]: the eight components in one execution context, their data ports connected,
//! the service calls made between ticks, and the GUI-facing API (what InventGUI did).

use std::collections::VecDeque;

use core::fmt;

use serde::Serialize;

use super::clearance::{ClearanceTracker, could_be_below};
use super::events::{EventKind, SystemEvent};
use super::kind::ComponentKind;
use super::rates::Rates;
use super::script::DriveScript;
use super::telemetry::{Telemetry, TelemetrySample};
use crate::components::{
    DriveControl, GlobalPathPlanning, LocalPathPlanning, Localization, MapBuilder, MapMaintenance,
    MapUpdate, MotorControl, PhysicsSim, SetMapMessage,
};
use crate::errors::{LifecycleError, SystemError};
use crate::interfaces::{Direction, GlobalPathCourse, GridPath, PlanningFailure, Pose};
use crate::local::FieldExtent;
use crate::map::{Cell, GridMap};
use crate::motion::{BumpReport, ModelFrame, PhysicsParams, angle_diff};
use crate::rtc::{
    Component, ComponentId, ConfigAccess, ExecutionContext, InPort, LifecycleEvent, LifecycleState,
    Time, TimedDoubleSeq,
};

/// How many events are kept (the oldest are dropped beyond this).
pub const EVENT_CAPACITY: usize = 4096;
/// How many plan times are kept (for the plots' replan marks).
pub const PLAN_TIMES_CAPACITY: usize = 1024;
/// How many trail points are kept.
pub const TRAIL_CAPACITY: usize = 20_000;
/// Trail points are at least this far apart \[m\].
const TRAIL_SPACING: f64 = 0.02;

/// The whole system's state, from its components' states.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub enum SystemState {
    /// Every component Inactive.
    Inactive,
    /// Every component Active.
    Active,
    /// Some Active, some Inactive, none in Error (e.g. the planning-only preview).
    Partial,
    /// At least one component in Error (e.g. after a bump): Reset recovers.
    Error,
}

impl fmt::Display for SystemState {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Inactive => "Inactive",
            Self::Active => "Active",
            Self::Partial => "Partial",
            Self::Error => "Error",
        })
    }
}

/// One component as the GUI's RTC panel shows it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ComponentInfo {
    /// Which component.
    pub kind: ComponentKind,
    /// Its instance name.
    pub instance_name: String,
    /// Its lifecycle state.
    pub state: LifecycleState,
    /// Its rate \[Hz\].
    pub rate: f64,
    /// The reason of its last callback failure (kept until a reset succeeds).
    pub last_error: Option<String>,
    /// What it is doing, in a few words.
    pub status: String,
}

/// Running totals of a drive, for the summary and the scenario checks.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RunStats {
    /// Distance driven by the robot's centre \[m\].
    pub path_length: f64,
    /// Smallest clearance seen while the physics ran \[m\] (infinite before it ran).
    pub min_clearance: f64,
    /// Global plans sent.
    pub global_plans: u64,
    /// Local plans (potential fields) LocalPathPlanning attempted.
    pub local_plans: u64,
    /// Paths LocalPathPlanning sent.
    pub local_paths_sent: u64,
    /// Planning-failure notices.
    pub planning_failures: u64,
    /// Bumps.
    pub bumps: u64,
}

impl Default for RunStats {
    fn default() -> Self {
        Self {
            path_length: 0.0,
            min_clearance: f64::INFINITY,
            global_plans: 0,
            local_plans: 0,
            local_paths_sent: 0,
            planning_failures: 0,
            bumps: 0,
        }
    }
}

/// The system's end of the ports whose data becomes a service call or an event (SPEC §0's
/// service arrows): read after every tick and after every GUI request.
#[derive(Debug)]
struct Bridges {
    set_map: InPort<SetMapMessage>,
    map_update: InPort<MapUpdate>,
    global_path: InPort<GlobalPathCourse>,
    global_failure: InPort<PlanningFailure>,
    local_path: InPort<GridPath>,
    local_failure: InPort<PlanningFailure>,
    bump: InPort<BumpReport>,
}

/// The whole robot: MapBuilder, MapMaintenance, the physics, MotorControl, Localization,
/// GlobalPathPlanning, LocalPathPlanning and DriveControl in one [`ExecutionContext`]
/// (see the module documentation of `crate::system` for the wiring and the order).
pub struct System {
    ec: ExecutionContext,
    rates: Rates,
    telemetry_period_ticks: u64,
    drive_period_ticks: u64,
    rx: Bridges,
    events: VecDeque<SystemEvent>,
    event_total: u64,
    telemetry: Telemetry,
    trail: Vec<(f64, f64)>,
    start: Option<Pose>,
    goal: Option<Pose>,
    direction: Direction,
    global_path: Vec<Cell>,
    stats: RunStats,
    last_pose: Option<Pose>,
    arrived: bool,
    map_loads: u64,
    map_updates: u64,
    goal_epoch: u64,
    local_sent_epoch: u64,
    failed_epoch: u64,
    halted: bool,
    /// While the system works after a tick: that tick's time (events are stamped with it).
    tick_time_ns: Option<u64>,
    clearance: ClearanceTracker,
    /// A scenario's timed events counted from the start of the drive (the page's).
    pub(super) script: DriveScript,
    /// When global and local plans were made (the newest [`PLAN_TIMES_CAPACITY`]) \[ns\].
    plan_times: VecDeque<u64>,
    #[cfg(feature = "render")]
    pub(super) scene_buffers: super::scene::SceneBuffers,
}

impl fmt::Debug for System {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("System")
            .field("time_ns", &self.ec.time_ns())
            .field("state", &self.state())
            .field("start", &self.start)
            .field("goal", &self.goal)
            .field("stats", &self.stats)
            .finish()
    }
}

fn period_ticks(base: u64, hz: f64, what: &str) -> Result<u64, LifecycleError> {
    let bad = |reason: String| LifecycleError::InvalidRate { rate: hz, reason };
    if !(hz.is_finite() && hz > 0.0) {
        return Err(bad(format!("{what}: it must be positive and finite")));
    }
    let p = 1e9 / hz;
    if p.fract() != 0.0 || p < 1.0 || !(p as u64).is_multiple_of(base) {
        return Err(bad(format!(
            "{what}: its period is not a whole number of base ticks ({base} ns)"
        )));
    }
    Ok(p as u64 / base)
}

impl System {
    /// Builds the system with `rates`: every component created (Inactive), ports connected,
    /// the execution context Running. No map is loaded.
    ///
    /// The robot model is the physics' default (SPEC §5) reporting its pose in the RH0 model
    /// frame (002 §4.2: `SimulatedOffsetY` 0.045795 m, `SimulatedOffsetAngle` 1.5708 rad),
    /// with MotorControl configured to match, so the §4 conversion is exercised. A bump fails
    /// the physics' `on_execute`, which puts it (and the system) in Error.
    pub fn new(rates: Rates) -> crate::Result<Self> {
        let frame = ModelFrame::RH0;
        let mut map_builder = MapBuilder::new(ComponentKind::MapBuilder.instance_name());
        let mut map_maintenance =
            MapMaintenance::new(ComponentKind::MapMaintenance.instance_name());
        let mut physics = PhysicsSim::new(
            ComponentKind::PhysicsSim.instance_name(),
            PhysicsParams::default().with_model_frame(frame),
        )?;
        physics.set_fail_on_bump(true);
        let mut motor = MotorControl::new(ComponentKind::MotorControl.instance_name());
        motor.config_mut().set("SimulatedOffsetX", frame.offset_x)?;
        motor.config_mut().set("SimulatedOffsetY", frame.offset_y)?;
        motor
            .config_mut()
            .set("SimulatedOffsetAngle", frame.offset_angle)?;
        // The robot model's own values, not a change waiting for an activation.
        motor.config_mut().apply_on_activation();
        let mut localization = Localization::new(ComponentKind::Localization.instance_name());
        let mut global = GlobalPathPlanning::new(ComponentKind::GlobalPathPlanning.instance_name());
        let mut local = LocalPathPlanning::new(ComponentKind::LocalPathPlanning.instance_name());
        let mut drive = DriveControl::new(ComponentKind::DriveControl.instance_name());

        // Data ports (SPEC §0).
        physics.angle.connect(&motor.in_current_wheel_angle);
        physics.position.connect(&motor.in_simulated_position);
        motor.torque.connect(&physics.torque);
        motor
            .out_current_wheel_angle
            .connect(&localization.in_current_wheel_angle);
        motor
            .out_simulated_position_to_localization
            .connect(&localization.in_simulated_position);
        localization
            .out_current_position
            .connect(&local.in_current_position);
        localization
            .out_current_position
            .connect(&drive.in_current_position);
        drive.target_velocity.connect(&motor.target_velocity);
        drive.out_deviating.connect(&local.in_deviating);
        local.drive_cons.connect(&drive.in_control_points);

        // The system's ends: service calls and events.
        let rx = Bridges {
            set_map: InPort::new("SetMap"),
            map_update: InPort::new("MapUpdate"),
            global_path: InPort::new("GlobalPathCourse"),
            global_failure: InPort::new("PlanningFailure"),
            local_path: InPort::new("InventGUICons"),
            local_failure: InPort::new("InventGUIConsFailure"),
            bump: InPort::new("BumpDetection"),
        };
        map_builder.set_map.connect(&rx.set_map);
        map_maintenance.map_update_out.connect(&rx.map_update);
        global.global_path_course.connect(&rx.global_path);
        global.planning_failure.connect(&rx.global_failure);
        local.invent_gui_cons.connect(&rx.local_path);
        local.invent_gui_failure.connect(&rx.local_failure);
        physics.bump.connect(&rx.bump);

        let mut ec = ExecutionContext::new(rates.base())?;
        let base = ec.base_period_ns();
        let boxes: [Box<dyn Component>; 8] = [
            Box::new(map_builder),
            Box::new(map_maintenance),
            Box::new(physics),
            Box::new(motor),
            Box::new(localization),
            Box::new(global),
            Box::new(local),
            Box::new(drive),
        ];
        for (kind, component) in ComponentKind::ALL.into_iter().zip(boxes) {
            let id = ec.attach(component, rates.of(kind))?;
            debug_assert_eq!(id, kind.index());
        }
        ec.start()?;
        let telemetry_period_ticks = period_ticks(base, rates.telemetry, "telemetry")?;
        let drive_period_ticks = period_ticks(base, rates.drive_control, "DriveControl")?;
        let mut system = Self {
            ec,
            rates,
            telemetry_period_ticks,
            drive_period_ticks,
            rx,
            events: VecDeque::new(),
            event_total: 0,
            telemetry: Telemetry::new(),
            trail: Vec::new(),
            start: None,
            goal: None,
            direction: Direction::Forward,
            global_path: Vec::new(),
            stats: RunStats::default(),
            last_pose: None,
            arrived: false,
            map_loads: 0,
            map_updates: 0,
            goal_epoch: 0,
            local_sent_epoch: 0,
            failed_epoch: 0,
            halted: false,
            tick_time_ns: None,
            clearance: ClearanceTracker::new(),
            script: DriveScript::default(),
            plan_times: VecDeque::new(),
            #[cfg(feature = "render")]
            scene_buffers: Default::default(),
        };
        system.drain_lifecycle_events();
        Ok(system)
    }

    // ------------------------------------------------------------------ components

    fn id(kind: ComponentKind) -> ComponentId {
        kind.index()
    }

    fn get<T: Component>(&self, kind: ComponentKind) -> &T {
        match self.ec.component::<T>(Self::id(kind)) {
            Some(c) => c,
            None => unreachable!("System::new attaches {kind} at index {}", kind.index()),
        }
    }

    fn get_mut<T: Component>(&mut self, kind: ComponentKind) -> &mut T {
        match self.ec.component_mut::<T>(Self::id(kind)) {
            Some(c) => c,
            None => unreachable!("System::new attaches {kind} at index {}", kind.index()),
        }
    }

    /// MapBuilder.
    pub fn map_builder(&self) -> &MapBuilder {
        self.get(ComponentKind::MapBuilder)
    }
    /// MapMaintenance.
    pub fn map_maintenance(&self) -> &MapMaintenance {
        self.get(ComponentKind::MapMaintenance)
    }
    /// The physics component.
    pub fn physics(&self) -> &PhysicsSim {
        self.get(ComponentKind::PhysicsSim)
    }
    /// MotorControl.
    pub fn motor_control(&self) -> &MotorControl {
        self.get(ComponentKind::MotorControl)
    }
    /// Localization.
    pub fn localization(&self) -> &Localization {
        self.get(ComponentKind::Localization)
    }
    /// GlobalPathPlanning.
    pub fn global_path_planning(&self) -> &GlobalPathPlanning {
        self.get(ComponentKind::GlobalPathPlanning)
    }
    /// LocalPathPlanning.
    pub fn local_path_planning(&self) -> &LocalPathPlanning {
        self.get(ComponentKind::LocalPathPlanning)
    }
    /// DriveControl.
    pub fn drive_control(&self) -> &DriveControl {
        self.get(ComponentKind::DriveControl)
    }

    /// The execution context (read-only: states, rates, time).
    pub fn execution_context(&self) -> &ExecutionContext {
        &self.ec
    }

    // ------------------------------------------------------------------ time and state

    /// Simulated time \[ns\] (the time of the next tick).
    pub fn time_ns(&self) -> u64 {
        self.ec.time_ns()
    }

    /// Simulated time \[s\].
    pub fn time(&self) -> f64 {
        self.ec.time_ns() as f64 * 1e-9
    }

    /// The rates in use.
    pub fn rates(&self) -> Rates {
        self.rates
    }

    /// The whole system's state.
    pub fn state(&self) -> SystemState {
        let mut active = 0;
        let mut error = false;
        for kind in ComponentKind::ALL {
            match self.component_state(kind) {
                LifecycleState::Active => active += 1,
                LifecycleState::Error => error = true,
                _ => {}
            }
        }
        if error {
            SystemState::Error
        } else if active == ComponentKind::ALL.len() {
            SystemState::Active
        } else if active == 0 {
            SystemState::Inactive
        } else {
            SystemState::Partial
        }
    }

    /// A component's lifecycle state.
    pub fn component_state(&self, kind: ComponentKind) -> LifecycleState {
        self.ec
            .state(Self::id(kind))
            .unwrap_or(LifecycleState::Finalized)
    }

    /// Whether the robot moves: the physics is Active.
    pub fn is_driving(&self) -> bool {
        self.component_state(ComponentKind::PhysicsSim) == LifecycleState::Active
    }

    /// Whether DriveControl has reached the current goal (reset by a new goal).
    pub fn is_arrived(&self) -> bool {
        self.arrived
    }

    /// One component as the RTC panel shows it.
    pub fn component_info(&self, kind: ComponentKind) -> ComponentInfo {
        let id = Self::id(kind);
        let status = match kind {
            ComponentKind::MapBuilder => match self.map_builder().map() {
                Some(m) => format!("map {}×{} at {} m", m.width(), m.height(), m.grid_size()),
                None => "no map".to_owned(),
            },
            ComponentKind::MapMaintenance => format!(
                "{} updates sent, {} queued",
                self.map_maintenance().sent_count(),
                self.map_maintenance().pending()
            ),
            ComponentKind::PhysicsSim => {
                let p = self.physics().physics();
                format!(
                    "{} bumps{}",
                    p.bump_count(),
                    if p.state().in_contact {
                        ", touching an obstacle"
                    } else {
                        ""
                    }
                )
            }
            ComponentKind::MotorControl => self.motor_control().status().to_string(),
            ComponentKind::Localization => {
                format!("{:?}", self.localization().config().params().mode())
            }
            ComponentKind::GlobalPathPlanning => match self.global_path_planning().last_error() {
                Some(e) => format!("failed: {e}"),
                None => match self.global_path_planning().path_length() {
                    Some(l) => format!("route of {l:.2} m"),
                    None => "no route".to_owned(),
                },
            },
            ComponentKind::LocalPathPlanning => {
                // The held flags of 000 §5.2.4, the ones that are set, and the plans made.
                let f = self.local_path_planning().flags();
                let held: Vec<&str> = [
                    (f.map, "map"),
                    (f.position, "start and goal"),
                    (f.path, "path"),
                    (f.arrived, "arrived"),
                    (f.safe_mode, "SafeMode"),
                ]
                .into_iter()
                .filter_map(|(on, name)| on.then_some(name))
                .collect();
                let plans = self.local_path_planning().plan_count();
                format!(
                    "holds: {}; {plans} plan{}",
                    if held.is_empty() {
                        "nothing".to_owned()
                    } else {
                        held.join(", ")
                    },
                    if plans == 1 { "" } else { "s" }
                )
            }
            ComponentKind::DriveControl => self.drive_control().status().to_string(),
        };
        ComponentInfo {
            kind,
            instance_name: kind.instance_name().to_owned(),
            state: self.component_state(kind),
            rate: self.ec.rate(id).unwrap_or(f64::NAN),
            last_error: self.ec.last_error(id).ok().flatten().map(str::to_owned),
            status,
        }
    }

    /// Every component, in attachment order.
    pub fn components(&self) -> Vec<ComponentInfo> {
        ComponentKind::ALL
            .into_iter()
            .map(|k| self.component_info(k))
            .collect()
    }

    // ------------------------------------------------------------------ lifecycle

    /// Activates one component (Inactive → Active; a failing `on_activated` → Error).
    pub fn activate(&mut self, kind: ComponentKind) -> crate::Result<LifecycleState> {
        let drive_was_active = self.drive_control_active();
        let r = self.ec.activate(Self::id(kind));
        self.after_request();
        self.resume_after_activation(drive_was_active);
        Ok(r?)
    }

    /// Deactivates one component (Active → Inactive).
    pub fn deactivate(&mut self, kind: ComponentKind) -> crate::Result<LifecycleState> {
        let r = self.ec.deactivate(Self::id(kind));
        self.after_request();
        Ok(r?)
    }

    /// Resets one component (Error → Inactive if `on_reset` succeeds).
    pub fn reset(&mut self, kind: ComponentKind) -> crate::Result<LifecycleState> {
        let r = self.ec.reset(Self::id(kind));
        self.after_request();
        Ok(r?)
    }

    /// Activates every Inactive component, in attachment order (components in Error stay
    /// there: reset them first). Returns the system's state.
    pub fn activate_all(&mut self) -> SystemState {
        self.activate_set(&ComponentKind::ALL)
    }

    fn activate_set(&mut self, kinds: &[ComponentKind]) -> SystemState {
        let drive_was_active = self.drive_control_active();
        for &kind in kinds {
            if self.component_state(kind) == LifecycleState::Inactive {
                // Cannot fail: Inactive and the context is Running; a failing
                // `on_activated` is recorded as an event.
                let _ = self.ec.activate(Self::id(kind));
            }
        }
        self.after_request();
        self.resume_after_activation(drive_was_active);
        self.state()
    }

    fn drive_control_active(&self) -> bool {
        self.component_state(ComponentKind::DriveControl) == LifecycleState::Active
    }

    /// DriveControl starts without a path when it is activated (after a Reset or a
    /// Deactivate), and LocalPathPlanning sends a path only when it changes (000
    /// §5.2.4.13): the robot would stand before a goal the system still holds. **Decision**:
    /// when DriveControl has just been activated with no path waiting on its
    /// `InControlPoints`, while a goal is held, not reached, not halted, and
    /// LocalPathPlanning is Active and had sent its path, the system sends the held goal
    /// again from where the robot stands ([`System::set_goal`]), as InventGUI's operator
    /// would; [`EventKind::GoalResent`] says so. (At a headless run's start nothing has been
    /// sent yet, so this never fires there.)
    fn resume_after_activation(&mut self, drive_was_active: bool) {
        if drive_was_active || !self.drive_control_active() {
            return;
        }
        let Some(goal) = self.goal else {
            return;
        };
        let waiting = self
            .get::<DriveControl>(ComponentKind::DriveControl)
            .in_control_points
            .is_new();
        if waiting
            || self.arrived
            || self.halted
            || self.local_sent_epoch != self.goal_epoch
            || self.goal_epoch == 0
            || self.component_state(ComponentKind::LocalPathPlanning) != LifecycleState::Active
        {
            return;
        }
        let direction = self.direction;
        let reason = self.set_goal(goal, direction).err().map(|e| e.to_string());
        self.push_event(EventKind::GoalResent { refused: reason });
    }

    /// Writes one sample into a component's input port, as a connected output port would
    /// (OpenRTM rtshell's `rtinject`), just before the component's next execution
    /// ([`ExecutionContext::inject_input`]): the page's "Sensor glitch" sends a NaN pose to
    /// Localization. Known ports: Localization's `InSimulatedPosition` (`[X, Y, Z, θ]`) and
    /// `InCurrentWheelAngle` (`[left, right]` rad). The data is not checked here — that is
    /// the receiving component's job (a non-finite pose puts Localization in Error).
    pub fn inject_input(
        &mut self,
        kind: ComponentKind,
        port: &str,
        data: Vec<f64>,
    ) -> crate::Result<()> {
        if !(kind == ComponentKind::Localization
            && matches!(port, "InSimulatedPosition" | "InCurrentWheelAngle"))
        {
            return Err(SystemError::UnknownPort {
                component: kind.name().to_owned(),
                port: port.to_owned(),
                known: "Localization.InSimulatedPosition, Localization.InCurrentWheelAngle",
            }
            .into());
        }
        let message = TimedDoubleSeq {
            tm: Time::from_nanos(self.time_ns()),
            data,
        };
        let simulated = port == "InSimulatedPosition";
        self.ec.inject_input(
            Self::id(kind),
            Box::new(move |c: &mut dyn Component| {
                let c: &mut dyn core::any::Any = c;
                if let Some(l) = c.downcast_mut::<Localization>() {
                    let target = if simulated {
                        &l.in_simulated_position
                    } else {
                        &l.in_current_wheel_angle
                    };
                    target.put(message);
                }
            }),
        )?;
        self.push_event(EventKind::InputInjected {
            component: kind.name().to_owned(),
            port: port.to_owned(),
        });
        Ok(())
    }

    /// Deactivates every Active component, in reverse attachment order (DriveControl sends
    /// zero velocity and MotorControl zero torque on the way out). Returns the system's state.
    pub fn deactivate_all(&mut self) -> SystemState {
        for kind in ComponentKind::ALL.into_iter().rev() {
            if self.component_state(kind) == LifecycleState::Active {
                let _ = self.ec.deactivate(Self::id(kind));
            }
        }
        self.after_request();
        self.state()
    }

    /// Reset of the whole system: every component in Error is reset, every Active one
    /// deactivated, so that all end Inactive (unless an `on_reset` fails). The robot stays
    /// where it is; set a start and goal and activate again.
    pub fn reset_all(&mut self) -> SystemState {
        for kind in ComponentKind::ALL {
            if self.component_state(kind) == LifecycleState::Error {
                let _ = self.ec.reset(Self::id(kind));
            }
        }
        self.deactivate_all()
    }

    /// Makes the component's next `on_execute` fail with `injected fault: {reason}`
    /// (the page's "Inject fault"; legal while Inactive or Active).
    pub fn inject_fault(&mut self, kind: ComponentKind, reason: &str) -> crate::Result<()> {
        self.ec.inject_fault(Self::id(kind), reason)?;
        Ok(())
    }

    /// Changes a component's rate (SPEC §6: rates are configuration).
    pub fn set_rate(&mut self, kind: ComponentKind, hz: f64) -> crate::Result<()> {
        if kind == ComponentKind::DriveControl {
            let p = period_ticks(self.ec.base_period_ns(), hz, "DriveControl")?;
            self.ec.set_rate(Self::id(kind), hz)?;
            self.drive_period_ticks = p;
        } else {
            self.ec.set_rate(Self::id(kind), hz)?;
        }
        self.rates.set(kind, hz);
        self.after_request();
        Ok(())
    }

    /// Changes the telemetry sampling rate.
    pub fn set_telemetry_rate(&mut self, hz: f64) -> crate::Result<()> {
        self.telemetry_period_ticks = period_ticks(self.ec.base_period_ns(), hz, "telemetry")?;
        self.rates.telemetry = hz;
        Ok(())
    }

    /// A component's configuration parameters, to read and edit live (SPEC §1
    /// "Configuration parameters"). MapBuilder and MapMaintenance have none; PhysicsSim's
    /// are the model's dynamics (SPEC §5 "Physics"), used from its next tick on.
    pub fn config_mut(&mut self, kind: ComponentKind) -> crate::Result<&mut dyn ConfigAccess> {
        let c = self.ec.component_dyn_mut(Self::id(kind))?;
        c.configuration().ok_or_else(|| {
            SystemError::NoConfiguration {
                component: kind.name().to_owned(),
            }
            .into()
        })
    }

    /// Whether LocalPathPlanning computes the whole potential field (for the heat map) or
    /// stops at the robot's cell (faster; the same path).
    pub fn set_full_field(&mut self, full: bool) {
        let extent = if full {
            FieldExtent::Full
        } else {
            FieldExtent::UntilCurrent
        };
        self.get_mut::<LocalPathPlanning>(ComponentKind::LocalPathPlanning)
            .set_field_extent(extent);
    }

    // ------------------------------------------------------------------ map

    /// Loads `map` (MapBuilder's `SetMap` reaches every component at once). The goal, the
    /// paths and queued map updates are dropped (they belong to the old map); the robot is
    /// not moved. A map that cannot be read never gets here (`GridMap` is valid by
    /// construction), so the old map stays when a file is bad.
    pub fn load_map(&mut self, map: GridMap) {
        let tm = Time::from_nanos(self.ec.time_ns());
        {
            let mm = self.get_mut::<MapMaintenance>(ComponentKind::MapMaintenance);
            mm.clear_queue();
        }
        self.get_mut::<LocalPathPlanning>(ComponentKind::LocalPathPlanning)
            .clear();
        self.goal = None;
        self.global_path.clear();
        self.arrived = false;
        self.get_mut::<MapBuilder>(ComponentKind::MapBuilder)
            .load(map, tm);
        self.pump();
    }

    /// The current map: the one loaded, with every `MapUpdate` since.
    pub fn map(&self) -> Option<&GridMap> {
        self.map_maintenance().map()
    }

    /// Changes whenever the current map changes (a load or an update): a key for the
    /// renderer's cached layers.
    pub fn map_key(&self) -> u64 {
        (self.map_loads << 32) | (self.map_updates & 0xffff_ffff)
    }

    /// `MapUpdate` now (the GUI's obstacle brush): checked completely against the current
    /// map (nothing changes on an error), then applied by MapMaintenance and sent to the
    /// planners and the physics. Returns the number of cells that changed.
    pub fn map_update(&mut self, update: MapUpdate) -> crate::Result<usize> {
        let tm = Time::from_nanos(self.ec.time_ns());
        let changed = self
            .get_mut::<MapMaintenance>(ComponentKind::MapMaintenance)
            .map_update(update.at(tm))?;
        self.pump();
        Ok(changed)
    }

    /// [`System::map_update`] of `cells` `(x, y, value)`.
    pub fn set_cells(&mut self, cells: &[(i64, i64, i16)]) -> crate::Result<usize> {
        self.map_update(MapUpdate::from_cells(cells, Time::default()))
    }

    /// Queues `update` to be sent by MapMaintenance at simulated time `at_ns` (checked
    /// now; nothing is queued on an error).
    pub fn schedule_map_update(&mut self, at_ns: u64, update: MapUpdate) -> crate::Result<()> {
        self.get_mut::<MapMaintenance>(ComponentKind::MapMaintenance)
            .schedule(at_ns, update)
    }

    // ------------------------------------------------------------------ goals

    /// `SetPosition(start, goal, direction)` (000 §3.2.2.1 (1)) while the robot is not
    /// driving: the robot is placed at `start` (physics and Localization), and the planners
    /// get start and goal. Checked first by LocalPathPlanning's rules (finite numbers, start
    /// and goal inside the map and farther than `dmin` from every obstacle): on an error
    /// nothing changes — the robot, the previous goal and its path stay.
    ///
    /// While driving, use [`System::set_goal`] (the start is then the robot's pose); this
    /// returns an error.
    pub fn set_position(
        &mut self,
        start: Pose,
        goal: Pose,
        direction: Direction,
    ) -> crate::Result<()> {
        if self.is_driving() {
            return Err(SystemError::Driving {
                call: "SetPosition",
            }
            .into());
        }
        self.submit_position(start, goal, direction, true)
    }

    /// A new goal from where the robot is: Localization's estimate while driving (the
    /// planners plan from what the robot believes), the robot's pose otherwise (e.g. after a
    /// bump and a reset). The robot must have been placed by a [`System::set_position`]
    /// first. Checked as [`System::set_position`]; on an error nothing changes.
    pub fn set_goal(&mut self, goal: Pose, direction: Direction) -> crate::Result<()> {
        if self.start.is_none() {
            return Err(SystemError::NoStart { call: "SetGoal" }.into());
        }
        if self.is_driving() {
            let start = self.localization().current_pose();
            self.submit_position(start, goal, direction, false)
        } else {
            let start = self.robot_pose();
            self.submit_position(start, goal, direction, true)
        }
    }

    fn submit_position(
        &mut self,
        start: Pose,
        goal: Pose,
        direction: Direction,
        place: bool,
    ) -> crate::Result<()> {
        let map = self.map().cloned().ok_or(SystemError::NoMap {
            call: "SetPosition",
        })?;
        let dir = direction.to_short();
        {
            // LocalPathPlanning's checks decide; on an error nothing has changed.
            let local = self.get_mut::<LocalPathPlanning>(ComponentKind::LocalPathPlanning);
            local.set_position(
                start.x,
                start.y,
                start.theta,
                goal.x,
                goal.y,
                goal.theta,
                dir,
            )?;
            if place {
                // The robot is placed anew: the old path and what was sent are dropped (the
                // consumers get an empty path, then the new one), so the new path reaches
                // DriveControl even when it equals the last one sent. (While driving the
                // robot has moved, so the new path differs anyway, and it does not stop.)
                local.clear();
                local.set_grid_map(map);
                local.set_position(
                    start.x,
                    start.y,
                    start.theta,
                    goal.x,
                    goal.y,
                    goal.theta,
                    dir,
                )?;
            }
        }
        if place {
            self.get_mut::<PhysicsSim>(ComponentKind::PhysicsSim)
                .set_pose(start)?;
            self.get_mut::<Localization>(ComponentKind::Localization)
                .set_start_pose(start)?;
            self.last_pose = None;
            self.trail.clear();
        }
        self.get_mut::<GlobalPathPlanning>(ComponentKind::GlobalPathPlanning)
            .set_position(start, goal)?;
        self.start = Some(start);
        self.goal = Some(goal);
        self.direction = direction;
        self.global_path.clear();
        self.arrived = false;
        self.halted = false;
        self.goal_epoch += 1;
        self.push_event(EventKind::GoalSet {
            start,
            goal,
            direction,
        });
        self.pump();
        Ok(())
    }

    /// `Clear` (000 §5.2.4.7): LocalPathPlanning drops everything it holds and sends an
    /// empty path (DriveControl stops). The system then gives it the current map again, so
    /// that a new start and goal can be set; the goal and the paths shown are dropped.
    pub fn clear(&mut self) {
        let map = self.map().cloned();
        let local = self.get_mut::<LocalPathPlanning>(ComponentKind::LocalPathPlanning);
        local.clear();
        if let Some(map) = map {
            local.set_grid_map(map);
        }
        self.goal = None;
        self.global_path.clear();
        self.halted = true;
        self.push_event(EventKind::Cleared);
    }

    /// `SafeMode` (SPEC §3 Decision): the robot halts (empty path) and nothing is replanned
    /// until the next `SetPosition`.
    pub fn safe_mode(&mut self) {
        self.get_mut::<LocalPathPlanning>(ComponentKind::LocalPathPlanning)
            .safe_mode();
        self.halted = true;
        self.push_event(EventKind::SafeMode);
    }

    /// Whether SafeMode or Clear halted the robot (until the next goal).
    pub fn is_halted(&self) -> bool {
        self.halted
    }

    /// Asks LocalPathPlanning for a local (potential-field) plan at its next tick, as a
    /// deviation would. Returns whether the request counts.
    pub fn request_replan(&mut self) -> bool {
        self.get_mut::<LocalPathPlanning>(ComponentKind::LocalPathPlanning)
            .request_replan()
    }

    /// The start of the current goal.
    pub fn start(&self) -> Option<Pose> {
        self.start
    }

    /// The current goal.
    pub fn goal(&self) -> Option<Pose> {
        self.goal
    }

    /// The commanded direction.
    pub fn direction(&self) -> Direction {
        self.direction
    }

    /// The last global route (cells, start first).
    pub fn global_path(&self) -> &[Cell] {
        &self.global_path
    }

    /// The robot's true pose (the physics).
    pub fn robot_pose(&self) -> Pose {
        self.physics().physics().pose()
    }

    /// Where the robot has been (points at least 2 cm apart, oldest first).
    pub fn trail(&self) -> &[(f64, f64)] {
        &self.trail
    }

    /// Running totals.
    pub fn stats(&self) -> RunStats {
        let mut s = self.stats;
        s.local_plans = self.local_path_planning().plan_count();
        s
    }

    // ------------------------------------------------------------------ events, telemetry

    pub(super) fn push_event(&mut self, kind: EventKind) {
        if self.events.len() == EVENT_CAPACITY {
            self.events.pop_front();
        }
        let time_ns = self.tick_time_ns.unwrap_or_else(|| self.ec.time_ns());
        let plan = matches!(
            kind,
            EventKind::GlobalPlan { .. } | EventKind::LocalPlanSent { cells: 1.., .. }
        );
        if plan {
            if self.plan_times.len() == PLAN_TIMES_CAPACITY {
                self.plan_times.pop_front();
            }
            self.plan_times.push_back(time_ns);
        }
        self.events.push_back(SystemEvent { time_ns, kind });
        self.event_total += 1;
    }

    /// The events kept (the newest [`EVENT_CAPACITY`]), oldest first.
    pub fn events(&self) -> &VecDeque<SystemEvent> {
        &self.events
    }

    /// When the newest global and local plans were made \[ns\], oldest first (kept apart
    /// from the events, which the GUI drains).
    pub fn plan_times(&self) -> impl Iterator<Item = u64> + '_ {
        self.plan_times.iter().copied()
    }

    /// MotorControl's service `Motor::SetPDGain(PGainL, PGainR, DGainL, DGainR)` (002
    /// §3.2.2.1 (1)): the four gains at once; all checked first, nothing changes on an error.
    pub fn set_pd_gain(&mut self, p_l: f64, p_r: f64, d_l: f64, d_r: f64) -> crate::Result<()> {
        self.get_mut::<MotorControl>(ComponentKind::MotorControl)
            .set_pd_gain(p_l, p_r, d_l, d_r)
    }

    /// Takes the events kept.
    pub fn drain_events(&mut self) -> Vec<SystemEvent> {
        self.events.drain(..).collect()
    }

    /// Events since the start (kept or not).
    pub fn event_count(&self) -> u64 {
        self.event_total
    }

    /// The telemetry history and trace hash.
    pub fn telemetry(&self) -> &Telemetry {
        &self.telemetry
    }

    /// The telemetry, to change its capacity.
    pub fn telemetry_mut(&mut self) -> &mut Telemetry {
        &mut self.telemetry
    }

    fn sample(&self, time_ns: u64) -> TelemetrySample {
        let physics = self.physics().physics();
        let state = physics.state();
        let motor = self.motor_control();
        let drive = self.drive_control();
        let (v_cmd, w_cmd) = drive.pursuit().last_command();
        let (v, w) = physics.body_velocity();
        TelemetrySample {
            time_ns,
            pose: state.pose,
            estimate: self.localization().current_pose(),
            wheel_angle: state.wheel_angle,
            wheel_rate: state.wheel_rate,
            target_wheel_angle: motor.target_wheel_angles(),
            target_wheel_rate: motor.target_wheel_rates(),
            torque: motor.last_torque(),
            v_cmd,
            w_cmd,
            v,
            w,
            deviation: drive.deviation().unwrap_or(f64::NAN),
        }
    }

    // ------------------------------------------------------------------ running

    /// Runs `ticks` base ticks.
    pub fn step(&mut self, ticks: u64) {
        for _ in 0..ticks {
            if self.script.has_due() {
                self.apply_due_script();
            }
            self.tick();
        }
        if self.script.has_due() {
            self.apply_due_script();
        }
    }

    /// Runs for `seconds` of simulated time (rounded down to whole base ticks).
    pub fn run_for(&mut self, seconds: f64) -> crate::Result<()> {
        let ticks = self.ticks_in(seconds, "run_for seconds")?;
        self.step(ticks);
        Ok(())
    }

    fn ticks_in(&self, seconds: f64, what: &'static str) -> Result<u64, SystemError> {
        if !(seconds.is_finite() && seconds >= 0.0) {
            return Err(SystemError::BadNumber {
                what,
                value: seconds,
                non_negative: true,
            });
        }
        Ok((seconds * 1e9 / self.ec.base_period_ns() as f64) as u64)
    }

    /// Runs until `stop(self)` is true (checked after every tick) or `max_seconds` of
    /// simulated time have passed. Returns whether `stop` said so.
    pub fn run_until(
        &mut self,
        max_seconds: f64,
        mut stop: impl FnMut(&System) -> bool,
    ) -> crate::Result<bool> {
        let ticks = self.ticks_in(max_seconds, "run_until max_seconds")?;
        for _ in 0..ticks {
            self.tick();
            if stop(self) {
                return Ok(true);
            }
        }
        Ok(false)
    }

    /// The planning-only preview (the page's first frame, `rtnav render`): activates what
    /// planning needs (MapBuilder, MapMaintenance, GlobalPathPlanning, LocalPathPlanning),
    /// runs until the route for the current goal has reached LocalPathPlanning and been sent
    /// (or planning failed, or `max_seconds` passed), then asks for one local plan so the
    /// potential field can be drawn. The robot does not move. Returns whether a path was
    /// sent.
    pub fn preview(&mut self, max_seconds: f64) -> crate::Result<bool> {
        let ticks = self.ticks_in(max_seconds, "preview max_seconds")?;
        self.activate_set(&ComponentKind::PLANNING);
        let epoch = self.goal_epoch;
        let mut sent = false;
        for _ in 0..ticks {
            self.tick();
            if self.failed_epoch == epoch && epoch > 0 {
                break;
            }
            if self.local_sent_epoch == epoch && epoch > 0 {
                sent = true;
                break;
            }
        }
        if sent && self.request_replan() {
            let plans = self.local_path_planning().plan_count();
            for _ in 0..ticks {
                self.tick();
                if self.local_path_planning().plan_count() > plans {
                    break;
                }
            }
        }
        Ok(sent)
    }

    /// One base tick, then the system's work between ticks.
    fn tick(&mut self) {
        let k = self.ec.tick_count();
        let time_ns = self.ec.time_ns();
        self.ec.tick();
        self.tick_time_ns = Some(time_ns);
        if self.is_driving() {
            self.track_robot();
        }
        self.pump();
        if k.is_multiple_of(self.drive_period_ticks) {
            self.check_arrival();
        }
        if k.is_multiple_of(self.telemetry_period_ticks) {
            let s = self.sample(time_ns);
            self.telemetry.record(s);
        }
        self.tick_time_ns = None;
    }

    /// Path length, clearance and trail, every tick the physics runs.
    fn track_robot(&mut self) {
        let pose = self.robot_pose();
        if let Some(last) = self.last_pose {
            let (dx, dy) = (pose.x - last.x, pose.y - last.y);
            if dx != 0.0 || dy != 0.0 {
                self.stats.path_length += f64::sqrt(dx * dx + dy * dy);
            }
        }
        self.last_pose = Some(pose);
        let key = self.map_key();
        let mut tracker = core::mem::take(&mut self.clearance);
        if let Some(map) = self.physics().physics().map()
            && could_be_below(map, pose.x, pose.y, self.stats.min_clearance)
        {
            let c = tracker.clearance(map, key, pose.x, pose.y);
            if c < self.stats.min_clearance {
                self.stats.min_clearance = c;
            }
        }
        self.clearance = tracker;
        let far = self.trail.last().is_none_or(|&(x, y)| {
            (pose.x - x) * (pose.x - x) + (pose.y - y) * (pose.y - y)
                >= TRAIL_SPACING * TRAIL_SPACING
        });
        if far {
            if self.trail.len() == TRAIL_CAPACITY {
                self.trail.drain(..TRAIL_CAPACITY / 2);
            }
            self.trail.push((pose.x, pose.y));
        }
    }

    fn check_arrival(&mut self) {
        let arrived = self.drive_control().is_arrived();
        if arrived && !self.arrived {
            let pose = self.robot_pose();
            let (position_error, heading_error) = match self.goal {
                Some(g) => (
                    libm::hypot(pose.x - g.x, pose.y - g.y),
                    angle_diff(pose.theta, g.theta).abs(),
                ),
                None => (f64::NAN, f64::NAN),
            };
            self.push_event(EventKind::Arrived {
                pose,
                position_error,
                heading_error,
            });
        }
        self.arrived = arrived;
    }

    /// After a lifecycle request: the events it caused.
    fn after_request(&mut self) {
        self.pump();
        self.start_drive_script();
    }

    fn drain_lifecycle_events(&mut self) {
        if self.ec.events().is_empty() {
            return;
        }
        for e in self.ec.drain_events() {
            let LifecycleEvent {
                component,
                from,
                to,
                callback,
                reason,
                ..
            } = e;
            if let Some(reason) = reason {
                self.push_event(EventKind::ComponentError {
                    component: component.clone(),
                    callback: callback.to_owned(),
                    reason,
                });
            }
            if from != to {
                self.push_event(EventKind::StateChanged {
                    component,
                    from,
                    to,
                });
            }
        }
    }

    /// The service calls and events of SPEC §0, between ticks: reads the system's ends of
    /// the ports and calls the services they stand for.
    fn pump(&mut self) {
        if self.rx.set_map.is_new()
            && let Some(msg) = self.rx.set_map.read()
        {
            let map: GridMap = (*msg.map).clone();
            self.get_mut::<MapMaintenance>(ComponentKind::MapMaintenance)
                .set_map(map.clone());
            self.get_mut::<GlobalPathPlanning>(ComponentKind::GlobalPathPlanning)
                .set_map(map.clone());
            self.get_mut::<PhysicsSim>(ComponentKind::PhysicsSim)
                .set_map(Some(map.clone()));
            let (width, height, grid_size) = (map.width(), map.height(), map.grid_size());
            self.get_mut::<LocalPathPlanning>(ComponentKind::LocalPathPlanning)
                .set_grid_map(map);
            self.map_loads += 1;
            self.push_event(EventKind::MapLoaded {
                width,
                height,
                grid_size,
            });
        }
        if self.rx.map_update.is_new()
            && let Some(u) = self.rx.map_update.read()
        {
            self.deliver_map_update(&u);
        }
        if self.rx.global_path.is_new()
            && let Some(course) = self.rx.global_path.read()
        {
            let length = self
                .global_path_planning()
                .path_length()
                .unwrap_or(f64::NAN);
            self.global_path = course
                .grid_path_x
                .iter()
                .zip(&course.grid_path_y)
                .map(|(&x, &y)| (x.max(0) as usize, y.max(0) as usize))
                .collect();
            self.stats.global_plans += 1;
            self.push_event(EventKind::GlobalPlan {
                cells: self.global_path.len(),
                length,
            });
            let r = self
                .get_mut::<LocalPathPlanning>(ComponentKind::LocalPathPlanning)
                .set_global_path(&course);
            if let Err(e) = r {
                self.push_event(EventKind::PlanningFailed {
                    planner: ComponentKind::LocalPathPlanning.name().to_owned(),
                    reason: format!("GlobalPathCourse refused: {e}"),
                });
            }
        }
        if self.rx.global_failure.is_new()
            && let Some(f) = self.rx.global_failure.read()
        {
            self.stats.planning_failures += 1;
            self.failed_epoch = self.goal_epoch;
            self.push_event(EventKind::PlanningFailed {
                planner: f.planner,
                reason: f.reason,
            });
        }
        if self.rx.local_path.is_new()
            && let Some(path) = self.rx.local_path.read()
        {
            let lpp = self.local_path_planning();
            let replanned = lpp.local_plan().is_some();
            let control_points = lpp.control_points().map_or(0, |c| c.points.len());
            self.stats.local_paths_sent += 1;
            if !path.cells.is_empty() {
                self.local_sent_epoch = self.goal_epoch;
            }
            self.push_event(EventKind::LocalPlanSent {
                cells: path.cells.len(),
                control_points,
                replanned,
            });
        }
        if self.rx.local_failure.is_new()
            && let Some(f) = self.rx.local_failure.read()
        {
            self.stats.planning_failures += 1;
            self.failed_epoch = self.goal_epoch;
            self.push_event(EventKind::PlanningFailed {
                planner: f.planner,
                reason: f.reason,
            });
        }
        if self.rx.bump.is_new()
            && let Some(report) = self.rx.bump.read()
        {
            // Bump detection calls MotorControl's `Stop` (SPEC §4 Decision).
            self.get_mut::<MotorControl>(ComponentKind::MotorControl)
                .stop();
            self.stats.bumps += 1;
            self.push_event(EventKind::Bump { report });
        }
        self.drain_lifecycle_events();
    }

    fn deliver_map_update(&mut self, u: &MapUpdate) {
        let mut problems = Vec::new();
        let r = self
            .get_mut::<GlobalPathPlanning>(ComponentKind::GlobalPathPlanning)
            .map_update(&u.x, &u.y, &u.value, u.num, u.tm);
        let changed = match r {
            Ok(c) => c,
            Err(e) => {
                problems.push(format!("GlobalPathPlanning: {e}"));
                0
            }
        };
        if let Err(e) = self
            .get_mut::<PhysicsSim>(ComponentKind::PhysicsSim)
            .map_update(&u.x, &u.y, &u.value, u.num, u.tm)
        {
            problems.push(format!("PhysicsSim: {e}"));
        }
        if let Err(e) = self
            .get_mut::<LocalPathPlanning>(ComponentKind::LocalPathPlanning)
            .map_update(&u.x, &u.y, &u.value, u.num, u.tm.sec, u.tm.nsec)
        {
            problems.push(format!("LocalPathPlanning: {e}"));
        }
        self.map_updates += 1;
        self.push_event(EventKind::MapUpdated {
            cells: u.x.len(),
            changed,
        });
        for p in problems {
            self.push_event(EventKind::ComponentError {
                component: ComponentKind::MapMaintenance.instance_name().to_owned(),
                callback: "MapUpdate".to_owned(),
                reason: p,
            });
        }
    }
}
