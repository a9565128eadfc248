//! The soak: the closed loop on a scenario for hours of simulated time, with seeded random
//! map edits (never on or near the robot, never cutting the robot off its goal) and random
//! reachable goals, watched for what must never happen — a bump, a component error, a panic,
//! a **stuck period** (a goal held and no motion for [`STUCK_AFTER_NS`] of simulated time, or
//! no new goal accepted for as long) and memory that grows.
//!
//! **Arrivals are counted as spec §7 defines them** (Decision 0.3): an `Arrived` fact of the
//! system counts only after the soak has checked it on its own, on the tick it was logged —
//! the robot **at rest** by the physics' measured speeds (below [`AT_REST_SPEED`] and
//! [`AT_REST_TURN_RATE`]), for the goal the soak set and the mission then holds, within the
//! arrival tolerances of that goal (one map cell of its position, [`ARRIVAL_HEADING_DEG`] of
//! its heading: the runner's). An `Arrived` fact that fails the check is a **false arrival**:
//! reported with why, never counted as an arrival, and a failure of the soak. Either way the
//! system has said the goal is done, and the next goal follows.
//!
//! This is one of the three files of the tools that use `System` (the fuzzer's system
//! targets and its `script` target are the others). Its requests are [`Input`]s
//! (`ActivateAll`, `ResetAll`, `SetGoal`, `MapUpdate`) through [`System::apply`]; it reads
//! the record (events, telemetry), the statistics, the state, the robot's pose and the map.
//!
//! **Memory**: the bytes live on the heap (the counting allocator, [`crate::alloc`]) and the
//! resident set size (`/proc/self/statm`, Linux) at the start, once the bounded histories are
//! full (the telemetry keeps its newest `DEFAULT_TELEMETRY_CAPACITY` samples, about 22 min at
//! 50 Hz: the *warm-up*), and at the end; the heap also every simulated minute after the
//! warm-up. What is live at a given minute depends on what the planners hold then (a
//! potential field of the map's size, or none), so "flat" compares like with like: the
//! largest heap of the last quarter of those minutes is within [`MEMORY_TOLERANCE`] of the
//! largest of the first quarter. A leak, however slow, raises the later maximum.

use std::collections::BTreeSet;
use std::time::{Duration, Instant};

use rtnav::components::{LocalPathPlanningParams, MotorControlParams};
use rtnav::global::AStar;
use rtnav::interfaces::{Direction, Pose};
use rtnav::map::{Cell, GridMap, MapUpdate, within_dmin};
use rtnav::rtc::Time;
use rtnav::system::{
    ARRIVAL_HEADING_DEG, DEFAULT_TELEMETRY_CAPACITY, EventKind, Input, Scenario, System,
    SystemState,
};

use crate::alloc;
use crate::rng::Rng;

/// No motion for this long while a goal is held is a stuck period (60 s).
pub const STUCK_AFTER_NS: u64 = 60_000_000_000;
/// Motion: the robot moved this far \[m\] …
const MOVED_M: f64 = 0.01;
/// … or turned this much \[rad\] since the last motion.
const TURNED_RAD: f64 = 0.01;
/// At rest (spec §7): the physics' measured speed below this \[m/s\] …
pub const AT_REST_SPEED: f64 = 0.01;
/// … and its turn rate below this \[rad/s\].
pub const AT_REST_TURN_RATE: f64 = 0.01;
/// Heap growth allowed after the warm-up.
pub const MEMORY_TOLERANCE: f64 = 0.05;
/// One step of the soak's loop: 100 ms (100 base ticks at 1 kHz).
const CHUNK_TICKS: u64 = 100;
const NS_PER_S: u64 = 1_000_000_000;

/// How a soak runs.
#[derive(Debug, Clone)]
pub struct SoakOptions {
    /// Simulated hours.
    pub hours: f64,
    /// The seed of the goals and edits.
    pub seed: u64,
    /// `dmin` in force \[m\] (the scenario's, else the default).
    pub dmin: f64,
    /// The robot's body radius \[m\] (`radiusOfBodyArea`).
    pub body_radius: f64,
}

