//! ROS `map_server` maps: a YAML file and an image (PGM or PNG), read as map_server reads
//! them (spec §2, §5 "MapBuilder"; the rule is spec §2 "Map formats").
//!
//! The YAML keys (all required except `mode`, as in map_server; other keys are ignored, as
//! map_server ignores them):
//!
//! | key | meaning |
//! | --- | --- |
//! | `image` | the image file, relative to the YAML file (only [`load_file`] reads it) |
//! | `resolution` | metres per pixel → `GridSize`; with `origin` and the image's size, within the map's limits ([`GridMap::check_geometry`]) |
//! | `origin` | `[x, y, yaw]`: the pose of the lower-left pixel → the map origin (yaw is kept in [`RosMapYaml::origin`] but a `GridMap` is axis-aligned, so it is not applied — as "many parts of the system" in ROS ignore it) |
//! | `negate` | `0`/`1` (or `false`/`true`): swap the meaning of black and white |
//! | `occupied_thresh`, `free_thresh` | thresholds on the occupancy probability `p` |
//! | `mode` | `trinary` (default) or `scale`; `raw` is refused (its values are not occupancy) |
//!
//! Per pixel, with `v` the mean of its channels (in trinary mode the alpha channel is part
//! of the mean, as map_server does) and `max` the largest sample value (255 for 8-bit):
//! `p = (max − v) / max`, or `p = v / max` when `negate` is set. Then `p ≥ occupied_thresh`
//! → **occupied**, `p ≤ free_thresh` → **free**, anything else → **unknown**. In `scale`
//! mode, a pixel that is not fully opaque is unknown, and the in-between probabilities
//! (which map_server scales to 1–99) are unknown too: a `GridMap` cell is free or obstacle.
//!
//! (map_server's C++ compares with `>` and `<`; the data README states `≥` and `≤`, which is
//! what is implemented. The two differ only for a `p` exactly equal to a threshold, which no
//! 8-bit grey value reaches with the usual thresholds 0.65 / 0.196 / 0.25.)
//!
//! Occupied cells become obstacles, free cells free, and unknown cells obstacles by default
//! ([`UnknownCells`]; a robot should not plan through what it has not seen). Image row 0 is
//! the top of the map: pixel `(column, row)` is the `GridMap` cell
//! `(column, height − 1 − row)`.

use std::io::Cursor;

use image::ImageDecoder;
use image::codecs::png::PngDecoder;
use image::codecs::pnm::{PnmDecoder, PnmHeader, PnmSubtype, SampleEncoding};

use super::yaml_mapping::{Mapping, Problem};
use crate::errors::MapError;
use crate::map::GridMap;

const YAML: &str = "ROS map YAML";

/// The largest map_server YAML file read \[bytes\]: the file is a handful of lines, and the
/// YAML parser keeps state for every collection left open, about 90 bytes per byte of input
/// at worst (found by the fuzzer), so a larger file is refused before it is
/// parsed.
pub const MAX_YAML_BYTES: usize = 64 * 1024;
const IMAGE: &str = "ROS map image";

/// The YAML's keys, read (their values checked by [`parse_yaml`]).
struct RawYaml {
    image: String,
    resolution: f64,
    origin: Vec<f64>,
    negate: bool,
    occupied_thresh: f64,
    free_thresh: f64,
    mode: Option<String>,
}

fn yaml_err(reason: impl Into<String>) -> MapError {
    MapError::Format {
        format: YAML,
        line: None,
        reason: reason.into(),
    }
}

fn image_err(reason: impl Into<String>) -> MapError {
    MapError::Format {
        format: IMAGE,
        line: None,
        reason: reason.into(),
    }
}

/// What unknown cells become in the `GridMap`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum UnknownCells {
    /// Obstacle (the default): never plan through unexplored space.
    #[default]
    Obstacle,
    /// Free.
    Free,
}

/// Options of [`load`].
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct RosLoadOptions {
    /// What unknown cells become.
    pub unknown: UnknownCells,
}

