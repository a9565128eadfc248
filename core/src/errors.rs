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
    /// A timestamp refused where a sample entered a component (SPEC §4 Decision 0.2:
    /// `nsec` ≥ 10⁹), by [`Time::checked`](crate::rtc::Time::checked).
    #[error(transparent)]
    Timestamp(#[from] crate::rtc::TimestampError),
    /// A map that cannot be built, loaded or updated (SPEC §2).
    #[error(transparent)]
    Map(#[from] MapError),
    // --- motion (MotorControl, physics, DriveControl, Localization) ---
    /// Bad input or parameters of the motion components (SPEC §4, §5).
    #[error(transparent)]
    Motion(#[from] MotionError),

    // --- LocalPathPlanning (branch `local`) ---
    /// A LocalPath service call refused, or a local plan that could not be made (SPEC §3).
    #[error(transparent)]
    LocalPath(#[from] LocalPathError),

    // --- renderer (render engineer) ---
    /// A scene or frame the renderer cannot draw (SPEC §5 InventGUI).
    #[error(transparent)]
    Render(#[from] RenderError),

    // --- maps: global path planning ---
    /// A global plan that cannot be made (SPEC §5 "GlobalPathPlanning").
    #[error(transparent)]
    GlobalPlanning(#[from] GlobalPlanningError),

    // --- system: the whole system, scenarios, trace ---
    /// A request to the whole system or a scenario that cannot be carried out (SPEC §0, §6).
    #[error(transparent)]
    System(#[from] SystemError),
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

// --- motion (MotorControl, physics, DriveControl, Localization): SPEC §4, §5 ---

/// Errors of the motion components: MotorControl (SPEC §4), the physics, DriveControl and
/// Localization (SPEC §5). A component that meets one of these on a data port does not fail:
/// it goes to its safe state (zero torque, zero velocity, the held pose) and reports it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum MotionError {
    /// A NaN or infinite number where a finite one is needed.
    #[error("{port}: {field} = {value} is not finite")]
    NonFinite {
        /// The port, service or parameter that carried it (seed name).
        port: &'static str,
        /// Which value, e.g. `vx`, `data[1]`.
        field: String,
        /// The value.
        value: f64,
    },
    /// A sequence of the wrong length.
    #[error("{port}: {len} values, expected {expected}")]
    WrongLength {
        /// The port (seed name).
        port: &'static str,
        /// Values received.
        len: usize,
        /// What is needed, e.g. `2`, `at least 2`, `12`.
        expected: String,
    },
    /// A timestamp with `nsec` ≥ 10⁹ on a port or service (SPEC §4 Decision 0.2), refused
    /// by [`Time::checked`](crate::rtc::Time::checked).
    #[error(transparent)]
    BadTimestamp(#[from] crate::rtc::TimestampError),
    /// A timestamp not later than the previous one on the same port.
    #[error("{port}: time went backwards (or stood still): {now_s} s after {previous_s} s")]
    TimeWentBackwards {
        /// The port (seed name).
        port: &'static str,
        /// The previous timestamp \[s\].
        previous_s: f64,
        /// The refused timestamp \[s\].
        now_s: f64,
    },
    /// No new data on a port for too long.
    #[error("{port}: no new data for {age_s} s (limit {limit_s} s)")]
    Stale {
        /// The port (seed name).
        port: &'static str,
        /// Time since the last valid data \[s\].
        age_s: f64,
        /// The limit \[s\].
        limit_s: f64,
    },
    /// A model or controller parameter that cannot be used.
    #[error("parameter `{name}` = {value}: {reason}")]
    BadParameter {
        /// The parameter's name.
        name: String,
        /// The value given.
        value: f64,
        /// Why it is refused.
        reason: &'static str,
    },
    /// `leftWheelID` and `rightWheelID` name the same joint (002 §4.2).
    #[error("leftWheelID and rightWheelID are both {id}: the wheels need two joints")]
    SameWheelId {
        /// The shared id.
        id: i32,
    },
    /// A map operation on a physics that has no map yet.
    #[error("{what}: no map has been set")]
    NoMap {
        /// The operation, e.g. `MapUpdate`.
        what: &'static str,
    },
    /// A component's period that is not a whole number of physics steps.
    #[error(
        "period of {period_ns} ns is not a whole, positive number of {step_ns} ns physics steps"
    )]
    BadPeriod {
        /// The component's period.
        period_ns: u64,
        /// The physics step.
        step_ns: u64,
    },
}

// --- LocalPathPlanning (branch `local`) ---

/// Errors of the LocalPathPlanning component (seed 000, SPEC §3): a `LocalPath` service call
/// refused (nothing held changes), or the reason a local plan could not be made (sent to the
/// GUI as the planning-failure notice of 000 §5.2.4.13).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum LocalPathError {
    /// A number that must be finite is NaN or infinite.
    #[error("{call}: {argument} = {value} is not finite")]
    NotFinite {
        /// The service call, e.g. `SetPosition`.
        call: &'static str,
        /// The argument, e.g. `StartX`.
        argument: &'static str,
        /// The value given.
        value: f64,
    },
    /// `Direction` other than 1 (forward) or 2 (backward) (000 §3.2.2.1 (1)).
    #[error("SetPosition: Direction = {value} must be 1 (forward) or 2 (backward)")]
    BadDirection {
        /// The value given.
        value: i16,
    },
    /// A call that needs the map before `SetMap` (000 §5.2.4.1).
    #[error("{call}: no map has been set (SetMap first)")]
    NoMap {
        /// The service call.
        call: &'static str,
    },
    /// A position outside the map (outside counts as obstacle, SPEC §2).
    #[error("{what} ({x}, {y}) is outside the map")]
    OutsideMap {
        /// `start`, `goal` or `current position`.
        what: &'static str,
        /// X \[m\].
        x: f64,
        /// Y \[m\].
        y: f64,
    },
    /// A position whose cell, or a cell within `dmin` of it, is an obstacle (000 §5.2.4.2,
    /// §5.2.4.4).
    #[error(
        "{what} ({x}, {y}) in cell ({}, {}) is too close to an obstacle: obstacle distance {distance} m ≤ dmin = {dmin} m",
        cell.0, cell.1
    )]
    NotClear {
        /// `start`, `goal` or `current position`.
        what: &'static str,
        /// X \[m\].
        x: f64,
        /// Y \[m\].
        y: f64,
        /// Its cell.
        cell: (usize, usize),
        /// The cell's obstacle distance \[m\].
        distance: f64,
        /// `dmin` \[m\].
        dmin: f64,
    },
    /// A `MapUpdate` timestamp with `nsec` ≥ 10⁹.
    #[error("MapUpdate: nsec = {nsec} must be below 1000000000")]
    BadTimestamp {
        /// The value given.
        nsec: u32,
    },
    /// `GlobalPathCourse` arrays whose length differs from `num`.
    #[error("GlobalPathCourse: {array} has {len} entries, but num = {num}")]
    PathLength {
        /// `GridPathX` or `GridPathY`.
        array: &'static str,
        /// Its length.
        len: usize,
        /// `num` as given.
        num: i32,
    },
    /// `GlobalPathCourse` with no cell.
    #[error("GlobalPathCourse: the path is empty")]
    EmptyPath,
    /// A path cell outside the map.
    #[error("GlobalPathCourse: cell {index} = ({x}, {y}) is outside the {width}×{height} map")]
    PathCellOutside {
        /// Index in the path.
        index: usize,
        /// x index.
        x: i64,
        /// y index.
        y: i64,
        /// Map width.
        width: usize,
        /// Map height.
        height: usize,
    },
    /// Consecutive path cells that are not 8-neighbours (SPEC §3 Decision).
    #[error(
        "GlobalPathCourse: cells {} = ({}, {}) and {} = ({}, {}) are not 8-neighbours",
        index - 1, from.0, from.1, index, to.0, to.1
    )]
    PathNotAdjacent {
        /// Index of the second cell.
        index: usize,
        /// The cell before.
        from: (i64, i64),
        /// The cell at `index`.
        to: (i64, i64),
    },
    /// The held path does not pass the goal cell after the current position, so there is
    /// no local target (000 §5.2.4.8).
    #[error("the held path does not reach the goal cell ({}, {})", goal.0, goal.1)]
    GoalNotOnPath {
        /// The goal's cell.
        goal: (usize, usize),
    },
    /// Every held-path cell from the local target to the goal is within `dmin` of an
    /// obstacle, so no target for the field is left (000 §5.2.4.9).
    #[error("the held path is blocked from cell ({}, {}) to the goal: no passable local target", from.0, from.1)]
    TargetBlocked {
        /// The local target found by distance.
        from: (usize, usize),
    },
    /// The potential field never reached the current cell: no passable route between the
    /// current position and the local target (000 §5.2.4.9).
    #[error(
        "no route: the potential field from the local target ({}, {}) does not reach the current cell ({}, {})",
        target.0, target.1, current.0, current.1
    )]
    NoRoute {
        /// The local target.
        target: (usize, usize),
        /// The current cell.
        current: (usize, usize),
    },
    /// A cell of a field request that is not in the field's map.
    #[error("{what} cell ({x}, {y}) is outside the {width}×{height} map")]
    CellOutside {
        /// `target` or `current`.
        what: &'static str,
        /// x index.
        x: usize,
        /// y index.
        y: usize,
        /// Map width.
        width: usize,
        /// Map height.
        height: usize,
    },
    /// A planner parameter outside its range (000 §4.2).
    #[error("{name} = {value} is out of range {range}")]
    BadParameter {
        /// The parameter's seed name.
        name: &'static str,
        /// The value.
        value: f64,
        /// The allowed range.
        range: &'static str,
    },
}

