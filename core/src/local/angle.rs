//! `atan2(y, x)` for `y ≥ 0`, bit for bit the value of `libm::atan2` (FreeBSD's `e_atan2.c`
//! and `s_atan.c`, as the `libm` crate has them), but without its unpredictable branches.
//!
//! The potential field needs two angles per cell (spec §3 step 4, `S_Angle` and `G_Angle`).
//! `libm::atan` picks one of five argument reductions by the size of its argument, each
//! with its own division; cells are reached in potential order, not in space order, so that
//! branch is a coin toss for the processor and costs more than the arithmetic. Here every
//! reduction is one formula `(a·t + b) / (c·t + d)` with its coefficients looked up by the
//! same thresholds, so there is one division and no branch:
//!
//! | `t = |y/x|` | libm | here (a, b, c, d) |
//! | --- | --- | --- |
//! | < 7/16 | `t` | (1, 0, 0, 1): `(1·t + 0) / (0·t + 1)` = `t` exactly |
//! | < 11/16 | `(2t − 1) / (2 + t)` | (2, −1, 1, 2) |
//! | < 19/16 | `(t − 1) / (t + 1)` | (1, −1, 1, 1) |
//! | < 39/16 | `(t − 1.5) / (1 + 1.5t)` | (1, −1.5, 1.5, 1) |
//! | ≥ 39/16 | `−1 / t` | (0, −1, 1, 0) |
//!
//! Each row computes the very same IEEE operations on the same operands (multiplying by 1,
//! adding 0 and `a + b = b + a` are exact), so the reduced argument has the same bits; the
//! polynomial is libm's, term for term; and libm's two finishing formulas are one here,
//! `hi − ((x·s − lo) − x)` with `hi = lo = 0` for the first row, which equals libm's
//! `x − x·s` exactly (`0 − (u − x) = x − u` in round-to-nearest). libm's early exits for
//! tiny and huge `t` return what the formula gives anyway (checked by the tests, with the
//! special cases kept as rare, predictable branches). `f64::sqrt`-free, `libm`-free: plain
//! IEEE arithmetic, so the same on every target (spec §6).

// The constants of `s_atan.c` and `e_atan2.c`, by their bits (as their comments give them).
const ATANHI: [f64; 5] = [
    0.0,
    f64::from_bits(0x3FDD_AC67_0561_BB4F), // atan(0.5) hi
    f64::from_bits(0x3FE9_21FB_5444_2D18), // atan(1.0) hi
    f64::from_bits(0x3FEF_730B_D281_F69B), // atan(1.5) hi
    f64::from_bits(0x3FF9_21FB_5444_2D18), // atan(inf) hi
];

const ATANLO: [f64; 5] = [
    0.0,
    f64::from_bits(0x3C7A_2B7F_222F_65E2),
    f64::from_bits(0x3C81_A626_3314_5C07),
    f64::from_bits(0x3C70_0788_7AF0_CBBD),
    f64::from_bits(0x3C91_A626_3314_5C07),
];

const AT: [f64; 11] = [
    f64::from_bits(0x3FD5_5555_5555_550D),
    f64::from_bits(0xBFC9_9999_9998_EBC4),
    f64::from_bits(0x3FC2_4924_9200_83FF),
    f64::from_bits(0xBFBC_71C6_FE23_1671),
    f64::from_bits(0x3FB7_45CD_C54C_206E),
    f64::from_bits(0xBFB3_B0F2_AF74_9A6D),
    f64::from_bits(0x3FB1_0D66_A0D0_3D51),
    f64::from_bits(0xBFAD_DE2D_52DE_FD9A),
    f64::from_bits(0x3FA9_7B4B_2476_0DEB),
    f64::from_bits(0xBFA2_B444_2C6A_6C2F),
    f64::from_bits(0x3F90_AD3A_E322_DA11),
];

/// The reductions' coefficients `(a, b, c, d)`: `x = (a·t + b) / (c·t + d)`.
const REDUCE: [[f64; 4]; 5] = [
    [1.0, 0.0, 0.0, 1.0],
    [2.0, -1.0, 1.0, 2.0],
    [1.0, -1.0, 1.0, 1.0],
    [1.0, -1.5, 1.5, 1.0],
    [0.0, -1.0, 1.0, 0.0],
];

const PI: f64 = f64::from_bits(0x4009_21FB_5444_2D18);
const PI_LO: f64 = f64::from_bits(0x3CA1_A626_3314_5C07);

