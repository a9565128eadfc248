//! The scenario file's JSON Schema and the check of a file against it (`rtnav scenario
//! schema`, `rtnav scenario check`).
//!
//! The schema is made from the core's own types (`rtnav::system::Scenario` and every type
//! it holds, `schemars::JsonSchema` with rtnav's feature `schema`), so it says exactly what
//! the core reads: the keys, which are required, their types, defaults and documentation,
//! and that unknown keys are refused. It is kept in the repository as
//! `docs/scenario.schema.json` for editors (their JSON settings map `fixtures/scenarios/*.json`
//! to it; a scenario file cannot name it, the core refuses unknown keys such as `$schema`); the
//! test `cli/tests/scenario_schema.rs` fails when that file is not what the types give, and
//! writes it with `RTNAV_WRITE_SCHEMA=1`.
//!
//! [`problems`] checks a file's text against the schema and says where each problem is —
//! the path in the file (`events[2].boxes[0].x`) and the line and column — in plain words.

use rtnav::system::Scenario;
use serde_json::Value;

/// Where the committed schema is, relative to the project's root.
pub const SCHEMA_PATH: &str = "docs/scenario.schema.json";

/// The scenario file's JSON Schema (draft 2020-12), as JSON.
pub fn schema() -> Value {
    let mut schema = schemars::schema_for!(Scenario).to_value();
    plain_descriptions(&mut schema);
    if let Some(root) = schema.as_object_mut() {
        root.insert(
            "title".to_owned(),
            Value::String("rtnav scenario".to_owned()),
        );
        root.insert(
            "description".to_owned(),
            Value::String(
                "A scenario of rtnav (fixtures/scenarios/*.json): a map, a start and a goal, \
                 configuration, timed events, the expected outcome and, optionally, an \
                 exercise. Written from the core's types; see docs/authoring.md."
                    .to_owned(),
            ),
        );
    }
    schema
}

/// Every `description` (the types' documentation) as plain text for a teacher: without
/// rustdoc's escapes (`\[m\]` → `[m]`) and links (`` [`Exercise`] `` → `` `Exercise` ``), one
/// paragraph a line.
fn plain_descriptions(value: &mut Value) {
    match value {
        Value::Object(map) => {
            for (key, v) in map.iter_mut() {
                match v {
                    Value::String(text) if key == "description" => *text = plain(text),
                    _ => plain_descriptions(v),
                }
            }
        }
        Value::Array(items) => items.iter_mut().for_each(plain_descriptions),
        _ => {}
    }
}

fn plain(doc: &str) -> String {
    let unescaped = doc.replace("\\[", "\u{1}").replace("\\]", "\u{2}");
    let mut out = String::new();
    let mut rest = unescaped.as_str();
    // [`name`](target) and [`name`] → `name`.
    while let Some(at) = rest.find("[`") {
        out.push_str(&rest[..at]);
        let after = &rest[at + 1..];
        match after.find("`]") {
            Some(end) => {
                out.push_str(&after[..=end]);
                rest = &after[end + 2..];
                if let (true, Some(close)) = (rest.starts_with('('), rest.find(')')) {
                    rest = &rest[close + 1..];
                }
            }
            None => {
                out.push('[');
                rest = after;
            }
        }
    }
    out.push_str(rest);
    let out = out.replace('\u{1}', "[").replace('\u{2}', "]");
    out.split("\n\n")
        .map(|para| {
            para.split('\n')
                .map(str::trim)
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// [`schema`] as the committed file's text (pretty, one newline at the end).
pub fn schema_text() -> String {
    let mut text = serde_json::to_string_pretty(&schema()).unwrap_or_default();
    text.push('\n');
    text
}

/// One thing wrong with a file, and where.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Problem {
    /// The path in the file, as a reader writes it (`events[2].at`; `(the file)` for the
    /// whole file).
    pub path: String,
    /// The line, from 1.
    pub line: usize,
    /// The column, from 1 (characters).
    pub column: usize,
    /// What is wrong, in plain words.
    pub message: String,
}

impl core::fmt::Display for Problem {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "line {}, column {}: {}: {}",
            self.line, self.column, self.path, self.message
        )
    }
}

