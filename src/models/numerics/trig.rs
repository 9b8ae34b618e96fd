//! Sine and cosine without libm's general path. For angles known to be small (the rod angle, the
//! piston tilt) its range reduction is wasted, and its `sin_cos` would be a sixth of the crank
//! train's run time: two polynomials do it in a dozen multiply-adds, a tilt in two. The crank angle, of
//! any size, takes a quarter-turn reduction and the same polynomials: half of libm's cost.

/// Widest small angle: covers the rod's swing asin(l1/l2) of any sensible engine, and up to it
/// 7 and 8 Taylor terms truncate below half an ulp (8 and 9 up to π/4, all of them).
const LIMIT: f64 = 0.5;

/// Up to this angle (a piston's tilt) two terms of each series truncate below 1e-17: the next are
/// x⁶/5040 and x⁶/720 relative to 1.
const TILT_LIMIT: f64 = 1.0 / 256.0;

/// Taylor coefficients in x² from the lowest: sin x = x (1 + Σ SIN_k x^(2k+2)) with SIN_k =
/// (−1)^(k+1) / (2k+3)!, cos x = 1 + Σ COS_k x^(2k+2) with COS_k = (−1)^(k+1) / (2k+2)!.
const SIN: [f64; 7] =
    [-1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0, 1.0 / 362_880.0, -1.0 / 39_916_800.0, 1.0 / 6_227_020_800.0, -1.0 / 1_307_674_368_000.0];
const COS: [f64; 8] = [
    -1.0 / 2.0,
    1.0 / 24.0,
    -1.0 / 720.0,
    1.0 / 40_320.0,
    -1.0 / 3_628_800.0,
    1.0 / 479_001_600.0,
    -1.0 / 87_178_291_200.0,
    1.0 / 20_922_789_888_000.0,
];

/// Σ c_k y^k by Horner. Not `mul_add`: built without target-cpu flags, it calls a software-dispatched
/// `fma`, slower than a multiply and an add.
fn horner(y: f64, c: &[f64]) -> f64 {
    let (last, rest) = c.split_last().expect("coefficients");
    rest.iter().rfold(*last, |acc, &c| acc * y + c)
}

/// The two Taylor series in x with the given coefficients. Inlined, so that the slices' lengths
/// are constants and the loops unroll.
#[inline(always)]
fn series(x: f64, sin: &[f64], cos: &[f64]) -> (f64, f64) {
    let y = x * x;
    (x + x * y * horner(y, sin), 1.0 + y * horner(y, cos))
}

/// `libm::sincos(x)` within an ulp or so, by polynomials for |x| ≤ [`LIMIT`], by libm otherwise
/// (NaN and infinities included).
#[inline]
pub(crate) fn small_sin_cos(x: f64) -> (f64, f64) {
    if x.abs() <= TILT_LIMIT {
        series(x, &SIN[..2], &COS[..2])
    } else if x.abs() <= LIMIT {
        series(x, &SIN[..6], &COS[..7])
    } else {
        libm::sincos(x)
    }
}

/// π/2 in three parts (their sum is π/2 to 1e-37): the first two of at most 32 significant bits,
/// so that their products with k, and x − k·part₁, are exact for the |k| ≤ 2¹⁴ of [`REDUCIBLE`]; the last
/// rounded, its error far below an ulp of the smallest remainder (|r| ≳ 6e-17 |k| at x = k·π/2
/// rounded to a double).
const HALF_PI: [f64; 3] = [1.570_796_326_734_125_6, 6.077_100_506_303_966e-11, 2.022_266_248_795_950_6e-21];

/// Angles whose quarter turns [`sin_cos`] takes off itself; beyond, libm (the crank train keeps
/// its crank angle within a cycle, 4π, the roller within 2048 turns).
const REDUCIBLE: f64 = 16384.0 * std::f64::consts::FRAC_PI_2;

