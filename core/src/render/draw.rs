//! Vector drawing with tiny-skia, in frame pixel coordinates: paths, markers, arrows and the
//! robot. Only lines, polygons and circles are used (no cubics, no rotation transforms), so
//! tiny-skia needs no platform float function; every angle goes through `libm` (spec §6).
//! A path that cannot be built (e.g. coordinates overflowing `f32`) is skipped, never a panic.

use tiny_skia::{FillRule, LineCap, LineJoin, Paint, PathBuilder, Pixmap, Stroke, Transform};

use super::colour::Rgba;
use super::style;

/// A point in frame pixels.
pub(crate) type Px = (f32, f32);

fn paint(c: Rgba) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color_rgba8(c.r, c.g, c.b, c.a);
    p.anti_alias = true;
    p
}

fn finite(p: Px) -> bool {
    p.0.is_finite() && p.1.is_finite()
}

/// Strokes the polyline through `points` (round joins and caps).
pub(crate) fn polyline(pixmap: &mut Pixmap, points: &[Px], width: f32, c: Rgba) {
    if points.len() < 2 || !points.iter().all(|&p| finite(p)) {
        return;
    }
    let mut pb = PathBuilder::with_capacity(points.len(), points.len());
    pb.move_to(points[0].0, points[0].1);
    for p in &points[1..] {
        pb.line_to(p.0, p.1);
    }
    let Some(path) = pb.finish() else { return };
    let stroke = Stroke {
        width,
        line_cap: LineCap::Round,
        line_join: LineJoin::Round,
        ..Stroke::default()
    };
    pixmap.stroke_path(&path, &paint(c), &stroke, Transform::identity(), None);
}

/// Fills the closed polygon `points`.
pub(crate) fn polygon(pixmap: &mut Pixmap, points: &[Px], c: Rgba) {
    if points.len() < 3 || !points.iter().all(|&p| finite(p)) {
        return;
    }
    let mut pb = PathBuilder::with_capacity(points.len() + 1, points.len());
    pb.move_to(points[0].0, points[0].1);
    for p in &points[1..] {
        pb.line_to(p.0, p.1);
    }
    pb.close();
    if let Some(path) = pb.finish() {
        pixmap.fill_path(
            &path,
            &paint(c),
            FillRule::Winding,
            Transform::identity(),
            None,
        );
    }
}

/// Strokes the outline of the closed polygon `points`.
pub(crate) fn polygon_outline(pixmap: &mut Pixmap, points: &[Px], width: f32, c: Rgba) {
    if points.len() < 2 {
        return;
    }
    let mut closed = points.to_vec();
    closed.push(points[0]);
    polyline(pixmap, &closed, width, c);
}

/// Fills a circle.
pub(crate) fn disc(pixmap: &mut Pixmap, centre: Px, r: f32, c: Rgba) {
    if !(finite(centre) && r.is_finite() && r > 0.0) {
        return;
    }
    if let Some(path) = PathBuilder::from_circle(centre.0, centre.1, r) {
        pixmap.fill_path(
            &path,
            &paint(c),
            FillRule::Winding,
            Transform::identity(),
            None,
        );
    }
}

/// Fills a disc of radius `r` at each of `centres` (non-finite ones skipped), as one path:
/// one fill instead of one per disc, the same pixels where the discs do not share one
/// (where they do, their union is filled once).
pub(crate) fn discs(pixmap: &mut Pixmap, centres: impl IntoIterator<Item = Px>, r: f32, c: Rgba) {
    if !(r.is_finite() && r > 0.0) {
        return;
    }
    let mut b = PathBuilder::new();
    for p in centres.into_iter().filter(|&p| finite(p)) {
        b.push_circle(p.0, p.1, r);
    }
    if let Some(path) = b.finish() {
        pixmap.fill_path(
            &path,
            &paint(c),
            FillRule::Winding,
            Transform::identity(),
            None,
        );
    }
}

