//! An input over a communication step: its value at the step start and, when the host gives them
//! (fmi2SetRealInputDerivatives), its first and second time derivatives there, so that inside the step
//! `u(t) = u₀ + u̇₀ τ + ü₀ τ²/2` with τ = t − t₀. Without derivatives it is the value held, exactly.

use serde::{Deserialize, Serialize};

/// `u(t) = value + slope τ + curvature τ²/2`, τ = t − `time`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct InputPolynomial {
    /// t₀, s.
    pub time: f64,
    /// u(t₀).
    pub value: f64,
    /// du/dt at t₀, per second.
    pub slope: f64,
    /// d²u/dt² at t₀, per second squared.
    pub curvature: f64,
}

impl InputPolynomial {
    /// `value` held from any time on.
    pub fn held(value: f64) -> Self {
        Self { time: 0.0, value, slope: 0.0, curvature: 0.0 }
    }

    /// Whether the input is held (no derivatives): then every function below is the held value's,
    /// bit for bit as without this type.
    #[inline(always)]
    pub fn is_held(&self) -> bool {
        // slope == 0.0 && curvature == 0.0 (either zero's sign) in one test of the bits without
        // the sign bits: asked several times in every evaluation of the crank train.
        (self.slope.to_bits() | self.curvature.to_bits()) << 1 == 0
    }

    /// Whether `other` is the same input function: the same held value, or the same polynomial.
    pub fn same_as(&self, other: &Self) -> bool {
        (self.is_held() && other.is_held() && self.value == other.value) || self == other
    }

    /// u(t).
    #[inline(always)]
    pub fn at(&self, t: f64) -> f64 {
        if self.is_held() {
            return self.value;
        }
        let tau = t - self.time;
        self.value + tau * (self.slope + 0.5 * tau * self.curvature)
    }

    /// du/dt at t.
    #[inline(always)]
    pub fn rate(&self, t: f64) -> f64 {
        self.slope + (t - self.time) * self.curvature
    }

    /// ∫ u from t₀ to t, exact for the polynomial.
    #[inline(always)]
    pub fn integral(&self, t: f64) -> f64 {
        let tau = t - self.time;
        if self.is_held() {
            return self.value * tau;
        }
        tau * (self.value + tau * (0.5 * self.slope + tau * self.curvature / 6.0))
    }

    /// The same polynomial expanded about `t` instead of t₀.
    pub fn from(&self, t: f64) -> Self {
        Self { time: t, value: self.at(t), slope: self.rate(t), curvature: self.curvature }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn value_rate_and_integral_of_a_quadratic() {
        let u = InputPolynomial { time: 2.0, value: 3.0, slope: -4.0, curvature: 10.0 };
        let (t, tau) = (2.5, 0.5);
        assert_eq!(u.at(t), 3.0 - 4.0 * tau + 5.0 * tau * tau);
        assert_eq!(u.rate(t), -4.0 + 10.0 * tau);
        assert!((u.integral(t) - (3.0 * tau - 2.0 * tau * tau + 10.0 / 6.0 * tau.powi(3))).abs() < 1e-15);
        let moved = u.from(t);
        for s in [2.0, 2.7, 3.1] {
            assert!((moved.at(s) - u.at(s)).abs() < 1e-14);
            assert!((moved.integral(s) - (u.integral(s) - u.integral(t))).abs() < 1e-14);
        }
    }

    #[test]
    fn held_is_the_value_bit_for_bit() {
        let u = InputPolynomial::held(125.66);
        assert!(u.is_held());
        let with = |slope: f64, curvature: f64| InputPolynomial { slope, curvature, ..u };
        assert!(with(-0.0, 0.0).is_held() && with(0.0, -0.0).is_held());
        assert!([(f64::NAN, 0.0), (0.0, f64::MIN_POSITIVE), (-5e-324, 0.0), (0.0, f64::INFINITY)]
            .iter()
            .all(|&(s, c)| !with(s, c).is_held()));
        assert_eq!((u.at(7.3), u.rate(7.3), u.integral(0.1)), (125.66, 0.0, 125.66 * 0.1));
    }
}
