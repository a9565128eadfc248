//! [`Rgba`]: the colour every drawing module of the renderer uses.

/// An sRGB colour with straight alpha (255 = opaque).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Rgba {
    pub r: u8,
    pub g: u8,
    pub b: u8,
    pub a: u8,
}

impl Rgba {
    /// An opaque colour.
    pub const fn rgb(r: u8, g: u8, b: u8) -> Self {
        Self { r, g, b, a: 255 }
    }

    /// The same colour with alpha `a`.
    pub const fn with_alpha(self, a: u8) -> Self {
        Self { a, ..self }
    }

    /// `self` blended towards `other` by `w`/255.
    pub fn mix(self, other: Self, w: u32) -> Self {
        let m = |a: u8, b: u8| ((u32::from(a) * (255 - w) + u32::from(b) * w + 127) / 255) as u8;
        Self::rgb(m(self.r, other.r), m(self.g, other.g), m(self.b, other.b))
    }

    /// Scaled by `f`/256 (darker).
    pub(crate) fn shade(self, f: u32) -> Self {
        let s = |c: u8| ((u32::from(c) * f) >> 8) as u8;
        Self::rgb(s(self.r), s(self.g), s(self.b))
    }

    pub(crate) fn pack(self) -> u32 {
        u32::from(self.r) | u32::from(self.g) << 8 | u32::from(self.b) << 16
    }
}
