//! Errors building, loading or updating a grid map (spec §2).

/// Errors building, loading or updating a grid map (spec §2).
#[derive(Debug, Clone, PartialEq, thiserror::Error, serde::Serialize, strum::VariantNames)]
#[serde(tag = "kind")]
#[non_exhaustive]
pub enum MapError {
    /// A dimension of zero (or negative in the source data).
    #[error("map dimension {axis} = {value} must be at least 1")]
    BadDimension {
        /// `MapLengthX` or `MapLengthY`.
        axis: &'static str,
        /// The value given.
        value: i64,
    },
    /// More cells than the map size limit.
    #[error("map of {width}×{height} = {cells} cells exceeds the limit of {limit} cells")]
    TooLarge {
        /// Cells in x, as given.
        width: u64,
        /// Cells in y, as given.
        height: u64,
        /// width × height, exactly, in decimal digits: two 64-bit sizes multiply to up to
        /// 128 bits, which neither a JSON number nor JavaScript holds exactly.
        cells: String,
        /// The limit.
        limit: usize,
    },
    /// `GridSize` outside the limits, or not a number (spec §2 Decision "geometry").
    #[error("GridSize {} m must lie between {min} m and {max} m", number(*value))]
    BadGridSize {
        /// The value given \[m\].
        value: f64,
        /// The smallest accepted, [`MIN_GRID_SIZE`](crate::map::MIN_GRID_SIZE).
        min: f64,
        /// The largest accepted, [`MAX_GRID_SIZE`](crate::map::MAX_GRID_SIZE).
        max: f64,
    },
    /// An origin, or a far corner (origin + size · `GridSize`), that is not finite or lies
    /// beyond the coordinate limit (spec §2 Decision "geometry").
    #[error(
        "map origin ({}, {}) and far corner ({}, {}) must be finite and within ±{limit} m",
        number(*x),
        number(*y),
        number(*far_x),
        number(*far_y)
    )]
    BadOrigin {
        /// Origin x \[m\].
        x: f64,
        /// Origin y \[m\].
        y: f64,
        /// The far corner's x: x + width · GridSize \[m\].
        far_x: f64,
        /// The far corner's y: y + height · GridSize \[m\].
        far_y: f64,
        /// The largest distance from 0 accepted on either axis,
        /// [`MAX_COORDINATE`](crate::map::MAX_COORDINATE) \[m\].
        limit: f64,
    },
    /// `MapData` of the wrong length.
    #[error("MapData has {len} cells, expected MapLengthX × MapLengthY = {expected}")]
    DataLength {
        /// Cells given.
        len: usize,
        /// Cells expected.
        expected: usize,
    },
    /// A cell value other than 0 (free) or 1 (obstacle).
    #[error("{what}[{index}] = {value}: a cell must be 0 (free) or 1 (obstacle)")]
    BadCellValue {
        /// `MapData` or `value` (MapUpdate).
        what: &'static str,
        /// Index in the array.
        index: usize,
        /// The value given.
        value: i64,
    },
    /// MapUpdate arrays whose length differs from `num`.
    #[error("MapUpdate: {array} has {len} entries, but num = {num}")]
    UpdateLength {
        /// `X`, `Y` or `value`.
        array: &'static str,
        /// Its length.
        len: usize,
        /// `num` as given.
        num: i64,
    },
    /// A cell index outside the map.
    #[error("{what}: cell ({x}, {y}) is outside the {width}×{height} map")]
    CellOutside {
        /// Which call or array.
        what: &'static str,
        /// x index.
        x: i64,
        /// y index.
        y: i64,
        /// Map width.
        width: usize,
        /// Map height.
        height: usize,
    },
    /// A map file that cannot be read as its format requires.
    #[error("{format}{}: {reason}", at_line(*line))]
    Format {
        /// `rtnav JSON map`, `ROS map YAML`, `ROS map image`, `MovingAI .map`,
        /// `MovingAI .scen`.
        format: &'static str,
        /// 1-based line, if the problem has one.
        line: Option<usize>,
        /// What is wrong.
        reason: String,
    },
    /// A map file that cannot be read (native convenience loaders only).
    #[error("cannot read `{path}`: {reason}")]
    Io {
        /// The file.
        path: String,
        /// The operating system's reason.
        reason: String,
    },
    /// A timestamp whose `nsec` is not below 10⁹ (spec §4 Decision 0.2).
    #[error("{what}: timestamp nsec = {nsec} must be below 1000000000")]
    BadTimestamp {
        /// Where it came in, e.g. `MapUpdate`.
        what: &'static str,
        /// The nanoseconds given.
        nsec: u32,
    },
}

/// A number as a person would write it: plainly, or in exponent form (`1e300`, `1e-12`)
/// where plain digits would run past 15 places.
fn number(v: f64) -> String {
    let size = v.abs();
    if v.is_finite() && size != 0.0 && !(1e-6..1e15).contains(&size) {
        format!("{v:e}")
    } else {
        v.to_string()
    }
}

fn at_line(line: Option<usize>) -> String {
    line.map(|l| format!(" (line {l})")).unwrap_or_default()
}
