//! [`Record`]: what is kept of a run — the event log, the running totals, the trail, the
//! exact minimum clearance and the telemetry with its trace hash — written from the reports
//! of the wiring.
//!
//! **Architecture invariant**: the record observes; it never changes a component or the
//! mission. Two systems given the same inputs keep the same record, bit for bit.

use std::collections::VecDeque;

use serde::Serialize;

use super::wiring::{Report, Wiring};
use crate::errors::SystemError;
use crate::interfaces::Pose;
use crate::map::{ClearanceTracker, could_be_below};
use crate::system::vocabulary::events::{EventKind, SystemEvent};

use super::telemetry::{Telemetry, TelemetrySample};

/// How many events are kept (the oldest are dropped beyond this).
pub const EVENT_CAPACITY: usize = 4096;
/// How many plan times are kept (for the plots' replan marks).
pub const PLAN_TIMES_CAPACITY: usize = 1024;
/// How many trail points are kept.
pub const TRAIL_CAPACITY: usize = 20_000;
/// Trail points are at least this far apart \[m\].
const TRAIL_SPACING: f64 = 0.02;

/// Running totals of a drive, for the summary and the scenario checks.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RunStats {
    /// Distance driven by the robot's centre \[m\].
    pub path_length: f64,
    /// Smallest clearance seen while the physics ran \[m\] (infinite before it ran).
    pub min_clearance: f64,
    /// Global plans sent.
    pub global_plans: u64,
    /// Local (potential-field) plans sent.
    pub local_plans: u64,
    /// Paths LocalPathPlanning sent (local plans, global paths as received, empty paths).
    pub paths_sent: u64,
    /// Planning-failure notices.
    pub planning_failures: u64,
    /// Bumps.
    pub bumps: u64,
}

impl Default for RunStats {
    fn default() -> Self {
        Self {
            path_length: 0.0,
            min_clearance: f64::INFINITY,
            global_plans: 0,
            local_plans: 0,
            paths_sent: 0,
            planning_failures: 0,
            bumps: 0,
        }
    }
}

/// The log, totals, trail and telemetry of a run (module documentation).
#[derive(Debug, Clone)]
pub struct Record {
    events: VecDeque<SystemEvent>,
    event_total: u64,
    plan_times: VecDeque<u64>,
    stats: RunStats,
    trail: Vec<(f64, f64)>,
    last_pose: Option<Pose>,
    clearance: ClearanceTracker,
    telemetry: Telemetry,
    telemetry_period_ticks: u64,
}

impl Record {
    /// An empty record sampling telemetry every `telemetry_period_ticks` base ticks.
    pub fn new(telemetry_period_ticks: u64) -> Self {
        Self {
            events: VecDeque::new(),
            event_total: 0,
            plan_times: VecDeque::new(),
            stats: RunStats::default(),
            trail: Vec::new(),
            last_pose: None,
            clearance: ClearanceTracker::new(),
            telemetry: Telemetry::new(),
            telemetry_period_ticks: telemetry_period_ticks.max(1),
        }
    }

    /// Writes down `report`: its facts as events (stamped with its time) and in the totals;
    /// after a tick, the robot's track while the physics runs and a telemetry sample at the
    /// telemetry rate.
    pub fn observe(&mut self, report: &Report, wiring: &Wiring) {
        for fact in &report.facts {
            self.count(fact);
            self.push(report.time_ns, fact.clone());
        }
        let Some(index) = report.tick else {
            return;
        };
        if wiring.is_driving() {
            self.track(wiring);
        }
        if index.is_multiple_of(self.telemetry_period_ticks) {
            self.telemetry
                .record(TelemetrySample::of(wiring, report.time_ns));
        }
    }

    fn count(&mut self, fact: &EventKind) {
        let s = &mut self.stats;
        match fact {
            EventKind::GlobalPlan { .. } => s.global_plans += 1,
            EventKind::LocalPlanSent { replanned, .. } => {
                s.paths_sent += 1;
                if *replanned {
                    s.local_plans += 1;
                }
            }
            EventKind::PlanningFailed { .. } => s.planning_failures += 1,
            EventKind::Bump { .. } => s.bumps += 1,
            EventKind::GoalSet { placed: true, .. } => {
                self.trail.clear();
                self.last_pose = None;
            }
            _ => {}
        }
    }

