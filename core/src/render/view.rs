//! Frame layout and the world ↔ pixel view transform.
//!
//! The frame is split into the map area (left) and, when the frame is wide enough and the
//! renderer has one, a side panel (right) for the colour bar, legend, scale bar and caption.
//! The layout and the view depend only on the frame size, the side panel, the map's geometry
//! and the [`Camera`] (the page's zoom and pan) — never on the layers or the scene — so a
//! click maps to the same world point whatever is shown.

use crate::errors::RenderError;
use crate::map::{Cell, GridMap};

/// The largest frame side accepted, pixels.
pub const MAX_FRAME_SIDE: u32 = 8192;

/// An axis-aligned rectangle of whole pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct PixelRect {
    pub x: u32,
    pub y: u32,
    pub w: u32,
    pub h: u32,
}

/// Sizes derived from the frame size: text scale, line unit, margin, panel and map area.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Layout {
    pub width: u32,
    pub height: u32,
    /// Font scale: each 5×7 font pixel is `k×k` frame pixels.
    pub k: u32,
    /// Line-width unit in pixels (markers and strokes are multiples of it).
    pub unit: f32,
    /// Free space around the map and the panel, pixels.
    pub margin: u32,
    /// The side panel, if the frame is wide enough for one.
    pub panel: Option<PixelRect>,
    /// Where the map is fitted (aspect kept, centred).
    pub map_area: PixelRect,
}

/// Width of the side panel in font pixels (characters × advance + padding).
const PANEL_FONT_PX: u32 = 19 * super::font::ADVANCE + 4;

impl Layout {
    /// The layout of a `width × height` frame, with the side panel when `side_panel` is set
    /// and the frame is wide enough for it.
    pub fn new(width: u32, height: u32, side_panel: bool) -> Result<Self, RenderError> {
        if width == 0 || height == 0 || width > MAX_FRAME_SIDE || height > MAX_FRAME_SIDE {
            return Err(RenderError::FrameSize {
                width,
                height,
                max: MAX_FRAME_SIDE,
            });
        }
        let short = width.min(height);
        let k = ((short + 200) / 400).clamp(1, 4);
        let unit = (short as f32 / 400.0).clamp(1.0, 4.0);
        let margin = (4 * k + 4).min(short / 8);
        let panel_w = PANEL_FONT_PX * k;
        // The panel is shown only if the map keeps at least half of the width.
        let fits = width >= 2 * (panel_w + 2 * margin) && height >= 24 * k;
        let panel = (side_panel && fits).then(|| PixelRect {
            x: width - margin - panel_w,
            y: margin,
            w: panel_w,
            h: height - 2 * margin,
        });
        let right = panel.map_or(width - margin, |p| p.x - margin);
        let map_area = PixelRect {
            x: margin,
            y: margin,
            w: right.saturating_sub(margin).max(1),
            h: height.saturating_sub(2 * margin).max(1),
        };
        Ok(Self {
            width,
            height,
            k,
            unit,
            margin,
            panel,
            map_area,
        })
    }

    /// The view that fits `map` into the map area, aspect kept, centred, its top-left corner
    /// on a whole pixel.
    pub fn view(&self, map: &GridMap) -> ViewTransform {
        let g = map.grid_size();
        let (ox, oy) = map.origin();
        let (mw, mh) = (map.width() as f64 * g, map.height() as f64 * g);
        let a = self.map_area;
        let scale = (f64::from(a.w) / mw).min(f64::from(a.h) / mh);
        let (pw, ph) = (mw * scale, mh * scale);
        let left = libm::floor(f64::from(a.x) + (f64::from(a.w) - pw) / 2.0 + 0.5);
        let top = libm::floor(f64::from(a.y) + (f64::from(a.h) - ph) / 2.0 + 0.5);
        ViewTransform {
            scale,
            tx: left - ox * scale,
            ty: top + ph + oy * scale,
            map_rect: (left, top, left + pw, top + ph),
        }
    }
}

/// The most a [`Camera`] magnifies the fitted view.
pub const MAX_ZOOM: f64 = 64.0;

/// Where the viewer looks (the page's zoom and pan): the fitted view magnified `zoom` times
/// (1 to [`MAX_ZOOM`]) with the world point `centre` (metres) at the middle of the map area.
/// A camera is kept inside the map: its centre never leaves the map's rectangle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    /// Magnification of the fitted view.
    pub zoom: f64,
    /// The world point at the middle of the map area \[m\].
    pub centre: (f64, f64),
}

impl Camera {
    /// The camera with its zoom clamped to 1..=[`MAX_ZOOM`] and its centre to `map`'s
    /// rectangle; `None` (the fitted view) for a zoom of 1 or less, or a non-finite value.
    pub fn clamped(self, map: &GridMap) -> Option<Self> {
        let finite =
            self.zoom.is_finite() && self.centre.0.is_finite() && self.centre.1.is_finite();
        if !finite || self.zoom <= 1.0 {
            return None;
        }
        let g = map.grid_size();
        let (ox, oy) = map.origin();
        let (w, h) = (map.width() as f64 * g, map.height() as f64 * g);
        Some(Self {
            zoom: self.zoom.min(MAX_ZOOM),
            centre: (
                self.centre.0.clamp(ox, ox + w),
                self.centre.1.clamp(oy, oy + h),
            ),
        })
    }
}

