//! DriveControl's clearance check of the commanded motion (spec §5 "DriveControl", as
//! Nav2's collision monitor does it): how far the robot can still drive along the arc it is
//! commanded before its body would come within a margin of an obstacle.
//!
//! The planners keep `dmin` between cell centres, and the body (a circle) is tested against
//! the obstacle cells' squares (spec §5 "Physics"); on a fine map the route can leave only
//! millimetres between them, and tracking strays by more. The check closes that gap whatever
//! the map's cell size: the robot slows so that it can stop before any contact, and says so.

use crate::interfaces::Pose;
use crate::map::{GridMap, clearance, clearance_lower_bound};

use super::diff_drive::arc_step;

/// The distance \[m\] the robot at `pose` can travel along the arc of curvature `kappa`
/// (1/m; `direction` +1 forward, −1 backward) before the body of radius `radius` comes
/// within `margin` of an obstacle square (cells outside the map count as obstacles), looked
/// at up to `reach`; `reach` if the arc is clear that far. 0 if the body is within `margin`
/// already.
///
/// The arc is sampled every `min(GridSize/2, 2 cm)`; the exact clearance
/// ([`clearance`]) is computed only where its one-look-up lower bound is not already enough.
pub fn free_travel(
    map: &GridMap,
    pose: Pose,
    direction: f64,
    kappa: f64,
    radius: f64,
    margin: f64,
    reach: f64,
) -> f64 {
    let need = radius + margin;
    let touching =
        |p: Pose| clearance_lower_bound(map, p.x, p.y) < need && clearance(map, p.x, p.y) < need;
    if touching(pose) {
        return 0.0;
    }
    let ds = (map.grid_size() / 2.0).min(0.02);
    let steps = libm::ceil(reach / ds).max(1.0) as u64;
    let mut p = pose;
    // Travelled backward, the body still moves along the arc the heading gives; the arc's
    // turn per metre is the same.
    for k in 1..=steps {
        let s = (k as f64 * ds).min(reach);
        let step = s - (k - 1) as f64 * ds;
        p = arc_step(p, direction * step, direction * kappa * step);
        if touching(p) {
            return (s - ds).max(0.0);
        }
    }
    reach
}

#[cfg(test)]
mod tests {
    use super::*;

    fn room() -> GridMap {
        // 40 × 20 cells of 0.1 m, an obstacle column at x = 30 (3.0 m .. 3.1 m).
        let mut data = vec![0i16; 40 * 20];
        for y in 0..20 {
            data[30 + y * 40] = 1;
        }
        GridMap::from_map_data(&data, 40, 20, 0.1).unwrap()
    }

    #[test]
    fn straight_ahead_the_free_travel_ends_a_margin_before_the_wall() {
        let m = room();
        let d = free_travel(&m, Pose::new(1.0, 1.0, 0.0), 1.0, 0.0, 0.45, 0.01, 5.0);
        // The wall's face is at x = 3.0: the centre may come to 3.0 − 0.46 = 2.54; the arc is
        // sampled every 2 cm and the last free sample counts.
        assert!((1.52..=1.54).contains(&d), "{d}");
        // Backward, away from the wall: clear as far as looked (the map's west edge is
        // 1.0 m behind, so look 0.5 m).
        let back = free_travel(&m, Pose::new(1.0, 1.0, 0.0), -1.0, 0.0, 0.45, 0.01, 0.5);
        assert_eq!(back, 0.5);
        // Along the wall: clear.
        let turn = free_travel(&m, Pose::new(2.0, 1.0, 1.5), 1.0, 0.0, 0.45, 0.01, 0.5);
        assert_eq!(turn, 0.5);
        // Already within the margin: nothing.
        assert_eq!(
            free_travel(&m, Pose::new(2.545, 1.0, 0.0), 1.0, 0.0, 0.45, 0.01, 1.0),
            0.0
        );
    }
}
