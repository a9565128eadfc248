//! A script component's console (spec §8): what the script `print`s and the errors of its
//! actions, bounded, with a line that repeats folded into one entry and a count (as the
//! page's log folds a repeating condition, spec §7 Decision 0.3 "repeats").

use std::collections::VecDeque;

use serde::Serialize;

/// Lines kept; older ones are dropped (and counted).
pub const CONSOLE_LINES: usize = 200;
/// Characters kept of one printed line; the rest is cut (and the line says so).
pub const LINE_CHARS: usize = 400;

/// What a console line is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
#[serde(rename_all = "lowercase")]
pub enum ConsoleKind {
    /// The script's `print` (or `debug`).
    Print,
    /// An action's failure.
    Error,
}

/// One entry of the console.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct ConsoleLine {
    /// Print or error.
    pub kind: ConsoleKind,
    /// Simulated time of its first occurrence \[s\].
    pub first_s: f64,
    /// Simulated time of its last repeat \[s\].
    pub last_s: f64,
    /// The action that printed it or failed.
    pub action: String,
    /// The 1-based line and column of an error, if it names one.
    pub at: Option<(usize, usize)>,
    /// The text.
    pub text: String,
    /// How many times in a row it came (1 for once).
    pub count: u64,
}

/// The console: the newest [`CONSOLE_LINES`] entries.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Console {
    lines: VecDeque<ConsoleLine>,
    dropped: u64,
}

impl Console {
    /// Adds a line at simulated time `time_s`; the same line as the last one (same kind,
    /// action, place and text) only counts again.
    pub fn push(
        &mut self,
        kind: ConsoleKind,
        time_s: f64,
        action: &str,
        at: Option<(usize, usize)>,
        text: &str,
    ) {
        let text = cut(text);
        if let Some(last) = self.lines.back_mut()
            && last.kind == kind
            && last.action == action
            && last.at == at
            && last.text == text
        {
            last.count += 1;
            last.last_s = time_s;
            return;
        }
        if self.lines.len() == CONSOLE_LINES {
            self.lines.pop_front();
            self.dropped += 1;
        }
        self.lines.push_back(ConsoleLine {
            kind,
            first_s: time_s,
            last_s: time_s,
            action: action.to_owned(),
            at,
            text,
            count: 1,
        });
    }

    /// The entries, oldest first.
    pub fn lines(&self) -> impl Iterator<Item = &ConsoleLine> {
        self.lines.iter()
    }

    /// How many older entries were dropped to keep the bound.
    pub fn dropped(&self) -> u64 {
        self.dropped
    }

    /// Forgets everything (a new script).
    pub fn clear(&mut self) {
        self.lines.clear();
        self.dropped = 0;
    }
}

fn cut(text: &str) -> String {
    match text.char_indices().nth(LINE_CHARS) {
        None => text.to_owned(),
        Some((i, _)) => format!("{}… (cut at {LINE_CHARS} characters)", &text[..i]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn repeats_fold_and_the_bound_holds() {
        let mut c = Console::default();
        for i in 0..5 {
            c.push(ConsoleKind::Print, f64::from(i), "on_execute", None, "tick");
        }
        c.push(ConsoleKind::Print, 5.0, "on_execute", None, "other");
        let lines: Vec<_> = c.lines().collect();
        assert_eq!(lines.len(), 2);
        assert_eq!(
            (lines[0].count, lines[0].first_s, lines[0].last_s),
            (5, 0.0, 4.0)
        );
        for i in 0..(CONSOLE_LINES + 10) {
            c.push(ConsoleKind::Print, 6.0, "on_execute", None, &i.to_string());
        }
        assert_eq!(c.lines().count(), CONSOLE_LINES);
        assert_eq!(c.dropped(), 12);
        c.push(
            ConsoleKind::Print,
            7.0,
            "a",
            None,
            &"x".repeat(LINE_CHARS + 5),
        );
        assert!(
            c.lines()
                .last()
                .is_some_and(|l| l.text.ends_with("characters)"))
        );
    }
}
