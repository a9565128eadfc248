//! Colours of the renderer: one place, so the map, the overlays and the legend agree.

use super::colour::Rgba;

/// Page and panel background.
pub(crate) const PAGE: Rgba = Rgba::rgb(241, 241, 237);
/// Free cells.
pub(crate) const FREE: Rgba = Rgba::rgb(255, 255, 255);
/// Obstacle cells.
pub(crate) const OBSTACLE: Rgba = Rgba::rgb(46, 52, 64);
/// The `dmin` zone tint, blended over free cells with [`DMIN_ALPHA`].
pub(crate) const DMIN: Rgba = Rgba::rgb(239, 99, 81);
/// Blend weight of the `dmin` tint, out of 255.
pub(crate) const DMIN_ALPHA: u32 = 100;
/// Cell grid lines darken a pixel to this fraction, out of 256.
pub(crate) const GRID_SHADE: u32 = 236;
/// Map border and panel frame lines.
pub(crate) const BORDER: Rgba = Rgba::rgb(120, 124, 130);
/// Text.
pub(crate) const TEXT: Rgba = Rgba::rgb(31, 41, 55);
/// Secondary text (tick labels).
pub(crate) const TEXT_DIM: Rgba = Rgba::rgb(75, 85, 99);
/// Light outline drawn under paths so they stand out on any background.
pub(crate) const HALO: Rgba = Rgba::rgb(255, 255, 255);
/// Global path (dashed).
pub(crate) const GLOBAL_PATH: Rgba = Rgba::rgb(37, 99, 235);
/// Merged local path.
pub(crate) const LOCAL_PATH: Rgba = Rgba::rgb(234, 88, 12);
/// Control point outline.
pub(crate) const CONTROL_LINE: Rgba = Rgba::rgb(17, 24, 39);
/// Control point fill.
pub(crate) const CONTROL_FILL: Rgba = Rgba::rgb(250, 204, 21);
/// Local target.
pub(crate) const TARGET: Rgba = Rgba::rgb(192, 38, 211);
/// Robot body fill.
pub(crate) const ROBOT_BODY: Rgba = Rgba::rgb(203, 213, 225).with_alpha(225);
/// Robot outline and heading.
pub(crate) const ROBOT_LINE: Rgba = Rgba::rgb(30, 41, 59);
/// Robot outline when it bumped into an obstacle.
pub(crate) const ROBOT_BUMP: Rgba = Rgba::rgb(220, 38, 38);
/// Wheels.
pub(crate) const WHEEL: Rgba = Rgba::rgb(17, 17, 17);
/// Trail.
pub(crate) const TRAIL: Rgba = Rgba::rgb(13, 148, 136).with_alpha(210);
/// The ghost robot and its trail (the compare view's run B).
pub(crate) const GHOST: Rgba = Rgba::rgb(124, 58, 237).with_alpha(220);
/// Start arrow.
pub(crate) const START: Rgba = Rgba::rgb(22, 163, 74);
/// Goal arrow.
pub(crate) const GOAL: Rgba = Rgba::rgb(220, 38, 38);
