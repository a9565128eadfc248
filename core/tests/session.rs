//! The interactive session (what the page drives): share links reproduce the set-up and the
//! first frame, a changed planning parameter is planned at once, a NaN pose puts
//! Localization in Error and Reset recovers, the plot window.

use rtnav::interfaces::{Direction, Pose};
use rtnav::render::{Layers, Renderer, caption};
use rtnav::rtc::LifecycleState;
use rtnav::system::{ComponentKind, EventKind, Input, Session, Telemetry};

mod common;
use common::loaded;

/// What the page draws: every layer, the page's caption.
fn frame(session: &Session) -> Vec<u8> {
    let system = session.system();
    Renderer::new(640, 400)
        .unwrap()
        .render_system(system, &caption(system), Layers::ALL)
        .unwrap()
        .data()
        .to_vec()
}

/// A parameter's (requested, effective, pending) as the parameter panel shows it.
fn value(session: &Session, component: &str, name: &str) -> (f64, f64, bool) {
    let view = session.parameters_view();
    let p = view
        .iter()
        .find(|c| c.component == component)
        .unwrap()
        .params
        .iter()
        .find(|p| p.name == name)
        .unwrap();
    (p.value, p.effective, p.pending)
}

#[test]
fn a_share_token_reproduces_the_set_up_and_the_first_frame() {
    let mut a = loaded("open_field");
    // Time passes, cells are painted, parameters change, the goal moves.
    a.advance(100.0);
    let painted = vec![(12, 6, 1), (12, 7, 1), (13, 6, 1)];
    a.apply(&Input::MapUpdate { cells: painted }).unwrap();
    assert!(
        a.new_events()
            .iter()
            .any(|e| matches!(e.kind, EventKind::MapUpdated { changed: 3, .. }))
    );
    a.set_param_text(
        ComponentKind::LocalPathPlanning,
        "PostureConsiderationLevel",
        "20",
    )
    .unwrap();
    a.set_param_text(ComponentKind::MotorControl, "lengthOfAxle", "0.5")
        .unwrap();
    a.apply(&Input::SetGoal {
        goal: Pose::new(22.0, 14.0, 0.5),
        direction: Direction::Forward,
    })
    .unwrap();
    a.advance(100.0);
    let token = a.share_token().unwrap();
    assert!(
        token
            .bytes()
            .all(|b| b.is_ascii_alphanumeric() || b == b'-' || b == b'_')
    );
    let setup = a.setup().unwrap();
    assert_eq!(setup.edits, vec![(12, 6, 1), (12, 7, 1), (13, 6, 1)]);
    assert_eq!(
        setup.params["LocalPathPlanning"]["PostureConsiderationLevel"],
        20.0
    );
    assert_eq!(setup.params["MotorControl"]["lengthOfAxle"], 0.5);
    assert_eq!(setup.params.len(), 2, "only what differs from the scenario");

    assert_eq!(Session::share_scenario(&token).unwrap(), "open_field");
    let mut b = loaded("open_field");
    b.apply_share(&token).unwrap();
    assert_eq!(b.setup().unwrap(), setup);
    assert_eq!(b.parameters_view(), a.parameters_view());
    assert_eq!(b.system().time_ns(), a.system().time_ns());
    assert!(frame(&b) == frame(&a), "identical first frame");
    assert!(b.system().map().unwrap().is_obstacle(12, 6));
}

#[test]
fn a_bad_or_foreign_token_is_refused_and_nothing_changes() {
    let mut a = loaded("corridor_turn");
    let token = a.share_token().unwrap();
    let mut b = loaded("open_field");
    let before = b.setup().unwrap();
    let err = b.apply_share(&token).unwrap_err().to_string();
    assert_eq!(
        err,
        "share link: it was made for scenario `corridor_turn`, but `open_field` is loaded"
    );
    for junk in ["", "!!!", "AAAA", &token[..token.len() / 2]] {
        let e = b.apply_share(junk).unwrap_err().to_string();
        assert!(e.starts_with("share link: "), "{e}");
    }
    assert_eq!(b.setup().unwrap(), before);
}

#[test]
fn a_link_needs_a_scenario() {
    let mut s = Session::new().unwrap();
    let map = rtnav::map::GridMap::new(10, 10, 0.1, (0.0, 0.0), vec![0; 100]).unwrap();
    s.load_map("free.json", map).unwrap();
    assert_eq!(
        s.share_token().unwrap_err().to_string(),
        "share link: a share link needs a scenario; this map was loaded from a file"
    );
}

