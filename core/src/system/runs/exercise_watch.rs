//! [`ExerciseWatch`]: an exercise's checks decided while the robot drives, from the
//! record's time-stamped events and telemetry samples (see [`super::exercise`] for the
//! decisions: when the drive starts and ends, how open checks are settled, the rule on
//! parameters).

use super::exercise::{
    Check, CheckState, CheckStatus, DecidedBy, Exercise, ExerciseStatus, ParameterValues, Stuck,
    Verdict, parameter_values,
};
use crate::motion::angle_diff;
use crate::system::simulation::parameter_warning::ParameterWarning;
use crate::system::simulation::rest::{Motion, Offset};
use crate::system::simulation::robot::System;
use crate::system::simulation::status::Status;
use crate::system::simulation::telemetry::TelemetrySample;
use crate::system::vocabulary::events::EventKind;
use crate::system::vocabulary::kind::ComponentKind;

/// Four decimals: what a person reads (the state is decided on the exact value).
fn round4(v: f64) -> f64 {
    libm::round(v * 1e4) / 1e4
}

/// What a check has seen so far.
#[derive(Debug, Clone, PartialEq)]
struct Progress {
    state: CheckState,
    measured: Option<f64>,
}

/// An exercise being watched: fed the system after any number of ticks, it reads the facts
/// and samples since it last looked (module documentation).
#[derive(Debug, Clone)]
pub struct ExerciseWatch {
    exercise: Exercise,
    time_limit_ns: u64,
    baseline: ParameterValues,
    progress: Vec<Progress>,
    rule: Progress,
    changed: Vec<String>,
    warning_rule: Progress,
    warned: Vec<String>,
    /// Where the robot came to rest off the goal, as last looked (the mission's).
    off_goal: Option<Offset>,
    /// The heading error at the goal position before the final turn \[rad\] (the
    /// mission's), as last looked.
    approach: Option<f64>,
    events_seen: u64,
    samples_seen: u64,
    started_ns: Option<u64>,
    ended_ns: Option<u64>,
    /// Time of the previous sample while driving \[ns\].
    last_sample_ns: Option<u64>,
    /// DriveControl's first speed command \[ns\].
    command_ns: Option<u64>,
    replans: u64,
    global_plans: u64,
    backward_m: f64,
    max_speed: f64,
    faulted: Vec<String>,
    fault_seen: bool,
    /// The first check seen failed once the drive started: its index in the status's
    /// checks (the exercise's, then the two rules).
    first_failed: Option<usize>,
    /// Left alone, why the run cannot move on, as last looked (spec §7 Decision 0.4).
    stuck: Option<Stuck>,
}

/// How long the drive must have run before a run that looks stuck is decided \[ns\]: at
/// the drive's very start (an activation before the planners have run, a paused clock)
/// nothing is decided.
pub const STUCK_NS: u64 = 500_000_000;

impl ExerciseWatch {
    /// Watches `exercise` on a system built with the scenario's own configuration,
    /// `baseline` ([`parameter_values`] of it); the exercise ends at the latest
    /// `time_limit_s` after the drive's start. Events and samples already in the record
    /// are not the exercise's.
    pub fn new(
        exercise: &Exercise,
        time_limit_s: f64,
        baseline: ParameterValues,
        system: &System,
    ) -> Self {
        let open = Progress {
            state: CheckState::Open,
            measured: None,
        };
        let mut watch = Self {
            exercise: exercise.clone(),
            time_limit_ns: libm::round(time_limit_s * 1e9) as u64,
            baseline,
            progress: vec![open.clone(); exercise.checks.len()],
            rule: open.clone(),
            changed: Vec::new(),
            warning_rule: open,
            warned: Vec::new(),
            off_goal: None,
            approach: None,
            events_seen: system.record().event_count(),
            samples_seen: system.record().telemetry().total(),
            started_ns: None,
            ended_ns: None,
            last_sample_ns: None,
            command_ns: None,
            replans: 0,
            global_plans: 0,
            backward_m: 0.0,
            max_speed: 0.0,
            faulted: Vec::new(),
            fault_seen: false,
            first_failed: None,
            stuck: None,
        };
        if system.is_driving() {
            watch.started_ns = Some(system.time_ns());
        }
        watch.check_rule(system);
        watch
    }

