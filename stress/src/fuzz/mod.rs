//! The project's own fuzzer, on stable Rust: one target per reader and per kind of hostile
//! call, inputs made by mutating fixture inputs and by generating them at random, every input
//! checked for four properties:
//!
//! 1. **no panic** — each input runs under `std::panic::catch_unwind`;
//! 2. **bounded allocation** — with the counting allocator installed ([`crate::alloc`]), the
//!    largest single request and the peak of live bytes stay within the target's stated
//!    bound ([`Target::alloc_bound`]);
//! 3. **no input slower than [`SLOW`]** (1 s in a release build, which `cargo xtask fuzz`
//!    makes; 10 s in a debug build — the short run of `cargo test` on a shared CI machine —
//!    where the same code is roughly ten times slower);
//! 4. **the target's own invariants** — a map read back equals itself, and, above all, a
//!    refused call changes nothing (compared with a twin that never got it).
//!
//! Input `i` of target `t` under seed `s` is a function of `(s, t, i)` alone (the corpus is
//! the fixed fixture inputs), so `rtnav-stress fuzz --seed s --target t --case i` replays a failure
//! exactly. The run is bounded by time per target ([`Options::per_target`]) or by a number of
//! cases ([`Options::cases`]).
//!
//! **Mutations that reach a text reader's edge early** ([`mutate_text`]): a multi-byte
//! character (2, 3 or 4 bytes, a byte-order mark, a line separator) inserted or put in place
//! of a character — half the time where the target's parser stops ([`Target::fail_at`]: for
//! the JSON readers, serde_json's position of the error), and then often with the input cut
//! right after it, so the error falls on or just past the character; invalid UTF-8; a
//! byte-order mark; a very long line; deep nesting. A third of the inputs get one.
//!
//! **Kept regression cases** (`fixtures/fuzz-regressions/TARGET/`): every input that once
//! failed is kept as a file there and replayed first by every run that is given the folder
//! ([`Options::corpus`]: `rtnav-stress fuzz --corpus`, the fuzz stage of `cargo xtask test`) and by
//! `stress/tests/fuzz.rs`. A failing input is written out as such a file when the run is given
//! [`Options::save`] (`rtnav-stress fuzz --save DIR`), ready to be kept.

pub mod components;
pub mod readers;
pub mod scripts;
pub mod system;

use std::cell::{Cell, RefCell};
use std::fmt::Write as _;
use std::panic::AssertUnwindSafe;
use std::path::{Path, PathBuf};
use std::sync::Once;
use std::time::{Duration, Instant};

use crate::alloc;
use crate::rng::{Rng, name_hash};

/// The slowest an input may be: 1 s, measured in a release build; a debug build
/// (the short run of `cargo test`) is allowed ten times that, as its code is about ten times
/// slower.
pub const SLOW: Duration = if cfg!(debug_assertions) {
    Duration::from_secs(10)
} else {
    Duration::from_secs(1)
};

/// The longest input the mutator makes \[bytes\].
const MAX_LEN: usize = 256 * 1024;

/// One input: one part per file (a ROS map is its YAML and its image), or the bytes an
/// operation sequence is decoded from.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Case {
    /// The parts.
    pub parts: Vec<Vec<u8>>,
}

impl Case {
    /// An input of one part.
    pub fn one(bytes: impl Into<Vec<u8>>) -> Self {
        Self {
            parts: vec![bytes.into()],
        }
    }

    /// The whole length \[bytes\].
    pub fn len(&self) -> usize {
        self.parts.iter().map(Vec::len).sum()
    }

    /// Whether every part is empty.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Part `i` (empty if missing).
    pub fn part(&self, i: usize) -> &[u8] {
        self.parts.get(i).map_or(&[], Vec::as_slice)
    }

    /// Part `i` as text (lossy).
    pub fn text(&self, i: usize) -> String {
        String::from_utf8_lossy(self.part(i)).into_owned()
    }

