//! Exact Euclidean distance transform in linear time (Felzenszwalb & Huttenlocher, "Distance
//! Transforms of Sampled Functions", 2012), SPEC §2 "Obstacle distance".
//!
//! Everything outside the map is obstacle (SPEC §2), so the transform sees a virtual ring of
//! obstacle cells around the map: distances are always finite.

/// Squared distance, in cells², from every cell's centre to the nearest obstacle cell's
/// centre, counting the ring of cells just outside the map as obstacles. `obstacle` is
/// x-fastest, `width × height`.
pub fn euclidean_distance_squared(obstacle: &[bool], width: usize, height: usize) -> Vec<f64> {
    debug_assert_eq!(obstacle.len(), width * height);
    let n = width.max(height) + 2;
    let mut f = vec![0.0; n];
    let mut out = vec![0.0; n];
    let mut v = vec![0usize; n];
    let mut z = vec![0.0; n + 1];
    let mut cols = vec![0.0; width * height];
    // Column pass: along y, with virtual obstacles at y = -1 and y = height.
    for x in 0..width {
        f[0] = 0.0;
        f[height + 1] = 0.0;
        for y in 0..height {
            f[y + 1] = if obstacle[x + y * width] {
                0.0
            } else {
                f64::INFINITY
            };
        }
        dt1d(&f[..height + 2], &mut out[..height + 2], &mut v, &mut z);
        for y in 0..height {
            cols[x + y * width] = out[y + 1];
        }
    }
    // Row pass: along x, with virtual obstacle columns at x = -1 and x = width.
    let mut result = vec![0.0; width * height];
    for y in 0..height {
        f[0] = 0.0;
        f[width + 1] = 0.0;
        f[1..=width].copy_from_slice(&cols[y * width..(y + 1) * width]);
        dt1d(&f[..width + 2], &mut out[..width + 2], &mut v, &mut z);
        result[y * width..(y + 1) * width].copy_from_slice(&out[1..=width]);
    }
    result
}

/// One-dimensional squared-distance transform of `f` into `d` (lower envelope of parabolas).
fn dt1d(f: &[f64], d: &mut [f64], v: &mut [usize], z: &mut [f64]) {
    let n = f.len();
    let mut k = 0usize;
    // Find the first finite site (there always is one: the virtual ends are 0).
    let first = f.iter().position(|x| x.is_finite()).unwrap_or(0);
    v[0] = first;
    z[0] = f64::NEG_INFINITY;
    z[1] = f64::INFINITY;
    for q in first + 1..n {
        if !f[q].is_finite() {
            continue;
        }
        let qf = q as f64;
        loop {
            let p = v[k];
            let pf = p as f64;
            let s = ((f[q] + qf * qf) - (f[p] + pf * pf)) / (2.0 * (qf - pf));
            if s <= z[k] && k > 0 {
                k -= 1;
                continue;
            }
            if s <= z[k] {
                // k == 0 and the new parabola dominates from -inf.
                v[0] = q;
                z[0] = f64::NEG_INFINITY;
                z[1] = f64::INFINITY;
                break;
            }
            k += 1;
            v[k] = q;
            z[k] = s;
            z[k + 1] = f64::INFINITY;
            break;
        }
    }
    k = 0;
    for (q, dq) in d.iter_mut().enumerate().take(n) {
        let qf = q as f64;
        while z[k + 1] < qf {
            k += 1;
        }
        let p = v[k] as f64;
        *dq = (qf - p) * (qf - p) + f[v[k]];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn brute(obstacle: &[bool], w: usize, h: usize) -> Vec<f64> {
        let mut out = vec![f64::INFINITY; w * h];
        for y in 0..h as i64 {
            for x in 0..w as i64 {
                let mut best = f64::INFINITY;
                for oy in -1..=h as i64 {
                    for ox in -1..=w as i64 {
                        let outside = ox < 0 || oy < 0 || ox >= w as i64 || oy >= h as i64;
                        if outside || obstacle[(ox + oy * w as i64) as usize] {
                            let d = ((x - ox).pow(2) + (y - oy).pow(2)) as f64;
                            best = best.min(d);
                        }
                    }
                }
                out[(x + y * w as i64) as usize] = best;
            }
        }
        out
    }

    #[test]
    fn matches_brute_force_on_small_maps() {
        let mut seed = 12345u64;
        for (w, h) in [(1, 1), (3, 1), (1, 4), (7, 5), (13, 9), (20, 20)] {
            for density in [0u64, 5, 30, 90] {
                let obstacle: Vec<bool> = (0..w * h)
                    .map(|_| {
                        seed = seed
                            .wrapping_mul(6364136223846793005)
                            .wrapping_add(1442695040888963407);
                        (seed >> 33) % 100 < density
                    })
                    .collect();
                assert_eq!(
                    euclidean_distance_squared(&obstacle, w, h),
                    brute(&obstacle, w, h),
                    "{w}x{h} density {density}"
                );
            }
        }
    }
}
