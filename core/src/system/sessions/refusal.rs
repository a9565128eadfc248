//! [`Refusal`]: a refused request as a user interface shows it — the core's English words,
//! and the error as data ([`ErrorDetail`]) with the file or scenario it was about, for the
//! page to say in its own language.

use serde::Serialize;

use super::picked_files::PickError;
use crate::errors::{Error, ErrorDetail};

/// A refused request: serialized as the detail the page reads (`{area, kind, fields,
/// file?, scenario?}`); the English words apart.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct Refusal {
    /// The English words (the error's `Display`, after the file or scenario it is about).
    #[serde(skip)]
    pub message: String,
    /// The error as data.
    #[serde(flatten)]
    pub detail: ErrorDetail,
    /// The file the error is about.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[cfg_attr(feature = "typescript", ts(optional))]
    pub file: Option<String>,
    /// The scenario the error is about.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[cfg_attr(feature = "typescript", ts(optional))]
    pub scenario: Option<String>,
}

impl Refusal {
    /// The refusal about the file `name`: the words start with it.
    pub fn about_file(mut self, name: &str) -> Self {
        self.message = format!("`{name}`: {}", self.message);
        self.file = Some(name.to_owned());
        self
    }

    /// The refusal about the scenario `name`: the words start with it.
    pub fn about_scenario(mut self, name: &str) -> Self {
        self.message = format!("scenario `{name}`: {}", self.message);
        self.scenario = Some(name.to_owned());
        self
    }
}

impl From<Error> for Refusal {
    fn from(e: Error) -> Self {
        Self {
            message: e.to_string(),
            detail: e.detail(),
            file: None,
            scenario: None,
        }
    }
}

impl From<PickError> for Refusal {
    fn from(e: PickError) -> Self {
        let r = Refusal::from(*e.error);
        match &e.file {
            Some(name) => r.about_file(name),
            None => r,
        }
    }
}