/// What is wrong with `text` as a scenario file by the schema (nothing: an empty list). Text
/// that is not JSON is one problem, where the JSON breaks.
pub fn problems(text: &str) -> Vec<Problem> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let value: Value = match serde_json::from_str(text) {
        Ok(v) => v,
        Err(e) => {
            return vec![Problem {
                path: "(the file)".to_owned(),
                line: e.line(),
                column: e.column(),
                message: format!("not valid JSON: {}", strip_position(&e.to_string())),
            }];
        }
    };
    let schema = schema();
    let validator = match jsonschema::validator_for(&schema) {
        Ok(v) => v,
        Err(e) => {
            return vec![Problem {
                path: "(the schema)".to_owned(),
                line: 1,
                column: 1,
                message: format!("the schema itself is not valid (a defect): {e}"),
            }];
        }
    };
    let mut found = Vec::new();
    let mut keys = Vec::new();
    for error in validator.iter_errors(&value) {
        explain(&error, text, &mut found, &mut keys);
    }
    let mut found = with_spelling_hints(found, &keys);
    found.sort_by(|a, b| (a.line, a.column, &a.message).cmp(&(b.line, b.column, &b.message)));
    found.dedup();
    found
}

/// serde_json's message without its ` at line L column C` (given apart).
fn strip_position(message: &str) -> String {
    match message.rfind(" at line ") {
        Some(i) => message[..i].to_owned(),
        None => message.to_owned(),
    }
}

/// The JSON pointer's segments (`/events/2/at` → `events`, `2`, `at`).
fn segments(pointer: &str) -> Vec<String> {
    pointer
        .split('/')
        .skip(1)
        .map(|s| s.replace("~1", "/").replace("~0", "~"))
        .collect()
}

/// A pointer as a reader writes a path: `events[2].boxes[0].x`.
fn readable(segments: &[String]) -> String {
    if segments.is_empty() {
        return "(the top level)".to_owned();
    }
    let mut out = String::new();
    for s in segments {
        if s.bytes().all(|b| b.is_ascii_digit()) && !s.is_empty() {
            out.push_str(&format!("[{s}]"));
        } else {
            if !out.is_empty() {
                out.push('.');
            }
            out.push_str(s);
        }
    }
    out
}

/// A key found missing or unknown: where (the object's readable path), which, and whether
/// it is missing (else unknown).
type KeyNote = (String, String, bool);

/// A missing key and an unknown one of the same object that differ by a letter or two are
/// one misspelling: said once, at the unknown key, with the name meant.
fn with_spelling_hints(found: Vec<Problem>, keys: &[KeyNote]) -> Vec<Problem> {
    let mut drop = Vec::new();
    let mut hints = Vec::new();
    for (object, unknown, _) in keys.iter().filter(|k| !k.2) {
        let meant = keys
            .iter()
            .filter(|k| k.2 && &k.0 == object)
            .find(|k| edit_distance(&k.1, unknown) <= 2);
        if let Some((_, missing, _)) = meant {
            drop.push(missing_message(missing));
            hints.push((unknown.clone(), missing.clone()));
        }
    }
    found
        .into_iter()
        .filter(|p| !drop.contains(&p.message))
        .map(|mut p| {
            for (unknown, missing) in &hints {
                if p.message == unknown_message(std::slice::from_ref(unknown)) {
                    p.message = format!("unknown key `{unknown}`: did you mean `{missing}`?");
                }
            }
            p
        })
        .collect()
}

fn missing_message(key: &str) -> String {
    format!("the key \"{key}\" is missing")
}

fn unknown_message(unexpected: &[String]) -> String {
    format!(
        "unknown key{} {} (misspelt, or not allowed here)",
        if unexpected.len() > 1 { "s" } else { "" },
        unexpected
            .iter()
            .map(|k| format!("`{k}`"))
            .collect::<Vec<_>>()
            .join(", ")
    )
}

/// Levenshtein distance (keys are short).
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let cost = usize::from(ca != *cb);
            let next = (row[j + 1] + 1).min(row[j] + 1).min(prev + cost);
            prev = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

