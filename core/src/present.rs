//! Numbers and quoted text for people: what the core's words (event texts, warnings,
//! statuses) print, so a value computed in binary reads as a person would write it (`4000`,
//! not `4000.0000000000005`; `0.0025`, not `0.0025000000000000005`), and what an error
//! message quotes of a file is short and cut where a character ends ([`excerpt`]).

/// The characters of a person's text an error message quotes at most ([`excerpt`]).
pub const EXCERPT_CHARS: usize = 40;

/// `text` as an error message quotes it: at most [`EXCERPT_CHARS`] characters, cut with `…`,
/// so a file that is not what it should be (one enormous line, key or value) gives a short
/// message. The cut is counted in characters, never in bytes, so it never lands inside a
/// multi-byte character: the one helper every reader's error uses to quote its input.
pub fn excerpt(text: &str) -> String {
    excerpt_of(text, EXCERPT_CHARS)
}

/// `text` cut to at most `chars` characters, with `…` when something was cut.
pub fn excerpt_of(text: &str, chars: usize) -> String {
    match text.char_indices().nth(chars) {
        Some((cut, _)) => format!("{}…", text.get(..cut).unwrap_or_default()),
        None => text.to_owned(),
    }
}

/// The most characters of a message a reader's error quotes from a parser (serde_json's,
/// which quotes what it could not use in full), its position left out
/// ([`with_short_quotes`]).
pub const MAX_MESSAGE_CHARS: usize = 360;

/// A parser's `message` with every quotation between backticks cut to an [`excerpt`], and
/// at most [`MAX_MESSAGE_CHARS`] characters in all: what a reader says of a file however
/// long the key or value the parser quotes.
pub fn with_short_quotes(message: &str) -> String {
    let mut out = String::new();
    let mut rest = message;
    while let Some(open) = rest.find('`') {
        out.push_str(&rest[..=open]);
        let after = &rest[open + 1..];
        match after.find('`') {
            Some(close) => {
                out.push_str(&excerpt(&after[..close]));
                out.push('`');
                rest = &after[close + 1..];
            }
            None => {
                out.push_str(&excerpt(after));
                rest = "";
            }
        }
    }
    out.push_str(rest);
    excerpt_of(&out, MAX_MESSAGE_CHARS)
}

/// The longest index `≤ at` that is a character boundary of `text` (`text.len()` at most):
/// where a byte offset reported by a parser (serde_json's column counts bytes) may cut
/// `text` without landing inside a multi-byte character.
pub fn floor_char_boundary(text: &str, at: usize) -> usize {
    let mut i = at.min(text.len());
    while !text.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// `v` rounded to six significant digits, without trailing zeros: plain from 10⁻⁴ to below
/// 10⁹, else in scientific form (`1.5e-7`, `2e12`); `NaN`, `inf` and `-inf` as such.
pub fn number(v: f64) -> String {
    if !v.is_finite() {
        return format!("{v}");
    }
    if v == 0.0 {
        return "0".to_owned();
    }
    let a = v.abs();
    if !(1e-4..1e9).contains(&a) {
        let s = format!("{v:.5e}");
        return match s.split_once('e') {
            Some((mantissa, exponent)) => format!("{}e{exponent}", trim(mantissa)),
            None => s,
        };
    }
    // Digits after the point for six significant digits.
    let magnitude = libm::floor(libm::log10(a)) as i32;
    let decimals = (5 - magnitude).clamp(0, 12) as usize;
    trim(&format!("{v:.decimals$}"))
}

/// `v` with `decimals` digits after the point (`{:.N}`), as the core's event and status
/// texts print poses, headings and distances — except that a value that rounds to zero
/// reads `0.0`, never `-0.0` (`{:.1}` writes `-0.0` for −0 and for any tiny negative, e.g.
/// a heading of −1e-17° after a turn to 0°).
pub fn fixed(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    match s.strip_prefix('-') {
        Some(digits) if digits.bytes().all(|b| b == b'0' || b == b'.') => digits.to_owned(),
        _ => s,
    }
}

/// A position as people read it (spec §7): metres first, the map cell in parentheses —
/// `(1.55 m, 1.55 m) (cell 15, 15)`.
pub fn place((x, y): (f64, f64), (i, j): (usize, usize)) -> String {
    format!("({} m, {} m) (cell {i}, {j})", number(x), number(y))
}

fn trim(s: &str) -> String {
    let t = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    };
    if t == "-0" {
        "0".to_owned()
    } else {
        t.to_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::{excerpt, excerpt_of, fixed, floor_char_boundary, number, place};

    #[test]
    fn places_read_in_metres_with_the_cell() {
        assert_eq!(
            place((1.55 + 1e-15, 0.05), (15, 0)),
            "(1.55 m, 0.05 m) (cell 15, 0)"
        );
    }

    #[test]
    fn excerpts_are_cut_on_characters_and_bounded() {
        assert_eq!(excerpt("short"), "short");
        let long = "é".repeat(100);
        assert_eq!(excerpt(&long), format!("{}…", "é".repeat(40)));
        assert_eq!(excerpt_of("あいう", 2), "あい…");
        assert_eq!(excerpt_of("😀😀", 0), "…");
        assert_eq!(excerpt_of("", 3), "");
        for at in 0..8 {
            let b = floor_char_boundary("aé😀", at);
            assert!("aé😀".is_char_boundary(b) && b <= at, "{at} → {b}");
        }
        assert_eq!(floor_char_boundary("aé", 2), 1);
        assert_eq!(floor_char_boundary("aé", 99), 3);
    }

    #[test]
    fn fixed_decimals_never_say_minus_zero() {
        let cases = [
            (-0.0, 1, "0.0"),
            (-1e-17, 1, "0.0"),
            (-0.04, 1, "0.0"),
            (-0.05000001, 1, "-0.1"),
            (-0.0004, 3, "0.000"),
            (-1.25, 2, "-1.25"),
            (1.23456, 2, "1.23"),
            (-0.0, 0, "0"),
            (f64::NAN, 1, "NaN"),
            (f64::NEG_INFINITY, 1, "-inf"),
        ];
        for (v, d, s) in cases {
            assert_eq!(fixed(v, d), s, "{v} with {d} decimals");
        }
    }

    #[test]
    fn numbers_read_as_a_person_writes_them() {
        let cases = [
            (0.0, "0"),
            (4.0 / 0.001, "4000"),
            (5.0 * 0.001 / 2.0, "0.0025"),
            (6.300000000000001, "6.3"),
            (0.1 + 0.2, "0.3"),
            (0.45, "0.45"),
            (-57.12345678, "-57.1235"),
            (123456.7, "123457"),
            (1.0e9, "1e9"),
            (1.5e-7, "1.5e-7"),
            (-0.0, "0"),
            (f64::NAN, "NaN"),
            (f64::INFINITY, "inf"),
        ];
        for (v, s) in cases {
            assert_eq!(number(v), s, "{v}");
        }
    }
}
