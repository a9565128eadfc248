//! Scenarios: a map, a start and goal, configuration, timed events and the expected outcome,
//! as JSON files in `fixtures/scenarios/` (unknown keys refused), and the resolver that
//! supplies the files they name — from the filesystem natively, from memory in wasm.
//!
//! ```json
//! {
//!   "name": "open_field",
//!   "description": "An empty yard: the robot drives across it.",
//!   "lesson": "Raise PostureConsiderationLevel and watch the path bend.",
//!   "map": { "format": "json", "path": "fixtures/maps/scenarios/open_field.json" },
//!   "start": { "x": 2.0, "y": 2.0, "heading_deg": 0 },
//!   "goal":  { "x": 12.0, "y": 8.0, "heading_deg": 90 },
//!   "direction": "forward",
//!   "config": { "LocalPathPlanning": { "dmin": 0.6 } },
//!   "rates": { "drive_control": 50 },
//!   "events": [
//!     { "at": 5.0, "type": "map_update", "boxes": [ { "x": [6.0, 6.5], "y": [4.0, 6.0] } ] },
//!     { "at": 9.0, "type": "goal", "goal": { "x": 3, "y": 8, "heading_deg": 180 } },
//!     { "at": 20.0, "type": "safe_mode" }
//!   ],
//!   "time_limit": 60.0,
//!   "expect": { "outcome": "arrived", "min_replans": 1 }
//! }
//! ```
//!
//! | key | meaning |
//! | --- | --- |
//! | `map` | `{"format": "json", "path"}` (rtnav JSON), `{"format": "ros", "yaml", "unknown": "obstacle" \| "free"}` (ROS map_server YAML + image, the image relative to the YAML), `{"format": "movingai", "path", "grid_size", "origin": [x, y]}` |
//! | `start`, `goal` | metres and degrees (counter-clockwise from +x) |
//! | `direction` | `forward` (default) or `backward` (`SetPosition`'s `Direction`) |
//! | `config` | per component (seed names, e.g. `LocalPathPlanning`), parameter (seed names, e.g. `RouteRemakeDistance`) → value |
//! | `rates` | [`Rates`] (missing keys: defaults) |
//! | `events` | timed, in seconds: `map_update` (`boxes` in metres — cells whose centre lies inside — and/or `cells` `[x, y]`; `value` 1 obstacle, 0 free; default 1), `goal` (a new goal from the robot's pose), `safe_mode`, `clear`, `fault` (`component`, `reason`: its next execution fails) |
//! | `time_limit` | seconds of simulated time |
//! | `expect` | [`Expectation`] |
//! | `exercise` | optional: a task, the parameters that may change, checks ([`Exercise`]) |
//!
//! Paths are relative to the project's root (e.g. `fixtures/maps/…`,
//! `../shared/data/rosmaps/…`); a [`FileResolver`] turns them into bytes.

use std::borrow::Cow;
use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::exercise::Exercise;
use crate::errors::ScenarioError;
use crate::interfaces::{Direction, Pose};
use crate::map::GridMap;
use crate::map::formats::{json, movingai, ros};
use crate::system::vocabulary::input::Input;
use crate::system::vocabulary::json_text;
use crate::system::vocabulary::kind::ComponentKind;
use crate::system::vocabulary::rates::Rates;
use crate::system::vocabulary::run_limit::beyond_replay_limit_s;

/// A scenario file (see the module documentation).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Scenario {
    /// Short name (the file's stem).
    pub name: String,
    /// What it shows.
    pub description: String,
    /// What to try (the teaching page shows it).
    pub lesson: String,
    /// The map file.
    pub map: MapSource,
    /// Where the robot starts.
    pub start: PoseSpec,
    /// Where it should go.
    pub goal: PoseSpec,
    /// Forward or backward.
    #[serde(default)]
    pub direction: DirectionSpec,
    /// Configuration overrides: component → parameter → value (seed names).
    #[serde(default)]
    pub config: BTreeMap<String, BTreeMap<String, f64>>,
    /// Rates.
    #[serde(default)]
    pub rates: Rates,
    /// Timed events.
    #[serde(default)]
    pub events: Vec<ScenarioEvent>,
    /// Seconds of simulated time before the run is stopped.
    pub time_limit: f64,
    /// What should happen.
    pub expect: Expectation,
    /// The exercise a student can do on it ([`Exercise`]), if any.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub exercise: Option<Exercise>,
}

