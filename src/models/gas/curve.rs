//! Built-in four-stroke cylinder pressure (gauge: cylinder minus crankcase), period 4π of crank angle.
//!
//! With ϑ the crank angle reduced to [−2π, 2π) about firing TDC (ϑ = 0, crank angle 0 mod 4π):
//!
//! - compression and expansion, ϑ ∈ [−π, π]: a closed-cylinder polytropic process whose constant
//!   grows with the burnt fraction (a single-zone, constant-exponent approximation of the first law),
//!   `p̂(ϑ) = [(V(π)/V(ϑ))ⁿ (1 + (ρ − 1) x_b(ϑ)) − 1] w(ϑ)`, in units of the intake pressure;
//!   `V(ϑ)/V_d = 1/(ε − 1) + ½[(1 − cos ϑ) + λ(1 − √(1 − sin²ϑ/λ²))]` is the slider-crank volume
//!   (Heywood, *Internal Combustion Engine Fundamentals*, eq 2.6), `λ` = rod length / crank radius;
//!   `x_b = 1 − exp(−a ((ϑ − ϑ_s)/Δϑ)^(m+1))` for ϑ ≥ ϑ_s is the Wiebe burn fraction (Heywood eq 9.23; both
//!   equation numbers not checked against the book);
//!   `w` = 1 up to exhaust valve opening ϑ_EVO, then `cos²(π/2 · (ϑ − ϑ_EVO)/(π − ϑ_EVO))` (blowdown to
//!   crankcase pressure at BDC);
//! - exhaust and intake strokes, ϑ ∈ (π, 3π) mod 4π: 0 (gas exchange at crankcase pressure).
//!
//! The curve is `p = p_max p̂/max p̂`, so its maximum is exactly `p_max` (A&K eq 30: `p_max p(φ1)` with
//! max p = 1). Constants: ε = 17, n = 1.35, ρ = 3.2, ϑ_s = −8°, Δϑ = 60°, a = 6.9, m = 1, ϑ_EVO = 130°,
//! a direct-injection diesel like A&K's source engine 1HC102; with p_max = 8 MPa the peak lies near
//! 11° after firing TDC and the compression pressure at −76° is ≈ 1.7 bar gauge.

use serde::{Deserialize, Serialize};
use std::f64::consts::{FRAC_PI_2, PI};

const COMPRESSION_RATIO: f64 = 17.0;
const POLYTROPIC_EXPONENT: f64 = 1.35;
const COMBUSTION_PRESSURE_RATIO: f64 = 3.2;
const BURN_START: f64 = -8.0 * PI / 180.0;
const BURN_DURATION: f64 = 60.0 * PI / 180.0;
const WIEBE_EFFICIENCY: f64 = 6.9;
/// An integer, so that the Wiebe exponent m + 1 is a product, not a `pow`.
const WIEBE_FORM: i32 = 1;
const EXHAUST_OPENS: f64 = 130.0 * PI / 180.0;
/// V(π)/V_d: clearance plus displaced volume.
const BDC_VOLUME: f64 = 1.0 / (COMPRESSION_RATIO - 1.0) + 1.0;

/// The built-in gauge pressure curve, Pa, as a function of crank angle.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FourStrokePressure {
    rod_ratio: f64,
    /// p_max / max p̂.
    scale: f64,
}

impl FourStrokePressure {
    /// `peak` in Pa (≥ 0); `rod_ratio` = l2/l1 > 1.
    pub fn new(peak: f64, rod_ratio: f64) -> Self {
        let unscaled = Self { rod_ratio, scale: 1.0 };
        // The maximum lies between TDC and 60° after it; a fine scan then a golden-section refinement.
        let samples = 600;
        let spacing = (PI / 3.0) / samples as f64;
        let coarse =
            (0..=samples).map(|k| k as f64 * spacing).max_by(|a, b| unscaled.gauge(*a).total_cmp(&unscaled.gauge(*b))).unwrap_or(0.0);
        let (mut lo, mut hi) = (coarse - spacing, coarse + spacing);
        let ratio = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..60 {
            let (a, b) = (hi - ratio * (hi - lo), lo + ratio * (hi - lo));
            if unscaled.gauge(a) < unscaled.gauge(b) {
                lo = a;
            } else {
                hi = b;
            }
        }
        Self { rod_ratio, scale: peak / unscaled.gauge(0.5 * (lo + hi)) }
    }

    /// Gauge pressure at `crank_angle` (rad, any value; period 4π).
    pub fn gauge(&self, crank_angle: f64) -> f64 {
        let (sin, cos) = libm::sincos(crank_angle);
        self.gauge_at(crank_angle, sin, cos)
    }

    /// [`Self::gauge`] with the crank angle's sine and cosine at hand (the linkage needs them too).
    pub fn gauge_at(&self, crank_angle: f64, sin: f64, cos: f64) -> f64 {
        self.scale * self.shape(crank_angle, sin, cos)
    }

