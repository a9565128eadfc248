//! [`Wiring`]: the eight components in one execution context, their data ports connected,
//! and the service calls made between ticks (spec §0). Each tick returns a [`Report`] of what
//! happened; every request leaves its facts for the next [`Wiring::take_facts`].
//!
//! **Architecture invariant**: the wiring knows the components and the messages between them.
//! It knows nothing of the mission (what the robot is asked to do), of the record (what is
//! kept of a run) or of any user interface.

use core::fmt;

use crate::components::{
    DriveControl, GlobalPathPlanning, LocalPathPlanning, Localization, MapBuilder, MapMaintenance,
    MotorControl, PhysicsSim, SetMapMessage,
};
use crate::errors::{LifecycleError, SystemError};
use crate::interfaces::{Direction, GlobalPathCourse, GridPath, PlanningFailure, Pose};
use crate::local::FieldExtent;
use crate::map::{GridMap, MapUpdate};
use crate::motion::{BumpReport, ModelFrame, PhysicsParams};
use crate::reason::Reason;
use crate::rtc::{
    Component, ConfigAccess, ExecutionContext, InPort, LifecycleEvent, LifecycleState, Time,
    TimedDouble, TimedDoubleSeq,
};
use crate::system::vocabulary::events::EventKind;
use crate::system::vocabulary::kind::ComponentKind;
use crate::system::vocabulary::rates::Rates;

pub(super) mod connections;
mod places;
use connections::{Links, ServiceCall, Services};
pub use places::MotorReadings;

/// What happened in one base tick, or in one request between ticks.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// Simulated time of the tick (or of the request) \[ns\].
    pub time_ns: u64,
    /// The base tick's index; `None` for a request between ticks.
    pub tick: Option<u64>,
    /// What happened, in order.
    pub facts: Vec<EventKind>,
}

/// The system's end of the ports whose data becomes a service call or a fact (spec §0's
/// service arrows): read after every tick and after every request.
#[derive(Debug, Clone)]
struct Bridges {
    set_map: InPort<SetMapMessage>,
    map_update: InPort<MapUpdate>,
    global_path: InPort<GlobalPathCourse>,
    global_failure: InPort<PlanningFailure>,
    local_path: InPort<GridPath>,
    local_failure: InPort<PlanningFailure>,
    bump: InPort<BumpReport>,
    safety_stop: InPort<TimedDouble>,
}

/// The components, their connections and the service calls between ticks (module
/// documentation; the connections are listed in `crate::system`).
pub struct Wiring {
    ec: ExecutionContext,
    rx: Bridges,
    /// Every data connection as it was made.
    links: Links,
    /// Every service port and the calls made on it.
    services: Services,
    map_loads: u64,
    map_updates: u64,
    /// Facts of requests and of the tick being pumped, not yet taken.
    facts: Vec<EventKind>,
    /// The `(dmin, GridSize, radiusOfBodyArea)` last checked for the clearance warning.
    clearance_checked: Option<[u64; 3]>,
}

impl fmt::Debug for Wiring {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Wiring")
            .field("time_ns", &self.ec.time_ns())
            .field("map_loads", &self.map_loads)
            .field("map_updates", &self.map_updates)
            .finish()
    }
}

/// The newest value of `port` if it has not been read yet.
fn take_new<T: Clone>(port: &InPort<T>) -> Option<T> {
    if port.is_new() { port.read() } else { None }
}