    /// The exercise.
    pub fn exercise(&self) -> &Exercise {
        &self.exercise
    }

    /// Whether the exercise has ended.
    pub fn ended(&self) -> bool {
        self.ended_ns.is_some()
    }

    /// Reads what happened since the last look: the record's new events, then its new
    /// telemetry samples, then the time limit. Does nothing once ended. `more_to_come`:
    /// whether a request is still to come without anyone asking (an event of the scenario's
    /// timeline, a recorded request of a replay); without one, a robot that stands where
    /// nothing moves it again decides the verdict (spec §7 Decision 0.4).
    pub fn observe(&mut self, system: &System, more_to_come: bool) {
        if self.ended() {
            return;
        }
        if self.started_ns.is_some() {
            self.off_goal = system.mission().off_goal();
            self.approach = system.mission().approach_heading_error();
        }
        let record = system.record();
        let events: Vec<_> = record.events_since(self.events_seen).cloned().collect();
        self.events_seen = record.event_count();
        let samples: Vec<_> = record
            .telemetry()
            .since(self.samples_seen)
            .copied()
            .collect();
        self.samples_seen = record.telemetry().total();
        // Both in time order, merged (a sample before an event of the same time).
        let (mut e, mut s) = (events.iter().peekable(), samples.iter().peekable());
        loop {
            let next = match (e.peek(), s.peek()) {
                (Some(ev), Some(sa)) => ev.time_ns.min(sa.time_ns),
                (Some(ev), None) => ev.time_ns,
                (None, Some(sa)) => sa.time_ns,
                (None, None) => break,
            };
            // Nothing after the time limit is the exercise's, however late it is read.
            if let Some(start) = self.started_ns
                && next.saturating_sub(start) > self.time_limit_ns
            {
                self.end(start.saturating_add(self.time_limit_ns));
                return;
            }
            match (e.peek(), s.peek()) {
                (Some(ev), Some(sa)) if sa.time_ns <= ev.time_ns => {
                    if let Some(sa) = s.next() {
                        self.on_sample(sa);
                    }
                }
                (Some(_), _) => {
                    if let Some(ev) = e.next() {
                        self.on_event(ev.time_ns, &ev.kind, system);
                    }
                }
                (None, _) => {
                    if let Some(sa) = s.next() {
                        self.on_sample(sa);
                    }
                }
            }
            if self.ended() {
                return;
            }
            self.note_failure();
        }
        self.check_rule(system);
        let clearance = system.stats().min_clearance;
        if let Some(start) = self.started_ns {
            self.on_clearance(clearance);
            let now = system.time_ns();
            if now.saturating_sub(start) >= self.time_limit_ns {
                self.end(start.saturating_add(self.time_limit_ns));
            } else {
                self.deadlines(now);
            }
            self.note_failure();
            self.stuck = if more_to_come || self.ended() || now.saturating_sub(start) < STUCK_NS {
                None
            } else {
                stuck(system)
            };
        }
    }

    /// Notes the first check seen failed once the drive has started.
    fn note_failure(&mut self) {
        if self.first_failed.is_some() || self.started_ns.is_none() {
            return;
        }
        let rules = [self.rule.state, self.warning_rule.state];
        self.first_failed = self
            .progress
            .iter()
            .map(|p| p.state)
            .chain(rules)
            .position(|state| state == CheckState::Failed);
    }

