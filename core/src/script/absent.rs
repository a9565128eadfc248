//! A build without the feature `script`: no engine. A script cannot be compiled, and the
//! refusal says why; [`Program`] has no value here.

use super::error::ScriptError;

/// A compiled script, absent from this build (module documentation).
#[derive(Debug, Clone, PartialEq)]
pub enum Program {}

impl Program {
    /// Refused: this build has no script engine.
    pub fn compile(_name: &str, _source: &str) -> Result<Self, ScriptError> {
        Err(ScriptError::Declaration {
            message: "this build of rtnav has no script engine (it was built without its \
                      feature `script`)"
                .to_owned(),
        })
    }
    /// The script's text.
    pub fn source(&self) -> &str {
        match *self {}
    }
    /// Its name.
    pub fn name(&self) -> &str {
        match *self {}
    }
    /// The component its declaration names.
    pub fn declared(&self) -> Option<&str> {
        match *self {}
    }
}
