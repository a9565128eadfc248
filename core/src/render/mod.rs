//! The renderer: one tiny-skia drawing of the system for PNGs and the browser canvas
//! (spec §5 InventGUI).
//!
//! A [`Scene`] borrows plain data — the [`GridMap`](crate::map::GridMap), `dmin`, an optional
//! potential field ([`FieldView`]), paths as cells, control points, the local target, the
//! robot ([`RobotView`]), its trail, start and goal, the direction and a caption — and
//! [`Layers`] says what to show. A [`Renderer`] draws it into its [`Frame`]: opaque RGBA for a
//! browser `ImageData`, or a PNG via [`Frame::encode_png`]. [`ViewTransform`] maps world
//! points to frame pixels and back (clicks).
//!
//! Layers, bottom to top: occupancy, `dmin` zone, heat map (log scale, viridis) — cached —
//! then global path, local path, trail, control points, start/goal arrows, local target,
//! robot; the side panel holds the colour bar, legend, scale bar, direction and caption.
//!
//! **Architecture Invariant**: `render` knows only `map` and `interfaces`: no planner,
//! motion or system type. **Determinism** (spec §6): angles through `libm`, no `sin`/`cos`
//! inside tiny-skia (no rotation transforms, no cubics), tiny-skia built without its `simd`
//! feature so native and wasm32 run the same scalar code: a scene gives the same bytes on
//! both.

mod error;
pub use error::RenderError;

mod colour;
mod draw;
mod font;
mod frame;
mod of_system;
mod panel;
mod raster;
mod renderer;
mod scene;
mod screen;
mod style;
mod view;

pub use frame::Frame;
pub use of_system::{FieldBuffers, caption, ghost_of, scene_of};
pub use renderer::Renderer;
pub use scene::{FieldCellState, FieldView, Ghost, Layers, RobotView, Scene};
pub use screen::{PAGE_LAYERS, Screen};
pub use view::{Camera, MAX_FRAME_SIDE, MAX_ZOOM, ViewTransform};
