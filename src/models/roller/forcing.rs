//! Farahanchi's linearized slider crank (thesis ch. 2) in its own dimensionless variables:
//! time τ = crank angle θ, ( )' = d/dτ, rod deviation ψ from its nominal (zero-clearance) angle.
//!
//! Derivation (Lagrange with q = ψ, crank at constant speed, rod uniform, roller piston): with
//! u = φ − ψ the rod direction angle is −u, and
//!   T = ½(M + m) r²θ̇² + ½ I u̇² − (M + m/2) r l θ̇ u̇ cos(θ + u),  I = M l² + m l²/4 + J_r,
//!   Q' = −c₂ (ψ̇ − φ̇ − θ̇)   (crank-pin damping on the relative rotation of rod and crank).
//! The ψ equation is I (ψ̈ − φ̈) − (M + m/2) r l θ̇² sin(θ + φ − ψ) = Q'; divided by M l² Ω² and
//! linearized in ψ (sin φ = ξ sin τ, cos φ = Λ) it is eq 2.13, a ψ'' + b ψ' + c(τ) ψ = f(τ), with
//!   a = 1 + α/4 + β,  b = λ,  c = (1 + α/2) ξ cos(τ + φ),
//!   f = (1 + α/4 + β) φ'' + (1 + α/2) ξ sin(τ + φ) + λ (1 + φ'),  φ'' = (ξ³ − ξ) sin τ / Λ³.
//! The thesis prints (1 + α/4 − β) φ'' (ARCHITECTURE.md §6.1): it took the rod's angular velocity as
//! φ̇ + ψ̇, which flips the sign of J_r φ̈. Both forms are offered; the unit tests below check each
//! against a finite-difference evaluation of the exact Lagrangian it comes from.

use serde::{Deserialize, Serialize};

/// Which f(τ) of eq 2.13 drives the roller.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Forcing {
    /// Exactly as printed in the thesis: reproduces its figures and tables.
    Printed,
    /// Consistent with the rod's kinematics (rod angular velocity ψ̇ − φ̇).
    Corrected,
}

/// Where sliding is possible over a crank cycle, as the regions of Fig 2.10 classify (ρ, λ).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum SlidingRegion {
    /// I: part of the cycle on the upper wall, part on the lower (Figs 2.4–2.6).
    Both,
    /// II: the whole cycle on the upper wall, and an interval on the lower too (Fig 2.7).
    UpperAlwaysLowerSometimes,
    /// III: the whole cycle on the upper wall, never on the lower (Fig 2.9).
    UpperOnly,
    /// Any other pattern (not met in the thesis's parameter range).
    Other,
}

/// A value and its first two derivatives with respect to τ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Jet {
    /// The value.
    pub value: f64,
    /// Its first derivative.
    pub d1: f64,
    /// Its second derivative.
    pub d2: f64,
}

/// The dimensionless mechanism of the thesis: ξ = r/l, α = m/M, β = J_r/(M l²).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct RollerMechanism {
    /// ξ = r/l, crank radius over rod length.
    pub xi: f64,
    /// α = m/M, rod over piston mass.
    pub alpha: f64,
    /// β = J_r/(M l²), the rod's scaled inertia.
    pub beta: f64,
    /// The side force's pattern.
    pub forcing: Forcing,
}

/// The mechanism at one crank angle τ: sin τ, cos τ and Λ = cos φ with its derivatives, computed
/// once for every term of an evaluation (when each term computed its own, sine and cosine were a
/// third of the roller's run time).
#[derive(Clone, Copy, Debug)]
pub struct AtAngle {
    mechanism: RollerMechanism,
    sin: f64,
    cos: f64,
    /// Λ = cos φ = √(1 − ξ² sin²τ), with Λ' = −ξ² sin 2τ / (2Λ) and Λ'' = −ξ² cos 2τ / Λ − Λ'²/Λ.
    pub cos_phi: Jet,
}

impl RollerMechanism {
    /// The mechanism's terms at crank angle `tau`.
    pub fn at(&self, tau: f64) -> AtAngle {
        let xi2 = self.xi * self.xi;
        let (s, c) = crate::models::numerics::trig::sin_cos(tau);
        let value = (1.0 - xi2 * s * s).sqrt();
        let d1 = -xi2 * s * c / value;
        let d2 = -xi2 * (c * c - s * s) / value - d1 * d1 / value;
        AtAngle { mechanism: *self, sin: s, cos: c, cos_phi: Jet { value, d1, d2 } }
    }

