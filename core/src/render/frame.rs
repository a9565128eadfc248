//! The rendered frame: opaque RGBA pixels, and their PNG encoding for the runner.

use tiny_skia::Pixmap;

use crate::errors::RenderError;

/// One rendered frame: `width × height` RGBA8 pixels, rows top to bottom, every alpha 255.
/// tiny-skia stores premultiplied colour; since every pixel is opaque, the bytes are also
/// straight RGBA, ready for a browser `ImageData` without conversion.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    pub(crate) pixmap: Pixmap,
}

impl Frame {
    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.pixmap.width()
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.pixmap.height()
    }

    /// The pixels: `4 · width · height` bytes, RGBA, row-major from the top-left corner.
    pub fn data(&self) -> &[u8] {
        self.pixmap.data()
    }

    /// The pixel at `(x, y)` as `[r, g, b, a]`, if inside the frame.
    pub fn pixel(&self, x: u32, y: u32) -> Option<[u8; 4]> {
        if x >= self.width() || y >= self.height() {
            return None;
        }
        let i = (y as usize * self.width() as usize + x as usize) * 4;
        let d = self.data();
        Some([d[i], d[i + 1], d[i + 2], d[i + 3]])
    }

    /// The frame as a PNG file (8-bit RGB: the frame is opaque, so nothing is lost).
    pub fn encode_png(&self) -> Result<Vec<u8>, RenderError> {
        let rgb: Vec<u8> = self
            .data()
            .chunks_exact(4)
            .flat_map(|p| [p[0], p[1], p[2]])
            .collect();
        let mut out = Vec::new();
        let mut encoder = png::Encoder::new(&mut out, self.width(), self.height());
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        let png_error = |e: png::EncodingError| RenderError::Png {
            reason: e.to_string(),
        };
        let mut writer = encoder.write_header().map_err(png_error)?;
        writer.write_image_data(&rgb).map_err(png_error)?;
        writer.finish().map_err(png_error)?;
        Ok(out)
    }
}