impl SoakOptions {
    /// `hours` with `seed`, the default `dmin` and body.
    pub fn new(hours: f64, seed: u64) -> Self {
        Self {
            hours,
            seed,
            dmin: LocalPathPlanningParams::default().dmin,
            body_radius: MotorControlParams::default().radius_of_body_area,
        }
    }

    /// [`SoakOptions::new`] with the `dmin` `scenario` gives LocalPathPlanning, if it sets
    /// one.
    pub fn of_scenario(hours: f64, seed: u64, scenario: &Scenario) -> Self {
        let mut options = Self::new(hours, seed);
        if let Some(d) = scenario
            .config
            .get("LocalPathPlanning")
            .and_then(|c| c.get("dmin"))
        {
            options.dmin = *d;
        }
        options
    }
}

/// A stuck period.
#[derive(Debug, Clone, PartialEq)]
pub struct StuckPeriod {
    /// When it was noticed \[s\] (60 s after the last motion or accepted goal).
    pub at_s: f64,
    /// Where the robot stood.
    pub pose: Pose,
    /// The goal held, if any.
    pub goal: Option<Pose>,
    /// The obstacle distance of the robot's cell then \[m\] (compare with `dmin`).
    pub cell_distance: Option<f64>,
    /// Why: no motion, or no goal accepted (and the last refusal's reason).
    pub reason: String,
    /// How long it lasted \[s\]: until the robot moved again (or a goal was accepted), or
    /// the end of the soak.
    pub lasted_s: f64,
}

/// Memory figures \[bytes\].
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Memory {
    /// Heap live at the start.
    pub heap_start: i64,
    /// Heap live once the histories were full (`None`: the soak was shorter).
    pub heap_warm: Option<i64>,
    /// Simulated time of the warm-up mark \[s\].
    pub warm_at_s: f64,
    /// Heap live at the end.
    pub heap_end: i64,
    /// The heap live at every minute mark after the warm-up.
    pub heap_after_warm: Vec<i64>,
    /// Resident set size at the start (0 where unknown).
    pub rss_start: u64,
    /// Resident set size at the end.
    pub rss_end: u64,
}

impl Memory {
    /// The largest heap of the first and of the last quarter of the minutes after the
    /// warm-up (`None` with fewer than 4 such minutes).
    pub fn quarters(&self) -> Option<(i64, i64)> {
        let h = &self.heap_after_warm;
        let q = h.len() / 4;
        if q == 0 {
            return None;
        }
        let first = h[..q].iter().copied().max()?;
        let last = h[h.len() - q..].iter().copied().max()?;
        Some((first, last))
    }

    /// Heap growth after the warm-up: the last quarter's largest over the first quarter's,
    /// minus one (`None` when too short or without the counting allocator).
    pub fn growth(&self) -> Option<f64> {
        let (first, last) = self.quarters()?;
        (first > 0).then(|| (last - first) as f64 / first as f64)
    }
}

/// What a soak saw.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SoakReport {
    /// Simulated hours run.
    pub sim_hours: f64,
    /// Goals accepted (the scenario's first goal included).
    pub goals: u64,
    /// Goals refused by `set_goal` (another is tried).
    pub goals_refused: u64,
    /// Goals given up: not reached within their time allowance, while the robot moved.
    pub goals_given_up: u64,
    /// Arrivals: `Arrived` facts that the soak's own check confirmed (spec §7: at rest,
    /// within the tolerances of the goal then held).
    pub arrivals: u64,
    /// `Arrived` facts that failed the check: not counted as arrivals.
    pub false_arrivals: u64,
    /// The first false arrivals, with why.
    pub false_arrival_texts: Vec<String>,
    /// Bumps.
    pub bumps: u64,
    /// Component errors other than a bump's (callback failures).
    pub component_errors: u64,
    /// The first component errors' texts.
    pub error_texts: Vec<String>,
    /// Planning-failure notices (a passing obstacle may cause them; not a failure).
    pub planning_failures: u64,
    /// Stuck periods.
    pub stuck: Vec<StuckPeriod>,
    /// Obstacles placed.
    pub edits_added: u64,
    /// Obstacles taken away.
    pub edits_removed: u64,
    /// Recoveries (reset and activate after an Error).
    pub recoveries: u64,
    /// Memory.
    pub memory: Memory,
    /// Wall time.
    pub wall: Duration,
    /// The trace hash at the end.
    pub trace_hash: String,
}

