//! Errors of the whole system (`crate::system`), one enum per part: requests to the system,
//! scenario files, the page's session, and the configuration bundle.

use crate::rtc::ConfigError;

/// A request to the whole system that cannot be carried out. Nothing held changes when one
/// is returned.
#[derive(Debug, Clone, PartialEq, thiserror::Error, serde::Serialize, strum::VariantNames)]
#[serde(tag = "kind")]
#[non_exhaustive]
pub enum SystemError {
    /// An input port the system cannot write into ([`Input::InjectInput`](crate::system::Input::InjectInput)).
    #[error("{component} has no input port `{port}` to inject into (ports: {known})")]
    UnknownPort {
        /// The component named.
        component: String,
        /// The port named.
        port: String,
        /// The ports that can be injected into.
        known: &'static str,
    },
    /// A connection id that is not one of the system's data connections between components.
    #[error("no connection `{id}` to cut or restore (connections: {known})")]
    UnknownConnection {
        /// The id given.
        id: String,
        /// The ids of the connections that can be cut.
        known: String,
    },
    /// A connection to InventGUI: it carries the facts the log and the mission are made of.
    #[error(
        "`{id}` carries what InventGUI is told and cannot be cut (cut one between two components)"
    )]
    ConnectionKept {
        /// The id given.
        id: String,
    },
    /// A cut of a cut connection, or a restore of a connected one.
    #[error("`{id}` is already {state}")]
    ConnectionAlready {
        /// The id given.
        id: String,
        /// `cut` or `connected`.
        state: &'static str,
    },
    /// A data port the wiring's table names that the component in that place does not have
    /// (a component standing in for another must have its ports, spec §8).
    #[error("{component} has no {direction}-port `{port}` of type {idl} to connect")]
    PortMissing {
        /// The component.
        component: String,
        /// `in` or `out`.
        direction: &'static str,
        /// The port's name.
        port: &'static str,
        /// Its IDL type.
        idl: &'static str,
    },
    /// A script for a component no script can stand in for (spec §8, Decision 0.4 "what can
    /// be replaced").
    #[error("a script cannot stand in for {component} (it can for {places})")]
    NotScriptable {
        /// The component named.
        component: String,
        /// The components a script can stand in for.
        places: &'static str,
    },
    /// A script declares one component but is loaded into another.
    #[error("the script declares `COMPONENT = \"{declared}\"`, not {component}")]
    ScriptForAnother {
        /// What the script declares.
        declared: String,
        /// Where it was to be loaded.
        component: String,
    },
    /// The built-in component put back where it already is.
    #[error("{component} already runs the built-in component, not a script")]
    NotScripted {
        /// The component named.
        component: String,
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
    /// A request that would set the robot moving before it has a pose (spec §5 "Physics",
    /// Decision 0.4 "no pose until placed"): PhysicsSim is not activated until a start is
    /// placed (`SetPosition`, or a scenario's start).
    #[error("the robot has no pose yet, so PhysicsSim cannot be activated (place a start first)")]
    NotPlaced {
        /// The request (`Activate` or `ActivateAll`); the words leave it to the one who made
        /// it (the page says "Activate all refused: …").
        call: &'static str,
    },
    /// A `MapUpdate` that would put an obstacle under the robot's body (spec §5 "Physics",
    /// Decision 0.4 "an edit on the body"): refused as a whole, as every refused
    /// `MapUpdate` is (spec §2), naming the first such cell.
    #[error(
        "cell ({x}, {y}) lies under the robot's body, so no obstacle can be put there (move the \
         robot or paint around it)"
    )]
    UnderRobot {
        /// Column of the cell.
        x: i64,
        /// Row of the cell.
        y: i64,
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
    /// A telemetry history of capacity zero.
    #[error("telemetry capacity must be at least 1")]
    ZeroCapacity,
    /// A run asked to go on for longer than any run goes ([`MAX_REPLAY_NS`](crate::system::MAX_REPLAY_NS),
    /// 24 h of simulated time): an absurd count of ticks or seconds is refused, not run.
    #[error(
        "{what} asks for {seconds} s of simulated time, more than the {limit_s} s (24 h) a run \
         goes at most"
    )]
    RunTooLong {
        /// The call and its argument, e.g. `run_for seconds`.
        what: &'static str,
        /// The simulated time asked for \[s\].
        seconds: f64,
        /// The most a run goes \[s\].
        limit_s: u64,
    },
    /// A configuration that gives the two planners different `dmin`s (spec §3 Decision 0.2:
    /// one value for the system).
    #[error(
        "dmin must be one value: {first} gives {first_value} m, {second} gives {second_value} m"
    )]
    DminMismatch {
        /// The first component's instance name.
        first: &'static str,
        /// Its `dmin` \[m\].
        first_value: f64,
        /// The second component's instance name.
        second: &'static str,
        /// Its `dmin` \[m\].
        second_value: f64,
    },
}

/// A scenario file that cannot be read or used, or a file it names that cannot be supplied.
#[derive(Debug, Clone, PartialEq, thiserror::Error, serde::Serialize, strum::VariantNames)]
#[serde(tag = "kind")]
#[non_exhaustive]
pub enum ScenarioError {
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
}

