//! The side panel: the heat map's colour bar (log scale, labelled min/max and decades), the
//! legend of the layers shown, the scale bar, and room for the direction and caption text.

use tiny_skia::Pixmap;

use super::colour::Rgba;
use super::draw::{self, Px};
use super::font::{self, ADVANCE, LINE};
use super::raster::{HeatRange, fill_rect};
use super::scene::Layers;
use super::style;
use super::view::{Layout, PixelRect, ViewTransform};

/// What the static panel needs.
pub(crate) struct PanelInput<'a> {
    pub layers: Layers,
    /// Whether the scene has a field (then the colour bar is drawn if the layer is on).
    pub has_field: bool,
    /// The heat map's colour scale, if a cell is reached.
    pub range: Option<HeatRange>,
    pub viridis: &'a [Rgba; 256],
}

/// Where the dynamic text goes: `[top, bottom)` rows of the panel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct TextArea {
    pub top: u32,
    pub bottom: u32,
}

fn text(pixmap: &mut Pixmap, x: u32, y: u32, k: u32, s: &str, c: Rgba) {
    font::draw_text(pixmap, i64::from(x), i64::from(y), k, s, c);
}

/// Draws the static panel into `pixmap`; returns the area left for dynamic text.
pub(crate) fn draw_static(
    pixmap: &mut Pixmap,
    layout: &Layout,
    view: &ViewTransform,
    input: &PanelInput<'_>,
) -> Option<TextArea> {
    let panel = layout.panel?;
    let k = layout.k;
    let u = layout.unit;
    let width = pixmap.width();
    fill_rect(
        pixmap.data_mut(),
        width,
        (panel.x, panel.y, panel.x + panel.w, panel.y + panel.h),
        style::FREE,
    );
    let frame = [
        (panel.x as f32 + 0.5, panel.y as f32 + 0.5),
        ((panel.x + panel.w) as f32 - 0.5, panel.y as f32 + 0.5),
        (
            (panel.x + panel.w) as f32 - 0.5,
            (panel.y + panel.h) as f32 - 0.5,
        ),
        (panel.x as f32 + 0.5, (panel.y + panel.h) as f32 - 0.5),
    ];
    draw::polygon_outline(pixmap, &frame, 1.0, style::BORDER);
    let pad = 3 * k;
    let x = panel.x + pad;
    let inner_w = panel.w - 2 * pad;
    let mut y = panel.y + pad;
    let bottom = panel.y + panel.h - pad;

    if input.layers.heat_map && input.has_field {
        y = colour_bar(pixmap, layout, panel, x, y, input);
        y += LINE * k;
    }
    if input.layers.legend {
        y = legend(pixmap, k, u, x, y, bottom, input.layers);
        y += LINE * k / 2;
    }
    let mut text_bottom = bottom;
    if input.layers.scale_bar {
        text_bottom = scale_bar(pixmap, k, u, x, inner_w, bottom, view);
    }
    (y < text_bottom).then_some(TextArea {
        top: y,
        bottom: text_bottom,
    })
}

