//! The core of the teaching tools: PhysicsSim's configuration (spec §5 "Physics"),
//! the whole configuration as one OpenRTM `.conf` bundle (spec §1), and the cell inspector
//! (spec §2 obstacle distance, spec §3 step 4 potential field).

use std::collections::BTreeSet;

use rtnav::Error;
use rtnav::components::{PhysicsSim, PhysicsSimParams};
use rtnav::errors::{ConfBundleError, ConfigError, MotionError, ScenarioError, SystemError};
use rtnav::interfaces::{Direction, Pose};
use rtnav::map::GridMap;
use rtnav::motion::{Physics, PhysicsParams};
use rtnav::rtc::{
    ComponentId, ConfFile, ConfigAccess, ExecutionContext, LifecycleState, OutPort, Time,
    TimedDoubleSeq,
};
use rtnav::system::setup::{self, BuildOptions, PLAN_SECONDS, Setup};
use rtnav::system::{
    CONF_BUNDLE_HEADER, ComponentKind, DirResolver, Input, Rates, Scenario, System,
};

/// `SetParam` of `component`'s `name`.
fn param(component: ComponentKind, name: &str, value: f64) -> Input {
    Input::SetParam {
        component,
        name: name.to_owned(),
        value,
    }
}

/// `LoadConf` of `text`.
fn load_conf(text: &str) -> Input {
    Input::LoadConf {
        text: text.to_owned(),
    }
}

// ---------------------------------------------------------------- PhysicsSim's configuration

#[test]
fn physics_parameter_defaults_are_the_model_the_system_is_built_with() {
    let d = PhysicsSimParams::default();
    let p = PhysicsParams::default();
    assert_eq!(
        (d.mass, d.yaw_inertia, d.viscous_friction, d.max_torque),
        (p.mass, p.yaw_inertia, p.viscous_friction, p.max_torque)
    );
    assert_eq!((d.mass, d.max_torque), (20.0, 5.0));
    let s = System::new(Rates::default()).unwrap();
    let cfg = s.wiring().config(ComponentKind::PhysicsSim).unwrap();
    let names: Vec<_> = cfg.specs().iter().map(|s| s.name).collect();
    assert_eq!(
        names,
        ["Mass", "YawInertia", "ViscousFriction", "MaxTorque"]
    );
    let units: Vec<_> = cfg.specs().iter().map(|s| s.unit).collect();
    assert_eq!(units, ["kg", "kg·m²", "N·m·s/rad", "N·m"]);
    for spec in cfg.specs() {
        assert_eq!(spec.reflection.to_string(), "always");
        assert!(
            spec.description.contains("spec §5 Physics"),
            "{}",
            spec.name
        );
        assert!(spec.min >= 0.0 && spec.max.is_finite(), "{}", spec.name);
    }
    let model = s.wiring().physics().physics().params();
    assert_eq!(cfg.value("Mass").unwrap(), model.mass);
    assert_eq!(cfg.value("YawInertia").unwrap(), model.yaw_inertia);
    assert_eq!(
        cfg.value("ViscousFriction").unwrap(),
        model.viscous_friction
    );
    assert_eq!(cfg.value("MaxTorque").unwrap(), model.max_torque);
}

/// PhysicsSim alone at 1 kHz, a constant torque on both wheels.
struct PhysicsRig {
    ec: ExecutionContext,
    id: ComponentId,
    torque: OutPort<TimedDoubleSeq>,
}

impl PhysicsRig {
    fn new() -> Self {
        let physics = PhysicsSim::new("PhysicsSim0", PhysicsParams::default()).unwrap();
        let mut torque = OutPort::new("Torque");
        torque.connect(&physics.torque);
        let mut ec = ExecutionContext::new(1000.0).unwrap();
        let id = ec.attach(Box::new(physics), 1000.0).unwrap();
        ec.start().unwrap();
        assert_eq!(ec.activate(id).unwrap(), LifecycleState::Active);
        Self { ec, id, torque }
    }