    /// a of eq 2.13: the rod and roller inertia about the crank pin, over M l².
    pub fn inertia(&self) -> f64 {
        1.0 + self.alpha / 4.0 + self.beta
    }

    /// (f_u, f_l) of eq 2.29, linearized like eq 2.13: the dimensionless wall forces F/(M l Ω²) that
    /// keep the roller on ψ = ψ_max (upper wall) or ψ = ψ_min (lower wall); positive = compressive.
    /// The upper wall acts on ψ through ∂y/∂ψ = l cos(φ − ψ) ≈ l Λ, so a ψ_max'' = a ψ''_free − Λ f_u.
    pub fn constraint_forces(&self, tau: f64, lambda: f64, rho: f64) -> (f64, f64) {
        let (a, at) = (self.inertia(), self.at(tau));
        let cos_phi = at.cos_phi.value;
        let limit = at.psi_max(rho);
        let upper = a * (at.free_acceleration(limit.value, limit.d1, lambda) - limit.d2) / cos_phi;
        let lower = a * (-limit.d2 - at.free_acceleration(-limit.value, -limit.d1, lambda)) / cos_phi;
        (upper, lower)
    }
    /// The region of Fig 2.10 for (λ, ρ), from the signs of f_u, f_l on `samples` crank angles.
    pub fn sliding_region(&self, lambda: f64, rho: f64, samples: usize) -> SlidingRegion {
        let (mut upper_always, mut upper_some, mut lower_some) = (true, false, false);
        for k in 0..samples {
            let (fu, fl) = self.constraint_forces(2.0 * std::f64::consts::PI * k as f64 / samples as f64, lambda, rho);
            upper_always &= fu > 0.0;
            upper_some |= fu > 0.0;
            lower_some |= fl > 0.0;
        }
        match (upper_always, upper_some, lower_some) {
            (true, _, true) => SlidingRegion::UpperAlwaysLowerSometimes,
            (true, _, false) => SlidingRegion::UpperOnly,
            (false, true, true) => SlidingRegion::Both,
            _ => SlidingRegion::Other,
        }
    }

    /// Torque the drive must apply to hold the crank speed, over M l² Ω², at ψ with rates ψ', ψ''.
    /// Power balance of the consistent kinetic energy T (module doc; crank inertia does no work at
    /// constant speed, frictionless walls do none while sliding): τ Ω = dT/dt + c₂ (ω_rod − Ω)², i.e.
    /// τ = a u'u'' − k u'' cos(τ + u) + k u'(1 + u') sin(τ + u) + λ (1 + u')², with u = φ − ψ and
    /// k = (1 + α/2) ξ. Exact in ψ; with the printed forcing it is the torque of the corrected physics.
    pub fn drive_torque(&self, tau: f64, psi: [f64; 3], lambda: f64) -> f64 {
        let phi = self.at(tau).rod_angle();
        let (u, du, ddu) = (phi.value - psi[0], phi.d1 - psi[1], phi.d2 - psi[2]);
        let k = (1.0 + self.alpha / 2.0) * self.xi;
        let (s, c) = libm::sincos(tau + u);
        self.inertia() * du * ddu - k * ddu * c + k * du * (1.0 + du) * s + lambda * (1.0 + du) * (1.0 + du)
    }

    /// Kinetic energy of rod and roller over M l² Ω² at crank angle τ, exact in ψ: the rod's
    /// angular velocity is ψ' − φ' (module doc), its centre of mass at mid-length.
    pub fn kinetic_energy(&self, tau: f64, psi: f64, dpsi: f64) -> f64 {
        self.kinetic_energy_with(tau, psi, dpsi, dpsi - self.at(tau).rod_angle().d1)
    }