impl SoakReport {
    /// Why the soak failed, if it did: false arrivals, bumps, component errors, stuck
    /// periods, memory growth.
    pub fn problems(&self) -> Vec<String> {
        let mut p = Vec::new();
        if self.false_arrivals > 0 {
            p.push(format!(
                "{} false arrivals (Arrived facts not at rest within the goal's tolerances)",
                self.false_arrivals
            ));
        }
        if self.bumps > 0 {
            p.push(format!("{} bumps", self.bumps));
        }
        if self.component_errors > 0 {
            p.push(format!("{} component errors", self.component_errors));
        }
        if !self.stuck.is_empty() {
            p.push(format!("{} stuck periods", self.stuck.len()));
        }
        if let Some(g) = self.memory.growth()
            && g > MEMORY_TOLERANCE
        {
            p.push(format!("heap grew {:.1} % after the warm-up", g * 100.0));
        }
        p
    }

    /// The summary, one figure a line.
    pub fn text(&self) -> String {
        let mib = |b: i64| format!("{:.1} MiB", b as f64 / 1048576.0);
        let m = &self.memory;
        let mut s = String::new();
        s += &format!("simulated hours   {:.2}\n", self.sim_hours);
        s += &format!(
            "goals             {} accepted, {} refused, {} given up\n",
            self.goals, self.goals_refused, self.goals_given_up
        );
        s += &format!(
            "arrivals          {} (Arrived facts checked: at rest within the goal's tolerances)\n",
            self.arrivals
        );
        s += &format!("false arrivals    {}\n", self.false_arrivals);
        for e in &self.false_arrival_texts {
            s += &format!("                  {e}\n");
        }
        s += &format!("bumps             {}\n", self.bumps);
        s += &format!("component errors  {}\n", self.component_errors);
        for e in &self.error_texts {
            s += &format!("                  {e}\n");
        }
        s += &format!("planning failures {}\n", self.planning_failures);
        s += &format!("stuck periods     {}\n", self.stuck.len());
        for p in self.stuck.iter().take(10) {
            s += &format!(
                "                  from {:.1} s for {:.1} s: robot ({:.3}, {:.3}, {:.3}) in a cell \
                 {} m from an obstacle, goal {}: {}\n",
                p.at_s - STUCK_AFTER_NS as f64 * 1e-9,
                p.lasted_s,
                p.pose.x,
                p.pose.y,
                p.pose.theta,
                p.cell_distance.map_or("?".to_owned(), |d| format!("{d:?}")),
                p.goal
                    .map_or("none".to_owned(), |g| format!("({:.2}, {:.2})", g.x, g.y)),
                p.reason
            );
        }
        s += &format!(
            "map edits         {} obstacles placed, {} taken away\n",
            self.edits_added, self.edits_removed
        );
        s += &format!("recoveries        {}\n", self.recoveries);
        if alloc::installed() {
            s += &format!(
                "memory (heap)     start {}, after warm-up {}, end {}\n",
                mib(m.heap_start),
                m.heap_warm
                    .map_or("— (shorter than the warm-up)".to_owned(), |w| format!(
                        "{} (at {:.0} s)",
                        mib(w),
                        m.warm_at_s
                    )),
                mib(m.heap_end),
            );
            if let (Some((first, last)), Some(g)) = (m.quarters(), m.growth()) {
                s += &format!(
                    "                  largest of the first quarter after warm-up {}, of the last {} ({:+.2} %)\n",
                    mib(first),
                    mib(last),
                    g * 100.0
                );
            }
        }
        if m.rss_start > 0 {
            s += &format!(
                "memory (RSS)      start {}, end {}\n",
                mib(m.rss_start as i64),
                mib(m.rss_end as i64)
            );
        }
        let sim = self.sim_hours * 3600.0;
        s += &format!(
            "wall time         {:.1} s ({:.0}× real time)\n",
            self.wall.as_secs_f64(),
            sim / self.wall.as_secs_f64().max(1e-9)
        );
        s += &format!("trace hash        {}\n", self.trace_hash);
        s
    }
}