    fn on_event(&mut self, time_ns: u64, kind: &EventKind, system: &System) {
        let physics = ComponentKind::PhysicsSim.instance_name();
        if self.started_ns.is_none() {
            if let EventKind::StateChanged { component, to, .. } = kind
                && component == physics
                && *to == crate::rtc::LifecycleState::Active
            {
                self.started_ns = Some(time_ns);
            }
            return;
        }
        match kind {
            EventKind::LocalPlanSent { replanned, .. } if *replanned => {
                self.replans += 1;
                self.set_count(
                    |c| matches!(c, Check::MaxReplans { .. } | Check::MinReplans { .. }),
                    self.replans,
                );
            }
            EventKind::GlobalPlan { .. } => {
                self.global_plans += 1;
                self.set_count(
                    |c| matches!(c, Check::MinGlobalPlans { .. }),
                    self.global_plans,
                );
            }
            EventKind::ComponentError { component, .. } => {
                self.fault_seen = true;
                if !self.faulted.contains(component) {
                    self.faulted.push(component.clone());
                }
            }
            EventKind::StateChanged { component, to, .. }
                if *to == crate::rtc::LifecycleState::Active =>
            {
                self.faulted.retain(|c| c != component);
                if self.fault_seen && self.faulted.is_empty() {
                    self.decide(|c| matches!(c, Check::Recovered), CheckState::Passed, None);
                }
            }
            EventKind::Bump { .. } => {
                self.decide(|c| matches!(c, Check::NoBump), CheckState::Failed, None);
                self.on_clearance(system.stats().min_clearance);
                self.end(time_ns);
            }
            EventKind::Arrived {
                approach_heading_error,
                heading_error,
                ..
            } => {
                let after = self.since_start(time_ns);
                for (check, p) in self.exercise.checks.iter().zip(&mut self.progress) {
                    match check {
                        Check::Arrived { within_s } => {
                            // Late (its deadline failed it): the time is still the time.
                            p.measured = Some(after);
                            if p.state == CheckState::Open {
                                p.state = pass_if(after <= *within_s);
                            }
                        }
                        Check::ArrivalHeading { within_deg } => {
                            let deg = heading_error.abs().to_degrees();
                            p.measured = Some(deg);
                            p.state = pass_if(deg <= *within_deg);
                        }
                        Check::ApproachHeading { within_deg } => {
                            let deg = approach_heading_error.to_degrees();
                            p.measured = deg.is_finite().then_some(deg);
                            p.state = pass_if(deg.is_finite() && deg <= *within_deg);
                        }
                        _ => {}
                    }
                }
                self.on_clearance(system.stats().min_clearance);
                self.end(time_ns);
            }
            _ => {}
        }
    }