/// map_server's `mode`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum RosMapMode {
    /// Free, occupied or unknown by the thresholds (the default).
    #[default]
    Trinary,
    /// As trinary, but transparent pixels are unknown and the alpha channel is not averaged.
    Scale,
}

/// The YAML file, checked.
#[derive(Debug, Clone, PartialEq)]
pub struct RosMapYaml {
    /// The image file name as written (relative to the YAML file unless absolute).
    pub image: String,
    /// Metres per pixel.
    pub resolution: f64,
    /// `[x, y, yaw]` of the lower-left pixel (metres, radians).
    pub origin: [f64; 3],
    /// Whether black and white are swapped.
    pub negate: bool,
    /// `p` at or above which a pixel is occupied.
    pub occupied_thresh: f64,
    /// `p` at or below which a pixel is free.
    pub free_thresh: f64,
    /// The mode.
    pub mode: RosMapMode,
}

/// A loaded ROS map: the grid and how its pixels were classified.
#[derive(Debug, Clone, PartialEq)]
pub struct RosMap {
    /// The grid: size of the image, `GridSize` = `resolution`, origin = `origin[0..2]`.
    pub map: GridMap,
    /// The YAML it was loaded with.
    pub yaml: RosMapYaml,
    /// Pixels classified free.
    pub free: usize,
    /// Pixels classified occupied.
    pub occupied: usize,
    /// Pixels classified unknown (they are obstacles or free cells in `map`, by the options).
    pub unknown: usize,
}

/// Reads and checks a map_server YAML file.
pub fn parse_yaml(text: &str) -> Result<RosMapYaml, MapError> {
    let yaml = |p: Problem| MapError::Format {
        format: YAML,
        line: p.line,
        reason: p.reason,
    };
    let text = crate::rtc::without_bom(text);
    if text.len() > MAX_YAML_BYTES {
        return Err(yaml_err(format!(
            "the file has {} bytes; a map's YAML is a few lines (at most {MAX_YAML_BYTES} bytes)",
            text.len()
        )));
    }
    let m = Mapping::parse(text).map_err(yaml)?;
    let negate = match m.required_text("negate").map_err(yaml)?.trim() {
        "true" | "True" | "TRUE" => true,
        "false" | "False" | "FALSE" => false,
        // map_server reads an integer: non-zero is true.
        other => match other.parse::<i64>() {
            Ok(v) => v != 0,
            Err(_) => return Err(yaml(m.wrong("negate", "0, 1, true or false", other))),
        },
    };
    let raw = RawYaml {
        image: m.required_text("image").map_err(yaml)?.to_owned(),
        resolution: m.number("resolution").map_err(yaml)?,
        origin: m.numbers("origin").map_err(yaml)?,
        negate,
        occupied_thresh: m.number("occupied_thresh").map_err(yaml)?,
        free_thresh: m.number("free_thresh").map_err(yaml)?,
        mode: m.text("mode").map_err(yaml)?.map(str::to_owned),
    };
    if raw.image.trim().is_empty() {
        return Err(yaml_err("`image` is empty"));
    }
    let origin: [f64; 3] = raw.origin.as_slice().try_into().map_err(|_| {
        yaml_err(format!(
            "`origin` must have 3 elements [x, y, yaw], not {}",
            raw.origin.len()
        ))
    })?;
    // The map's geometry rule, on the smallest map: the image's size is not known yet
    // (`load_image` checks again with it).
    GridMap::check_geometry(1, 1, raw.resolution, (origin[0], origin[1]))?;
    if !origin[2].is_finite() {
        return Err(yaml_err(format!(
            "`origin` yaw {} must be finite",
            origin[2]
        )));
    }
    for (name, v) in [
        ("occupied_thresh", raw.occupied_thresh),
        ("free_thresh", raw.free_thresh),
    ] {
        if !(0.0..=1.0).contains(&v) {
            return Err(yaml_err(format!("`{name}` {v} must lie in [0, 1]")));
        }
    }
    if raw.free_thresh >= raw.occupied_thresh {
        return Err(yaml_err(format!(
            "`free_thresh` {} must be below `occupied_thresh` {}",
            raw.free_thresh, raw.occupied_thresh
        )));
    }
    let mode = match raw.mode.as_deref().map(str::trim) {
        None | Some("trinary") => RosMapMode::Trinary,
        Some("scale") => RosMapMode::Scale,
        Some("raw") => {
            return Err(yaml_err(
                "`mode: raw` is not supported: its values are not free/occupied",
            ));
        }
        Some(other) => {
            return Err(yaml_err(format!(
                "`mode` `{}` is not one of trinary, scale",
                super::shown(other)
            )));
        }
    };
    Ok(RosMapYaml {
        image: raw.image,
        resolution: raw.resolution,
        origin,
        negate: raw.negate,
        occupied_thresh: raw.occupied_thresh,
        free_thresh: raw.free_thresh,
        mode,
    })
}