/// Resident set size \[bytes\] from `/proc/self/statm` (0 where there is none).
pub fn rss() -> u64 {
    std::fs::read_to_string("/proc/self/statm")
        .ok()
        .and_then(|s| s.split_whitespace().nth(1)?.parse::<u64>().ok())
        .map_or(0, |pages| pages * 4096)
}

/// An obstacle the soak placed, and when it goes.
#[derive(Debug, Clone)]
struct Edit {
    cells: Vec<(i64, i64)>,
    until_ns: u64,
}

/// A soak in progress (see the module documentation).
#[derive(Debug)]
pub struct Soak {
    system: System,
    options: SoakOptions,
    rng: Rng,
    report: SoakReport,
    started: Instant,
    end_ns: u64,
    goal: Option<Pose>,
    /// Arrived at the current goal (a new one follows after `next_goal_ns`).
    arrived: bool,
    next_goal_ns: u64,
    goal_deadline_ns: u64,
    /// Last motion (or accepted goal): time and pose.
    still_since_ns: u64,
    still_pose: Pose,
    stuck_noticed: bool,
    /// Since when a new goal is wanted (after an arrival's wait, a give-up, a recovery).
    want_goal_since_ns: Option<u64>,
    last_refusal: Option<String>,
    edits: Vec<Edit>,
    ours: BTreeSet<(i64, i64)>,
    next_edit_ns: u64,
    next_minute_ns: u64,
    bumps_seen: u64,
    /// Events of the record read so far.
    events_seen: u64,
}

impl Soak {
    /// A soak of `system` (map loaded, start and `goal` set, components Inactive, as
    /// `setup::build` leaves it); activates every component.
    pub fn new(mut system: System, goal: Option<Pose>, options: SoakOptions) -> Self {
        let now = system.time_ns();
        // Activating every Inactive component cannot be refused.
        let _ = system.apply(&Input::ActivateAll);
        let pose = system.robot_pose();
        let end_ns = now + (options.hours * 3600.0 * NS_PER_S as f64) as u64;
        let mut rng = Rng::new(options.seed);
        let next_edit_ns = now + (rng.range(5.0, 20.0) * NS_PER_S as f64) as u64;
        let report = SoakReport {
            goals: u64::from(goal.is_some()),
            memory: Memory {
                heap_start: alloc::total_live(),
                rss_start: rss(),
                ..Memory::default()
            },
            ..SoakReport::default()
        };
        Self {
            options,
            rng,
            report,
            started: Instant::now(),
            end_ns,
            goal,
            arrived: false,
            next_goal_ns: now,
            goal_deadline_ns: now + 600 * NS_PER_S,
            still_since_ns: now,
            still_pose: pose,
            stuck_noticed: false,
            want_goal_since_ns: goal.is_none().then_some(now),
            last_refusal: None,
            edits: Vec::new(),
            ours: BTreeSet::new(),
            next_edit_ns,
            next_minute_ns: now + 60 * NS_PER_S,
            bumps_seen: 0,
            events_seen: system.record().event_count(),
            system,
        }
    }

