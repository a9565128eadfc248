//! The command line says the core's facts from the page's English catalogue
//! (`rtnav_cli::words`): every fact kind it can say has words there, and the facts of real
//! runs said by the command line are, word for word, what the page's `web/js/say.js` says
//! for them (run under Node by `say.mjs`; without Node that half prints one SKIPPED line).

use std::io::Write;
use std::path::Path;
use std::process::{Command, Stdio};

use rtnav::Reason;
use rtnav::interfaces::{Direction, Pose};
use rtnav::system::setup::{self, BuildOptions, Setup};
use rtnav::system::{
    ComponentActivity, ComponentKind, DirResolver, EventKind, EventView, Held, Input, InputSummary,
    ParameterWarning, RequestSource, Scenario, Status, SystemEvent, ZeroOutput,
};
use rtnav_cli::words::Words;
use serde_json::{Value, json};
use strum::VariantNames;

fn root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

fn system(name: &str) -> rtnav::system::System {
    let path = root().join(format!("fixtures/scenarios/{name}.json"));
    let s = Scenario::from_json(&std::fs::read_to_string(path).unwrap()).unwrap();
    setup::build(
        &s,
        &DirResolver::new(root()),
        &Setup::of(&s),
        BuildOptions::default(),
    )
    .unwrap()
}

/// One fact as the command line says it, and the call that makes the page say it.
struct Said {
    cli: String,
    page: Value,
}

fn data<T: serde::Serialize>(v: &T) -> Value {
    serde_json::to_value(v).unwrap()
}