    fn tick(&mut self, torque: [f64; 2]) {
        self.torque.write(TimedDoubleSeq {
            tm: Time::from_nanos(self.ec.time_ns()),
            data: torque.to_vec(),
        });
        self.ec.tick();
    }

    fn sim(&self) -> &PhysicsSim {
        self.ec.component::<PhysicsSim>(self.id).unwrap()
    }

    fn config(&mut self) -> &mut dyn ConfigAccess {
        self.ec
            .component_dyn_mut(self.id)
            .unwrap()
            .configuration()
            .unwrap()
    }
}

#[test]
fn a_changed_mass_takes_effect_at_the_next_tick_and_the_state_carries_over() {
    let torque = [1.0, 0.8];
    let mut rig = PhysicsRig::new();
    // The same model by hand: 50 steps at 20 kg, then 50 at 35 kg with every other value kept.
    let mut reference = Physics::new(PhysicsParams::default()).unwrap();
    for _ in 0..50 {
        rig.tick(torque);
        reference.step(torque).unwrap();
    }
    rig.config().set("Mass", 35.0).unwrap();
    // Requested and effective at once (`always`); the physics uses it from the next tick.
    assert_eq!(rig.config().effective_value("Mass").unwrap(), 35.0);
    assert_eq!(rig.sim().physics().params().mass, 20.0);
    let heavier = PhysicsParams {
        mass: 35.0,
        ..PhysicsParams::default()
    };
    reference.set_params(heavier.clone()).unwrap();
    for _ in 0..50 {
        rig.tick(torque);
        reference.step(torque).unwrap();
    }
    let physics = rig.sim().physics();
    assert_eq!(physics.params(), &heavier);
    assert_eq!(physics.mass_matrix(), heavier.mass_matrix());
    assert_eq!(physics.state().wheel_rate, reference.state().wheel_rate);
    assert_eq!(physics.state().wheel_angle, reference.state().wheel_angle);
    assert_eq!(physics.pose(), reference.pose());
}

#[test]
fn a_heavier_robot_and_a_weaker_motor_accelerate_less() {
    // 0.3 s of 2 N·m on both wheels: straight driving from rest.
    let speed = |key: &str, value: f64| {
        let mut rig = PhysicsRig::new();
        rig.config().set(key, value).unwrap();
        for _ in 0..300 {
            rig.tick([2.0, 2.0]);
        }
        rig.sim().physics().body_velocity().0
    };
    let base = speed("Mass", 20.0);
    assert!(base > 0.0);
    assert!(speed("Mass", 40.0) < base);
    assert!(speed("Mass", 10.0) > base);
    // Saturated at 1 N·m: half the torque.
    assert!(speed("MaxTorque", 1.0) < base);
    assert!(speed("ViscousFriction", 1.0) < base);
    // Straight driving does not feel the yaw inertia (c = m r²/4 − I r²/(4R²) cancels it).
    let straight = speed("YawInertia", 3.0);
    assert!((straight - base).abs() < 1e-12, "{straight} vs {base}");
}

#[test]
fn bad_physics_values_are_refused_and_change_nothing() {
    let mut s = System::new(Rates::default()).unwrap();
    let physics = ComponentKind::PhysicsSim;
    for (name, value) in [
        ("Mass", 0.0),
        ("Mass", -1.0),
        ("Mass", f64::NAN),
        ("Mass", 1e6),
        ("YawInertia", 0.0),
        ("ViscousFriction", -0.1),
        ("MaxTorque", 0.0),
        ("MaxTorque", f64::INFINITY),
    ] {
        let e = s.apply(&param(physics, name, value)).unwrap_err();
        assert!(
            matches!(&e, Error::Config(ConfigError::OutOfRange { name: n, .. }) if n == name),
            "{name} = {value}: {e}"
        );
    }
    let e = s.apply(&param(physics, "Masse", 30.0)).unwrap_err();
    assert!(
        matches!(&e, Error::Config(ConfigError::UnknownParameter { .. })),
        "{e}"
    );
    // Named with its component: the request named both.
    assert_eq!(
        e.to_string(),
        "unknown configuration parameter `PhysicsSim.Masse`"
    );
    let cfg = s.wiring().config(physics).unwrap();
    assert_eq!(cfg.value("Mass").unwrap(), 20.0);
    assert_eq!(cfg.value("MaxTorque").unwrap(), 5.0);
    // Zero friction is allowed.
    s.apply(&param(physics, "ViscousFriction", 0.0)).unwrap();
    // A model outside the configuration's range cannot be built into a PhysicsSim.
    let heavy = PhysicsParams {
        mass: 5000.0,
        ..PhysicsParams::default()
    };
    match PhysicsSim::new("PhysicsSim0", heavy) {
        Err(MotionError::BadParameter { name, value, .. }) => {
            assert_eq!((name.as_str(), value), ("Mass", 5000.0));
        }
        other => panic!("{other:?}"),
    }
}

