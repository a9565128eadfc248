//! The MovingAI grid pathfinding benchmark's `.map` and `.scen` files (spec §5
//! "GlobalPathPlanning"; N. Sturtevant, "Benchmarks for Grid-Based Pathfinding", 2012;
//! movingai.com/benchmarks/formats.html).
//!
//! **Coordinates.** MovingAI's `(x, y)` has x the column and y the *row counted from the top*
//! (row 0 is the first map line). A [`GridMap`] has y pointing up, (0, 0) the lower-left
//! cell. The file is therefore read so that it looks the same way up: MovingAI `(x, y)` is
//! the `GridMap` cell `(x, height − 1 − y)` ([`to_cell`]), and scenario coordinates are
//! converted the same way ([`ScenProblem::start_cell`], [`ScenProblem::goal_cell`]). A
//! vertical flip maps 8-neighbours to 8-neighbours and keeps the corner-cutting rule, so the
//! optimal lengths of the `.scen` files hold unchanged.
//!
//! **`.map`**: the header lines `type octile`, `height H`, `width W` (in either order), then
//! `map`, then `H` rows of `W` characters. `.`, `G`, `S` are passable (free), `@`, `O`, `T`,
//! `W` are not (obstacle); any other character is an error. Spaces or tabs may separate a
//! header key from its value; CRLF line ends and blank lines are accepted; a header key given
//! twice is an error.
//!
//! **`.scen`**: the line `version 1` (or `version 1.0`), then one problem per line: bucket,
//! map, map width, map height, start x, start y, goal x, goal y, optimal length — separated
//! by tabs (then the map name may contain spaces) or by spaces.

use super::shown;
use crate::errors::MapError;
use crate::map::{Cell, GridMap};

const MAP: &str = "MovingAI .map";
const SCEN: &str = "MovingAI .scen";

fn err(format: &'static str, line: usize, reason: impl Into<String>) -> MapError {
    MapError::Format {
        format,
        line: Some(line),
        reason: reason.into(),
    }
}

/// The `GridMap` cell of MovingAI coordinates `(x, y)` (y = row from the top) on a map
/// `height` rows high: `(x, height − 1 − y)`. `None` if `y ≥ height`.
pub fn to_cell(x: usize, y: usize, height: usize) -> Option<Cell> {
    (y < height).then(|| (x, height - 1 - y))
}

/// Non-blank lines with their 1-based numbers, line ends (`\n`, `\r\n`, a final `\r`) and
/// trailing blanks removed.
fn lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim_end()))
        .filter(|(_, l)| !l.is_empty())
}

/// Why a number is refused when its digits are more than its type holds.
const TOO_LARGE: &str = "is too large";

/// A whole number ≥ 0 as written, or why not: [`TOO_LARGE`], or not such a number.
fn whole<T: std::str::FromStr>(v: &str) -> Result<T, &'static str> {
    v.parse().map_err(|_| {
        if !v.is_empty() && v.bytes().all(|b| b.is_ascii_digit()) {
            TOO_LARGE
        } else {
            "is not a whole number ≥ 0"
        }
    })
}

/// Sets a header `key`'s value, read on line `n`; a key given twice is an error (which of
/// the two the file means cannot be told).
fn once<T>(slot: &mut Option<T>, value: T, key: &str, n: usize) -> Result<(), MapError> {
    match slot.replace(value) {
        None => Ok(()),
        Some(_) => Err(err(MAP, n, format!("`{key}` is given twice in the header"))),
    }
}