    /// A short printable view for reports.
    pub fn preview(&self) -> String {
        let mut s = String::new();
        for (i, p) in self.parts.iter().enumerate() {
            let shown: String = String::from_utf8_lossy(&p[..p.len().min(160)])
                .chars()
                .flat_map(char::escape_debug)
                .collect();
            let _ = write!(
                s,
                "{}part {i} ({} bytes): \"{shown}{}\"",
                if i > 0 { "; " } else { "" },
                p.len(),
                if p.len() > 160 { "…" } else { "" }
            );
        }
        s
    }
}

/// A fuzz target.
pub trait Target {
    /// Its name (`rtnav-stress fuzz --target NAME`).
    fn name(&self) -> &'static str;
    /// The fixture inputs mutated (may be empty: then every input is generated).
    fn seeds(&self) -> &[Case];
    /// A fresh input made at random, knowing the format.
    fn generate(&self, rng: &mut Rng) -> Case;
    /// Runs one input. `Err` names a broken invariant (panics, time and allocation are
    /// checked by the runner).
    fn run(&mut self, case: &Case) -> Result<(), String>;
    /// The most this input may allocate at once and at its peak \[bytes\].
    fn alloc_bound(&self, case: &Case) -> u64;
    /// Where in `bytes` (part `part` of an input) the target's parser stops with an error,
    /// as a byte offset — where a text mutation does the most ([`mutate_text`]); `None`
    /// where the target cannot tell (the mutation then picks a place at random).
    fn fail_at(&self, _part: usize, _bytes: &[u8]) -> Option<usize> {
        None
    }
}

/// Where serde_json stops reading `bytes` as JSON, as a byte offset (its line and column,
/// which counts bytes, turned into one); `None` if the text is JSON.
pub fn json_fail_at(bytes: &[u8]) -> Option<usize> {
    let e = serde_json::from_slice::<serde_json::Value>(bytes).err()?;
    let line_start: usize = bytes
        .split(|&b| b == b'\n')
        .take(e.line().saturating_sub(1))
        .map(|l| l.len() + 1)
        .sum();
    Some((line_start + e.column().saturating_sub(1)).min(bytes.len()))
}

/// How a run is bounded.
#[derive(Debug, Clone)]
pub struct Options {
    /// The seed (printed, for replays).
    pub seed: u64,
    /// Wall time per target (ignored when `cases` is set).
    pub per_target: Duration,
    /// Exactly this many cases per target instead of a time budget.
    pub cases: Option<u64>,
    /// Only the targets whose name contains one of these (all when empty).
    pub only: Vec<String>,
    /// Run only this case of each chosen target (a replay).
    pub replay: Option<u64>,
    /// The kept regression cases (`fixtures/fuzz-regressions`): each target's are run first.
    pub corpus: Option<PathBuf>,
    /// Where each failing input is written, as a regression case to keep.
    pub save: Option<PathBuf>,
}

impl Options {
    /// `seed`, `cases` inputs per target (or `per_target` of time when `None`), every
    /// target, nothing kept or saved.
    pub fn new(seed: u64, per_target: Duration, cases: Option<u64>) -> Self {
        Self {
            seed,
            per_target,
            cases,
            only: Vec::new(),
            replay: None,
            corpus: None,
            save: None,
        }
    }
}

/// One failed input.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Failure {
    /// Its case number (for `--case`).
    pub case: u64,
    /// The kept regression case it is, if it is one (its file name).
    pub regression: Option<String>,
    /// Where the input was written ([`Options::save`]).
    pub saved: Option<PathBuf>,
    /// `panic`, `slow`, `alloc` or `invariant`.
    pub kind: &'static str,
    /// What happened.
    pub message: String,
    /// The input, shortened.
    pub input: String,
}