fn open_field_json(config: serde_json::Value) -> String {
    let text = std::fs::read_to_string("../fixtures/scenarios/open_field.json").unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["config"] = config;
    v.to_string()
}

#[test]
fn a_scenario_configures_physics_sim_by_name() {
    let json = open_field_json(serde_json::json!({
        "PhysicsSim": { "Mass": 35.0, "MaxTorque": 2.5 },
        "LocalPathPlanning": { "dmin": 0.6 }
    }));
    let scenario = Scenario::from_json(&json).unwrap();
    let mut s = build(&scenario).unwrap();
    let cfg = s.wiring().config(ComponentKind::PhysicsSim).unwrap();
    assert_eq!(cfg.effective_value("Mass").unwrap(), 35.0);
    assert_eq!(cfg.effective_value("MaxTorque").unwrap(), 2.5);
    assert_eq!(cfg.value("YawInertia").unwrap(), 1.0);
    s.apply(&Input::ActivateAll).unwrap();
    s.step(1);
    let model = s.wiring().physics().physics().params();
    assert_eq!((model.mass, model.max_torque), (35.0, 2.5));

    // A value out of range: the scenario is refused, naming the parameter.
    let json = open_field_json(serde_json::json!({ "PhysicsSim": { "Mass": -1.0 } }));
    let scenario = Scenario::from_json(&json).unwrap();
    let e = build(&scenario).err().unwrap();
    assert!(
        matches!(e, Error::Scenario(ScenarioError::Scenario { .. })),
        "{e}"
    );
    assert!(e.to_string().contains("`Mass`"), "{e}");
    // An unknown parameter too.
    let json = open_field_json(serde_json::json!({ "PhysicsSim0": { "Weight": 30.0 } }));
    let scenario = Scenario::from_json(&json).unwrap();
    let e = build(&scenario).err().unwrap();
    assert!(e.to_string().contains("`PhysicsSim.Weight`"), "{e}");
}

/// The set-up of `scenario` as the runner and the page build it (files from the project).
fn build(scenario: &Scenario) -> rtnav::Result<System> {
    setup::build(
        scenario,
        &DirResolver::new(".."),
        &Setup::of(scenario),
        BuildOptions::default(),
    )
}

// ---------------------------------------------------------------- the .conf bundle

/// The marker lines' names, in order.
fn markers(text: &str) -> Vec<String> {
    text.lines()
        .filter_map(|l| l.strip_prefix("# [")?.strip_suffix(']'))
        .map(str::to_owned)
        .collect()
}

/// The 1-based line of the first line that starts with `prefix` after the marker of
/// `component`.
fn line_of(text: &str, component: &str, prefix: &str) -> usize {
    let marker = format!("# [{component}]");
    let start = text.lines().position(|l| l == marker).unwrap();
    start
        + 1
        + text
            .lines()
            .skip(start)
            .position(|l| l.starts_with(prefix))
            .unwrap()
}

/// `text` with line `line` (1-based) replaced.
fn with_line(text: &str, line: usize, new: &str) -> String {
    let mut lines: Vec<&str> = text.lines().collect();
    lines[line - 1] = new;
    lines.join("\n") + "\n"
}