/// `libm::sincos(x)` of any angle, within 2 ulp of libm up to [`REDUCIBLE`]: x = k π/2 + r with
/// |r| ≤ π/4, then the polynomials on r. libm's reduction makes its call ≈ 150 instructions;
/// this one takes ≈ 70.
pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
    if x.abs() > REDUCIBLE || x.is_nan() {
        return libm::sincos(x);
    }
    // k = round(2x/π) by the 1.5·2⁵² shifter: `round` is a call on baseline x86-64.
    let shifter = 6_755_399_441_055_744.0;
    let k = (x * std::f64::consts::FRAC_2_PI + shifter) - shifter;
    let r = ((x - k * HALF_PI[0]) - k * HALF_PI[1]) - k * HALF_PI[2];
    let (s, c) = series(r, &SIN, &COS);
    match (k as i64) & 3 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    /// Relative error in sin and absolute error in cos against libm, or both bit-identical.
    fn check_small(x: f64) {
        let ((s, c), (sr, cr)) = (small_sin_cos(x), libm::sincos(x));
        let same = |a: f64, b: f64| a.to_bits() == b.to_bits();
        assert!(same(s, sr) || (s - sr).abs() <= 4e-16 * sr.abs(), "sin {x:e}: {s:e} vs {sr:e}");
        assert!(same(c, cr) || (c - cr).abs() <= 2e-16, "cos {x:e}: {c:e} vs {cr:e}");
    }

    /// Both within 2 ulp of libm's.
    fn check_any(x: f64) {
        let ((s, c), (sr, cr)) = (sin_cos(x), libm::sincos(x));
        let ulp = |v: f64| v.abs().next_up() - v.abs();
        assert!((s - sr).abs() <= 2.0 * ulp(sr), "sin {x:e}: {s:e} vs {sr:e}");
        assert!((c - cr).abs() <= 2.0 * ulp(cr), "cos {x:e}: {c:e} vs {cr:e}");
    }

    fn grid(limit: f64) -> impl Iterator<Item = f64> {
        const N: i32 = 100_000;
        (-N..=N).map(move |k| limit * f64::from(k) / f64::from(N))
    }

    #[test]
    fn small_angles_match_libm_over_the_range_and_fall_back_beyond_it() {
        grid(LIMIT).for_each(check_small);
        let above = LIMIT.next_up();
        let tilt = [TILT_LIMIT, -TILT_LIMIT, TILT_LIMIT.next_up(), -TILT_LIMIT.next_up(), 1e-3, -1e-3];
        for x in
            [0.0, -0.0, 1e-300, -1e-300, 5e-324, -5e-324, 1e-8, -1e-8, LIMIT, -LIMIT, above, -above, 1.0, 1e300].into_iter().chain(tilt)
        {
            check_small(x);
        }
        for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let (s, c) = small_sin_cos(x);
            assert!(s.is_nan() && c.is_nan(), "{x}");
        }
    }

    #[test]
    fn small_sine_and_cosine_squared_sum_to_one() {
        for x in grid(LIMIT) {
            let (s, c) = small_sin_cos(x);
            assert!((s * s + c * c - 1.0).abs() <= 4e-16, "{x}: {:e}", s * s + c * c - 1.0);
        }
    }

    #[test]
    fn any_angle_matches_libm_near_every_quarter_turn_and_falls_back_beyond_them() {
        grid(REDUCIBLE).for_each(check_any);
        // Where one of the two crosses zero its relative error is set by the reduction, and
        // halfway between, by the polynomials at their widest |r| = π/4.
        for k in -16384..=16384 {
            for x in [f64::from(k) * FRAC_PI_2, (f64::from(k) + 0.5) * FRAC_PI_2] {
                [x, x.next_up(), x.next_down(), x + 1e-9, x - 1e-9].into_iter().for_each(check_any);
            }
        }
        let above = REDUCIBLE.next_up();
        for x in [0.0, -0.0, 1e-300, 5e-324, 1e-8, -1e-8, REDUCIBLE, -REDUCIBLE, above, -above, 1e300] {
            check_any(x);
        }
        for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let (s, c) = sin_cos(x);
            assert!(s.is_nan() && c.is_nan(), "{x}");
        }
    }
}
