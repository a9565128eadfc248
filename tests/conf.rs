//! Configuration parameters and OpenRTM `.conf` files (spec §1 "Configuration parameters",
//! 000 §4, 002 §4.2). Every test runs natively and as wasm32 under Node.

use rtnav::errors::ConfigError;
use rtnav::rtc::{
    Component, ConfFile, ConfigAccess, Configuration, ExecutionContext, ParamKind, ParamSpec,
    ParameterSet, Reflection, ReturnCode, Tick,
};

/// 000 §4.2 (表4.2-1): LocalPathPlanning's six parameters, all reflected "always".
mod lpp {
    rtnav::define_parameters! {
        /// LocalPathPlanning's configuration, as the test knows it from 000 §4.2.
        pub struct LppParams {
            /// Path distance from the current position to the local target.
            route_remake_distance: f64 = ("RouteRemakeDistance", "m", 10.0, 0.0, f64::INFINITY, Always, "局所経路を生成する際の現在位置から目標位置までの経路上の距離"),
            /// Deviation that triggers a replan.
            deviatinglen: f64 = ("Deviatinglen", "m", 0.1, 0.0, f64::INFINITY, Always, "経路逸脱限界距離"),
            /// Closest allowed approach to an obstacle.
            dmin: f64 = ("dmin", "m", 0.5, 0.0, f64::INFINITY, Always, "障害物に近づくことができる距離"),
            /// Weight of start/goal posture.
            posture_consideration_level: f64 = ("PostureConsiderationLevel", "%", 85.0, 0.0, 100.0, Always, "スタート姿勢・ゴール姿勢の考慮レベル"),
            /// Within this distance of the goal posture is ignored.
            not_posture_distance: f64 = ("NotPostureDistance", "m", 1.0, 0.0, f64::INFINITY, Always, "姿勢を考慮せずに経路生成を行う目標位置からの距離"),
            /// Near the goal, forward/backward is chosen.
            target_area: f64 = ("TargetArea", "m", 0.5, 0.0, f64::INFINITY, Always, "目標位置付近において前進、後進を変更しつつ目標位置に近づく経路生成を行う範囲"),
        }
    }
}
use lpp::LppParams;

/// A test parameter set: one parameter per kind and reflection timing (as 002 §4.2 mixes).
mod tuned {
    rtnav::define_parameters! {
        /// The parameters of the test component `Tuned0`.
        pub struct TunedParams {
            /// A gain, reflected at once.
            gain: f64 = ("Gain", "-", 5.0, 0.0, 100.0, Always, "a gain", seed: "ゲイン"),
            /// A wheel radius, reflected on activation.
            radius: f64 = ("radiusOfWheel", "m", 0.1, 0.001, f64::INFINITY, OnActivation, "wheel radius"),
            /// A wheel id, reflected on activation.
            wheel_id: i32 = ("wheelID", "-", 0.0, 0.0, 7.0, OnActivation, "wheel id"),
        }
    }
}
use tuned::TunedParams;

const FIXTURE: &str = include_str!("../fixtures/conf/LocalPathPlanning.conf");

fn lpp(
    route_remake_distance: f64,
    deviatinglen: f64,
    dmin: f64,
    posture_consideration_level: f64,
    not_posture_distance: f64,
    target_area: f64,
) -> LppParams {
    LppParams {
        route_remake_distance,
        deviatinglen,
        dmin,
        posture_consideration_level,
        not_posture_distance,
        target_area,
    }
}

fn tuned(gain: f64, radius: f64, wheel_id: i32) -> TunedParams {
    TunedParams {
        gain,
        radius,
        wheel_id,
    }
}

fn loaded(text: &str) -> Configuration<LppParams> {
    let mut c = Configuration::new();
    c.load_conf(&ConfFile::parse(text).unwrap()).unwrap();
    c
}

