//! The crate's error types: one `thiserror` enum per area, gathered in [`Error`].
//!
//! Every variant names the problem with named fields, so a GUI can show it and a test can
//! match it. Library code returns these; it does not panic on bad input.

use crate::rtc::{ContextState, LifecycleState, Request};

/// Any error `rtnav` returns.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// An illegal lifecycle request or an execution-context problem (SPEC §1).
    #[error(transparent)]
    Lifecycle(#[from] LifecycleError),
    /// A configuration parameter or `.conf` file problem (SPEC §1).
    #[error(transparent)]
    Config(#[from] ConfigError),
    /// A map that cannot be built, loaded or updated (SPEC §2).
    #[error(transparent)]
    Map(#[from] MapError),
    // --- maps: global path planning ---
    /// A global plan that cannot be made (SPEC §5 "GlobalPathPlanning").
    #[error(transparent)]
    GlobalPlanning(#[from] GlobalPlanningError),
}

/// `Result` with this crate's [`Error`].
pub type Result<T, E = Error> = core::result::Result<T, E>;

/// Errors of the RT-component lifecycle and execution context (SPEC §1, seed 003).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum LifecycleError {
    /// The request is not a legal transition from the component's current state.
    #[error("component `{component}`: cannot {request} while {from}")]
    InvalidTransition {
        /// The component's instance name.
        component: String,
        /// Its state when the request arrived (unchanged).
        from: LifecycleState,
        /// What was asked.
        request: Request,
    },
    /// Activate / deactivate / reset need a running execution context (no callback runs while
    /// it is Stopped, 003 "スレッドの停止状態と実行状態").
    #[error("component `{component}`: cannot {request} while the execution context is {context}")]
    ContextNotRunning {
        /// The component's instance name.
        component: String,
        /// What was asked.
        request: Request,
        /// The context's state.
        context: ContextState,
    },
    /// Start while Running or stop while Stopped.
    #[error("execution context is already {state}")]
    ContextAlready {
        /// The state it is already in.
        state: ContextState,
    },
    /// No component with that id is attached.
    #[error("no component with id {id}")]
    UnknownComponent {
        /// The id asked for.
        id: usize,
    },
    /// A rate that is not positive and finite, or whose period is not a whole number of
    /// the context's base ticks.
    #[error("rate {rate} Hz is not usable: {reason}")]
    InvalidRate {
        /// The rate asked for, in Hz.
        rate: f64,
        /// Why it was refused.
        reason: String,
    },
    /// A callback returned an error; the state change it caused is described by `outcome`.
    #[error("component `{component}`: {callback} failed: {reason}")]
    CallbackFailed {
        /// The component's instance name.
        component: String,
        /// The callback that failed, e.g. `on_activated`.
        callback: &'static str,
        /// The reason the callback gave.
        reason: String,
    },
}

/// Errors of configuration parameters and `.conf` files (SPEC §1).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ConfigError {
    /// No parameter of that name.
    #[error("unknown configuration parameter `{name}`{}", at_line(*line))]
    UnknownParameter {
        /// The key as written.
        name: String,
        /// 1-based line in the `.conf` file, if it came from one.
        line: Option<usize>,
    },
    /// A value outside the parameter's range (or NaN).
    #[error("configuration parameter `{name}`{}: {value} is out of range {range}", at_line(*line))]
    OutOfRange {
        /// The parameter.
        name: String,
        /// The value refused.
        value: String,
        /// The allowed range, e.g. `[0, 100]`.
        range: String,
        /// 1-based line in the `.conf` file, if it came from one.
        line: Option<usize>,
    },
    /// A value that does not parse as the parameter's type.
    #[error("configuration parameter `{name}`{}: `{value}` is not a valid {kind}", at_line(*line))]
    BadValue {
        /// The parameter.
        name: String,
        /// The text refused.
        value: String,
        /// The expected type, e.g. `double`.
        kind: &'static str,
        /// 1-based line in the `.conf` file, if it came from one.
        line: Option<usize>,
    },
    /// A `.conf` line that is not `key: value`, a comment or blank.
    #[error("line {line}: cannot read `{text}`: {reason}")]
    Syntax {
        /// 1-based line number.
        line: usize,
        /// The line as written.
        text: String,
        /// What is wrong with it.
        reason: String,
    },
    /// No configuration set of that name.
    #[error("unknown configuration set `{name}`")]
    UnknownSet {
        /// The set asked for.
        name: String,
    },
}

fn at_line(line: Option<usize>) -> String {
    line.map(|l| format!(" (line {l})")).unwrap_or_default()
}

/// Errors building, loading or updating a grid map (SPEC §2).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
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
        /// Cells in x.
        width: usize,
        /// Cells in y.
        height: usize,
        /// width × height.
        cells: u64,
        /// The limit.
        limit: usize,
    },
    /// `GridSize` zero, negative or not finite.
    #[error("GridSize {value} must be positive and finite")]
    BadGridSize {
        /// The value given.
        value: f64,
    },
    /// An origin coordinate that is not finite.
    #[error("map origin ({x}, {y}) must be finite")]
    BadOrigin {
        /// x in metres.
        x: f64,
        /// y in metres.
        y: f64,
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
}

// --- maps: global path planning ---

/// Errors of the global planner (SPEC §5 "GlobalPathPlanning"). Each is also sent as a
/// `PlanningFailure` notice by the component.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum GlobalPlanningError {
    /// Planning was requested before any map was set.
    #[error("no map has been set")]
    NoMap,
    /// A start or goal pose with a NaN or infinite coordinate.
    #[error("{which} pose ({x}, {y}, {theta}) is not finite")]
    NonFinitePose {
        /// `start` or `goal`.
        which: &'static str,
        /// x (m).
        x: f64,
        /// y (m).
        y: f64,
        /// θ (rad).
        theta: f64,
    },
    /// A start or goal outside the map.
    #[error("{which} ({x}, {y}) m is outside the map")]
    OutsideMap {
        /// `start` or `goal`.
        which: &'static str,
        /// x (m).
        x: f64,
        /// y (m).
        y: f64,
    },
    /// A start or goal cell outside the planning grid.
    #[error("{which} cell ({}, {}) is outside the {width}×{height} map", cell.0, cell.1)]
    CellOutside {
        /// `start` or `goal`.
        which: &'static str,
        /// The cell.
        cell: (usize, usize),
        /// Map width.
        width: usize,
        /// Map height.
        height: usize,
    },
    /// A start or goal cell that is an obstacle or lies within `dmin` of one (its obstacle
    /// distance is ≤ `dmin`).
    #[error(
        "{which} cell ({}, {}) is blocked: it is an obstacle or within dmin = {dmin} m of one",
        cell.0, cell.1
    )]
    Blocked {
        /// `start` or `goal`.
        which: &'static str,
        /// The cell.
        cell: (usize, usize),
        /// The `dmin` in force (m).
        dmin: f64,
    },
    /// No path joins start and goal.
    #[error("no path from cell ({}, {}) to cell ({}, {})", start.0, start.1, goal.0, goal.1)]
    NoPath {
        /// The start cell.
        start: (usize, usize),
        /// The goal cell.
        goal: (usize, usize),
    },
    /// A `dmin` that is negative or not finite.
    #[error("dmin {value} m must be finite and ≥ 0")]
    BadDmin {
        /// The value given.
        value: f64,
    },
}