fn explain(
    error: &jsonschema::ValidationError<'_>,
    text: &str,
    out: &mut Vec<Problem>,
    keys: &mut Vec<KeyNote>,
) {
    use jsonschema::error::ValidationErrorKind as Kind;
    let mut path = segments(error.instance_path().as_str());
    let message = match error.kind() {
        Kind::OneOfNotValid { context } | Kind::AnyOf { context } => {
            // The form the value meant (its tag matched, or fewest problems): its problems.
            let meant = context
                .iter()
                .filter(|branch| !branch.is_empty())
                .min_by_key(|branch| {
                    let tag_wrong = branch.iter().any(|e| {
                        matches!(e.kind(), Kind::Constant { .. } | Kind::Enum { .. })
                            && segments(e.instance_path().as_str()).len() == path.len() + 1
                    });
                    (tag_wrong, branch.len())
                });
            match meant {
                Some(branch) => {
                    for e in branch {
                        explain(e, text, out, keys);
                    }
                    return;
                }
                None => "matches none of the forms allowed here".to_owned(),
            }
        }
        Kind::AdditionalProperties { unexpected } => {
            let object = readable(&path);
            if let [key] = unexpected.as_slice() {
                keys.push((object, key.clone(), false));
            }
            if let Some(key) = unexpected.first() {
                path.push(key.clone());
            }
            unknown_message(unexpected)
        }
        Kind::Required { property } => {
            let key = property
                .as_str()
                .map_or_else(|| property.to_string(), str::to_owned);
            keys.push((readable(&path), key.clone(), true));
            missing_message(&key)
        }
        Kind::Type { kind } => format!(
            "{} is {}, expected {}",
            excerpt(error.instance()),
            type_name(error.instance()),
            type_words(&format!("{kind:?}"))
        ),
        Kind::Constant { expected_value } => {
            format!("{} must be {expected_value}", excerpt(error.instance()))
        }
        Kind::Enum { options } => format!(
            "{} is not one of {}",
            excerpt(error.instance()),
            options
                .as_array()
                .map(|a| a
                    .iter()
                    .map(Value::to_string)
                    .collect::<Vec<_>>()
                    .join(", "))
                .unwrap_or_else(|| options.to_string())
        ),
        Kind::Minimum { limit } => format!("{} is below {limit}", excerpt(error.instance())),
        Kind::ExclusiveMinimum { limit } => {
            format!("{} must be more than {limit}", excerpt(error.instance()))
        }
        Kind::Maximum { limit } => format!("{} is above {limit}", excerpt(error.instance())),
        Kind::MinItems { limit } | Kind::MaxItems { limit } => format!(
            "{} items, expected {limit}",
            error.instance().as_array().map_or(0, Vec::len)
        ),
        _ => error.to_string(),
    };
    let at = locate(text, &path);
    let (line, column) = line_column(text, at);
    out.push(Problem {
        path: readable(&path),
        line,
        column,
        message,
    });
}

fn excerpt(value: &Value) -> String {
    rtnav::present::excerpt(&value.to_string())
}

fn type_name(value: &Value) -> &'static str {
    match value {
        Value::Null => "null",
        Value::Bool(_) => "true or false",
        Value::Number(_) => "a number",
        Value::String(_) => "text",
        Value::Array(_) => "a list",
        Value::Object(_) => "an object",
    }
}

/// `Single(Number)`, `Multiple([Integer, Null])` in words.
fn type_words(debug: &str) -> String {
    let words: Vec<&str> = [
        ("Array", "a list"),
        ("Boolean", "true or false"),
        ("Integer", "a whole number"),
        ("Null", "null"),
        ("Number", "a number"),
        ("Object", "an object"),
        ("String", "text"),
    ]
    .iter()
    .filter(|(k, _)| debug.contains(k))
    .map(|(_, w)| *w)
    .collect();
    if words.is_empty() {
        debug.to_owned()
    } else {
        words.join(" or ")
    }
}

/// The byte offset, in `text`, of the value at `path` (as far as it exists; the top level's
/// when not at all). `text` is JSON that parsed.
pub fn locate(text: &str, path: &[String]) -> usize {
    let bytes = text.as_bytes();
    let mut at = skip_ws(bytes, 0);
    for seg in path {
        match find_child(bytes, at, seg) {
            Some(next) => at = next,
            None => break,
        }
    }
    at
}