    fn on_sample(&mut self, sample: &TelemetrySample) {
        let (time_ns, v_cmd, v) = (sample.time_ns, sample.v_cmd, sample.v);
        let position_error = libm::hypot(
            sample.estimate.x - sample.pose.x,
            sample.estimate.y - sample.pose.y,
        );
        let heading_error = angle_diff(sample.estimate.theta, sample.pose.theta)
            .abs()
            .to_degrees();
        let Some(start) = self.started_ns else {
            return;
        };
        if time_ns < start {
            return;
        }
        if let Some(last) = self.last_sample_ns
            && v < 0.0
        {
            self.backward_m += -v * (time_ns - last) as f64 * 1e-9;
        }
        self.last_sample_ns = Some(time_ns);
        if self.command_ns.is_none() && v_cmd > 0.0 {
            self.command_ns = Some(time_ns);
        }
        self.max_speed = self.max_speed.max(v);
        let (command, backward, max_speed) = (self.command_ns, self.backward_m, self.max_speed);
        for (check, p) in self.exercise.checks.iter().zip(&mut self.progress) {
            match *check {
                Check::ReachSpeed {
                    speed,
                    within_s,
                    band_percent,
                } => {
                    // The fastest speed within `within_s` of the first command: one meaning,
                    // passed or failed.
                    let Some(c) = command else { continue };
                    let after = (time_ns - c) as f64 * 1e-9;
                    if after > within_s {
                        if p.state == CheckState::Open {
                            p.state = CheckState::Failed;
                        }
                        continue;
                    }
                    let fastest = p.measured.map_or(v, |m| m.max(v));
                    p.measured = Some(fastest);
                    if p.state == CheckState::Open
                        && fastest >= speed * (1.0 - band_percent / 100.0)
                    {
                        p.state = CheckState::Passed;
                    }
                }
                Check::MaxOvershoot {
                    speed,
                    at_most_percent,
                } => {
                    let over = (max_speed / speed - 1.0) * 100.0;
                    p.measured = Some(over.max(0.0));
                    if over > at_most_percent && p.state == CheckState::Open {
                        p.state = CheckState::Failed;
                    }
                }
                Check::MaxLocalizationError { at_most_m } => {
                    let worst = p.measured.map_or(position_error, |m| m.max(position_error));
                    p.measured = Some(worst);
                    if worst > at_most_m && p.state == CheckState::Open {
                        p.state = CheckState::Failed;
                    }
                }
                Check::MaxLocalizationHeadingError { at_most_deg } => {
                    let worst = p.measured.map_or(heading_error, |m| m.max(heading_error));
                    p.measured = Some(worst);
                    if worst > at_most_deg && p.state == CheckState::Open {
                        p.state = CheckState::Failed;
                    }
                }
                Check::BackwardDistance { at_least_m } => {
                    p.measured = Some(backward);
                    if backward >= at_least_m && p.state == CheckState::Open {
                        p.state = CheckState::Passed;
                    }
                }
                _ => {}
            }
        }
    }

    fn on_clearance(&mut self, clearance: f64) {
        for (check, p) in self.exercise.checks.iter().zip(&mut self.progress) {
            if let Check::MinClearance { at_least_m } = *check {
                p.measured = clearance.is_finite().then_some(clearance);
                if clearance < at_least_m && p.state == CheckState::Open {
                    p.state = CheckState::Failed;
                }
            }
        }
    }

    /// Fails `arrived` checks whose time is up.
    fn deadlines(&mut self, now: u64) {
        let after = self.since_start(now);
        for (check, p) in self.exercise.checks.iter().zip(&mut self.progress) {
            if let Check::Arrived { within_s } = *check
                && p.state == CheckState::Open
                && after > within_s
            {
                p.state = CheckState::Failed;
            }
        }
    }

    fn set_count(&mut self, which: impl Fn(&Check) -> bool, count: u64) {
        for (check, p) in self.exercise.checks.iter().zip(&mut self.progress) {
            if !which(check) {
                continue;
            }
            // The count goes on after the check is decided: one number, the plans made.
            p.measured = Some(count as f64);
            if p.state != CheckState::Open {
                continue;
            }
            match *check {
                Check::MaxReplans { at_most } if count > at_most => p.state = CheckState::Failed,
                Check::MinReplans { at_least } | Check::MinGlobalPlans { at_least }
                    if count >= at_least =>
                {
                    p.state = CheckState::Passed;
                }
                _ => {}
            }
        }
    }

    fn decide(&mut self, which: impl Fn(&Check) -> bool, state: CheckState, measured: Option<f64>) {
        for (check, p) in self.exercise.checks.iter().zip(&mut self.progress) {
            if which(check) && p.state == CheckState::Open {
                p.state = state;
                if measured.is_some() {
                    p.measured = measured;
                }
            }
        }
    }