    /// The system (to tamper with it in tests).
    pub fn system_mut(&mut self) -> &mut System {
        &mut self.system
    }

    /// Whether the soak's time is up.
    pub fn done(&self) -> bool {
        self.system.time_ns() >= self.end_ns
    }

    /// Runs until the end; `progress` is told the simulated hours and the report so far
    /// every simulated hour.
    pub fn run(mut self, mut progress: impl FnMut(f64, &SoakReport)) -> SoakReport {
        let start = self.system.time_ns();
        let mut next_progress = start + 3600 * NS_PER_S;
        while !self.done() {
            self.chunk();
            if self.system.time_ns() >= next_progress {
                progress(
                    (self.system.time_ns() - start) as f64 / 3.6e12,
                    &self.report,
                );
                next_progress += 3600 * NS_PER_S;
            }
        }
        self.finish()
    }

    /// Runs `seconds` of simulated time (whole chunks), whatever the end.
    pub fn run_for(&mut self, seconds: f64) {
        let until = self.system.time_ns() + (seconds * NS_PER_S as f64) as u64;
        while self.system.time_ns() < until {
            self.chunk();
        }
    }

    /// The report so far.
    pub fn report(&self) -> &SoakReport {
        &self.report
    }

    /// The final report.
    pub fn finish(mut self) -> SoakReport {
        let now = self.system.time_ns();
        self.end_stuck(now);
        let s = &self.system;
        self.report.sim_hours = s.time_ns() as f64 / 3.6e12;
        self.report.wall = self.started.elapsed();
        self.report.trace_hash = s.record().telemetry().trace_hash();
        self.report.memory.heap_end = alloc::total_live();
        self.report.memory.rss_end = rss();
        self.report
    }

    /// One chunk: step (reading the events on the tick they are logged, so an arrival is
    /// checked on the physics' state of that tick), watch motion, recover, goals, edits,
    /// memory.
    fn chunk(&mut self) {
        for _ in 0..CHUNK_TICKS {
            self.system.step(1);
            if self.system.record().event_count() != self.events_seen {
                self.read_events();
            }
        }
        let now = self.system.time_ns();
        let bumps = self.system.stats().bumps;
        if bumps > self.bumps_seen {
            self.report.bumps += bumps - self.bumps_seen;
            self.bumps_seen = bumps;
        }
        self.watch_motion(now);
        if self.system.state() == SystemState::Error {
            self.recover(now);
        }
        self.goals(now);
        self.edits(now);
        if now >= self.next_minute_ns {
            self.next_minute_ns += 60 * NS_PER_S;
            self.sample_memory(now);
        }
    }

    fn read_events(&mut self) {
        let record = self.system.record();
        let events: Vec<_> = record.events_since(self.events_seen).cloned().collect();
        self.events_seen = record.event_count();
        for e in events {
            match e.kind {
                EventKind::Arrived { .. } => {
                    match self.check_arrival() {
                        Ok(()) => self.report.arrivals += 1,
                        Err(why) => {
                            self.report.false_arrivals += 1;
                            if self.report.false_arrival_texts.len() < 10 {
                                self.report
                                    .false_arrival_texts
                                    .push(format!("at {:.3} s: {why}", e.time_ns as f64 * 1e-9));
                            }
                        }
                    }
                    // The system says the goal is done: the next one follows (counted or not).
                    self.arrived = true;
                    // A short wait at the goal, then the next one.
                    self.next_goal_ns =
                        e.time_ns + (self.rng.range(0.5, 5.0) * NS_PER_S as f64) as u64;
                    self.want_goal_since_ns = Some(self.next_goal_ns);
                }
                EventKind::PlanningFailed { .. } => self.report.planning_failures += 1,
                EventKind::ComponentError {
                    component,
                    callback,
                    reason,
                } if !matches!(reason, rtnav::Reason::Bump(_)) => {
                    self.report.component_errors += 1;
                    if self.report.error_texts.len() < 10 {
                        self.report.error_texts.push(format!(
                            "at {:.1} s: {component} {callback}: {reason}",
                            e.time_ns as f64 * 1e-9
                        ));
                    }
                }
                _ => {}
            }
        }
    }

