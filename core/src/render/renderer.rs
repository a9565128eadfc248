//! The [`Renderer`]: draws a [`Scene`] into its own [`Frame`], caching the static layers.
//!
//! A frame is the cached *plan layer* copied in, then the moving things drawn over it: the
//! trail, the start and goal, the local target and the robot. The plan layer is the cached
//! *background* (map raster, `dmin` zone, heat map, map border and the static panel) with the
//! global path, the local path and the control points over it; it is redrawn only when the
//! background or one of them changes (a new plan), not every frame. The background is
//! rebuilt only when its inputs change — the caller's map and field keys, the map geometry,
//! `dmin` or the layers — and the heat-map colours only when the field's key changes, so a
//! frame costs a copy, the trail and the robot (see `benches/render.rs`). A cached frame
//! equals a fresh one pixel for pixel (tested).

use tiny_skia::Pixmap;

use super::colour::Rgba;
use super::draw::{self, Px};
use super::frame::Frame;
use super::of_system::{FieldBuffers, ghost_of, scene_of, scene_with, shown_field};
use super::panel::{self, PanelInput, TextArea};
use super::raster::{
    Base, Bounds, Heat, LogBins, Recoloured, Region, draw_map, fill_rect, viridis,
};
use super::scene::{Layers, Scene};
use super::style;
use super::view::{Camera, Layout, PixelRect, ViewTransform};
use crate::errors::RenderError;
use crate::interfaces::Direction;
use crate::map::{Cell, CellRect, GridMap};
use crate::rtc::Time;
use crate::system::System;

/// A map's geometry: what the per-cell caches (base and heat colours) must match.
#[derive(Debug, Clone, Copy, PartialEq)]
struct MapShape {
    width: usize,
    height: usize,
    grid_size: u64,
    origin: (u64, u64),
}

impl MapShape {
    fn of(map: &GridMap) -> Self {
        Self {
            width: map.width(),
            height: map.height(),
            grid_size: map.grid_size().to_bits(),
            origin: (map.origin().0.to_bits(), map.origin().1.to_bits()),
        }
    }
}

/// What identifies a map for the background: the caller's key, the geometry and the map's
/// version (the time of its last `MapUpdate`).
#[derive(Debug, Clone, Copy, PartialEq)]
struct MapKey {
    key: u64,
    shape: MapShape,
    version: Time,
}

