//! A scenario's timed events in an interactive session (the page): they count from the moment
//! the robot starts driving, not from when the scenario was loaded, so the obstacle of
//! `appearing_obstacle` appears while the robot drives however long the teacher waited before
//! pressing **Activate**. (A headless [`ScenarioRun`](super::ScenarioRun) counts from 0, when
//! it activates everything.)

use super::events::EventKind;
use super::runtime::System;
use super::scenario::{Scenario, ScenarioEvent};

/// Seconds → nanoseconds as the scenario runner rounds them.
fn secs_to_ns(s: f64) -> u64 {
    libm::round(s * 1e9) as u64
}

/// The events waiting for the drive to start, then the non-map ones waiting for their time.
#[derive(Debug, Clone, Default)]
pub(super) struct DriveScript {
    /// Times relative to the start of the drive \[ns\]; emptied when the drive starts.
    armed: Vec<(u64, ScenarioEvent)>,
    /// Absolute simulated times \[ns\], in order; map updates are queued on MapMaintenance
    /// instead.
    due: Vec<(u64, ScenarioEvent)>,
}

impl DriveScript {
    /// Whether an event waits for its time.
    pub(super) fn has_due(&self) -> bool {
        !self.due.is_empty()
    }
}

impl System {
    /// Holds `events` (a scenario's timed events) until the robot starts driving, then runs
    /// them at their times counted from that moment: map updates through MapMaintenance, a
    /// new goal as [`System::set_goal`] (a refused one is an event), `SafeMode`, `Clear`.
    /// Replaces any events held before.
    pub fn set_drive_script(&mut self, events: &[ScenarioEvent]) {
        let mut armed: Vec<(u64, ScenarioEvent)> = events
            .iter()
            .map(|e| (secs_to_ns(e.at()), e.clone()))
            .collect();
        armed.sort_by_key(|(at, _)| *at);
        self.script = DriveScript {
            armed,
            due: Vec::new(),
        };
        self.start_drive_script();
    }

    /// The events still waiting (for the drive to start, or for their time).
    pub fn drive_script_len(&self) -> usize {
        self.script.armed.len() + self.script.due.len()
    }

    /// Once the robot drives, queues the held events from now.
    pub(super) fn start_drive_script(&mut self) {
        if self.script.armed.is_empty() || !self.is_driving() {
            return;
        }
        let now = self.time_ns();
        for (at, event) in std::mem::take(&mut self.script.armed) {
            match &event {
                ScenarioEvent::MapUpdate {
                    boxes,
                    cells,
                    value,
                    ..
                } => {
                    let Some(map) = self.map() else {
                        continue;
                    };
                    let update = Scenario::map_update(map, boxes, cells, *value);
                    if let Err(e) = self.schedule_map_update(now + at, update) {
                        self.push_event(EventKind::RequestRefused {
                            request: "the scenario's map update".to_owned(),
                            reason: e.to_string(),
                        });
                    }
                }
                _ => self.script.due.push((now + at, event)),
            }
        }
    }

    /// Applies the events whose time has come (before the tick at that time).
    pub(super) fn apply_due_script(&mut self) {
        let now = self.time_ns();
        while let Some((at, _)) = self.script.due.first()
            && *at <= now
        {
            let (_, event) = self.script.due.remove(0);
            match event {
                ScenarioEvent::Goal {
                    goal, direction, ..
                } => {
                    if let Err(e) = self.set_goal(goal.pose(), direction.direction()) {
                        self.push_event(EventKind::RequestRefused {
                            request: "the scenario's next goal".to_owned(),
                            reason: e.to_string(),
                        });
                    }
                }
                ScenarioEvent::SafeMode { .. } => self.safe_mode(),
                ScenarioEvent::Clear { .. } => self.clear(),
                ScenarioEvent::MapUpdate { .. } => {}
            }
        }
    }
}
