//! Why something failed or stopped, as data: a component's callback failure, a planner's
//! failure notice, a refused request, a safety stop. A [`Reason`] serializes as a kind and
//! its fields (`{"kind": "error", "error": {area, kind, fields}}`, `{"kind": "bump",
//! "report": {…}}`), so a user interface says it in its own words (`reason.<kind>` in the
//! page's catalogues); its `Display` is the core's English, for logs, the command line and
//! traces.

use core::fmt;

use serde::Serialize;

use crate::errors::{Error, ErrorDetail};
use crate::motion::BumpReport;
use crate::present::fixed;

/// Why something failed or stopped (see the module documentation).
#[derive(Debug, Clone, PartialEq, strum::EnumDiscriminants)]
#[strum_discriminants(
    name(ReasonKind),
    vis(pub(crate)),
    derive(strum::VariantNames, strum::IntoStaticStr),
    strum(serialize_all = "snake_case")
)]
#[non_exhaustive]
#[cfg_attr(
    feature = "typescript",
    derive(ts_rs::TS),
    ts(as = "ReasonData<'static>", rename = "Reason")
)]
pub enum Reason {
    /// An error of the core (a refused input, a plan that cannot be made).
    Error(Error),
    /// The robot touched an obstacle: the physics' bump report (spec §5).
    Bump(BumpReport),
    /// A fault made to happen from outside (the page's "Inject fault", a scenario's timed
    /// fault), with the words it was given.
    InjectedFault(String),
    /// LocalPathPlanning refused the route GlobalPathPlanning sent (`GlobalPathCourse`).
    CourseRefused(Error),
    /// A component refused a `MapUpdate` the system delivered to it.
    MapUpdateRefused {
        /// The component's name.
        component: String,
        /// Its error.
        error: Error,
    },
    /// DriveControl's clearance check: the way ahead is blocked.
    ObstacleAhead {
        /// Free travel left along the commanded arc \[m\].
        ahead: f64,
    },
    /// Words of a component the core does not know (a test's own component): shown as given.
    Words(String),
}

impl Reason {
    /// Every kind a reason serializes with (`error`, `bump`, …): what a user interface must
    /// have words for (`reason.<kind>`).
    pub const KINDS: &'static [&'static str] = <ReasonKind as strum::VariantNames>::VARIANTS;

    /// The kind it serializes with.
    pub fn kind(&self) -> &'static str {
        ReasonKind::from(self).into()
    }

    /// The error, when the reason is one of the core's errors (directly or as the cause of
    /// a refused course or map update).
    pub fn error(&self) -> Option<&Error> {
        match self {
            Self::Error(e) | Self::CourseRefused(e) | Self::MapUpdateRefused { error: e, .. } => {
                Some(e)
            }
            _ => None,
        }
    }
}

impl From<Error> for Reason {
    fn from(e: Error) -> Self {
        Self::Error(e)
    }
}

/// What a [`Reason`] serializes as (and, for the page's declarations, its type).
#[derive(Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS), ts(rename = "ReasonData"))]
#[serde(tag = "kind", rename_all = "snake_case")]
enum ReasonData<'a> {
    Error {
        error: ErrorDetail,
    },
    Bump {
        report: &'a BumpReport,
    },
    InjectedFault {
        words: &'a str,
    },
    CourseRefused {
        error: ErrorDetail,
    },
    MapUpdateRefused {
        component: &'a str,
        error: ErrorDetail,
    },
    ObstacleAhead {
        ahead: f64,
    },
    Words {
        words: &'a str,
    },
}

impl Serialize for Reason {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Self::Error(e) => ReasonData::Error { error: e.detail() },
            Self::Bump(report) => ReasonData::Bump { report },
            Self::InjectedFault(words) => ReasonData::InjectedFault { words },
            Self::CourseRefused(e) => ReasonData::CourseRefused { error: e.detail() },
            Self::MapUpdateRefused { component, error } => ReasonData::MapUpdateRefused {
                component,
                error: error.detail(),
            },
            Self::ObstacleAhead { ahead } => ReasonData::ObstacleAhead { ahead: *ahead },
            Self::Words(words) => ReasonData::Words { words },
        }
        .serialize(s)
    }
}

impl fmt::Display for Reason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Error(e) => write!(f, "{e}"),
            Self::Bump(report) => write!(f, "bump: {report}"),
            Self::InjectedFault(words) => write!(f, "injected fault: {words}"),
            Self::CourseRefused(e) => write!(f, "GlobalPathCourse refused: {e}"),
            Self::MapUpdateRefused { component, error } => write!(f, "{component}: {error}"),
            Self::ObstacleAhead { ahead } => write!(f, "obstacle {} m ahead", fixed(*ahead, 2)),
            Self::Words(words) => f.write_str(words),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::errors::{GlobalPlanningError, LocalPathError};
    use crate::interfaces::Pose;
    use crate::rtc::Time;

    /// One reason of every kind.
    pub(crate) fn every_reason() -> Vec<Reason> {
        let report = BumpReport {
            tm: Time::from_nanos(1_500_000_000),
            who: "robot".into(),
            pose: Pose::new(1.0, 2.0, 0.5),
            cell: (3, 4),
            contact: (1.25, 2.5),
            speed: 0.3,
        };
        vec![
            Reason::Error(GlobalPlanningError::NoMap.into()),
            Reason::Bump(report),
            Reason::InjectedFault("encoder cable pulled".into()),
            Reason::CourseRefused(
                LocalPathError::NoMap {
                    call: "SetPosition",
                }
                .into(),
            ),
            Reason::MapUpdateRefused {
                component: "PhysicsSim".into(),
                error: GlobalPlanningError::NoMap.into(),
            },
            Reason::ObstacleAhead { ahead: 0.25 },
            Reason::Words("a test's words".into()),
        ]
    }

    /// Every kind serializes as its kind and its fields, and every kind is listed.
    #[test]
    fn every_kind_serializes_with_its_fields() {
        let all = every_reason();
        let kinds: Vec<&str> = all.iter().map(Reason::kind).collect();
        assert_eq!(kinds, Reason::KINDS);
        for r in &all {
            let v = serde_json::to_value(r).unwrap();
            let obj = v.as_object().unwrap();
            assert_eq!(obj["kind"], r.kind(), "{v}");
            assert!(obj.len() >= 2, "a reason without its fields: {v}");
        }
        let v = serde_json::to_value(&all[0]).unwrap();
        assert_eq!(
            v,
            serde_json::json!({"kind": "error",
                "error": {"area": "GlobalPlanning", "kind": "NoMap", "fields": {}}})
        );
        let v = serde_json::to_value(&all[1]).unwrap();
        assert_eq!(v["report"]["cell"], serde_json::json!([3, 4]));
        let v = serde_json::to_value(&all[4]).unwrap();
        assert_eq!(v["component"], "PhysicsSim");
        assert_eq!(v["error"]["kind"], "NoMap");
        assert_eq!(serde_json::to_value(&all[5]).unwrap()["ahead"], 0.25);
    }

    /// The English words are the core's as before: a bump, a fault, a refused course.
    #[test]
    fn display_is_the_cores_english() {
        let all = every_reason();
        assert!(
            all[1]
                .to_string()
                .starts_with("bump: robot bumped into obstacle cell (3, 4)")
        );
        assert_eq!(all[2].to_string(), "injected fault: encoder cable pulled");
        assert!(all[3].to_string().starts_with("GlobalPathCourse refused: "));
        assert_eq!(all[5].to_string(), "obstacle 0.25 m ahead");
        assert_eq!(all[6].to_string(), "a test's words");
    }
}
