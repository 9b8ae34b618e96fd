//! Sine and cosine of angles known to be small (the rod angle, the piston tilt): libm's general
//! path, range reduction included, is wasted on them, and its `sin_cos` was a sixth of the crank
//! train's run time. Two polynomials do it in a dozen multiply-adds, a tilt in two.

/// Widest angle of the polynomials: covers the rod's swing asin(l1/l2) of any sensible engine,
/// and up to it 7 and 8 Taylor terms truncate below half an ulp.
const LIMIT: f64 = 0.5;

/// Up to this angle (a piston's tilt) two terms of each series truncate below 1e-17: the next are
/// x⁶/5040 and x⁶/720 relative to 1.
const TILT_LIMIT: f64 = 1.0 / 256.0;

/// Taylor coefficients in x² from the lowest: sin x = x (1 + Σ SIN_k x^(2k+2)) with SIN_k =
/// (−1)^(k+1) / (2k+3)!, cos x = 1 + Σ COS_k x^(2k+2) with COS_k = (−1)^(k+1) / (2k+2)!.
const SIN: [f64; 6] = [-1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0, 1.0 / 362_880.0, -1.0 / 39_916_800.0, 1.0 / 6_227_020_800.0];
const COS: [f64; 7] = [-1.0 / 2.0, 1.0 / 24.0, -1.0 / 720.0, 1.0 / 40_320.0, -1.0 / 3_628_800.0, 1.0 / 479_001_600.0, -1.0 / 87_178_291_200.0];

/// Σ c_k y^k by Horner. Not `mul_add`: built without target-cpu flags, it calls a software-dispatched
/// `fma`, which made an evaluation 40 % slower instead of faster.
fn horner(y: f64, c: &[f64]) -> f64 {
    let (last, rest) = c.split_last().expect("coefficients");
    rest.iter().rfold(*last, |acc, &c| acc * y + c)
}

/// `x.sin_cos()` within an ulp or so, by polynomials for |x| ≤ [`LIMIT`], by libm otherwise
/// (NaN and infinities included).
#[inline]
pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
    if x.abs() <= TILT_LIMIT {
        let y = x * x;
        (x + x * y * horner(y, &SIN[..2]), 1.0 + y * horner(y, &COS[..2]))
    } else if x.abs() <= LIMIT {
        let y = x * x;
        (x + x * y * horner(y, &SIN), 1.0 + y * horner(y, &COS))
    } else {
        x.sin_cos()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Relative error in sin and absolute error in cos against libm, or both bit-identical.
    fn check(x: f64) {
        let ((s, c), (sr, cr)) = (sin_cos(x), x.sin_cos());
        let same = |a: f64, b: f64| a.to_bits() == b.to_bits();
        assert!(same(s, sr) || (s - sr).abs() <= 4e-16 * sr.abs(), "sin {x:e}: {s:e} vs {sr:e}");
        assert!(same(c, cr) || (c - cr).abs() <= 2e-16, "cos {x:e}: {c:e} vs {cr:e}");
    }

    fn grid() -> impl Iterator<Item = f64> {
        const N: i32 = 100_000;
        (-N..=N).map(|k| LIMIT * f64::from(k) / f64::from(N))
    }

    #[test]
    fn matches_libm_over_the_range_and_falls_back_beyond_it() {
        grid().for_each(check);
        let above = LIMIT.next_up();
        let tilt = [TILT_LIMIT, -TILT_LIMIT, TILT_LIMIT.next_up(), -TILT_LIMIT.next_up(), 1e-3, -1e-3];
        for x in [0.0, -0.0, 1e-300, -1e-300, 5e-324, -5e-324, 1e-8, -1e-8, LIMIT, -LIMIT, above, -above, 1.0, 1e300].into_iter().chain(tilt) {
            check(x);
        }
        for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let (s, c) = sin_cos(x);
            assert!(s.is_nan() && c.is_nan(), "{x}");
        }
    }

    #[test]
    fn sine_and_cosine_squared_sum_to_one() {
        for x in grid() {
            let (s, c) = sin_cos(x);
            assert!((s * s + c * c - 1.0).abs() <= 4e-16, "{x}: {:e}", s * s + c * c - 1.0);
        }
    }
}