/// Where the map comes from.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(tag = "format", rename_all = "snake_case", deny_unknown_fields)]
pub enum MapSource {
    /// rtnav's JSON map (`crate::map::formats::json`).
    Json {
        /// The file.
        path: String,
    },
    /// A ROS map_server map (`crate::map::formats::ros`).
    Ros {
        /// The YAML file; the image it names is read relative to it.
        yaml: String,
        /// What unknown cells become.
        #[serde(default)]
        unknown: UnknownSpec,
    },
    /// A MovingAI `.map` (`crate::map::formats::movingai`), scaled to `grid_size`.
    Movingai {
        /// The file.
        path: String,
        /// Metres per cell.
        grid_size: f64,
        /// World position of the lower-left corner \[m\].
        #[serde(default)]
        origin: [f64; 2],
    },
}

impl MapSource {
    /// Loads the map through `resolver`.
    pub fn load(&self, resolver: &dyn FileResolver) -> Result<GridMap, crate::Error> {
        Ok(match self {
            MapSource::Json { path } => json::load(&text(resolver, path)?)?,
            MapSource::Ros { yaml, unknown } => {
                let text = text(resolver, yaml)?;
                let parsed = ros::parse_yaml(&text)?;
                let image = resolver.read(&sibling(yaml, &parsed.image))?;
                let options = ros::RosLoadOptions {
                    unknown: match unknown {
                        UnknownSpec::Obstacle => ros::UnknownCells::Obstacle,
                        UnknownSpec::Free => ros::UnknownCells::Free,
                    },
                };
                ros::load_image(parsed, &image, &options)?.map
            }
            MapSource::Movingai {
                path,
                grid_size,
                origin,
            } => {
                let m = movingai::load_map(&text(resolver, path)?)?;
                GridMap::new(
                    m.width(),
                    m.height(),
                    *grid_size,
                    (origin[0], origin[1]),
                    m.cells().to_vec(),
                )?
            }
        })
    }
}

/// What unknown cells of a ROS map become.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum UnknownSpec {
    /// Obstacles (the default).
    #[default]
    Obstacle,
    /// Free.
    Free,
}

/// A pose in metres and degrees.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct PoseSpec {
    /// X \[m\].
    pub x: f64,
    /// Y \[m\].
    pub y: f64,
    /// Heading \[°\], counter-clockwise from +x.
    #[serde(default)]
    pub heading_deg: f64,
}

impl PoseSpec {
    /// As a [`Pose`] (radians). The conversion multiplies by `π/180` (no transcendental
    /// function: the same bits everywhere).
    pub fn pose(&self) -> Pose {
        Pose::new(
            self.x,
            self.y,
            self.heading_deg * (core::f64::consts::PI / 180.0),
        )
    }
}

/// `forward` or `backward`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum DirectionSpec {
    /// Direction 1.
    #[default]
    Forward,
    /// Direction 2.
    Backward,
}

impl DirectionSpec {
    /// As a [`Direction`].
    pub fn direction(self) -> Direction {
        match self {
            Self::Forward => Direction::Forward,
            Self::Backward => Direction::Backward,
        }
    }
}

/// A timed event.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum ScenarioEvent {
    /// Cells change (MapMaintenance sends them at `at`).
    MapUpdate {
        /// Seconds.
        at: f64,
        /// Rectangles in metres: `x: [min, max]`, `y: [min, max]`; the cells whose centre
        /// lies inside (edges included).
        #[serde(default)]
        boxes: Vec<BoxSpec>,
        /// Single cells `[x, y]`.
        #[serde(default)]
        cells: Vec<[i64; 2]>,
        /// 1 obstacle (default), 0 free.
        #[serde(default = "one")]
        value: i16,
    },
    /// A new goal, from the robot's pose at `at`.
    Goal {
        /// Seconds.
        at: f64,
        /// The new goal.
        goal: PoseSpec,
        /// Its direction.
        #[serde(default)]
        direction: DirectionSpec,
    },
    /// `SafeMode`.
    SafeMode {
        /// Seconds.
        at: f64,
    },
    /// `Clear`.
    Clear {
        /// Seconds.
        at: f64,
    },
    /// A fault: `component`'s next execution fails with `reason` (seed 003's Error state).
    Fault {
        /// Seconds.
        at: f64,
        /// Which component.
        component: ComponentKind,
        /// The reason it fails with.
        reason: String,
    },
    /// An operator's Reset of `component` (seed 003: Error → Inactive), as the RTC tab's
    /// button; refused, and logged, if it is not in Error.
    Reset {
        /// Seconds.
        at: f64,
        /// Which component.
        component: ComponentKind,
    },
    /// An operator's Activate of `component` (Inactive → Active); refused, and logged, if
    /// it is not Inactive.
    Activate {
        /// Seconds.
        at: f64,
        /// Which component.
        component: ComponentKind,
    },
}

