//! Telemetry: the robot's state sampled at a fixed simulated rate into a bounded history,
//! and the trace hash over every sample (spec §6: "the same scenario gives the same trace
//! bit for bit, natively and in wasm").

use std::collections::VecDeque;
use std::fmt::Write as _;

use serde::Serialize;
use sha2::{Digest, Sha256};

use super::wiring::Wiring;
use crate::errors::SystemError;
use crate::interfaces::Pose;

/// One telemetry sample: what the GUI plots (pose, wheels, torques, velocities, deviation).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TelemetrySample {
    /// Simulated time of the tick sampled \[ns\].
    pub time_ns: u64,
    /// The robot's true axle-centre pose (the physics).
    pub pose: Pose,
    /// The pose Localization publishes (simulated pose or odometry).
    pub estimate: Pose,
    /// Wheel angles `[left, right]` \[rad\] (the physics).
    pub wheel_angle: [f64; 2],
    /// Wheel rates `[left, right]` \[rad/s\] (the physics).
    pub wheel_rate: [f64; 2],
    /// MotorControl's target wheel angles (002 §5.2.5.4) \[rad\]; a script in its place
    /// gives the `target_wheel_angle` pair it keeps in its state, NaN where it keeps none.
    pub target_wheel_angle: [f64; 2],
    /// MotorControl's target wheel rates (002 §5.2.5.4) \[rad/s\].
    pub target_wheel_rate: [f64; 2],
    /// MotorControl's torques `[left, right]` \[N·m\] (before the physics' saturation).
    pub torque: [f64; 2],
    /// The torques the physics applied in its last step, after saturation at its
    /// `MaxTorque` \[N·m\]. Not in the CSV or the trace hash (it follows from `torque` and the
    /// physics' parameters).
    pub applied_torque: [f64; 2],
    /// DriveControl's commanded speed \[m/s\].
    pub v_cmd: f64,
    /// DriveControl's commanded turn rate \[rad/s\].
    pub w_cmd: f64,
    /// The robot's actual speed \[m/s\] (the physics).
    pub v: f64,
    /// The robot's actual turn rate \[rad/s\] (the physics).
    pub w: f64,
    /// DriveControl's deviation from the path \[m\]; NaN while it has none.
    pub deviation: f64,
}

impl TelemetrySample {
    /// The sample of the components' state now, stamped `time_ns`.
    pub fn of(wiring: &Wiring, time_ns: u64) -> Self {
        let physics = wiring.physics().physics();
        let state = physics.state();
        let motor = wiring.motor_readings();
        let (v_cmd, w_cmd) = wiring.drive_command();
        let (v, w) = physics.body_velocity();
        Self {
            time_ns,
            pose: state.pose,
            estimate: wiring.localization().current_pose(),
            wheel_angle: state.wheel_angle,
            wheel_rate: state.wheel_rate,
            target_wheel_angle: motor.target_wheel_angle,
            target_wheel_rate: motor.target_wheel_rate,
            torque: motor.torque,
            applied_torque: state.torque,
            v_cmd,
            w_cmd,
            v,
            w,
            deviation: wiring.drive_deviation().unwrap_or(f64::NAN),
        }
    }

    /// The CSV header matching [`TelemetrySample::write_csv_row`].
    pub const CSV_HEADER: &'static str = "t,x,y,theta,est_x,est_y,est_theta,\
wheel_angle_l,wheel_angle_r,wheel_rate_l,wheel_rate_r,target_angle_l,target_angle_r,\
target_rate_l,target_rate_r,torque_l,torque_r,v_cmd,w_cmd,v,w,deviation";

    /// Every number of the sample, in the order of [`TelemetrySample::CSV_HEADER`] after `t`.
    pub fn values(&self) -> [f64; 21] {
        [
            self.pose.x,
            self.pose.y,
            self.pose.theta,
            self.estimate.x,
            self.estimate.y,
            self.estimate.theta,
            self.wheel_angle[0],
            self.wheel_angle[1],
            self.wheel_rate[0],
            self.wheel_rate[1],
            self.target_wheel_angle[0],
            self.target_wheel_angle[1],
            self.target_wheel_rate[0],
            self.target_wheel_rate[1],
            self.torque[0],
            self.torque[1],
            self.v_cmd,
            self.w_cmd,
            self.v,
            self.w,
            self.deviation,
        ]
    }

    /// The bytes the trace hash covers: the time, then every value's IEEE-754 bits,
    /// little-endian.
    pub fn bits(&self) -> [u8; 8 * 22] {
        let mut out = [0u8; 8 * 22];
        out[..8].copy_from_slice(&self.time_ns.to_le_bytes());
        for (i, v) in self.values().iter().enumerate() {
            out[8 * (i + 1)..8 * (i + 2)].copy_from_slice(&v.to_bits().to_le_bytes());
        }
        out
    }

    /// Appends one CSV row (no newline): the time in seconds, then every value (shortest
    /// round-trip form; `NaN` for a missing deviation).
    pub fn write_csv_row(&self, out: &mut String) {
        let _ = write!(out, "{}", self.time_ns as f64 * 1e-9);
        for v in self.values() {
            let _ = write!(out, ",{v}");
        }
    }
}

/// The sampled history (bounded: the oldest samples are dropped) and the running trace hash
/// over every sample ever taken.
#[derive(Debug, Clone)]
pub struct Telemetry {
    capacity: usize,
    samples: VecDeque<TelemetrySample>,
    total: u64,
    hasher: Sha256,
}

