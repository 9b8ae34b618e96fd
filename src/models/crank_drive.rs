//! The crank train as a `System` for the core, in its two crank modes.
//!
//! - [`PrescribedCrank`]: φ1(t) = φ1_ref + ω (t − t_ref) is given, q = (φ2, φ3). Rows 2–3 of the linkage
//!   equations with φ̇1 = ω, φ̈1 = 0; the gaps become rheonomic: `∂h/∂t = (∂h/∂φ1) ω` and d keeps the ω²
//!   term. The crank row then yields the drive torque.
//! - [`FreeCrank`]: q = (φ1, φ2, φ3) under gas force, load torque and damping (A&K eq 55).

use super::crank_linkage::{Linkage, Loads};
use super::pressure::FourStrokePressure;
use super::{Inputs, Parameters};
use crate::dynamics::{Evaluation, System};
use nalgebra::{Matrix4x2, SVector, Vector2, Vector3, Vector4};
use serde::{Deserialize, Serialize};

/// Where the gas pressure comes from.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum GasPressure {
    /// The built-in four-stroke curve of crank angle.
    BuiltIn(FourStrokePressure),
    /// The host's `gas_pressure` input, Pa, held over a step.
    Held(f64),
}

/// What drives the links apart from the crank motion: linkage, pressure, restitution.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Engine {
    pub linkage: Linkage,
    pub pressure: GasPressure,
    /// Crown area π d²/4, m².
    pub crown_area: f64,
    pub restitution: f64,
}

impl Engine {
    /// The engine of validated parameters; a held pressure starts at the input's default.
    pub fn new(params: &Parameters) -> Self {
        let pressure = match params.pressure_source {
            1 => GasPressure::Held(Inputs::default().gas_pressure),
            _ => GasPressure::BuiltIn(FourStrokePressure::new(params.peak_pressure, params.rod_length / params.crank_radius)),
        };
        Self {
            linkage: Linkage::new(params),
            pressure,
            crown_area: 0.25 * std::f64::consts::PI * params.piston_diameter * params.piston_diameter,
            restitution: params.restitution,
        }
    }

    /// Gas force toward the crank at crank angle φ1, N.
    pub fn gas_force(&self, crank_angle: f64) -> f64 {
        let p = match &self.pressure {
            GasPressure::BuiltIn(curve) => curve.gauge(crank_angle),
            GasPressure::Held(p) => *p,
        };
        p * self.crown_area
    }
}

/// Rod and piston with the crank turning at a held speed.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PrescribedCrank {
    pub engine: Engine,
    angle_ref: f64,
    time_ref: f64,
    speed: f64,
}

impl PrescribedCrank {
    pub fn new(engine: Engine, crank_angle: f64, time: f64, speed: f64) -> Self {
        Self { engine, angle_ref: crank_angle, time_ref: time, speed }
    }

    pub fn crank_angle(&self, t: f64) -> f64 {
        self.angle_ref + self.speed * (t - self.time_ref)
    }

    pub fn speed(&self) -> f64 {
        self.speed
    }

    /// Holds a new crank speed from time `t` on, keeping the crank angle continuous.
    pub fn hold_speed(&mut self, t: f64, speed: f64) {
        if speed != self.speed {
            self.angle_ref = self.crank_angle(t);
            self.time_ref = t;
            self.speed = speed;
        }
    }

    /// Full coordinates and velocities at `(t, q, q̇)`.
    pub fn full_state(&self, t: f64, q: &Vector2<f64>, qd: &Vector2<f64>) -> (Vector3<f64>, Vector3<f64>) {
        (Vector3::new(self.crank_angle(t), q[0], q[1]), Vector3::new(self.speed, qd[0], qd[1]))
    }

    /// Linkage evaluation in full coordinates.
    pub fn evaluate_full(&self, t: f64, q: &Vector2<f64>, qd: &Vector2<f64>) -> Evaluation<3, 4> {
        let (phi, phid) = self.full_state(t, q, qd);
        let loads = Loads { gas_force: self.engine.gas_force(phi[0]), load_torque: 0.0 };
        self.engine.linkage.evaluate(&phi, &phid, loads)
    }

    /// Torque the drive applies to the crank: the crank row `M_1· φ̈ − f_1 − (Jᵀλ)_1` with φ̈1 = 0.
    pub fn drive_torque(&self, t: f64, q: &Vector2<f64>, qd: &Vector2<f64>, qdd: &Vector2<f64>, forces: &Vector4<f64>) -> f64 {
        let full = self.evaluate_full(t, q, qd);
        full.mass[(0, 1)] * qdd[0] + full.mass[(0, 2)] * qdd[1] - full.force[0] - full.gap_jacobian.column(0).dot(forces)
    }
}

