//! The step's continuous extension: the quintic through both ends' values, rates and accelerations.

use nalgebra::SVector;

/// Quintic Hermite interpolant of one step, matching `q`, `q̇`, `q̈` at both ends; `q` is any
/// smooth function of time: the coordinates, or the gaps `h` (with `ḣ` and `ḧ = J q̈ + d`).
///
/// Its interpolation error is O(dt⁶), below the O(dt⁵) local error of the RK4 step itself, so
/// event location on it is as accurate as the step; the stepper still confirms every located
/// event on the RK4 map (see `search.rs`).
#[derive(Clone, Debug)]
pub(crate) struct Hermite5<const N: usize> {
    pub t0: f64,
    pub dt: f64,
    pub q0: SVector<f64, N>,
    pub v0: SVector<f64, N>,
    pub a0: SVector<f64, N>,
    pub q1: SVector<f64, N>,
    pub v1: SVector<f64, N>,
    pub a1: SVector<f64, N>,
}

impl<const N: usize> Hermite5<N> {
    /// `(q, q̇)` at time `t ∈ [t0, t0 + dt]`.
    pub fn at(&self, t: f64) -> (SVector<f64, N>, SVector<f64, N>) {
        let ([d1, d2, d3, d4, d5], dt) = (self.velocity_weights(t), self.dt);
        let v = (self.q1 - self.q0) * (d3 / dt) + self.v0 * d1 + self.v1 * d4 + (self.a0 * d2 + self.a1 * d5) * dt;
        (self.position(t), v)
    }

    /// Component `i` of `q̇` at time `t`: the event search looks for the bottom of a gap's dip.
    pub fn velocity_of(&self, i: usize, t: f64) -> f64 {
        let ([d1, d2, d3, d4, d5], dt) = (self.velocity_weights(t), self.dt);
        (self.q1[i] - self.q0[i]) * (d3 / dt) + self.v0[i] * d1 + self.v1[i] * d4 + (self.a0[i] * d2 + self.a1[i] * d5) * dt
    }

    /// The weights of `q̇₀`, `q̈₀ dt`, `(q₁ − q₀)/dt`, `q̇₁`, `q̈₁ dt` in `q̇(t)`.
    fn velocity_weights(&self, t: f64) -> [f64; 5] {
        let s = (t - self.t0) / self.dt;
        let (s2, s3, s4) = (s * s, s * s * s, s * s * s * s);
        [
            1.0 - 18.0 * s2 + 32.0 * s3 - 15.0 * s4,
            s - 4.5 * s2 + 6.0 * s3 - 2.5 * s4,
            30.0 * s2 - 60.0 * s3 + 30.0 * s4,
            -12.0 * s2 + 28.0 * s3 - 15.0 * s4,
            1.5 * s2 - 4.0 * s3 + 2.5 * s4,
        ]
    }

    /// `q` alone at time `t`.
    pub fn position(&self, t: f64) -> SVector<f64, N> {
        let [h1, h2, h3, h4, h5] = self.position_weights(t);
        let dt = self.dt;
        self.q0 + (self.q1 - self.q0) * h3 + (self.v0 * h1 + self.v1 * h4) * dt + (self.a0 * h2 + self.a1 * h5) * (dt * dt)
    }

    /// Component `i` of `q` at time `t`: the event search watches one gap at a time.
    pub fn position_of(&self, i: usize, t: f64) -> f64 {
        let [h1, h2, h3, h4, h5] = self.position_weights(t);
        let dt = self.dt;
        self.q0[i]
            + (self.q1[i] - self.q0[i]) * h3
            + (self.v0[i] * h1 + self.v1[i] * h4) * dt
            + (self.a0[i] * h2 + self.a1[i] * h5) * (dt * dt)
    }

    /// The weights of `q̇₀ dt`, `q̈₀ dt²`, `q₁ − q₀`, `q̇₁ dt`, `q̈₁ dt²` in `q(t)`.
    fn position_weights(&self, t: f64) -> [f64; 5] {
        let s = (t - self.t0) / self.dt;
        let (s2, s3) = (s * s, s * s * s);
        let (s4, s5) = (s3 * s, s3 * s2);
        [
            s - 6.0 * s3 + 8.0 * s4 - 3.0 * s5,
            0.5 * s2 - 1.5 * s3 + 1.5 * s4 - 0.5 * s5,
            10.0 * s3 - 15.0 * s4 + 6.0 * s5,
            -4.0 * s3 + 7.0 * s4 - 3.0 * s5,
            0.5 * s3 - s4 + 0.5 * s5,
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector1;

    /// The interpolant reproduces any quintic exactly (independent of the integrator).
    #[test]
    fn hermite_reproduces_a_quintic() {
        let p = |t: f64| 1.0 - 2.0 * t + 0.5 * t * t + 3.0 * t.powi(3) - t.powi(4) + 0.7 * t.powi(5);
        let dp = |t: f64| -2.0 + t + 9.0 * t * t - 4.0 * t.powi(3) + 3.5 * t.powi(4);
        let ddp = |t: f64| 1.0 + 18.0 * t - 12.0 * t * t + 14.0 * t.powi(3);
        let (t0, dt) = (0.3, 0.9);
        let v = |f: &dyn Fn(f64) -> f64, t| Vector1::new(f(t));
        let h = Hermite5 {
            t0,
            dt,
            q0: v(&p, t0),
            v0: v(&dp, t0),
            a0: v(&ddp, t0),
            q1: v(&p, t0 + dt),
            v1: v(&dp, t0 + dt),
            a1: v(&ddp, t0 + dt),
        };
        for k in 0..=10 {
            let t = t0 + dt * k as f64 / 10.0;
            let (q, qd) = h.at(t);
            assert!((q[0] - p(t)).abs() < 1e-13 && (h.position_of(0, t) - p(t)).abs() < 1e-13, "q at {t}");
            assert!((qd[0] - dp(t)).abs() < 1e-12, "q̇ at {t}");
        }
    }
}
