//! Hand-ins stay valid (spec §6, Decision 0.3): replays recorded as the page records them,
//! kept in `fixtures/replays/`, replay in this build with their recorded trace hash and the
//! exercise verdict their name says; a replay of a changed scenario or of another behaviour
//! version is refused with that reason.
//!
//! There is one replay per scenario with an exercise (`fixtures/scenarios/ex_*.json`): the
//! reference solution (`fixtures/exercises/NAME.solution.conf`, loaded as the page loads a
//! `.conf`; in an exercise with code, `fixtures/scripts/exercises/NAME.solution.rhai`, loaded as
//! the page loads a script) driven to its verdict, which must pass; seed 003's fault exercise is recovered
//! with Reset and Activate on DriveControl, and once more left in Error, which must fail.
//!
//! **Re-blessing.** When a change of behaviour changes traces, raise
//! `rtnav::BEHAVIOUR_VERSION`, say why in `CHANGELOG.md`, and record the fixtures again with
//! one command:
//!
//! ```text
//! RTNAV_BLESS=1 cargo test -p rtnav --test replay_fixtures
//! ```

use std::path::{Path, PathBuf};

use rtnav::data::RepoResolver;
use rtnav::errors::SessionError;
use rtnav::rtc::LifecycleState;
use rtnav::system::{
    ComponentKind, FileResolver, Input, MemoryResolver, Replay, Scenario, Session, Verdict,
};

fn root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

fn replays_dir() -> PathBuf {
    root().join("fixtures/replays")
}

const BLESS: &str = "RTNAV_BLESS=1 cargo test -p rtnav --test replay_fixtures";

/// One recorded run: the scenario, the variant (`solution` or `wrong`), the verdict it must
/// get.
#[derive(Debug, Clone)]
struct Recipe {
    scenario: String,
    variant: &'static str,
    verdict: Verdict,
}

impl Recipe {
    fn file(&self) -> PathBuf {
        replays_dir().join(format!("{}.{}.rtnav.json", self.scenario, self.variant))
    }

    /// Seed 003's exercise: the student recovers DriveControl (solution) or does not.
    fn recovers(&self) -> bool {
        self.scenario == "ex_fault_recovery" && self.variant == "solution"
    }
}

/// Every scenario with an exercise: its solution; the fault exercise also left unrecovered.
fn recipes() -> Vec<Recipe> {
    let mut names: Vec<String> = std::fs::read_dir(root().join("fixtures/scenarios"))
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|n| n.starts_with("ex_") && n.ends_with(".json"))
        .map(|n| n.trim_end_matches(".json").to_owned())
        .collect();
    names.sort();
    assert!(!names.is_empty(), "no exercise scenarios");
    let mut out: Vec<Recipe> = names
        .into_iter()
        .map(|scenario| Recipe {
            scenario,
            variant: "solution",
            verdict: Verdict::Passed,
        })
        .collect();
    out.push(Recipe {
        scenario: "ex_fault_recovery".to_owned(),
        variant: "wrong",
        verdict: Verdict::Failed,
    });
    out
}