fn one() -> i16 {
    1
}

impl ScenarioEvent {
    /// When it happens \[s\].
    pub fn at(&self) -> f64 {
        match self {
            Self::MapUpdate { at, .. }
            | Self::Goal { at, .. }
            | Self::SafeMode { at }
            | Self::Clear { at }
            | Self::Fault { at, .. }
            | Self::Reset { at, .. }
            | Self::Activate { at, .. } => *at,
        }
    }
}

/// A rectangle in metres.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct BoxSpec {
    /// `[min, max]` in x \[m\].
    pub x: [f64; 2],
    /// `[min, max]` in y \[m\].
    pub y: [f64; 2],
}

/// How a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
#[serde(rename_all = "snake_case")]
pub enum OutcomeKind {
    /// The robot came to rest within the goal's arrival tolerances (spec §7).
    Arrived,
    /// The robot came to rest outside the goal's arrival tolerances, DriveControl done
    /// with the path (it overshot or stopped short), and stayed there.
    StoppedOffGoal,
    /// A planner failed and the robot stands still without a path.
    PlanningFailed,
    /// The robot touched an obstacle.
    Bumped,
    /// A component went to Error for another reason.
    ComponentError,
    /// SafeMode or Clear halted the robot, and it stands still.
    Halted,
    /// The time limit (or `--until`) came first.
    TimeLimit,
}

/// What a scenario expects.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Expectation {
    /// How it ends.
    pub outcome: OutcomeKind,
    /// At least this many local (potential-field) plans.
    #[serde(default)]
    pub min_replans: u64,
    /// Which planner's failure, for `planning_failed`.
    #[serde(default)]
    pub planner: Option<String>,
}

/// Supplies the bytes of the files a scenario names.
pub trait FileResolver {
    /// The bytes of `path` (as the scenario writes it).
    fn read(&self, path: &str) -> Result<Cow<'_, [u8]>, ScenarioError>;
}

/// Files from memory (wasm: `include_bytes!`; tests).
#[derive(Debug, Clone, Default)]
pub struct MemoryResolver {
    files: BTreeMap<String, Cow<'static, [u8]>>,
}

impl MemoryResolver {
    /// No files.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds (or replaces) a file.
    pub fn insert(&mut self, path: &str, bytes: impl Into<Cow<'static, [u8]>>) -> &mut Self {
        self.files.insert(normalize(path), bytes.into());
        self
    }

    /// With a file added.
    pub fn with(mut self, path: &str, bytes: impl Into<Cow<'static, [u8]>>) -> Self {
        self.insert(path, bytes);
        self
    }
}

impl FileResolver for MemoryResolver {
    fn read(&self, path: &str) -> Result<Cow<'_, [u8]>, ScenarioError> {
        self.files
            .get(&normalize(path))
            .map(|b| Cow::Borrowed(b.as_ref()))
            .ok_or_else(|| ScenarioError::File {
                path: path.to_owned(),
                reason: "not among the files supplied".to_owned(),
            })
    }
}

/// Files from the filesystem, relative to a root folder (native only).
#[cfg(not(target_arch = "wasm32"))]
#[derive(Debug, Clone)]
pub struct DirResolver {
    root: std::path::PathBuf,
}

#[cfg(not(target_arch = "wasm32"))]
impl DirResolver {
    /// Paths are read relative to `root` (the project's root for the fixtures).
    pub fn new(root: impl Into<std::path::PathBuf>) -> Self {
        Self { root: root.into() }
    }
}