/// `atan(t)` for finite `t ≥ 0` below 2^66, as `libm::atan`.
#[inline(always)]
fn atan_nonneg(t: f64) -> f64 {
    let ix = (t.to_bits() >> 32) as u32;
    // libm's thresholds on the high word: 7/16, 11/16, 19/16, 39/16.
    let row = usize::from(ix >= 0x3fdc_0000)
        + usize::from(ix >= 0x3fe6_0000)
        + usize::from(ix >= 0x3ff3_0000)
        + usize::from(ix >= 0x4003_8000);
    let [a, b, c, d] = REDUCE[row];
    let x = (a * t + b) / (c * t + d);
    let z = x * x;
    let w = z * z;
    let s1 = z * (AT[0] + w * (AT[2] + w * (AT[4] + w * (AT[6] + w * (AT[8] + w * AT[10])))));
    let s2 = w * (AT[1] + w * (AT[3] + w * (AT[5] + w * (AT[7] + w * AT[9]))));
    ATANHI[row] - (x * (s1 + s2) - ATANLO[row] - x)
}

/// `libm::atan2(y, x)` for finite `y ≥ 0` and finite `x`, not both 0 — bit for bit.
#[inline(always)]
pub fn atan2_nonneg(y: f64, x: f64) -> f64 {
    let (ix, iy) = (
        (x.to_bits() >> 32) as u32 & 0x7fff_ffff,
        (y.to_bits() >> 32) as u32 & 0x7fff_ffff,
    );
    let negative_x = x.is_sign_negative();
    // libm's special cases: y = 0, x = 0, |y/x| > 2^64, and |y/x| < 2^-64 with x < 0.
    // Rare (never, for the field's vectors but exact zeros), so predictable branches.
    if y == 0.0 {
        return if negative_x { PI } else { y };
    }
    if x == 0.0 || ix.wrapping_add(64 << 20) < iy {
        return PI / 2.0;
    }
    let z = if negative_x && iy.wrapping_add(64 << 20) < ix {
        0.0
    } else {
        atan_nonneg((y / x).abs())
    };
    if negative_x { PI - (z - PI_LO) } else { z }
}

#[cfg(test)]
mod tests {
    use super::atan2_nonneg;

    fn check(y: f64, x: f64) {
        let want = libm::atan2(y, x);
        let got = atan2_nonneg(y, x);
        assert_eq!(got.to_bits(), want.to_bits(), "atan2({y:e}, {x:e})");
    }

    /// Random bit patterns, random small-integer vectors against unit headings (what the
    /// field computes), and the edges: zeros, the reduction thresholds, tiny and huge
    /// ratios, signed zero.
    #[test]
    fn equals_libm_bit_for_bit() {
        let mut seed = 0x1234_5678_9abc_def0u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        for _ in 0..400_000 {
            let y = f64::from_bits(next() & 0x7fff_ffff_ffff_ffff);
            let x = f64::from_bits(next());
            if y.is_finite() && x.is_finite() && !(x == 0.0 && y == 0.0) {
                check(y, x);
            }
        }
        for _ in 0..400_000 {
            let theta = (next() % 100_000) as f64 * 1e-4 - 5.0;
            let (c, s) = (libm::cos(theta), libm::sin(theta));
            let vx = (next() % 4001) as f64 - 2000.0;
            let vy = (next() % 4001) as f64 - 2000.0;
            if vx == 0.0 && vy == 0.0 {
                continue;
            }
            check((vx * s - vy * c).abs(), vx * c + vy * s);
        }
        for t in [
            7.0f64 / 16.0,
            11.0 / 16.0,
            19.0 / 16.0,
            39.0 / 16.0,
            1.0,
            0.5,
            1.5,
        ] {
            for k in -4i64..=4 {
                let t = f64::from_bits(t.to_bits().wrapping_add_signed(k));
                check(t, 1.0);
                check(t, -1.0);
                check(1.0, 1.0 / t);
                check(t * 3.0, 3.0);
            }
        }
        for &(y, x) in &[
            (0.0, 1.0),
            (0.0, -1.0),
            (0.0, -0.0),
            (1.0, 0.0),
            (1.0, -0.0),
            (1e-300, 1.0),
            (1e-300, -1.0),
            (1e-320, -3.0),
            (1.0, 1e-300),
            (1.0, -1e-300),
            (2f64.powi(65), 1.0),
            (2f64.powi(65), -1.0),
            (2f64.powi(66), 1.0),
            (2f64.powi(66), -1.0),
            (1.0, 2f64.powi(64)),
            (1.0, -(2f64.powi(64))),
            (1.0, -(2f64.powi(66))),
            (2f64.powi(-28), 1.0),
            (2f64.powi(-27), 1.0),
            (f64::MIN_POSITIVE, 1.0),
            (f64::MAX, 1.0),
            (1.0, f64::MAX),
            (1.0, -f64::MAX),
        ] {
            check(y, x);
        }
    }
}