#[test]
fn posture_consideration_changes_the_next_plan_at_once() {
    let mut s = loaded("parking_wall");
    let mut merged_path_with = |level: &str| {
        s.set_param_text(
            ComponentKind::LocalPathPlanning,
            "PostureConsiderationLevel",
            level,
        )
        .unwrap();
        let lpp = s.system().wiring().local_path_planning();
        lpp.merged_path().to_vec()
    };
    let low = merged_path_with("0");
    let high = merged_path_with("100");
    assert_eq!(
        value(&s, "LocalPathPlanning", "PostureConsiderationLevel"),
        (100.0, 100.0, false)
    );
    assert!(!low.is_empty() && !high.is_empty());
    assert_ne!(low, high);
    // Out of range: refused with the reason, the value stays.
    let e = s
        .set_param_text(
            ComponentKind::LocalPathPlanning,
            "PostureConsiderationLevel",
            "101",
        )
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("PostureConsiderationLevel") && e.contains("[0, 100]"),
        "{e}"
    );
    assert_eq!(
        value(&s, "LocalPathPlanning", "PostureConsiderationLevel").0,
        100.0
    );
}

#[test]
fn an_on_activation_parameter_waits_for_the_next_activation() {
    let mut s = loaded("open_field");
    let pending: Vec<&str> = s
        .parameters_view()
        .iter()
        .flat_map(|c| c.params.iter().filter(|p| p.pending).map(|p| p.name))
        .collect();
    assert!(
        pending.is_empty(),
        "nothing waits after a load: {pending:?}"
    );
    s.apply(&Input::ActivateAll).unwrap();
    s.advance(50.0);
    s.set_param_text(ComponentKind::MotorControl, "lengthOfAxle", "0.5")
        .unwrap();
    assert_eq!(
        value(&s, "MotorControl", "lengthOfAxle"),
        (0.5, 0.441, true)
    );
    let component = ComponentKind::MotorControl;
    s.apply(&Input::Deactivate { component }).unwrap();
    s.apply(&Input::Activate { component }).unwrap();
    assert_eq!(value(&s, "MotorControl", "lengthOfAxle"), (0.5, 0.5, false));
}

#[test]
fn a_nan_pose_puts_localization_in_error_and_reset_recovers() {
    let mut s = loaded("open_field");
    s.apply(&Input::ActivateAll).unwrap();
    s.advance(100.0);
    s.apply(&Input::InjectInput {
        component: ComponentKind::Localization,
        port: "InSimulatedPosition".to_owned(),
        data: vec![f64::NAN, 0.0, 0.0, 0.0],
    })
    .unwrap();
    s.step_ticks(1).unwrap();
    let info = s.system().component(ComponentKind::Localization);
    assert_eq!(info.state, LifecycleState::Error);
    assert_eq!(
        info.last_error.map(|r| r.to_string()).as_deref(),
        Some("InSimulatedPosition: data[0] = NaN is not finite")
    );
    let unknown = s
        .apply(&Input::InjectInput {
            component: ComponentKind::MotorControl,
            port: "Torque".to_owned(),
            data: vec![0.0],
        })
        .unwrap_err()
        .to_string();
    assert!(
        unknown.starts_with("MotorControl has no input port `Torque`"),
        "{unknown}"
    );
    let component = ComponentKind::Localization;
    s.apply(&Input::Reset { component }).unwrap();
    assert_eq!(
        s.system().component_state(component),
        LifecycleState::Inactive
    );
    s.apply(&Input::Activate { component }).unwrap();
    assert_eq!(
        s.system().component_state(component),
        LifecycleState::Active
    );
    s.advance(100.0);
    assert_eq!(
        s.system().component_state(component),
        LifecycleState::Active
    );
}

#[test]
fn the_plot_window_holds_the_last_seconds_and_the_replans() {
    let mut s = loaded("open_field");
    s.apply(&Input::ActivateAll).unwrap();
    s.set_speed(16.0).unwrap();
    for _ in 0..50 {
        s.advance(16.0);
    }
    let w = s.plot(60.0);
    let n = w.t.len();
    assert!(n > 100, "{n} samples");
    for series in [&w.rate_l, &w.torque_r, &w.v, &w.w_cmd] {
        assert_eq!(series.len(), n);
    }
    assert_eq!(w.deviation.len(), n);
    assert_eq!(w.deviatinglen, 0.1);
    let now = s.system().time();
    assert!(w.t[0] >= now - 60.0 - 1e-9 && w.t[n - 1] <= now);
    assert!(w.t.windows(2).all(|p| p[0] < p[1]));
    assert!(!w.replans.is_empty(), "the first plans are in the window");
    assert!(
        w.replans
            .iter()
            .all(|&t| t >= now - 60.0 - 1e-9 && t <= now)
    );
    let plans = s
        .new_events()
        .iter()
        .filter(|e| {
            matches!(
                e.kind,
                EventKind::GlobalPlan { .. } | EventKind::LocalPlanSent { cells: 1.., .. }
            )
        })
        .count();
    assert!(plans >= w.replans.len());
}