impl Wiring {
    /// Every component created (Inactive), ports connected, the execution context Running at
    /// `rates`. No map is loaded.
    ///
    /// The robot model is the physics' default (spec §5) reporting its pose in the RH0 model
    /// frame (002 §4.2: `SimulatedOffsetY` 0.045795 m, `SimulatedOffsetAngle` 1.5708 rad),
    /// with MotorControl configured to match, so the §4 conversion is exercised. A bump fails
    /// the physics' `on_execute`, which puts it in Error.
    pub fn new(rates: Rates) -> crate::Result<Self> {
        let frame = ModelFrame::RH0;
        let map_builder = MapBuilder::new(ComponentKind::MapBuilder.instance_name());
        let map_maintenance = MapMaintenance::new(ComponentKind::MapMaintenance.instance_name());
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
        let localization = Localization::new(ComponentKind::Localization.instance_name());
        let global = GlobalPathPlanning::new(ComponentKind::GlobalPathPlanning.instance_name());
        let local = LocalPathPlanning::new(ComponentKind::LocalPathPlanning.instance_name());
        let drive = DriveControl::new(ComponentKind::DriveControl.instance_name());

        // The system's ends: service calls (`Services`) and facts (InventGUI's in-ports).
        let rx = Bridges {
            set_map: InPort::new("SetMap"),
            map_update: InPort::new("MapUpdate"),
            global_path: InPort::new("GlobalPathCourse"),
            global_failure: InPort::new("GlobalPathFailure"),
            local_path: InPort::new("LocalPathInventGUI"),
            local_failure: InPort::new("LocalPathInventGUIFailure"),
            bump: InPort::new("BumpDetection"),
            safety_stop: InPort::new("SafetyStop"),
        };

        rates.check()?;
        let mut ec = ExecutionContext::new(rates.base())?;
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
        let mut wiring = Self {
            ec,
            rx,
            links: Links::default(),
            services: Services::default(),
            map_loads: 0,
            map_updates: 0,
            facts: Vec::new(),
            clearance_checked: None,
        };
        wiring.connect()?;
        wiring.drain_lifecycle_events();
        wiring.tell_body_radius();
        Ok(wiring)
    }

    // ------------------------------------------------------------------ components

    /// The component in `kind`'s place as its type. Only DriveControl's and MotorControl's
    /// places can hold another type (a student's script, spec §8: [`Wiring::load_script`]
    /// refuses every other place), and the system reaches those two only through
    /// [`Wiring::drive_control`], [`Wiring::motor_control`] and [`Wiring::script`], which
    /// say `None` for the other type; so for the places this is asked of, `Wiring::new`'s
    /// attachment decides the type for good.
    pub(in crate::system) fn get<T: Component>(&self, kind: ComponentKind) -> &T {
        match self.ec.component::<T>(kind.index()) {
            Some(c) => c,
            None => unreachable!("Wiring::new attaches {kind} at index {}", kind.index()),
        }
    }