/// Strokes a circle.
pub(crate) fn ring(pixmap: &mut Pixmap, centre: Px, r: f32, width: f32, c: Rgba) {
    if !(finite(centre) && r.is_finite() && r > 0.0) {
        return;
    }
    if let Some(path) = PathBuilder::from_circle(centre.0, centre.1, r) {
        let stroke = Stroke {
            width,
            ..Stroke::default()
        };
        pixmap.stroke_path(&path, &paint(c), &stroke, Transform::identity(), None);
    }
}

/// A unit vector in frame pixels for world heading `theta` (y flipped).
pub(crate) fn heading(theta: f64) -> (f64, f64) {
    (libm::cos(theta), -libm::sin(theta))
}

fn at(p: (f64, f64), d: (f64, f64), along: f64, across: f64) -> Px {
    // `across` is to the left of `d` as seen on screen (world counter-clockwise).
    (
        (p.0 + d.0 * along + d.1 * across) as f32,
        (p.1 + d.1 * along - d.0 * across) as f32,
    )
}

/// A pose arrow: a dot at `p` and an arrow of `length` pixels along the unit vector `d`,
/// with a light halo so it reads on any background.
pub(crate) fn pose_arrow(
    pixmap: &mut Pixmap,
    p: (f64, f64),
    d: (f64, f64),
    length: f64,
    u: f32,
    c: Rgba,
) {
    let uf = f64::from(u);
    let head = 5.0 * uf;
    let tip = at(p, d, length, 0.0);
    let neck = at(p, d, length - head, 0.0);
    let base = (p.0 as f32, p.1 as f32);
    let wing = [
        tip,
        at(p, d, length - head * 1.3, head * 0.75),
        at(p, d, length - head * 1.3, -head * 0.75),
    ];
    polyline(pixmap, &[base, neck], 4.5 * u, style::HALO);
    polygon_outline(pixmap, &wing, 2.0 * u, style::HALO);
    disc(pixmap, base, 3.6 * u, style::HALO);
    polyline(pixmap, &[base, neck], 2.2 * u, c);
    polygon(pixmap, &wing, c);
    disc(pixmap, base, 2.6 * u, c);
}

/// The robot in pixel units: body circle of radius `r`, wheels at `±axle/2` of radius
/// `wheel`, a nose showing the heading `d`, a red outline if `bumped`, and a chevron behind
/// it if it drives `backward`.
#[allow(clippy::too_many_arguments)]
pub(crate) fn robot(
    pixmap: &mut Pixmap,
    p: (f64, f64),
    d: (f64, f64),
    r: f64,
    axle: f64,
    wheel: f64,
    bumped: bool,
    backward: bool,
    u: f32,
) {
    let centre = (p.0 as f32, p.1 as f32);
    let rf = r as f32;
    disc(pixmap, centre, rf, style::ROBOT_BODY);
    // Wheels: rectangles 2·wheel long, at least 2u wide.
    let ww = (0.45 * wheel).max(1.6 * f64::from(u)).min(r * 0.4);
    for side in [-1.0, 1.0] {
        let lateral = side * axle / 2.0;
        let corners = [
            at(p, d, -wheel, lateral - ww / 2.0),
            at(p, d, wheel, lateral - ww / 2.0),
            at(p, d, wheel, lateral + ww / 2.0),
            at(p, d, -wheel, lateral + ww / 2.0),
        ];
        polygon(pixmap, &corners, style::WHEEL);
    }
    // Nose: a triangle pointing along the heading.
    let nose = [
        at(p, d, 0.9 * r, 0.0),
        at(p, d, 0.3 * r, 0.36 * r),
        at(p, d, 0.3 * r, -0.36 * r),
    ];
    polygon(pixmap, &nose, style::ROBOT_LINE);
    disc(pixmap, centre, (0.1 * r) as f32, style::ROBOT_LINE);
    let (outline, width) = if bumped {
        (style::ROBOT_BUMP, 3.0 * u)
    } else {
        (style::ROBOT_LINE, 1.5 * u)
    };
    ring(pixmap, centre, rf, width, outline);
    if backward {
        let uf = f64::from(u);
        let back = r + 4.0 * uf;
        let size = 4.0 * uf;
        let chevron = [
            at(p, d, -back + size, size),
            at(p, d, -back, 0.0),
            at(p, d, -back + size, -size),
        ];
        polyline(pixmap, &chevron, 4.0 * u, style::HALO);
        polyline(pixmap, &chevron, 2.0 * u, style::ROBOT_LINE);
    }
}