#[test]
fn the_bundle_has_one_block_per_component_each_a_conf_file_of_its_own() {
    let s = System::new(Rates::default()).unwrap();
    let text = s.wiring().to_conf();
    assert_eq!(text.lines().next(), Some(CONF_BUNDLE_HEADER));
    assert_eq!(
        markers(&text),
        [
            "PhysicsSim0",
            "MotorControl0",
            "Localization0",
            "GlobalPathPlanning0",
            "LocalPathPlanning0",
            "DriveControl0"
        ]
    );
    assert_eq!(
        s.wiring().configured_components(),
        [
            ComponentKind::PhysicsSim,
            ComponentKind::MotorControl,
            ComponentKind::Localization,
            ComponentKind::GlobalPathPlanning,
            ComponentKind::LocalPathPlanning,
            ComponentKind::DriveControl
        ]
    );
    // Reading and setting agree on who has parameters: a component without any refuses a
    // parameter as such, one with parameters refuses only the unknown name.
    let mut m = System::new(Rates::default()).unwrap();
    for kind in ComponentKind::ALL {
        let e = m.apply(&param(kind, "NoSuchParameter", 1.0)).unwrap_err();
        let has_none = matches!(e, Error::System(SystemError::NoConfiguration { .. }));
        assert_eq!(s.wiring().config(kind).is_err(), has_none, "{kind}: {e}");
    }
    // Each block is exactly that component's own `.conf` text, and loads alone.
    for kind in s.wiring().configured_components() {
        let marker = format!("# [{}]\n", kind.instance_name());
        let own = s.wiring().config(kind).unwrap().to_conf();
        assert!(text.contains(&format!("{marker}{own}")), "{kind}");
        ConfFile::parse(&own).unwrap();
        m.apply(&load_conf(&format!("{marker}{own}"))).unwrap();
    }
    assert_eq!(m.wiring().to_conf(), text);
    assert!(text.contains("# [PhysicsSim0]\n# -*- Property -*-\n"));
    assert!(text.contains("conf.default.Mass: 20.0\n"));
    assert!(text.contains("conf.default.MaxTorque: 5.0\n"));
    // The whole text reads as one properties file too (markers are comments).
    assert!(ConfFile::parse(&text).is_ok());
}

#[test]
fn export_import_export_is_identical() {
    let mut s = System::new(Rates::default()).unwrap();
    let fresh = s.wiring().to_conf();
    s.apply(&load_conf(&fresh)).unwrap();
    assert_eq!(s.wiring().to_conf(), fresh);
    // Non-default values, a second configuration set and widgets (from the fixture).
    s.apply(&param(ComponentKind::PhysicsSim, "Mass", 31.25))
        .unwrap();
    s.apply(&param(ComponentKind::DriveControl, "MaxVelocity", 0.3))
        .unwrap();
    let fixture = std::fs::read_to_string("../fixtures/conf/LocalPathPlanning.conf").unwrap();
    s.apply(&load_conf(&format!("# [LocalPathPlanning]\n{fixture}")))
        .unwrap();
    let first = s.wiring().to_conf();
    assert_ne!(first, fresh);
    let mut t = System::new(Rates::default()).unwrap();
    t.apply(&load_conf(&first)).unwrap();
    assert_eq!(t.wiring().to_conf(), first);
    s.apply(&load_conf(&first)).unwrap();
    assert_eq!(s.wiring().to_conf(), first);
}

#[test]
fn a_byte_order_mark_before_a_conf_is_skipped() {
    // Editors on Windows write one; the first line is still a marker (or a key).
    let mut s = System::new(Rates::default()).unwrap();
    s.apply(&param(ComponentKind::DriveControl, "MaxVelocity", 0.3))
        .unwrap();
    let text = s.wiring().to_conf();
    let mut t = System::new(Rates::default()).unwrap();
    t.apply(&load_conf(&format!("\u{feff}{text}"))).unwrap();
    assert_eq!(t.wiring().to_conf(), text);
    let block = "\u{feff}# [DriveControl0]\nconf.default.MaxVelocity: 0.25\n";
    t.apply(&load_conf(block)).unwrap();
    let one = ConfFile::parse("\u{feff}conf.default.MaxVelocity: 0.25\n").unwrap();
    assert_eq!(one.entries.len(), 1);
    assert_eq!(one.entries[0].key.to_string(), "conf.default.MaxVelocity");
}