    /// [`Wiring::get`], mutably (for a service call).
    pub(in crate::system) fn get_mut<T: Component>(&mut self, kind: ComponentKind) -> &mut T {
        match self.ec.component_mut::<T>(kind.index()) {
            Some(c) => c,
            None => unreachable!("Wiring::new attaches {kind} at index {}", kind.index()),
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
    /// The built-in MotorControl, while it is in its place (`None` while a script is).
    pub fn motor_control(&self) -> Option<&MotorControl> {
        self.ec
            .component::<MotorControl>(ComponentKind::MotorControl.index())
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
    /// The built-in DriveControl, while it is in its place (`None` while a script is).
    pub fn drive_control(&self) -> Option<&DriveControl> {
        self.ec
            .component::<DriveControl>(ComponentKind::DriveControl.index())
    }

    /// The execution context (read-only: states, rates, time).
    pub fn execution_context(&self) -> &ExecutionContext {
        &self.ec
    }

    pub(in crate::system) fn ec_mut(&mut self) -> &mut ExecutionContext {
        &mut self.ec
    }

    /// A component's lifecycle state.
    pub fn component_state(&self, kind: ComponentKind) -> LifecycleState {
        self.ec
            .state(kind.index())
            .unwrap_or(LifecycleState::Finalized)
    }

    /// Whether a component is Active and runs at base tick `index`.
    pub fn runs_at(&self, kind: ComponentKind, index: u64) -> bool {
        self.component_state(kind) == LifecycleState::Active
            && self
                .ec
                .period_of(kind.index())
                .is_ok_and(|p| index.is_multiple_of(p))
    }

    /// Whether the robot moves: the physics is Active.
    pub fn is_driving(&self) -> bool {
        self.component_state(ComponentKind::PhysicsSim) == LifecycleState::Active
    }

    /// The robot's true pose (the physics).
    pub fn robot_pose(&self) -> Pose {
        self.physics().physics().pose()
    }

    /// The current map: the one loaded, with every `MapUpdate` since.
    pub fn map(&self) -> Option<&GridMap> {
        self.map_maintenance().map()
    }

    /// Changes whenever the current map changes (a load or an update): a key for cached
    /// layers.
    pub fn map_key(&self) -> u64 {
        (self.map_loads << 32) | (self.map_updates & 0xffff_ffff)
    }

    /// Whether `kind`'s place holds a student's script.
    pub fn is_scripted(&self, kind: ComponentKind) -> bool {
        self.script(kind).is_some()
    }

    /// Whether the planners have nothing left to do for now: no global request pending, no
    /// local plan or course waiting (spec §3).
    pub fn planning_settled(&self) -> bool {
        !self.global_path_planning().is_requested() && self.local_path_planning().is_settled()
    }

    // ------------------------------------------------------------------ ticks and facts

    /// One base tick, then the service calls it caused. Returns what happened.
    pub fn tick(&mut self) -> Report {
        let index = self.ec.tick_count();
        let time_ns = self.ec.time_ns();
        self.ec.tick();
        self.pump();
        Report {
            time_ns,
            tick: Some(index),
            facts: core::mem::take(&mut self.facts),
        }
    }

    /// The facts of the requests since the last tick or take (after their service calls).
    pub fn take_facts(&mut self) -> Vec<EventKind> {
        self.pump();
        core::mem::take(&mut self.facts)
    }

    /// Records a fact (for the wiring's own parts: configuration, lifecycle).
    pub(in crate::system) fn fact(&mut self, fact: EventKind) {
        self.facts.push(fact);
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
                self.facts.push(EventKind::ComponentError {
                    component: component.clone(),
                    callback: callback.to_owned(),
                    reason,
                });
            }
            if from != to {
                self.facts.push(EventKind::StateChanged {
                    component,
                    from,
                    to,
                });
            }
        }
    }

    /// The service calls and facts of spec §0, between ticks: reads the system's ends of the
    /// ports and calls the services they stand for.
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
            if let Some(drive) = self.drive_control_mut() {
                drive.set_map(map.clone());
            }
            let (width, height, grid_size) = (map.width(), map.height(), map.grid_size());
            self.get_mut::<LocalPathPlanning>(ComponentKind::LocalPathPlanning)
                .set_grid_map(map);
            self.record_call(ServiceCall::SetMap(width, height, grid_size));
            self.map_loads += 1;
            self.facts.push(EventKind::MapLoaded {
                width,
                height,
                grid_size,
            });
            self.check_clearance();
        }
        if self.rx.map_update.is_new()
            && let Some(u) = self.rx.map_update.read()
        {
            self.deliver_map_update(&u);
        }
        if self.rx.global_path.is_new()
            && let Some(course) = self.rx.global_path.read()
        {
            let gpp = self.global_path_planning();
            let fact = EventKind::GlobalPlan {
                cells: course.grid_path_x.len(),
                length: gpp.path_length().unwrap_or(f64::NAN),
                reason: gpp
                    .last_reason()
                    .map(|r| format!("{r:?}"))
                    .unwrap_or_default(),
                escaped: gpp.escaped_steps(),
            };
            self.facts.push(fact);
            self.record_call(ServiceCall::GlobalPathCourse(course.num));
            let r = self
                .get_mut::<LocalPathPlanning>(ComponentKind::LocalPathPlanning)
                .set_global_path(&course);
            if let Err(e) = r {
                self.facts.push(EventKind::PlanningFailed {
                    planner: ComponentKind::LocalPathPlanning.name().to_owned(),
                    reason: Reason::CourseRefused(e),
                });
            }
        }
        for failure in [&self.rx.global_failure, &self.rx.local_failure]
            .into_iter()
            .filter_map(take_new)
            .collect::<Vec<_>>()
        {
            self.facts.push(EventKind::PlanningFailed {
                planner: failure.planner,
                reason: failure.reason,
            });
        }
        if self.rx.local_path.is_new()
            && let Some(path) = self.rx.local_path.read()
        {
            let lpp = self.local_path_planning();
            let planned = lpp.local_plan().is_some();
            self.facts.push(EventKind::LocalPlanSent {
                cells: path.cells.len(),
                control_points: lpp.control_points().map_or(0, |c| c.points.len()),
                replanned: planned,
                escaped: if planned { lpp.escaped_steps() } else { 0 },
            });
        }
        if let Some(stop) = take_new(&self.rx.safety_stop) {
            // DriveControl's clearance check stopped the robot: a new plan from where it
            // stands (as a deviation would ask for one) — while the robot can move. With the
            // physics not Active (a bump put it in Error) every new plan would stop the same
            // way, ten times a second: none is asked for until it runs again.
            let replanning = self.is_driving() && self.request_replan();
            self.facts.push(EventKind::SafetyStop {
                ahead: stop.data,
                replanning,
            });
        }
        if self.rx.bump.is_new()
            && let Some(report) = self.rx.bump.read()
        {
            // Bump detection calls MotorControl's `Stop` (spec §4 Decision). A script in its
            // place has no `Stop` service: the call is recorded, and the physics, in Error
            // after the bump, applies no torque.
            if let Some(motor) = self.motor_control_mut() {
                motor.stop();
            }
            self.record_call(ServiceCall::Stop);
            self.facts.push(EventKind::Bump { report });
        }
        self.drain_lifecycle_events();
    }

    fn deliver_map_update(&mut self, u: &MapUpdate) {
        self.record_call(ServiceCall::MapUpdate(u.x.len()));
        let mut problems = Vec::new();
        let r = self
            .get_mut::<GlobalPathPlanning>(ComponentKind::GlobalPathPlanning)
            .map_update(u);
        if let Err(e) = r {
            problems.push((ComponentKind::GlobalPathPlanning, e));
        }
        if let Err(e) = self
            .get_mut::<PhysicsSim>(ComponentKind::PhysicsSim)
            .map_update(u)
        {
            problems.push((ComponentKind::PhysicsSim, e));
        }
        if let Err(e) = self
            .get_mut::<LocalPathPlanning>(ComponentKind::LocalPathPlanning)
            .map_update(u)
        {
            problems.push((ComponentKind::LocalPathPlanning, e));
        }
        if let Some(drive) = self.drive_control_mut()
            && let Err(e) = drive.map_update(u)
        {
            problems.push((ComponentKind::DriveControl, e));
        }
        self.map_updates += 1;
        for (kind, error) in problems {
            self.facts.push(EventKind::ComponentError {
                component: ComponentKind::MapMaintenance.instance_name().to_owned(),
                callback: "MapUpdate".to_owned(),
                reason: Reason::MapUpdateRefused {
                    component: kind.name().to_owned(),
                    error,
                },
            });
        }
    }

    // ------------------------------------------------------------------ lifecycle

    /// Activates one component (Inactive → Active; a failing `on_activated` → Error).
    pub fn activate(&mut self, kind: ComponentKind) -> crate::Result<LifecycleState> {
        let r = self.ec.activate(kind.index());
        self.after_lifecycle();
        Ok(r?)
    }

    /// Deactivates one component (Active → Inactive).
    pub fn deactivate(&mut self, kind: ComponentKind) -> crate::Result<LifecycleState> {
        let r = self.ec.deactivate(kind.index());
        self.after_lifecycle();
        Ok(r?)
    }

    /// Resets one component (Error → Inactive if `on_reset` succeeds).
    pub fn reset(&mut self, kind: ComponentKind) -> crate::Result<LifecycleState> {
        let r = self.ec.reset(kind.index());
        self.after_lifecycle();
        Ok(r?)
    }

    /// Activates every Inactive component of `kinds`, in order (components in Error stay
    /// there: reset them first).
    pub fn activate_set(&mut self, kinds: &[ComponentKind]) {
        for &kind in kinds {
            if self.component_state(kind) == LifecycleState::Inactive {
                // Cannot fail: Inactive and the context is Running; a failing
                // `on_activated` is recorded as a fact.
                let _ = self.ec.activate(kind.index());
            }
        }
        self.after_lifecycle();
    }

    /// Deactivates every Active component, in reverse attachment order (DriveControl sends
    /// zero velocity and MotorControl zero torque on the way out).
    pub fn deactivate_all(&mut self) {
        for kind in ComponentKind::ALL.into_iter().rev() {
            if self.component_state(kind) == LifecycleState::Active {
                let _ = self.ec.deactivate(kind.index());
            }
        }
        self.after_lifecycle();
    }

    /// Every component in Error is reset, every Active one deactivated, so that all end
    /// Inactive (unless an `on_reset` fails).
    pub fn reset_all(&mut self) {
        for kind in ComponentKind::ALL {
            if self.component_state(kind) == LifecycleState::Error {
                let _ = self.ec.reset(kind.index());
            }
        }
        self.deactivate_all();
    }

    fn after_lifecycle(&mut self) {
        self.pump();
        // An activation of MotorControl applies its `on_activation` radiusOfBodyArea.
        self.check_clearance();
    }

    /// Tells DriveControl the robot's body radius: MotorControl's effective
    /// `radiusOfBodyArea` (002 §4.2), the one value of the robot model.
    fn tell_body_radius(&mut self) {
        let radius = self.motor_geometry().radius_of_body_area;
        // MotorControl's geometry is checked when built: finite and > 0.
        if let Some(drive) = self.drive_control_mut() {
            let _ = drive.set_body_radius(radius);
        }
    }

    /// Makes the component's next `on_execute` fail with `injected fault: {reason}`.
    pub fn inject_fault(&mut self, kind: ComponentKind, reason: &str) -> crate::Result<()> {
        self.ec.inject_fault(kind.index(), reason)?;
        self.facts.push(EventKind::FaultInjected {
            component: kind.instance_name().to_owned(),
            reason: reason.to_owned(),
        });
        Ok(())
    }

    /// Writes one sample into a component's input port, as a connected output port would
    /// (OpenRTM rtshell's `rtinject`), just before the component's next execution
    /// ([`ExecutionContext::inject_input`]). Known ports: Localization's
    /// `InSimulatedPosition` (`[X, Y, Z, θ]`) and `InCurrentWheelAngle` (`[left, right]`
    /// rad). The data is not checked here — that is the receiving component's job.
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
                port: crate::present::excerpt(port),
                known: "Localization.InSimulatedPosition, Localization.InCurrentWheelAngle",
            }
            .into());
        }
        let message = TimedDoubleSeq {
            tm: Time::from_nanos(self.ec.time_ns()),
            data,
        };
        let simulated = port == "InSimulatedPosition";
        self.ec.inject_input(
            kind.index(),
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
        self.facts.push(EventKind::InputInjected {
            component: kind.name().to_owned(),
            port: port.to_owned(),
        });
        Ok(())
    }

    /// Changes a component's rate (spec §6: rates are configuration).
    pub fn set_rate(&mut self, kind: ComponentKind, hz: f64) -> Result<(), LifecycleError> {
        self.ec.set_rate(kind.index(), hz)
    }

    // ------------------------------------------------------------------ services

    /// Loads `map` (MapBuilder's `SetMap` reaches every component at once). LocalPathPlanning
    /// and GlobalPathPlanning drop their goal and paths (they belong to the old map); the
    /// robot is not moved.
    pub fn load_map(&mut self, map: GridMap) {
        let tm = Time::from_nanos(self.ec.time_ns());
        self.get_mut::<LocalPathPlanning>(ComponentKind::LocalPathPlanning)
            .clear();
        let call = ServiceCall::LoadMap(map.width(), map.height());
        self.get_mut::<MapBuilder>(ComponentKind::MapBuilder)
            .load(map, tm);
        self.record_call(call);
        self.pump();
    }

    /// `MapUpdate` now (through MapMaintenance, which checks it completely first): returns the
    /// number of cells that changed; nothing changes on an error.
    pub fn map_update(&mut self, update: MapUpdate) -> crate::Result<usize> {
        let cells = update.x.len();
        let update = update.at(Time::from_nanos(self.ec.time_ns()));
        let changed = self
            .get_mut::<MapMaintenance>(ComponentKind::MapMaintenance)
            .map_update(update)?;
        self.record_call(ServiceCall::EditMap(cells));
        self.facts.push(EventKind::MapUpdated { cells, changed });
        self.pump();
        Ok(changed)
    }

    /// `SetPosition` (000 §3.2.2.1 (1)) on LocalPathPlanning — whose checks decide: on an
    /// error nothing has changed — then on GlobalPathPlanning. With `place`, the robot is put
    /// at `start` (physics and Localization) and LocalPathPlanning's old path is dropped (its
    /// consumers get an empty path, then the new one).
    pub fn set_position(
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
        let set = |local: &mut LocalPathPlanning| {
            local.set_position(
                start.x,
                start.y,
                start.theta,
                goal.x,
                goal.y,
                goal.theta,
                dir,
            )
        };
        {
            let local = self.get_mut::<LocalPathPlanning>(ComponentKind::LocalPathPlanning);
            set(local)?;
            if place {
                local.clear();
                local.set_grid_map(map);
                set(local)?;
            }
        }
        if place {
            self.get_mut::<PhysicsSim>(ComponentKind::PhysicsSim)
                .set_pose(start)?;
            self.get_mut::<Localization>(ComponentKind::Localization)
                .set_start_pose(start)?;
        }
        self.get_mut::<GlobalPathPlanning>(ComponentKind::GlobalPathPlanning)
            .set_position(start, goal)?;
        self.record_call(ServiceCall::SetPosition(start, goal, dir, place));
        self.facts.push(EventKind::GoalSet {
            start,
            goal,
            direction,
            placed: place,
        });
        self.pump();
        Ok(())
    }

    /// `Clear` (000 §5.2.4.7): LocalPathPlanning drops everything it holds and sends an
    /// empty path (DriveControl stops); GlobalPathPlanning drops its goal. LocalPathPlanning
    /// gets the current map again, so that a new start and goal can be set.
    pub fn clear(&mut self) {
        let map = self.map().cloned();
        let local = self.get_mut::<LocalPathPlanning>(ComponentKind::LocalPathPlanning);
        local.clear();
        if let Some(map) = map {
            local.set_grid_map(map);
        }
        self.get_mut::<GlobalPathPlanning>(ComponentKind::GlobalPathPlanning)
            .clear();
        self.record_call(ServiceCall::Clear);
        self.facts.push(EventKind::Cleared);
    }

    /// `SafeMode` (spec §3 Decision): the robot halts (empty path) and nothing is replanned
    /// until the next `SetPosition`.
    pub fn safe_mode(&mut self) {
        self.get_mut::<LocalPathPlanning>(ComponentKind::LocalPathPlanning)
            .safe_mode();
        self.record_call(ServiceCall::SafeMode);
        self.facts.push(EventKind::SafeMode);
    }

    /// MotorControl's service `Motor::SetPDGain(PGainL, PGainR, DGainL, DGainR)` (002
    /// §3.2.2.1 (1)): the four gains at once; all checked first, nothing changes on an error.
    /// A script in MotorControl's place gets the same four parameters set at once.
    pub fn set_pd_gain(&mut self, p_l: f64, p_r: f64, d_l: f64, d_r: f64) -> crate::Result<()> {
        if let Some(motor) = self.motor_control_mut() {
            motor.set_pd_gain(p_l, p_r, d_l, d_r)?;
        } else {
            self.set_script_pd_gain([p_l, p_r, d_l, d_r])?;
        }
        self.record_call(ServiceCall::SetPdGain([p_l, p_r, d_l, d_r]));
        self.facts.push(EventKind::GainsSet { p_l, p_r, d_l, d_r });
        Ok(())
    }

    /// Asks LocalPathPlanning for a local (potential-field) plan at its next tick, as a
    /// deviation would. Returns whether the request counts.
    pub fn request_replan(&mut self) -> bool {
        self.get_mut::<LocalPathPlanning>(ComponentKind::LocalPathPlanning)
            .request_replan()
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

    /// Spec §3 Decision 0.2 "one `dmin`": when the values now let the body of radius
    /// `radiusOfBodyArea` touch an obstacle while the planners keep `dmin` between cell
    /// centres (`dmin − GridSize/2 < radiusOfBodyArea`), a warning fact, once per change of
    /// the values.
    pub(in crate::system) fn check_clearance(&mut self) {
        let Some(grid_size) = self.map().map(GridMap::grid_size) else {
            return;
        };
        self.tell_body_radius();
        let dmin = self.local_path_planning().params().dmin;
        let body_radius = self.motor_geometry().radius_of_body_area;
        let key = [dmin.to_bits(), grid_size.to_bits(), body_radius.to_bits()];
        if self.clearance_checked == Some(key) {
            return;
        }
        self.clearance_checked = Some(key);
        if let Some(warning) = self.clearance_warning() {
            self.facts.push(warning);
        }
    }

    /// Spec §3 Decision 0.2 "one `dmin`": [`EventKind::ClearanceWarning`] when the values in
    /// use let the body touch an obstacle (`dmin − GridSize/2 < radiusOfBodyArea`, with
    /// LocalPathPlanning's `dmin`, the map's `GridSize` and MotorControl's effective
    /// `radiusOfBodyArea`); `None` when it cannot, or without a map.
    pub fn clearance_warning(&self) -> Option<EventKind> {
        let grid_size = self.map()?.grid_size();
        let dmin = self.local_path_planning().params().dmin;
        let body_radius = self.motor_geometry().radius_of_body_area;
        (dmin - grid_size / 2.0 < body_radius).then_some(EventKind::ClearanceWarning {
            dmin,
            grid_size,
            body_radius,
        })
    }
}