/// The facts of real runs: every event, status and component activity met, the reasons they
/// carry, the requests made and the refusals met, and each parameter warning.
fn facts() -> Vec<Said> {
    let words = Words::english();
    let mut said = Vec::new();
    let look = |s: &rtnav::system::System, said: &mut Vec<Said>| {
        let status = s.status();
        let mut fields = data(&status);
        let kind = fields
            .as_object_mut()
            .and_then(|m| m.remove("kind"))
            .unwrap();
        said.push(Said {
            cli: words.status(&status),
            page: json!(["statusText", kind, fields]),
        });
        for c in s.components() {
            said.push(Said {
                cli: words.activity(&c.status),
                page: json!(["activityText", data(&c.status)]),
            });
            if let Some(r) = &c.last_error {
                said.push(Said {
                    cli: words.reason(r),
                    page: json!(["reasonText", data(r)]),
                });
            }
        }
    };
    let apply = |s: &mut rtnav::system::System, input: Input, said: &mut Vec<Said>| {
        let summary = input.summary();
        said.push(Said {
            cli: words.input(&summary),
            page: json!(["inputText", data(&summary)]),
        });
        if let Err(e) = s.apply(&input) {
            said.push(Said {
                cli: words.error(&e),
                page: json!(["errorDetail", data(&e.detail())]),
            });
        }
    };

    // A drive with a fault, a reset, a new goal, SafeMode, Clear, a cut connection, a
    // parameter out of range, a goal off the map.
    let mut s = system("open_field");
    look(&s, &mut said);
    apply(&mut s, Input::ActivateAll, &mut said);
    s.run_for(3.0).unwrap();
    look(&s, &mut said);
    let fault = Input::InjectFault {
        component: ComponentKind::DriveControl,
        reason: "test".into(),
    };
    apply(&mut s, fault, &mut said);
    s.run_for(0.5).unwrap();
    look(&s, &mut said);
    let reset = Input::Reset {
        component: ComponentKind::DriveControl,
    };
    apply(&mut s, reset, &mut said);
    look(&s, &mut said);
    apply(&mut s, Input::ResetAll, &mut said);
    apply(&mut s, Input::ActivateAll, &mut said);
    s.run_for(1.0).unwrap();
    if let Some(link) = s.wiring().links().all().iter().find(|l| l.cuttable()) {
        let id = link.id();
        apply(
            &mut s,
            Input::CutConnection {
                connection: id.clone(),
            },
            &mut said,
        );
        s.run_for(0.5).unwrap();
        look(&s, &mut said);
        apply(
            &mut s,
            Input::RestoreConnection { connection: id },
            &mut said,
        );
    }
    let param = Input::SetParam {
        component: ComponentKind::LocalPathPlanning,
        name: "dmin".into(),
        value: -1.0,
    };
    apply(&mut s, param, &mut said);
    let off_map = Input::SetGoal {
        goal: Pose::new(-500.0, 3.0, 0.0),
        direction: Direction::Forward,
    };
    apply(&mut s, off_map, &mut said);
    apply(&mut s, Input::SafeMode, &mut said);
    look(&s, &mut said);
    apply(&mut s, Input::Clear, &mut said);
    look(&s, &mut said);
    let events: Vec<SystemEvent> = s.record().events().iter().cloned().collect();

    // A route that cannot be planned.
    let mut u = system("unreachable");
    apply(&mut u, Input::ActivateAll, &mut said);
    u.run_for(2.0).unwrap();
    look(&u, &mut said);

    for e in events.iter().chain(u.record().events()) {
        let view = EventView::of(e);
        said.push(Said {
            cli: words.event(&e.kind),
            page: json!(["eventText", data(&view)]),
        });
        if let EventKind::PlanningFailed { reason, .. }
        | EventKind::ComponentError { reason, .. }
        | EventKind::RequestRefused { reason, .. } = &e.kind
        {
            said.push(Said {
                cli: words.reason(reason),
                page: json!(["reasonText", data(reason)]),
            });
        }
    }
    for w in [
        ParameterWarning::GainUnstable {
            p: 120.0,
            d: 0.01,
            bound: 20.0,
        },
        ParameterWarning::GainLimp {
            p: 3.0,
            rate_gain: 0.0015,
        },
        ParameterWarning::Clearance {
            dmin: 0.3,
            grid_size: 0.1,
            body_radius: 0.29,
        },
    ] {
        said.push(Said {
            cli: words.warning(&w),
            page: json!(["warningText", data(&w)]),
        });
    }
    // The session's paused clock, a cause said with the status.
    let paused = json!({ "direction": "Forward", "paused": true });
    said.push(Said {
        cli: words.status_text("driving", &paused),
        page: json!(["statusText", "driving", paused]),
    });
    said.push(Said {
        cli: words.reason(&Reason::ObstacleAhead { ahead: 0.42 }),
        page: json!(["reasonText", {"kind": "obstacle_ahead", "ahead": 0.42}]),
    });
    said
}

#[test]
fn every_fact_kind_the_command_line_says_has_words_in_the_english_catalogue() {
    let words = Words::english();
    let lists: [(&str, &[&str]); 9] = [
        ("event", EventKind::VARIANTS),
        ("status", Status::KINDS),
        ("rtcstatus", ComponentActivity::KINDS),
        ("held", Held::VARIANTS),
        ("reason", Reason::KINDS),
        ("warning", ParameterWarning::KINDS),
        ("input", InputSummary::VARIANTS),
        ("source", RequestSource::VARIANTS),
        ("rtcstatus.zero", ZeroOutput::VARIANTS),
    ];
    let mut wanted: Vec<String> = lists
        .iter()
        .flat_map(|(prefix, kinds)| kinds.iter().map(move |k| format!("{prefix}.{k}")))
        .collect();
    for (area, kinds) in rtnav::Error::KINDS {
        wanted.extend(kinds.iter().map(|k| format!("error.{area}.{k}")));
    }
    assert!(wanted.len() > 100, "{}", wanted.len());
    let lacking: Vec<&String> = wanted.iter().filter(|k| !words.has(k)).collect();
    assert!(lacking.is_empty(), "no words in en.json for {lacking:?}");
    // What the runs say is words, every placeholder filled: no key left as it is.
    for s in facts() {
        assert!(
            !s.cli.is_empty() && !words.has(&s.cli) && !s.cli.contains('{'),
            "{}: `{}`",
            s.page,
            s.cli
        );
    }
}