#[test]
fn an_imported_value_reaches_the_configuration() {
    let mut s = System::new(Rates::default()).unwrap();
    let text = s.wiring().to_conf();
    let mass = line_of(&text, "PhysicsSim0", "conf.default.Mass:");
    let text = with_line(&text, mass, "conf.default.Mass: 42.5");
    let lpp_dmin = line_of(&text, "LocalPathPlanning0", "conf.default.dmin:");
    let gpp_dmin = line_of(&text, "GlobalPathPlanning0", "conf.default.dmin:");
    let text = with_line(&text, lpp_dmin, "conf.default.dmin = 0.75");

    // Spec §3 Decision 0.2 "one dmin": a bundle giving the planners different values is
    // refused, naming both, and nothing changes.
    let before = s.wiring().to_conf();
    assert_eq!(
        s.apply(&load_conf(&text)).unwrap_err(),
        Error::System(SystemError::DminMismatch {
            first: "GlobalPathPlanning0",
            first_value: 0.5,
            second: "LocalPathPlanning0",
            second_value: 0.75,
        })
    );
    assert_eq!(s.wiring().to_conf(), before);

    let text = with_line(&text, gpp_dmin, "conf.default.dmin: 0.75");
    s.apply(&load_conf(&text)).unwrap();
    let physics = s.wiring().config(ComponentKind::PhysicsSim).unwrap();
    assert_eq!(physics.value("Mass").unwrap(), 42.5);
    assert_eq!(physics.effective_value("Mass").unwrap(), 42.5);
    assert_eq!(s.wiring().local_path_planning().params().dmin, 0.75);
    assert_eq!(s.wiring().global_path_planning().params().dmin, 0.75);
    // The physics uses it from its next tick, once the robot is placed (spec §5 Decision
    // 0.4): an open 4 × 4 m floor.
    s.load_map(rtnav::map::GridMap::from_map_data(&[0; 1600], 40, 40, 0.1).unwrap());
    s.apply(&Input::SetPosition {
        start: rtnav::interfaces::Pose::new(2.0, 2.0, 0.0),
        goal: rtnav::interfaces::Pose::new(2.2, 2.0, 0.0),
        direction: rtnav::interfaces::Direction::Forward,
    })
    .unwrap();
    s.apply(&Input::Activate {
        component: ComponentKind::PhysicsSim,
    })
    .unwrap();
    s.step(1);
    assert_eq!(s.wiring().physics().physics().params().mass, 42.5);

    // A bundle of one component (the fixture's hand-written file after a marker) changes
    // only that component; its active set is `mode1` ...
    let before = s.wiring().to_conf();
    let fixture = std::fs::read_to_string("../fixtures/conf/LocalPathPlanning.conf").unwrap();
    s.apply(&load_conf(&format!("# [LocalPathPlanning]\n{fixture}")))
        .unwrap();
    let lpp = s.wiring().config(ComponentKind::LocalPathPlanning).unwrap();
    assert_eq!(lpp.active_set(), "mode1");
    assert_eq!(lpp.value("dmin").unwrap(), 0.25);
    // ... but for `dmin`, one value for the system (spec §3 Decision 0.2).
    let gpp = s
        .wiring()
        .config(ComponentKind::GlobalPathPlanning)
        .unwrap();
    assert_eq!(gpp.value("dmin").unwrap(), 0.25);
    let after = s.wiring().to_conf();
    let block = |t: &str, name: &str| {
        let start = t.find(&format!("# [{name}]")).unwrap();
        let rest = &t[start + 1..];
        rest[..rest.find("# [").unwrap_or(rest.len())].to_owned()
    };
    for name in [
        "PhysicsSim0",
        "MotorControl0",
        "Localization0",
        "DriveControl0",
    ] {
        assert_eq!(block(&after, name), block(&before, name), "{name}");
    }
}

