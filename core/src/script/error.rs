//! What goes wrong in a student's script (spec §8, Decision 0.4 "the actions", "loading",
//! "bounds"): every error names where — the action, the line and the column — and says what
//! went wrong in the student's terms.

use serde::Serialize;

/// A script's error: refused at load, or an action's failure.
#[derive(Debug, Clone, PartialEq, thiserror::Error, Serialize, strum::VariantNames)]
#[serde(tag = "kind")]
#[non_exhaustive]
pub enum ScriptError {
    /// The script does not compile: the load is refused and nothing changes.
    #[error("syntax error at line {line}, column {column}: {message}")]
    Syntax {
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// What the parser found.
        message: String,
    },
    /// The script's declaration is missing or names no component a script can stand in for.
    #[error("{message}")]
    Declaration {
        /// What is wrong with it.
        message: String,
    },
    /// An action is defined with parameters a component cannot give it.
    #[error("`{action}` at line {line}: {message}")]
    Signature {
        /// The action.
        action: String,
        /// 1-based line of its definition.
        line: usize,
        /// What is wrong with it.
        message: String,
    },
    /// An action (or the script's top level, at load) failed: the script threw, hit a
    /// runtime error, or used a port, a sample or a parameter wrongly.
    #[error("{action}, line {line}, column {column}: {message}")]
    Runtime {
        /// The action (`on_execute`), or `top level`.
        action: String,
        /// 1-based line (0 where the engine knows none).
        line: usize,
        /// 1-based column (0 where the engine knows none).
        column: usize,
        /// What went wrong, in the student's terms.
        message: String,
    },
    /// An action ran past one of its bounds: the operations budget (an endless loop), the
    /// call depth, or the size of a string, an array or a map.
    #[error("{action}, line {line}, column {column}: {message}")]
    Bound {
        /// The action.
        action: String,
        /// 1-based line (0 where the engine knows none).
        line: usize,
        /// 1-based column (0 where the engine knows none).
        column: usize,
        /// Which bound, and its size.
        message: String,
    },
}

impl ScriptError {
    /// The action it names, if any.
    pub fn action(&self) -> Option<&str> {
        match self {
            Self::Runtime { action, .. }
            | Self::Bound { action, .. }
            | Self::Signature { action, .. } => Some(action),
            Self::Syntax { .. } | Self::Declaration { .. } => None,
        }
    }

    /// The `(line, column)` it names, 1-based, if any.
    pub fn position(&self) -> Option<(usize, usize)> {
        match self {
            Self::Syntax { line, column, .. }
            | Self::Runtime { line, column, .. }
            | Self::Bound { line, column, .. } => (*line > 0).then_some((*line, *column)),
            Self::Signature { line, .. } => Some((*line, 1)),
            Self::Declaration { .. } => None,
        }
    }

    /// The words without the place (what went wrong).
    pub fn message(&self) -> &str {
        match self {
            Self::Syntax { message, .. }
            | Self::Declaration { message }
            | Self::Signature { message, .. }
            | Self::Runtime { message, .. }
            | Self::Bound { message, .. } => message,
        }
    }
}
