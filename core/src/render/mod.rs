//! The renderer: one tiny-skia drawing of the system for PNGs and the browser canvas.