#[test]
fn a_bad_bundle_changes_nothing_and_names_line_component_and_problem() {
    let mut s = System::new(Rates::default()).unwrap();
    s.apply(&param(ComponentKind::DriveControl, "MaxVelocity", 0.4))
        .unwrap();
    let good = s.wiring().to_conf();
    // A valid change early in the file, so a late error must undo nothing that was applied.
    let mass = line_of(&good, "PhysicsSim0", "conf.default.Mass:");
    let base = with_line(&good, mass, "conf.default.Mass: 50.0");
    let lpp_dmin = line_of(&base, "LocalPathPlanning0", "conf.default.dmin:");
    let dc_marker = line_of(&base, "DriveControl0", "# [DriveControl0]");
    let dc_vel = line_of(&base, "DriveControl0", "conf.default.MaxVelocity:");
    let dc_set = line_of(&base, "DriveControl0", "configuration.active_config:");

    let cases: Vec<(String, usize, &str, &str)> = vec![
        (
            with_line(&base, lpp_dmin, "conf.default.dmin: -0.5"),
            lpp_dmin,
            "LocalPathPlanning0",
            "configuration parameter `dmin`: -0.5 is out of range [0, ∞)",
        ),
        (
            with_line(&base, dc_vel, "conf.default.MaxVelocity: fast"),
            dc_vel,
            "DriveControl0",
            "configuration parameter `MaxVelocity`: `fast` is not a valid double",
        ),
        (
            with_line(&base, dc_vel, "conf.default.MaxSpeed: 0.3"),
            dc_vel,
            "DriveControl0",
            "unknown configuration parameter `conf.default.MaxSpeed`",
        ),
        (
            with_line(&base, dc_vel, "conf.default.MaxVelocity 0.3"),
            dc_vel,
            "DriveControl0",
            "cannot read `conf.default.MaxVelocity 0.3`: expected `key: value`",
        ),
        (
            with_line(&base, dc_set, "configuration.active_config: fast"),
            dc_set,
            "DriveControl0",
            "unknown configuration set `fast`",
        ),
    ];
    for (text, line, component, problem) in &cases {
        let e = s.apply(&load_conf(text)).unwrap_err();
        assert_eq!(
            e.to_string(),
            format!("configuration file line {line}, component `{component}`: {problem}")
        );
        match e {
            Error::ConfBundle(ConfBundleError::ConfBlock {
                component: c,
                line: l,
                ..
            }) => assert_eq!((c.as_str(), l), (*component, *line)),
            other => panic!("{other:?}"),
        }
        assert_eq!(
            s.wiring().to_conf(),
            good,
            "changed by a bad file: {problem}"
        );
    }

    // Markers and text outside blocks.
    let e = s
        .apply(&load_conf(&with_line(&base, dc_marker, "# [Planner0]")))
        .unwrap_err();
    assert_eq!(
        e,
        Error::ConfBundle(ConfBundleError::ConfUnknownComponent {
            line: dc_marker,
            name: "Planner0".to_owned(),
            expected: "PhysicsSim0, MotorControl0, Localization0, GlobalPathPlanning0, \
                       LocalPathPlanning0, DriveControl0"
                .to_owned(),
        })
    );
    assert!(
        e.to_string().starts_with(&format!(
            "configuration file line {dc_marker}: marker `# [Planner0]`"
        )),
        "{e}"
    );
    let e = s
        .apply(&load_conf(&with_line(&base, dc_marker, "# [MapBuilder0]")))
        .unwrap_err();
    assert!(
        matches!(&e, Error::ConfBundle(ConfBundleError::ConfUnknownComponent { name, .. }) if name == "MapBuilder0"),
        "{e}"
    );
    let e = s
        .apply(&load_conf(&with_line(&base, dc_marker, "# [PhysicsSim0]")))
        .unwrap_err();
    assert_eq!(
        e,
        Error::ConfBundle(ConfBundleError::ConfDuplicateComponent {
            line: dc_marker,
            component: "PhysicsSim0".to_owned(),
            first: 3,
        })
    );
    let e = s
        .apply(&load_conf(&format!(
            "# a comment\n\nconf.default.Mass: 30\n{base}"
        )))
        .unwrap_err();
    assert_eq!(
        e,
        Error::ConfBundle(ConfBundleError::ConfOutsideBlock {
            line: 3,
            text: "conf.default.Mass: 30".to_owned(),
        })
    );
    assert_eq!(s.wiring().to_conf(), good);
    // And the base itself is fine.
    s.apply(&load_conf(&base)).unwrap();
    assert_eq!(
        s.wiring()
            .config(ComponentKind::PhysicsSim)
            .unwrap()
            .value("Mass")
            .unwrap(),
        50.0
    );
}