// --- renderer (render engineer) ---

/// Errors of the renderer (SPEC §5 InventGUI): a frame size or a scene it cannot draw. Drawing
/// itself never fails for a valid scene.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RenderError {
    /// A frame with no pixels, or larger than the renderer accepts.
    #[error("frame size {width}×{height} is not drawable: each side must be 1..={max}")]
    FrameSize {
        /// Width asked for, pixels.
        width: u32,
        /// Height asked for, pixels.
        height: u32,
        /// The largest side accepted.
        max: u32,
    },
    /// A number in the scene that is not usable (NaN, infinite, negative, …).
    #[error("scene {what}{}: {value} must be {expected}", at_index(*index))]
    BadNumber {
        /// Which value, e.g. `robot.pose.theta`.
        what: &'static str,
        /// Index in its list, if it is in one.
        index: Option<usize>,
        /// The value given.
        value: f64,
        /// What it must be, e.g. `finite and ≥ 0`.
        expected: &'static str,
    },
    /// A per-cell array whose length is not the map's cell count.
    #[error("scene {what} has {len} entries, but the map has {expected} cells")]
    FieldLength {
        /// `field.potential` or `field.state`.
        what: &'static str,
        /// Its length.
        len: usize,
        /// width × height of the map.
        expected: usize,
    },
    /// A path cell outside the map.
    #[error("scene {what}[{index}]: cell ({x}, {y}) is outside the {width}×{height} map")]
    CellOutside {
        /// `global_path` or `local_path`.
        what: &'static str,
        /// Index in the path.
        index: usize,
        /// x index.
        x: usize,
        /// y index.
        y: usize,
        /// Map width.
        width: usize,
        /// Map height.
        height: usize,
    },
    /// The PNG encoder failed.
    #[error("PNG encoding failed: {reason}")]
    Png {
        /// The encoder's message.
        reason: String,
    },
}