#[cfg(not(target_arch = "wasm32"))]
impl FileResolver for DirResolver {
    fn read(&self, path: &str) -> Result<Cow<'_, [u8]>, ScenarioError> {
        let full = self.root.join(path);
        std::fs::read(&full)
            .map(Cow::Owned)
            .map_err(|e| ScenarioError::File {
                path: full.display().to_string(),
                reason: e.to_string(),
            })
    }
}

/// `a/./b/../c` → `a/c` (leading `..` kept), so that a ROS image named relative to its
/// YAML finds the same key in a [`MemoryResolver`]. An absolute path stays absolute
/// (`/m/./x` → `/m/x`; `..` above the root stays at the root).
fn normalize(path: &str) -> String {
    let absolute = path.starts_with('/');
    let mut parts: Vec<&str> = Vec::new();
    for p in path.split('/') {
        match p {
            "" | "." => {}
            ".." if parts.last().is_some_and(|l| *l != "..") => {
                parts.pop();
            }
            ".." if absolute => {}
            _ => parts.push(p),
        }
    }
    let joined = parts.join("/");
    if absolute {
        format!("/{joined}")
    } else {
        joined
    }
}

/// `image` named in the YAML at `yaml`: relative to the YAML's folder unless absolute.
fn sibling(yaml: &str, image: &str) -> String {
    if image.starts_with('/') {
        return image.to_owned();
    }
    match yaml.rfind('/') {
        Some(i) => normalize(&format!("{}/{image}", &yaml[..i])),
        None => normalize(image),
    }
}

impl Scenario {
    /// Reads a scenario from JSON (unknown keys are errors) and checks it.
    pub fn from_json(text: &str) -> Result<Self, ScenarioError> {
        let s: Self = json_text::parse(text).map_err(|reason| ScenarioError::Scenario {
            scenario: "(JSON)".to_owned(),
            reason,
        })?;
        s.validate()?;
        Ok(s)
    }

    fn err(&self, reason: impl Into<String>) -> ScenarioError {
        ScenarioError::Scenario {
            scenario: crate::present::excerpt(&self.name),
            reason: reason.into(),
        }
    }

    /// Checks what serde cannot: finite numbers, a positive time limit, event times within
    /// it and in order, known component names (parameter names and ranges are checked when
    /// applied).
    pub fn validate(&self) -> Result<(), ScenarioError> {
        for (what, p) in [("start", self.start), ("goal", self.goal)] {
            if !(p.x.is_finite() && p.y.is_finite() && p.heading_deg.is_finite()) {
                return Err(self.err(format!("{what} has a number that is not finite")));
            }
        }
        if !(self.time_limit.is_finite() && self.time_limit > 0.0) {
            return Err(self.err(format!(
                "time_limit = {} must be positive and finite",
                self.time_limit
            )));
        }
        if let Some(reason) = beyond_replay_limit_s(
            &format!("time_limit {} s", self.time_limit),
            self.time_limit,
        ) {
            return Err(self.err(reason));
        }
        let mut last = 0.0;
        for (i, e) in self.events.iter().enumerate() {
            let at = e.at();
            if !(at.is_finite() && at >= last && at <= self.time_limit) {
                return Err(self.err(format!(
                    "events[{i}].at = {at}: event times must be finite, in order and within 0..time_limit"
                )));
            }
            last = at;
            match e {
                ScenarioEvent::MapUpdate {
                    boxes,
                    cells,
                    value,
                    ..
                } => {
                    if !(0..=1).contains(value) {
                        return Err(self.err(format!("events[{i}].value = {value} must be 0 or 1")));
                    }
                    if boxes.is_empty() && cells.is_empty() {
                        return Err(
                            self.err(format!("events[{i}]: a map_update needs boxes or cells"))
                        );
                    }
                    if boxes
                        .iter()
                        .any(|b| !(b.x.iter().chain(&b.y).all(|v| v.is_finite())))
                    {
                        return Err(self.err(format!(
                            "events[{i}]: a box has a number that is not finite"
                        )));
                    }
                }
                ScenarioEvent::Goal { goal, .. } => {
                    if !(goal.x.is_finite() && goal.y.is_finite() && goal.heading_deg.is_finite()) {
                        return Err(
                            self.err(format!("events[{i}].goal has a number that is not finite"))
                        );
                    }
                }
                ScenarioEvent::SafeMode { .. }
                | ScenarioEvent::Clear { .. }
                | ScenarioEvent::Fault { .. }
                | ScenarioEvent::Reset { .. }
                | ScenarioEvent::Activate { .. } => {}
            }
        }
        self.rates
            .check()
            .map_err(|e| self.err(format!("rates: {e}")))?;
        for component in self.config.keys() {
            ComponentKind::from_name(component).map_err(|e| self.err(format!("config: {e}")))?;
        }
        if let Some(exercise) = &self.exercise {
            exercise.validate(&self.name)?;
        }
        // The map's one geometry rule, on the smallest map: the size is known once the file
        // is read, and checked again then.
        if let MapSource::Movingai {
            grid_size, origin, ..
        } = &self.map
        {
            GridMap::check_geometry(1, 1, *grid_size, (origin[0], origin[1]))
                .map_err(|e| self.err(format!("map: {e}")))?;
        }
        Ok(())
    }