/// Loads a map from the YAML text and the bytes of the image it names (PGM or PNG, detected
/// from the bytes).
pub fn load(
    yaml_text: &str,
    image_bytes: &[u8],
    options: &RosLoadOptions,
) -> Result<RosMap, MapError> {
    let yaml = parse_yaml(yaml_text)?;
    load_image(yaml, image_bytes, options)
}

/// Loads the image of an already parsed YAML.
pub fn load_image(
    yaml: RosMapYaml,
    image_bytes: &[u8],
    options: &RosLoadOptions,
) -> Result<RosMap, MapError> {
    let file = &yaml.image;
    let kind = match image::guess_format(image_bytes) {
        Ok(image::ImageFormat::Pnm) => Kind::Pnm,
        Ok(image::ImageFormat::Png) => Kind::Png,
        _ => {
            return Err(image_err(format!(
                "`{file}` is neither a PGM nor a PNG image"
            )));
        }
    };
    let bad = |e: image::ImageError| image_err(undecodable(kind, file, image_bytes, &e));
    let geometry = |w: usize, h: usize| {
        GridMap::check_geometry(w, h, yaml.resolution, (yaml.origin[0], yaml.origin[1]))
    };
    // The format's own decoder, samples as stored (a PNG's palette, low bit depths and
    // transparency expanded to 8-bit samples, 16-bit ones kept): no conversion of the pixels.
    let image = match kind {
        Kind::Png => decode(
            PngDecoder::new(Cursor::new(image_bytes)).map_err(bad)?,
            None,
            geometry,
        ),
        // A PNM image is not compressed: it needs at least one bit a pixel (P4's packing), so
        // a header that claims more pixels than the file can hold is refused before anything
        // is allocated for them.
        Kind::Pnm => decode(
            PnmDecoder::new(image_bytes).map_err(bad)?,
            Some(8 * image_bytes.len() as u64),
            geometry,
        ),
    };
    let Decoded {
        width,
        height,
        colour,
        samples,
    } = image?.map_err(bad)?;
    let rule = Rule {
        negate: yaml.negate,
        occupied: yaml.occupied_thresh,
        free: yaml.free_thresh,
        mode: yaml.mode,
    };
    let wide = || -> Vec<u16> {
        samples
            .chunks_exact(2)
            .map(|b| u16::from_ne_bytes([b[0], b[1]]))
            .collect()
    };
    use image::ColorType as C;
    let classes = match colour {
        C::L8 => rule.classify(&samples, 1, false, 255.0),
        C::La8 => rule.classify(&samples, 2, true, 255.0),
        C::Rgb8 => rule.classify(&samples, 3, false, 255.0),
        C::Rgba8 => rule.classify(&samples, 4, true, 255.0),
        C::L16 => rule.classify(&wide(), 1, false, 65535.0),
        C::La16 => rule.classify(&wide(), 2, true, 65535.0),
        C::Rgb16 => rule.classify(&wide(), 3, false, 65535.0),
        C::Rgba16 => rule.classify(&wide(), 4, true, 65535.0),
        other => {
            return Err(image_err(format!(
                "the {} image `{file}`'s samples ({other:?}) are not 8 or 16-bit integers",
                kind.name()
            )));
        }
    };
    let (mut free, mut occupied, mut unknown) = (0, 0, 0);
    let unknown_value = match options.unknown {
        UnknownCells::Obstacle => 1,
        UnknownCells::Free => 0,
    };
    let mut grid = vec![0u8; width * height];
    for (row, pixels) in classes.chunks_exact(width).enumerate() {
        let y = height - 1 - row;
        for (x, &class) in pixels.iter().enumerate() {
            grid[x + y * width] = match class {
                Class::Free => {
                    free += 1;
                    0
                }
                Class::Occupied => {
                    occupied += 1;
                    1
                }
                Class::Unknown => {
                    unknown += 1;
                    unknown_value
                }
            };
        }
    }
    let map = GridMap::new(
        width,
        height,
        yaml.resolution,
        (yaml.origin[0], yaml.origin[1]),
        grid,
    )?;
    Ok(RosMap {
        map,
        yaml,
        free,
        occupied,
        unknown,
    })
}

