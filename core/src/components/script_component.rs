//! A component a student writes (spec §8, Decisions 0.4): an RT-component whose actions are
//! the functions of a script, standing in for DriveControl or MotorControl with that
//! component's instance name, ports (the seeds' names; the script names them in snake case)
//! and configuration parameters, so everything wired to it is unchanged.
//!
//! Each callback of seed 003's table runs the script's function of the same name, if it
//! defines one (one it does not define succeeds and does nothing, as the built-in defaults
//! do), with `this` the component's state — one map, started afresh by `on_initialize` —
//! and `rtc` its ports, parameters and tick ([`crate::script`]). An action fails when the
//! script throws, hits a runtime error or runs past a bound; the failure takes the
//! lifecycle's usual path (spec §1) and names the action, the line and the column. What the
//! script prints and every failure go to the component's [`Console`].
//!
//! One guard the built-in components do not need: an `on_error` that fails is not run again
//! until a Reset (it would fail every period, and an endless loop there would spend the
//! whole budget every tick); the console says so.

use rhai::{Dynamic, Map};

use super::{DriveControlParams, MotorControlParams, ScriptPlace};
use crate::interfaces::ControlPoints;
use crate::rtc::{
    Component, ComponentError, ConfigAccess, Configuration, InPort, OutPort, PortView, ReturnCode,
    Tick, TimedDouble, TimedDoubleSeq, TimedPosition, TimedVelocity,
};
use crate::script::{
    Console, ConsoleKind, Io, Program, Rtc, ScriptError, ScriptIn, ScriptOut, script_name,
};

/// A place's in-ports and out-ports.
type PortSet = (Vec<Box<dyn ScriptIn>>, Vec<Box<dyn ScriptOut>>);

/// The ports of `place`'s component, unconnected.
fn ports(place: ScriptPlace) -> PortSet {
    match place {
        ScriptPlace::DriveControl => (
            vec![
                Box::new(InPort::<ControlPoints>::new("InControlPoints")),
                Box::new(InPort::<TimedPosition>::new("InCurrentPosition")),
            ],
            vec![
                Box::new(OutPort::<TimedVelocity>::new("TargetVelocity")),
                Box::new(OutPort::<TimedDouble>::new("OutDeviating")),
                Box::new(OutPort::<TimedDouble>::new("SafetyStop")),
            ],
        ),
        ScriptPlace::MotorControl => (
            vec![
                Box::new(InPort::<TimedVelocity>::new("TargetVelocity")),
                Box::new(InPort::<TimedDoubleSeq>::new("InCurrentWheelAngle")),
                Box::new(InPort::<TimedDoubleSeq>::new("InSimulatedPosition")),
            ],
            vec![
                Box::new(OutPort::<TimedDoubleSeq>::new("Torque")),
                Box::new(OutPort::<TimedDoubleSeq>::new("OutCurrentWheelAngle")),
                Box::new(OutPort::<TimedDoubleSeq>::new(
                    "OutSimulatedPositionToInventGUI",
                )),
                Box::new(OutPort::<TimedDoubleSeq>::new(
                    "OutSimulatedPositionToLocalization",
                )),
            ],
        ),
    }
}

/// The configuration of the component a script stands in for: the same parameters.
#[derive(Debug, Clone, PartialEq)]
enum PlaceConfig {
    Drive(Configuration<DriveControlParams>),
    Motor(Configuration<MotorControlParams>),
}

impl PlaceConfig {
    fn of(place: ScriptPlace) -> Self {
        match place {
            ScriptPlace::DriveControl => Self::Drive(Configuration::new()),
            ScriptPlace::MotorControl => Self::Motor(Configuration::new()),
        }
    }

    fn get(&self) -> &dyn ConfigAccess {
        match self {
            Self::Drive(c) => c,
            Self::Motor(c) => c,
        }
    }

    fn get_mut(&mut self) -> &mut dyn ConfigAccess {
        match self {
            Self::Drive(c) => c,
            Self::Motor(c) => c,
        }
    }
}