fn at_index(index: Option<usize>) -> String {
    index.map(|i| format!("[{i}]")).unwrap_or_default()
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

// --- system: the whole system, scenarios, trace (SPEC §0, §6) ---

/// Errors of the whole system (`crate::system`): GUI requests that cannot be carried out,
/// and scenario files that cannot be used. Nothing held changes when one is returned.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SystemError {
    /// A share link's token that cannot be used.
    #[error("share link: {reason}")]
    BadShareToken {
        /// Why.
        reason: String,
    },
    /// A clock speed outside the range offered.
    #[error("speed {speed}× is outside {min}× to {max}×")]
    BadSpeed {
        /// The speed asked for.
        speed: f64,
        /// The slowest.
        min: f64,
        /// The fastest.
        max: f64,
    },
    /// An input port the system cannot write into ([`System::inject_input`](crate::system::System::inject_input)).
    #[error("{component} has no input port `{port}` to inject into (ports: {known})")]
    UnknownPort {
        /// The component named.
        component: String,
        /// The port named.
        port: String,
        /// The ports that can be injected into.
        known: &'static str,
    },
    /// A request that needs a map before one is loaded.
    #[error("{call}: no map is loaded")]
    NoMap {
        /// The request, e.g. `MapUpdate`.
        call: &'static str,
    },
    /// A component name that is not one of the system's.
    #[error("no component named `{name}` (expected one of {expected})")]
    UnknownComponent {
        /// The name given.
        name: String,
        /// The names known.
        expected: String,
    },
    /// A component without configuration parameters.
    #[error("component `{component}` has no configuration parameters")]
    NoConfiguration {
        /// The component.
        component: String,
    },
    /// A request that places the robot, made while it drives.
    #[error("{call}: the robot is driving (deactivate the physics first, or set only a new goal)")]
    Driving {
        /// The request.
        call: &'static str,
    },
    /// A new goal without a start: the robot has not been placed yet.
    #[error("{call}: no start pose yet (set start and goal first)")]
    NoStart {
        /// The request.
        call: &'static str,
    },
    /// A number that must be finite (and, for times, non-negative) is not.
    #[error("{what} = {value} must be finite{}", if *non_negative { " and ≥ 0" } else { "" })]
    BadNumber {
        /// What it is, e.g. `run_until seconds`.
        what: &'static str,
        /// The value given.
        value: f64,
        /// Whether it must also be ≥ 0.
        non_negative: bool,
    },
    /// A scenario file that cannot be read or used.
    #[error("scenario `{scenario}`: {reason}")]
    Scenario {
        /// The scenario's name or file.
        scenario: String,
        /// What is wrong.
        reason: String,
    },
    /// A file a scenario names that the resolver cannot supply.
    #[error("cannot read `{path}`: {reason}")]
    File {
        /// The path as the scenario gives it.
        path: String,
        /// Why.
        reason: String,
    },
    /// A telemetry history of capacity zero.
    #[error("telemetry capacity must be at least 1")]
    ZeroCapacity,

    // --- teaching tools (branch `teachcore`): the configuration bundle, the inspector ---
    /// A line of a configuration bundle (`System::load_conf`) before the first component
    /// marker that is neither a comment nor blank.
    #[error(
        "configuration file line {line}: `{text}` is not inside a component's block \
         (a block starts with a marker line `# [InstanceName]`)"
    )]
    ConfOutsideBlock {
        /// 1-based line in the whole file.
        line: usize,
        /// The line as written.
        text: String,
    },
    /// A block marker `# [NAME]` that names no component with configuration parameters.
    #[error(
        "configuration file line {line}: marker `# [{name}]` names no component with \
         configuration parameters (expected one of {expected})"
    )]
    ConfUnknownComponent {
        /// 1-based line of the marker in the whole file.
        line: usize,
        /// The name in the marker.
        name: String,
        /// The instance names known.
        expected: String,
    },
    /// A second block for the same component.
    #[error(
        "configuration file line {line}: a second block for `{component}` (its first block \
         starts at line {first})"
    )]
    ConfDuplicateComponent {
        /// 1-based line of the second marker.
        line: usize,
        /// The component's instance name.
        component: String,
        /// 1-based line of the first marker.
        first: usize,
    },
    /// A component's block that cannot be read or applied (unknown key, bad value, value
    /// out of range, unknown configuration set).
    #[error("configuration file line {line}, component `{component}`: {}", conf_problem(.problem))]
    ConfBlock {
        /// The component's instance name.
        component: String,
        /// 1-based line in the whole file.
        line: usize,
        /// The problem, as the component's configuration reports it.
        problem: ConfigError,
    },
    /// A cell that is not in the map.
    #[error("cell ({x}, {y}) is outside the map ({width} × {height} cells)")]
    CellOutsideMap {
        /// Column asked for.
        x: i64,
        /// Row asked for.
        y: i64,
        /// Cells in x.
        width: usize,
        /// Cells in y.
        height: usize,
    },
}

/// A `.conf` problem without its line (the bundle's error names the line of the whole file).
fn conf_problem(e: &ConfigError) -> String {
    let mut e = e.clone();
    match &mut e {
        ConfigError::UnknownParameter { line, .. }
        | ConfigError::OutOfRange { line, .. }
        | ConfigError::BadValue { line, .. } => *line = None,
        ConfigError::Syntax { text, reason, .. } => {
            return format!("cannot read `{text}`: {reason}");
        }
        _ => {}
    }
    e.to_string()
}