impl System<2, 4> for PrescribedCrank {
    fn evaluate(&self, t: f64, q: &Vector2<f64>, qd: &Vector2<f64>) -> Evaluation<2, 4> {
        let full = self.evaluate_full(t, q, qd);
        Evaluation {
            mass: full.mass.fixed_view::<2, 2>(1, 1).into_owned(),
            force: full.force.fixed_rows::<2>(1).into_owned(),
            gap: full.gap,
            gap_jacobian: Matrix4x2::from_columns(&[full.gap_jacobian.column(1), full.gap_jacobian.column(2)]),
            gap_time_rate: full.gap_jacobian.column(0) * self.speed,
            gap_bias: full.gap_bias,
        }
    }

    fn gaps(&self, t: f64, q: &Vector2<f64>) -> Vector4<f64> {
        self.engine.linkage.gaps(&Vector3::new(self.crank_angle(t), q[0], q[1]))
    }

    fn restitution(&self, _constraint: usize) -> f64 {
        self.engine.restitution
    }
}

/// Crank, rod and piston, the crank loaded by a held torque.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FreeCrank {
    pub engine: Engine,
    /// N·m, opposing rotation.
    pub load_torque: f64,
}

impl System<3, 4> for FreeCrank {
    fn evaluate(&self, _t: f64, q: &Vector3<f64>, qd: &Vector3<f64>) -> Evaluation<3, 4> {
        let loads = Loads { gas_force: self.engine.gas_force(q[0]), load_torque: self.load_torque };
        self.engine.linkage.evaluate(q, qd, loads)
    }

    fn gaps(&self, _t: f64, q: &SVector<f64, 3>) -> Vector4<f64> {
        self.engine.linkage.gaps(q)
    }

    fn restitution(&self, _constraint: usize) -> f64 {
        self.engine.restitution
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::Parameters;

    fn prescribed() -> PrescribedCrank {
        let p = Parameters::default();
        let engine = Engine {
            linkage: Linkage::new(&p),
            pressure: GasPressure::BuiltIn(FourStrokePressure::new(8e6, 3.75)),
            crown_area: 0.25 * std::f64::consts::PI * 0.08 * 0.08,
            restitution: 0.5,
        };
        PrescribedCrank::new(engine, 0.4, 0.01, 125.66)
    }

    #[test]
    fn rheonomic_gap_rates_match_finite_differences_in_time() {
        let sys = prescribed();
        let (t, q, qd) = (0.013, Vector2::new(-0.05, 0.0007), Vector2::new(-28.0, 3.0));
        let ev = sys.evaluate(t, &q, &qd);
        // ḣ = J q̇ + ∂h/∂t and d = d²/dτ² h(q + q̇τ, t + τ) along a path with q̈ = 0.
        let tau = 1e-7;
        let path = |s: f64| sys.gaps(t + s, &(q + qd * s));
        let rate = (path(tau) - path(-tau)) / (2.0 * tau);
        assert!((rate - (ev.gap_jacobian * qd + ev.gap_time_rate)).norm() < 1e-8, "{rate} vs {}", ev.gap_jacobian * qd + ev.gap_time_rate);
        let tau = 1e-5;
        let second = (path(tau) - 2.0 * path(0.0) + path(-tau)) / (tau * tau);
        assert!((second - ev.gap_bias).norm() < 1e-4 * ev.gap_bias.norm(), "{second} vs {}", ev.gap_bias);
        let column = |i: usize| {
            let step = Vector2::from_fn(|r, _| if r == i { 1e-6 } else { 0.0 });
            (sys.gaps(t, &(q + step)) - sys.gaps(t, &(q - step))) / 2e-6
        };
        assert!((column(0) - ev.gap_jacobian.column(0)).norm() < 1e-8);
        assert!((column(1) - ev.gap_jacobian.column(1)).norm() < 1e-8);
    }

    #[test]
    fn speed_change_keeps_the_crank_angle_continuous() {
        let mut sys = prescribed();
        let before = sys.crank_angle(0.02);
        sys.hold_speed(0.02, 50.0);
        assert_eq!(sys.crank_angle(0.02), before);
        assert!((sys.crank_angle(0.03) - (before + 0.5)).abs() < 1e-14);
    }

    #[test]
    fn drive_torque_balances_the_crank_row_of_the_free_equations() {
        // With φ̈ = (0, q̈) and the drive torque added to the load, the free system's crank row holds.
        let sys = prescribed();
        let (t, q, qd, qdd) = (0.02, Vector2::new(0.1, -0.001), Vector2::new(20.0, 1.0), Vector2::new(-3000.0, 50.0));
        let forces = Vector4::new(120.0, 0.0, 0.0, 35.0);
        let torque = sys.drive_torque(t, &q, &qd, &qdd, &forces);
        let (phi, phid) = sys.full_state(t, &q, &qd);
        let free = FreeCrank { engine: sys.engine.clone(), load_torque: -torque }.evaluate(0.0, &phi, &phid);
        let phidd = Vector3::new(0.0, qdd[0], qdd[1]);
        let residual = free.mass * phidd - free.force - free.gap_jacobian.transpose() * forces;
        assert!(residual[0].abs() < 1e-9 * torque.abs().max(1.0), "residual {residual}");
    }
}
