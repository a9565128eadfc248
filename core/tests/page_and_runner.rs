//! The page and the runner drive the same system: for every scenario in `fixtures/`, the
//! page's set-up ([`Session`]) activated at once and driven to the end gives the same trace
//! hash as a headless run (`rtnav run`, [`ScenarioRun`]).

use std::path::PathBuf;

use rtnav::data::RepoResolver;
use rtnav::system::{Input, OutcomeKind, Scenario, ScenarioRun, Session, judge};

fn scenarios() -> Vec<PathBuf> {
    let mut paths: Vec<PathBuf> = std::fs::read_dir("../fixtures/scenarios")
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    paths.sort();
    paths
}

/// The data a scenario names beyond the repository (`../shared/data/...`) is there.
fn available(scenario: &Scenario, root: &RepoResolver) -> bool {
    use rtnav::system::FileResolver;
    scenario
        .map_files(root)
        .is_ok_and(|files| files.iter().all(|f| root.read(f).is_ok()))
}

#[test]
fn the_pages_set_up_driven_to_the_end_gives_the_runners_trace() {
    let root = RepoResolver::new("..");
    for path in scenarios() {
        let scenario = Scenario::from_json(&std::fs::read_to_string(&path).unwrap()).unwrap();
        if !available(&scenario, &root) {
            eprintln!(
                "SKIPPED {}: its map is external data, not here",
                path.display()
            );
            continue;
        }
        let mut run = ScenarioRun::new(&scenario, &root).unwrap();
        let outcome = run.run_to_end().clone();
        let report = run.report();

        let mut session = Session::new().unwrap();
        session.load_scenario(scenario.clone(), &root).unwrap();
        session.apply(&Input::ActivateAll).unwrap();
        session.set_speed(16.0).unwrap();
        let limit = session.system().time_ns() + (scenario.time_limit * 1e9) as u64;
        let (mut cursor, mut refused, mut still) = (0, None, None);
        let ended = loop {
            // The page's frames: 16 ms of wall time at 16× (the timeline applies the events).
            session.advance(16.0);
            if let Some(o) = judge(
                session.system(),
                session.timeline().pending() > 0,
                &mut cursor,
                &mut refused,
                &mut still,
                limit,
            ) {
                break o;
            }
        };
        // The page runs whole frames; the runner stops at the tick it judged. Compare the
        // trace up to the runner's end.
        assert_eq!(ended.kind, outcome.kind, "{}", scenario.name);
        let page = session.system().record().telemetry();
        let samples = usize::try_from(report.samples).unwrap();
        assert!(page.samples().len() >= samples || page.total() >= report.samples);
        let runner_hash = report.trace_hash.clone();
        let page_hash = rtnav::system::Telemetry::hash_of(page.samples().iter().take(samples));
        assert_eq!(
            page_hash, runner_hash,
            "{}: the page and the runner differ",
            scenario.name
        );
        // A scenario ends before its time limit; an exercise as written may not (the
        // student's change is what makes it arrive: `ex_model_offset`).
        if scenario.exercise.is_none() {
            assert_ne!(outcome.kind, OutcomeKind::TimeLimit, "{}", scenario.name);
        }
    }
}