    /// The soak's own check of an `Arrived` fact, made on the tick it was logged: the
    /// robot at rest by the physics' measured speeds, the mission holding the goal the soak
    /// set, the robot within one cell and [`ARRIVAL_HEADING_DEG`] of it. `Err` says why not.
    fn check_arrival(&self) -> Result<(), String> {
        let (v, w) = self.system.wiring().physics().physics().body_velocity();
        let pose = self.system.robot_pose();
        let held = self.system.mission().goal();
        let mut why = Vec::new();
        if !(v.abs() < AT_REST_SPEED && w.abs() < AT_REST_TURN_RATE) {
            why.push(format!("not at rest ({v:.4} m/s, {w:.4} rad/s)"));
        }
        match (self.goal, held) {
            (Some(set), Some(held)) if set == held => {
                let cell = self.system.map().map_or(f64::NAN, |m| m.grid_size());
                let off = libm::hypot(pose.x - held.x, pose.y - held.y);
                let turned = rtnav::motion::angle_diff(pose.theta, held.theta).abs();
                if off.is_nan() || cell.is_nan() || off > cell {
                    why.push(format!(
                        "{off:.3} m from the goal, more than one cell ({cell} m)"
                    ));
                }
                if turned.is_nan() || turned.to_degrees() > ARRIVAL_HEADING_DEG {
                    why.push(format!(
                        "{:.1}° off the goal's heading, more than {ARRIVAL_HEADING_DEG}°",
                        turned.to_degrees()
                    ));
                }
            }
            (set, held) => why.push(format!(
                "the goal held ({held:?}) is not the goal set ({set:?})"
            )),
        }
        if why.is_empty() {
            Ok(())
        } else {
            Err(why.join("; "))
        }
    }

    fn watch_motion(&mut self, now: u64) {
        let p = self.system.robot_pose();
        let moved = libm::hypot(p.x - self.still_pose.x, p.y - self.still_pose.y) > MOVED_M
            || rtnav::motion::angle_diff(p.theta, self.still_pose.theta).abs() > TURNED_RAD;
        if moved {
            self.still_since_ns = now;
            self.still_pose = p;
            if self.want_goal_since_ns.is_none() {
                self.end_stuck(now);
            }
        }
        // Stuck: a goal held and no motion for 60 s, or no new goal accepted for 60 s.
        let since = match self.want_goal_since_ns {
            Some(since) => since,
            None => self.still_since_ns,
        };
        if !self.stuck_noticed && now.saturating_sub(since) >= STUCK_AFTER_NS {
            self.stuck_noticed = true;
            let reason = if self.want_goal_since_ns.is_some() {
                format!(
                    "no new goal accepted for {} s (last refusal: {})",
                    STUCK_AFTER_NS / NS_PER_S,
                    self.last_refusal
                        .as_deref()
                        .unwrap_or("no reachable goal found")
                )
            } else {
                format!(
                    "a goal held and no motion for {} s",
                    STUCK_AFTER_NS / NS_PER_S
                )
            };
            let cell_distance = self
                .system
                .map()
                .and_then(|m| Some(m.obstacle_distance(m.world_to_cell(p.x, p.y)?)));
            self.report.stuck.push(StuckPeriod {
                at_s: now as f64 * 1e-9,
                pose: p,
                goal: self.goal,
                cell_distance,
                reason,
                lasted_s: 0.0,
            });
        }
    }

    /// Ends a stuck period in progress (its length is set).
    fn end_stuck(&mut self, now: u64) {
        if self.stuck_noticed {
            self.stuck_noticed = false;
            if let Some(p) = self.report.stuck.last_mut() {
                p.lasted_s = now as f64 * 1e-9 - (p.at_s - STUCK_AFTER_NS as f64 * 1e-9);
            }
        }
    }