/// Drops points closer than ¾ pixel to the last one kept (the last point is always kept).
pub(crate) fn decimate(points: impl Iterator<Item = Px>) -> Vec<Px> {
    let mut out: Vec<Px> = Vec::new();
    let mut pending = None;
    for p in points {
        match out.last() {
            Some(&q) if (p.0 - q.0) * (p.0 - q.0) + (p.1 - q.1) * (p.1 - q.1) < 0.5625 => {
                pending = Some(p);
            }
            _ => {
                out.push(p);
                pending = None;
            }
        }
    }
    out.extend(pending);
    out
}

/// Squared distance from `p` to the segment `a`–`b`.
fn segment_distance2(p: Px, a: Px, b: Px) -> f32 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let (ex, ey) = (a.0 + t * dx - p.0, a.1 + t * dy - p.1);
    ex * ex + ey * ey
}

/// Douglas–Peucker: the fewest points of `points` whose polyline stays within `tolerance`
/// pixels of it. A grid path's staircase and collinear runs become a few segments, so a long
/// path strokes fast; at half a pixel the difference cannot be seen.
pub(crate) fn simplify(points: &[Px], tolerance: f32) -> Vec<Px> {
    let n = points.len();
    if n <= 2 {
        return points.to_vec();
    }
    let tol2 = tolerance * tolerance;
    let mut keep = vec![false; n];
    keep[0] = true;
    keep[n - 1] = true;
    let mut stack = vec![(0, n - 1)];
    while let Some((a, b)) = stack.pop() {
        let mut far = (tol2, None);
        for (i, &p) in points.iter().enumerate().take(b).skip(a + 1) {
            let d = segment_distance2(p, points[a], points[b]);
            if d > far.0 {
                far = (d, Some(i));
            }
        }
        if let Some(i) = far.1 {
            keep[i] = true;
            stack.push((a, i));
            stack.push((i, b));
        }
    }
    points
        .iter()
        .zip(keep)
        .filter_map(|(&p, k)| k.then_some(p))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn simplify_keeps_corners_and_drops_collinear_and_staircase_points() {
        let line: Vec<Px> = (0..10).map(|i| (i as f32, 2.0)).collect();
        assert_eq!(simplify(&line, 0.5), [(0.0, 2.0), (9.0, 2.0)]);
        let corner = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (2.0, 1.0), (2.0, 2.0)];
        assert_eq!(simplify(&corner, 0.5), [(0.0, 0.0), (2.0, 0.0), (2.0, 2.0)]);
        // A staircase of 0.4 px steps is a straight line at half a pixel.
        let stairs: Vec<Px> = (0..20)
            .map(|i| {
                (
                    (i / 2) as f32 * 0.4 + (i % 2) as f32 * 0.4,
                    (i / 2) as f32 * 0.4,
                )
            })
            .collect();
        assert_eq!(simplify(&stairs, 0.5).len(), 2);
        // A path that turns back keeps its far end.
        let back = [(0.0, 0.0), (10.0, 0.0), (1.0, 0.0)];
        assert_eq!(simplify(&back, 0.5), back);
    }

    #[test]
    fn decimate_drops_points_closer_than_three_quarters_of_a_pixel() {
        let pts = [(0.0, 0.0), (0.5, 0.0), (1.0, 0.0), (1.2, 0.0), (1.3, 0.0)];
        assert_eq!(
            decimate(pts.into_iter()),
            [(0.0, 0.0), (1.0, 0.0), (1.3, 0.0)]
        );
    }
}
