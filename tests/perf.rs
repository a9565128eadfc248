//! Times the operations of `docs/performance.md`'s table — the same code
//! (`core/benches/support/workloads.rs`) natively and compiled to wasm32 under Node — and
//! prints one line per operation, `RTNAV-BENCH {"op":…,"target":…,"median_ms":…,"runs":…}`,
//! for `cargo xtask bench` to compare the two. A report, never an assertion: timing is
//! the harness's business (the host's clock: `Instant` natively, `performance.now()` in
//! Node), never the core's.
//!
//! Not part of `cargo test` (`test = false`); run it in release builds:
//!
//! ```text
//! cargo test --release -p rtnav-tests --test perf -- --nocapture
//! CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER=wasm-bindgen-test-runner \
//!     cargo test --release -p rtnav-tests --test perf --target wasm32-unknown-unknown -- --nocapture
//! ```

#[path = "../core/benches/support/warehouse.rs"]
mod warehouse;
#[path = "../core/benches/support/workloads.rs"]
mod workloads;

use std::hint::black_box;

use rtnav::global::AStar;
use rtnav::local::PotentialField;

#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

macro_rules! say {
    ($($t:tt)*) => {{
        #[cfg(not(target_arch = "wasm32"))]
        println!($($t)*);
        #[cfg(target_arch = "wasm32")]
        wasm_bindgen_test::console_log!($($t)*);
    }};
}

/// Wall-clock milliseconds.
#[cfg(not(target_arch = "wasm32"))]
fn now_ms() -> f64 {
    use std::sync::OnceLock;
    use std::time::Instant;
    static START: OnceLock<Instant> = OnceLock::new();
    START.get_or_init(Instant::now).elapsed().as_secs_f64() * 1e3
}

/// `performance.now()`: sub-millisecond in Node (falls back to `Date.now()`).
#[cfg(target_arch = "wasm32")]
fn now_ms() -> f64 {
    let performance = js_sys::Reflect::get(&js_sys::global(), &"performance".into()).ok();
    let now = performance.as_ref().and_then(|p| {
        let f = js_sys::Reflect::get(p, &"now".into()).ok()?;
        let f: js_sys::Function = wasm_bindgen::JsCast::dyn_into(f).ok()?;
        f.call0(p).ok()?.as_f64()
    });
    now.unwrap_or_else(js_sys::Date::now)
}

const TARGET: &str = if cfg!(target_arch = "wasm32") {
    "wasm32"
} else {
    "native"
};

/// Runs `op` `runs` times after one warm-up run and prints the median.
fn time(op: &str, runs: usize, mut f: impl FnMut() -> usize) {
    black_box(f());
    let mut ms: Vec<f64> = (0..runs)
        .map(|_| {
            let t0 = now_ms();
            black_box(f());
            now_ms() - t0
        })
        .collect();
    ms.sort_by(f64::total_cmp);
    let median = ms[ms.len() / 2];
    say!(
        "RTNAV-BENCH {{\"op\":\"{op}\",\"target\":\"{TARGET}\",\"median_ms\":{median:.4},\"runs\":{runs}}}"
    );
}

#[test]
fn operations_of_the_table() {
    let mut edit = workloads::Edit::new();
    time("edit", 15, || {
        let (route, local) = edit.step();
        route + local
    });
    let mut plans = workloads::LocalPlans::new();
    let n = plans.len();
    time("local_plan", n, || plans.step());
    let (map, request) = workloads::open_field();
    let mut field = PotentialField::new();
    time("full_field", 5, || {
        workloads::full_field(&mut field, &map, &request)
    });
    let map = warehouse::map();
    let mut astar = AStar::new(&map, workloads::DMIN).expect("a planner");
    time("route", 15, || {
        astar
            .plan(warehouse::LONG_START, warehouse::LONG_GOAL)
            .expect("a route")
            .cells
            .len()
    });
}
