//! What the page is told when a request is refused ([`Refusal`]): the English words and the
//! error as data — the core's [`rtnav::ErrorDetail`] — made a JavaScript `Error` with a
//! `detail` by [`js`].

use wasm_bindgen::prelude::*;

/// A result whose error is what the page shows. Kept apart from `JsValue` (which exists
/// only in a browser) so the native tests can check the exact words.
pub(crate) type Msg<T> = Result<T, Refusal>;

/// A refusal: the English words, and — when the core refused — the core's
/// [`rtnav::system::Refusal`] (`{area, kind, fields, file?, scenario?}`) for the page to
/// say in its language.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Refusal {
    /// The English words (the error's `Display`).
    pub message: String,
    /// The error as data.
    pub detail: Option<Box<rtnav::system::Refusal>>,
}

impl From<String> for Refusal {
    fn from(message: String) -> Self {
        Self {
            message,
            detail: None,
        }
    }
}

impl From<rtnav::system::Refusal> for Refusal {
    fn from(r: rtnav::system::Refusal) -> Self {
        Self {
            message: r.message.clone(),
            detail: Some(Box::new(r)),
        }
    }
}

impl From<rtnav::Error> for Refusal {
    fn from(e: rtnav::Error) -> Self {
        rtnav::system::Refusal::from(e).into()
    }
}

impl From<rtnav::system::PickError> for Refusal {
    fn from(e: rtnav::system::PickError) -> Self {
        rtnav::system::Refusal::from(e).into()
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

/// A refusal of the core's, with its detail.
pub(crate) fn refused(e: impl Into<rtnav::Error>) -> Refusal {
    Refusal::from(e.into())
}

/// A message without detail (an error that is not the core's: JSON).
pub(crate) fn msg(e: impl std::fmt::Display) -> Refusal {
    Refusal::from(e.to_string())
}

/// A core's view as a JavaScript value (its serde JSON, parsed by the engine's
/// `JSON.parse`: one pass each way, as fast as handing the text over).
pub(crate) fn value<T: serde::Serialize>(v: &T) -> Result<JsValue, JsValue> {
    let text = serde_json::to_string(v).map_err(|e| js(msg(e)))?;
    json_parse(&text)
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
    if let Some(Ok(detail)) = e.detail.map(|d| value(&d)) {
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
    /// [`rtnav::Error::KINDS`], `rtcstatus.<kind>` for every [`ComponentActivity`],
    /// `held.<flag>` for every [`Held`], `reason.<kind>` for every [`rtnav::Reason`],
    /// `warning.<kind>` for every [`ParameterWarning`], `input.<Kind>` for every
    /// [`InputSummary`], `source.<Source>` for every [`RequestSource`] and
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

    /// A refusal of the core's carries its detail; a picked file's names the file.
    #[test]
    fn refusals_carry_their_detail() {
        let r = refused(rtnav::errors::SessionError::BadSpeed {
            speed: 32.0,
            min: 0.25,
            max: 16.0,
        });
        assert_eq!(r, "speed 32× is outside 0.25× to 16×");
        assert_eq!(
            serde_json::to_value(r.detail).unwrap(),
            (serde_json::json!({"area": "Session", "kind": "BadSpeed",
                                    "fields": {"speed": 32.0, "min": 0.25, "max": 16.0}}))
        );
        let p = refused(rtnav::errors::SessionError::FileCount { count: 2 });
        assert!(p.message.starts_with("2 files chosen: expected"), "{p}");
        assert_eq!(
            serde_json::to_value(p.detail).unwrap(),
            (serde_json::json!({"area": "Session", "kind": "FileCount",
                                    "fields": {"count": 2}}))
        );
        let mut broken = rtnav::system::PickedFiles::new();
        broken.add("broken.json", b"{\"width\": 3".to_vec());
        let picked = Refusal::from(broken.load_map(1.0).unwrap_err());
        assert!(
            picked.message.starts_with("`broken.json`: rtnav JSON"),
            "{picked}"
        );
        assert_eq!(
            serde_json::to_value(picked.detail).unwrap()["file"],
            "broken.json"
        );
        assert_eq!(msg("plain").detail, None);
    }
}