/// What a target's run found.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct TargetReport {
    /// The target.
    pub name: String,
    /// Inputs tried (the kept regression cases included).
    pub tried: u64,
    /// Kept regression cases replayed.
    pub regressions: u64,
    /// Inputs that failed.
    pub failed: u64,
    /// The first failures (at most 20).
    pub failures: Vec<Failure>,
    /// Refused calls compared with a twin.
    pub refusals: u64,
    /// The slowest input's time.
    pub slowest: Duration,
    /// Its case number.
    pub slowest_case: u64,
    /// Its size \[bytes\].
    pub slowest_len: usize,
    /// The largest single allocation request seen \[bytes\].
    pub largest_request: usize,
    /// The highest peak of live bytes of one input \[bytes\].
    pub peak: i64,
    /// Wall time of the target's run.
    pub wall: Duration,
}

impl TargetReport {
    /// One line: tried, failures, slowest, allocation.
    pub fn line(&self) -> String {
        let refusals = if self.refusals > 0 {
            format!("  {} refusals compared", self.refusals)
        } else {
            String::new()
        };
        format!(
            "{:<14} {:>7} inputs ({} kept) {:>3} failures  slowest {:>8.2} ms (case {}, {} bytes)  \
             largest request {}  peak {}{refusals}",
            self.name,
            self.tried,
            self.regressions,
            self.failed,
            self.slowest.as_secs_f64() * 1e3,
            self.slowest_case,
            self.slowest_len,
            bytes(self.largest_request as u64),
            bytes(self.peak.max(0) as u64),
        )
    }
}

/// `1234567` → `1.2 MiB`.
pub fn bytes(n: u64) -> String {
    const K: f64 = 1024.0;
    let f = n as f64;
    if f < K {
        format!("{n} B")
    } else if f < K * K {
        format!("{:.1} KiB", f / K)
    } else if f < K * K * K {
        format!("{:.1} MiB", f / K / K)
    } else {
        format!("{:.2} GiB", f / K / K / K)
    }
}

thread_local! {
    /// Refused calls compared with a twin on this thread (the twin targets count them).
    pub static REFUSED: Cell<u64> = const { Cell::new(0) };
    static QUIET: Cell<bool> = const { Cell::new(false) };
    static LAST_PANIC: RefCell<String> = const { RefCell::new(String::new()) };
}

/// Installs (once) a panic hook that records the message and location instead of printing
/// while this thread runs a fuzz input, and defers to the previous hook otherwise.
fn install_quiet_hook() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if QUIET.with(Cell::get) {
                let message = format!("{info}{}", rtnav_frames());
                let _ = LAST_PANIC.try_with(|p| *p.borrow_mut() = message);
            } else {
                previous(info);
            }
        }));
    });
}

/// The innermost frames of the core (`rtnav::…`) in the current backtrace, with their
/// locations: where in the library a panic happened, even when it was raised in `core`.
fn rtnav_frames() -> String {
    let trace = std::backtrace::Backtrace::force_capture().to_string();
    let lines: Vec<&str> = trace.lines().map(str::trim).collect();
    let mut out = String::new();
    let mut shown = 0;
    for (i, l) in lines.iter().enumerate() {
        let name = l.split_once(": ").map_or("", |(_, n)| n);
        let at = lines
            .get(i + 1)
            .filter(|n| n.starts_with("at "))
            .map_or("", |n| n);
        // The core's frames (the tools' own are named `rtnav_stress::`).
        if name.starts_with("rtnav::") && shown < 4 {
            let _ = write!(out, "\n    in {name} {at}");
            shown += 1;
        }
    }
    out
}