// ---------------------------------------------------------------- the cell inspector

/// 24 × 16 cells of 0.1 m: a wall up from the bottom at x = 9..10 (y ≤ 6), a closed room in
/// the upper right corner (walls x = 17, y = 9; inside x ≥ 18, y ≥ 10).
fn inspector_map() -> GridMap {
    let (w, h) = (24usize, 16usize);
    let mut cells = vec![0u8; w * h];
    let mut set = |x: usize, y: usize| cells[x + y * w] = 1;
    for y in 0..=6 {
        set(9, y);
        set(10, y);
    }
    for y in 9..h {
        set(17, y);
    }
    for x in 17..w {
        set(x, 9);
    }
    GridMap::new(w, h, 0.1, (0.0, 0.0), cells).unwrap()
}

const DMIN: f64 = 0.25;

fn inspector_system() -> System {
    let mut s = System::new(Rates::default()).unwrap();
    // One `dmin` (spec §3 Decision 0.2): LocalPathPlanning's sets GlobalPathPlanning's too.
    s.apply(&param(ComponentKind::LocalPathPlanning, "dmin", DMIN))
        .unwrap();
    s.load_map(inspector_map());
    // From cell (3, 3) to cell (16, 3), over the wall.
    s.apply(&Input::SetPosition {
        start: Pose::new(0.35, 0.35, 0.0),
        goal: Pose::new(1.65, 0.35, 0.0),
        direction: Direction::Forward,
    })
    .unwrap();
    s
}

/// Activates the planning components and runs until they have planned, the robot standing
/// (what the set-up builder does).
fn plan(s: &mut System) -> bool {
    for component in ComponentKind::PLANNING {
        s.apply(&Input::Activate { component }).unwrap();
    }
    s.run_until_planned(PLAN_SECONDS).unwrap()
}

#[test]
fn inspecting_needs_a_map_and_a_cell_inside_it() {
    let s = System::new(Rates::default()).unwrap();
    assert_eq!(
        s.wiring().inspect_cell(0, 0).unwrap_err(),
        Error::System(SystemError::NoMap {
            call: "inspect_cell"
        })
    );
    let s = inspector_system();
    for (x, y) in [(24, 0), (0, 16), (-1, 5), (5, -1), (i64::MAX, i64::MIN)] {
        let e = s.wiring().inspect_cell(x, y).unwrap_err();
        assert_eq!(
            e.to_string(),
            format!("cell ({x}, {y}) is outside the map (24 × 16 cells)")
        );
    }
    // No local plan yet: the map only.
    let c = s.wiring().inspect_cell(23, 15).unwrap();
    assert_eq!(c.field, None);
    assert_eq!((c.occupancy, c.obstacle_distance), (0, 0.1));
    assert!(c.impassable);
}