/// Reads a `.map` file into a [`GridMap`] with `GridSize` 1 m and origin (0, 0), rows
/// flipped as the module documentation says.
pub fn load_map(text: &str) -> Result<GridMap, MapError> {
    let mut it = lines(crate::rtc::without_bom(text));
    let (mut width, mut height, mut kind) = (None, None, None);
    let mut last_line = 0;
    loop {
        let Some((n, line)) = it.next() else {
            return Err(err(
                MAP,
                last_line + 1,
                "missing the `map` line before the rows",
            ));
        };
        last_line = n;
        let mut words = line.split_whitespace();
        let key = words.next().unwrap_or_default();
        let value = words.next();
        if words.next().is_some() {
            return Err(err(
                MAP,
                n,
                format!("cannot read header line `{}`", shown(line)),
            ));
        }
        let number = |v: Option<&str>| -> Result<u64, MapError> {
            let why = match v.map(whole::<u64>) {
                Some(Ok(v)) if v >= 1 => return Ok(v),
                Some(Err(TOO_LARGE)) => TOO_LARGE,
                _ => "must be a whole number ≥ 1",
            };
            Err(err(MAP, n, format!("`{}`: {key} {why}", shown(line))))
        };
        match (key, value) {
            ("map", None) => break,
            ("type", Some(t)) => once(&mut kind, t.to_owned(), key, n)?,
            ("height", v) => once(&mut height, number(v)?, key, n)?,
            ("width", v) => once(&mut width, number(v)?, key, n)?,
            _ => {
                return Err(err(
                    MAP,
                    n,
                    format!("unexpected header line `{}`", shown(line)),
                ));
            }
        }
    }
    match kind.as_deref() {
        Some("octile") => {}
        Some(other) => {
            return Err(err(
                MAP,
                last_line,
                format!("type `{}` is not `octile`", shown(other)),
            ));
        }
        None => return Err(err(MAP, last_line, "missing `type octile` in the header")),
    }
    let width = width.ok_or_else(|| err(MAP, last_line, "missing `width` in the header"))?;
    let height = height.ok_or_else(|| err(MAP, last_line, "missing `height` in the header"))?;
    // The size is checked before anything is allocated (spec §2 Decision 0.2), and the
    // cells are gathered as the rows arrive, so the allocation never exceeds what the file
    // holds.
    GridMap::check_size(width, height)?;
    // Each at most the cell count, which is within the limit.
    let (width, height) = (width as usize, height as usize);
    // The rows in file order (top row first), flipped at the end.
    let mut file_rows: Vec<u8> = Vec::new();
    let mut row = 0;
    for (n, line) in it {
        last_line = n;
        if row == height {
            return Err(err(
                MAP,
                n,
                format!("more than the {height} rows the header gives"),
            ));
        }
        let mut count = 0;
        for (x, c) in line.chars().enumerate() {
            count += 1;
            if x >= width {
                continue;
            }
            file_rows.push(match c {
                '.' | 'G' | 'S' => 0,
                '@' | 'O' | 'T' | 'W' => 1,
                other => {
                    return Err(err(
                        MAP,
                        n,
                        format!("column {x}: {other:?} is not a terrain character (.GS@OTW)"),
                    ));
                }
            });
        }
        if count != width {
            return Err(err(
                MAP,
                n,
                format!("row {row} has {count} cells, expected width {width}"),
            ));
        }
        row += 1;
    }
    if row != height {
        return Err(err(
            MAP,
            last_line,
            format!("only {row} rows, expected height {height}"),
        ));
    }
    // Row 0 of the file is y = height − 1.
    let mut cells = Vec::with_capacity(file_rows.len());
    for r in file_rows.chunks_exact(width).rev() {
        cells.extend_from_slice(r);
    }
    GridMap::new(width, height, 1.0, (0.0, 0.0), cells)
}

/// One problem of a `.scen` file, as written (MovingAI coordinates).
#[derive(Debug, Clone, PartialEq)]
pub struct ScenProblem {
    /// The bucket (problems grouped by optimal length).
    pub bucket: u32,
    /// The map column: a bare name or a path.
    pub map: String,
    /// Map width in cells.
    pub map_width: usize,
    /// Map height in cells.
    pub map_height: usize,
    /// Start `(x, y)`, y the row from the top.
    pub start: (usize, usize),
    /// Goal `(x, y)`, y the row from the top.
    pub goal: (usize, usize),
    /// The optimal path length in cells (octile, no corner cutting).
    pub optimal_length: f64,
}

impl ScenProblem {
    /// The start as a `GridMap` cell: `(x, map_height − 1 − y)` (see the module docs).
    /// A problem whose start lies outside its map size (one built by hand: [`load_scen`]
    /// checks what it reads) is refused with [`MapError::CellOutside`].
    pub fn start_cell(&self) -> Result<Cell, MapError> {
        self.cell(self.start, "ScenProblem start")
    }

