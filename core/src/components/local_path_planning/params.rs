//! LocalPathPlanning's configuration parameters (000 §4.2) and its held flags (000 §5.2.4).

use serde::{Deserialize, Serialize};

use crate::define_parameters;

define_parameters! {
    /// The configuration parameters of 000 §4.2, all reflected `always` (常時).
    pub struct LocalPathPlanningParams {
        /// `RouteRemakeDistance` \[m\]: path distance from the current position to the local
        /// target (局所経路を生成する際の現在位置から目標位置までの経路上の距離).
        route_remake_distance: f64 = ("RouteRemakeDistance", "m", 10.0, 0.0, f64::INFINITY, Always,
            "how far ahead along the held path the local target lies: the potential field is grown from there back to the robot (000 §5.2.4.8)",
            seed: "局所経路を生成する際の現在位置から目標位置までの経路上の距離"),
        /// `Deviatinglen` \[m\]: deviation that triggers a local replan (経路逸脱限界距離).
        deviatinglen: f64 = ("Deviatinglen", "m", 0.1, 0.0, f64::INFINITY, Always,
            "how far the robot may stray from its path (DriveControl's InDeviating) before a new local plan is made (000 §5.2.4.5)",
            seed: "経路逸脱限界距離"),
        /// `dmin` \[m\]: closest allowed approach to an obstacle (障害物に近づくことができる距離).
        /// The seed's table gives its unit as "-"; it is compared with obstacle distances in
        /// metres, so spec §3 gives `m`.
        dmin: f64 = ("dmin", "m", 0.5, 0.0, f64::INFINITY, Always,
            "the robot's clearance: cells closer than this to an obstacle are impassable for both planners (one value for the system, spec §3)",
            seed: "障害物に近づくことができる距離"),
        /// `PostureConsiderationLevel` \[%\]: weight of the start/goal posture
        /// (スタート姿勢・ゴール姿勢の考慮レベル).
        posture_consideration_level: f64 = ("PostureConsiderationLevel", "%", 85.0, 0.0, 100.0, Always,
            "how much the start and goal headings shape the path: 0 shortest path, 100 posture only (000 §5.2.4.9)",
            seed: "スタート姿勢・ゴール姿勢の考慮レベル"),
        /// `NotPostureDistance` \[m\]: within this straight distance of the goal, posture is
        /// ignored (姿勢を考慮せずに経路生成を行う目標位置からの距離).
        not_posture_distance: f64 = ("NotPostureDistance", "m", 1.0, 0.0, f64::INFINITY, Always,
            "within this straight distance of the goal the headings are no longer considered (000 §5.2.4.9)",
            seed: "姿勢を考慮せずに経路生成を行う目標位置からの距離"),
        /// `TargetArea` \[m\]: near the goal, forward/backward is chosen by where the goal lies
        /// (目標位置付近において前進、後進を変更しつつ目標位置に近づく経路生成を行う範囲).
        target_area: f64 = ("TargetArea", "m", 0.5, 0.0, f64::INFINITY, Always,
            "within this distance of the goal, the robot drives forward or backward depending on whether the goal lies ahead or behind (000 §5.2.4.4)",
            seed: "目標位置付近において前進、後進を変更しつつ目標位置に近づく経路生成を行う範囲"),
    }
}

/// The held flags of 000 §5.2.4 ("…を取得したか判断するためのフラグ"), readable for the GUI.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct LocalPathFlags {
    /// A map is held (`SetMap`, 000 §5.2.4.1).
    pub map: bool,
    /// Start and goal are held and passable (`SetPosition`, 000 §5.2.4.2).
    pub position: bool,
    /// A grid path is held (`GlobalPathCourse`, 000 §5.2.4.3).
    pub path: bool,
    /// The current position is in the map and passable (000 §5.2.4.4).
    pub current_position: bool,
    /// The goal is reached: straight distance ≤ `GridSize` (000 §5.2.4.4). Latched until the
    /// next `SetPosition` or `Clear`.
    pub arrived: bool,
    /// A local replan is requested (000 §5.2.4.5, §5.2.4.6).
    pub replan_request: bool,
    /// SafeMode: halted until the next `SetPosition` (spec §3 Decision).
    pub safe_mode: bool,
}
