//! Path following for DriveControl (spec §5 "DriveControl"): the control points as a
//! polyline, pure pursuit with a look-ahead, limits on speed, acceleration and turn rate,
//! turning on the spot when the heading error is large, slowing to a stop at the goal and
//! turning to the goal heading, backward driving.
//!
//! **Stops.** The robot stops at the goal and at every *sharp* control point, one where the
//! path turns by more than `turn_in_place_angle`: it slows down so that it reaches the point
//! at `min_velocity`, turns on the spot towards the next segment, and drives on. Between
//! stops it follows the polyline by pure pursuit, its speed limited by the distance `d` to
//! the next stop (`v ≤ √(2·(a/2)·(d − tolerance))`: braking at half the acceleration limit)
//! and by the curvature (`|κ|·v ≤ ω_max`).
//! Driving backward (`Direction::Backward`) is driving forward with the heading turned by π
//! and the speed negated; the goal heading is the robot's own heading at the goal.

use crate::errors::MotionError;
use crate::interfaces::{ControlPoints, Direction, Pose};

use super::diff_drive::{angle_diff, wrap_angle};

/// A polyline through control points, with arc-length parameter `s` (0 at the first point).
///
/// A `Polyline` that exists has at least one point, finite coordinates and no two equal
/// consecutive points.
#[derive(Debug, Clone, PartialEq)]
pub struct Polyline {
    points: Vec<(f64, f64)>,
    cumulative: Vec<f64>,
}

/// The nearest point of a polyline to a given point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Projection {
    /// Arc length of the nearest point \[m\] (beyond the end when projecting on an extension).
    pub s: f64,
    /// The nearest point.
    pub point: (f64, f64),
    /// Distance from the given point to it \[m\].
    pub distance: f64,
    /// Index of the segment (from point `segment` to `segment + 1`; 0 for a single point).
    pub segment: usize,
}

impl Polyline {
    /// A polyline through `points` (at least one, all finite); repeated consecutive points
    /// are dropped.
    pub fn new(points: &[(f64, f64)]) -> Result<Self, MotionError> {
        if points.is_empty() {
            return Err(MotionError::WrongLength {
                port: "InControlPoints",
                len: 0,
                expected: "at least 1".to_owned(),
            });
        }
        let mut kept: Vec<(f64, f64)> = Vec::with_capacity(points.len());
        for (i, &(x, y)) in points.iter().enumerate() {
            for (axis, v) in [("x", x), ("y", y)] {
                if !v.is_finite() {
                    return Err(MotionError::NonFinite {
                        port: "InControlPoints",
                        field: format!("points[{i}].{axis}"),
                        value: v,
                    });
                }
            }
            if kept.last() != Some(&(x, y)) {
                kept.push((x, y));
            }
        }
        let mut cumulative = Vec::with_capacity(kept.len());
        let mut s = 0.0;
        cumulative.push(0.0);
        for w in kept.windows(2) {
            s += libm::hypot(w[1].0 - w[0].0, w[1].1 - w[0].1);
            cumulative.push(s);
        }
        if !s.is_finite() {
            // Finite points so far apart that the length overflows (found by the fuzzer).
            return Err(MotionError::NonFinite {
                port: "InControlPoints",
                field: "length".to_owned(),
                value: s,
            });
        }
        Ok(Self {
            points: kept,
            cumulative,
        })
    }

    /// The points.
    pub fn points(&self) -> &[(f64, f64)] {
        &self.points
    }

    /// Arc length at each point.
    pub fn cumulative(&self) -> &[f64] {
        &self.cumulative
    }

    /// Total length \[m\].
    pub fn length(&self) -> f64 {
        self.cumulative.last().copied().unwrap_or(0.0)
    }