/// Input `case` of `target` under `seed`: a mutated fixture input or a generated one.
pub fn case_for(target: &dyn Target, seed: u64, case: u64) -> Case {
    let mut rng = Rng::stream(seed, &[name_hash(target.name()), case]);
    let seeds = target.seeds();
    if !seeds.is_empty() && (case < seeds.len() as u64) {
        // The fixtures themselves come first.
        return seeds[case as usize].clone();
    }
    let mut c = if !seeds.is_empty() && rng.chance(0.65) {
        let mut c = rng.pick(seeds).clone();
        let other = rng.pick(seeds).clone();
        for _ in 0..=rng.below(6) {
            mutate(&mut c, &other, &mut rng);
        }
        c
    } else {
        target.generate(&mut rng)
    };
    if rng.chance(0.35) {
        mutate_text(&mut c, target, &mut rng);
    }
    c
}

/// Characters of 2, 3 and 4 bytes in UTF-8 (and a byte-order mark, a line separator, a
/// combining accent, the replacement character).
pub const MULTI_BYTE: &[&str] = &[
    "é", "ü", "ß", "Ω", "\u{301}", "あ", "漢", "\u{feff}", "\u{2028}", "\u{200b}", "\u{fffd}",
    "😀", "𝕏",
];

/// Byte sequences that are not UTF-8: a lone continuation byte, a lead byte without its
/// continuation, an encoded surrogate, an overlong `/`, bytes never used, a code point past
/// U+10FFFF.
const NOT_UTF8: &[&[u8]] = &[
    b"\x80",
    b"\xc3",
    b"\xe3\x81",
    b"\xed\xa0\x80",
    b"\xc0\xaf",
    b"\xff",
    b"\xfe",
    b"\xf4\x90\x80\x80",
];

/// What deep nesting repeats: JSON arrays and objects, YAML flow and block collections.
const NESTS: &[&[u8]] = &[b"[", b"{\"a\":", b"[{\"a\":", b"{a: ", b"- "];

/// One change of the kinds that break text readers ([module documentation](self)): a
/// multi-byte character where the parser stops (or anywhere), invalid UTF-8, a byte-order
/// mark, a very long line, deep nesting.
pub fn mutate_text(c: &mut Case, target: &dyn Target, rng: &mut Rng) {
    if c.parts.is_empty() {
        c.parts.push(Vec::new());
    }
    let which = rng.index(c.parts.len());
    let fail = if rng.chance(0.5) {
        target.fail_at(which, c.part(which))
    } else {
        None
    };
    let p = &mut c.parts[which];
    let len = p.len();
    let at = fail.unwrap_or_else(|| rng.index(len + 1)).min(len);
    let ch = rng.pick(MULTI_BYTE).as_bytes().to_vec();
    match rng.below(8) {
        // A multi-byte character at the place, often with the input cut just after it.
        0 | 1 => {
            let end = at + ch.len();
            p.splice(at..at, ch);
            if rng.chance(0.5) {
                p.truncate(end);
            }
        }
        // A multi-byte character in place of the one at the place.
        2 => {
            let mut end = (at + 1).min(len);
            while end < len && (p[end] & 0xc0) == 0x80 {
                end += 1;
            }
            p.splice(at..end, ch);
        }
        // Invalid UTF-8.
        3 => {
            let bad = rng.pick(NOT_UTF8).to_vec();
            p.splice(at..at, bad);
        }
        // A byte-order mark (at the start, twice, or where the parser stops).
        4 => {
            let bom = "\u{feff}".as_bytes();
            match rng.below(3) {
                0 => drop(p.splice(0..0, bom.iter().copied())),
                1 => drop(p.splice(0..0, bom.iter().chain(bom).copied())),
                _ => drop(p.splice(at..at, bom.iter().copied())),
            }
        }
        // A very long line: one character repeated, no line break.
        5 => {
            let unit = if rng.chance(0.5) { ch } else { vec![b'a'] };
            let times = 1000 + rng.index(60_000);
            let mut run = Vec::with_capacity(unit.len() * times);
            for _ in 0..times {
                run.extend_from_slice(&unit);
            }
            p.splice(at..at, run);
        }
        // Deep nesting: JSON arrays or objects, YAML flow collections.
        _ => {
            let open = rng.pick(NESTS);
            let deepest = if rng.chance(0.2) { 20_000 } else { 600 };
            let depth = 64 + rng.index(deepest);
            let mut run = Vec::with_capacity(open.len() * depth);
            for _ in 0..depth {
                run.extend_from_slice(open);
            }
            p.splice(at..at, run);
        }
    }
    p.truncate(MAX_LEN);
}

