//! Execution rates (spec §6): the one check that turns a rate in Hz into a period of whole
//! base ticks. The execution context uses it for its base tick, for each component it
//! attaches and at every rate change; the system uses it for a scenario's rates when it is
//! read and built, and for the telemetry.

use crate::errors::LifecycleError;

/// Nanoseconds per second.
const NANOS_PER_SEC: f64 = 1e9;

/// The highest rate anything runs at \[Hz\], and so the highest base rate of an execution
/// context: the physics steps 1 ms at a time (spec §5 "Physics") and, with MotorControl,
/// runs at 1 kHz (spec §6, 002 §5.2.7); nothing in the system is faster. A higher rate
/// would only multiply the ticks of a run (a base of 1 GHz makes 5 s of planning five
/// billion ticks).
pub const MAX_BASE_RATE_HZ: f64 = 1000.0;

/// `rate_hz`, the rate of `who` (a component's instance name, `telemetry`, …), as its
/// period in ticks of `base_period_ns` (1 for the period in nanoseconds). Refused, with an
/// error naming `who`, the rate and the limit it breaks: a rate that is not positive and
/// finite, one above [`MAX_BASE_RATE_HZ`], a period that is not a whole number of
/// nanoseconds, or not a whole number of base ticks.
pub fn period_ticks(who: &str, rate_hz: f64, base_period_ns: u64) -> Result<u64, LifecycleError> {
    let bad = |reason: String| LifecycleError::InvalidRate {
        component: who.to_owned(),
        rate: rate_hz,
        reason,
    };
    if !(rate_hz.is_finite() && rate_hz > 0.0) {
        return Err(bad("it must be positive and finite".to_owned()));
    }
    if rate_hz > MAX_BASE_RATE_HZ {
        return Err(bad(format!(
            "it is above the highest rate, {MAX_BASE_RATE_HZ} Hz (the physics' 1 ms step)"
        )));
    }
    let p = NANOS_PER_SEC / rate_hz;
    // `u64::MAX as f64` rounds up to 2⁶⁴, which no u64 holds: the period must be below it.
    if p.fract() != 0.0 || p * rate_hz != NANOS_PER_SEC || p >= u64::MAX as f64 {
        return Err(bad(
            "its period is not a whole number of nanoseconds".to_owned()
        ));
    }
    let p = p as u64;
    if base_period_ns == 0 || !p.is_multiple_of(base_period_ns) {
        return Err(bad(format!(
            "its period of {p} ns is not a whole number of base ticks ({base_period_ns} ns)"
        )));
    }
    Ok(p / base_period_ns)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn reason(who: &str, hz: f64, base: u64) -> String {
        match period_ticks(who, hz, base) {
            Ok(t) => format!("{t} ticks"),
            Err(e) => e.to_string(),
        }
    }

    #[test]
    fn a_rate_is_whole_base_ticks_at_most_one_kilohertz() {
        assert_eq!(period_ticks("DriveControl", 50.0, 1_000_000), Ok(20));
        assert_eq!(period_ticks("PhysicsSim", 1000.0, 1), Ok(1_000_000));
        assert_eq!(period_ticks("MapBuilder", 0.001, 1_000_000), Ok(1_000_000));
        assert_eq!(
            reason("PhysicsSim", 1e9, 1),
            "PhysicsSim: rate 1000000000 Hz is not usable: it is above the highest rate, \
             1000 Hz (the physics' 1 ms step)"
        );
        // A period that would round to 0 ns.
        assert!(reason("telemetry", 3e9, 1).contains("above the highest rate"));
        assert_eq!(
            reason("DriveControl", 3.0, 1_000_000),
            "DriveControl: rate 3 Hz is not usable: its period is not a whole number of \
             nanoseconds"
        );
        assert_eq!(
            reason("DriveControl", 400.0, 1_000_000),
            "DriveControl: rate 400 Hz is not usable: its period of 2500000 ns is not a whole \
             number of base ticks (1000000 ns)"
        );
        for hz in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(reason("x", hz, 1).contains("positive and finite"), "{hz}");
        }
        // A period longer than any u64 of nanoseconds.
        assert!(reason("x", 1e-11, 1).contains("whole number of nanoseconds"));
        assert!(reason("x", 1e-300, 1).contains("whole number of nanoseconds"));
    }
}
