//! What the page is told when a request is refused ([`Refusal`]): the English words and the
//! error as data — the core's [`rtnav::ErrorDetail`], or a [`PageError`] of this layer's
//! own (a picked file it cannot use) — made a JavaScript `Error` with a `detail` by [`js`].

use wasm_bindgen::prelude::*;

/// What the page expects to be picked as a map.
pub(crate) const EXPECTED: &str = "expected an rtnav JSON map (.json), a ROS map (its .yaml \
                                   and its .pgm or .png image, picked together) or a MovingAI \
                                   map (.map)";

/// A request of this layer's own that is refused (area `Page` in the detail): the files a
/// user picked, the page's arrays and layer names. `PageError::VARIANTS` lists every kind.
#[derive(
    Debug,
    Clone,
    PartialEq,
    thiserror::Error,
    serde::Serialize,
    strum::VariantNames,
    strum::IntoStaticStr,
)]
#[serde(tag = "kind")]
pub(crate) enum PageError {
    /// No file picked.
    #[error("no file chosen: {EXPECTED}")]
    NoFile,
    /// A file whose name says no map format.
    #[error("`{name}` is not a map file I know: {EXPECTED}")]
    UnknownFile { name: String },
    /// A ROS YAML file that is not UTF-8.
    #[error("`{name}` is not text: {reason}")]
    NotText { name: String, reason: String },
    /// A ROS YAML file picked without its image.
    #[error("`{name}` names the image `{image}`: pick it together with the YAML file")]
    MissingImage { name: String, image: String },
    /// More than one map picked (other than a YAML file and its image).
    #[error("{count} files chosen: {EXPECTED}")]
    FileCount { count: usize },
    /// A MovingAI cell size that is not positive.
    #[error("MovingAI cell size {value} m must be positive")]
    BadCellSize { value: f64 },
    /// A ROS image picked without its YAML file.
    #[error("`{name}` is an image: a ROS map needs its .yaml file too (pick both)")]
    ImageOnly { name: String },
    /// `set_cells` with lists of different lengths.
    #[error("MapUpdate: {xs} x indices but {ys} y indices")]
    CellLists { xs: usize, ys: usize },
    /// A layer name the renderer does not have.
    #[error("no layer named `{name}` (layers: {known})")]
    UnknownLayer { name: String, known: String },
}

/// A result whose error is what the page shows. Kept apart from `JsValue` (which exists
/// only in a browser) so the native tests can check the exact words.
pub(crate) type Msg<T> = Result<T, Refusal>;

/// A refusal: the core's English words, and — when the core refused — the error as data
/// ([`rtnav::ErrorDetail`]: `{area, kind, fields}`) for the page to say in its language,
/// with the file or scenario it was about.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Refusal {
    /// The English words (the error's `Display`).
    pub message: String,
    /// The error as data, with `file` or `scenario` when the words start with one.
    pub detail: Option<serde_json::Value>,
}

impl Refusal {
    /// The refusal about `what` (`file` or `scenario`) named `name`: the words start with it.
    pub(crate) fn about(mut self, what: &str, name: &str) -> Self {
        self.message = match what {
            "scenario" => format!("scenario `{name}`: {}", self.message),
            _ => format!("`{name}`: {}", self.message),
        };
        if let Some(serde_json::Value::Object(d)) = &mut self.detail {
            d.insert(what.to_owned(), serde_json::Value::String(name.to_owned()));
        }
        self
    }
}

impl From<String> for Refusal {
    fn from(message: String) -> Self {
        Self {
            message,
            detail: None,
        }
    }
}

impl From<rtnav::Error> for Refusal {
    fn from(e: rtnav::Error) -> Self {
        Self {
            message: e.to_string(),
            detail: serde_json::to_value(e.detail()).ok(),
        }
    }
}

impl std::fmt::Display for Refusal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::ops::Deref for Refusal {
    type Target = str;
    fn deref(&self) -> &str {
        &self.message
    }
}

impl PartialEq<&str> for Refusal {
    fn eq(&self, other: &&str) -> bool {
        self.message == *other
    }
}

impl From<PageError> for Refusal {
    fn from(e: PageError) -> Self {
        let fields = match serde_json::to_value(&e) {
            Ok(serde_json::Value::Object(mut m)) => {
                m.remove("kind");
                serde_json::Value::Object(m)
            }
            _ => serde_json::Value::Object(serde_json::Map::new()),
        };
        let kind: &'static str = (&e).into();
        Self {
            message: e.to_string(),
            detail: Some(serde_json::json!({"area": "Page", "kind": kind, "fields": fields})),
        }
    }
}

/// A refusal of the core's, with its detail.
pub(crate) fn refused(e: impl Into<rtnav::Error>) -> Refusal {
    Refusal::from(e.into())
}

/// A message without detail (an error that is not the core's: JSON, UTF-8).
pub(crate) fn msg(e: impl std::fmt::Display) -> Refusal {
    Refusal::from(e.to_string())
}

#[wasm_bindgen]
extern "C" {
    #[wasm_bindgen(js_namespace = Reflect, js_name = set)]
    fn reflect_set(target: &JsValue, key: &JsValue, value: &JsValue) -> bool;
    #[wasm_bindgen(js_namespace = JSON, js_name = parse, catch)]
    fn json_parse(text: &str) -> Result<JsValue, JsValue>;
}