/// Numbers that break parsers and arithmetic, as text.
pub const INTERESTING_NUMBERS: &[&str] = &[
    "0",
    "-0",
    "1",
    "-1",
    "2",
    "255",
    "256",
    "4096",
    "4097",
    "65535",
    "65536",
    "2147483647",
    "2147483648",
    "4294967295",
    "4294967296",
    "1000000000",
    "999999999",
    "9223372036854775807",
    "18446744073709551615",
    "18446744073709551616",
    "99999999999999999999999999",
    "1e308",
    "1e309",
    "-1e308",
    "5e-324",
    "1e-320",
    "0.5",
    "0.1",
    "NaN",
    "nan",
    "inf",
    "-inf",
    "Infinity",
    "1.7976931348623157e308",
    "0x10",
    "1_000",
    "",
];

/// One random change to one part of `c` (`other` gives material to splice).
pub fn mutate(c: &mut Case, other: &Case, rng: &mut Rng) {
    if c.parts.is_empty() {
        c.parts.push(Vec::new());
    }
    let which = rng.index(c.parts.len());
    let donor = other.part(rng.index(other.parts.len().max(1))).to_vec();
    let p = &mut c.parts[which];
    let len = p.len();
    match rng.below(11) {
        // Flip a bit.
        0 if len > 0 => {
            let i = rng.index(len);
            p[i] ^= 1 << rng.below(8);
        }
        // An interesting byte.
        1 if len > 0 => {
            let i = rng.index(len);
            p[i] = *rng.pick(&[
                0u8, 0xff, 0x7f, 0x80, b'0', b'9', b'\n', b'"', b'#', b'.', b',', b'-', b'e', b'[',
                b']', b'{', b'}', b':', b' ', b'\r', b'\t',
            ]);
        }
        // Insert random bytes.
        2 => {
            let at = rng.index(len + 1);
            let n = 1 + rng.index(8);
            let bytes: Vec<u8> = (0..n).map(|_| rng.next_u64() as u8).collect();
            p.splice(at..at, bytes);
        }
        // Delete a range.
        3 if len > 0 => {
            let at = rng.index(len);
            let n = 1 + rng.index((len - at).min(64));
            p.drain(at..at + n);
        }
        // Repeat a range (long inputs).
        4 if len > 0 => {
            let at = rng.index(len);
            let n = 1 + rng.index((len - at).min(64));
            let piece = p[at..at + n].to_vec();
            let most = if rng.chance(0.1) { 4096 } else { 16 };
            let times = 1 + rng.index(most);
            let mut add = Vec::with_capacity(piece.len() * times);
            for _ in 0..times {
                add.extend_from_slice(&piece);
            }
            p.splice(at..at, add);
        }
        // Truncate.
        5 if len > 0 => {
            let at = rng.index(len);
            p.truncate(at);
        }
        // Splice a piece of another input.
        6 if !donor.is_empty() => {
            let from = rng.index(donor.len());
            let n = 1 + rng.index((donor.len() - from).min(256));
            let at = rng.index(len + 1);
            p.splice(at..at, donor[from..from + n].iter().copied());
        }
        // Replace a number in the text with an interesting one (or insert one).
        7..=9 => {
            let number = rng.pick(INTERESTING_NUMBERS).as_bytes().to_vec();
            let digits: Vec<usize> = (0..len).filter(|&i| p[i].is_ascii_digit()).collect();
            if digits.is_empty() {
                let at = rng.index(len + 1);
                p.splice(at..at, number);
            } else {
                let mut start = *rng.pick(&digits);
                while start > 0 && (p[start - 1].is_ascii_digit() || p[start - 1] == b'.') {
                    start -= 1;
                }
                let mut end = start;
                while end < len && (p[end].is_ascii_digit() || p[end] == b'.' || p[end] == b'e') {
                    end += 1;
                }
                p.splice(start..end, number);
            }
        }
        // Swap two bytes.
        _ if len > 1 => {
            let (a, b) = (rng.index(len), rng.index(len));
            p.swap(a, b);
        }
        _ => p.push(rng.next_u64() as u8),
    }
    p.truncate(MAX_LEN);
}