    /// The same for a given rod angular velocity over Ω (the thesis's eq 2.1 takes another).
    fn kinetic_energy_with(&self, tau: f64, psi: f64, dpsi: f64, rod_rate: f64) -> f64 {
        let phi = self.at(tau).rod_angle();
        let (u, du) = (phi.value - psi, phi.d1 - dpsi);
        let (s, c) = libm::sincos(tau);
        // Speed² of the point a fraction k along the rod from the crank pin (k = 1: the roller).
        let speed2 = |k: f64| {
            let vx = -self.xi * s - k * du * libm::sin(u);
            let vy = self.xi * c - k * du * libm::cos(u);
            vx * vx + vy * vy
        };
        0.5 * self.alpha * speed2(0.5) + 0.5 * self.beta * rod_rate * rod_rate + 0.5 * speed2(1.0)
    }
}

impl AtAngle {
    /// φ' = ξ cos τ / Λ and φ'' = (ξ³ − ξ) sin τ / Λ³.
    fn rod_rates(&self) -> (f64, f64) {
        let (xi, cos_phi) = (self.mechanism.xi, self.cos_phi.value);
        (xi * self.cos / cos_phi, (xi.powi(3) - xi) * self.sin / cos_phi.powi(3))
    }

    /// The rod angle φ (value) with φ' and φ''.
    pub fn rod_angle(&self) -> Jet {
        let (d1, d2) = self.rod_rates();
        Jet { value: libm::asin(self.mechanism.xi * self.sin), d1, d2 }
    }

    /// ψ_max = ρ/Λ (eq 2.14; ψ_min = −ψ_max, eq 2.15) for the dimensionless clearance ρ = Δ/l.
    pub fn psi_max(&self, rho: f64) -> Jet {
        let l = self.cos_phi;
        Jet {
            value: rho / l.value,
            d1: -rho * l.d1 / (l.value * l.value),
            d2: rho * (2.0 * l.d1 * l.d1 / l.value - l.d2) / (l.value * l.value),
        }
    }

    /// c(τ) of eq 2.13: (1 + α/2) ξ (Λ cos τ − ξ sin²τ).
    pub fn stiffness(&self) -> f64 {
        let (m, s, c) = (&self.mechanism, self.sin, self.cos);
        (1.0 + m.alpha / 2.0) * m.xi * (self.cos_phi.value * c - m.xi * s * s)
    }

    /// f(τ) of eq 2.13 at damping λ = c₂/(M l² Ω).
    pub fn forcing(&self, lambda: f64) -> f64 {
        let (m, s, c) = (&self.mechanism, self.sin, self.cos);
        let (phi_d1, phi_d2) = self.rod_rates();
        let phi_coefficient = match m.forcing {
            Forcing::Printed => 1.0 + m.alpha / 4.0 - m.beta,
            Forcing::Corrected => m.inertia(),
        };
        // sin(τ + φ) = Λ sin τ + ξ sin τ cos τ.
        phi_coefficient * phi_d2 + (1.0 + m.alpha / 2.0) * m.xi * s * (self.cos_phi.value + m.xi * c) + lambda * (1.0 + phi_d1)
    }