    /// The paths of every file the map needs (the image of a ROS map is named inside its
    /// YAML, so it is listed after reading the YAML through `resolver`).
    pub fn map_files(&self, resolver: &dyn FileResolver) -> Result<Vec<String>, crate::Error> {
        Ok(match &self.map {
            MapSource::Json { path } | MapSource::Movingai { path, .. } => vec![path.clone()],
            MapSource::Ros { yaml, .. } => {
                let text = text(resolver, yaml)?;
                let y = ros::parse_yaml(&text)?;
                vec![yaml.clone(), sibling(yaml, &y.image)]
            }
        })
    }

    /// Loads the map through `resolver`.
    pub fn load_map(&self, resolver: &dyn FileResolver) -> Result<GridMap, crate::Error> {
        self.map.load(resolver)
    }

    /// The cells `(x, y, value)` of a `map_update` event on `map`: the cells listed, then
    /// the cells whose centre lies in each box (clipped to the map; cells outside the map are
    /// refused when applied).
    pub fn cells_of(
        map: &GridMap,
        boxes: &[BoxSpec],
        cells: &[[i64; 2]],
        value: i16,
    ) -> Vec<(i64, i64, i16)> {
        let mut list: Vec<(i64, i64, i16)> = cells.iter().map(|c| (c[0], c[1], value)).collect();
        let g = map.grid_size();
        let (ox, oy) = map.origin();
        for b in boxes {
            let (x0, x1) = (b.x[0].min(b.x[1]), b.x[0].max(b.x[1]));
            let (y0, y1) = (b.y[0].min(b.y[1]), b.y[0].max(b.y[1]));
            // Cells whose centre ox + (i + ½)g lies in [x0, x1].
            let i0 = libm::ceil((x0 - ox) / g - 0.5).max(0.0) as i64;
            let i1 = libm::floor((x1 - ox) / g - 0.5).min(map.width() as f64 - 1.0) as i64;
            let j0 = libm::ceil((y0 - oy) / g - 0.5).max(0.0) as i64;
            let j1 = libm::floor((y1 - oy) / g - 0.5).min(map.height() as f64 - 1.0) as i64;
            for j in j0..=j1 {
                for i in i0..=i1 {
                    list.push((i, j, value));
                }
            }
        }
        list
    }
}

impl ScenarioEvent {
    /// The request this event makes of the system with `map` loaded (the timeline's
    /// interpretation; a `goal` is a new goal from where the robot is).
    pub fn to_input(&self, map: Option<&GridMap>) -> Input {
        match self {
            Self::MapUpdate {
                boxes,
                cells,
                value,
                ..
            } => Input::MapUpdate {
                cells: map.map_or_else(Vec::new, |m| Scenario::cells_of(m, boxes, cells, *value)),
            },
            Self::Goal {
                goal, direction, ..
            } => Input::SetGoal {
                goal: goal.pose(),
                direction: direction.direction(),
            },
            Self::SafeMode { .. } => Input::SafeMode,
            Self::Clear { .. } => Input::Clear,
            Self::Fault {
                component, reason, ..
            } => Input::InjectFault {
                component: *component,
                reason: reason.clone(),
            },
            Self::Reset { component, .. } => Input::Reset {
                component: *component,
            },
            Self::Activate { component, .. } => Input::Activate {
                component: *component,
            },
        }
    }
}