/// Runs one case of `target`: the four checks. `None` if it passed.
fn run_case(
    target: &mut dyn Target,
    case: &Case,
) -> (Option<(&'static str, String)>, Duration, alloc::Usage) {
    let bound = target.alloc_bound(case);
    QUIET.with(|q| q.set(true));
    let started = Instant::now();
    let (result, usage) =
        alloc::measure(|| std::panic::catch_unwind(AssertUnwindSafe(|| target.run(case))));
    let took = started.elapsed();
    QUIET.with(|q| q.set(false));
    let failure = match result {
        Err(payload) => {
            let message = LAST_PANIC
                .with(|p| core::mem::take(&mut *p.borrow_mut()))
                .to_string();
            let message = if message.is_empty() {
                payload
                    .downcast_ref::<&str>()
                    .map(|s| (*s).to_owned())
                    .or_else(|| payload.downcast_ref::<String>().cloned())
                    .unwrap_or_else(|| "panic".to_owned())
            } else {
                message
            };
            Some(("panic", message))
        }
        Ok(Err(message)) => Some(("invariant", message)),
        Ok(Ok(())) => {
            let over =
                alloc::installed() && (usage.largest as u64 > bound || usage.peak > bound as i64);
            let alloc_text = format!(
                "asked for {} at once, {} at the peak: the bound is {}",
                bytes(usage.largest as u64),
                bytes(usage.peak.max(0) as u64),
                bytes(bound)
            );
            let slow_text = format!(
                "took {:.3} s (limit {:.0} s)",
                took.as_secs_f64(),
                SLOW.as_secs_f64()
            );
            match (over, took > SLOW) {
                (true, true) => Some(("alloc", format!("{alloc_text}; {slow_text}"))),
                (true, false) => Some(("alloc", alloc_text)),
                (false, true) => Some(("slow", slow_text)),
                (false, false) => None,
            }
        }
    };
    (failure, took, usage)
}

/// Runs `target` under `options` (`progress` is told each finished target's report).
pub fn run_target(target: &mut dyn Target, options: &Options) -> TargetReport {
    install_quiet_hook();
    let mut report = TargetReport {
        name: target.name().to_owned(),
        ..TargetReport::default()
    };
    let started = Instant::now();
    let refused = REFUSED.with(Cell::get);
    if let (Some(dir), None) = (&options.corpus, options.replay) {
        for (name, case) in kept_cases(dir, target.name()) {
            let (failure, took, usage) = run_case(target, &case);
            report.tried += 1;
            report.regressions += 1;
            note(&mut report, 0, &case, took, usage);
            if let Some((kind, message)) = failure {
                report.failed += 1;
                report.failures.push(Failure {
                    case: 0,
                    regression: Some(name),
                    saved: None,
                    kind,
                    message,
                    input: case.preview(),
                });
            }
        }
    }
    let mut i = options.replay.unwrap_or(0);
    loop {
        let done = match (options.replay, options.cases) {
            (Some(r), _) => i > r,
            (None, Some(n)) => i >= n,
            (None, None) => started.elapsed() >= options.per_target,
        };
        if done {
            break;
        }
        let case = case_for(target, options.seed, i);
        let (failure, took, usage) = run_case(target, &case);
        report.tried += 1;
        note(&mut report, i, &case, took, usage);
        if let Some((kind, message)) = failure {
            report.failed += 1;
            if report.failures.len() < 20 {
                let saved = options
                    .save
                    .as_ref()
                    .and_then(|dir| save_case(dir, target.name(), options.seed, i, &case));
                report.failures.push(Failure {
                    case: i,
                    regression: None,
                    saved,
                    kind,
                    message,
                    input: case.preview(),
                });
            }
        }
        i += 1;
    }
    report.wall = started.elapsed();
    report.refusals = REFUSED.with(Cell::get) - refused;
    report
}

/// The slowest input and the allocation figures of `report`, with one more input.
fn note(report: &mut TargetReport, i: u64, case: &Case, took: Duration, usage: alloc::Usage) {
    if took > report.slowest {
        report.slowest = took;
        report.slowest_case = i;
        report.slowest_len = case.len();
    }
    report.largest_request = report.largest_request.max(usage.largest);
    report.peak = report.peak.max(usage.peak);
}

/// The kept regression cases of `target` under `dir` (`dir/TARGET/NAME`, one file an input;
/// an input of several parts, a ROS map's YAML and image, is `NAME.part0`, `NAME.part1`, …),
/// by name.
pub fn kept_cases(dir: &Path, target: &str) -> Vec<(String, Case)> {
    let mut files: Vec<(String, PathBuf)> = std::fs::read_dir(dir.join(target))
        .into_iter()
        .flatten()
        .filter_map(|e| {
            let e = e.ok()?;
            let name = e.file_name().into_string().ok()?;
            (e.path().is_file() && name != "README.md").then(|| (name, e.path()))
        })
        .collect();
    files.sort();
    let mut out: Vec<(String, Case)> = Vec::new();
    for (name, path) in files {
        let bytes = std::fs::read(&path).unwrap_or_default();
        match name.rsplit_once(".part") {
            Some((stem, n)) if n.parse::<usize>().is_ok() => match out.last_mut() {
                Some((last, case)) if last == stem => case.parts.push(bytes),
                _ => out.push((stem.to_owned(), Case::one(bytes))),
            },
            _ => out.push((name, Case::one(bytes))),
        }
    }
    out
}

/// Writes `case` (input `i` of `target` under `seed`) under `dir` as a regression case to
/// keep ([`kept_cases`]); its path, or `None` if it could not be written.
fn save_case(dir: &Path, target: &str, seed: u64, i: u64, case: &Case) -> Option<PathBuf> {
    let folder = dir.join(target);
    std::fs::create_dir_all(&folder).ok()?;
    let stem = format!("seed{seed}-case{i}");
    if case.parts.len() == 1 {
        let path = folder.join(&stem);
        std::fs::write(&path, case.part(0)).ok()?;
        return Some(path);
    }
    for (n, part) in case.parts.iter().enumerate() {
        std::fs::write(folder.join(format!("{stem}.part{n}")), part).ok()?;
    }
    Some(folder.join(format!("{stem}.part*")))
}

/// Every target, built from the fixtures under `root` (the project's root) and the shared
/// data at `data` where present.
pub fn all_targets(root: &Path, data: Option<&Path>) -> Vec<Box<dyn Target>> {
    let mut targets: Vec<Box<dyn Target>> = readers::targets(root, data);
    targets.extend(components::targets());
    targets.extend(system::targets(root));
    targets.extend(scripts::targets(root));
    targets
}

/// Whether `name` is chosen by `only`: every target when `only` is empty; else a target
/// named exactly, or whose name contains a filter that names no target exactly.
pub fn chosen(name: &str, only: &[String], names: &[&str]) -> bool {
    only.is_empty()
        || only
            .iter()
            .any(|o| o == name || (!names.contains(&o.as_str()) && name.contains(o.as_str())))
}

/// Runs every chosen target; returns the reports.
pub fn run(
    root: &Path,
    data: Option<&Path>,
    options: &Options,
    progress: impl FnMut(&TargetReport),
) -> Vec<TargetReport> {
    run_targets(all_targets(root, data), options, progress)
}

/// Runs the chosen ones of `targets`; returns the reports.
pub fn run_targets(
    targets: Vec<Box<dyn Target>>,
    options: &Options,
    mut progress: impl FnMut(&TargetReport),
) -> Vec<TargetReport> {
    let mut reports = Vec::new();
    let names: Vec<&'static str> = targets.iter().map(|t| t.name()).collect();
    for mut target in targets {
        if !chosen(target.name(), &options.only, &names) {
            continue;
        }
        let report = run_target(target.as_mut(), options);
        progress(&report);
        reports.push(report);
    }
    reports
}

// ------------------------------------------------------------------ structured inputs

/// Reads values out of fuzz bytes (as libFuzzer's `FuzzedDataProvider`): zeros once the
/// bytes run out, so every byte string is a valid program for an operation-sequence target.
#[derive(Debug, Clone)]
pub struct Bytes<'a> {
    data: &'a [u8],
    pos: usize,
}

