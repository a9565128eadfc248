//! The places of the wiring a student's script can take (spec §8, Decisions 0.4): putting a
//! script in DriveControl's or MotorControl's place and the built-in one back, and what the
//! system reads of whoever stands there — the built-in component's own state, or, for a
//! script, what every component shows: its ports' newest samples, its configuration, the
//! pairs its state keeps for the telemetry.

use super::Wiring;
use crate::components::{
    DriveControl, MotorControl, MotorGeometry, ScriptComponent, ScriptPlace, default_geometry,
};
use crate::errors::SystemError;
use crate::motion::DrivePhase;
use crate::rtc::Component;
use crate::script::Program;
use crate::system::vocabulary::events::EventKind;
use crate::system::vocabulary::input::Input;

/// How long a script in DriveControl's place commands nothing before it counts as done
/// with its path \[ns\].
pub const STANDING_NS: u64 = 500_000_000;

/// `SetPDGain`'s parameters, in its order (002 §3.2.2.1 (1)).
const GAINS: [&str; 4] = ["PGainL", "PGainR", "DGainL", "DGainR"];
use crate::system::vocabulary::kind::ComponentKind;

impl Wiring {
    /// The student's script in `kind`'s place, if one is there (spec §8).
    pub fn script(&self, kind: ComponentKind) -> Option<&ScriptComponent> {
        self.ec.component::<ScriptComponent>(kind.index())
    }

    /// The robot model's geometry: MotorControl's `on_activation` parameters as locked at its
    /// last activation (002 §5.2.3 (2)); for a script in MotorControl's place, its effective
    /// parameters (the defaults' geometry where they are not usable, e.g. equal wheel ids).
    pub fn motor_geometry(&self) -> MotorGeometry {
        if let Some(m) = self.motor_control() {
            return *m.geometry();
        }
        self.script(ComponentKind::MotorControl)
            .and_then(ScriptComponent::motor_params)
            .and_then(|p| MotorGeometry::from_params(p).ok())
            .unwrap_or_else(default_geometry)
    }

    /// What MotorControl computed last (002 §5.2.5.4–5): the built-in's target wheel angles
    /// and rates and its torques; for a script in its place, the `target_wheel_angle` and
    /// `target_wheel_rate` pairs it keeps in its state (NaN where it keeps none) and the
    /// last `Torque` it wrote, at the wheel ids.
    pub fn motor_readings(&self) -> MotorReadings {
        if let Some(m) = self.motor_control() {
            return MotorReadings {
                target_wheel_angle: m.target_wheel_angles(),
                target_wheel_rate: m.target_wheel_rates(),
                torque: m.last_torque(),
            };
        }
        let script = self.script(ComponentKind::MotorControl);
        let pair = |key: &str| {
            script
                .and_then(|s| s.state_pair(key))
                .unwrap_or([f64::NAN; 2])
        };
        let g = self.motor_geometry();
        let torque = script
            .and_then(|s| s.last_torque(g.left_wheel_id, g.right_wheel_id))
            .unwrap_or([0.0; 2]);
        MotorReadings {
            target_wheel_angle: pair("target_wheel_angle"),
            target_wheel_rate: pair("target_wheel_rate"),
            torque,
        }
    }

    /// DriveControl's last command `(v, ω)`: the built-in's pursuit command, or the last
    /// `TargetVelocity` a script in its place wrote (`(0, 0)` before any).
    pub fn drive_command(&self) -> (f64, f64) {
        if let Some(d) = self.drive_control() {
            return d.pursuit().last_command();
        }
        self.script(ComponentKind::DriveControl)
            .and_then(ScriptComponent::last_command)
            .unwrap_or((0.0, 0.0))
    }

    /// DriveControl's deviation from the path \[m\]: the built-in's, or the last
    /// `OutDeviating` a script in its place wrote.
    pub fn drive_deviation(&self) -> Option<f64> {
        if let Some(d) = self.drive_control() {
            return d.deviation();
        }
        self.script(ComponentKind::DriveControl)
            .and_then(ScriptComponent::last_deviation)
    }

    /// The last control point DriveControl holds: the end of the built-in's path, or of the
    /// newest control points that reached a script in its place.
    pub fn drive_path_end(&self) -> Option<(f64, f64)> {
        if let Some(d) = self.drive_control() {
            return d
                .pursuit()
                .polyline()
                .and_then(|l| l.points().last().copied());
        }
        self.script(ComponentKind::DriveControl)?.path_end()
    }

    /// Whether a script in DriveControl's place is done with its path: it has commanded
    /// nothing for [`STANDING_NS`] (a script has no phase; a moment of zero, as at the start
    /// or on a turn, is not the end of a path). `false` for the built-in (it has a phase).
    pub fn drive_stands(&self) -> bool {
        self.script(ComponentKind::DriveControl)
            .and_then(ScriptComponent::standing_since)
            .is_some_and(|t| self.ec.time_ns().saturating_sub(t) >= STANDING_NS)
    }

    /// The built-in DriveControl's phase (`None` while a script is in its place: a script has
    /// no phase the system reads; spec §7 makes arrival the system's own fact).
    pub fn drive_phase(&self) -> Option<DrivePhase> {
        self.drive_control().map(|d| d.pursuit().phase())
    }