    /// The point at arc length `s`, clamped to the polyline.
    pub fn point_at(&self, s: f64) -> (f64, f64) {
        let n = self.points.len();
        if n == 1 || s <= 0.0 {
            return self.points[0];
        }
        // The first segment whose end is at or beyond `s`.
        let i = self.cumulative[1..].partition_point(|&c| c < s);
        if i >= n - 1 {
            return self.points[n - 1];
        }
        let (s0, s1) = (self.cumulative[i], self.cumulative[i + 1]);
        let t = (s - s0) / (s1 - s0);
        let (a, b) = (self.points[i], self.points[i + 1]);
        (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1))
    }

    /// Unit direction of segment `i`.
    fn direction(&self, i: usize) -> (f64, f64) {
        let (a, b) = (self.points[i], self.points[i + 1]);
        let len = self.cumulative[i + 1] - self.cumulative[i];
        ((b.0 - a.0) / len, (b.1 - a.1) / len)
    }

    /// The nearest point of the whole polyline to `p` (ties: the earliest).
    pub fn project(&self, p: (f64, f64)) -> Projection {
        self.project_range(p, 0.0, self.length(), false)
    }

    /// The distance from `p` to the polyline \[m\]: DriveControl's `OutDeviating`.
    pub fn distance_to(&self, p: (f64, f64)) -> f64 {
        self.project(p).distance
    }

    /// The nearest point to `p` of the part `[lo, hi]` of the polyline; with `extend`, the
    /// segment ending at `hi` continues beyond it as a ray.
    fn project_range(&self, p: (f64, f64), lo: f64, hi: f64, extend: bool) -> Projection {
        let n = self.points.len();
        let single = |i: usize| {
            let q = self.points[i];
            Projection {
                s: self.cumulative[i],
                point: q,
                distance: libm::hypot(p.0 - q.0, p.1 - q.1),
                segment: i.min(n.saturating_sub(2)),
            }
        };
        if n == 1 {
            return single(0);
        }
        let mut best: Option<Projection> = None;
        for i in 0..n - 1 {
            let (s0, s1) = (self.cumulative[i], self.cumulative[i + 1]);
            if s1 <= lo || s0 >= hi {
                continue;
            }
            let len = s1 - s0;
            let a = self.points[i];
            let (dx, dy) = self.direction(i);
            let t_min = ((lo - s0) / len).max(0.0);
            let ends_here = s1 >= hi;
            let t_max = if extend && ends_here {
                f64::INFINITY
            } else {
                ((hi - s0) / len).min(1.0)
            };
            let along = ((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len;
            let t = along.clamp(t_min, t_max);
            let q = (a.0 + t * len * dx, a.1 + t * len * dy);
            let d = libm::hypot(p.0 - q.0, p.1 - q.1);
            if best.is_none_or(|b| d < b.distance) {
                best = Some(Projection {
                    s: s0 + t * len,
                    point: q,
                    distance: d,
                    segment: i,
                });
            }
        }
        best.unwrap_or_else(|| single(0))
    }
}

/// DriveControl's limits and gains (spec §5; DriveControl's configuration parameters).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PursuitParams {
    /// Largest speed \[m/s\].
    pub max_velocity: f64,
    /// Largest speed change \[m/s²\] (also the braking rate towards a stop).
    pub max_acceleration: f64,
    /// Largest turn rate \[rad/s\].
    pub max_angular_velocity: f64,
    /// Largest turn-rate change \[rad/s²\].
    pub max_angular_acceleration: f64,
    /// Pure-pursuit look-ahead \[m\].
    pub look_ahead_distance: f64,
    /// Heading error \[rad\] above which the robot turns on the spot; also the path angle
    /// above which a control point is a stop.
    pub turn_in_place_angle: f64,
    /// Distance \[m\] at which a stop (or the goal) counts as reached.
    pub goal_tolerance: f64,
    /// Heading error \[rad\] at which the goal heading counts as reached.
    pub goal_angle_tolerance: f64,
    /// Creep speed near a stop \[m/s\].
    pub min_velocity: f64,
    /// Turn rate per radian of heading error when turning on the spot \[1/s\].
    pub heading_gain: f64,
}