/// Floats that break arithmetic.
pub const HOSTILE_F64: &[f64] = &[
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    0.0,
    -0.0,
    f64::MAX,
    f64::MIN,
    f64::MIN_POSITIVE,
    5e-324,
    1e300,
    -1e300,
    1e15,
    -1e15,
    4294967296.0,
    -1.0,
    0.5,
    1.0,
    2.0,
    1e-9,
    0.6000000000000001,
];

impl<'a> Bytes<'a> {
    /// Over `data`.
    pub fn new(data: &'a [u8]) -> Self {
        Self { data, pos: 0 }
    }

    /// Whether every byte was read.
    pub fn is_empty(&self) -> bool {
        self.pos >= self.data.len()
    }

    /// The next byte (0 past the end).
    pub fn u8(&mut self) -> u8 {
        let b = self.data.get(self.pos).copied().unwrap_or(0);
        self.pos += 1;
        b
    }

    /// The next little-endian `u16`.
    pub fn u16(&mut self) -> u16 {
        u16::from_le_bytes([self.u8(), self.u8()])
    }

    /// The next little-endian `u32`.
    pub fn u32(&mut self) -> u32 {
        u32::from_le_bytes([self.u8(), self.u8(), self.u8(), self.u8()])
    }

    /// The next little-endian `u64`.
    pub fn u64(&mut self) -> u64 {
        u64::from(self.u32()) | (u64::from(self.u32()) << 32)
    }