/// A refusal as a JavaScript `Error`: `message` the English words, `detail` the error as
/// data (`{area, kind, fields, file?, scenario?}`) when the core refused.
pub(crate) fn js(e: Refusal) -> JsValue {
    let error: JsValue = JsError::new(&e.message).into();
    let detail = e.detail.and_then(|d| serde_json::to_string(&d).ok());
    if let Some(Ok(detail)) = detail.map(|d| json_parse(&d)) {
        reflect_set(&error, &JsValue::from_str("detail"), &detail);
    }
    error
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeMap;

    use rtnav::system::{
        ComponentActivity, EventKind, Held, InputSummary, ParameterWarning, RequestSource,
        ZeroOutput,
    };
    use strum::VariantNames;

    use super::*;

    /// One of the page's catalogues (`web/i18n/LANG.json`).
    fn catalogue(lang: &str) -> BTreeMap<String, String> {
        let path = format!("{}/../web/i18n/{lang}.json", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
        serde_json::from_str(&text).unwrap_or_else(|e| panic!("{path}: {e}"))
    }

    /// The keys the page says the core's facts with, from the code's own lists:
    /// `event.<Kind>` for every [`EventKind`], `error.<Area>.<Kind>` for every
    /// [`rtnav::Error::KINDS`] and every [`PageError`], `rtcstatus.<kind>` for every
    /// [`ComponentActivity`], `held.<flag>` for every [`Held`], `reason.<kind>` for every
    /// [`rtnav::Reason`], `warning.<kind>` for every [`ParameterWarning`], `input.<Kind>` for
    /// every [`InputSummary`], `source.<Source>` for every [`RequestSource`] and
    /// `rtcstatus.zero.<output>` for every [`ZeroOutput`].
    fn wanted() -> Vec<String> {
        let lists: [(&str, &[&str]); 8] = [
            ("event", EventKind::VARIANTS),
            ("rtcstatus", ComponentActivity::KINDS),
            ("held", Held::VARIANTS),
            ("reason", rtnav::Reason::KINDS),
            ("warning", ParameterWarning::KINDS),
            ("input", InputSummary::VARIANTS),
            ("source", RequestSource::VARIANTS),
            ("rtcstatus.zero", ZeroOutput::VARIANTS),
        ];
        let mut keys: Vec<String> = lists
            .iter()
            .flat_map(|(prefix, kinds)| kinds.iter().map(move |k| format!("{prefix}.{k}")))
            .collect();
        for (area, kinds) in rtnav::Error::KINDS {
            keys.extend(kinds.iter().map(|k| format!("error.{area}.{k}")));
        }
        keys.extend(
            PageError::VARIANTS
                .iter()
                .map(|k| format!("error.Page.{k}")),
        );
        keys
    }

    fn lacking(catalogue: &BTreeMap<String, String>) -> Vec<String> {
        wanted()
            .into_iter()
            .filter(|k| !catalogue.contains_key(k))
            .collect()
    }

    #[test]
    fn every_event_and_error_kind_has_words_in_both_languages() {
        assert!(wanted().len() > 100, "{}", wanted().len());
        assert!(wanted().contains(&"event.Bump".to_owned()));
        assert!(wanted().contains(&"error.Lifecycle.InvalidTransition".to_owned()));
        for key in [
            "rtcstatus.local_planning",
            "rtcstatus.in_error",
            "reason.bump",
            "reason.map_update_refused",
            "warning.clearance",
            "input.MapUpdate",
            "held.start_and_goal",
            "source.Replay",
        ] {
            assert!(wanted().contains(&key.to_owned()), "{key}");
        }
        for lang in ["en", "ja"] {
            assert_eq!(
                lacking(&catalogue(lang)),
                Vec::<String>::new(),
                "{lang}.json"
            );
        }
        // The check can fail: a catalogue without one kind's words is found out.
        let mut less = catalogue("ja");
        less.remove("error.Config.OutOfRange");
        less.remove("rtcstatus.following_path");
        assert_eq!(
            lacking(&less),
            ["rtcstatus.following_path", "error.Config.OutOfRange"]
        );
    }

    /// A refusal of the core's carries its detail; the page's own carry area `Page`.
    #[test]
    fn refusals_carry_their_detail() {
        let r = refused(rtnav::errors::SessionError::BadSpeed {
            speed: 32.0,
            min: 0.25,
            max: 16.0,
        });
        assert_eq!(r, "speed 32× is outside 0.25× to 16×");
        assert_eq!(
            r.detail,
            Some(serde_json::json!({"area": "Session", "kind": "BadSpeed",
                                    "fields": {"speed": 32.0, "min": 0.25, "max": 16.0}}))
        );
        let p = Refusal::from(PageError::FileCount { count: 2 });
        assert!(p.message.starts_with("2 files chosen: expected"), "{p}");
        assert_eq!(
            p.detail,
            Some(serde_json::json!({"area": "Page", "kind": "FileCount", "fields": {"count": 2}}))
        );
        let f = refused(rtnav::errors::GlobalPlanningError::NoMap).about("file", "a.json");
        assert_eq!(f, "`a.json`: no map has been set");
        assert_eq!(f.detail.unwrap()["file"], "a.json");
        assert_eq!(msg("plain").detail, None);
    }
}