    /// p̂ in units of the intake pressure.
    fn shape(&self, crank_angle: f64, sin: f64, cos: f64) -> f64 {
        let cycle = 4.0 * PI;
        let theta = crank_angle - cycle * nearest_whole(crank_angle / cycle);
        if theta.abs() > PI {
            return 0.0;
        }
        let burnt = if theta > BURN_START {
            1.0 - libm::exp(-WIEBE_EFFICIENCY * ((theta - BURN_START) / BURN_DURATION).powi(WIEBE_FORM + 1))
        } else {
            0.0
        };
        let blowdown =
            if theta > EXHAUST_OPENS { libm::cos(FRAC_PI_2 * (theta - EXHAUST_OPENS) / (PI - EXHAUST_OPENS)).powi(2) } else { 1.0 };
        let expansion = libm::pow(BDC_VOLUME / self.volume(sin, cos), POLYTROPIC_EXPONENT);
        (expansion * (1.0 + (COMBUSTION_PRESSURE_RATIO - 1.0) * burnt) - 1.0) * blowdown
    }

    /// Cylinder volume over displaced volume at a crank angle of sine `sin` and cosine `cos`.
    fn volume(&self, sin: f64, cos: f64) -> f64 {
        let lambda = self.rod_ratio;
        let s = sin / lambda;
        1.0 / (COMPRESSION_RATIO - 1.0) + 0.5 * ((1.0 - cos) + lambda * (1.0 - (1.0 - s * s).sqrt()))
    }
}

/// The whole number nearest `x`, ties away from zero, as `x.round()` but for |x| < 2⁵² by a
/// conversion to an integer: baseline x86-64 has no rounding instruction, so `round` is a call
/// in the crank train's every evaluation. Where `x + ½` rounds up to a whole number from
/// just below a tie, the result is one more than `round`'s: the crank angle then lies at ϑ = ±2π,
/// where the curve is 0 either way.
fn nearest_whole(x: f64) -> f64 {
    if x.abs() < 4.5e15 {
        (x + 0.5f64.copysign(x)) as i64 as f64
    } else {
        x.round()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn curve() -> FourStrokePressure {
        FourStrokePressure::new(8e6, 3.75)
    }

    #[test]
    fn peak_is_the_requested_value_shortly_after_firing_tdc() {
        let p = curve();
        let (angle, max) = (0..40_000).map(|k| k as f64 * 4.0 * PI / 40_000.0).map(|a| (a, p.gauge(a))).fold((0.0, f64::MIN), |best, x| {
            if x.1 > best.1 {
                x
            } else {
                best
            }
        });
        assert!((max - 8e6).abs() < 1e-6 * 8e6, "max {max}");
        assert!(angle > 0.0 && angle < 20f64.to_radians(), "peak at {} deg", angle.to_degrees());
    }

    #[test]
    fn gas_exchange_is_at_crankcase_pressure_and_the_curve_is_continuous() {
        let p = curve();
        for k in 0..1000 {
            let a = PI + 1e-9 + k as f64 * (2.0 * PI - 2e-9) / 999.0;
            assert_eq!(p.gauge(a), 0.0);
        }
        for edge in [-PI, PI] {
            assert!(p.gauge(edge - 1e-7).abs() < 1.0 && p.gauge(edge + 1e-7).abs() < 1.0);
        }
        // Gauge pressure is never below crankcase pressure and repeats every 4π.
        for k in 0..4000 {
            let a = -13.0 + 0.0071 * k as f64;
            assert!(p.gauge(a) >= 0.0);
            assert!((p.gauge(a) - p.gauge(a + 4.0 * PI)).abs() < 1e-6 * 8e6);
        }
    }

    #[test]
    fn nearest_whole_is_round_but_below_a_tie_where_the_curve_is_zero() {
        for x in [0.0, -0.0, 0.3, 0.5, -0.5, 0.7, -0.7, 1.5, -2.5, 1e6 + 0.5, -3e15 - 0.5, 5e15 + 1.0, -1e300, 2.6e-308] {
            assert_eq!(nearest_whole(x), x.round(), "{x}");
        }
        assert!(nearest_whole(f64::NAN).is_nan());
        // Just below a tie, x + ½ rounds to the next whole number; the angle is then 2π from a
        // firing TDC either way, in gas exchange.
        let below = 0.5f64.next_down();
        assert_eq!((nearest_whole(below), below.round()), (1.0, 0.0));
        let angle = below * 4.0 * PI;
        let p = curve();
        for theta in [angle, angle - 4.0 * PI] {
            assert_eq!(p.shape(theta, libm::sin(theta), libm::cos(theta)), 0.0);
        }
    }

    #[test]
    fn compression_before_combustion_is_polytropic() {
        // Before burn start p̂ + 1 = (V(BDC)/V)^n: the absolute pressure ratio between two angles.
        let p = curve();
        let (a, b) = (-2.5, -0.5);
        let shape = |x: f64| p.shape(x, libm::sin(x), libm::cos(x));
        let ratio = (shape(b) + 1.0) / (shape(a) + 1.0);
        let expected = libm::pow(p.volume(libm::sin(a), libm::cos(a)) / p.volume(libm::sin(b), libm::cos(b)), POLYTROPIC_EXPONENT);
        assert!((ratio - expected).abs() < 1e-12 * expected);
        assert_eq!(BDC_VOLUME, p.volume(libm::sin(PI), libm::cos(PI)));
    }
}
