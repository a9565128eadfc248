//! What a data port shows of itself (RT System Editor's port view): its name, direction, the
//! IDL type it carries, how many samples passed, and the newest one with its timestamp.
//!
//! [`Sample`] is the one way a value that travels through a port describes itself for
//! people; the IDL types implement it here, the other port types next to the components
//! (`crate::components::samples`).

use serde::Serialize;

use super::idl::{Time, TimedDouble, TimedDoubleSeq, TimedPosition, TimedVelocity};
use crate::present::number;

/// A value that travels through a data port.
pub trait Sample {
    /// The IDL type's name (`TimedVelocity`, `TimedDoubleSeq`, …).
    const IDL: &'static str;
    /// The sample's timestamp, if it has one.
    fn tm(&self) -> Option<Time>;
    /// The fields other than the timestamp, for people: `vx: 0.48, vy: 0, w: -0.12`.
    fn fields(&self) -> String;
}

/// `v` to three decimals at most, written as a person would (`0.48`, `0`, `-0.12`).
pub fn short(v: f64) -> String {
    if v.is_finite() && v.abs() < 1e12 {
        number((v * 1000.0).round() / 1000.0)
    } else {
        number(v)
    }
}

/// Up to `max` numbers of `values`, then `… (n values)`.
pub fn short_list(values: &[f64], max: usize) -> String {
    let mut s = values
        .iter()
        .take(max)
        .map(|v| short(*v))
        .collect::<Vec<_>>()
        .join(", ");
    if values.len() > max {
        s.push_str(&format!(", … ({} values)", values.len()));
    }
    format!("[{s}]")
}

/// The newest sample of a port, for people.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct SampleView {
    /// Its timestamp \[s\], if it has one.
    pub tm: Option<f64>,
    /// `TimedVelocity {tm: 12.340 s, vx: 0.48, vy: 0, w: -0.12}`.
    pub text: String,
}

impl SampleView {
    /// The view of `sample`.
    pub fn of<T: Sample>(sample: &T) -> Self {
        let tm = sample.tm().map(Time::as_secs_f64);
        let fields = sample.fields();
        let text = match (tm, fields.is_empty()) {
            (Some(t), false) => format!("{} {{tm: {t:.3} s, {fields}}}", T::IDL),
            (Some(t), true) => format!("{} {{tm: {t:.3} s}}", T::IDL),
            (None, _) => format!("{} {{{fields}}}", T::IDL),
        };
        Self { tm, text }
    }
}

/// Whether a data port receives or sends.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum PortDirection {
    /// An `InPort`.
    In,
    /// An `OutPort`.
    Out,
}

/// A data port as RT System Editor shows it, with its newest sample.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PortView {
    /// The seed's name (`TargetVelocity`).
    pub name: &'static str,
    /// In or out.
    pub direction: PortDirection,
    /// The IDL type.
    pub idl: &'static str,
    /// Samples received (an in-port) or written (an out-port) so far.
    pub count: u64,
    /// The newest sample.
    pub last: Option<SampleView>,
}

impl Sample for TimedPosition {
    const IDL: &'static str = "TimedPosition";
    fn tm(&self) -> Option<Time> {
        Some(self.tm)
    }
    fn fields(&self) -> String {
        format!(
            "x: {}, y: {}, theta: {}",
            short(self.x),
            short(self.y),
            short(self.theta)
        )
    }
}

impl Sample for TimedVelocity {
    const IDL: &'static str = "TimedVelocity";
    fn tm(&self) -> Option<Time> {
        Some(self.tm)
    }
    fn fields(&self) -> String {
        format!(
            "vx: {}, vy: {}, w: {}",
            short(self.vx),
            short(self.vy),
            short(self.w)
        )
    }
}

impl Sample for TimedDouble {
    const IDL: &'static str = "TimedDouble";
    fn tm(&self) -> Option<Time> {
        Some(self.tm)
    }
    fn fields(&self) -> String {
        format!("data: {}", short(self.data))
    }
}

impl Sample for TimedDoubleSeq {
    const IDL: &'static str = "TimedDoubleSeq";
    fn tm(&self) -> Option<Time> {
        Some(self.tm)
    }
    fn fields(&self) -> String {
        format!("data: {}", short_list(&self.data, 6))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_velocity_reads_as_the_system_tab_shows_it() {
        let v = TimedVelocity {
            tm: Time::from_nanos(12_340_000_000),
            vx: 0.480_000_1,
            vy: 0.0,
            w: -0.12,
            ..TimedVelocity::default()
        };
        let view = SampleView::of(&v);
        assert_eq!(
            view.text,
            "TimedVelocity {tm: 12.340 s, vx: 0.48, vy: 0, w: -0.12}"
        );
        assert_eq!(view.tm, Some(12.34));
        assert_eq!(short_list(&[1.0, 2.5, 3.0], 2), "[1, 2.5, … (3 values)]");
    }
}