/// Default history: 65 536 samples (about 22 minutes at 50 Hz).
pub const DEFAULT_TELEMETRY_CAPACITY: usize = 1 << 16;

impl Default for Telemetry {
    fn default() -> Self {
        Self {
            capacity: DEFAULT_TELEMETRY_CAPACITY,
            samples: VecDeque::new(),
            total: 0,
            hasher: Sha256::new(),
        }
    }
}

impl Telemetry {
    /// An empty history of [`DEFAULT_TELEMETRY_CAPACITY`] samples.
    pub fn new() -> Self {
        Self::default()
    }

    /// Changes how many samples are kept (the oldest are dropped now if needed). Zero is
    /// refused.
    pub fn set_capacity(&mut self, capacity: usize) -> Result<(), SystemError> {
        if capacity == 0 {
            return Err(SystemError::ZeroCapacity);
        }
        self.capacity = capacity;
        while self.samples.len() > capacity {
            self.samples.pop_front();
        }
        Ok(())
    }

    /// Drops all but the newest `keep` samples now (the capacity stays; the hash and the
    /// count go on).
    pub(in crate::system) fn trim(&mut self, keep: usize) {
        let drop = self.samples.len().saturating_sub(keep);
        self.samples.drain(..drop);
        self.samples.shrink_to_fit();
    }

    /// How many samples are kept.
    pub fn capacity(&self) -> usize {
        self.capacity
    }

    /// Records a sample: hashed, and kept (dropping the oldest when full).
    pub fn record(&mut self, sample: TelemetrySample) {
        self.hasher.update(sample.bits());
        if self.samples.len() == self.capacity {
            self.samples.pop_front();
        }
        self.samples.push_back(sample);
        self.total += 1;
    }

    /// The samples kept, oldest first.
    pub fn samples(&self) -> &VecDeque<TelemetrySample> {
        &self.samples
    }

    /// The newest sample.
    pub fn last(&self) -> Option<&TelemetrySample> {
        self.samples.back()
    }

    /// Samples taken since the start (kept or not).
    pub fn total(&self) -> u64 {
        self.total
    }

    /// The samples with sequence number ≥ `seq` that are still kept (the first sample has
    /// number 0): for a consumer that reads the history piece by piece.
    pub fn since(&self, seq: u64) -> impl Iterator<Item = &TelemetrySample> {
        let first_kept = self.total - self.samples.len() as u64;
        let skip = seq
            .saturating_sub(first_kept)
            .min(self.samples.len() as u64) as usize;
        self.samples.iter().skip(skip)
    }

    /// The trace hash: SHA-256 over [`TelemetrySample::bits`] of every sample taken, as 64
    /// lowercase hex digits.
    pub fn trace_hash(&self) -> String {
        hex(&self.hasher.clone().finalize())
    }

    /// The trace hash of `samples` alone (e.g. a prefix of a history, to compare two runs
    /// up to where the shorter one ended).
    pub fn hash_of<'a>(samples: impl IntoIterator<Item = &'a TelemetrySample>) -> String {
        let mut hasher = Sha256::new();
        for s in samples {
            hasher.update(s.bits());
        }
        hex(&hasher.finalize())
    }

    /// The whole history as CSV, header first.
    pub fn to_csv(&self) -> String {
        let mut out = String::from(TelemetrySample::CSV_HEADER);
        out.push('\n');
        for s in &self.samples {
            s.write_csv_row(&mut out);
            out.push('\n');
        }
        out
    }
}

pub(in crate::system) fn hex(digest: &[u8]) -> String {
    let mut s = String::with_capacity(2 * digest.len());
    for b in digest {
        let _ = write!(s, "{b:02x}");
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(t: u64) -> TelemetrySample {
        TelemetrySample {
            time_ns: t,
            pose: Pose::new(1.0, 2.0, 0.5),
            estimate: Pose::new(1.0, 2.0, 0.5),
            wheel_angle: [0.0; 2],
            wheel_rate: [0.0; 2],
            target_wheel_angle: [0.0; 2],
            target_wheel_rate: [0.0; 2],
            torque: [0.0; 2],
            applied_torque: [0.0; 2],
            v_cmd: 0.0,
            w_cmd: 0.0,
            v: 0.0,
            w: 0.0,
            deviation: f64::NAN,
        }
    }

    #[test]
    fn history_is_bounded_and_the_hash_covers_every_sample() {
        let mut t = Telemetry::new();
        assert_eq!(
            t.trace_hash(),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855"
        );
        assert!(t.set_capacity(0).is_err());
        t.set_capacity(2).unwrap();
        for k in 0..3 {
            t.record(sample(k));
        }
        assert_eq!(t.total(), 3);
        assert_eq!(t.samples().len(), 2);
        assert_eq!(t.since(0).count(), 2);
        assert_eq!(t.since(2).next().unwrap().time_ns, 2);
        assert_eq!(t.since(3).count(), 0);
        let mut u = Telemetry::new();
        for k in 0..3 {
            u.record(sample(k));
        }
        assert_eq!(
            t.trace_hash(),
            u.trace_hash(),
            "dropping samples keeps the hash"
        );
        u.record(sample(3));
        assert_ne!(t.trace_hash(), u.trace_hash());
        let csv = t.to_csv();
        assert_eq!(csv.lines().count(), 3);
        assert!(
            csv.lines()
                .nth(1)
                .unwrap()
                .starts_with("0.000000001,1,2,0.5,")
        );
        assert!(csv.ends_with(",NaN\n"));
        assert_eq!(
            TelemetrySample::CSV_HEADER.split(',').count(),
            1 + sample(0).values().len()
        );
    }
}
