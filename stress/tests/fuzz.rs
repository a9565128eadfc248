//! The short fuzz run of `cargo test`: every target for a fixed number of inputs under a
//! fixed seed, after every kept regression case (`fixtures/fuzz-regressions/`); the fuzz
//! stage of `cargo xtask test` runs the readers for a time budget with a fresh seed, and
//! `cargo xtask fuzz --seconds N` longer. Each input is checked for panics, time (1 s), allocation
//! (this binary counts with its own allocator) and refused calls that change something.

use std::path::PathBuf;
use std::time::Duration;

use rtnav::system::System;
use rtnav_stress::alloc::Counting;
use rtnav_stress::fuzz::{self, Options, Target, TargetReport};

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// The seed of the CI run (any failure prints it with its case number for `rtnav-stress fuzz`).
const SEED: u64 = 18;

/// The kept regression cases, under the project's root.
const CORPUS: &str = "fixtures/fuzz-regressions";

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn run(names: &[&str], cases: u64) -> Vec<TargetReport> {
    let root = root();
    let data = match rtnav::data::data_dir(&root) {
        Ok(dir) => Some(dir),
        Err(missing) => {
            println!("fuzz: the real maps among the inputs SKIPPED: {missing}");
            None
        }
    };
    let mut options = Options::new(SEED, Duration::ZERO, Some(cases));
    options.only = names.iter().map(|s| (*s).to_owned()).collect();
    options.corpus = Some(root.join(CORPUS));
    let reports = fuzz::run(&root, data.as_deref(), &options, |r| {
        println!("{}", r.line())
    });
    assert_eq!(reports.len(), names.len(), "every target named ran");
    for r in &reports {
        assert!(
            r.failures.is_empty(),
            "{}: {} failures (seed {SEED}), the first: {:#?}",
            r.name,
            r.failed,
            r.failures.first()
        );
    }
    reports
}

#[test]
fn the_readers_hold_for_hostile_inputs() {
    run(
        &[
            "json-map",
            "ros-map",
            "ros-yaml",
            "movingai-map",
            "movingai-scen",
            "conf",
            "scenario",
            "replay",
        ],
        150,
    );
}

/// Every input that once failed, kept in `fixtures/fuzz-regressions/TARGET/`, passes now (the
/// runs above replay them too, before their own inputs; this names each).
#[test]
fn every_kept_regression_case_passes() {
    let root = root();
    let dir = root.join(CORPUS);
    let mut options = Options::new(SEED, Duration::ZERO, Some(0));
    options.corpus = Some(dir.clone());
    let reports = fuzz::run(
        &root,
        rtnav::data::data_dir(&root).ok().as_deref(),
        &options,
        |r| println!("{}", r.line()),
    );
    let mut kept = 0;
    for r in &reports {
        kept += r.regressions;
        assert!(
            r.failures.is_empty(),
            "{}: kept regression cases fail: {:#?}",
            r.name,
            r.failures
        );
    }
    // Every folder names a target, and the folders hold cases.
    for entry in std::fs::read_dir(&dir).unwrap() {
        let name = entry.unwrap().file_name().into_string().unwrap();
        if name != "README.md" {
            assert!(
                reports.iter().any(|r| r.name == name),
                "fixtures/fuzz-regressions/{name}: no such target"
            );
        }
    }
    assert!(kept >= 4, "{kept} kept regression cases");
}

#[test]
fn the_components_refuse_hostile_calls_without_changing() {
    let r = run(&["components"], 150);
    assert!(
        r[0].refusals > 100,
        "the twin compared refusals: {}",
        r[0].refusals
    );
}

#[test]
fn the_system_refuses_hostile_calls_and_lifecycle_requests_without_changing() {
    let r = run(&["system-calls", "lifecycle", "conf-bundle"], 40);
    assert!(r[0].refusals > 20 && r[1].refusals > 20, "{r:?}");
}

/// Share links, deflate bombs among them: refused within the bound (a token that inflates
/// past the 16 MiB limit costs its inflated bytes, twice at most, and a short message).
#[test]
fn share_tokens_are_refused_cheaply() {
    run(&["share-token", "share-json"], 150);
}