    /// The goal as a `GridMap` cell: `(x, map_height − 1 − y)`; refused as
    /// [`start_cell`](Self::start_cell) is.
    pub fn goal_cell(&self) -> Result<Cell, MapError> {
        self.cell(self.goal, "ScenProblem goal")
    }

    fn cell(&self, (x, y): (usize, usize), what: &'static str) -> Result<Cell, MapError> {
        let flipped = self
            .map_height
            .checked_sub(1)
            .and_then(|top| top.checked_sub(y));
        match flipped {
            Some(row) if x < self.map_width => Ok((x, row)),
            _ => Err(MapError::CellOutside {
                what,
                x: i64::try_from(x).unwrap_or(i64::MAX),
                y: i64::try_from(y).unwrap_or(i64::MAX),
                width: self.map_width,
                height: self.map_height,
            }),
        }
    }
}

/// Reads a `.scen` file (version 1 / 1.0). Every coordinate is checked to lie inside the
/// map size given on its line.
pub fn load_scen(text: &str) -> Result<Vec<ScenProblem>, MapError> {
    let mut it = lines(crate::rtc::without_bom(text));
    match it.next() {
        Some((n, line)) => {
            let words: Vec<&str> = line.split_whitespace().collect();
            if !matches!(words.as_slice(), ["version", "1" | "1.0"]) {
                return Err(err(
                    SCEN,
                    n,
                    format!("expected `version 1`, found `{}`", shown(line)),
                ));
            }
        }
        None => return Err(err(SCEN, 1, "empty file: expected `version 1`")),
    }
    it.map(|(n, line)| parse_problem(n, line)).collect()
}

fn parse_problem(n: usize, line: &str) -> Result<ScenProblem, MapError> {
    let fields: Vec<&str> = if line.contains('\t') {
        line.split('\t').map(str::trim).collect()
    } else {
        line.split_whitespace().collect()
    };
    let [bucket, map, w, h, sx, sy, gx, gy, opt] = fields.as_slice() else {
        return Err(err(
            SCEN,
            n,
            format!("expected 9 fields, found {}", fields.len()),
        ));
    };
    let int = |name: &str, v: &str| -> Result<usize, MapError> {
        whole(v).map_err(|why| err(SCEN, n, format!("{name} `{}` {why}", shown(v))))
    };
    let bucket = u32::try_from(int("bucket", bucket)?)
        .map_err(|_| err(SCEN, n, format!("bucket `{bucket}` is too large")))?;
    let (map_width, map_height) = (int("map width", w)?, int("map height", h)?);
    let start = (int("start x", sx)?, int("start y", sy)?);
    let goal = (int("goal x", gx)?, int("goal y", gy)?);
    for (what, (x, y)) in [("start", start), ("goal", goal)] {
        if x >= map_width || y >= map_height {
            return Err(err(
                SCEN,
                n,
                format!("{what} ({x}, {y}) is outside the {map_width}×{map_height} map"),
            ));
        }
    }
    let optimal_length = opt
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite() && *v >= 0.0)
        .ok_or_else(|| {
            err(
                SCEN,
                n,
                format!("optimal length `{}` is not a number ≥ 0", shown(opt)),
            )
        })?;
    Ok(ScenProblem {
        bucket,
        map: (*map).to_owned(),
        map_width,
        map_height,
        start,
        goal,
        optimal_length,
    })
}

/// Reads a `.map` file (native only).
#[cfg(not(target_arch = "wasm32"))]
pub fn load_map_file(path: impl AsRef<std::path::Path>) -> Result<GridMap, MapError> {
    load_map(&text_of(path.as_ref(), MAP)?)
}

/// Reads a `.scen` file (native only).
#[cfg(not(target_arch = "wasm32"))]
pub fn load_scen_file(path: impl AsRef<std::path::Path>) -> Result<Vec<ScenProblem>, MapError> {
    load_scen(&text_of(path.as_ref(), SCEN)?)
}

#[cfg(not(target_arch = "wasm32"))]
fn text_of(path: &std::path::Path, format: &'static str) -> Result<String, MapError> {
    String::from_utf8(super::read_file(path)?).map_err(|e| MapError::Format {
        format,
        line: None,
        reason: format!("not UTF-8: {e}"),
    })
}