fn colour_bar(
    pixmap: &mut Pixmap,
    layout: &Layout,
    panel: PixelRect,
    x: u32,
    mut y: u32,
    input: &PanelInput<'_>,
) -> u32 {
    let k = layout.k;
    text(pixmap, x, y, k, "potential (log)", style::TEXT);
    y += LINE * k + k;
    let Some(HeatRange { lo, hi, clipped }) = input.range else {
        text(pixmap, x, y, k, "no cell reached", style::TEXT_DIM);
        return y + LINE * k;
    };
    let bar_w = 7 * k;
    let bar_h = (panel.h / 3).max(8 * LINE * k / 2).min(panel.h / 2);
    let width = pixmap.width();
    let data = pixmap.data_mut();
    for row in 0..bar_h {
        // Top = max (index 255), bottom = min (index 0).
        let index = ((bar_h - 1 - row) * 255 + (bar_h - 1) / 2) / (bar_h - 1).max(1);
        let c = input.viridis[index as usize];
        fill_rect(data, width, (x, y + row, x + bar_w, y + row + 1), c);
    }
    let frame = [
        (x as f32 - 0.5, y as f32 - 0.5),
        ((x + bar_w) as f32 + 0.5, y as f32 - 0.5),
        ((x + bar_w) as f32 + 0.5, (y + bar_h) as f32 + 0.5),
        (x as f32 - 0.5, (y + bar_h) as f32 + 0.5),
    ];
    draw::polygon_outline(pixmap, &frame, 1.0, style::BORDER);
    let label_x = x + bar_w + 3 * k;
    let glyph_h = font::CAP_H * k;
    // Row of a potential on the bar.
    let (l0, l1) = (libm::log10(lo), libm::log10(hi));
    let row_of = |l: f64| -> f64 {
        if l1 > l0 {
            f64::from(bar_h - 1) * (1.0 - (l - l0) / (l1 - l0))
        } else {
            f64::from(bar_h - 1)
        }
    };
    let tick = |pixmap: &mut Pixmap, row: f64| {
        let py = y as f32 + row as f32 + 0.5;
        draw::polyline(
            pixmap,
            &[((x + bar_w) as f32, py), ((x + bar_w + 2 * k) as f32, py)],
            1.0,
            style::TEXT,
        );
    };
    let max_top = y;
    let min_top = y + bar_h - glyph_h;
    let top_label = if clipped {
        format!(">{}", format_value(hi))
    } else {
        format_value(hi)
    };
    text(pixmap, label_x, max_top, k, &top_label, style::TEXT);
    if hi > lo {
        text(pixmap, label_x, min_top, k, &format_value(lo), style::TEXT);
    }
    tick(pixmap, 0.0);
    tick(pixmap, row_of(l0));
    // Decades between (at most five, every `step`-th), where their labels do not collide
    // with min/max or each other.
    let mut last_top = max_top + LINE * k;
    let first = libm::floor(l1) as i32;
    let last = libm::ceil(l0) as i32;
    let step = ((first - last) / 5 + 1).max(1);
    let mut e = first - first.rem_euclid(step);
    while e >= last && hi > lo {
        let row = row_of(f64::from(e));
        let top = (f64::from(y) + row) as i64 - i64::from(glyph_h / 2);
        if row > 0.5
            && row < f64::from(bar_h) - 1.5
            && top >= i64::from(last_top)
            && top + i64::from(LINE * k) <= i64::from(min_top)
        {
            tick(pixmap, row);
            let label = format_value(libm::pow(10.0, f64::from(e)));
            text(pixmap, label_x, top as u32, k, &label, style::TEXT_DIM);
            last_top = top as u32 + LINE * k;
        }
        e -= step;
    }
    y + bar_h
}

