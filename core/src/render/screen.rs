//! [`Screen`]: a user interface's picture of a [`Session`] — the renderer, the layers shown
//! and whether anything may have changed since the last frame — and of a [`Comparison`].
//! Every call takes the session it shows; the screen knows nothing else of the system.

use super::frame::Frame;
use super::of_system::caption;
use super::renderer::Renderer;
use super::scene::Layers;
use super::view::ViewTransform;
use crate::errors::RenderError;
use crate::map::Cell;
use crate::system::{Comparison, Session};

/// The layers a page draws: everything on the map; the legend, scale bar and caption are
/// the page's own (the renderer has no side panel here).
pub const PAGE_LAYERS: Layers = Layers {
    scale_bar: false,
    legend: false,
    caption: false,
    ..Layers::ALL
};

/// The renderer of a page, its layers, and whether the next frame must be drawn.
#[derive(Debug)]
pub struct Screen {
    renderer: Renderer,
    layers: Layers,
    /// Whether something may have changed since the last frame.
    stale: bool,
}

impl Screen {
    /// A `width × height` screen without a side panel, showing [`PAGE_LAYERS`].
    pub fn new(width: u32, height: u32) -> Result<Self, RenderError> {
        let mut renderer = Renderer::new(width, height)?;
        renderer.set_side_panel(false);
        Ok(Self {
            renderer,
            layers: PAGE_LAYERS,
            stale: true,
        })
    }

    /// Something may have changed: the next [`Screen::draw`] draws.
    pub fn changed(&mut self) {
        self.stale = true;
    }

    /// The session's map was replaced: forget the caches and show the whole map.
    pub fn replaced(&mut self, session: &Session) {
        self.renderer.invalidate();
        if let Some(map) = session.map() {
            self.renderer.set_camera(map, None);
        }
        self.stale = true;
    }

    /// Draws `session` if anything changed since the last frame. Returns whether it drew
    /// (false: the frame is the same, or no map yet).
    pub fn draw(&mut self, session: &Session) -> Result<bool, RenderError> {
        if !self.stale || session.map().is_none() {
            return Ok(false);
        }
        let system = session.system();
        self.renderer
            .render_system(system, &caption(system), self.layers)?;
        self.stale = false;
        Ok(true)
    }

    /// Whether the next [`Screen::draw`] is cheap: nothing to draw, or only the moving parts
    /// over the layers kept ([`Renderer::draws_from_cache`]).
    pub fn draws_from_cache(&self, session: &Session) -> bool {
        !self.stale
            || self
                .renderer
                .draws_from_cache(session.system(), self.layers)
    }

    /// Changes the frame size (pixels).
    pub fn resize(&mut self, width: u32, height: u32) -> Result<(), RenderError> {
        self.renderer.resize(width, height)?;
        self.stale = true;
        Ok(())
    }

    /// The layers shown.
    pub fn layers(&self) -> Layers {
        self.layers
    }

    /// Shows or hides the layer `name`; an unknown name is refused.
    pub fn set_layer(&mut self, name: &str, on: bool) -> Result<(), RenderError> {
        self.layers.set(name, on)?;
        self.stale = true;
        Ok(())
    }

    /// The frame drawn last.
    pub fn frame(&self) -> &Frame {
        self.renderer.frame()
    }

    /// The frame's width in pixels.
    pub fn width(&self) -> u32 {
        self.renderer.width()
    }

    /// The frame's height in pixels.
    pub fn height(&self) -> u32 {
        self.renderer.height()
    }

    /// Where the frame's pixels show the world, without a map `None`.
    pub fn view(&self, session: &Session) -> Option<ViewTransform> {
        session.map().map(|m| self.renderer.view(m))
    }

    /// Frame pixel → map cell (`None` outside the map or without one).
    pub fn pixel_to_cell(&self, session: &Session, px: f64, py: f64) -> Option<Cell> {
        let map = session.map()?;
        self.renderer.view(map).pixel_to_cell(map, px, py)
    }

    /// Zooms by `factor` about the frame pixel `(px, py)` (back to the whole map at 1×).
    pub fn zoom_at(&mut self, session: &Session, px: f64, py: f64, factor: f64) {
        if let Some(map) = session.map() {
            self.renderer.zoom_at(map, px, py, factor);
            self.stale = true;
        }
    }

    /// Drags the picture by `(dx, dy)` frame pixels (while zoomed in).
    pub fn pan_by(&mut self, session: &Session, dx: f64, dy: f64) {
        if let Some(map) = session.map() {
            self.renderer.pan_by(map, dx, dy);
            self.stale = true;
        }
    }

    /// The whole map, fitted.
    pub fn fit(&mut self, session: &Session) {
        if let Some(map) = session.map() {
            self.renderer.set_camera(map, None);
            self.stale = true;
        }
    }

    /// The magnification of the whole-map view (1 when it is fitted).
    pub fn zoom(&self) -> f64 {
        self.renderer.camera().map_or(1.0, |c| c.zoom)
    }

    /// The heat map's colour scale `(lo, hi, clipped)`, if one is drawn.
    pub fn heat_range(&self) -> Option<(f64, f64, bool)> {
        self.renderer.heat_range()
    }

    /// Draws both runs of `comparison` at their end, B as the ghost, with [`PAGE_LAYERS`].
    pub fn draw_compare(&mut self, comparison: &Comparison) -> Result<(), RenderError> {
        let a = comparison.system_a();
        self.renderer
            .render_compare(a, comparison.system_b(), &caption(a), PAGE_LAYERS)
            .map(drop)
    }
}