    /// After an Error (a bump, a failed callback): reset everything, activate, new goal.
    fn recover(&mut self, now: u64) {
        self.report.recoveries += 1;
        // Neither can be refused (each acts on the components in the right state).
        let _ = self.system.apply(&Input::ResetAll);
        let _ = self.system.apply(&Input::ActivateAll);
        self.arrived = true;
        self.next_goal_ns = now;
        self.want_goal_since_ns.get_or_insert(now);
    }

    fn goals(&mut self, now: u64) {
        if self.goal.is_some() && !self.arrived && now >= self.goal_deadline_ns {
            self.report.goals_given_up += 1;
            self.arrived = true;
            self.next_goal_ns = now;
            self.want_goal_since_ns = Some(now);
        }
        if !(self.arrived || self.goal.is_none()) || now < self.next_goal_ns {
            return;
        }
        let Some(goal) = self.pick_goal() else {
            return;
        };
        match self.system.apply(&Input::SetGoal {
            goal,
            direction: Direction::Forward,
        }) {
            Ok(()) => {
                self.report.goals += 1;
                self.goal = Some(goal);
                self.arrived = false;
                self.last_refusal = None;
                self.want_goal_since_ns = None;
                self.end_stuck(now);
                let p = self.system.robot_pose();
                let straight = libm::hypot(goal.x - p.x, goal.y - p.y);
                // Generous: the route may be three times the straight line, at 0.1 m/s.
                self.goal_deadline_ns = now + ((120.0 + straight * 30.0) * NS_PER_S as f64) as u64;
                self.still_since_ns = now;
            }
            Err(e) => {
                self.report.goals_refused += 1;
                self.last_refusal = Some(e.to_string());
                // Try again in a second.
                self.next_goal_ns = now + NS_PER_S;
            }
        }
    }

    /// A random goal at least 2 m away, well clear of obstacles, reachable from the robot's
    /// cell on the current map. (If the robot's own cell is blocked — within `dmin` — no goal
    /// is reachable: one is picked all the same, so that `set_goal` says why it refuses.)
    fn pick_goal(&mut self) -> Option<Pose> {
        let map = self.system.map()?.clone();
        let dmin = self.options.dmin;
        let robot = self.system.robot_pose();
        let from = map.world_to_cell(robot.x, robot.y)?;
        let mut planner = AStar::new(&map, dmin).ok()?;
        let blocked = !planner.is_passable(from.0 as i64, from.1 as i64);
        for _ in 0..60 {
            let c = (self.rng.index(map.width()), self.rng.index(map.height()));
            if within_dmin(map.obstacle_distance(c), dmin + 0.25) {
                continue;
            }
            let (x, y) = map.cell_center(c);
            if libm::hypot(x - robot.x, y - robot.y) < 2.0 {
                continue;
            }
            if blocked || planner.plan(from, c).is_ok() {
                let theta = self
                    .rng
                    .range(-core::f64::consts::PI, core::f64::consts::PI);
                return Some(Pose::new(x, y, theta));
            }
        }
        None
    }

    /// Takes away the obstacles whose time is up; now and then places a new one.
    fn edits(&mut self, now: u64) {
        let mut gone = Vec::new();
        self.edits.retain(|e| {
            if e.until_ns <= now {
                gone.push(e.cells.clone());
                false
            } else {
                true
            }
        });
        for cells in gone {
            let list: Vec<(i64, i64, i16)> = cells.iter().map(|&(x, y)| (x, y, 0)).collect();
            if self.system.apply(&Input::MapUpdate { cells: list }).is_ok() {
                self.report.edits_removed += 1;
            }
            for c in cells {
                self.ours.remove(&c);
            }
        }
        if now < self.next_edit_ns {
            return;
        }
        self.next_edit_ns = now + (self.rng.range(5.0, 20.0) * NS_PER_S as f64) as u64;
        if self.edits.len() >= 6 {
            return;
        }
        if let Some(cells) = self.pick_edit() {
            let list: Vec<(i64, i64, i16)> = cells.iter().map(|&(x, y)| (x, y, 1)).collect();
            if self.system.apply(&Input::MapUpdate { cells: list }).is_ok() {
                self.report.edits_added += 1;
                self.ours.extend(cells.iter().copied());
                let life = self.rng.range(15.0, 45.0);
                self.edits.push(Edit {
                    cells,
                    until_ns: now + (life * NS_PER_S as f64) as u64,
                });
            }
        }
    }

