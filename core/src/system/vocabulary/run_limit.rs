//! The longest simulated time a run goes: a bound on every time someone asks the system to
//! run to, and on every length of run someone asks for (`System::run_for`, `run_until`,
//! `Session::step_ticks`), so that an absurd one is refused instead of run for ever.

use crate::errors::SystemError;

/// The latest simulated time a replay runs to \[ns\]: 24 h. It bounds every run to a time
/// someone asks for — a replay's `end_ns`, a seek, a scenario's `time_limit`, `rtnav run
/// --until` — so that an absurd time (10¹⁸ ns) is refused instead of running for ever.
pub const MAX_REPLAY_NS: u64 = 24 * 3600 * 1_000_000_000;

/// `seconds` of simulated time asked for by `what` (a count of ticks or seconds to run), or
/// [`SystemError::RunTooLong`] past [`MAX_REPLAY_NS`]: the bound on the library's loops.
pub(in crate::system) fn check_run_length(
    what: &'static str,
    seconds: f64,
) -> Result<(), SystemError> {
    if seconds * 1e9 > MAX_REPLAY_NS as f64 {
        return Err(SystemError::RunTooLong {
            what,
            seconds,
            limit_s: MAX_REPLAY_NS / 1_000_000_000,
        });
    }
    Ok(())
}

/// Why `what`, a time of `t_ns`, is too late to run to ([`MAX_REPLAY_NS`]); `None` if it
/// is not.
pub(in crate::system) fn beyond_replay_limit(what: &str, t_ns: u64) -> Option<String> {
    (t_ns > MAX_REPLAY_NS).then(|| {
        format!(
            "{what} is later than {MAX_REPLAY_NS} ns (24 h of simulated time), the longest a \
             run or a replay goes"
        )
    })
}

/// [`beyond_replay_limit`] for a time in seconds (`what` says it as given).
pub(in crate::system) fn beyond_replay_limit_s(what: &str, seconds: f64) -> Option<String> {
    (seconds * 1e9 > MAX_REPLAY_NS as f64).then(|| {
        format!(
            "{what} is later than {} s (24 h of simulated time), the longest a run or a \
             replay goes",
            MAX_REPLAY_NS / 1_000_000_000
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_run_longer_than_a_day_is_refused_by_name() {
        assert!(check_run_length("run_for seconds", 86_400.0).is_ok());
        let e = check_run_length("run_for seconds", 86_400.001).unwrap_err();
        assert!(
            matches!(
                e,
                SystemError::RunTooLong {
                    limit_s: 86_400,
                    ..
                }
            ),
            "{e:?}"
        );
        assert_eq!(
            e.to_string(),
            "run_for seconds asks for 86400.001 s of simulated time, more than the 86400 s \
             (24 h) a run goes at most"
        );
    }
}