/// The script component.
#[derive(Debug)]
pub struct ScriptComponent {
    name: String,
    place: ScriptPlace,
    program: Program,
    config: PlaceConfig,
    ins: Vec<(String, Box<dyn ScriptIn>)>,
    outs: Vec<(String, Box<dyn ScriptOut>)>,
    state: Dynamic,
    console: Console,
    tick: Tick,
    /// `on_error` failed: not run again until a Reset.
    error_quiet: bool,
    /// In DriveControl's place: since when \[ns\] every `TargetVelocity` written was zero.
    standing_since: Option<u64>,
    last_error: Option<ScriptError>,
}

impl Clone for ScriptComponent {
    fn clone(&self) -> Self {
        Self {
            name: self.name.clone(),
            place: self.place,
            program: self.program.clone(),
            config: self.config.clone(),
            ins: self
                .ins
                .iter()
                .map(|(n, p)| (n.clone(), p.boxed_clone()))
                .collect(),
            outs: self
                .outs
                .iter()
                .map(|(n, p)| (n.clone(), p.boxed_clone()))
                .collect(),
            state: self.state.clone(),
            console: self.console.clone(),
            tick: self.tick,
            error_quiet: self.error_quiet,
            standing_since: self.standing_since,
            last_error: self.last_error.clone(),
        }
    }
}

impl ScriptComponent {
    /// The component running `program` in `place`, named `name` (the replaced component's
    /// instance name), with the parameters of `from` (the component it replaces: requested
    /// and effective values alike) or the defaults. `now` is the simulated time, for an
    /// action that runs before the first tick. Its `on_initialize` has not run: the execution
    /// context runs it when it creates the component there.
    pub fn new(
        place: ScriptPlace,
        name: &str,
        program: Program,
        from: Option<&dyn ConfigAccess>,
        now: Tick,
    ) -> Self {
        let mut config = PlaceConfig::of(place);
        if let Some(from) = from {
            let target = config.get_mut();
            for spec in target.specs() {
                if let Ok(v) = from.value(spec.name) {
                    // The same parameter set: every value is in range.
                    let _ = target.set(spec.name, v);
                }
            }
            target.restore_effective(&from.effective_values());
        }
        let (ins, outs) = ports(place);
        Self {
            name: name.to_owned(),
            place,
            program,
            config,
            ins: ins
                .into_iter()
                .map(|p| (script_name(p.name()), p))
                .collect(),
            outs: outs
                .into_iter()
                .map(|p| (script_name(p.name()), p))
                .collect(),
            state: Dynamic::from_map(Map::new()),
            console: Console::default(),
            tick: now,
            error_quiet: false,
            standing_since: None,
            last_error: None,
        }
    }

    /// The place it stands in.
    pub fn place(&self) -> ScriptPlace {
        self.place
    }

    /// MotorControl's parameters as they are in effect, in MotorControl's place.
    pub fn motor_params(&self) -> Option<&MotorControlParams> {
        match &self.config {
            PlaceConfig::Motor(c) => Some(c.params()),
            PlaceConfig::Drive(_) => None,
        }
    }

    /// The script.
    pub fn program(&self) -> &Program {
        &self.program
    }

    /// The state object the script keeps between actions (`this`).
    pub fn state(&self) -> &Dynamic {
        &self.state
    }

    /// A number the script keeps in its state under `key`: a pair `[left, right]` (for the
    /// telemetry's MotorControl targets), if it keeps one.
    pub fn state_pair(&self, key: &str) -> Option<[f64; 2]> {
        let map = self.state.read_lock::<Map>()?;
        let array = map.get(key)?.read_lock::<rhai::Array>()?;
        match array.as_slice() {
            [a, b] => Some([a.as_float().ok()?, b.as_float().ok()?]),
            _ => None,
        }
    }

    /// The console.
    pub fn console(&self) -> &Console {
        &self.console
    }

    /// The last failure of an action, kept until the next success of `on_reset` or a new
    /// activation.
    pub fn last_error(&self) -> Option<&ScriptError> {
        self.last_error.as_ref()
    }

    /// The newest sample of in-port `name` (seed name), as a map, not marked read.
    fn peek_in(&self, name: &str) -> Option<Map> {
        self.ins
            .iter()
            .find(|(_, p)| p.name() == name)
            .and_then(|(_, p)| p.peek())
    }