// ---------------------------------------------------------------------------------------------
// Declaration and single values.

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn define_parameters_declares_the_seed_table() {
    assert_eq!(
        TunedParams::SPECS,
        &[
            ParamSpec {
                name: "Gain",
                kind: ParamKind::Double,
                unit: "-",
                default: 5.0,
                min: 0.0,
                max: 100.0,
                reflection: Reflection::Always,
                description: "a gain",
                seed_text: Some("ゲイン"),
            },
            ParamSpec {
                name: "radiusOfWheel",
                kind: ParamKind::Double,
                unit: "m",
                default: 0.1,
                min: 0.001,
                max: f64::INFINITY,
                reflection: Reflection::OnActivation,
                description: "wheel radius",
                seed_text: None,
            },
            ParamSpec {
                name: "wheelID",
                kind: ParamKind::Int,
                unit: "-",
                default: 0.0,
                min: 0.0,
                max: 7.0,
                reflection: Reflection::OnActivation,
                description: "wheel id",
                seed_text: None,
            },
        ]
    );
    assert_eq!(TunedParams::defaults(), tuned(5.0, 0.1, 0));
    assert_eq!(TunedParams::default(), tuned(5.0, 0.1, 0));
    let ranges: Vec<String> = TunedParams::SPECS
        .iter()
        .map(ParamSpec::range_text)
        .collect();
    assert_eq!(ranges, ["[0, 100]", "[0.001, ∞)", "[0, 7]"]);
    let names: Vec<&str> = LppParams::SPECS.iter().map(|s| s.name).collect();
    assert_eq!(
        names,
        [
            "RouteRemakeDistance",
            "Deviatinglen",
            "dmin",
            "PostureConsiderationLevel",
            "NotPostureDistance",
            "TargetArea"
        ]
    );
    assert_eq!(LppParams::defaults(), lpp(10.0, 0.1, 0.5, 85.0, 1.0, 0.5));
}