    /// A block of free cells (0.1 to 1 m a side) at least `radiusOfBodyArea + dmin + 1 m`
    /// from the robot and `dmin + 0.5 m` from the goal, that leaves the goal reachable.
    fn pick_edit(&mut self) -> Option<Vec<(i64, i64)>> {
        let map = self.system.map()?.clone();
        let g = map.grid_size();
        let robot = self.system.robot_pose();
        let goal = self.goal;
        let dmin = self.options.dmin;
        let keep_robot = self.options.body_radius + dmin + 1.0;
        let keep_goal = dmin + 0.5;
        let side = |rng: &mut Rng| 1 + rng.index(((1.0 / g) as usize).max(1));
        for _ in 0..40 {
            let (w, h) = (side(&mut self.rng), side(&mut self.rng));
            let x0 = self.rng.index(map.width()) as i64;
            let y0 = self.rng.index(map.height()) as i64;
            let mut cells = Vec::new();
            let mut fits = true;
            'block: for y in y0..y0 + h as i64 {
                for x in x0..x0 + w as i64 {
                    if !map.contains(x, y) || map.is_obstacle(x, y) || self.ours.contains(&(x, y)) {
                        fits = false;
                        break 'block;
                    }
                    let (cx, cy) = map.cell_center((x as usize, y as usize));
                    let near_robot = libm::hypot(cx - robot.x, cy - robot.y) < keep_robot;
                    let near_goal =
                        goal.is_some_and(|g| libm::hypot(cx - g.x, cy - g.y) < keep_goal);
                    if near_robot || near_goal {
                        fits = false;
                        break 'block;
                    }
                    cells.push((x, y));
                }
            }
            if !fits || cells.is_empty() {
                continue;
            }
            if let Some(goal) = goal
                && !self.still_reachable(&map, &cells, robot, goal)
            {
                continue;
            }
            return Some(cells);
        }
        None
    }

    /// Whether `goal` stays reachable from `robot` with `cells` made obstacles.
    fn still_reachable(
        &self,
        map: &GridMap,
        cells: &[(i64, i64)],
        robot: Pose,
        goal: Pose,
    ) -> bool {
        let mut edited = map.clone();
        let list: Vec<(i64, i64, i16)> = cells.iter().map(|&(x, y)| (x, y, 1)).collect();
        if edited
            .map_update(&MapUpdate::from_cells(&list, Time::default()))
            .is_err()
        {
            return false;
        }
        let (Some(from), Some(to)) = (
            edited.world_to_cell(robot.x, robot.y),
            edited.world_to_cell(goal.x, goal.y),
        ) else {
            return false;
        };
        let to: Cell = to;
        AStar::new(&edited, self.options.dmin)
            .ok()
            .is_some_and(|mut a| a.plan(from, to).is_ok())
    }

    fn sample_memory(&mut self, now: u64) {
        let live = alloc::total_live();
        let m = &mut self.report.memory;
        let full = self.system.record().telemetry().total() >= DEFAULT_TELEMETRY_CAPACITY as u64;
        match m.heap_warm {
            None if full => {
                m.heap_warm = Some(live);
                m.warm_at_s = now as f64 * 1e-9;
                m.heap_after_warm.push(live);
            }
            Some(_) => m.heap_after_warm.push(live),
            None => {}
        }
    }
}