    /// A number in `0..n` (0 when `n` is 0).
    pub fn below(&mut self, n: usize) -> usize {
        if n == 0 {
            0
        } else if n <= 256 {
            self.u8() as usize % n
        } else {
            self.u32() as usize % n
        }
    }

    /// A float: often hostile ([`HOSTILE_F64`]), often plausible within `lo..hi`, sometimes
    /// any bit pattern.
    pub fn f64_in(&mut self, lo: f64, hi: f64) -> f64 {
        match self.u8() {
            0..=79 => HOSTILE_F64[self.below(HOSTILE_F64.len())],
            80..=239 => lo + (hi - lo) * (f64::from(self.u16()) / 65535.0),
            _ => f64::from_bits(self.u64()),
        }
    }

    /// An integer: often within `lo..hi`, sometimes hostile.
    pub fn i64_in(&mut self, lo: i64, hi: i64) -> i64 {
        match self.u8() {
            0..=199 => lo + (self.u32() as i64).rem_euclid((hi - lo).max(1)),
            200..=219 => -1,
            220..=229 => i64::from(i32::MAX) + 1,
            230..=239 => i64::MIN,
            _ => self.u64() as i64,
        }
    }

    /// A length: mostly small, sometimes long.
    pub fn length(&mut self, small: usize, long: usize) -> usize {
        if self.u8() < 240 {
            self.below(small + 1)
        } else {
            self.below(long + 1)
        }
    }
}