/// The line and column (from 1; the column in characters) of byte `at`.
pub fn line_column(text: &str, at: usize) -> (usize, usize) {
    let at = rtnav::present::floor_char_boundary(text, at.min(text.len()));
    let before = &text[..at];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

fn skip_ws(b: &[u8], mut i: usize) -> usize {
    while i < b.len() && matches!(b[i], b' ' | b'\t' | b'\n' | b'\r') {
        i += 1;
    }
    i
}

/// The end (exclusive) of the string starting at `i` (its opening quote).
fn string_end(b: &[u8], mut i: usize) -> usize {
    i += 1;
    while i < b.len() {
        match b[i] {
            b'\\' => i += 2,
            b'"' => return i + 1,
            _ => i += 1,
        }
    }
    b.len()
}

/// The end (exclusive) of the value starting at `i`.
fn value_end(b: &[u8], i: usize) -> usize {
    match b.get(i) {
        Some(b'"') => string_end(b, i),
        Some(b'{' | b'[') => {
            let mut depth = 0usize;
            let mut j = i;
            while j < b.len() {
                match b[j] {
                    b'"' => {
                        j = string_end(b, j);
                        continue;
                    }
                    b'{' | b'[' => depth += 1,
                    b'}' | b']' => {
                        depth -= 1;
                        if depth == 0 {
                            return j + 1;
                        }
                    }
                    _ => {}
                }
                j += 1;
            }
            b.len()
        }
        _ => {
            let mut j = i;
            while j < b.len() && !matches!(b[j], b',' | b'}' | b']' | b' ' | b'\t' | b'\n' | b'\r')
            {
                j += 1;
            }
            j
        }
    }
}

/// The start of the member `seg` of the object or array starting at `i` (for an object's
/// key: where its value starts).
fn find_child(b: &[u8], i: usize, seg: &str) -> Option<usize> {
    match b.get(i)? {
        b'{' => {
            let mut j = skip_ws(b, i + 1);
            while b.get(j) == Some(&b'"') {
                let key_end = string_end(b, j);
                let key: String = serde_json::from_slice(&b[j..key_end]).ok()?;
                let colon = skip_ws(b, key_end);
                let value = skip_ws(b, colon + 1);
                if key == seg {
                    return Some(value);
                }
                j = skip_ws(b, value_end(b, value));
                if b.get(j) == Some(&b',') {
                    j = skip_ws(b, j + 1);
                }
            }
            None
        }
        b'[' => {
            let index: usize = seg.parse().ok()?;
            let mut j = skip_ws(b, i + 1);
            for _ in 0..index {
                if b.get(j) == Some(&b']') {
                    return None;
                }
                j = skip_ws(b, value_end(b, j));
                if b.get(j) == Some(&b',') {
                    j = skip_ws(b, j + 1);
                }
            }
            (b.get(j) != Some(&b']')).then_some(j)
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_are_located_by_their_path() {
        let text = "{\n  \"a\": {\"b\": [1, {\"c\": \"x,}\"}, 3]},\n  \"d\": true\n}";
        let at = |p: &[&str]| {
            let path: Vec<String> = p.iter().map(|s| s.to_string()).collect();
            line_column(text, locate(text, &path))
        };
        assert_eq!(at(&[]), (1, 1));
        assert_eq!(at(&["a", "b", "1", "c"]), (2, 24));
        assert_eq!(at(&["a", "b", "2"]), (2, 32));
        assert_eq!(at(&["d"]), (3, 8));
        // A path that goes further than the file: as far as it goes.
        assert_eq!(at(&["d", "e"]), (3, 8));
        assert_eq!(
            readable(&["events".into(), "2".into(), "at".into()]),
            "events[2].at"
        );
    }

    #[test]
    fn descriptions_are_plain_text() {
        assert_eq!(
            plain("X \\[m\\], see [`Exercise`] and\n[`MAX`](crate::MAX).\n\nMore [a]."),
            "X [m], see `Exercise` and `MAX`.\nMore [a]."
        );
    }
}