#[test]
fn the_command_line_says_each_fact_in_the_words_the_page_says_it() {
    let facts = facts();
    assert!(facts.len() > 60, "{} facts", facts.len());
    let calls = Value::Array(facts.iter().map(|s| s.page.clone()).collect());
    let script = root().join("cli/tests/say.mjs");
    let child = Command::new("node")
        .arg(&script)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn();
    let Ok(mut child) = child else {
        println!("SKIPPED: no `node` to run the page's say.js");
        return;
    };
    let mut stdin = child.stdin.take().unwrap();
    stdin.write_all(calls.to_string().as_bytes()).unwrap();
    drop(stdin);
    let out = child.wait_with_output().unwrap();
    assert!(out.status.success(), "{}", script.display());
    let page: Vec<String> = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(page.len(), facts.len());
    let differ: Vec<String> = facts
        .iter()
        .zip(&page)
        .filter(|(s, p)| &s.cli != *p)
        .map(|(s, p)| format!("{}\n  cli:  {}\n  page: {p}", s.page, s.cli))
        .collect();
    assert!(differ.is_empty(), "{}", differ.join("\n"));
    // The facts cover the kinds that carry forms and nested words.
    let kinds = |f: &str| facts.iter().filter(|s| s.page[0] == f).count();
    for f in [
        "eventText",
        "statusText",
        "activityText",
        "reasonText",
        "inputText",
        "errorDetail",
        "warningText",
    ] {
        assert!(kinds(f) > 0, "no {f} said");
    }
}

#[test]
fn events_never_say_minus_zero() {
    let words = Words::english();
    // A heading of −1e-17 rad (a turn that ended at 0) and a distance of −0.
    let goal_set = words.event(&EventKind::GoalSet {
        start: Pose::new(-0.001, 1.0, -1e-17),
        goal: Pose::new(2.0, -0.0, -0.0),
        direction: Direction::Forward,
        placed: true,
    });
    assert!(!goal_set.contains("-0"), "{goal_set}");
    assert!(goal_set.contains("0.00"), "{goal_set}");
    let arrived = words.event(&EventKind::Arrived {
        pose: Pose::new(1.0, 2.0, -1e-9),
        position_error: 0.0,
        heading_error: -1e-9,
        approach_heading_error: -1e-9,
    });
    assert!(!arrived.contains("-0"), "{arrived}");
}

#[test]
fn every_way_a_run_ends_is_said_in_words() {
    use rtnav::system::{DirResolver, EndReason, Scenario, ScenarioRun};
    let words = Words::english();
    let scenario = Scenario::from_json(
        &std::fs::read_to_string(root().join("fixtures/scenarios/unreachable.json")).unwrap(),
    )
    .unwrap();
    let mut run = ScenarioRun::new(&scenario, &DirResolver::new(root())).unwrap();
    let failed = run
        .run_to_end()
        .reason
        .clone()
        .expect("a planning failure says why");
    let ends = [
        failed,
        EndReason::Status {
            status: Status::StoppedOffGoal {
                distance: 0.31,
                heading_error: 0.2,
            },
        },
        EndReason::ComponentError {
            component: "PhysicsSim0",
            reason: Some(Reason::ObstacleAhead { ahead: 0.42 }),
        },
        EndReason::ComponentError {
            component: "PhysicsSim0",
            reason: None,
        },
        EndReason::Halted,
        EndReason::TimeLimit { seconds: 120.0 },
        EndReason::Running,
    ];
    let said: Vec<String> = ends.iter().map(|e| words.end_reason(e)).collect();
    for s in &said {
        assert!(!s.is_empty() && !words.has(s) && !s.contains('{'), "`{s}`");
    }
    assert!(said[0].contains("GlobalPathPlanning"), "{}", said[0]);
    assert_eq!(said[5], "stopped at the time limit, 120 s");
    let ahead = words.reason(&Reason::ObstacleAhead { ahead: 0.42 });
    assert_eq!(said[2], format!("PhysicsSim0 in Error: {ahead}"));
}