impl Layout {
    /// The view of `map` through `camera` (the fitted view when `None`).
    pub fn view_with(&self, map: &GridMap, camera: Option<Camera>) -> ViewTransform {
        let fit = self.view(map);
        let Some(c) = camera else { return fit };
        let scale = fit.scale * c.zoom;
        let a = self.map_area;
        let mx = f64::from(a.x) + f64::from(a.w) / 2.0;
        let my = f64::from(a.y) + f64::from(a.h) / 2.0;
        let (tx, ty) = (mx - scale * c.centre.0, my + scale * c.centre.1);
        let g = map.grid_size();
        let (ox, oy) = map.origin();
        let (w, h) = (map.width() as f64 * g, map.height() as f64 * g);
        ViewTransform {
            scale,
            tx,
            ty,
            map_rect: (
                tx + scale * ox,
                ty - scale * (oy + h),
                tx + scale * (ox + w),
                ty - scale * oy,
            ),
        }
    }

    /// The camera after zooming `view` (the view of `camera`) by `factor` about the frame
    /// pixel `(px, py)`: the world point under it stays under it (as far as the map's
    /// rectangle allows). `None`: back to the fitted view.
    pub fn zoom_at(
        &self,
        map: &GridMap,
        camera: Option<Camera>,
        px: f64,
        py: f64,
        factor: f64,
    ) -> Option<Camera> {
        if !(factor.is_finite() && factor > 0.0 && px.is_finite() && py.is_finite()) {
            return camera;
        }
        let view = self.view_with(map, camera);
        let (wx, wy) = view.pixel_to_world(px, py);
        let zoom = camera.map_or(1.0, |c| c.zoom) * factor;
        let scale = self.view(map).scale * zoom.clamp(1.0, MAX_ZOOM);
        let a = self.map_area;
        let mx = f64::from(a.x) + f64::from(a.w) / 2.0;
        let my = f64::from(a.y) + f64::from(a.h) / 2.0;
        Camera {
            zoom,
            centre: (wx - (px - mx) / scale, wy + (py - my) / scale),
        }
        .clamped(map)
    }

    /// The camera after dragging the picture by `(dx, dy)` frame pixels. The fitted view
    /// shows the whole map and does not move.
    pub fn pan_by(
        &self,
        map: &GridMap,
        camera: Option<Camera>,
        dx: f64,
        dy: f64,
    ) -> Option<Camera> {
        let c = camera?;
        if !(dx.is_finite() && dy.is_finite()) {
            return Some(c);
        }
        let scale = self.view(map).scale * c.zoom;
        Camera {
            zoom: c.zoom,
            centre: (c.centre.0 - dx / scale, c.centre.1 + dy / scale),
        }
        .clamped(map)
    }
}

/// The map's world frame ↔ frame pixels: `px = tx + s·x`, `py = ty − s·y` (pixel y grows
/// downward, world y upward). Pixel coordinates are continuous: pixel `(i, j)` covers
/// `[i, i+1) × [j, j+1)`, its centre is `(i + ½, j + ½)`, `(0, 0)` is the frame's top-left
/// corner. The browser turns a click into world coordinates with [`Self::pixel_to_world`]
/// (after scaling CSS pixels to canvas pixels).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ViewTransform {
    scale: f64,
    tx: f64,
    ty: f64,
    map_rect: (f64, f64, f64, f64),
}

impl ViewTransform {
    /// The view the renderer uses for `map` in a `width × height` frame.
    pub fn fit(width: u32, height: u32, map: &GridMap) -> Result<Self, RenderError> {
        Ok(Layout::new(width, height, true)?.view(map))
    }

    /// Pixels per metre.
    pub fn pixels_per_metre(&self) -> f64 {
        self.scale
    }

    /// World point (metres) → frame pixel coordinates.
    pub fn world_to_pixel(&self, x: f64, y: f64) -> (f64, f64) {
        (self.tx + self.scale * x, self.ty - self.scale * y)
    }

    /// Frame pixel coordinates → world point (metres).
    pub fn pixel_to_world(&self, px: f64, py: f64) -> (f64, f64) {
        ((px - self.tx) / self.scale, (self.ty - py) / self.scale)
    }

    /// The map cell under frame pixel coordinates `(px, py)`, if any.
    pub fn pixel_to_cell(&self, map: &GridMap, px: f64, py: f64) -> Option<Cell> {
        let (x, y) = self.pixel_to_world(px, py);
        map.world_to_cell(x, y)
    }

    /// The map's rectangle in frame pixels: `(left, top, right, bottom)`.
    pub fn map_rect(&self) -> (f64, f64, f64, f64) {
        self.map_rect
    }
}
