//! [`Comparison`]: one scenario run to its outcome with two configurations, side by side —
//! the summary table of `rtnav compare` and of the page's compare view, the two systems at
//! the end (drawn on one canvas, the second as a ghost) and their speeds over time.
//!
//! Each run is built by the one set-up builder with its [`Setup`] (the configurations are
//! set-up parameter changes) and driven headlessly ([`ScenarioRun`]) from the activation.
//! The energy is the wheels' mechanical work, Σ (|τ_L·ω_L| + |τ_R·ω_R|)·Δt over every base
//! tick, with the torque the physics applied and the wheel rates it integrated.

use core::fmt;

use serde::Serialize;

use super::runner::{ScenarioReport, ScenarioRun};
use super::scenario::{FileResolver, OutcomeKind, Scenario};
use super::setup::Setup;
use crate::errors::ScenarioError;
use crate::system::simulation::robot::System;
use crate::system::simulation::telemetry::TelemetrySample;
use crate::system::vocabulary::events::EventKind;
use crate::system::vocabulary::kind::ComponentKind;

/// One run's measures (a column of the table).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct RunSummary {
    /// The configuration in words (`PostureConsiderationLevel=85`, or `as written`).
    pub label: String,
    /// How the run ended.
    pub outcome: OutcomeKind,
    /// From the activation to the arrival \[s\]; `None` if it did not arrive.
    pub time_to_goal_s: Option<f64>,
    /// Distance the robot's centre drove \[m\].
    pub path_length_m: f64,
    /// Smallest distance from the robot's centre to an obstacle while driving \[m\].
    pub min_clearance_m: f64,
    /// Heading error when it reached the goal position, before the final turn \[°\];
    /// `None` if it never did.
    pub arrival_heading_error_deg: Option<f64>,
    /// Heading error at the end \[°\].
    pub final_heading_error_deg: f64,
    /// Local plans made.
    pub replans: u64,
    /// Global plans sent.
    pub global_plans: u64,
    /// The wheels' mechanical work \[J\] (module documentation).
    pub energy_j: f64,
    /// Simulated time at the end \[s\].
    pub sim_time_s: f64,
    /// The trace hash.
    pub trace_hash: String,
}

/// Speeds over time of both runs (the overlaid plots).
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct ComparePlots {
    /// Time since the activation, run A \[s\].
    pub t_a: Vec<f64>,
    /// Speed, run A \[m/s\].
    pub v_a: Vec<f64>,
    /// Turn rate, run A \[rad/s\].
    pub w_a: Vec<f64>,
    /// Time since the activation, run B \[s\].
    pub t_b: Vec<f64>,
    /// Speed, run B \[m/s\].
    pub v_b: Vec<f64>,
    /// Turn rate, run B \[rad/s\].
    pub w_b: Vec<f64>,
}

/// The compare view's table.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct CompareTable {
    /// The scenario.
    pub scenario: String,
    /// `[measure, A, B]` in words.
    pub rows: Vec<[String; 3]>,
    /// Run A's measures.
    pub a: RunSummary,
    /// Run B's measures.
    pub b: RunSummary,
}

/// Two runs of one scenario (module documentation).
#[derive(Debug)]
pub struct Comparison {
    scenario: String,
    a: (RunSummary, System, u64),
    b: (RunSummary, System, u64),
}

/// A set-up of `scenario` with `assignments` (`Component.Name=value`, separated by commas,
/// semicolons or new lines; `#` starts a comment) as its parameter changes.
pub fn setup_with(scenario: &Scenario, assignments: &str) -> crate::Result<Setup> {
    let mut setup = Setup::of(scenario);
    let bad = |reason: String| -> crate::Error {
        ScenarioError::Scenario {
            scenario: scenario.name.clone(),
            reason,
        }
        .into()
    };
    for item in assignments
        .lines()
        .map(|l| l.split('#').next().unwrap_or(""))
        .flat_map(|l| l.split([',', ';']))
        .map(str::trim)
        .filter(|i| !i.is_empty())
    {
        let (key, value) = item
            .split_once('=')
            .ok_or_else(|| bad(format!("`{item}`: expected Component.Name=value")))?;
        let (component, name) = key
            .trim()
            .split_once('.')
            .ok_or_else(|| bad(format!("`{key}`: expected Component.Name")))?;
        let component = ComponentKind::from_name(component.trim())?;
        let value: f64 = value
            .trim()
            .parse()
            .map_err(|e| bad(format!("`{item}`: {e}")))?;
        setup
            .params
            .entry(component.name().to_owned())
            .or_default()
            .insert(name.trim().to_owned(), value);
    }
    Ok(setup)
}

/// The words for a set-up's changes (`as written` for none).
fn label_of(setup: &Setup) -> String {
    let words: Vec<String> = setup
        .params
        .iter()
        .flat_map(|(c, ps)| ps.iter().map(move |(n, v)| format!("{c}.{n}={v}")))
        .collect();
    if words.is_empty() {
        "as written".to_owned()
    } else {
        words.join(", ")
    }
}