    /// The last sample written on out-port `name` (seed name), as a map.
    fn last_out(&self, name: &str) -> Option<Map> {
        self.outs
            .iter()
            .find(|(_, p)| p.name() == name)
            .and_then(|(_, p)| p.last())
    }

    /// In DriveControl's place: the last `TargetVelocity` written, `(vx, w)`.
    pub fn last_command(&self) -> Option<(f64, f64)> {
        self.last_out("TargetVelocity")
            .map(|m| (map_number(&m, "vx"), map_number(&m, "w")))
    }

    /// In DriveControl's place: since when \[ns\] it has commanded nothing (every
    /// `TargetVelocity` written zero); `None` while it commands motion or before it wrote one.
    pub fn standing_since(&self) -> Option<u64> {
        self.standing_since
    }

    /// In DriveControl's place: the last `OutDeviating` written \[m\].
    pub fn last_deviation(&self) -> Option<f64> {
        self.last_out("OutDeviating")
            .map(|m| map_number(&m, "data"))
    }

    /// In DriveControl's place: the last point of the newest control points received.
    pub fn path_end(&self) -> Option<(f64, f64)> {
        let points = self.peek_in("InControlPoints")?;
        let points = points.get("points")?.read_lock::<rhai::Array>()?.clone();
        let last = points.last()?.read_lock::<Map>()?.clone();
        Some((map_number(&last, "x"), map_number(&last, "y")))
    }

    /// In MotorControl's place: the last `Torque` written, at the wheel ids `[left, right]`.
    pub fn last_torque(&self, left: usize, right: usize) -> Option<[f64; 2]> {
        let m = self.last_out("Torque")?;
        let data = m.get("data")?.read_lock::<rhai::Array>()?.clone();
        let at = |i: usize| data.get(i).and_then(|v| v.as_float().ok());
        Some([at(left)?, at(right)?])
    }

    /// Runs `action` (module documentation).
    fn run(&mut self, action: &'static str, tick: Option<&Tick>) -> ReturnCode {
        if let Some(t) = tick {
            self.tick = *t;
        }
        if !self.program.defines(action) {
            return Ok(());
        }
        let config = self.config.get();
        let params = config
            .specs()
            .iter()
            .zip(config.effective_values())
            .map(|(s, v)| (s.name, v, s.kind == crate::rtc::ParamKind::Int))
            .collect::<Vec<_>>();
        // What the action starts from, to find where it ran past a bound if it does.
        let before = (
            self.state.clone(),
            self.ins
                .iter()
                .map(|(n, p)| (n.clone(), p.boxed_clone()))
                .collect::<Vec<_>>(),
            params.clone(),
        );
        let io = Io {
            ins: core::mem::take(&mut self.ins),
            outs: core::mem::take(&mut self.outs),
            params,
            tick: self.tick,
            live: true,
        };
        let rtc = Rtc(std::rc::Rc::new(std::cell::RefCell::new(io)));
        let (printed, result) = self.program.call(action, &mut self.state, rtc.clone());
        {
            let mut io = rtc.0.borrow_mut();
            io.live = false;
            self.ins = core::mem::take(&mut io.ins);
            self.outs = core::mem::take(&mut io.outs);
        }
        let result = match result {
            Err(ScriptError::Bound {
                action: name,
                line: 0,
                message,
                ..
            }) => {
                let (mut state, ins, params) = before;
                let outs = self
                    .outs
                    .iter()
                    .map(|(n, p)| (n.clone(), p.boxed_clone()))
                    .collect();
                let io = Io {
                    ins,
                    outs,
                    params,
                    tick: self.tick,
                    live: true,
                };
                let copy = Rtc(std::rc::Rc::new(std::cell::RefCell::new(io)));
                let (line, column) = self
                    .program
                    .locate(action, &mut state, copy)
                    .unwrap_or((0, 0));
                Err(ScriptError::Bound {
                    action: name,
                    line,
                    column,
                    message,
                })
            }
            other => other,
        };
        let time_s = self.tick.seconds();
        for line in &printed {
            self.console
                .push(ConsoleKind::Print, time_s, action, None, line);
        }
        result.map_err(|e| {
            self.console.push(
                ConsoleKind::Error,
                time_s,
                action,
                e.position(),
                e.message(),
            );
            self.last_error = Some(e.clone());
            ComponentError::from(crate::Error::from(e))
        })
    }
}