impl Default for PursuitParams {
    fn default() -> Self {
        Self {
            max_velocity: 0.5,
            max_acceleration: 0.5,
            max_angular_velocity: 1.0,
            max_angular_acceleration: 2.0,
            look_ahead_distance: 0.3,
            turn_in_place_angle: core::f64::consts::FRAC_PI_4,
            goal_tolerance: 0.01,
            goal_angle_tolerance: 0.01,
            min_velocity: 0.03,
            heading_gain: 2.0,
        }
    }
}

/// What DriveControl is doing.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum DrivePhase {
    /// No path: standing (or braking to a stand).
    #[default]
    Idle,
    /// Turning on the spot towards the path.
    TurnInPlace,
    /// Following the path by pure pursuit.
    Following,
    /// At the goal, turning to the goal heading.
    FinalTurn,
    /// At the goal with the goal heading: done.
    Arrived,
}

/// One control step's result.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PursuitCommand {
    /// Speed command \[m/s\] (negative when driving backward).
    pub v: f64,
    /// Turn-rate command \[rad/s\].
    pub w: f64,
    /// The phase after this step.
    pub phase: DrivePhase,
    /// Distance from the robot to the polyline \[m\], if there is a path.
    pub deviation: Option<f64>,
    /// The look-ahead point used, if following.
    pub lookahead: Option<(f64, f64)>,
}

#[derive(Debug, Clone, PartialEq)]
struct Path {
    line: Polyline,
    direction: Direction,
    goal_theta: f64,
    /// Index of the last stop point reached (0: the start).
    reached: usize,
}

/// The path follower: holds the path, the phase and the last command (for the rate limits).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PurePursuit {
    path: Option<Path>,
    phase: DrivePhase,
    last: (f64, f64),
}

fn ramp(from: f64, to: f64, step: f64) -> f64 {
    to.clamp(from - step, from + step)
}

impl PurePursuit {
    /// A follower with no path.
    pub fn new() -> Self {
        Self::default()
    }

    /// Takes new control points (000 §5.2.4.12–13): an empty list means "stop" (no path).
    /// Invalid points are refused and the held path stays.
    pub fn set_path(&mut self, cp: &ControlPoints) -> Result<(), MotionError> {
        if cp.points.is_empty() {
            self.path = None;
            self.phase = DrivePhase::Idle;
            return Ok(());
        }
        if !cp.goal_theta.is_finite() {
            return Err(MotionError::NonFinite {
                port: "InControlPoints",
                field: "goal_theta".to_owned(),
                value: cp.goal_theta,
            });
        }
        let line = Polyline::new(&cp.points)?;
        self.path = Some(Path {
            line,
            direction: cp.direction,
            goal_theta: wrap_angle(cp.goal_theta),
            reached: 0,
        });
        self.phase = DrivePhase::Following;
        Ok(())
    }

    /// Drops the path (the robot brakes to a stand).
    pub fn clear(&mut self) {
        self.path = None;
        self.phase = DrivePhase::Idle;
    }

    /// The current phase.
    pub fn phase(&self) -> DrivePhase {
        self.phase
    }

    /// The held path's polyline.
    pub fn polyline(&self) -> Option<&Polyline> {
        self.path.as_ref().map(|p| &p.line)
    }

    /// The last command `(v, ω)`.
    pub fn last_command(&self) -> (f64, f64) {
        self.last
    }

    /// Forgets the last command (the rate limits start from a stand).
    pub fn reset_command(&mut self) {
        self.last = (0.0, 0.0);
    }

    /// Replaces the last command by `(v, ω)` (a slower one a safety check allowed), so the
    /// rate limits continue from what was sent.
    pub fn limit_command(&mut self, v: f64, w: f64) {
        self.last = (v, w);
    }

    /// While following, turns on the spot towards the look-ahead point first (a circular
    /// body may always turn where it stands).
    pub fn turn_in_place(&mut self) {
        if self.phase == DrivePhase::Following {
            self.phase = DrivePhase::TurnInPlace;
        }
    }