impl MapKey {
    fn of(map: &GridMap, key: u64) -> Self {
        Self {
            key,
            shape: MapShape::of(map),
            version: map.version(),
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
struct BackgroundKey {
    map: MapKey,
    dmin: u64,
    field: Option<u64>,
    layers: Layers,
    camera: Option<Camera>,
}

/// The base colours follow the map value they show by its stamp ([`Base::follow`]: where it
/// changed, or everywhere for another map), so their key is the geometry, not the caller's
/// key or the version.
#[derive(Debug, Clone, Copy, PartialEq)]
struct BaseKey {
    map: MapShape,
    dmin: u64,
    occupancy: bool,
    dmin_zone: bool,
}

/// The heat colours depend on the field alone, which its key names (`FieldView::key`),
/// and the map's geometry: an edit of the map does not recolour them.
#[derive(Debug, Clone, Copy, PartialEq)]
struct HeatKey {
    map: MapShape,
    field: u64,
}

/// Paths and the trail are drawn through the fewest points within this many pixels of them.
const SIMPLIFY: f32 = 0.5;

/// What the plan layer shows over the background: the paths and control points drawn, or
/// nothing valid since the background was redrawn.
#[derive(Debug, Clone, Default, PartialEq)]
struct PlanDrawn {
    valid: bool,
    global_path: Vec<Cell>,
    local_path: Vec<Cell>,
    control_points: Vec<(f64, f64)>,
}

impl PlanDrawn {
    /// Whether the layer shows `scene`'s plan over the current background.
    fn shows(&self, scene: &Scene<'_>) -> bool {
        self.valid
            && self.global_path == scene.global_path
            && self.local_path == scene.local_path
            && self.control_points == scene.control_points
    }

    fn remember(&mut self, scene: &Scene<'_>) {
        self.valid = true;
        for (kept, now) in [
            (&mut self.global_path, scene.global_path),
            (&mut self.local_path, scene.local_path),
        ] {
            kept.clear();
            kept.extend_from_slice(now);
        }
        self.control_points.clear();
        self.control_points.extend_from_slice(scene.control_points);
    }

    /// The background changed under the layer.
    fn forget(&mut self) {
        self.valid = false;
    }
}

/// Draws scenes into an owned `width × height` frame (spec §5 InventGUI): the runner's PNGs
/// and the browser canvas. Keep one per canvas: it caches the static layers between frames.
pub struct Renderer {
    layout: Layout,
    /// Whether the frame has the side panel (when wide enough).
    side_panel: bool,
    /// Where the viewer looks (`None`: the whole map, fitted).
    camera: Option<Camera>,
    frame: Frame,
    background: Pixmap,
    background_key: Option<BackgroundKey>,
    /// The background with the paths and control points over it.
    plan_layer: Pixmap,
    plan_drawn: PlanDrawn,
    text_area: Option<TextArea>,
    base: Option<(BaseKey, Base)>,
    heat: Option<(HeatKey, Heat)>,
    log: LogBins,
    viridis: [Rgba; 256],
    /// The potential field of the system drawn last, in the renderer's form.
    field_buffers: FieldBuffers,
}

impl std::fmt::Debug for Renderer {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Renderer")
            .field("width", &self.layout.width)
            .field("height", &self.layout.height)
            .field("background_key", &self.background_key)
            .field("base_cached", &self.base.as_ref().map(|b| b.0))
            .field("heat_cached", &self.heat.as_ref().map(|h| h.0))
            .finish_non_exhaustive()
    }
}

fn pixmap(width: u32, height: u32) -> Result<Pixmap, RenderError> {
    Pixmap::new(width, height).ok_or(RenderError::FrameSize {
        width,
        height,
        max: super::view::MAX_FRAME_SIDE,
    })
}

impl Renderer {
    /// A renderer for `width × height` frames (each side 1..=[`super::MAX_FRAME_SIDE`]),
    /// with the side panel (when the frame is wide enough) and the whole map in view.
    pub fn new(width: u32, height: u32) -> Result<Self, RenderError> {
        let layout = Layout::new(width, height, true)?;
        Ok(Self {
            layout,
            side_panel: true,
            camera: None,
            frame: Frame {
                pixmap: pixmap(width, height)?,
            },
            background: pixmap(width, height)?,
            background_key: None,
            plan_layer: pixmap(width, height)?,
            plan_drawn: PlanDrawn::default(),
            text_area: None,
            base: None,
            heat: None,
            log: LogBins::new(),
            viridis: viridis(),
            field_buffers: FieldBuffers::default(),
        })
    }

    /// Changes the frame size (the heat-map colours stay cached). On error nothing changes.
    pub fn resize(&mut self, width: u32, height: u32) -> Result<(), RenderError> {
        if (width, height) == (self.layout.width, self.layout.height) {
            return Ok(());
        }
        let layout = Layout::new(width, height, self.side_panel)?;
        let (frame, background) = (pixmap(width, height)?, pixmap(width, height)?);
        let plan_layer = pixmap(width, height)?;
        self.layout = layout;
        self.frame = Frame { pixmap: frame };
        self.background = background;
        self.plan_layer = plan_layer;
        self.background_key = None;
        self.text_area = None;
        Ok(())
    }

    /// Draws the side panel (colour bar, legend, scale bar, caption) beside the map when the
    /// frame is wide enough (`true`, the default: the PNGs of `rtnav render`), or gives the
    /// map the whole frame (`false`: the page, which shows these itself).
    pub fn set_side_panel(&mut self, on: bool) {
        if on == self.side_panel {
            return;
        }
        self.side_panel = on;
        if let Ok(layout) = Layout::new(self.layout.width, self.layout.height, on) {
            self.layout = layout;
        }
        self.background_key = None;
        self.text_area = None;
    }

    /// Where the viewer looks; `None`: the whole map, fitted.
    pub fn camera(&self) -> Option<Camera> {
        self.camera
    }

    /// Looks through `camera` at `map` ([`Camera::clamped`]; `None`: the whole map).
    pub fn set_camera(&mut self, map: &GridMap, camera: Option<Camera>) {
        self.camera = camera.and_then(|c| c.clamped(map));
    }

    /// Zooms by `factor` about the frame pixel `(px, py)`, which keeps showing the same world
    /// point (a wheel step, a pinch, the zoom buttons about the middle). Back to the whole
    /// map at a zoom of 1 or less.
    pub fn zoom_at(&mut self, map: &GridMap, px: f64, py: f64, factor: f64) {
        self.camera = self.layout.zoom_at(map, self.camera, px, py, factor);
    }

    /// Drags the picture by `(dx, dy)` frame pixels (while zoomed in).
    pub fn pan_by(&mut self, map: &GridMap, dx: f64, dy: f64) {
        self.camera = self.layout.pan_by(map, self.camera, dx, dy);
    }

    /// The potential range the heat map's colours span, `(lo, hi, clipped)` (log scale;
    /// `clipped`: the top half percent of the reached cells is above `hi`), when the last
    /// frame showed a heat map with a reached cell.
    pub fn heat_range(&self) -> Option<(f64, f64, bool)> {
        self.background_key.and_then(|k| k.field)?;
        let range = self.heat.as_ref()?.1.range?;
        Some((range.lo, range.hi, range.clipped))
    }

    /// Forgets the cached layers, so the next frame redraws everything.
    pub fn invalidate(&mut self) {
        self.background_key = None;
        self.base = None;
        self.heat = None;
        self.field_buffers = FieldBuffers::default();
    }

    /// Frame width in pixels.
    pub fn width(&self) -> u32 {
        self.layout.width
    }

    /// Frame height in pixels.
    pub fn height(&self) -> u32 {
        self.layout.height
    }

    /// The view this renderer uses for `map`: world ↔ pixel, for turning clicks into world
    /// coordinates and back.
    pub fn view(&self, map: &GridMap) -> ViewTransform {
        self.layout.view_with(map, self.camera)
    }

    /// The last frame drawn (blank before the first).
    pub fn frame(&self) -> &Frame {
        &self.frame
    }

    /// Draws `system` now ([`scene_of`]) with `layers` and `caption`; an error before a map
    /// is loaded. The potential field is converted only when a new one was planned.
    pub fn render_system(
        &mut self,
        system: &System,
        caption: &str,
        layers: Layers,
    ) -> Result<&Frame, RenderError> {
        let mut buffers = core::mem::take(&mut self.field_buffers);
        let result = match scene_of(system, &mut buffers, caption, layers) {
            Some(scene) => self.render(&scene).map(|_| ()),
            None => Err(RenderError::NoMap),
        };
        self.field_buffers = buffers;
        result.map(|()| &self.frame)
    }

    /// Draws `system` as [`Renderer::render_system`] does, with `ghost`'s robot and trail
    /// over it ([`ghost_of`]: the compare view, run B as the ghost).
    pub fn render_compare(
        &mut self,
        system: &System,
        ghost: &System,
        caption: &str,
        layers: Layers,
    ) -> Result<&Frame, RenderError> {
        let mut buffers = core::mem::take(&mut self.field_buffers);
        let result = match scene_of(system, &mut buffers, caption, layers) {
            Some(scene) => {
                let scene = Scene {
                    ghost: ghost_of(ghost),
                    ..scene
                };
                self.render(&scene).map(|_| ())
            }
            None => Err(RenderError::NoMap),
        };
        self.field_buffers = buffers;
        result.map(|()| &self.frame)
    }

    /// Draws `scene` and returns the frame. A scene with a non-finite number, a negative
    /// size or `dmin`, a path cell outside the map, per-cell arrays of the wrong length or
    /// (when the heat map is shown and its field is new) a reached cell without a positive
    /// finite potential is refused with an error, and nothing held changes: the frame keeps
    /// the last drawing.
    pub fn render(&mut self, scene: &Scene<'_>) -> Result<&Frame, RenderError> {
        scene.validate()?;
        let map = scene.map;
        let field = scene.field.filter(|_| scene.layers.heat_map);
        if let Some(f) = &field {
            let key = HeatKey {
                map: MapShape::of(map),
                field: f.key,
            };
            if self.heat.as_ref().map(|h| h.0) != Some(key) {
                let heat = Heat::new(f, &self.log, &self.viridis)?;
                self.heat = Some((key, heat));
            }
        }
        let view = self.layout.view_with(map, self.camera);
        let key = self.background_key_of(scene, field.map(|f| f.key));
        if self.background_key != Some(key) {
            self.update_background(scene, &view, key, field.is_some());
        }
        if !self.plan_drawn.shows(scene) {
            self.plan_layer
                .data_mut()
                .copy_from_slice(self.background.data());
            self.draw_plan(scene, &view);
            self.plan_drawn.remember(scene);
        }
        self.frame
            .pixmap
            .data_mut()
            .copy_from_slice(self.plan_layer.data());
        self.draw_overlays(scene, &view);
        self.draw_panel_text(scene);
        Ok(&self.frame)
    }

    /// What the background of `scene` with the potential field `field` (its key, if the
    /// heat map shows one) is drawn from.
    fn background_key_of(&self, scene: &Scene<'_>, field: Option<u64>) -> BackgroundKey {
        BackgroundKey {
            map: MapKey::of(scene.map, scene.map_key),
            dmin: scene.dmin.to_bits(),
            field,
            layers: scene.layers,
            camera: self.camera,
        }
    }

    /// Whether drawing `system` with `layers` now ([`Renderer::render_system`]) would start
    /// from the layers kept from the last frame — the map, the heat map, the paths and the
    /// control points as drawn then — and draw only the robot, its trail and the marks
    /// again: `false` after a new plan, a `MapUpdate`, a new view or layer set, or before the
    /// first frame. Converts nothing: a caller that spreads expensive work over frames (the
    /// page) asks it before drawing.
    pub fn draws_from_cache(&self, system: &System, layers: Layers) -> bool {
        let Some(scene) = scene_with(system, None, "", layers) else {
            return false;
        };
        let field = shown_field(system, layers).map(|(_, key)| key);
        self.background_key == Some(self.background_key_of(&scene, field))
            && self.plan_drawn.shows(&scene)
    }

    /// Brings the background up to `key`, with the base colours it is drawn from: after a
    /// `MapUpdate` alone, only the pixels of the cells the base recoloured ([`Base::follow`]);
    /// else all of it. The base changes only here, so it always shows what the background
    /// was last drawn from.
    fn update_background(
        &mut self,
        scene: &Scene<'_>,
        view: &ViewTransform,
        key: BackgroundKey,
        heat_on: bool,
    ) {
        let (map, dmin, layers) = (scene.map, scene.dmin, &scene.layers);
        let base_key = BaseKey {
            map: key.map.shape,
            dmin: dmin.to_bits(),
            occupancy: layers.occupancy,
            dmin_zone: layers.dmin_zone,
        };
        let recoloured = match &mut self.base {
            Some((k, base)) if *k == base_key => base.follow(map, dmin, layers),
            _ => {
                self.base = Some((base_key, Base::new(map, dmin, layers)));
                Recoloured::All
            }
        };
        // Only the map's key or version changed: a `MapUpdate`.
        let map_updated = self.background_key.is_some_and(|old| {
            let (k, version) = (key.map.key, key.map.version);
            BackgroundKey {
                map: MapKey {
                    key: k,
                    version,
                    ..old.map
                },
                ..old
            } == key
        });
        let redrawn = map_updated
            && match recoloured {
                Recoloured::Nothing => true,
                Recoloured::Within(cells) => self.redraw_map_cells(scene, view, heat_on, cells),
                Recoloured::All => false,
            };
        if !redrawn {
            self.draw_background(scene, view, heat_on);
        }
        self.background_key = Some(key);
        self.plan_drawn.forget();
    }

    /// Redraws the background's pixels that show a cell of `cells`, if they lie inside the
    /// map's picture, two pixels clear of its border and of the side panel (which are drawn
    /// over the map raster); `false` (nothing drawn) otherwise.
    fn redraw_map_cells(
        &mut self,
        scene: &Scene<'_>,
        view: &ViewTransform,
        heat_on: bool,
        cells: CellRect,
    ) -> bool {
        let Some((_, base)) = &self.base else {
            return false;
        };
        let panel = self.layout.panel;
        let heat = self.heat.as_ref().map(|h| &h.1).filter(|_| heat_on);
        let (l, t, r, b) = view.map_rect();
        let clear = |(x0, y0, x1, y1): Bounds| {
            let apart = |p: PixelRect| {
                x1 + 2 <= p.x || p.x + p.w + 2 <= x0 || y1 + 2 <= p.y || p.y + p.h + 2 <= y0
            };
            f64::from(x0) >= l + 2.0
                && f64::from(y0) >= t + 2.0
                && f64::from(x1) + 2.0 <= r
                && f64::from(y1) + 2.0 <= b
                && panel.is_none_or(apart)
        };
        let (data, width) = (self.background.data_mut(), self.layout.width);
        let only = Region {
            cells,
            fits: &clear,
        };
        draw_map(data, width, view, scene.map, base, heat, Some(only)).is_some()
    }

    fn draw_background(&mut self, scene: &Scene<'_>, view: &ViewTransform, heat_on: bool) {
        let (width, height) = (self.layout.width, self.layout.height);
        let heat = self.heat.as_ref().map(|h| &h.1).filter(|_| heat_on);
        let bg = &mut self.background;
        fill_rect(bg.data_mut(), width, (0, 0, width, height), style::PAGE);
        if let Some((_, base)) = &self.base {
            draw_map(bg.data_mut(), width, view, scene.map, base, heat, None);
        }
        let (l, t, r, b) = view.map_rect();
        let (l, t, r, b) = (l as f32, t as f32, r as f32, b as f32);
        draw::polygon_outline(
            bg,
            &[
                (l - 0.5, t - 0.5),
                (r + 0.5, t - 0.5),
                (r + 0.5, b + 0.5),
                (l - 0.5, b + 0.5),
            ],
            1.0,
            style::BORDER,
        );
        self.text_area = panel::draw_static(
            bg,
            &self.layout,
            view,
            &PanelInput {
                layers: scene.layers,
                has_field: heat_on,
                range: heat.and_then(|h| h.range),
                viridis: &self.viridis,
            },
        );
    }

    /// The global path, the local path and the control points, into the plan layer.
    fn draw_plan(&mut self, scene: &Scene<'_>, view: &ViewTransform) {
        let layers = scene.layers;
        let u = self.layout.unit;
        let map = scene.map;
        let px = |x: f64, y: f64| -> Px {
            let p = view.world_to_pixel(x, y);
            (p.0 as f32, p.1 as f32)
        };
        let cells = |path: &[Cell]| -> Vec<Px> {
            path.iter()
                .map(|&c| {
                    let (x, y) = map.cell_center(c);
                    px(x, y)
                })
                .collect()
        };
        let pm = &mut self.plan_layer;
        if layers.global_path && !scene.global_path.is_empty() {
            let pts = draw::simplify(&cells(scene.global_path), SIMPLIFY);
            draw::polyline(pm, &pts, 10.0 * u, style::GLOBAL_PATH.with_alpha(100));
        }
        if layers.local_path && !scene.local_path.is_empty() {
            let pts = draw::simplify(&cells(scene.local_path), SIMPLIFY);
            draw::polyline(pm, &pts, 4.0 * u, style::HALO);
            draw::polyline(pm, &pts, 2.5 * u, style::LOCAL_PATH);
        }
        if layers.control_points && !scene.control_points.is_empty() {
            // All rims, then all fills: two fills for any number of points (a staircase
            // route on a fine map has hundreds).
            let centres: Vec<Px> = scene
                .control_points
                .iter()
                .map(|&(x, y)| px(x, y))
                .collect();
            draw::discs(pm, centres.iter().copied(), 3.5 * u, style::CONTROL_LINE);
            draw::discs(pm, centres, 2.3 * u, style::CONTROL_FILL);
        }
    }

    /// What moves every frame, over the plan layer: the trails, the start and goal, the
    /// local target, the ghost and the robot.
    fn draw_overlays(&mut self, scene: &Scene<'_>, view: &ViewTransform) {
        let layers = scene.layers;
        let u = self.layout.unit;
        let uf = f64::from(u);
        let px = |x: f64, y: f64| -> (f64, f64) { view.world_to_pixel(x, y) };
        let to_f32 = |p: (f64, f64)| -> Px { (p.0 as f32, p.1 as f32) };
        let pm = &mut self.frame.pixmap;
        // The trail over the plan (the robot drives along it), with its own halo.
        if layers.trail && scene.trail.len() >= 2 {
            let pts = draw::decimate(scene.trail.iter().map(|&(x, y)| to_f32(px(x, y))));
            let pts = draw::simplify(&pts, SIMPLIFY);
            draw::polyline(pm, &pts, 3.0 * u, style::HALO);
            draw::polyline(pm, &pts, 1.75 * u, style::TRAIL);
        }
        // The ghost's trail, dashed by its own colour, under the robot's.
        if let Some(g) = scene.ghost.filter(|g| layers.trail && g.trail.len() >= 2) {
            let pts = draw::decimate(g.trail.iter().map(|&(x, y)| to_f32(px(x, y))));
            let pts = draw::simplify(&pts, SIMPLIFY);
            draw::polyline(pm, &pts, 3.0 * u, style::HALO);
            draw::polyline(pm, &pts, 1.75 * u, style::GHOST);
        }
        let arrow = 18.0 * uf;
        if layers.start_goal {
            for (pose, c) in [(scene.start, style::START), (scene.goal, style::GOAL)] {
                if let Some(p) = pose {
                    let d = draw::heading(p.theta);
                    draw::pose_arrow(pm, px(p.x, p.y), d, arrow, u, c);
                }
            }
        }
        if let Some(p) = scene.local_target.filter(|_| layers.local_target) {
            panel::target_marker(pm, px(p.x, p.y), draw::heading(p.theta), u);
        }
        if let Some(g) = scene.ghost.filter(|_| layers.robot) {
            let s = view.pixels_per_metre();
            let body = (g.robot.body_radius * s).max(5.0 * uf);
            let c = px(g.robot.pose.x, g.robot.pose.y);
            let d = draw::heading(g.robot.pose.theta);
            draw::disc(pm, to_f32(c), body as f32, style::GHOST.with_alpha(70));
            let tip = (c.0 + d.0 * body, c.1 + d.1 * body);
            draw::polyline(pm, &[to_f32(c), to_f32(tip)], 2.5 * u, style::GHOST);
        }
        if let Some(r) = scene.robot.filter(|_| layers.robot) {
            let s = view.pixels_per_metre();
            // A radius of at least 5 units, so a robot on a huge map stays visible.
            let body = (r.body_radius * s).max(5.0 * uf);
            let f = if r.body_radius > 0.0 {
                body / (r.body_radius * s)
            } else {
                1.0
            };
            draw::robot(
                pm,
                px(r.pose.x, r.pose.y),
                draw::heading(r.pose.theta),
                body,
                r.axle_length * s * f,
                r.wheel_radius * s * f,
                r.bumped,
                scene.direction == Direction::Backward,
                u,
            );
        }
    }

    /// Restores the panel (overlays may reach into it) and writes the direction and caption.
    fn draw_panel_text(&mut self, scene: &Scene<'_>) {
        let Some(p) = self.layout.panel else { return };
        let width = self.layout.width as usize;
        let (x0, x1) = (p.x as usize * 4, (p.x + p.w) as usize * 4);
        let src = self.background.data();
        let dst = self.frame.pixmap.data_mut();
        for y in p.y as usize..(p.y + p.h) as usize {
            let row = y * width * 4;
            dst[row + x0..row + x1].copy_from_slice(&src[row + x0..row + x1]);
        }
        if !scene.layers.caption {
            return;
        }
        if let Some(area) = self.text_area {
            let direction = match scene.direction {
                Direction::Forward => "drive: forward",
                Direction::Backward => "drive: backward",
            };
            panel::draw_dynamic(
                &mut self.frame.pixmap,
                &self.layout,
                area,
                direction,
                scene.caption,
            );
        }
    }
}