/// Runs `scenario` with `setup` to its outcome.
fn run(
    scenario: &Scenario,
    resolver: &dyn FileResolver,
    setup: &Setup,
) -> crate::Result<(RunSummary, System, u64)> {
    let mut run = ScenarioRun::with_setup(scenario, resolver, setup)?;
    let start_ns = run.system().time_ns();
    let base = run.system().wiring().execution_context().base_period_ns();
    let dt = base as f64 * 1e-9;
    let mut energy = 0.0;
    while run.advance(1).is_none() {
        let s = TelemetrySample::of(run.system().wiring(), run.system().time_ns());
        energy += (s.applied_torque[0] * s.wheel_rate[0]).abs() * dt
            + (s.applied_torque[1] * s.wheel_rate[1]).abs() * dt;
    }
    let report: ScenarioReport = run.report();
    let arrived_ns = run
        .system()
        .record()
        .events()
        .iter()
        .find(|e| matches!(e.kind, EventKind::Arrived { .. }))
        .map(|e| e.time_ns);
    let summary = RunSummary {
        label: label_of(setup),
        outcome: report.outcome.kind,
        time_to_goal_s: arrived_ns.map(|t| t.saturating_sub(start_ns) as f64 * 1e-9),
        path_length_m: report.path_length,
        min_clearance_m: report.min_clearance,
        arrival_heading_error_deg: report
            .approach_heading_deg
            .is_finite()
            .then_some(report.approach_heading_deg),
        final_heading_error_deg: report.heading_error_deg,
        replans: report.replans,
        global_plans: report.global_plans,
        energy_j: energy,
        sim_time_s: report.sim_time,
        trace_hash: report.trace_hash,
    };
    let system = run.into_system();
    Ok((summary, system, start_ns))
}

/// Runs `scenario` (files through `resolver`) with set-ups `a` and `b` (module
/// documentation).
pub fn compare(
    scenario: &Scenario,
    resolver: &dyn FileResolver,
    a: &Setup,
    b: &Setup,
) -> crate::Result<Comparison> {
    Ok(Comparison {
        scenario: scenario.name.clone(),
        a: run(scenario, resolver, a)?,
        b: run(scenario, resolver, b)?,
    })
}

impl Comparison {
    /// The scenario's name.
    pub fn scenario(&self) -> &str {
        &self.scenario
    }

    /// Run A's measures.
    pub fn a(&self) -> &RunSummary {
        &self.a.0
    }

    /// Run B's measures.
    pub fn b(&self) -> &RunSummary {
        &self.b.0
    }

    /// Run A's system at its end.
    pub fn system_a(&self) -> &System {
        &self.a.1
    }

    /// Run B's system at its end (drawn as the ghost).
    pub fn system_b(&self) -> &System {
        &self.b.1
    }

    /// The table: the scenario, the rows `[measure, A, B]` and both runs' measures.
    pub fn table(&self) -> CompareTable {
        CompareTable {
            scenario: self.scenario.clone(),
            rows: self.rows(),
            a: self.a.0.clone(),
            b: self.b.0.clone(),
        }
    }

    /// Speed and turn rate over time of both runs.
    pub fn plots(&self) -> ComparePlots {
        let mut p = ComparePlots::default();
        for (run, t, v, w) in [
            (&self.a, &mut p.t_a, &mut p.v_a, &mut p.w_a),
            (&self.b, &mut p.t_b, &mut p.v_b, &mut p.w_b),
        ] {
            for s in run.1.record().telemetry().samples() {
                if s.time_ns >= run.2 {
                    t.push((s.time_ns - run.2) as f64 * 1e-9);
                    v.push(s.v);
                    w.push(s.w);
                }
            }
        }
        p
    }

    /// The table's rows: a measure, run A's value, run B's value (in words and units).
    pub fn rows(&self) -> Vec<[String; 3]> {
        let (a, b) = (&self.a.0, &self.b.0);
        let opt = |v: Option<f64>, unit: &str, digits: usize| {
            v.map_or("-".to_owned(), |v| format!("{v:.digits$} {unit}"))
        };
        let num = |v: f64, unit: &str, digits: usize| {
            if v.is_finite() {
                format!("{v:.digits$} {unit}")
            } else {
                "-".to_owned()
            }
        };
        let row = |name: &str, f: &dyn Fn(&RunSummary) -> String| [name.to_owned(), f(a), f(b)];
        vec![
            row("configuration", &|r| r.label.clone()),
            row("outcome", &|r| format!("{:?}", r.outcome)),
            row("time to goal", &|r| opt(r.time_to_goal_s, "s", 2)),
            row("path length", &|r| num(r.path_length_m, "m", 2)),
            row("min clearance", &|r| num(r.min_clearance_m, "m", 3)),
            row("arrival heading error", &|r| {
                opt(r.arrival_heading_error_deg, "°", 1)
            }),
            row("final heading error", &|r| {
                num(r.final_heading_error_deg, "°", 1)
            }),
            row("replans", &|r| {
                format!("{} local, {} global", r.replans, r.global_plans)
            }),
            row("energy Σ|τ·ω|·Δt", &|r| num(r.energy_j, "J", 2)),
            row("trace hash", &|r| r.trace_hash.chars().take(16).collect()),
        ]
    }
}

impl fmt::Display for Comparison {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let rows = self.rows();
        let width = |i: usize| rows.iter().map(|r| r[i].chars().count()).max().unwrap_or(0);
        let (w0, w1) = (width(0), width(1).max(1));
        writeln!(f, "scenario  {}", self.scenario)?;
        writeln!(f, "{:w0$}  {:w1$}  B (ghost)", "", "A")?;
        for r in &rows {
            writeln!(f, "{:w0$}  {:w1$}  {}", r[0], r[1], r[2])?;
        }
        Ok(())
    }
}