/// A decoded image: its size, its colour type and its samples (interleaved; 16-bit samples in
/// native byte order).
struct Decoded {
    width: usize,
    height: usize,
    colour: image::ColorType,
    samples: Vec<u8>,
}

/// The two image formats read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Pnm,
    Png,
}

impl Kind {
    fn name(self) -> &'static str {
        match self {
            Kind::Pnm => "PGM/PNM",
            Kind::Png => "PNG",
        }
    }
}

/// Why the decoder refused `file`, in words: a file that ends before its pixel data does is
/// *truncated* (for a PGM/PNM, with what its header asks for and what there is); anything
/// else is the decoder's own reason.
fn undecodable(kind: Kind, file: &str, bytes: &[u8], e: &image::ImageError) -> String {
    let truncated = |detail: String| format!("`{file}` is truncated: {detail}");
    if kind == Kind::Pnm
        && let Ok(d) = PnmDecoder::new(bytes)
    {
        let (rest, header) = d.into_inner();
        let (expected, found, what) = pnm_pixel_data(&header, rest);
        if found < expected {
            return truncated(format!(
                "its header gives {}×{} pixels, {expected} {what}, but the file holds {found}",
                header.width(),
                header.height(),
            ));
        }
    }
    if ends_early(e) {
        return truncated("the file ends before the image does".to_owned());
    }
    format!("cannot decode the {} image `{file}`: {e}", kind.name())
}

/// What a PNM header asks for after it and what `rest` (the file after the header) holds:
/// `(expected, found, what is counted)`. A binary form counts bytes of pixel data (P4 packs
/// 8 pixels a byte, row by row; the others take one byte a sample, two when the largest
/// sample value exceeds 255); an ASCII form counts samples (P1 a `0` or `1` each, P2 and
/// P3 a number each).
fn pnm_pixel_data(header: &PnmHeader, rest: &[u8]) -> (u64, u64, &'static str) {
    let pixels = u64::from(header.width()) * u64::from(header.height());
    let held = rest.len() as u64;
    let sample_bytes = if header.maximal_sample() > 255 { 2 } else { 1 };
    let bytes = |samples: u64| {
        let expected = pixels.saturating_mul(samples).saturating_mul(sample_bytes);
        (expected, held, "bytes of pixel data")
    };
    let numbers = || {
        rest.split(|b| !b.is_ascii_digit())
            .filter(|run| !run.is_empty())
            .count() as u64
    };
    match header.subtype() {
        PnmSubtype::Bitmap(SampleEncoding::Binary) => (
            u64::from(header.width()).div_ceil(8) * u64::from(header.height()),
            held,
            "bytes of pixel data",
        ),
        PnmSubtype::Graymap(SampleEncoding::Binary) => bytes(1),
        PnmSubtype::Pixmap(SampleEncoding::Binary) => bytes(3),
        PnmSubtype::ArbitraryMap => bytes(header.as_arbitrary().map_or(1, |a| u64::from(a.depth))),
        PnmSubtype::Bitmap(SampleEncoding::Ascii) => {
            let digits = rest.iter().filter(|b| matches!(b, b'0' | b'1')).count() as u64;
            (pixels, digits, "samples")
        }
        PnmSubtype::Graymap(SampleEncoding::Ascii) => (pixels, numbers(), "samples"),
        PnmSubtype::Pixmap(SampleEncoding::Ascii) => (pixels * 3, numbers(), "samples"),
    }
}

