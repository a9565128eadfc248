//! Components a student writes (spec §8): what a script in a component's place costs the
//! whole system, each figure next to the built-in baseline measured in the same run
//! (`docs/performance.md`, "Scripts in components' places"):
//!
//! | group | what | baseline |
//! | --- | --- | --- |
//! | `tick` | one base tick (1 ms) of the whole system on open_field mid-drive (10 s to 12 s after the start, in turn), MotorControl and DriveControl both scripted (`fixtures/scripts/motor_control_pd.rhai`, `drive_control_pursuit.rhai`) | `built_in`: the same ticks with the built-in components |
//! | `endless_loop` | the tick in which MotorControl's `on_execute` is `loop {}` (`scripted`) or `loop { x = sin(x) + 1.0; }` (`scripted_busy`): the action runs into its operations budget and fails (the component goes to Error) | `built_in`: the same tick with the built-in MotorControl |
//!
//! Printed besides (once, outside criterion): the ratios of the medians, and the real-time
//! factor of the whole open_field run — simulated seconds per wall second, to the arrival —
//! built in, with MotorControl, DriveControl and both scripted.
//!
//! `cargo bench -p rtnav --bench scripts -- --quick`

use std::hint::black_box;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use criterion::{Criterion, criterion_group, criterion_main};
use rtnav::data::RepoResolver;
use rtnav::rtc::LifecycleState;
use rtnav::system::{ComponentKind, Scenario, ScenarioRun, ScriptText, Setup, System};

/// Where the drive is measured: this long after the start \[ticks of 1 ms\]…
const MID_DRIVE_TICKS: u64 = 10_000;
/// …for this many ticks, then again from the same point.
const WINDOW_TICKS: u64 = 2_000;

/// The endless loop in MotorControl's place.
const ENDLESS: &str = "const COMPONENT = \"MotorControl\";\nfn on_execute(rtc) { loop {} }\n";
/// An endless loop that does something each time round (each round costs the budget more
/// than an empty one).
const BUSY: &str = "const COMPONENT = \"MotorControl\";\n\
                    fn on_execute(rtc) { let x = 0.0; loop { x = sin(x) + 1.0; } }\n";

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn open_field() -> Scenario {
    let text = std::fs::read_to_string(root().join("fixtures/scenarios/open_field.json"))
        .expect("fixtures/scenarios/open_field.json");
    Scenario::from_json(&text).expect("open_field reads")
}

fn script(file: &str) -> ScriptText {
    ScriptText {
        name: file.to_owned(),
        source: std::fs::read_to_string(root().join("fixtures/scripts").join(file))
            .expect("a reference script"),
    }
}

/// open_field's set-up with `scripts` (component name → script) in their places, every
/// component activated.
fn run_of(scenario: &Scenario, scripts: &[(&str, ScriptText)]) -> ScenarioRun {
    let mut setup = Setup::of(scenario);
    for (component, text) in scripts {
        setup.scripts.insert((*component).to_owned(), text.clone());
    }
    ScenarioRun::with_setup(scenario, &RepoResolver::new(root()), &setup).expect("the set-up")
}

fn both_scripted() -> Vec<(&'static str, ScriptText)> {
    vec![
        ("MotorControl", script("motor_control_pd.rhai")),
        ("DriveControl", script("drive_control_pursuit.rhai")),
    ]
}

/// The system `ticks` ticks into the run.
fn mid_drive(mut run: ScenarioRun, ticks: u64) -> System {
    run.advance(ticks);
    run.into_system()
}

/// Times `iters` single ticks from `checkpoint` on, back to the checkpoint every
/// [`WINDOW_TICKS`] (the copies are not timed).
fn time_ticks(checkpoint: &System, iters: u64) -> Duration {
    let mut total = Duration::ZERO;
    let mut done = 0;
    while done < iters {
        let mut system = checkpoint.try_clone().expect("a checkpoint");
        let n = (iters - done).min(WINDOW_TICKS);
        let started = Instant::now();
        for _ in 0..n {
            system.step(1);
        }
        total += started.elapsed();
        black_box(system.time_ns());
        done += n;
    }
    total
}

/// Times `iters` copies of `ready` each stepped one tick (the copies are not timed).
fn time_first_tick(ready: &System, iters: u64) -> Duration {
    let mut total = Duration::ZERO;
    for _ in 0..iters {
        let mut system = ready.try_clone().expect("a checkpoint");
        let started = Instant::now();
        system.step(1);
        total += started.elapsed();
        black_box(system.time_ns());
    }
    total
}

/// The median of `n` runs of `f` (each the time of one call).
fn median(n: usize, mut f: impl FnMut() -> Duration) -> Duration {
    let mut times: Vec<Duration> = (0..n).map(|_| f()).collect();
    times.sort();
    times[n / 2]
}

fn say(line: &str) {
    let _ = writeln!(std::io::stderr(), "{line}");
}

