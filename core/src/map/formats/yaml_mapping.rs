//! The top-level mapping of a YAML document, read from `saphyr-parser`'s events: what a ROS
//! map_server YAML file is (a flat mapping of scalars and one sequence, `origin`).
//!
//! The YAML grammar is the parser's (block and flow styles, quoting, comments, anchors);
//! this module only collects the mapping's keys with their scalar or sequence-of-scalars
//! values, as text. Values nested deeper (a mapping, a sequence of sequences) are kept as
//! [`Value::Nested`]: a key nobody reads may hold anything. Scalars are typed by the reader
//! ([`Mapping::number`], …), leniently as yaml-cpp (map_server's reader) does: a quoted
//! `'0.05'` is a number too.

use std::collections::BTreeMap;

use saphyr_parser::{Event, Parser, ScanError};

/// A value under a top-level key.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Value {
    /// A scalar's text.
    Scalar(String),
    /// A sequence of scalars.
    Sequence(Vec<String>),
    /// Anything deeper, or an alias.
    Nested,
}

/// A problem, with its 1-based line where it has one.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Problem {
    pub line: Option<usize>,
    pub reason: String,
}

impl Problem {
    fn at(line: usize, reason: impl Into<String>) -> Self {
        Self {
            line: Some(line),
            reason: reason.into(),
        }
    }

    fn anywhere(reason: impl Into<String>) -> Self {
        Self {
            line: None,
            reason: reason.into(),
        }
    }
}

impl From<ScanError> for Problem {
    fn from(e: ScanError) -> Self {
        Self::at(e.marker().line(), e.info())
    }
}

/// The document's top-level mapping: each key with its value and the value's line.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct Mapping(BTreeMap<String, (Value, usize)>);

impl Mapping {
    /// Reads the first document of `text`, which must be a mapping with scalar keys, each
    /// key once.
    pub(crate) fn parse(text: &str) -> Result<Self, Problem> {
        let mut events = Parser::new_from_str(text);
        let mut next = move || -> Result<(Event<'_>, usize), Problem> {
            match events.next_event() {
                Some(Ok((event, span))) => Ok((event, span.start.line())),
                Some(Err(e)) => Err(e.into()),
                None => Err(Problem::anywhere("unexpected end of the YAML stream")),
            }
        };
        // StreamStart, then the first document (or none: an empty file).
        loop {
            match next()? {
                (Event::StreamStart, _) => {}
                (Event::DocumentStart(_), _) => break,
                (Event::StreamEnd, _) => return Err(Problem::anywhere("the file is empty")),
                (_, line) => return Err(Problem::at(line, "expected a YAML document")),
            }
        }
        match next()? {
            (Event::MappingStart(..), _) => {}
            (_, line) => {
                return Err(Problem::at(
                    line,
                    "expected a mapping of `key: value` lines",
                ));
            }
        }
        let mut map = BTreeMap::new();
        loop {
            let (key, line) = match next()? {
                (Event::MappingEnd, _) => return Ok(Self(map)),
                (Event::Scalar(key, ..), line) => (key.into_owned(), line),
                (_, line) => return Err(Problem::at(line, "a key must be a plain text")),
            };
            let value = match next()? {
                (Event::Scalar(text, ..), _) => Value::Scalar(text.into_owned()),
                (Event::SequenceStart(..), _) => sequence(&mut next)?,
                (Event::MappingStart(..), _) => {
                    skip(&mut next)?;
                    Value::Nested
                }
                _ => Value::Nested,
            };
            if map.insert(key.clone(), (value, line)).is_some() {
                return Err(Problem::at(
                    line,
                    format!("duplicate key `{}`", super::shown(&key)),
                ));
            }
        }
    }

    /// The value of `key`, if present.
    fn get(&self, key: &str) -> Option<&(Value, usize)> {
        self.0.get(key)
    }

    /// The scalar under `key`: `None` if the key is absent.
    pub(crate) fn text(&self, key: &str) -> Result<Option<&str>, Problem> {
        match self.get(key) {
            None => Ok(None),
            Some((Value::Scalar(s), _)) => Ok(Some(s)),
            Some((_, line)) => Err(Problem::at(*line, format!("`{key}` must be a scalar"))),
        }
    }

    /// The scalar under `key`, which must be present.
    pub(crate) fn required_text(&self, key: &str) -> Result<&str, Problem> {
        self.text(key)?
            .ok_or_else(|| Problem::anywhere(format!("missing field `{key}`")))
    }

    /// The number under `key`, which must be present.
    pub(crate) fn number(&self, key: &str) -> Result<f64, Problem> {
        let text = self.required_text(key)?;
        number(text).ok_or_else(|| self.wrong(key, "a number", text))
    }