/// Students' scripts: compiled (`Ok` or a short named error), loaded into MotorControl's or
/// DriveControl's place of open_field's set-up and run, each tick timed; a refused load, a
/// load over the Active script among them, changes nothing.
#[test]
fn scripts_compile_load_and_run_within_their_bounds() {
    let r = run(&["script"], 60);
    assert!(r[0].refusals > 20, "refusals compared: {}", r[0].refusals);
}

/// The checks have teeth: a call that is refused but changes the system is caught.
#[test]
fn a_refused_call_that_changes_the_system_is_caught() {
    let sneaky: fuzz::system::Op = Box::new(|s: &mut System| {
        s.step(1);
        Some(false)
    });
    let honest: fuzz::system::Op = Box::new(|s: &mut System| Some(s.run_for(f64::NAN).is_ok()));
    let ok = fuzz::system::check_twins(true, &[("run_for(NaN)".to_owned(), honest)]);
    assert_eq!(ok, Ok(()));
    let caught = fuzz::system::check_twins(true, &[("sneaky".to_owned(), sneaky)]);
    let e = caught.unwrap_err();
    assert!(e.contains("was refused but changed the system"), "{e}");
}

/// A target that panics, is slow or allocates too much is reported, with its case.
#[test]
fn panics_slowness_and_allocation_are_reported() {
    struct Bad;
    impl Target for Bad {
        fn name(&self) -> &'static str {
            "bad"
        }
        fn seeds(&self) -> &[fuzz::Case] {
            &[]
        }
        fn generate(&self, rng: &mut rtnav_stress::rng::Rng) -> fuzz::Case {
            fuzz::Case::one(vec![(rng.next_u64() % 3) as u8])
        }
        fn run(&mut self, case: &fuzz::Case) -> Result<(), String> {
            match case.part(0)[0] {
                0 => panic!("boom"),
                1 => {
                    let v = vec![1u8; 1 << 20];
                    std::hint::black_box(&v);
                    Ok(())
                }
                _ => Err("broken invariant".to_owned()),
            }
        }
        fn alloc_bound(&self, _case: &fuzz::Case) -> u64 {
            1024
        }
    }
    let options = Options::new(1, Duration::ZERO, Some(30));
    let r = fuzz::run_target(&mut Bad, &options);
    assert_eq!(r.failed, 30);
    let kinds: std::collections::BTreeSet<&str> = r.failures.iter().map(|f| f.kind).collect();
    assert_eq!(
        kinds,
        ["alloc", "invariant", "panic"].into_iter().collect(),
        "{r:#?}"
    );
    assert!(r.failures.iter().any(|f| f.message.contains("boom")));
}

/// The largest map the limit allows (4096 × 4096 = `MAX_CELLS`) as a 16 KiB PNG: accepted,
/// within the allocation bound; the time it takes is printed (run it with `--release`:
/// `cargo test --release -p rtnav-stress --test fuzz -- --ignored largest`).
#[test]
#[ignore = "a measurement: 16 Mi cells take seconds in a debug build"]
fn the_largest_legal_png_map_loads_within_the_bound() {
    use rtnav::map::MAX_CELLS;
    use rtnav::map::formats::ros;
    let pixels = vec![255u8; MAX_CELLS];
    let png = fuzz::readers::encode_png(
        4096,
        4096,
        png::ColorType::Grayscale,
        png::BitDepth::Eight,
        &pixels,
    )
    .unwrap();
    drop(pixels);
    let yaml = "image: m.png\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n\
                occupied_thresh: 0.65\nfree_thresh: 0.196\n";
    let started = std::time::Instant::now();
    let (r, usage) =
        rtnav_stress::alloc::measure(|| ros::load(yaml, &png, &ros::RosLoadOptions::default()));
    let took = started.elapsed();
    let map = r.unwrap().map;
    assert_eq!(map.cells().len(), MAX_CELLS);
    let bound = fuzz::readers::BASE
        + fuzz::readers::PER_BYTE * png.len() as u64
        + fuzz::readers::PER_PIXEL * MAX_CELLS as u64;
    println!(
        "4096 × 4096 PNG ({} bytes): {:.3} s, largest request {}, peak {} (bound {})",
        png.len(),
        took.as_secs_f64(),
        fuzz::bytes(usage.largest as u64),
        fuzz::bytes(usage.peak as u64),
        fuzz::bytes(bound)
    );
    assert!(usage.peak as u64 <= bound);
}
