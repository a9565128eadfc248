//! A reader for OpenRTM `.conf` files (spec §1 Decision; 000/002 §4.1 "変更方法２").
//!
//! OpenRTM writes them as Java-style properties: `key: value` (or `key = value`), `#` and `!`
//! comments, blank lines. The keys rtnav understands:
//! - `conf.<set>.<NAME>`: a parameter value in configuration set `<set>` (`default` first);
//! - `conf.__widget__.<NAME>`: the RT System Editor widget for a parameter (kept);
//! - `conf.__constraints__.<NAME>`, `conf.__type__.<NAME>`, `conf.__description__.<NAME>`:
//!   metadata RTCBuilder writes (names are checked, values ignored: the range is the seed's);
//! - `configuration.active_config`: the set to activate;
//! - `exec_cxt.periodic.rate`: the component's rate (recognised; the system applies rates).
//!
//! Any other key is an error naming the key and the line; names inside `conf.*` are checked
//! against the component's parameters when the file is applied ([`super::ConfigAccess::load_conf`]).

use core::fmt;

use crate::errors::ConfigError;
use crate::present::excerpt;

/// What a `.conf` key refers to.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ConfKey {
    /// `conf.<set>.<name>`.
    Param {
        /// The configuration set.
        set: String,
        /// The parameter.
        name: String,
    },
    /// `conf.__widget__.<name>`.
    Widget {
        /// The parameter.
        name: String,
    },
    /// `conf.__constraints__.<name>` and the like.
    Meta {
        /// `constraints`, `type` or `description`.
        kind: String,
        /// The parameter.
        name: String,
    },
    /// `configuration.active_config`.
    ActiveSet,
    /// `exec_cxt.periodic.rate`.
    ExecutionRate,
}

/// The key as a `.conf` file writes it, e.g. `conf.default.dmin` (errors name it).
impl fmt::Display for ConfKey {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Param { set, name } => write!(f, "conf.{set}.{name}"),
            Self::Widget { name } => write!(f, "conf.__widget__.{name}"),
            Self::Meta { kind, name } => write!(f, "conf.__{kind}__.{name}"),
            Self::ActiveSet => f.write_str("configuration.active_config"),
            Self::ExecutionRate => f.write_str("exec_cxt.periodic.rate"),
        }
    }
}

/// One `key: value` line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ConfEntry {
    /// 1-based line number.
    pub line: usize,
    /// The key, interpreted.
    pub key: ConfKey,
    /// The value as written (trimmed).
    pub value: String,
}

/// A parsed `.conf` file.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct ConfFile {
    /// The entries in file order.
    pub entries: Vec<ConfEntry>,
}

const META: [&str; 3] = ["__constraints__", "__type__", "__description__"];

/// `text` without a leading UTF-8 byte order mark (U+FEFF, which some editors write at the
/// start of a file and `str::trim` keeps): the one place every text reader of rtnav — `.conf`
/// files and bundles, scenario and replay JSON, the map formats — drops it.
pub fn without_bom(text: &str) -> &str {
    text.strip_prefix('\u{feff}').unwrap_or(text)
}

impl ConfFile {
    /// Parses the text of a `.conf` file (a leading byte order mark is skipped).
    pub fn parse(text: &str) -> Result<Self, ConfigError> {
        let mut entries = Vec::new();
        for (n, raw) in without_bom(text).lines().enumerate() {
            let line = n + 1;
            let t = raw.trim();
            if t.is_empty() || t.starts_with('#') || t.starts_with('!') {
                continue;
            }
            let syntax = |reason: &str| ConfigError::Syntax {
                line,
                text: excerpt(raw),
                reason: reason.to_owned(),
            };
            let sep = t
                .find([':', '='])
                .ok_or_else(|| syntax("expected `key: value`"))?;
            let key = t[..sep].trim();
            let value = t[sep + 1..].trim().to_owned();
            if key.is_empty() {
                return Err(syntax("empty key"));
            }
            let key = Self::key(key).ok_or_else(|| ConfigError::UnknownParameter {
                name: excerpt(key),
                line: Some(line),
            })?;
            entries.push(ConfEntry { line, key, value });
        }
        Ok(Self { entries })
    }

    fn key(key: &str) -> Option<ConfKey> {
        match key {
            "configuration.active_config" => return Some(ConfKey::ActiveSet),
            "exec_cxt.periodic.rate" => return Some(ConfKey::ExecutionRate),
            _ => {}
        }
        let rest = key.strip_prefix("conf.")?;
        let (set, name) = rest.split_once('.')?;
        if set.is_empty() || name.is_empty() || name.contains('.') {
            return None;
        }
        let name = name.to_owned();
        Some(if set == "__widget__" {
            ConfKey::Widget { name }
        } else if META.contains(&set) {
            ConfKey::Meta {
                kind: set.trim_matches('_').to_owned(),
                name,
            }
        } else {
            ConfKey::Param {
                set: set.to_owned(),
                name,
            }
        })
    }
}