#[test]
fn an_exported_conf_reimported_gives_the_same_configuration() {
    let mut s = loaded("open_field");
    let original = s.parameters_view();
    let text = s.system().wiring().to_conf();
    s.set_param_text(ComponentKind::DriveControl, "MaxVelocity", "0.3")
        .unwrap();
    s.set_param_text(ComponentKind::PhysicsSim, "Mass", "35")
        .unwrap();
    assert_ne!(s.parameters_view(), original);
    let load = |text: &str| Input::LoadConf {
        text: text.to_owned(),
    };
    s.apply(&load(&text)).unwrap();
    assert_eq!(s.parameters_view(), original);
    assert_eq!(s.system().wiring().to_conf(), text);
    // A bad file is refused with its line; nothing changes.
    let bad = text.replace(
        "conf.default.MaxVelocity: 0.5",
        "conf.default.MaxVelocity: 9",
    );
    assert_ne!(bad, text, "the export names MaxVelocity as written");
    let e = s.apply(&load(&bad)).unwrap_err().to_string();
    assert!(e.contains("MaxVelocity") && e.contains("line"), "{e}");
    assert_eq!(s.parameters_view(), original);
}

/// A frame whose budget is spent before it begins (the page after a long request) runs no
/// tick; the time stays owed and runs in the next frame.
#[test]
fn a_spent_budget_runs_no_tick_and_keeps_the_time_owed() {
    let mut s = loaded("open_field");
    s.apply(&Input::ActivateAll).unwrap();
    let before = s.system().time_ns();
    assert_eq!(s.advance_while(16.0, || false), 0);
    assert_eq!(s.system().time_ns(), before);
    assert!(
        (s.behind_s() - 0.016).abs() < 1e-9,
        "{} s owed",
        s.behind_s()
    );
    assert_eq!(s.advance(0.0), 16);
    assert_eq!(s.system().time_ns(), before + 16_000_000);
    assert!(s.behind_s() < 1e-9);
}

#[test]
fn a_frame_budget_cuts_the_time_but_not_the_trace() {
    const UNTIL_S: f64 = 3.0;
    const UNTIL_NS: u64 = 3_000_000_000;
    let drive = |budget: Option<u64>| {
        let mut s = loaded("open_field");
        s.apply(&Input::ActivateAll).unwrap();
        s.set_speed(16.0).unwrap();
        let (mut frames, mut most_owed) = (0, 0.0_f64);
        while s.system().time() < UNTIL_S {
            frames += 1;
            match budget {
                None => {
                    s.advance(16.0);
                }
                Some(n) => {
                    // The page's `more()` reads the wall clock; a count of ticks stands in.
                    let mut left = n;
                    let ran = s.advance_while(16.0, || {
                        left -= 1;
                        left > 0
                    });
                    assert!(ran <= n, "{ran} ticks ran on a budget of {n}");
                    most_owed = most_owed.max(s.behind_s());
                }
            }
        }
        let samples = s.system().record().telemetry().samples();
        let hash = Telemetry::hash_of(samples.iter().filter(|x| x.time_ns <= UNTIL_NS));
        (hash, frames, most_owed)
    };
    let (free, free_frames, _) = drive(None);
    let (budgeted, budget_frames, most_owed) = drive(Some(50));
    // 16 ms at 16× is 256 ticks a frame; at 50 ticks a frame the simulation runs slower ...
    assert!(
        budget_frames > 4 * free_frames,
        "{budget_frames} frames against {free_frames}"
    );
    // ... owing at most one capped frame's time (100 ms × 16) ...
    assert!(
        most_owed > 1.0 && most_owed <= 1.6 + 1e-9,
        "{most_owed} s owed at most"
    );
    // ... and runs the same ticks.
    assert_eq!(budgeted, free, "the frame budget changed the trace");
}
