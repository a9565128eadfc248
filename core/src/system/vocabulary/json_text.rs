//! The system's JSON texts — scenarios, replays, share links' set-ups — read in one way: a
//! leading UTF-8 byte order mark (which some editors write) is skipped, and serde_json's
//! terse message about a number it cannot read gets a hint a person can act on. JSON has no
//! `NaN` or `Infinity` (serde_json says only "expected value"), and a number beyond `f64`'s
//! range (`1e400`) is refused as "number out of range".
//!
//! The text is a person's (a file, a pasted link): whatever it holds, the answer is a value or
//! a message, never a panic, and the message is short — serde_json quotes what it could not
//! use (an unknown key, a string where a number belongs) in full, so each quotation is cut to
//! an excerpt and the whole message bounded ([`crate::present::with_short_quotes`]).
//! serde_json's column counts bytes: it is only ever used through
//! [`floor_char_boundary`](crate::present::floor_char_boundary).

use serde::de::DeserializeOwned;

use crate::present::{floor_char_boundary, with_short_quotes};
use crate::rtc::without_bom;

/// `text` (after a leading byte order mark) read as `T`; the error is serde_json's message,
/// with a hint when the problem is a number.
pub(in crate::system) fn parse<T: DeserializeOwned>(text: &str) -> Result<T, String> {
    let text = without_bom(text);
    serde_json::from_str(text).map_err(|e| explain(text, &e))
}

/// serde_json's message for `e`, met in `text`, with a hint when a number is the problem.
fn explain(text: &str, e: &serde_json::Error) -> String {
    let full = e.to_string();
    let position = format!(" at line {} column {}", e.line(), e.column());
    let message = match full.strip_suffix(&position) {
        Some(inner) => format!("{}{position}", with_short_quotes(inner)),
        None => with_short_quotes(&full),
    };
    let hint = if message.starts_with("number out of range") {
        Some("a JSON number must fit a 64-bit float (magnitude below about 1.8e308)")
    } else if not_a_number_at(text, e.line(), e.column()) {
        Some("JSON has no NaN or Infinity; write a number")
    } else {
        None
    };
    match hint {
        Some(hint) => format!("{message} ({hint})"),
        None => message,
    }
}

/// Whether the word at (1-based) `line` and `column` — where serde_json stopped — is a
/// spelling of NaN or infinity (`NaN`, `Infinity`, `-Infinity`, `inf`, …).
fn not_a_number_at(text: &str, line: usize, column: usize) -> bool {
    let Some(row) = line.checked_sub(1).and_then(|l| text.lines().nth(l)) else {
        return false;
    };
    // serde_json's column counts bytes and points at (or just past) the character it could
    // not read: look from the start of the word around it.
    let at = floor_char_boundary(row, column.saturating_sub(1));
    let start = row[..at]
        .char_indices()
        .rev()
        .find(|&(_, c)| !(c.is_ascii_alphanumeric() || c == '-' || c == '+' || c == '.'))
        .map_or(0, |(i, c)| i + c.len_utf8());
    let word = row[start..].trim_start_matches(['-', '+']);
    let lower: String = word
        .chars()
        .take(3)
        .collect::<String>()
        .to_ascii_lowercase();
    lower == "nan" || lower == "inf"
}

#[cfg(test)]
mod tests {
    use std::collections::BTreeMap;

    use super::*;
    use crate::present::MAX_MESSAGE_CHARS;

    fn error(text: &str) -> String {
        parse::<BTreeMap<String, f64>>(text).unwrap_err()
    }

    #[test]
    fn numbers_json_cannot_hold_are_explained() {
        let hint = "(JSON has no NaN or Infinity; write a number)";
        for text in [
            r#"{"x": NaN}"#,
            r#"{"x": Infinity}"#,
            r#"{"x": -Infinity}"#,
            "{\n  \"a\": 1,\n  \"x\": nan\n}",
            r#"{"x":inf}"#,
        ] {
            let e = error(text);
            assert!(e.ends_with(hint), "{text}: {e}");
        }
        let e = error(r#"{"x": 1e400}"#);
        assert!(
            e.starts_with("number out of range")
                && e.ends_with(
                    "(a JSON number must fit a 64-bit float (magnitude below about 1.8e308))"
                ),
            "{e}"
        );
        // Other problems keep serde_json's message alone.
        assert_eq!(
            error(r#"{"x": true}"#),
            "invalid type: boolean `true`, expected f64 at line 1 column 10"
        );
        assert!(!error(r#"{"x": }"#).contains("NaN"));
    }

    #[test]
    fn errors_after_multi_byte_characters_are_messages_not_panics() {
        // serde_json's column counts bytes: each of these stops inside or just after a
        // character of two, three or four bytes.
        for text in [
            "\"é",
            "\"あ",
            "\"😀",
            "{\"x\": é}",
            "{\"x\": 1é}",
            "{\"x\": nulé}",
            "{\"é\": NaNé}",
            "é",
            "\u{feff}\"\u{feff}",
            "{\"x\":\n  \"ü",
        ] {
            let e = error(text);
            assert!(!e.is_empty(), "{text:?}");
        }
    }

    #[test]
    fn what_serde_json_quotes_is_cut_to_an_excerpt() {
        #[derive(Debug, serde::Deserialize)]
        #[serde(deny_unknown_fields)]
        #[allow(dead_code)]
        struct Small {
            x: f64,
        }
        let key = "ключ".repeat(10_000);
        let e = parse::<Small>(&format!("{{\"{key}\": 1}}")).unwrap_err();
        assert!(
            e.chars().count() <= MAX_MESSAGE_CHARS + 40,
            "{} chars",
            e.len()
        );
        assert!(
            e.starts_with("unknown field `ключключ") && e.contains("…`"),
            "{e}"
        );
        assert!(e.contains(" at line 1 column "), "{e}");
    }

    #[test]
    fn a_byte_order_mark_is_skipped() {
        let read: BTreeMap<String, f64> = parse("\u{feff}{\"x\": 1.5}").unwrap();
        assert_eq!(read["x"], 1.5);
    }
}