#[test]
fn a_cell_shows_the_map_and_the_potential_field_parts() {
    let mut s = inspector_system();
    s.set_full_field(true);
    let planned = plan(&mut s);
    assert!(planned, "{:?}", s.record().events());
    let w = s.wiring();
    let field = w.local_path_planning().potential_field().unwrap();

    // An obstacle cell.
    let c = w.inspect_cell(9, 2).unwrap();
    assert_eq!((c.x, c.y, c.occupancy), (9, 2, 1));
    assert_eq!(c.obstacle_distance, 0.0);
    assert!(c.impassable);
    let f = c.field.unwrap();
    assert_eq!(f.state, "Impassable");
    assert!(!f.unreached);
    assert_eq!(
        (f.potential, f.repulsion, f.attraction, f.posture),
        (None, None, None, None)
    );

    // Two cells from the wall: 0.2 m ≤ dmin, impassable although free.
    let c = w.inspect_cell(7, 2).unwrap();
    assert_eq!(c.occupancy, 0);
    assert!((c.obstacle_distance - 0.2).abs() < 1e-12);
    assert!(c.impassable);
    assert_eq!(c.field.unwrap().state, "Impassable");

    // Three cells from the wall: 0.3 m, reached; R = 1 / (0.3 − 0.25)² = 400.
    let cell = (6usize, 2usize);
    let c = w.inspect_cell(6, 2).unwrap();
    assert!((c.obstacle_distance - 0.3).abs() < 1e-12);
    assert!(!c.impassable);
    let f = c.field.clone().unwrap();
    assert_eq!(f.state, "Reached");
    assert!(!f.unreached);
    let (g, r, a, p) = (
        f.potential.unwrap(),
        f.repulsion.unwrap(),
        f.attraction.unwrap(),
        f.posture.unwrap(),
    );
    assert_eq!(g, field.potential(cell));
    assert!((r - 400.0).abs() < 1e-6, "{r}");
    let info = field.info(cell).unwrap();
    // A = L · (100 − 85) / 100.
    assert_eq!(a, info.length * ((100.0 - 85.0) / 100.0));
    // G = G(parent) + R + A + P, as the field adds them.
    let parent = field.parent(cell).unwrap();
    assert_eq!(g, field.potential(parent) + r + a + p);
    assert!(p >= 0.0);
    // The inspector names the parent and its potential, and the cell's centre in metres.
    let shown = f.parent.clone().unwrap();
    assert_eq!(
        (shown.x, shown.y, shown.potential),
        (parent.0 as i64, parent.1 as i64, field.potential(parent))
    );
    assert_eq!(g, shown.potential + r + a + p);
    assert_eq!(f.length, Some(info.length));
    let m = w.map().unwrap();
    assert_eq!(c.centre, [m.cell_center(cell).0, m.cell_center(cell).1]);

    // The local target: G = 0.1, no parts.
    let target = field.request().unwrap().target;
    let c = w.inspect_cell(target.0 as i64, target.1 as i64).unwrap();
    let f = c.field.unwrap();
    assert_eq!(f.potential, Some(0.1));
    assert_eq!(
        (f.repulsion, f.attraction, f.posture),
        (Some(0.0), Some(0.0), Some(0.0))
    );
    assert_eq!(
        (f.parent, f.length),
        (None, Some(0.0)),
        "the target has no parent"
    );

    // Inside the closed room: passable, never reached.
    let c = w.inspect_cell(20, 12).unwrap();
    assert!((c.obstacle_distance - 0.3).abs() < 1e-12);
    assert!(!c.impassable);
    let f = c.field.unwrap();
    assert_eq!(f.state, "Unreached");
    assert!(f.unreached);
    assert_eq!(f.potential, None);

    // The JSON of the contract.
    let json = serde_json::to_value(w.inspect_cell(6, 2).unwrap()).unwrap();
    let keys = |v: &serde_json::Value| -> BTreeSet<String> {
        v.as_object().unwrap().keys().cloned().collect()
    };
    let names = |n: &[&str]| -> BTreeSet<String> { n.iter().map(|s| (*s).to_owned()).collect() };
    assert_eq!(
        keys(&json),
        names(&[
            "x",
            "y",
            "centre",
            "occupancy",
            "obstacle_distance",
            "impassable",
            "field"
        ])
    );
    assert_eq!(
        keys(&json["field"]),
        names(&[
            "potential",
            "repulsion",
            "attraction",
            "posture",
            "parent",
            "length",
            "state",
            "unreached"
        ])
    );
    assert_eq!(json["field"]["state"], "Reached");
    let unreached = serde_json::to_value(w.inspect_cell(20, 12).unwrap()).unwrap();
    assert!(unreached["field"]["potential"].is_null());
    assert_eq!(unreached["field"]["unreached"], true);
}
