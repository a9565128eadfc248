//! Exact octile path costs (spec §5 "GlobalPathPlanning": octile costs, optimal lengths).
//!
//! A path on the 8-connected grid costs `a + b·√2` cells for `a` straight and `b` diagonal
//! steps. Summing `f64`s would round, and rounding would make equal costs unequal depending
//! on the order of the steps — then tie-breaking (and so the path chosen) would hang on
//! rounding. [`OctileCost`] keeps the two counts, and [`OctileCost::key`] maps them to a
//! `u128` whose order is *exactly* the order of the real numbers `a + b·√2`.

use core::cmp::Ordering;
use core::f64::consts::SQRT_2;
use core::ops::Add;

/// `⌊√2 · 2^80⌋`.
const SQRT2_FIXED: u128 = 1_709_679_290_002_018_430_137_083;
/// Fractional bits of [`OctileCost::key`].
const FRACTION_BITS: u32 = 80;

/// A cost of `straight + diagonal·√2` cells.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct OctileCost {
    /// Straight (unit) steps.
    pub straight: u32,
    /// Diagonal (√2) steps.
    pub diagonal: u32,
}

impl OctileCost {
    /// No cost.
    pub const ZERO: Self = Self::new(0, 0);
    /// One straight step.
    pub const STRAIGHT: Self = Self::new(1, 0);
    /// One diagonal step.
    pub const DIAGONAL: Self = Self::new(0, 1);

    /// `straight + diagonal·√2`.
    pub const fn new(straight: u32, diagonal: u32) -> Self {
        Self { straight, diagonal }
    }

    /// The octile distance between two cells: the cost of the shortest path on an empty
    /// 8-connected grid, `|dx − dy| + min(dx, dy)·√2` (the A* heuristic).
    pub fn between(a: (usize, usize), b: (usize, usize)) -> Self {
        let dx = a.0.abs_diff(b.0) as u32;
        let dy = a.1.abs_diff(b.1) as u32;
        Self::new(dx.abs_diff(dy), dx.min(dy))
    }

    /// The cost in cells as `f64` (one rounding of the exact value, whatever the path).
    pub fn cells(self) -> f64 {
        f64::from(self.straight) + f64::from(self.diagonal) * SQRT_2
    }

    /// An integer ordered exactly as `straight + diagonal·√2`:
    /// `straight·2^80 + diagonal·⌊√2·2^80⌋`.
    ///
    /// Why it is exact for every pair of `u32` counts: the key differs from
    /// `(a + b√2)·2^80` by less than `b < 2^32`; two different costs differ by
    /// `|Δa + Δb√2| = |Δa² − 2Δb²| / |Δa − Δb√2| ≥ 1 / (2^32 · 2.42)` (the numerator is a
    /// non-zero integer), i.e. by more than `2^80 / 2^33.3 > 2^46` in key units — far more
    /// than the two truncation errors together. Equal keys mean equal counts (√2 is
    /// irrational).
    pub fn key(self) -> u128 {
        (u128::from(self.straight) << FRACTION_BITS) + u128::from(self.diagonal) * SQRT2_FIXED
    }

    /// A `u64` key ordered exactly as `straight + diagonal·√2` while
    /// `straight + diagonal ≤` [`OctileCost::SMALL_KEY_MAX`] (`2^20`):
    /// `straight·2^43 + diagonal·⌊√2·2^43⌋`.
    ///
    /// Exact by the argument of [`OctileCost::key`]: with step counts ≤ M = 2^20 each key is
    /// below the true `(a + b√2)·2^43` by less than `M` units, and two different costs differ
    /// by at least `2^43 / (2.42·M) > 2^21.7` units, more than both errors together; and
    /// `(a + b√2)·2^43 ≤ √2·M·2^43 < 2^64`. The key is linear:
    /// `small_key(a + b) = small_key(a) + small_key(b)`. Above the limit the value is
    /// meaningless (wrapping), so callers check the bound first.
    pub fn small_key(self) -> u64 {
        (u64::from(self.straight) << SMALL_FRACTION_BITS)
            .wrapping_add(u64::from(self.diagonal).wrapping_mul(SQRT2_SMALL))
    }

    /// The largest `straight + diagonal` for which [`OctileCost::small_key`] is exact.
    pub const SMALL_KEY_MAX: u32 = 1 << 20;
}