/// A request to a configuration, by value or by text.
#[derive(Debug, Clone, Copy)]
enum Set {
    Value(&'static str, f64),
    Text(&'static str, &'static str),
}

/// Applies `request` to a configuration that already holds non-default values and compares
/// with `expect`: the requested and effective values after, or the exact error (and then
/// nothing changed).
fn check_set(request: Set, expect: Result<(TunedParams, TunedParams), ConfigError>) {
    let mut c: Configuration<TunedParams> = Configuration::new();
    c.set("Gain", 6.0).unwrap();
    c.set("wheelID", 1.0).unwrap();
    let before = c.clone();
    let got = match request {
        Set::Value(name, v) => c.set(name, v),
        Set::Text(name, t) => c.set_text(name, t),
    };
    match expect {
        Ok((requested, effective)) => {
            assert_eq!(got, Ok(()), "{request:?}");
            assert_eq!(
                (*c.requested(), *c.params()),
                (requested, effective),
                "{request:?}"
            );
        }
        Err(e) => {
            assert_eq!(got, Err(e), "{request:?}");
            assert_eq!(c, before, "{request:?} changed the configuration");
        }
    }
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn values_are_checked_and_refused_values_change_nothing() {
    use Set::{Text, Value};
    let out_of_range = |name: &str, value: &str, range: &str| {
        Err(ConfigError::OutOfRange {
            name: name.to_owned(),
            value: value.to_owned(),
            range: range.to_owned(),
            line: None,
        })
    };
    let bad = |name: &str, value: &str, kind| {
        Err(ConfigError::BadValue {
            name: name.to_owned(),
            value: value.to_owned(),
            kind,
            line: None,
        })
    };
    let unknown = Err(ConfigError::UnknownParameter {
        name: "Nope".to_owned(),
        line: None,
    });
    #[rustfmt::skip]
    let rows = [
        // `always` takes effect at once; `on_activation` waits (wheelID 1 is already pending).
        (Value("Gain", 100.0), Ok((tuned(100.0, 0.1, 1), tuned(100.0, 0.1, 0)))),
        (Value("Gain", 0.0), Ok((tuned(0.0, 0.1, 1), tuned(0.0, 0.1, 0)))),
        (Text("Gain", " 12.5 "), Ok((tuned(12.5, 0.1, 1), tuned(12.5, 0.1, 0)))),
        (Value("radiusOfWheel", 0.25), Ok((tuned(6.0, 0.25, 1), tuned(6.0, 0.1, 0)))),
        (Value("wheelID", 7.0), Ok((tuned(6.0, 0.1, 7), tuned(6.0, 0.1, 0)))),
        (Text("wheelID", "0"), Ok((tuned(6.0, 0.1, 0), tuned(6.0, 0.1, 0)))),
        // refused, the old value stays
        (Value("Gain", 100.5), out_of_range("Gain", "100.5", "[0, 100]")),
        (Value("Gain", -0.1), out_of_range("Gain", "-0.1", "[0, 100]")),
        (Value("Gain", f64::NAN), out_of_range("Gain", "NaN", "[0, 100]")),
        (Value("radiusOfWheel", 0.0), out_of_range("radiusOfWheel", "0", "[0.001, ∞)")),
        (Value("radiusOfWheel", f64::INFINITY), out_of_range("radiusOfWheel", "inf", "[0.001, ∞)")),
        (Text("radiusOfWheel", "inf"), out_of_range("radiusOfWheel", "inf", "[0.001, ∞)")),
        (Value("wheelID", 8.0), out_of_range("wheelID", "8", "[0, 7]")),
        (Value("wheelID", 2.5), bad("wheelID", "2.5", "int")),
        (Text("wheelID", "3.0"), bad("wheelID", "3.0", "int")),
        (Text("Gain", "abc"), bad("Gain", "abc", "double")),
        (Text("Gain", ""), bad("Gain", "", "double")),
        (Value("Nope", 1.0), unknown),
    ];
    for (request, expect) in rows {
        check_set(request, expect);
    }
}

// ---------------------------------------------------------------------------------------------
// Reflection timing through the execution context.

/// A component with [`TunedParams`] that records the values it sees.
struct Tuned {
    config: Configuration<TunedParams>,
    seen: Vec<(&'static str, TunedParams)>,
}

impl Component for Tuned {
    fn instance_name(&self) -> &str {
        "Tuned0"
    }
    fn configuration(&mut self) -> Option<&mut dyn ConfigAccess> {
        Some(&mut self.config)
    }
    fn on_activated(&mut self, _tick: &Tick) -> ReturnCode {
        self.seen.push(("on_activated", *self.config.params()));
        Ok(())
    }
    fn on_execute(&mut self, _tick: &Tick) -> ReturnCode {
        self.seen.push(("on_execute", *self.config.params()));
        Ok(())
    }
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn always_at_once_on_activation_when_activated() {
    let mut ec = ExecutionContext::new(100.0).unwrap();
    let id = ec
        .attach(
            Box::new(Tuned {
                config: Configuration::new(),
                seen: Vec::new(),
            }),
            100.0,
        )
        .unwrap();
    ec.start().unwrap();
    ec.activate(id).unwrap();
    ec.tick();
    // what a GUI does: reach the configuration through the trait object
    let set = |ec: &mut ExecutionContext, name: &str, v: f64| {
        let c = ec.component_dyn_mut(id).unwrap().configuration().unwrap();
        c.set(name, v).unwrap();
    };
    set(&mut ec, "Gain", 7.0);
    set(&mut ec, "radiusOfWheel", 0.2);
    set(&mut ec, "wheelID", 3.0);
    let c = ec.component_dyn_mut(id).unwrap().configuration().unwrap();
    let view = |c: &dyn ConfigAccess, name| {
        (
            c.value(name).unwrap(),
            c.effective_value(name).unwrap(),
            c.is_pending(name).unwrap(),
        )
    };
    assert_eq!(view(c, "Gain"), (7.0, 7.0, false));
    assert_eq!(view(c, "radiusOfWheel"), (0.2, 0.1, true));
    assert_eq!(view(c, "wheelID"), (3.0, 0.0, true));
    ec.tick();
    ec.deactivate(id).unwrap();
    ec.tick();
    // still pending while Inactive
    let c = ec.component_dyn_mut(id).unwrap().configuration().unwrap();
    assert_eq!(view(c, "wheelID"), (3.0, 0.0, true));
    ec.activate(id).unwrap();
    let c = ec.component_dyn_mut(id).unwrap().configuration().unwrap();
    assert_eq!(view(c, "radiusOfWheel"), (0.2, 0.2, false));
    assert_eq!(view(c, "wheelID"), (3.0, 3.0, false));
    ec.tick();
    // locked until the next activation
    set(&mut ec, "wheelID", 5.0);
    ec.tick();
    assert_eq!(
        ec.component::<Tuned>(id).unwrap().seen,
        [
            ("on_activated", tuned(5.0, 0.1, 0)),
            ("on_execute", tuned(5.0, 0.1, 0)),
            ("on_execute", tuned(7.0, 0.1, 0)),
            ("on_activated", tuned(7.0, 0.2, 3)),
            ("on_execute", tuned(7.0, 0.2, 3)),
            ("on_execute", tuned(7.0, 0.2, 3)),
        ]
    );
}

// ---------------------------------------------------------------------------------------------
// Configuration sets.

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn configuration_sets_switch_atomically() {
    let mut c = loaded(FIXTURE);
    let mode1 = lpp(4.0, 0.1, 0.25, 50.0, 1.0, 0.5);
    let default = LppParams::defaults();
    assert_eq!(c.set_names(), ["default", "mode1"]);
    assert_eq!((c.active_set(), *c.params()), ("mode1", mode1));
    assert_eq!(c.set_values("default"), Some(&default));
    assert_eq!(c.set_values("mode1"), Some(&mode1));
    c.activate_set("default").unwrap();
    assert_eq!(
        (c.active_set(), *c.params(), *c.requested()),
        ("default", default, default)
    );
    c.activate_set("mode1").unwrap();
    assert_eq!((c.active_set(), *c.params()), ("mode1", mode1));
    // setting a value changes the active set only
    c.set("TargetArea", 0.75).unwrap();
    let mode1b = lpp(4.0, 0.1, 0.25, 50.0, 1.0, 0.75);
    assert_eq!(c.set_values("mode1"), Some(&mode1b));
    assert_eq!(c.set_values("default"), Some(&default));
    // an unknown set is refused and nothing changes
    let before = c.clone();
    assert_eq!(
        c.activate_set("mode2"),
        Err(ConfigError::UnknownSet {
            name: "mode2".to_owned()
        })
    );
    assert_eq!(c, before);
    assert_eq!(c.set_values("mode2"), None);

    // on_activation parameters of a newly active set wait for the next activation
    let mut t: Configuration<TunedParams> = Configuration::new();
    t.load_conf(&ConfFile::parse("conf.fast.Gain: 50\nconf.fast.wheelID: 2\n").unwrap())
        .unwrap();
    assert_eq!(t.active_set(), "default");
    t.activate_set("fast").unwrap();
    assert_eq!(
        (*t.requested(), *t.params()),
        (tuned(50.0, 0.1, 2), tuned(50.0, 0.1, 0))
    );
    t.apply_on_activation();
    assert_eq!(*t.params(), tuned(50.0, 0.1, 2));
    t.activate_set("default").unwrap();
    assert_eq!(
        (*t.requested(), *t.params()),
        (tuned(5.0, 0.1, 0), tuned(5.0, 0.1, 2))
    );

    // a file that names an existing set updates only what it names
    let mut c = loaded(FIXTURE);
    c.load_conf(
        &ConfFile::parse("conf.mode1.Deviatinglen: 0.2\nconf.default.dmin: 0.6\n").unwrap(),
    )
    .unwrap();
    assert_eq!(
        c.set_values("mode1"),
        Some(&lpp(4.0, 0.2, 0.25, 50.0, 1.0, 0.5))
    );
    assert_eq!(
        c.set_values("default"),
        Some(&lpp(10.0, 0.1, 0.6, 85.0, 1.0, 0.5))
    );
    assert_eq!(c.active_set(), "mode1");
    assert_eq!(*c.params(), lpp(4.0, 0.2, 0.25, 50.0, 1.0, 0.5));
}

// ---------------------------------------------------------------------------------------------
// `.conf` files.

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn the_fixture_parses_line_by_line() {
    let conf = ConfFile::parse(FIXTURE).unwrap();
    let entries: Vec<String> = conf
        .entries
        .iter()
        .map(|e| format!("{} {} = {}", e.line, e.key, e.value))
        .collect();
    assert_eq!(
        entries,
        [
            "18 exec_cxt.periodic.rate = 10.0",
            "21 configuration.active_config = mode1",
            "24 conf.default.RouteRemakeDistance = 10.0",
            "25 conf.default.Deviatinglen = 0.1",
            "26 conf.default.dmin = 0.5",
            "27 conf.default.PostureConsiderationLevel = 85.0",
            "28 conf.default.NotPostureDistance = 1.0",
            "29 conf.default.TargetArea = 0.5",
            "33 conf.mode1.RouteRemakeDistance = 4.0",
            "34 conf.mode1.dmin = 0.25",
            "35 conf.mode1.PostureConsiderationLevel = 50",
            "38 conf.__widget__.RouteRemakeDistance = text",
            "39 conf.__widget__.Deviatinglen = text",
            "40 conf.__widget__.dmin = text",
            "41 conf.__widget__.PostureConsiderationLevel = slider.0.1",
            "42 conf.__widget__.NotPostureDistance = text",
            "43 conf.__widget__.TargetArea = text",
            "46 conf.__constraints__.PostureConsiderationLevel = 0.0<=x<=100.0",
            "47 conf.__type__.dmin = double",
        ]
    );
}

/// Loads the fixture with line `from` replaced by `to` into a configuration that already
/// holds the fixture plus a change, and compares with `expect`; nothing may change.
fn check_conf_error(from: &str, to: &str, expect: ConfigError) {
    let text = FIXTURE.replacen(from, to, 1);
    assert_ne!(text, FIXTURE, "`{from}` is not in the fixture");
    let mut c = loaded(FIXTURE);
    c.set("Deviatinglen", 0.3).unwrap();
    let before = c.clone();
    let got = ConfFile::parse(&text).and_then(|conf| c.load_conf(&conf));
    assert_eq!(got, Err(expect), "`{to}`");
    assert_eq!(c, before, "`{to}` changed the configuration");
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn conf_errors_name_the_key_and_the_line_and_change_nothing() {
    let unknown = |name: &str, line| ConfigError::UnknownParameter {
        name: name.to_owned(),
        line: Some(line),
    };
    let rows = [
        // a bad value
        (
            "conf.mode1.dmin = 0.25",
            "conf.mode1.dmin = 0.25m",
            ConfigError::BadValue {
                name: "dmin".to_owned(),
                value: "0.25m".to_owned(),
                kind: "double",
                line: Some(34),
            },
        ),
        // an out-of-range value
        (
            "conf.mode1.PostureConsiderationLevel: 50",
            "conf.mode1.PostureConsiderationLevel: 150",
            ConfigError::OutOfRange {
                name: "PostureConsiderationLevel".to_owned(),
                value: "150".to_owned(),
                range: "[0, 100]".to_owned(),
                line: Some(35),
            },
        ),
        // unknown keys: a misspelt parameter, widget or metadata, and a key outside `conf.`
        (
            "conf.default.Deviatinglen: 0.1",
            "conf.default.DeviatingLen: 0.1",
            unknown("conf.default.DeviatingLen", 25),
        ),
        (
            "conf.__widget__.TargetArea: text",
            "conf.__widget__.TargetAria: text",
            unknown("conf.__widget__.TargetAria", 43),
        ),
        (
            "conf.__type__.dmin: double",
            "conf.__type__.dmax: double",
            unknown("conf.__type__.dmax", 47),
        ),
        (
            "conf.default.dmin: 0.5",
            "config.default.dmin: 0.5",
            unknown("config.default.dmin", 26),
        ),
        (
            "conf.default.TargetArea: 0.5",
            "conf.default.Target.Area: 0.5",
            unknown("conf.default.Target.Area", 29),
        ),
        // not `key: value`
        (
            "conf.default.TargetArea: 0.5",
            ": 0.5",
            ConfigError::Syntax {
                line: 29,
                text: ": 0.5".to_owned(),
                reason: "empty key".to_owned(),
            },
        ),
        (
            "conf.default.TargetArea: 0.5",
            "conf.default.TargetArea 0.5",
            ConfigError::Syntax {
                line: 29,
                text: "conf.default.TargetArea 0.5".to_owned(),
                reason: "expected `key: value`".to_owned(),
            },
        ),
        // an active set the file does not define
        (
            "configuration.active_config: mode1",
            "configuration.active_config: mode2",
            ConfigError::UnknownSet {
                name: "mode2".to_owned(),
            },
        ),
    ];
    for (from, to, expect) in rows {
        check_conf_error(from, to, expect);
    }
    // the messages a GUI shows
    assert_eq!(
        ConfigError::BadValue {
            name: "dmin".to_owned(),
            value: "0.25m".to_owned(),
            kind: "double",
            line: Some(34),
        }
        .to_string(),
        "configuration parameter `dmin` (line 34): `0.25m` is not a valid double"
    );
    assert_eq!(
        unknown("conf.default.DeviatingLen", 25).to_string(),
        "unknown configuration parameter `conf.default.DeviatingLen` (line 25)"
    );
}

const WRITTEN: &str = "\
# -*- Property -*-
# Written by rtnav (OpenRTM .conf syntax).
configuration.active_config: mode1

conf.default.RouteRemakeDistance: 10.0
conf.default.Deviatinglen: 0.1
conf.default.dmin: 0.5
conf.default.PostureConsiderationLevel: 85.0
conf.default.NotPostureDistance: 1.0
conf.default.TargetArea: 0.5

conf.mode1.RouteRemakeDistance: 4.0
conf.mode1.Deviatinglen: 0.1
conf.mode1.dmin: 0.25
conf.mode1.PostureConsiderationLevel: 50.0
conf.mode1.NotPostureDistance: 1.0
conf.mode1.TargetArea: 0.5

conf.__widget__.RouteRemakeDistance: text
conf.__widget__.Deviatinglen: text
conf.__widget__.dmin: text
conf.__widget__.PostureConsiderationLevel: slider.0.1
conf.__widget__.NotPostureDistance: text
conf.__widget__.TargetArea: text
";

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn to_conf_then_parse_gives_the_same_configuration() {
    let c = loaded(FIXTURE);
    assert_eq!(c.to_conf(), WRITTEN);
    let again = loaded(&c.to_conf());
    assert_eq!(again, c);

    // values that need every digit, an int parameter and a pending on_activation value
    let mut t: Configuration<TunedParams> = Configuration::new();
    t.set("Gain", 0.1 + 0.2).unwrap();
    t.set("radiusOfWheel", 1.0 / 3.0).unwrap();
    t.set("wheelID", 6.0).unwrap();
    let text = t.to_conf();
    assert_eq!(
        text,
        "# -*- Property -*-\n# Written by rtnav (OpenRTM .conf syntax).\n\
         configuration.active_config: default\n\n\
         conf.default.Gain: 0.30000000000000004\n\
         conf.default.radiusOfWheel: 0.3333333333333333\n\
         conf.default.wheelID: 6\n"
    );
    let mut back: Configuration<TunedParams> = Configuration::new();
    back.load_conf(&ConfFile::parse(&text).unwrap()).unwrap();
    assert_eq!(back, t);
    assert_eq!(back.requested().gain.to_bits(), (0.1f64 + 0.2).to_bits());
}