    /// The numbers of the sequence under `key`, which must be present.
    pub(crate) fn numbers(&self, key: &str) -> Result<Vec<f64>, Problem> {
        match self.get(key) {
            None => Err(Problem::anywhere(format!("missing field `{key}`"))),
            Some((Value::Sequence(items), _)) => items
                .iter()
                .map(|t| number(t).ok_or_else(|| self.wrong(key, "numbers", t)))
                .collect(),
            Some((_, line)) => Err(Problem::at(
                *line,
                format!("`{key}` must be a sequence of numbers, as [x, y, yaw]"),
            )),
        }
    }

    /// The line of `key`'s value and a reason: `key` should be `what`, not `text`.
    pub(crate) fn wrong(&self, key: &str, what: &str, text: &str) -> Problem {
        Problem {
            line: self.get(key).map(|(_, line)| *line),
            reason: format!("`{key}`: expected {what}, found `{}`", super::shown(text)),
        }
    }
}

/// The scalars of a sequence, after its `SequenceStart`.
fn sequence<'a>(
    next: &mut impl FnMut() -> Result<(Event<'a>, usize), Problem>,
) -> Result<Value, Problem> {
    let mut items = Vec::new();
    loop {
        match next()? {
            (Event::SequenceEnd, _) => return Ok(Value::Sequence(items)),
            (Event::Scalar(text, ..), _) => items.push(text.into_owned()),
            (Event::SequenceStart(..) | Event::MappingStart(..), _) => {
                skip(next)?; // the inner collection
                skip(next)?; // the rest of this one
                return Ok(Value::Nested);
            }
            _ => {
                skip(next)?;
                return Ok(Value::Nested);
            }
        }
    }
}

/// Skips to the end of the collection whose start event was just read.
fn skip<'a>(next: &mut impl FnMut() -> Result<(Event<'a>, usize), Problem>) -> Result<(), Problem> {
    let mut depth = 1usize;
    while depth > 0 {
        match next()? {
            (Event::SequenceStart(..) | Event::MappingStart(..), _) => depth += 1,
            (Event::SequenceEnd | Event::MappingEnd, _) => depth -= 1,
            _ => {}
        }
    }
    Ok(())
}

/// A YAML number (core schema: decimal and exponent forms, `.inf`, `-.inf`, `.nan` in any
/// of their spellings), as the nearest `f64`.
pub(crate) fn number(text: &str) -> Option<f64> {
    let t = text.trim();
    let (sign, body) = match t.strip_prefix('-') {
        Some(rest) => (-1.0, rest),
        None => (1.0, t.strip_prefix('+').unwrap_or(t)),
    };
    match body {
        ".inf" | ".Inf" | ".INF" => return Some(sign * f64::INFINITY),
        ".nan" | ".NaN" | ".NAN" if body == t => return Some(f64::NAN),
        _ => {}
    }
    // Digits, one point, an exponent: what Rust's parser accepts less its words ("inf",
    // "NaN", "infinity"), which are not YAML numbers.
    if body.is_empty()
        || body
            .bytes()
            .any(|b| b.is_ascii_alphabetic() && b != b'e' && b != b'E')
    {
        return None;
    }
    t.parse().ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_flat_mapping_in_block_and_flow_style() {
        let m = Mapping::parse(
            "# map_server\nimage: 'a b.pgm'\nresolution: 0.050000\norigin: [-1.5, 2, 0.0]\n\
             negate: 0\nnested: {a: [1, 2]}\nlist:\n  - 1\n  - [2]\n",
        )
        .unwrap();
        assert_eq!(m.required_text("image").unwrap(), "a b.pgm");
        assert_eq!(m.number("resolution").unwrap(), 0.05);
        assert_eq!(m.numbers("origin").unwrap(), [-1.5, 2.0, 0.0]);
        assert_eq!(m.text("negate").unwrap(), Some("0"));
        assert_eq!(m.get("nested").unwrap().0, Value::Nested);
        assert_eq!(m.get("list").unwrap().0, Value::Nested);
        assert_eq!(m.text("mode").unwrap(), None);
    }

    #[test]
    fn problems_name_the_line() {
        let dup = Mapping::parse("a: 1\nb: 2\na: 3\n").unwrap_err();
        assert_eq!(dup, Problem::at(3, "duplicate key `a`"));
        let m = Mapping::parse("a: 1\nb: x\n").unwrap();
        assert_eq!(m.number("b").unwrap_err().line, Some(2));
        assert_eq!(
            m.number("c").unwrap_err().reason,
            "missing field `c`".to_owned()
        );
        assert!(Mapping::parse("- 1\n- 2\n").is_err());
        assert!(Mapping::parse("").is_err());
        assert!(Mapping::parse("a: [1, 2\n").unwrap_err().line.is_some());
    }

    #[test]
    fn numbers_of_the_core_schema() {
        assert_eq!(number("1e-3"), Some(0.001));
        assert_eq!(number("+.5"), Some(0.5));
        assert_eq!(number("-.inf"), Some(f64::NEG_INFINITY));
        assert!(number(".nan").unwrap().is_nan());
        for bad in ["inf", "NaN", "", "1.0.0", "abc", "0x10"] {
            assert_eq!(number(bad), None, "{bad}");
        }
    }
}