    /// [`Input::LoadScript`] (the script compiled first: a syntax error refuses it, [`Wiring::load_script`])
    /// and [`Input::UseBuiltIn`] ([`Wiring::use_built_in`]); any other request is not one of
    /// these places' and changes nothing.
    pub fn replace_in_place(&mut self, input: &Input) -> crate::Result<()> {
        match input {
            Input::LoadScript {
                component,
                name,
                source,
            } => {
                let program = Program::compile(name, source)?;
                self.load_script(*component, program)
            }
            Input::UseBuiltIn { component } => self.use_built_in(*component),
            _ => Ok(()),
        }
    }

    /// `SetPDGain` on a script in MotorControl's place: the four gains set as its
    /// parameters, all or none.
    pub(super) fn set_script_pd_gain(&mut self, gains: [f64; 4]) -> crate::Result<()> {
        let config = self
            .ec
            .component_dyn_mut(ComponentKind::MotorControl.index())?
            .configuration()
            .ok_or_else(|| SystemError::NoConfiguration {
                component: ComponentKind::MotorControl.name().to_owned(),
            })?;
        let mut trial = config.boxed_copy();
        for (name, value) in GAINS.iter().zip(gains) {
            trial.set(name, value)?;
        }
        for (name, value) in GAINS.iter().zip(gains) {
            config.set(name, value)?;
        }
        Ok(())
    }

    pub(super) fn drive_control_mut(&mut self) -> Option<&mut DriveControl> {
        self.ec
            .component_mut::<DriveControl>(ComponentKind::DriveControl.index())
    }

    pub(super) fn motor_control_mut(&mut self) -> Option<&mut MotorControl> {
        self.ec
            .component_mut::<MotorControl>(ComponentKind::MotorControl.index())
    }

    /// Puts a student's script in `kind`'s place (spec §8, Decision 0.4 "loading"), with that
    /// component's instance name, ports and parameters (their values as they are now), wired
    /// exactly as the built-in one: the script's top level ran when it was compiled, its
    /// `on_initialize` runs now (Created → Inactive). Refused, changing nothing, for a place
    /// no script can take, a script that declares another component, a component that is
    /// Active, or a failing `on_initialize`.
    // Without the feature `script`, `program` cannot exist: what follows is never reached.
    #[cfg_attr(not(feature = "script"), allow(unreachable_code, unused_variables))]
    pub fn load_script(&mut self, kind: ComponentKind, program: Program) -> crate::Result<()> {
        let place = script_place(kind)?;
        if let Some(declared) = program.declared()
            && declared != place.name()
        {
            return Err(SystemError::ScriptForAnother {
                declared: crate::present::excerpt(declared),
                component: kind.name().to_owned(),
            }
            .into());
        }
        let now = self.ec.tick_now(kind.index())?;
        let from = self.ec.component_dyn(kind.index())?.configuration_ref();
        let script = ScriptComponent::new(place, kind.instance_name(), program, from, now);
        let name = script.program().name().to_owned();
        self.put_in_place(kind, Box::new(script))?;
        self.facts.push(EventKind::ScriptLoaded {
            component: kind.instance_name().to_owned(),
            script: name,
        });
        self.pump();
        Ok(())
    }

    /// Puts the built-in component back in `kind`'s place (spec §8: "the built-in component
    /// can always be put back"), with the parameters as they are now. Refused, changing
    /// nothing, where no script is, or while the component is Active.
    pub fn use_built_in(&mut self, kind: ComponentKind) -> crate::Result<()> {
        script_place(kind)?;
        let script = self.script(kind).ok_or_else(|| SystemError::NotScripted {
            component: kind.name().to_owned(),
        })?;
        let from = script.configuration_ref();
        let mut built_in: Box<dyn Component> = match kind {
            ComponentKind::MotorControl => Box::new(MotorControl::new(kind.instance_name())),
            _ => Box::new(DriveControl::new(kind.instance_name())),
        };
        if let (Some(from), Some(to)) = (from, built_in.configuration()) {
            for spec in to.specs() {
                if let Ok(v) = from.value(spec.name) {
                    let _ = to.set(spec.name, v);
                }
            }
            to.restore_effective(&from.effective_values());
        }
        self.put_in_place(kind, built_in)?;
        self.facts.push(EventKind::BuiltInRestored {
            component: kind.instance_name().to_owned(),
        });
        self.pump();
        self.tell_body_radius();
        Ok(())
    }

    /// Replaces the component in `kind`'s place and connects everything again; on a
    /// failure nothing has changed.
    fn put_in_place(
        &mut self,
        kind: ComponentKind,
        component: Box<dyn Component>,
    ) -> crate::Result<()> {
        let old = self.ec.replace(kind.index(), component)?;
        if let Err(e) = self.reconnect(kind) {
            // The new component lacks a port the table names: the old one goes back.
            let _ = self.ec.replace(kind.index(), old);
            let _ = self.reconnect(kind);
            return Err(e);
        }
        self.drain_lifecycle_events();
        Ok(())
    }
}

/// What MotorControl computed last ([`Wiring::motor_readings`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotorReadings {
    /// Target wheel angles `[left, right]` \[rad\].
    pub target_wheel_angle: [f64; 2],
    /// Target wheel rates `[left, right]` \[rad/s\].
    pub target_wheel_rate: [f64; 2],
    /// Torques `[left, right]` \[N·m\].
    pub torque: [f64; 2],
}

/// The place a script would take for `kind`, or the refusal.
fn script_place(kind: ComponentKind) -> crate::Result<ScriptPlace> {
    ScriptPlace::from_name(kind.name()).ok_or_else(|| {
        SystemError::NotScriptable {
            component: kind.name().to_owned(),
            places: "DriveControl and MotorControl",
        }
        .into()
    })
}