    fn push(&mut self, time_ns: u64, kind: EventKind) {
        let plan = matches!(
            kind,
            EventKind::GlobalPlan { .. } | EventKind::LocalPlanSent { cells: 1.., .. }
        );
        if plan {
            if self.plan_times.len() == PLAN_TIMES_CAPACITY {
                self.plan_times.pop_front();
            }
            self.plan_times.push_back(time_ns);
        }
        if self.events.len() == EVENT_CAPACITY {
            self.events.pop_front();
        }
        self.events.push_back(SystemEvent { time_ns, kind });
        self.event_total += 1;
    }

    /// Path length, clearance and trail, every tick the physics runs.
    fn track(&mut self, wiring: &Wiring) {
        let pose = wiring.robot_pose();
        if let Some(last) = self.last_pose {
            let (dx, dy) = (pose.x - last.x, pose.y - last.y);
            if dx != 0.0 || dy != 0.0 {
                self.stats.path_length += f64::sqrt(dx * dx + dy * dy);
            }
        }
        self.last_pose = Some(pose);
        if let Some(map) = wiring.physics().physics().map()
            && could_be_below(map, pose.x, pose.y, self.stats.min_clearance)
        {
            let c = self
                .clearance
                .clearance(map, wiring.map_key(), pose.x, pose.y);
            if c < self.stats.min_clearance {
                self.stats.min_clearance = c;
            }
        }
        let far = self.trail.last().is_none_or(|&(x, y)| {
            (pose.x - x) * (pose.x - x) + (pose.y - y) * (pose.y - y)
                >= TRAIL_SPACING * TRAIL_SPACING
        });
        if far {
            if self.trail.len() == TRAIL_CAPACITY {
                self.trail.drain(..TRAIL_CAPACITY / 2);
            }
            self.trail.push((pose.x, pose.y));
        }
    }

    /// The events kept (the newest [`EVENT_CAPACITY`]), oldest first.
    pub fn events(&self) -> &VecDeque<SystemEvent> {
        &self.events
    }

    /// Events since the start (kept or not).
    pub fn event_count(&self) -> u64 {
        self.event_total
    }

    /// The events after the first `seen` of all time (those still kept), oldest first: a
    /// reader that remembers [`Record::event_count`] gets each event once.
    pub fn events_since(&self, seen: u64) -> impl Iterator<Item = &SystemEvent> {
        let new = self
            .event_total
            .saturating_sub(seen)
            .min(self.events.len() as u64) as usize;
        self.events.iter().skip(self.events.len() - new)
    }

    /// When the newest global and local plans were made \[ns\], oldest first.
    pub fn plan_times(&self) -> impl Iterator<Item = u64> + '_ {
        self.plan_times.iter().copied()
    }

    /// Running totals.
    pub fn stats(&self) -> RunStats {
        self.stats
    }

    /// Where the robot has been (points at least 2 cm apart, oldest first).
    pub fn trail(&self) -> &[(f64, f64)] {
        &self.trail
    }

    /// The telemetry history and trace hash.
    pub fn telemetry(&self) -> &Telemetry {
        &self.telemetry
    }

    /// Keeps the newest `capacity` telemetry samples (the trace hash covers all of them).
    pub fn set_telemetry_capacity(&mut self, capacity: usize) -> Result<(), SystemError> {
        self.telemetry.set_capacity(capacity)
    }

    /// Keeps only the newest `keep` telemetry samples.
    pub(in crate::system) fn trim_telemetry(&mut self, keep: usize) {
        self.telemetry.trim(keep);
    }

    /// Samples telemetry every `period_ticks` base ticks.
    pub(in crate::system) fn set_telemetry_period(&mut self, period_ticks: u64) {
        self.telemetry_period_ticks = period_ticks.max(1);
    }
}