    /// Whether point `k` (1 ≤ k < n−1) turns the path by more than `angle`, or is the goal.
    /// The turn is measured over `window` metres each side (the chords from the path point
    /// `window` before the vertex and to the one `window` after it): a one-cell jog or
    /// zigzag of a grid path is followed smoothly, a real corner is a stop.
    fn is_stop(line: &Polyline, k: usize, angle: f64, window: f64) -> bool {
        let n = line.points.len();
        if k + 1 >= n {
            return true;
        }
        let v = line.points[k];
        let s = line.cumulative[k];
        let before = line.point_at((s - window).max(0.0));
        let after = line.point_at((s + window).min(line.length()));
        let chord = |a: (f64, f64), b: (f64, f64), fallback: (f64, f64)| {
            let (dx, dy) = (b.0 - a.0, b.1 - a.1);
            if dx == 0.0 && dy == 0.0 {
                fallback
            } else {
                (dx, dy)
            }
        };
        let (ax, ay) = chord(before, v, line.direction(k - 1));
        let (bx, by) = chord(v, after, line.direction(k));
        let turn = angle_diff(libm::atan2(by, bx), libm::atan2(ay, ax)).abs();
        turn > angle
    }

    fn next_stop(line: &Polyline, reached: usize, angle: f64, window: f64) -> usize {
        let n = line.points.len();
        (reached + 1..n)
            .find(|&k| Self::is_stop(line, k, angle, window))
            .unwrap_or(n - 1)
    }