    fn check_rule(&mut self, system: &System) {
        self.check_warnings(system);
        let now = parameter_values(system);
        let mut changed = Vec::new();
        for ((kind, name), value) in &now {
            let same = self
                .baseline
                .get(&(*kind, name.clone()))
                .is_some_and(|b| b.to_bits() == value.to_bits());
            if !same && !self.exercise.allows(*kind, name) {
                changed.push(format!("{}.{name}", kind.name()));
            }
        }
        if self.rule.state == CheckState::Failed && self.started_ns.is_some() {
            // Sticky once the drive has started: keep what was first found.
            return;
        }
        self.rule.state = if changed.is_empty() {
            CheckState::Passed
        } else {
            CheckState::Failed
        };
        self.changed = changed;
    }

    /// The rule [`Check::NoWarning`]: decided as [`Self::check_rule`]'s.
    fn check_warnings(&mut self, system: &System) {
        if self.warning_rule.state == CheckState::Failed && self.started_ns.is_some() {
            return;
        }
        let warned = ParameterWarning::warned(system.wiring());
        self.warning_rule.state = pass_if(warned.is_empty());
        self.warned = warned;
    }

    fn since_start(&self, time_ns: u64) -> f64 {
        self.started_ns
            .map_or(0.0, |s| time_ns.saturating_sub(s) as f64 * 1e-9)
    }

    /// Ends the exercise at `time_ns` (arrival, a bump, the time limit): every open check is
    /// settled (module documentation).
    fn end(&mut self, time_ns: u64) {
        if self.ended() {
            return;
        }
        self.ended_ns = Some(time_ns);
        let (replans, global_plans) = (self.replans, self.global_plans);
        for (check, p) in self.exercise.checks.iter().zip(&mut self.progress) {
            match check {
                Check::MaxReplans { .. } | Check::MinReplans { .. } if p.measured.is_none() => {
                    p.measured = Some(replans as f64);
                }
                Check::MinGlobalPlans { .. } if p.measured.is_none() => {
                    p.measured = Some(global_plans as f64);
                }
                _ => {}
            }
        }
        let faulted = self.fault_seen && self.faulted.is_empty();
        // At rest off the goal: the heading checks are decided on the heading it stopped
        // with, and the one it reached the goal position with, if it did.
        let at_rest = self.off_goal.map(|o| o.heading_error.to_degrees());
        let approach = self.approach.map(f64::to_degrees);
        for (check, p) in self.exercise.checks.iter().zip(&mut self.progress) {
            if p.state != CheckState::Open {
                continue;
            }
            let heading = match check {
                Check::ArrivalHeading { within_deg } => at_rest.map(|d| (d, *within_deg)),
                Check::ApproachHeading { within_deg } => approach.map(|d| (d, *within_deg)),
                _ => None,
            };
            if let Some((deg, within)) = heading {
                p.measured = Some(deg);
                p.state = pass_if(deg <= within);
                continue;
            }
            p.state = match check {
                Check::NoBump
                | Check::MinClearance { .. }
                | Check::MaxLocalizationError { .. }
                | Check::MaxLocalizationHeadingError { .. }
                | Check::MaxReplans { .. }
                | Check::MaxOvershoot { .. } => CheckState::Passed,
                Check::Recovered => pass_if(faulted),
                Check::Arrived { .. }
                | Check::ApproachHeading { .. }
                | Check::ArrivalHeading { .. }
                | Check::MinReplans { .. }
                | Check::MinGlobalPlans { .. }
                | Check::ReachSpeed { .. }
                | Check::BackwardDistance { .. }
                | Check::OnlyAllowed
                | Check::NoWarning => CheckState::Failed,
            };
        }
    }