fn scenario(name: &str) -> Scenario {
    let path = root().join(format!("fixtures/scenarios/{name}.json"));
    Scenario::from_json(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn session(s: Scenario, files: &dyn FileResolver) -> Session {
    let mut session = Session::new().unwrap();
    session.load_scenario(s, files).unwrap();
    session
}

fn decided(s: &Session) -> bool {
    matches!(
        s.exercise().expect("an exercise").verdict,
        Verdict::Passed | Verdict::Failed
    )
}

/// The run as a student makes it in the page, and the page's Download replay of it: the
/// `.conf` loaded, Activate all, 100 ms frames until the checklist has its verdict (seed
/// 003's: Reset and Activate on DriveControl once it is in Error).
fn record(recipe: &Recipe) -> String {
    let s = scenario(&recipe.scenario);
    let limit = s.time_limit;
    let mut session = session(s, &RepoResolver::new(root()));
    let conf = root().join(format!(
        "fixtures/exercises/{}.{}.conf",
        recipe.scenario, recipe.variant
    ));
    if let Ok(text) = std::fs::read_to_string(&conf) {
        session.apply(&Input::LoadConf { text }).unwrap();
    }
    // An exercise with code: the student's script loaded as the page loads it (spec §8); the
    // replay carries its text.
    let script = format!("{}.{}.rhai", recipe.scenario, recipe.variant);
    if let Ok(source) =
        std::fs::read_to_string(root().join("fixtures/scripts/exercises").join(&script))
    {
        let task = scenario(&recipe.scenario).exercise.and_then(|e| e.script);
        let component = task
            .expect("an exercise with code names its component")
            .component;
        session
            .apply(&Input::LoadScript {
                component,
                name: script,
                source,
            })
            .unwrap();
    }
    session.apply(&Input::ActivateAll).unwrap();
    let drive = ComponentKind::DriveControl;
    while !decided(&session) {
        assert!(
            session.system().time() < limit + 10.0,
            "{recipe:?}: no verdict"
        );
        session.advance(100.0);
        if recipe.recovers() && session.system().component_state(drive) == LifecycleState::Error {
            session.apply(&Input::Reset { component: drive }).unwrap();
            session
                .apply(&Input::Activate { component: drive })
                .unwrap();
        }
    }
    let mut json = session.replay_json().unwrap();
    json.push('\n');
    json
}

#[test]
fn every_replay_fixture_reproduces_its_trace_hash_and_verdict() {
    let recipes = recipes();
    if std::env::var_os("RTNAV_BLESS").is_some_and(|v| v == "1") {
        std::fs::create_dir_all(replays_dir()).unwrap();
        for r in &recipes {
            std::fs::write(r.file(), record(r)).unwrap();
            println!("blessed {}", r.file().display());
        }
    }
    // No stray fixture: each file is one of the recipes.
    let mut kept: Vec<String> = std::fs::read_dir(replays_dir())
        .unwrap_or_else(|e| panic!("fixtures/replays: {e} (record them: {BLESS})"))
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|n| n.ends_with(".rtnav.json"))
        .collect();
    kept.sort();
    let mut expected: Vec<String> = recipes
        .iter()
        .map(|r| r.file().file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    expected.sort();
    assert_eq!(kept, expected, "fixtures/replays (record them: {BLESS})");
    let resolver = RepoResolver::new(root());
    for r in &recipes {
        let text = std::fs::read_to_string(r.file()).unwrap();
        let replay = Replay::from_json(&text).unwrap();
        let mut s = session(scenario(&r.scenario), &resolver);
        let check = s.load_replay(&replay).unwrap_or_else(|e| {
            panic!(
                "{}: {e}\n(if the change is meant, raise BEHAVIOUR_VERSION and re-bless: {BLESS})",
                r.file().display()
            )
        });
        assert!(
            check.matches,
            "{}: trace hash {} (recorded {}), {} samples (recorded {}); if the change of \
             behaviour is meant, raise rtnav::BEHAVIOUR_VERSION, say why in CHANGELOG.md and \
             re-bless: {BLESS}",
            r.file().display(),
            check.hash,
            check.expected_hash,
            check.samples,
            check.expected_samples
        );
        let status = s.exercise().unwrap();
        assert_eq!(
            status.verdict,
            r.verdict,
            "{}: verdict\n{status}",
            r.file().display()
        );
    }
}

/// A scenario's map files, as a resolver that can be changed.
fn files_of(s: &Scenario) -> MemoryResolver {
    let repo = RepoResolver::new(root());
    let mut files = MemoryResolver::new();
    for path in s.map_files(&repo).unwrap() {
        files.insert(&path, repo.read(&path).unwrap().into_owned());
    }
    files
}

#[test]
fn a_replay_of_a_changed_scenario_is_refused_with_that_reason() {
    // Recorded here as the fixture is (the fixtures may be being re-blessed meanwhile).
    let recipe = Recipe {
        scenario: "ex_pd_gains".to_owned(),
        variant: "solution",
        verdict: Verdict::Passed,
    };
    let replay = Replay::from_json(&record(&recipe)).unwrap();
    let original = scenario("ex_pd_gains");
    let files = files_of(&original);
    let hash = original.content_hash(&files).unwrap();
    assert_eq!(replay.scenario_hash, hash);

    // The scenario's file says something else (a longer time limit).
    let mut longer = original.clone();
    longer.time_limit += 1.0;
    let mut s = session(longer, &files);
    let before = s.system().time_ns();
    let e = s.load_replay(&replay).unwrap_err();
    match &e {
        rtnav::Error::Session(SessionError::ReplayScenarioChanged {
            scenario,
            recorded,
            found,
        }) => {
            assert_eq!(scenario, "ex_pd_gains");
            assert_eq!(*recorded, hash);
            assert_ne!(*found, hash);
        }
        e => panic!("{e:?}"),
    }
    assert!(
        e.to_string().starts_with(
            "replay: scenario `ex_pd_gains` has changed since the replay was recorded"
        ),
        "{e}"
    );
    assert_eq!(s.system().time_ns(), before, "a refusal changes nothing");

    // The same scenario file, its map file's contents changed (a byte more at its end).
    let map_path = original.map_files(&files).unwrap().remove(0);
    let mut edited = files.read(&map_path).unwrap().into_owned();
    edited.extend_from_slice(b"\n");
    let mut other_map = files.clone();
    other_map.insert(&map_path, edited);
    let mut s = session(original.clone(), &other_map);
    assert!(matches!(
        s.load_replay(&replay),
        Err(rtnav::Error::Session(
            SessionError::ReplayScenarioChanged { .. }
        ))
    ));

    // The same scenario, a replay of another behaviour version.
    let mut older = replay.clone();
    older.behaviour = rtnav::BEHAVIOUR_VERSION + 1;
    let mut s = session(original, &files);
    let e = s.load_replay(&older).unwrap_err();
    assert!(
        matches!(
            &e,
            rtnav::Error::Session(SessionError::ReplayBehaviourChanged { recorded, this_build })
                if *recorded == rtnav::BEHAVIOUR_VERSION + 1 && *this_build == rtnav::BEHAVIOUR_VERSION
        ),
        "{e:?}"
    );
    // And the unchanged one replays.
    assert!(s.load_replay(&replay).unwrap().matches);
}