    /// One control step of `dt` seconds from the robot's `pose`: the velocity command, with
    /// every limit applied. A non-finite pose is refused, and so is a command that would not
    /// be finite (a path of huge coordinates); either way the last command is unchanged.
    pub fn update(
        &mut self,
        pose: Pose,
        dt: f64,
        params: &PursuitParams,
    ) -> Result<PursuitCommand, MotionError> {
        if let Some(v) = [pose.x, pose.y, pose.theta]
            .into_iter()
            .find(|v| !v.is_finite())
        {
            return Err(MotionError::NonFinite {
                port: "InCurrentPosition",
                field: "pose".to_owned(),
                value: v,
            });
        }
        let dt = if dt.is_finite() && dt > 0.0 { dt } else { 0.0 };
        let dv = params.max_acceleration * dt;
        let dw = params.max_angular_acceleration * dt;
        let p = (pose.x, pose.y);
        let turn_rate = |err: f64| {
            let mag = (params.heading_gain * err.abs())
                .min(params.max_angular_velocity)
                .min(f64::sqrt(2.0 * params.max_angular_acceleration * err.abs()));
            if err < 0.0 { -mag } else { mag }
        };

        let Some(path) = self.path.as_mut() else {
            self.phase = DrivePhase::Idle;
            self.last = (ramp(self.last.0, 0.0, dv), ramp(self.last.1, 0.0, dw));
            return Ok(PursuitCommand {
                v: self.last.0,
                w: self.last.1,
                phase: self.phase,
                deviation: None,
                lookahead: None,
            });
        };
        let sign = match path.direction {
            Direction::Forward => 1.0,
            Direction::Backward => -1.0,
        };
        let theta_e = match path.direction {
            Direction::Forward => pose.theta,
            Direction::Backward => wrap_angle(pose.theta + core::f64::consts::PI),
        };
        let deviation = Some(path.line.distance_to(p));
        let v_last = sign * self.last.0;
        let n = path.line.points.len();

        // (v_eff desired, ω desired, look-ahead); a phase change re-evaluates at once.
        let mut out = (0.0, 0.0, None);
        for _ in 0..n + 3 {
            match self.phase {
                DrivePhase::Idle | DrivePhase::Arrived => {
                    out = (0.0, 0.0, None);
                    break;
                }
                DrivePhase::FinalTurn => {
                    let err = angle_diff(path.goal_theta, pose.theta);
                    if err.abs() <= params.goal_angle_tolerance {
                        self.phase = DrivePhase::Arrived;
                        continue;
                    }
                    out = (0.0, turn_rate(err), None);
                    break;
                }
                DrivePhase::TurnInPlace | DrivePhase::Following => {
                    if n == 1 {
                        self.phase = DrivePhase::FinalTurn;
                        continue;
                    }
                    let stop = Self::next_stop(
                        &path.line,
                        path.reached,
                        params.turn_in_place_angle,
                        params.look_ahead_distance,
                    );
                    let (lo, hi) = (
                        path.line.cumulative[path.reached],
                        path.line.cumulative[stop],
                    );
                    let proj = path.line.project_range(p, lo, hi, true);
                    let vertex = path.line.points[stop];
                    let to_vertex = libm::hypot(vertex.0 - p.0, vertex.1 - p.1);
                    if proj.s >= hi - params.goal_tolerance || to_vertex <= params.goal_tolerance {
                        if stop + 1 >= n {
                            self.phase = DrivePhase::FinalTurn;
                        } else {
                            path.reached = stop;
                        }
                        continue;
                    }
                    let s_la = proj.s + params.look_ahead_distance;
                    let la = if s_la <= hi {
                        path.line.point_at(s_la)
                    } else {
                        let (dx, dy) = path.line.direction(stop - 1);
                        (vertex.0 + (s_la - hi) * dx, vertex.1 + (s_la - hi) * dy)
                    };
                    let (c, s) = (libm::cos(theta_e), libm::sin(theta_e));
                    let (dx, dy) = (la.0 - p.0, la.1 - p.1);
                    let (xl, yl) = (c * dx + s * dy, -s * dx + c * dy);
                    let alpha = libm::atan2(yl, xl);
                    let exit = (params.turn_in_place_angle / 2.0).min(0.1);
                    if self.phase == DrivePhase::Following
                        && alpha.abs() > params.turn_in_place_angle
                    {
                        self.phase = DrivePhase::TurnInPlace;
                    } else if self.phase == DrivePhase::TurnInPlace && alpha.abs() < exit {
                        self.phase = DrivePhase::Following;
                    }
                    if self.phase == DrivePhase::TurnInPlace {
                        out = (0.0, turn_rate(alpha), Some(la));
                        break;
                    }
                    let ld2 = xl * xl + yl * yl;
                    let kappa = if ld2 > 0.0 { 2.0 * yl / ld2 } else { 0.0 };
                    // Brake at half the acceleration limit, to reach the stop's tolerance
                    // at `min_velocity`: the other half absorbs the motors' lag, so the
                    // rate-limited command never falls behind the braking curve.
                    let d_stop = (hi - proj.s - params.goal_tolerance).max(0.0);
                    let mut v = params
                        .max_velocity
                        .min(f64::sqrt(params.max_acceleration * d_stop))
                        .max(params.min_velocity)
                        .min(params.max_velocity);
                    if kappa != 0.0 {
                        v = v.min(params.max_angular_velocity / kappa.abs());
                    }
                    let v_eff = ramp(v_last, v, dv);
                    out = (v_eff, kappa * v_eff, Some(la));
                    break;
                }
            }
        }
        let (v_eff, w_des, lookahead) = out;
        let v_eff = ramp(v_last, v_eff, dv);
        let w_des = w_des.clamp(-params.max_angular_velocity, params.max_angular_velocity);
        let w = ramp(self.last.1, w_des, dw);
        // A path of huge finite coordinates can still make the geometry overflow (∞ − ∞):
        // such a command is refused and never kept, so the rate limits stay finite
        // (a NaN kept here made the next tick's `clamp` panic).
        if let Some((field, value)) = [("v", v_eff), ("w", w)]
            .into_iter()
            .find(|(_, x)| !x.is_finite())
        {
            return Err(MotionError::NonFinite {
                port: "TargetVelocity",
                field: format!("{field} (from the control points and the pose)"),
                value,
            });
        }
        self.last = (sign * v_eff, w);
        Ok(PursuitCommand {
            v: self.last.0,
            w,
            phase: self.phase,
            deviation,
            lookahead,
        })
    }
}