fn legend(pixmap: &mut Pixmap, k: u32, u: f32, x: u32, mut y: u32, bottom: u32, l: Layers) -> u32 {
    let row_h = (LINE * k).max((13.0 * u) as u32);
    let sw = (16 * k).max((24.0 * u) as u32); // swatch width
    let entries: [(bool, &str, u8); 10] = [
        (l.occupancy, "obstacle", 0),
        (l.dmin_zone, "dmin zone", 1),
        (l.global_path, "global path", 2),
        (l.local_path, "local path", 3),
        (l.control_points, "control points", 4),
        (l.local_target, "local target", 5),
        (l.robot, "robot", 6),
        (l.trail, "trail", 7),
        (l.start_goal, "start", 8),
        (l.start_goal, "goal", 9),
    ];
    for (on, label, kind) in entries {
        if !on || y + row_h > bottom {
            continue;
        }
        let cy = f64::from(y) + f64::from(row_h) / 2.0;
        let (x0, x1) = (
            f64::from(x) + f64::from(k),
            f64::from(x + sw) - f64::from(k),
        );
        let mid = ((x0 + x1) / 2.0) as f32;
        let line: [Px; 2] = [(x0 as f32, cy as f32), (x1 as f32, cy as f32)];
        let half = (f64::from(LINE * k) * 0.35) as u32;
        let square = |pixmap: &mut Pixmap, c: Rgba| {
            let (cy, w) = (cy as u32, pixmap.width());
            fill_rect(
                pixmap.data_mut(),
                w,
                (x0 as u32, cy - half, x1 as u32, cy + half),
                c,
            );
        };
        match kind {
            0 => square(pixmap, style::OBSTACLE),
            1 => square(pixmap, style::FREE.mix(style::DMIN, style::DMIN_ALPHA)),
            2 => {
                let band = [
                    (line[0].0 + 5.0 * u, line[0].1),
                    (line[1].0 - 5.0 * u, line[1].1),
                ];
                draw::polyline(pixmap, &band, 10.0 * u, style::GLOBAL_PATH.with_alpha(100));
            }
            3 => {
                draw::polyline(pixmap, &line, 4.0 * u, style::BORDER.with_alpha(90));
                draw::polyline(pixmap, &line, 2.5 * u, style::LOCAL_PATH);
            }
            4 => {
                draw::disc(pixmap, (mid, cy as f32), 3.5 * u, style::CONTROL_LINE);
                draw::disc(pixmap, (mid, cy as f32), 2.3 * u, style::CONTROL_FILL);
            }
            5 => target_marker(
                pixmap,
                (f64::from(mid) - 4.0 * f64::from(u), cy),
                (1.0, 0.0),
                u,
            ),
            6 => {
                let r = f64::from(row_h) * 0.42;
                draw::robot(
                    pixmap,
                    (f64::from(mid), cy),
                    (1.0, 0.0),
                    r,
                    r * 0.98,
                    r * 0.45,
                    false,
                    false,
                    u,
                );
            }
            7 => {
                draw::polyline(pixmap, &line, 3.0 * u, style::HALO);
                draw::polyline(pixmap, &line, 1.75 * u, style::TRAIL);
            }
            8 | 9 => {
                let c = if kind == 8 { style::START } else { style::GOAL };
                draw::pose_arrow(pixmap, (x0 + 2.0, cy), (1.0, 0.0), x1 - x0 - 2.0, u, c);
            }
            _ => {}
        }
        let ty = y + (row_h - font::CAP_H * k) / 2;
        text(pixmap, x + sw + 3 * k, ty, k, label, style::TEXT);
        y += row_h;
    }
    y
}

/// The local target marker: a ring and a short heading tick.
pub(crate) fn target_marker(pixmap: &mut Pixmap, p: (f64, f64), d: (f64, f64), u: f32) {
    let r = 5.0 * u;
    let centre = (p.0 as f32, p.1 as f32);
    let tip = (
        (p.0 + d.0 * f64::from(r * 2.0)) as f32,
        (p.1 + d.1 * f64::from(r * 2.0)) as f32,
    );
    let start = (
        (p.0 + d.0 * f64::from(r)) as f32,
        (p.1 + d.1 * f64::from(r)) as f32,
    );
    draw::ring(pixmap, centre, r, 4.5 * u, style::HALO);
    draw::polyline(pixmap, &[start, tip], 4.5 * u, style::HALO);
    draw::ring(pixmap, centre, r, 2.5 * u, style::TARGET);
    draw::polyline(pixmap, &[start, tip], 2.5 * u, style::TARGET);
    draw::disc(pixmap, centre, 1.5 * u, style::TARGET);
}

/// Draws the scale bar at the bottom of the panel; returns its top row.
fn scale_bar(
    pixmap: &mut Pixmap,
    k: u32,
    u: f32,
    x: u32,
    inner_w: u32,
    bottom: u32,
    view: &ViewTransform,
) -> u32 {
    let s = view.pixels_per_metre();
    let max_px = f64::from(inner_w) * 0.9;
    // The largest 1-2-5 length that fits.
    let mut length = 1e-3;
    for e in -3..=6 {
        for m in [1.0, 2.0, 5.0] {
            let l = m * libm::pow(10.0, f64::from(e));
            if l * s <= max_px {
                length = l;
            }
        }
    }
    let px = (length * s) as f32;
    let bar_y = bottom as f32 - 3.0 * u;
    let x0 = x as f32 + 0.5 * u;
    let label = format!("{} m", format_value(length));
    let label_top = bottom.saturating_sub(LINE * k + (6.0 * u) as u32);
    text(pixmap, x, label_top, k, &label, style::TEXT);
    let ends = (x0, x0 + px);
    draw::polyline(
        pixmap,
        &[(ends.0, bar_y), (ends.1, bar_y)],
        2.0 * u,
        style::TEXT,
    );
    for ex in [ends.0, ends.1] {
        draw::polyline(
            pixmap,
            &[(ex, bar_y - 3.0 * u), (ex, bar_y + 2.0 * u)],
            1.5 * u,
            style::TEXT,
        );
    }
    label_top.saturating_sub(k * 2)
}

