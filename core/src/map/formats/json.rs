//! rtnav's own JSON map format: small, readable and writable by hand (spec §2).
//!
//! ```json
//! {
//!   "width": 6,
//!   "height": 3,
//!   "grid_size": 0.5,
//!   "origin": [-1.0, 0.0],
//!   "rows": [
//!     "######",
//!     "#..#.#",
//!     "#....#"
//!   ]
//! }
//! ```
//!
//! | key | type | meaning |
//! | --- | --- | --- |
//! | `width`, `height` | integers ≥ 1 | cells in x and y (`MapLengthX`, `MapLengthY`) |
//! | `grid_size` | number, 1e-4 ..= 1e3 | cell edge in metres (`GridSize`); the origin and the far corner lie within ±1e9 m ([`GridMap::check_geometry`]) |
//! | `origin` | `[x, y]`, optional | world position (m) of the lower-left corner of cell (0, 0); default `[0, 0]` |
//! | `rows` | `height` strings of `width` characters | `.` free, `#` obstacle. **The first string is the top row** (y = `height − 1`), so the file looks like the map; the last string is row y = 0 |
//! | `cells` | `width · height` numbers 0/1 | instead of `rows`: `SetMap`'s `MapData`, x fastest from y = 0 (000 §3.2.2.1 (4)) |
//!
//! Exactly one of `rows` and `cells` is given; any other key is an error (a typo is not
//! silently ignored). [`to_string`] writes `rows`.

use serde::{Deserialize, Serialize};

use crate::errors::MapError;
use crate::map::GridMap;

const FORMAT: &str = "rtnav JSON map";

/// The file as written (see the module documentation).
#[derive(Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct MapFile {
    width: u64,
    height: u64,
    grid_size: f64,
    #[serde(default)]
    origin: [f64; 2],
    #[serde(default, skip_serializing_if = "Option::is_none")]
    rows: Option<Vec<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    cells: Option<Vec<u8>>,
}

fn err(line: Option<usize>, reason: impl Into<String>) -> MapError {
    MapError::Format {
        format: FORMAT,
        line,
        reason: reason.into(),
    }
}

/// Reads an rtnav JSON map.
pub fn load(text: &str) -> Result<GridMap, MapError> {
    let file: MapFile = serde_json::from_str(crate::rtc::without_bom(text)).map_err(|e| {
        err(
            Some(e.line()),
            crate::present::with_short_quotes(&e.to_string()),
        )
    })?;
    // The size is checked before anything is allocated for the cells (spec §2 Decision
    // 0.2): `width × height` within the limit, no overflow; then the geometry, before the
    // rows are read.
    let count = GridMap::check_size(file.width, file.height)?;
    let too_big = |axis: &str, v: u64| err(None, format!("{axis} {v} is too large"));
    let width = usize::try_from(file.width).map_err(|_| too_big("width", file.width))?;
    let height = usize::try_from(file.height).map_err(|_| too_big("height", file.height))?;
    let origin = (file.origin[0], file.origin[1]);
    GridMap::check_geometry(width, height, file.grid_size, origin)?;
    let cells = match (file.rows, file.cells) {
        (Some(rows), None) => cells_from_rows(&rows, width, height, count)?,
        (None, Some(cells)) => cells,
        (Some(_), Some(_)) => return Err(err(None, "give either `rows` or `cells`, not both")),
        (None, None) => return Err(err(None, "missing `rows` (or `cells`)")),
    };
    GridMap::new(width, height, file.grid_size, origin, cells)
}

/// The cells of `rows` (`count` = `width × height`, already checked against the limit).
/// Every row is checked before the cells are allocated, so the allocation never exceeds
/// what the file holds.
fn cells_from_rows(
    rows: &[String],
    width: usize,
    height: usize,
    count: usize,
) -> Result<Vec<u8>, MapError> {
    if rows.len() != height {
        return Err(err(
            None,
            format!("`rows` has {} rows, expected height {height}", rows.len()),
        ));
    }
    for (r, row) in rows.iter().enumerate() {
        let n = row.chars().count();
        if n != width {
            let y = height - 1 - r;
            return Err(err(
                None,
                format!("rows[{r}] (y = {y}) has {n} cells, expected width {width}"),
            ));
        }
    }
    let mut cells = vec![0u8; count];
    for (r, row) in rows.iter().enumerate() {
        let y = height - 1 - r;
        for (x, c) in row.chars().enumerate() {
            cells[x + y * width] = match c {
                '.' => 0,
                '#' => 1,
                other => {
                    return Err(err(
                        None,
                        format!(
                            "rows[{r}] (y = {y}), column {x}: {other:?} is neither '.' (free) nor '#' (obstacle)"
                        ),
                    ));
                }
            };
        }
    }
    Ok(cells)
}

/// Writes `map` as an rtnav JSON map (with `rows`, top row first). [`load`] reads it back
/// into an equal map (same size, grid size, origin and cells; the version is not stored).
pub fn to_string(map: &GridMap) -> String {
    let (w, h) = (map.width(), map.height());
    let rows = (0..h)
        .rev()
        .map(|y| {
            map.cells()[y * w..(y + 1) * w]
                .iter()
                .map(|&c| if c == 1 { '#' } else { '.' })
                .collect()
        })
        .collect();
    let file = MapFile {
        width: w as u64,
        height: h as u64,
        grid_size: map.grid_size(),
        origin: [map.origin().0, map.origin().1],
        rows: Some(rows),
        cells: None,
    };
    // A struct of numbers and strings always serialises.
    let mut text = serde_json::to_string_pretty(&file).unwrap_or_default();
    text.push('\n');
    text
}

/// Reads an rtnav JSON map file (native only).
#[cfg(not(target_arch = "wasm32"))]
pub fn load_file(path: impl AsRef<std::path::Path>) -> Result<GridMap, MapError> {
    let bytes = super::read_file(path.as_ref())?;
    let text = String::from_utf8(bytes).map_err(|e| err(None, format!("not UTF-8: {e}")))?;
    load(&text)
}