fn text(resolver: &dyn FileResolver, path: &str) -> Result<String, ScenarioError> {
    let bytes = resolver.read(path)?;
    String::from_utf8(bytes.into_owned()).map_err(|e| ScenarioError::File {
        path: path.to_owned(),
        reason: format!("not UTF-8 text: {e}"),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_are_normalized_and_images_found_beside_their_yaml() {
        assert_eq!(normalize("./a//b/../c"), "a/c");
        assert_eq!(normalize("../shared/x/./y"), "../shared/x/y");
        assert_eq!(sibling("../d/m.yaml", "m.pgm"), "../d/m.pgm");
        assert_eq!(sibling("m.yaml", "./m.pgm"), "m.pgm");
        assert_eq!(sibling("a/m.yaml", "/abs/m.pgm"), "/abs/m.pgm");
    }

    #[test]
    fn absolute_paths_keep_their_root() {
        assert_eq!(normalize("/home/u/maps/./x.yaml"), "/home/u/maps/x.yaml");
        assert_eq!(normalize("/../x"), "/x");
        assert_eq!(
            sibling("/home/u/maps/x.yaml", "x.pgm"),
            "/home/u/maps/x.pgm"
        );
        assert_eq!(sibling("/x.yaml", "../x.pgm"), "/x.pgm");
        // A ROS map named by an absolute path finds its image beside it (the resolver's
        // root is not where the files are).
        #[cfg(not(target_arch = "wasm32"))]
        {
            let maps = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../fixtures/maps");
            let yaml = std::fs::canonicalize(maps).unwrap().join("tiny.yaml");
            let source = MapSource::Ros {
                yaml: yaml.display().to_string(),
                unknown: UnknownSpec::Obstacle,
            };
            let resolver = DirResolver::new("/nonexistent-root");
            assert!(source.load(&resolver).is_ok());
        }
    }

    #[test]
    fn boxes_cover_the_cells_whose_centre_is_inside() {
        let map = GridMap::from_map_data(&[0; 100], 10, 10, 0.5).unwrap();
        let cells = Scenario::cells_of(
            &map,
            &[BoxSpec {
                x: [1.0, 1.75],
                y: [0.25, 0.25],
            }],
            &[[9, 9]],
            1,
        );
        // x centres 1.25 (i = 2) and 1.75 (i = 3); y centre 0.25 (j = 0).
        assert_eq!(cells, vec![(9, 9, 1), (2, 0, 1), (3, 0, 1)]);
    }

    #[test]
    fn bad_scenarios_are_refused_with_the_reason() {
        let ok = r#"{"name": "t", "description": "", "lesson": "",
            "map": {"format": "json", "path": "m.json"},
            "start": {"x": 1, "y": 1}, "goal": {"x": 2, "y": 1, "heading_deg": 90},
            "time_limit": 10, "expect": {"outcome": "arrived"}}"#;
        let s = Scenario::from_json(ok).unwrap();
        assert_eq!(Scenario::from_json(&format!("\u{feff}{ok}")).unwrap(), s);
        let nan = Scenario::from_json(&ok.replace("\"x\": 2", "\"x\": NaN"))
            .unwrap_err()
            .to_string();
        assert!(
            nan.ends_with("(JSON has no NaN or Infinity; write a number)"),
            "{nan}"
        );
        assert_eq!(s.direction, DirectionSpec::Forward);
        assert_eq!(s.rates, Rates::default());
        let typo = ok.replace("\"lesson\"", "\"lessons\"");
        assert!(
            Scenario::from_json(&typo)
                .unwrap_err()
                .to_string()
                .contains("unknown field")
        );
        let late = ok.replace(
            "\"time_limit\": 10",
            "\"time_limit\": 10, \"events\": [{\"at\": 11, \"type\": \"safe_mode\"}]",
        );
        assert!(
            Scenario::from_json(&late)
                .unwrap_err()
                .to_string()
                .contains("events[0].at")
        );
        let who = ok.replace(
            "\"time_limit\": 10",
            "\"time_limit\": 10, \"config\": {\"Planner\": {\"dmin\": 1}}",
        );
        assert!(
            Scenario::from_json(&who)
                .unwrap_err()
                .to_string()
                .contains("no component named `Planner`")
        );
    }
}
