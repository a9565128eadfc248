//! Errors of the renderer.

/// Errors of the renderer (spec §5 InventGUI): a frame size or a scene it cannot draw. Drawing
/// itself never fails for a valid scene.
#[derive(Debug, Clone, PartialEq, thiserror::Error, serde::Serialize, strum::VariantNames)]
#[serde(tag = "kind")]
#[non_exhaustive]
pub enum RenderError {
    /// A frame with no pixels, or larger than the renderer accepts.
    #[error("frame size {width}×{height} is not drawable: each side must be 1..={max}")]
    FrameSize {
        /// Width asked for, pixels.
        width: u32,
        /// Height asked for, pixels.
        height: u32,
        /// The largest side accepted.
        max: u32,
    },
    /// A number in the scene that is not usable (NaN, infinite, negative, …).
    #[error("scene {what}{}: {value} must be {expected}", at_index(*index))]
    BadNumber {
        /// Which value, e.g. `robot.pose.theta`.
        what: &'static str,
        /// Index in its list, if it is in one.
        index: Option<usize>,
        /// The value given.
        value: f64,
        /// What it must be, e.g. `finite and ≥ 0`.
        expected: &'static str,
    },
    /// A per-cell array whose length is not the map's cell count.
    #[error("scene {what} has {len} entries, but the map has {expected} cells")]
    FieldLength {
        /// `field.potential` or `field.state`.
        what: &'static str,
        /// Its length.
        len: usize,
        /// width × height of the map.
        expected: usize,
    },
    /// A path cell outside the map.
    #[error("scene {what}[{index}]: cell ({x}, {y}) is outside the {width}×{height} map")]
    CellOutside {
        /// `global_path` or `local_path`.
        what: &'static str,
        /// Index in the path.
        index: usize,
        /// x index.
        x: usize,
        /// y index.
        y: usize,
        /// Map width.
        width: usize,
        /// Map height.
        height: usize,
    },
    /// The PNG encoder failed.
    #[error("PNG encoding failed: {reason}")]
    Png {
        /// The encoder's message.
        reason: String,
    },
    /// A system to draw before a map is loaded.
    #[error("nothing to draw: no map is loaded")]
    NoMap,
    /// A layer name the renderer does not have.
    #[error("no layer named `{name}` (layers: {known})")]
    UnknownLayer {
        /// The name asked for.
        name: String,
        /// The layers there are, comma-separated.
        known: String,
    },
}

fn at_index(index: Option<usize>) -> String {
    index.map(|i| format!("[{i}]")).unwrap_or_default()
}
