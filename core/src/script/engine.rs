//! The script engine (spec §8, Decisions 0.4 "bounds" and "determinism"): Rhai, sandboxed.
//!
//! - **Nothing reachable but what the component hands it**: the engine is built raw, with
//!   the language's arithmetic, strings, arrays, maps and iterators only — no clock
//!   (`no_time`), no `sleep`, no modules to import (`no_module`), no file, no network, no
//!   randomness.
//! - **Bounds** on every action: [`OPERATIONS`] operations, [`CALL_DEPTH`] calls deep,
//!   strings of [`STRING_BYTES`], arrays of [`ARRAY_ITEMS`], maps of [`MAP_ENTRIES`].
//! - **Determinism**: a fixed hashing seed; the math functions from `libm`, the same
//!   pure-Rust implementation natively and in wasm as the core's (spec §6). The float
//!   power operator `**` is left out (the platform's `powf` differs between targets):
//!   `pow(x, y)` is `libm`'s.

use rhai::{Engine, EvalAltResult, INT};

/// Operations one action may run (Rhai's operation count: about one per expression step).
/// A PD law takes a few hundred, a path follower over a long path a few tens of thousands.
pub const OPERATIONS: u64 = 200_000;
/// Nested calls one action may make.
pub const CALL_DEPTH: usize = 32;
/// Largest string, in bytes.
pub const STRING_BYTES: usize = 16 * 1024;
/// Largest array, in items (nested arrays counted in). The engine measures a value again
/// after every change, so the cost of growing one is quadratic in this bound: it is what
/// keeps an action that grows a value within a millisecond or so a step.
pub const ARRAY_ITEMS: usize = 1_000;
/// Largest map, in entries.
pub const MAP_ENTRIES: usize = 256;

/// The hashing seed: fixed, so the engine's hashes are the same in every run and build.
const HASHING_SEED: [u64; 4] = [0x7274_6e61_7600_0001, 0x5345_4544_3030_3300, 3, 2];

type Fallible<T> = Result<T, Box<EvalAltResult>>;

/// A new sandboxed engine with the bounds and the math above.
pub fn engine() -> Engine {
    // Set once per process; a second call finds it set (to the same seed) and is fine.
    let _ = rhai::config::hashing::set_hashing_seed(Some(HASHING_SEED));
    let mut engine = Engine::new_raw();
    {
        use rhai::packages::{
            ArithmeticPackage, BasicArrayPackage, BasicFnPackage, BasicIteratorPackage,
            BasicMapPackage, BasicStringPackage, LogicPackage, MoreStringPackage, Package,
        };
        ArithmeticPackage::new().register_into_engine(&mut engine);
        LogicPackage::new().register_into_engine(&mut engine);
        BasicStringPackage::new().register_into_engine(&mut engine);
        MoreStringPackage::new().register_into_engine(&mut engine);
        BasicIteratorPackage::new().register_into_engine(&mut engine);
        BasicArrayPackage::new().register_into_engine(&mut engine);
        BasicMapPackage::new().register_into_engine(&mut engine);
        BasicFnPackage::new().register_into_engine(&mut engine);
    }
    engine
        .set_max_operations(OPERATIONS)
        .set_max_call_levels(CALL_DEPTH)
        .set_max_expr_depths(64, 64)
        .set_max_string_size(STRING_BYTES)
        .set_max_array_size(ARRAY_ITEMS)
        .set_max_map_size(MAP_ENTRIES)
        .set_max_variables(1_000)
        .set_max_functions(256)
        .set_strict_variables(true);
    engine.disable_symbol("**").disable_symbol("**=");
    register_math(&mut engine);
    engine
}

/// The math a controller needs, from `libm` (spec §6): the same bits natively and in wasm.
fn register_math(engine: &mut Engine) {
    macro_rules! unary {
        ($($name:literal => $f:expr),* $(,)?) => {$(
            engine.register_fn($name, |x: f64| -> f64 { $f(x) });
            engine.register_fn($name, |x: INT| -> f64 { $f(x as f64) });
        )*};
    }
    unary!(
        "sin" => libm::sin, "cos" => libm::cos, "tan" => libm::tan,
        "asin" => libm::asin, "acos" => libm::acos, "atan" => libm::atan,
        "sinh" => libm::sinh, "cosh" => libm::cosh, "tanh" => libm::tanh,
        "exp" => libm::exp, "ln" => libm::log, "log10" => libm::log10,
        "sqrt" => f64::sqrt, "floor" => libm::floor, "ceil" => libm::ceil,
        "round" => libm::round, "trunc" => libm::trunc, "to_float" => core::convert::identity,
    );
    macro_rules! binary {
        ($($name:literal => $f:expr),* $(,)?) => {$(
            engine.register_fn($name, |y: f64, x: f64| -> f64 { $f(y, x) });
            engine.register_fn($name, |y: INT, x: f64| -> f64 { $f(y as f64, x) });
            engine.register_fn($name, |y: f64, x: INT| -> f64 { $f(y, x as f64) });
            engine.register_fn($name, |y: INT, x: INT| -> f64 { $f(y as f64, x as f64) });
        )*};
    }
    binary!(
        "atan2" => libm::atan2, "atan" => libm::atan2, "hypot" => libm::hypot,
        "pow" => libm::pow, "fmin" => libm::fmin, "fmax" => libm::fmax,
    );
    engine.register_fn("abs", |x: f64| x.abs());
    engine.register_fn("min", |a: f64, b: f64| if b < a { b } else { a });
    engine.register_fn("max", |a: f64, b: f64| if b > a { b } else { a });
    engine.register_fn("min", |a: INT, b: INT| a.min(b));
    engine.register_fn("max", |a: INT, b: INT| a.max(b));
    engine.register_fn("clamp", |x: f64, lo: f64, hi: f64| x.max(lo).min(hi));
    engine.register_fn("PI", || core::f64::consts::PI);
    engine.register_fn("to_int", |x: f64| -> Fallible<INT> {
        if x.is_finite() && x.abs() < 9.0e18 {
            Ok(x as INT)
        } else {
            Err(format!("to_int({x}): not a whole number a script can hold").into())
        }
    });
    engine.register_fn("to_float", |x: INT| x as f64);
    engine.register_fn("is_finite", |x: f64| x.is_finite());
    engine.register_fn("is_nan", |x: f64| x.is_nan());
    // The angle wrapped to (−π, π], as the core wraps headings (002 §5.2.5.6).
    engine.register_fn("wrap_angle", crate::motion::wrap_angle);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn math_is_libm_and_nothing_else_is_reachable() {
        let e = engine();
        let v: f64 = e.eval("sin(0.5) + atan2(1.0, 2) + pow(2.0, 0.5)").unwrap();
        assert_eq!(
            v.to_bits(),
            (libm::sin(0.5) + libm::atan2(1.0, 2.0) + libm::pow(2.0, 0.5)).to_bits()
        );
        for forbidden in [
            "sleep(1)",
            "timestamp()",
            "import \"x\" as y;",
            "2.0 ** 3.0",
        ] {
            assert!(e.eval::<rhai::Dynamic>(forbidden).is_err(), "{forbidden}");
        }
        let endless = e.eval::<()>("loop { }").unwrap_err();
        assert!(matches!(*endless, EvalAltResult::ErrorTooManyOperations(_)));
    }
}