/// Whether the decoder stopped because the data ran out.
fn ends_early(e: &image::ImageError) -> bool {
    matches!(e, image::ImageError::IoError(io) if io.kind() == std::io::ErrorKind::UnexpectedEof)
}

/// Decodes the image once its size, read from its header, is known to be a map's (not
/// empty, at most [`MAX_CELLS`](crate::map::MAX_CELLS): [`GridMap::check_size`], spec §2
/// Decision 0.2; its geometry accepted by `geometry`, [`GridMap::check_geometry`]) and, for
/// an image that is not compressed, at most `most_pixels`; the outer error is the map's,
/// the inner one the decoder's. Nothing is allocated for the pixels before these checks.
fn decode(
    d: impl ImageDecoder,
    most_pixels: Option<u64>,
    geometry: impl FnOnce(usize, usize) -> Result<(), MapError>,
) -> Result<image::ImageResult<Decoded>, MapError> {
    let (w, h) = d.dimensions();
    let (width, height) = (w as usize, h as usize);
    if width == 0 || height == 0 {
        return Err(image_err(format!(
            "image of {width}×{height} pixels is empty"
        )));
    }
    GridMap::check_size(u64::from(w), u64::from(h))?;
    geometry(width, height)?;
    if let Some(most) = most_pixels
        && u64::from(w) * u64::from(h) > most
    {
        return Err(image_err(format!(
            "the PGM/PNM header claims {w}×{h} pixels, but the file has only {} bytes",
            most / 8
        )));
    }
    let colour = d.color_type();
    let mut samples = vec![0; d.total_bytes() as usize];
    Ok(d.read_image(&mut samples).map(|()| Decoded {
        width,
        height,
        colour,
        samples,
    }))
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Class {
    Free,
    Occupied,
    Unknown,
}

struct Rule {
    negate: bool,
    occupied: f64,
    free: f64,
    mode: RosMapMode,
}

impl Rule {
    /// Classifies interleaved samples (`channels` per pixel, the last one alpha if
    /// `has_alpha`).
    fn classify<T: Copy + Into<f64>>(
        &self,
        samples: &[T],
        channels: usize,
        has_alpha: bool,
        max: f64,
    ) -> Vec<Class> {
        let averaged = if has_alpha && self.mode == RosMapMode::Scale {
            channels - 1
        } else {
            channels
        };
        samples
            .chunks_exact(channels)
            .map(|px| {
                if has_alpha && self.mode == RosMapMode::Scale && px[channels - 1].into() < max {
                    return Class::Unknown;
                }
                let sum: f64 = px[..averaged].iter().map(|&s| s.into()).sum();
                let v = sum / averaged as f64;
                let p = if self.negate {
                    v / max
                } else {
                    (max - v) / max
                };
                if p >= self.occupied {
                    Class::Occupied
                } else if p <= self.free {
                    Class::Free
                } else {
                    Class::Unknown
                }
            })
            .collect()
    }
}

/// Loads a map from its YAML file; the image is read relative to the YAML file's folder
/// unless its name is absolute (native only).
#[cfg(not(target_arch = "wasm32"))]
pub fn load_file(
    yaml_path: impl AsRef<std::path::Path>,
    options: &RosLoadOptions,
) -> Result<RosMap, MapError> {
    let yaml_path = yaml_path.as_ref();
    let text = String::from_utf8(super::read_file(yaml_path)?)
        .map_err(|e| yaml_err(format!("not UTF-8: {e}")))?;
    let yaml = parse_yaml(&text)?;
    let image_path = yaml_path
        .parent()
        .unwrap_or_else(|| std::path::Path::new("."))
        .join(&yaml.image);
    let bytes = super::read_file(&image_path)?;
    load_image(yaml, &bytes, options)
}