/// `⌊√2 · 2^43⌋`.
const SQRT2_SMALL: u64 = 12_439_554_047_901;
/// Fractional bits of [`OctileCost::small_key`].
const SMALL_FRACTION_BITS: u32 = 43;

impl Add for OctileCost {
    type Output = Self;

    /// Adds step counts (saturating: no path on a map of at most 16 Mi cells comes near).
    fn add(self, rhs: Self) -> Self {
        Self::new(
            self.straight.saturating_add(rhs.straight),
            self.diagonal.saturating_add(rhs.diagonal),
        )
    }
}

impl Ord for OctileCost {
    /// By the real value `straight + diagonal·√2`, exactly.
    fn cmp(&self, other: &Self) -> Ordering {
        self.key().cmp(&other.key())
    }
}

impl PartialOrd for OctileCost {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `SQRT2_FIXED² ≤ 2^161 < (SQRT2_FIXED + 1)²`, checked in 64-bit limbs.
    #[test]
    fn the_constant_is_the_floor_of_sqrt2_times_2_pow_80() {
        fn square(v: u128) -> [u128; 2] {
            // v = hi·2^64 + lo; v² = hi²·2^128 + 2·hi·lo·2^64 + lo².
            let (hi, lo) = (v >> 64, v & u128::from(u64::MAX));
            let cross = 2 * hi * lo; // < 2^82
            let low = lo * lo;
            let (sum, carry) = low.overflowing_add(cross << 64);
            [hi * hi + (cross >> 64) + u128::from(carry), sum]
        }
        let two_pow_161 = [1u128 << 33, 0];
        assert!(square(SQRT2_FIXED) <= two_pow_161);
        assert!(square(SQRT2_FIXED + 1) > two_pow_161);
        // ⌊√2·2^43⌋: its square is below 2^87 and the next one's above.
        let small = u128::from(SQRT2_SMALL);
        assert!(small * small <= 1 << 87);
        assert!((small + 1) * (small + 1) > 1 << 87);
    }

    #[test]
    fn the_small_key_orders_as_the_full_key_up_to_its_limit() {
        let m = OctileCost::SMALL_KEY_MAX;
        let costs = [
            OctileCost::new(19601, 0),
            OctileCost::new(0, 13860),
            OctileCost::new(8119, 0),
            OctileCost::new(0, 5741),
            OctileCost::new(m, 0),
            OctileCost::new(0, m),
            OctileCost::new(m / 2, m / 2),
            OctileCost::new(m / 2 + 1, m / 2 - 1),
            OctileCost::new(741_455, 0),
            // 665 857 − 470 832·√2 ≈ +7.5e-7 (a Pell pair near the limit).
            OctileCost::new(665_857, 0),
            OctileCost::new(0, 470_832),
            OctileCost::new(665_857, 1),
            OctileCost::new(1, 470_832),
        ];
        for a in costs {
            for b in costs {
                assert_eq!(a.small_key().cmp(&b.small_key()), a.cmp(&b), "{a:?} {b:?}");
            }
        }
    }

    #[test]
    fn order_is_exact_where_f64_would_tie_or_round() {
        // Pell pairs: 19601 − 13860·√2 ≈ +2.6e-5, 8119 − 5741·√2 ≈ −6.2e-5.
        assert!(OctileCost::new(19601, 0) > OctileCost::new(0, 13860));
        assert!(OctileCost::new(8119, 0) < OctileCost::new(0, 5741));
        assert!(OctileCost::new(19601, 5741) > OctileCost::new(8119, 13860));
        // Near u32::MAX: 3 037 000 499·√2 ≈ 4 294 967 294.62, 3 037 000 500·√2 ≈ …296.03.
        assert!(OctileCost::new(u32::MAX, 0) > OctileCost::new(0, 3_037_000_499));
        assert!(OctileCost::new(u32::MAX, 0) < OctileCost::new(0, 3_037_000_500));
        assert!(OctileCost::new(u32::MAX, 1) > OctileCost::new(0, 3_037_000_500));
        assert_eq!(
            OctileCost::new(1, 0) + OctileCost::new(2, 3),
            OctileCost::new(3, 3)
        );
        assert_eq!(OctileCost::between((0, 0), (5, 2)), OctileCost::new(3, 2));
    }
}