impl Component for ScriptComponent {
    fn instance_name(&self) -> &str {
        &self.name
    }

    fn boxed_clone(&self) -> Option<Box<dyn Component>> {
        Some(Box::new(self.clone()))
    }

    fn configuration(&mut self) -> Option<&mut dyn ConfigAccess> {
        Some(self.config.get_mut())
    }

    fn configuration_ref(&self) -> Option<&dyn ConfigAccess> {
        Some(self.config.get())
    }

    fn ports(&self) -> Vec<PortView> {
        self.ins
            .iter()
            .map(|(_, p)| p.view())
            .chain(self.outs.iter().map(|(_, p)| p.view()))
            .collect()
    }

    fn in_port(&self, name: &str) -> Option<&dyn core::any::Any> {
        self.ins
            .iter()
            .find(|(_, p)| p.name() == name)
            .map(|(_, p)| p.as_any())
    }

    fn out_port_mut(&mut self, name: &str) -> Option<&mut dyn core::any::Any> {
        self.outs
            .iter_mut()
            .find(|(_, p)| p.name() == name)
            .map(|(_, p)| p.as_any_mut())
    }

    fn disconnect_ports(&mut self) {
        for (_, p) in &mut self.outs {
            p.disconnect_all();
        }
    }

    fn script_name(&self) -> Option<&str> {
        Some(self.program.name())
    }

    /// Starts the state afresh (spec §8: "one state object that `on_initialize` starts
    /// afresh"), then the script's `on_initialize`.
    fn on_initialize(&mut self) -> ReturnCode {
        self.state = Dynamic::from_map(Map::new());
        self.console.clear();
        self.last_error = None;
        self.error_quiet = false;
        self.run("on_initialize", None)
    }
    fn on_finalize(&mut self) -> ReturnCode {
        self.run("on_finalize", None)
    }
    fn on_startup(&mut self, tick: &Tick) -> ReturnCode {
        self.run("on_startup", Some(tick))
    }
    fn on_shutdown(&mut self, tick: &Tick) -> ReturnCode {
        self.run("on_shutdown", Some(tick))
    }
    fn on_activated(&mut self, tick: &Tick) -> ReturnCode {
        self.last_error = None;
        self.standing_since = None;
        self.run("on_activated", Some(tick))
    }
    fn on_deactivated(&mut self, tick: &Tick) -> ReturnCode {
        self.run("on_deactivated", Some(tick))
    }
    fn on_execute(&mut self, tick: &Tick) -> ReturnCode {
        let r = self.run("on_execute", Some(tick));
        if self.place == ScriptPlace::DriveControl {
            self.standing_since = match self.last_command() {
                Some((v, w)) if v == 0.0 && w == 0.0 => {
                    Some(self.standing_since.unwrap_or(tick.time_ns))
                }
                _ => None,
            };
        }
        r
    }
    fn on_state_update(&mut self, tick: &Tick) -> ReturnCode {
        self.run("on_state_update", Some(tick))
    }
    fn on_aborting(&mut self, tick: &Tick) -> ReturnCode {
        self.run("on_aborting", Some(tick))
    }
    fn on_error(&mut self, tick: &Tick) -> ReturnCode {
        if self.error_quiet {
            return Ok(());
        }
        let r = self.run("on_error", Some(tick));
        if r.is_err() {
            self.error_quiet = true;
            self.console.push(
                ConsoleKind::Error,
                tick.seconds(),
                "on_error",
                None,
                "on_error failed: it is not run again until a Reset",
            );
        }
        r
    }
    fn on_reset(&mut self, tick: &Tick) -> ReturnCode {
        let r = self.run("on_reset", Some(tick));
        if r.is_ok() {
            self.error_quiet = false;
            self.last_error = None;
        }
        r
    }
    fn on_rate_changed(&mut self, tick: &Tick) -> ReturnCode {
        self.run("on_rate_changed", Some(tick))
    }
}

/// A number field of a sample map (0 where it has none: the map was checked when written).
fn map_number(map: &Map, key: &str) -> f64 {
    map.get(key).and_then(|v| v.as_float().ok()).unwrap_or(0.0)
}