    /// ψ'' of free flight (eqs 3.1–3.3): (f − λψ' − cψ)/a.
    pub fn free_acceleration(&self, psi: f64, dpsi: f64, lambda: f64) -> f64 {
        (self.forcing(lambda) - lambda * dpsi - self.stiffness() * psi) / self.mechanism.inertia()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// The thesis's mechanism (section 4.1).
    fn thesis(forcing: Forcing) -> RollerMechanism {
        RollerMechanism { xi: 0.3030, alpha: 1.9, beta: 0.4719, forcing }
    }

    /// Exact kinetic energy with l = M = Ω = 1, for a rod angular velocity ψ̇ − φ̇ (consistent) or
    /// φ̇ + ψ̇ (as the thesis writes it in eq 2.1).
    fn kinetic_energy(sc: &RollerMechanism, consistent: bool, psi: f64, dpsi: f64, t: f64) -> f64 {
        let phi = sc.at(t).rod_angle();
        let rod_rate = if consistent { dpsi - phi.d1 } else { phi.d1 + dpsi };
        sc.kinetic_energy_with(t, psi, dpsi, rod_rate)
    }

    /// d/dt ∂T/∂ψ̇ − ∂T/∂ψ − Q' along ψ(t), by central differences (exact for T quadratic in ψ̇).
    fn lagrange_residual(sc: &RollerMechanism, consistent: bool, lambda: f64, path: &dyn Fn(f64) -> [f64; 2], t: f64) -> f64 {
        let h = 1e-3;
        let momentum = |t: f64| {
            let [p, dp] = path(t);
            (kinetic_energy(sc, consistent, p, dp + h, t) - kinetic_energy(sc, consistent, p, dp - h, t)) / (2.0 * h)
        };
        let [p, dp] = path(t);
        let dt_momentum = (momentum(t + h) - momentum(t - h)) / (2.0 * h);
        let d_psi = (kinetic_energy(sc, consistent, p + h, dp, t) - kinetic_energy(sc, consistent, p - h, dp, t)) / (2.0 * h);
        let generalized_damping = -lambda * (dp - sc.at(t).rod_angle().d1 - 1.0);
        dt_momentum - d_psi - generalized_damping
    }

    /// Eq 2.13 of each form agrees with the Lagrangian it comes from up to O(ψ²).
    fn check_linearization(forcing: Forcing, consistent: bool) {
        let sc = thesis(forcing);
        let lambda = 0.05;
        for &eps in &[0.0, 1e-3] {
            let path = move |t: f64| [eps * libm::sin(1.7 * t + 0.3), 1.7 * eps * libm::cos(1.7 * t + 0.3)];
            for k in 0..24 {
                let t = 2.0 * PI * k as f64 / 24.0 + 0.1;
                let [p, dp] = path(t);
                let ddp = -1.7 * 1.7 * p;
                let linear = sc.inertia() * ddp + lambda * dp + sc.at(t).stiffness() * p - sc.at(t).forcing(lambda);
                let exact = lagrange_residual(&sc, consistent, lambda, &path, t);
                assert!((linear - exact).abs() < 1e-6 + 2.0 * eps * eps, "{forcing:?} eps {eps} t {t}: {linear} vs {exact}");
            }
        }
    }

    #[test]
    fn corrected_forcing_is_the_linearized_lagrangian() {
        check_linearization(Forcing::Corrected, true);
    }

    #[test]
    fn printed_forcing_follows_from_the_thesis_rod_angular_velocity() {
        check_linearization(Forcing::Printed, false);
    }

    #[test]
    fn the_two_forms_differ_by_two_beta_phi_second_derivative() {
        let (p, c) = (thesis(Forcing::Printed), thesis(Forcing::Corrected));
        for k in 0..16 {
            let t = k as f64 * 0.4;
            let difference = c.at(t).forcing(0.1) - p.at(t).forcing(0.1);
            assert!((difference - 2.0 * 0.4719 * c.at(t).rod_angle().d2).abs() < 1e-14);
        }
        // Large enough to matter: |2βφ''| reaches 2β(ξ − ξ³) ≈ 0.26 at τ = π/2.
        assert!((c.at(PI / 2.0).forcing(0.0) - p.at(PI / 2.0).forcing(0.0)).abs() > 0.25);
    }

    /// `sc.forcing` equals `formula(ξ, α, β, λ, τ, Λ)` over a cycle.
    fn assert_forcing_is(sc: RollerMechanism, lambda: f64, formula: impl Fn(f64, f64, f64, f64, f64, f64) -> f64) {
        for k in 0..16 {
            let t = k as f64 * 0.41;
            let big = (1.0 - sc.xi * sc.xi * libm::sin(t).powi(2)).sqrt();
            assert!((sc.at(t).forcing(lambda) - formula(sc.xi, sc.alpha, sc.beta, lambda, t, big)).abs() < 1e-14);
        }
    }

    /// The printed f(τ), term by term as eq 2.13 shows it.
    #[test]
    fn printed_forcing_is_eq_2_13_verbatim() {
        assert_forcing_is(thesis(Forcing::Printed), 0.2, |xi, al, be, lam, t, big| {
            (al / 4.0 + 1.0 - be) * (xi.powi(3) - xi) * libm::sin(t) / big.powi(3)
                + (xi * big + 0.5 * al * xi * big) * libm::sin(t)
                + (0.5 * xi * xi + 0.25 * xi * xi * al) * libm::sin(2.0 * t)
                + lam
                + lam * xi * libm::cos(t) / big
        });
    }

    /// The alternative form of ARCHITECTURE.md §6.1 is the same function as the corrected one.
    #[test]
    fn corrected_forcing_matches_design_form() {
        assert_forcing_is(thesis(Forcing::Corrected), 0.07, |xi, al, be, lam, t, big| {
            let (s, c) = libm::sincos(t);
            (1.0 + al / 4.0 + be) * xi.powi(3) * s * c * c / big.powi(3) - xi * s * ((1.0 + al / 4.0) * xi * xi * s * s + be) / big
                + (0.5 + al / 4.0) * xi * xi * libm::sin(2.0 * t)
                + al / 4.0 * xi * big * s
                + lam
                + lam * xi * c / big
        });
    }

    /// ψ_max of eq 2.14 is the linearization of the exact wall contact sin(φ − ψ) = sin φ − ρ (eq A.1),
    /// and ψ_max' = ψ_max ξ² sin τ cos τ / Λ², the moving-wall rate of eq 2.17.
    #[test]
    fn psi_max_is_the_linearized_wall_and_its_rate_is_eq_2_17() {
        let sc = thesis(Forcing::Corrected);
        let rho = 1e-3;
        for k in 0..16 {
            let t = k as f64 * 0.4;
            let phi = sc.at(t).rod_angle().value;
            let exact = phi - libm::asin(libm::sin(phi) - rho);
            let jet = sc.at(t).psi_max(rho);
            assert!((jet.value - exact).abs() < rho * rho);
            let big = sc.at(t).cos_phi.value;
            assert!((jet.d1 - jet.value * sc.xi * sc.xi * libm::sin(t) * libm::cos(t) / (big * big)).abs() < 1e-15);
            let h = 1e-4;
            let d2 = (sc.at(t + h).psi_max(rho).value - 2.0 * jet.value + sc.at(t - h).psi_max(rho).value) / (h * h);
            assert!((jet.d2 - d2).abs() < 1e-8);
            let phi_d2 = (sc.at(t + h).rod_angle().value - 2.0 * phi + sc.at(t - h).rod_angle().value) / (h * h);
            assert!((sc.at(t).rod_angle().d2 - phi_d2).abs() < 1e-6);
        }
    }

    /// Crank angles in [0, 2π) where f_u (upper) or f_l (lower) changes sign, on a fine grid.
    fn sign_changes(sc: &RollerMechanism, lambda: f64, rho: f64, upper: bool) -> Vec<f64> {
        let n = 20000;
        let force = |k: usize| {
            let (fu, fl) = sc.constraint_forces(2.0 * PI * k as f64 / n as f64, lambda, rho);
            if upper {
                fu
            } else {
                fl
            }
        };
        (1..=n).filter(|&k| (force(k) > 0.0) != (force(k - 1) > 0.0)).map(|k| 2.0 * PI * k as f64 / n as f64).collect()
    }

    fn assert_near(found: &[f64], expected: &[f64], tol: f64) {
        assert_eq!(found.len(), expected.len(), "{found:?} vs {expected:?}");
        for (f, e) in found.iter().zip(expected) {
            assert!((f - e).abs() < tol, "{found:?} vs {expected:?}");
        }
    }

    /// Fig 2.9: at λ = 0.35 the upper wall holds the roller over the whole cycle, the lower never.
    #[test]
    fn fig_2_9_upper_force_compressive_over_the_whole_cycle() {
        let sc = thesis(Forcing::Printed);
        for k in 0..720 {
            let (fu, fl) = sc.constraint_forces(k as f64 * PI / 360.0, 0.35, 0.01);
            assert!(fu > 0.0 && fl < 0.0);
        }
    }

    /// Figs 2.7/2.8: at (ρ, λ) = (0.02, 0.267) the upper force is compressive all cycle and the lower
    /// one too for about 4.96 < θ < 5.14.
    #[test]
    fn fig_2_7_both_forces_compressive_on_a_small_interval() {
        let sc = thesis(Forcing::Printed);
        assert!(sign_changes(&sc, 0.267, 0.02, true).is_empty());
        assert!(sc.constraint_forces(1.0, 0.267, 0.02).0 > 0.0);
        assert_near(&sign_changes(&sc, 0.267, 0.02, false), &[4.96, 5.14], 0.02);
        assert!(sc.constraint_forces(5.05, 0.267, 0.02).1 > 0.0);
    }

    /// Fig 2.4: at (ρ, λ) = (0.01, 0.01) the roller may slide on the upper wall for 0 < θ < ≈π and on
    /// the lower for ≈π < θ < ≈2π; the crossings near π and 2π are slightly detuned by ρ and λ.
    #[test]
    fn fig_2_4_sliding_alternates_between_the_walls() {
        let sc = thesis(Forcing::Printed);
        assert_near(&sign_changes(&sc, 0.01, 0.01, true), &[3.22, 6.27], 0.02);
        assert_near(&sign_changes(&sc, 0.01, 0.01, false), &[3.16, 6.24], 0.02);
        let (fu, fl) = sc.constraint_forces(1.5, 0.01, 0.01);
        assert!(fu > 0.0 && fl < 0.0);
        let (fu, fl) = sc.constraint_forces(4.5, 0.01, 0.01);
        assert!(fu < 0.0 && fl > 0.0);
    }

    /// With a massless rod, no damping and ψ ≡ 0 the drive only accelerates the piston:
    /// τ Ω = M ẋ ẍ with x = r cos θ + l cos φ (finite differences of the nominal kinematics).
    #[test]
    fn drive_torque_of_a_massless_rod_is_the_piston_inertia_torque() {
        let sc = RollerMechanism { xi: 0.3030, alpha: 0.0, beta: 0.0, forcing: Forcing::Corrected };
        let x = |t: f64| sc.xi * libm::cos(t) + sc.at(t).cos_phi.value;
        let h = 1e-4;
        for k in 0..24 {
            let t = k as f64 * 0.27;
            let dx = (x(t + h) - x(t - h)) / (2.0 * h);
            let ddx = (x(t + h) - 2.0 * x(t) + x(t - h)) / (h * h);
            assert!((sc.drive_torque(t, [0.0; 3], 0.0) - dx * ddx).abs() < 1e-6, "t {t}");
        }
    }

    /// Over one cycle of the rigid (ψ ≡ 0) mechanism the drive's work equals the damper's dissipation
    /// λ ∫(1 + φ')² dτ: the inertial part averages out.
    #[test]
    fn drive_work_over_a_cycle_is_the_damping_loss() {
        let sc = thesis(Forcing::Corrected);
        let (n, lambda) = (4000, 0.2);
        let dt = 2.0 * PI / n as f64;
        let (mut work, mut loss) = (0.0, 0.0);
        for k in 0..n {
            let t = k as f64 * dt;
            work += sc.drive_torque(t, [0.0; 3], lambda) * dt;
            loss += lambda * (1.0 + sc.at(t).rod_angle().d1).powi(2) * dt;
        }
        assert!((work - loss).abs() < 1e-9 && loss > 1.0);
    }

    /// The three examples of Fig 2.10's regions.
    #[test]
    fn fig_2_10_regions_of_the_thesis_examples() {
        let sc = thesis(Forcing::Printed);
        assert_eq!(sc.sliding_region(0.01, 0.01, 2000), SlidingRegion::Both);
        assert_eq!(sc.sliding_region(0.1, 0.01, 2000), SlidingRegion::Both);
        assert_eq!(sc.sliding_region(0.267, 0.02, 2000), SlidingRegion::UpperAlwaysLowerSometimes);
        assert_eq!(sc.sliding_region(0.35, 0.01, 2000), SlidingRegion::UpperOnly);
    }

    /// Symmetries at ρ = λ = 0 (section 2.6): f_u = −f_l, and f_u is odd in θ, so it vanishes at 0 and
    /// π. The thesis writes the second as f_u(θ + π) = −f_u(θ), which the rod's obliquity breaks: the
    /// half-cycles are mirror images, not shifted copies.
    #[test]
    fn constraint_force_symmetries_at_zero_clearance_and_damping() {
        for forcing in [Forcing::Printed, Forcing::Corrected] {
            let sc = thesis(forcing);
            for k in 0..32 {
                let t = k as f64 * 0.2;
                let (fu, fl) = sc.constraint_forces(t, 0.0, 0.0);
                assert!((fu + fl).abs() < 1e-12);
                assert!((sc.constraint_forces(-t, 0.0, 0.0).0 + fu).abs() < 1e-12);
                assert!((sc.constraint_forces(t + PI, 0.0, 0.0).0 + fu).abs() > 1e-3 || libm::sin(t).abs() < 0.1);
            }
        }
    }
}