/// A request of the page's session (its clock, its share links) that cannot be carried out.
#[derive(Debug, Clone, PartialEq, thiserror::Error, serde::Serialize, strum::VariantNames)]
#[serde(tag = "kind")]
#[non_exhaustive]
pub enum SessionError {
    /// A share link's token that cannot be used.
    #[error("share link: {reason}")]
    BadShareToken {
        /// Why.
        reason: String,
    },
    /// A replay file that cannot be used (`crate::system::Replay`).
    #[error("replay: {reason}")]
    BadReplay {
        /// Why.
        reason: String,
    },
    /// A replay file of a format version this build does not read (an rtnav of another
    /// release wrote it): what it is and what to do.
    #[error(
        "replay: this file is an rtnav replay of format version {found}, written by another \
         release of rtnav; this one reads version {reads}. Open it with the rtnav that wrote \
         it, or run the scenario again here and download a new replay"
    )]
    ReplayVersion {
        /// The version the file gives (`missing` when it gives none).
        found: String,
        /// The version this build reads.
        reads: u32,
    },
    /// A replay of a scenario whose content has changed since the replay was recorded (its
    /// file or its map's files): the run would be judged against something else, so it is
    /// refused (spec §6, Decision 0.3).
    #[error(
        "replay: scenario `{scenario}` has changed since the replay was recorded (content \
         hash recorded {recorded}, this scenario's is {found})"
    )]
    ReplayScenarioChanged {
        /// The scenario's name.
        scenario: String,
        /// The content hash the replay recorded.
        recorded: String,
        /// The content hash of the scenario loaded.
        found: String,
    },
    /// A replay recorded by a build of another behaviour version
    /// ([`BEHAVIOUR_VERSION`](crate::BEHAVIOUR_VERSION)): its runs differ from this build's,
    /// so it is refused rather than re-judged (spec §6, Decision 0.3).
    #[error(
        "replay: recorded by behaviour version {recorded} of the core; this build is \
         behaviour version {this_build}, whose runs differ"
    )]
    ReplayBehaviourChanged {
        /// The behaviour version the replay recorded.
        recorded: u32,
        /// This build's.
        this_build: u32,
    },
    /// A restart asked of a session with no scenario loaded (nothing, or a map picked from a
    /// file): there is no set-up to start again from.
    #[error(
        "restart: no scenario is loaded (a map picked from a file has no set-up to start \
         again from)"
    )]
    NothingToRestart,
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
    /// No file picked as a map.
    #[error("no file chosen: {MAP_FILES_EXPECTED}")]
    NoFile,
    /// A picked file whose name and first bytes say no map format.
    #[error("`{name}` is not a map file I know: {MAP_FILES_EXPECTED}")]
    UnknownFile {
        /// The file's name.
        name: String,
    },
    /// A picked ROS YAML file that is not UTF-8.
    #[error("`{name}` is not text: {reason}")]
    NotText {
        /// The file's name.
        name: String,
        /// Why.
        reason: String,
    },
    /// A ROS YAML file picked without its image.
    #[error("`{name}` names the image `{image}`: pick it together with the YAML file")]
    MissingImage {
        /// The YAML file's name.
        name: String,
        /// The image it names.
        image: String,
    },
    /// More than one map picked (other than a YAML file and its image).
    #[error("{count} files chosen: {MAP_FILES_EXPECTED}")]
    FileCount {
        /// How many.
        count: usize,
    },
    /// A MovingAI cell size that is not positive.
    #[error("MovingAI cell size {value} m must be positive")]
    BadCellSize {
        /// The size asked for \[m\].
        value: f64,
    },
    /// A ROS image picked without its YAML file.
    #[error("`{name}` is an image: a ROS map needs its .yaml file too (pick both)")]
    ImageOnly {
        /// The image's name.
        name: String,
    },
    /// A map edit whose lists of x and y indices differ in length.
    #[error("MapUpdate: {xs} x indices but {ys} y indices")]
    CellLists {
        /// x indices given.
        xs: usize,
        /// y indices given.
        ys: usize,
    },
}

/// What a person may pick as a map.
pub const MAP_FILES_EXPECTED: &str = "expected an rtnav JSON map (.json), a ROS map (its .yaml \
                                      and its .pgm or .png image, picked together) or a \
                                      MovingAI map (.map)";

/// A configuration bundle (`System::load_conf`) that cannot be read or applied; nothing
/// changes.
#[derive(Debug, Clone, PartialEq, thiserror::Error, serde::Serialize, strum::VariantNames)]
#[serde(tag = "kind")]
#[non_exhaustive]
pub enum ConfBundleError {
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
        /// The problem, as the component's configuration reports it (shown to the page as
        /// a `Config` error of its own, without its line).
        #[serde(serialize_with = "problem_detail")]
        problem: ConfigError,
    },
}

/// A `.conf` problem without its line (the bundle's error names the line of the whole file).
fn conf_problem(e: &ConfigError) -> String {
    match e {
        ConfigError::Syntax { text, reason, .. } => format!("cannot read `{text}`: {reason}"),
        e => without_line(e).to_string(),
    }
}

/// `e` with its line (in the component's block) left out.
fn without_line(e: &ConfigError) -> ConfigError {
    let mut e = e.clone();
    match &mut e {
        ConfigError::UnknownParameter { line, .. }
        | ConfigError::OutOfRange { line, .. }
        | ConfigError::BadValue { line, .. } => *line = None,
        _ => {}
    }
    e
}

/// `ConfBlock`'s problem as the page reads it: a `Config` error of its own
/// ([`ErrorDetail`](crate::errors::ErrorDetail)), without its line.
fn problem_detail<S: serde::Serializer>(e: &ConfigError, s: S) -> Result<S::Ok, S::Error> {
    serde::Serialize::serialize(&crate::Error::from(without_line(e)).detail(), s)
}
