//! The crate's error type: [`Error`] gathers one `thiserror` enum per area, each defined next
//! to the code it describes (`rtc/error.rs`, `map/error.rs`, `global/error.rs`,
//! `local/error.rs`, `motion/error.rs`, `render/error.rs`, `system/vocabulary/error.rs`) and
//! re-exported here.
//!
//! Every variant names the problem with named fields, so a GUI can show it and a test can
//! match it. Library code returns these; it does not panic on bad input. Each area's enum
//! also serializes as `{"kind": VARIANT, field: value, …}` and lists its variants
//! (`strum::VariantNames`): [`Error::detail`] gives a GUI the error as data
//! (`{area, kind, fields}`) to say in its own language, and [`Error::KINDS`] lists every
//! `(area, kind)` a GUI must have words for.

use serde::Serialize;
use strum::VariantNames;

pub use crate::global::GlobalPlanningError;
pub use crate::local::LocalPathError;
pub use crate::map::MapError;
pub use crate::motion::MotionError;
#[cfg(feature = "render")]
pub use crate::render::RenderError;
pub use crate::rtc::{ConfigError, LifecycleError, TimestampError};
pub use crate::script::ScriptError;
pub use crate::system::{ConfBundleError, ScenarioError, SessionError, SystemError};

/// Any error `rtnav` returns.
#[derive(Debug, Clone, PartialEq, thiserror::Error, strum::IntoStaticStr, strum::VariantNames)]
#[non_exhaustive]
pub enum Error {
    /// An illegal lifecycle request or an execution-context problem (spec §1).
    #[error(transparent)]
    Lifecycle(#[from] LifecycleError),
    /// A configuration parameter or `.conf` file problem (spec §1).
    #[error(transparent)]
    Config(#[from] ConfigError),
    /// A timestamp refused where a sample entered a component (spec §4 Decision 0.2:
    /// `nsec` ≥ 10⁹), by [`Time::checked`](crate::rtc::Time::checked).
    #[error(transparent)]
    Timestamp(#[from] TimestampError),
    /// A map that cannot be built, loaded or updated (spec §2).
    #[error(transparent)]
    Map(#[from] MapError),
    /// A global plan that cannot be made (spec §5 "GlobalPathPlanning").
    #[error(transparent)]
    GlobalPlanning(#[from] GlobalPlanningError),
    /// A LocalPath service call refused, or a local plan that could not be made (spec §3).
    #[error(transparent)]
    LocalPath(#[from] LocalPathError),
    /// Bad input or parameters of the motion components (spec §4, §5).
    #[error(transparent)]
    Motion(#[from] MotionError),
    /// A scene or frame the renderer cannot draw (spec §5 InventGUI).
    #[cfg(feature = "render")]
    #[error(transparent)]
    Render(#[from] RenderError),
    /// A request to the whole system that cannot be carried out (spec §0).
    #[error(transparent)]
    System(#[from] SystemError),
    /// A scenario that cannot be read or used (spec §6).
    #[error(transparent)]
    Scenario(#[from] ScenarioError),
    /// A request of the page's session (clock, share links).
    #[error(transparent)]
    Session(#[from] SessionError),
    /// A configuration bundle that cannot be read or applied (spec §1).
    #[error(transparent)]
    ConfBundle(#[from] ConfBundleError),
    /// A student's script that cannot be loaded, or whose action failed (spec §8).
    #[error(transparent)]
    Script(#[from] ScriptError),
}

/// An error as data, for a GUI that says it in its own language: the area (the variant of
/// [`Error`], `Lifecycle`), the kind (the area enum's variant, `InvalidTransition`) and its
/// named fields as the enum holds them (`{"component": "DriveControl", "from": "Inactive",
/// "request": "Deactivate"}`). The English words stay the error's `Display`.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct ErrorDetail {
    /// The [`Error`] variant: `Lifecycle`, `Config`, `Map`, ….
    pub area: &'static str,
    /// The area enum's variant (`Timestamp`'s one kind is `Invalid`).
    pub kind: String,
    /// The variant's named fields (an object; empty for a variant without fields).
    #[cfg_attr(feature = "typescript", ts(type = "Record<string, unknown>"))]
    pub fields: serde_json::Value,
}

/// [`TimestampError`]'s one kind.
const TIMESTAMP_KINDS: &[&str] = &["Invalid"];

impl Error {
    /// Every `(area, kinds)` the crate can return: what a GUI's catalogue needs words for.
    /// The kinds are each enum's own variant list.
    pub const KINDS: &'static [(&'static str, &'static [&'static str])] = &[
        ("Lifecycle", LifecycleError::VARIANTS),
        ("Config", ConfigError::VARIANTS),
        ("Timestamp", TIMESTAMP_KINDS),
        ("Map", MapError::VARIANTS),
        ("GlobalPlanning", GlobalPlanningError::VARIANTS),
        ("LocalPath", LocalPathError::VARIANTS),
        ("Motion", MotionError::VARIANTS),
        #[cfg(feature = "render")]
        ("Render", RenderError::VARIANTS),
        ("System", SystemError::VARIANTS),
        ("Scenario", ScenarioError::VARIANTS),
        ("Session", SessionError::VARIANTS),
        ("ConfBundle", ConfBundleError::VARIANTS),
        ("Script", ScriptError::VARIANTS),
    ];

    /// The error as data ([`ErrorDetail`]).
    pub fn detail(&self) -> ErrorDetail {
        let area: &'static str = self.into();
        let value = match self {
            Error::Lifecycle(e) => serde_json::to_value(e),
            Error::Config(e) => serde_json::to_value(e),
            Error::Timestamp(e) => serde_json::to_value(e),
            Error::Map(e) => serde_json::to_value(e),
            Error::GlobalPlanning(e) => serde_json::to_value(e),
            Error::LocalPath(e) => serde_json::to_value(e),
            Error::Motion(e) => serde_json::to_value(e),
            #[cfg(feature = "render")]
            Error::Render(e) => serde_json::to_value(e),
            Error::System(e) => serde_json::to_value(e),
            Error::Scenario(e) => serde_json::to_value(e),
            Error::Session(e) => serde_json::to_value(e),
            Error::ConfBundle(e) => serde_json::to_value(e),
            Error::Script(e) => serde_json::to_value(e),
        };
        let mut fields = match value {
            Ok(serde_json::Value::Object(m)) => m,
            // Every area serializes as a map; anything else has no fields to give.
            _ => serde_json::Map::new(),
        };
        let kind = match fields.remove("kind") {
            Some(serde_json::Value::String(k)) => k,
            _ => TIMESTAMP_KINDS[0].to_owned(),
        };
        ErrorDetail {
            area,
            kind,
            fields: serde_json::Value::Object(fields),
        }
    }
}

/// `Result` with this crate's [`Error`].
pub type Result<T, E = Error> = core::result::Result<T, E>;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rtc::{LifecycleState, Request};

    /// Every area of [`Error`] is listed in [`Error::KINDS`], in its order.
    #[test]
    fn kinds_list_every_area() {
        let areas: Vec<&str> = Error::KINDS.iter().map(|(a, _)| *a).collect();
        assert_eq!(areas, Error::VARIANTS);
    }

    /// The detail names the area, the kind (one of the area's listed kinds) and the fields.
    #[test]
    fn detail_is_area_kind_and_fields() {
        let e = Error::from(LifecycleError::InvalidTransition {
            component: "DriveControl".into(),
            from: LifecycleState::Inactive,
            request: Request::Deactivate,
        });
        let d = e.detail();
        assert_eq!(
            (d.area, d.kind.as_str()),
            ("Lifecycle", "InvalidTransition")
        );
        assert_eq!(
            d.fields,
            serde_json::json!({"component": "DriveControl", "from": "Inactive", "request": "Deactivate"})
        );
        let t = Error::from(TimestampError {
            what: "MapUpdate",
            sec: 1,
            nsec: 1_000_000_000,
        });
        assert_eq!(
            (t.detail().area, t.detail().kind.as_str()),
            ("Timestamp", "Invalid")
        );
        let n = Error::from(GlobalPlanningError::NoMap).detail();
        assert_eq!(
            (n.kind.as_str(), n.fields.clone()),
            ("NoMap", serde_json::json!({}))
        );
        for d in [d, n] {
            let (_, kinds) = Error::KINDS.iter().find(|(a, _)| *a == d.area).unwrap();
            assert!(kinds.contains(&d.kind.as_str()), "{d:?}");
        }
    }

    /// A bundle's block problem is a `Config` error of its own, without its line.
    #[test]
    fn nested_problem_is_a_detail() {
        let e = Error::from(ConfBundleError::ConfBlock {
            component: "DriveControl".into(),
            line: 4,
            problem: ConfigError::UnknownParameter {
                name: "x".into(),
                line: Some(2),
            },
        });
        assert_eq!(
            e.detail().fields["problem"],
            serde_json::json!({"area": "Config", "kind": "UnknownParameter",
                               "fields": {"name": "x", "line": null}})
        );
    }
}