/// Draws the direction line and the caption (wrapped) into the text area.
pub(crate) fn draw_dynamic(
    pixmap: &mut Pixmap,
    layout: &Layout,
    area: TextArea,
    direction_line: &str,
    caption: &str,
) {
    let Some(panel) = layout.panel else { return };
    let k = layout.k;
    let x = panel.x + 3 * k;
    let chars = ((panel.w - 6 * k) / (ADVANCE * k)).max(1) as usize;
    let mut y = area.top;
    let mut lines = vec![direction_line.to_string()];
    lines.extend(wrap(caption, chars));
    for line in lines {
        if y + LINE * k > area.bottom {
            break;
        }
        text(pixmap, x, y, k, &line, style::TEXT);
        y += LINE * k;
    }
}

/// Splits `s` into lines of at most `width` characters, at spaces where possible; `\n`
/// starts a new line.
pub(crate) fn wrap(s: &str, width: usize) -> Vec<String> {
    let mut out = Vec::new();
    for paragraph in s.split('\n') {
        let mut line = String::new();
        for word in paragraph.split(' ').filter(|w| !w.is_empty()) {
            let mut word: Vec<char> = word.chars().collect();
            loop {
                let used = line.chars().count();
                let need = if used == 0 { 0 } else { 1 };
                if used + need + word.len() <= width {
                    if need == 1 {
                        line.push(' ');
                    }
                    line.extend(word.iter());
                    break;
                }
                if used > 0 {
                    out.push(std::mem::take(&mut line));
                    continue;
                }
                // A word longer than a line: cut it.
                let rest = word.split_off(width);
                out.push(word.iter().collect());
                word = rest;
            }
        }
        if !line.is_empty() {
            out.push(line);
        }
    }
    out
}

/// A short label for a number: three significant digits, plain for 0.01 ≤ |v| < 10⁴,
/// else `1.23e5`; trailing zeros dropped (`0.1`, `1e4`).
pub(crate) fn format_value(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 {
        return "0".to_string();
    }
    if (0.01..1e4).contains(&a) {
        let decimals = if a >= 100.0 {
            0
        } else if a >= 10.0 {
            1
        } else if a >= 1.0 {
            2
        } else if a >= 0.1 {
            3
        } else {
            4
        };
        trim(format!("{v:.decimals$}"))
    } else {
        let s = format!("{v:.2e}");
        match s.split_once('e') {
            Some((mantissa, exponent)) => format!("{}e{exponent}", trim(mantissa.to_string())),
            None => s,
        }
    }
}

fn trim(s: String) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_get_three_significant_digits() {
        let cases = [
            (0.0, "0"),
            (0.1, "0.1"),
            (0.132, "0.132"),
            (0.0421, "0.0421"),
            (1.0, "1"),
            (2.5, "2.5"),
            (12.06, "12.1"),
            (100.0, "100"),
            (9999.4, "9999"),
            (10000.0, "1e4"),
            (65432.0, "6.54e4"),
            (3.25e32, "3.25e32"),
            (0.001, "1e-3"),
            (-0.5, "-0.5"),
        ];
        for (v, s) in cases {
            assert_eq!(format_value(v), s, "{v}");
        }
    }

    #[test]
    fn captions_wrap_at_spaces_and_cut_long_words() {
        assert_eq!(
            wrap("t = 12.30 s  planning ok", 12),
            ["t = 12.30 s", "planning ok"]
        );
        assert_eq!(wrap("abcdefghij", 4), ["abcd", "efgh", "ij"]);
        assert_eq!(wrap("one\ntwo three", 20), ["one", "two three"]);
        assert!(wrap("", 5).is_empty());
    }
}
