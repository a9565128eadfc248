//! What a parameter's value in use does that a person should know, as data: the warning
//! shown beside it in the parameters panel (spec §4 note: gains that make a wheel's rate loop
//! unstable or limp; spec §3 Decision 0.2: a `dmin` that lets the body touch obstacles). A
//! user interface says it from its catalogue (`warning.<kind>`); its `Display` is the core's
//! English.

use core::fmt;

use serde::Serialize;

use super::wiring::Wiring;
use crate::components::GainWarning;
use crate::present::number;
use crate::system::vocabulary::events::EventKind;
use crate::system::vocabulary::kind::ComponentKind;

/// The parameters a warning can stand beside, by component (the one list the parameters
/// panel and an exercise's rule read).
const WARNED: [(ComponentKind, &str); 5] = [
    (ComponentKind::MotorControl, "PGainL"),
    (ComponentKind::MotorControl, "DGainL"),
    (ComponentKind::MotorControl, "PGainR"),
    (ComponentKind::MotorControl, "DGainR"),
    (ComponentKind::LocalPathPlanning, "dmin"),
];

/// A parameter's warning (see the module documentation).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, strum::VariantNames)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
#[serde(tag = "kind", rename_all = "snake_case")]
#[strum(serialize_all = "snake_case")]
pub enum ParameterWarning {
    /// P is above `2·D/Δt`: the wheel's rate feedback turns positive.
    GainUnstable {
        /// The P gain.
        p: f64,
        /// The D gain.
        d: f64,
        /// The bound `2·D/Δt`.
        bound: f64,
    },
    /// D is 0: nothing holds the wheel at its target rate.
    GainLimp {
        /// The P gain.
        p: f64,
        /// The rate gain P alone gives, `P·Δt/2` \[N·m·s/rad\].
        rate_gain: f64,
    },
    /// `dmin − GridSize/2 < radiusOfBodyArea`: the body can touch obstacles.
    Clearance {
        /// `dmin` \[m\].
        dmin: f64,
        /// The map's `GridSize` \[m\].
        grid_size: f64,
        /// MotorControl's `radiusOfBodyArea` \[m\].
        body_radius: f64,
    },
}

impl From<GainWarning> for ParameterWarning {
    fn from(w: GainWarning) -> Self {
        match w {
            GainWarning::Unstable { p, d, bound } => Self::GainUnstable { p, d, bound },
            GainWarning::Limp { p, rate_gain } => Self::GainLimp { p, rate_gain },
        }
    }
}

impl ParameterWarning {
    /// Every kind a warning serializes with (`warning.<kind>` in a catalogue).
    pub const KINDS: &'static [&'static str] = <Self as strum::VariantNames>::VARIANTS;

    /// The warning beside `kind`'s parameter `name` with the values in use in `wiring`:
    /// MotorControl's gains of one wheel checked together at its period ([`GainWarning`];
    /// an unstable loop beside the P gain, a limp wheel beside the D gain),
    /// LocalPathPlanning's `dmin` against the map and the body
    /// ([`Wiring::clearance_warning`]). `None`: nothing to warn about.
    pub fn of(wiring: &Wiring, kind: ComponentKind, name: &str) -> Option<Self> {
        match (kind, name) {
            (ComponentKind::MotorControl, "PGainL" | "DGainL" | "PGainR" | "DGainR") => {
                let ec = wiring.execution_context();
                let dt = ec.period_of(kind.index()).map_or(f64::NAN, |ticks| {
                    (ticks * ec.base_period_ns()) as f64 * 1e-9
                });
                // By name: the same parameters whoever stands in MotorControl's place.
                let config = wiring.config(kind).ok()?;
                let side = if name.ends_with('L') { 'L' } else { 'R' };
                let pg = config.effective_value(&format!("PGain{side}")).ok()?;
                let dg = config.effective_value(&format!("DGain{side}")).ok()?;
                match GainWarning::check(pg, dg, dt)? {
                    w @ GainWarning::Unstable { .. } if name.starts_with('P') => Some(w),
                    w @ GainWarning::Limp { .. } if name.starts_with('D') => Some(w),
                    _ => None,
                }
                .map(Self::from)
            }
            (ComponentKind::LocalPathPlanning, "dmin") => match wiring.clearance_warning()? {
                EventKind::ClearanceWarning {
                    dmin,
                    grid_size,
                    body_radius,
                } => Some(Self::Clearance {
                    dmin,
                    grid_size,
                    body_radius,
                }),
                _ => None,
            },
            _ => None,
        }
    }

    /// Every parameter with a warning in `wiring`, as `Component.Parameter`, in the order
    /// the parameters panel lists them.
    pub fn warned(wiring: &Wiring) -> Vec<String> {
        WARNED
            .iter()
            .filter(|(kind, name)| Self::of(wiring, *kind, name).is_some())
            .map(|(kind, name)| format!("{}.{name}", kind.name()))
            .collect()
    }
}

impl fmt::Display for ParameterWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::GainUnstable { p, d, bound } => GainWarning::Unstable { p, d, bound }.fmt(f),
            Self::GainLimp { p, rate_gain } => GainWarning::Limp { p, rate_gain }.fmt(f),
            Self::Clearance {
                dmin,
                grid_size,
                body_radius,
            } => write!(
                f,
                "the body can touch obstacles: dmin {} m − half a cell ({} m) is less than \
                 radiusOfBodyArea {} m",
                number(dmin),
                number(grid_size / 2.0),
                number(body_radius)
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every kind serializes as its kind with its fields; the English is the core's.
    #[test]
    fn every_kind_serializes_with_its_fields() {
        let all = [
            ParameterWarning::from(GainWarning::check(900.0, 0.1, 0.001).unwrap()),
            ParameterWarning::from(GainWarning::check(20.0, 0.0, 0.001).unwrap()),
            ParameterWarning::Clearance {
                dmin: 0.3,
                grid_size: 0.1,
                body_radius: 0.3,
            },
        ];
        for (w, kind) in all.iter().zip(ParameterWarning::KINDS) {
            let v = serde_json::to_value(w).unwrap();
            assert_eq!(v["kind"], *kind, "{v}");
            assert!(v.as_object().unwrap().len() >= 3, "{v}");
        }
        assert_eq!(serde_json::to_value(all[1]).unwrap()["p"], 20.0);
        assert!(
            all[0]
                .to_string()
                .starts_with("P 900 is above 2·D/Δt = 200")
        );
        assert_eq!(
            all[2].to_string(),
            "the body can touch obstacles: dmin 0.3 m − half a cell (0.05 m) is less than \
             radiusOfBodyArea 0.3 m"
        );
    }
}