    /// The exercise as it stands. Spec §7 Decision 0.4: the verdict is `Failed` as soon as
    /// the run can no longer pass — a check failed (checks do not recover), or, left alone,
    /// the robot stands where nothing moves it and ending the exercise now would fail a
    /// check — naming the check that decided it. `Passed` comes at the end: until then a
    /// rule or a check that forbids something (a bump, a parameter changed) can still fail.
    pub fn status(&self) -> ExerciseStatus {
        if self.ended_ns.is_none()
            && self.first_failed.is_none()
            && let Some(stuck) = &self.stuck
        {
            // Left alone: what the end would settle now.
            let mut settled = self.clone();
            settled.stuck = None;
            settled.end(
                self.time_limit_ns
                    .saturating_add(self.started_ns.unwrap_or(0)),
            );
            let mut status = settled.status();
            if status.verdict == Verdict::Failed {
                status.ended_after = None;
                if let Some(d) = &mut status.decided_by {
                    d.stuck = Some(stuck.clone());
                }
                // The checks as they stand, but the deciding one as the end would settle
                // it: a Failed verdict always names a failed check (the page's ✗, `rtnav
                // check`'s reason); it is open again once the robot is set going.
                let mut checks = self.status_now().checks;
                if let Some(d) = &status.decided_by
                    && let (Some(own), Some(settled)) =
                        (checks.get_mut(d.check), status.checks.get(d.check))
                {
                    own.state = settled.state;
                }
                return ExerciseStatus { checks, ..status };
            }
        }
        self.status_now()
    }

    /// [`Self::status`] without looking ahead.
    fn status_now(&self) -> ExerciseStatus {
        let mut checks: Vec<CheckStatus> = self
            .exercise
            .checks
            .iter()
            .zip(&self.progress)
            .map(|(check, p)| CheckStatus {
                check: check.clone(),
                state: p.state,
                measured: p.measured.map(round4),
                unit: check.unit(),
                changed: Vec::new(),
                warned: Vec::new(),
            })
            .collect();
        checks.push(CheckStatus {
            check: Check::OnlyAllowed,
            state: self.rule.state,
            measured: None,
            unit: None,
            changed: self.changed.clone(),
            warned: Vec::new(),
        });
        checks.push(CheckStatus {
            check: Check::NoWarning,
            state: self.warning_rule.state,
            measured: None,
            unit: None,
            changed: Vec::new(),
            warned: self.warned.clone(),
        });
        let failed = self
            .first_failed
            .or_else(|| checks.iter().position(|c| c.state == CheckState::Failed));
        let verdict = match (self.started_ns, self.ended_ns) {
            (None, _) => Verdict::Waiting,
            (Some(_), None) if failed.is_some() => Verdict::Failed,
            (Some(_), None) => Verdict::Running,
            (Some(_), Some(_)) if failed.is_none() => Verdict::Passed,
            _ => Verdict::Failed,
        };
        let decided_by = match verdict {
            Verdict::Failed => failed.map(|check| DecidedBy { check, stuck: None }),
            _ => None,
        };
        ExerciseStatus {
            task: self.exercise.task.clone(),
            may_change: self.exercise.may_change.clone(),
            actions: self.exercise.actions.clone(),
            checks,
            verdict,
            decided_by,
            started_at: self.started_ns.map(|s| s as f64 * 1e-9),
            ended_after: self.ended_ns.map(|e| self.since_start(e)),
        }
    }
}

/// Left alone, why the robot of `system` cannot move on (spec §7 Decision 0.4): it stands,
/// and its status is one that nothing the system does on its own changes.
fn stuck(system: &System) -> Option<Stuck> {
    match system.status() {
        Status::ComponentError {
            component,
            motion: Motion::Stands,
            ..
        } => Some(Stuck::ComponentError { component }),
        Status::Inactive {
            component,
            motion: Motion::Stands,
        } => Some(Stuck::Inactive { component }),
        Status::NoRoute {
            motion: Motion::Stands,
            ..
        } => Some(Stuck::NoRoute),
        Status::StoppedOffGoal { .. } => Some(Stuck::StoppedOffGoal),
        Status::Halted {
            motion: Motion::Stands,
            ..
        } => Some(Stuck::Halted),
        _ => None,
    }
}

fn pass_if(ok: bool) -> CheckState {
    if ok {
        CheckState::Passed
    } else {
        CheckState::Failed
    }
}