fn tick(c: &mut Criterion) {
    let scenario = open_field();
    let built_in = mid_drive(run_of(&scenario, &[]), MID_DRIVE_TICKS);
    let scripted = mid_drive(run_of(&scenario, &both_scripted()), MID_DRIVE_TICKS);
    for (name, s) in [("built_in", &built_in), ("scripted", &scripted)] {
        assert!(s.is_driving(), "{name}: the robot drives at the checkpoint");
        for kind in [ComponentKind::MotorControl, ComponentKind::DriveControl] {
            assert_eq!(s.component_state(kind), LifecycleState::Active, "{name}");
        }
    }
    let mut g = c.benchmark_group("tick");
    g.sample_size(20);
    g.bench_function("built_in", |b| {
        b.iter_custom(|iters| time_ticks(&built_in, iters))
    });
    g.bench_function("scripted", |b| {
        b.iter_custom(|iters| time_ticks(&scripted, iters))
    });
    g.finish();
    // The ratio, measured here on the same windows (criterion's medians are in its report).
    let per_tick = |s: &System| median(5, || time_ticks(s, WINDOW_TICKS)) / WINDOW_TICKS as u32;
    let (b, s) = (per_tick(&built_in), per_tick(&scripted));
    say(&format!(
        "tick, open_field mid-drive: built-in {:.1} µs, both scripted {:.1} µs: {:.2}× the built-in",
        b.as_secs_f64() * 1e6,
        s.as_secs_f64() * 1e6,
        s.as_secs_f64() / b.as_secs_f64()
    ));
}

/// open_field's set-up with `source` in MotorControl's place, activated, before its first
/// tick; checks that the tick fails MotorControl's action.
fn looping(scenario: &Scenario, name: &str, source: &str) -> System {
    let system = run_of(
        scenario,
        &[(
            "MotorControl",
            ScriptText {
                name: name.to_owned(),
                source: source.to_owned(),
            },
        )],
    )
    .into_system();
    assert_eq!(
        system.component_state(ComponentKind::MotorControl),
        LifecycleState::Active
    );
    let mut after = system.try_clone().expect("a copy");
    after.step(1);
    assert_eq!(
        after.component_state(ComponentKind::MotorControl),
        LifecycleState::Error,
        "{name}: the endless loop fails its action"
    );
    let reason = after.component(ComponentKind::MotorControl).last_error;
    say(&format!("{name}: MotorControl's error: {reason:?}"));
    system
}

fn endless_loop(c: &mut Criterion) {
    let scenario = open_field();
    let built_in = run_of(&scenario, &[]).into_system();
    let empty = looping(&scenario, "endless.rhai", ENDLESS);
    let busy = looping(&scenario, "busy.rhai", BUSY);
    let mut g = c.benchmark_group("endless_loop");
    g.sample_size(20);
    g.bench_function("built_in", |b| {
        b.iter_custom(|iters| time_first_tick(&built_in, iters))
    });
    g.bench_function("scripted", |b| {
        b.iter_custom(|iters| time_first_tick(&empty, iters))
    });
    g.bench_function("scripted_busy", |b| {
        b.iter_custom(|iters| time_first_tick(&busy, iters))
    });
    g.finish();
    let b = median(21, || time_first_tick(&built_in, 1));
    for (what, s) in [
        ("`loop {}`", &empty),
        ("`loop { x = sin(x) + 1.0; }`", &busy),
    ] {
        let s = median(21, || time_first_tick(s, 1));
        say(&format!(
            "endless loop {what} in MotorControl's on_execute: the failing tick takes {:.2} ms \
             (the built-in's first tick {:.1} µs: {:.0}×)",
            s.as_secs_f64() * 1e3,
            b.as_secs_f64() * 1e6,
            s.as_secs_f64() / b.as_secs_f64()
        ));
    }
}

/// The whole open_field run, to the arrival: simulated seconds per wall second.
fn real_time_factor(_c: &mut Criterion) {
    let scenario = open_field();
    let factor = |scripts: &[(&str, ScriptText)]| {
        let mut run = run_of(&scenario, scripts);
        let start = run.system().time();
        let started = Instant::now();
        let outcome = format!("{:?}", run.run_to_end().kind);
        let wall = started.elapsed().as_secs_f64();
        let simulated = run.system().time() - start;
        (simulated, wall, simulated / wall, outcome)
    };
    let (bs, bw, bf, bo) = factor(&[]);
    say(&format!(
        "real-time factor, open_field to the end, built-in: {bs:.1} s simulated in {bw:.2} s \
         = {bf:.0}× ({bo})"
    ));
    let motor = [("MotorControl", script("motor_control_pd.rhai"))];
    let drive = [("DriveControl", script("drive_control_pursuit.rhai"))];
    for (what, scripts) in [
        ("MotorControl scripted", &motor[..]),
        ("DriveControl scripted", &drive[..]),
        ("both scripted", &both_scripted()[..]),
    ] {
        let (ss, sw, sf, so) = factor(scripts);
        say(&format!(
            "real-time factor, open_field to the end, {what}: {ss:.1} s simulated in {sw:.2} s \
             = {sf:.0}× ({so}): {:.3} of the built-in's",
            sf / bf
        ));
        assert!(sf > 1.0, "{what}: faster than real time");
    }
}

criterion_group!(benches, tick, endless_loop, real_time_factor);
criterion_main!(benches);
