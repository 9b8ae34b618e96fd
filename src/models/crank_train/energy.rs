//! The crank train's energy balance terms, and the liner's impulse per wall.
//!
//! With the crank held at ω (crank_mode 1) every impulse Λ on the corners is met by an impulse P_d
//! of the drive that keeps φ̇1 = ω: the full equations integrated over the impact,
//! `M Δφ̇ = J_fullᵀ Λ + (P_d, 0, 0)ᵀ` with `Δφ̇1 = 0`, give from the rod and piston rows
//! `Δq̇ = M_rr⁻¹ J_rᵀ Λ` and from the crank row `P_d = M_1r Δq̇ − (∂h/∂φ1)ᵀ Λ`. The drive does the
//! work `P_d ω`, and `ΔT = −(dissipation) + P_d ω` with dissipation `−Λᵀ(ḣ⁻ + ḣ⁺)/2`.

use super::books::{DAMPING, DRIVE, FILM, GAS, IMPLICIT};
use super::crank_train::{by_wall, CrankTrain};
use super::engine::PrescribedCrank;
use crate::models::{EnergyBalance, PowerFlows};
use nalgebra::{Vector2, Vector4};

impl PrescribedCrank {
    /// Work the drive does through the corner impulses of one jump at `(t, q)` with the velocity
    /// `v` before it, normal and tangential (friction), J; `None` if the rod and piston inertia is
    /// not positive definite there. The jump acts through the inertia the core gave it: an impact
    /// (`impact`) through the linkage's alone (`Evaluation::mass`), a projection
    /// through the lubricated skirt's, which depends on `v` and on the film prepared when this is
    /// asked (after the communication step: not always the one the jump acted through). A
    /// projection onto projected contacts (`dynamics/implicit/`) acts through `M⁻¹ Jᵀ`, the
    /// linkage's, and is reckoned here through the skirt's all the same: the event does not say.
    pub fn impulse_work(
        &self,
        (t, q, v): (f64, &Vector2<f64>, &Vector2<f64>),
        (normal, friction): (&Vector4<f64>, &Vector4<f64>),
        impact: bool,
    ) -> Option<f64> {
        let full = self.evaluate_full(t, q, v);
        let mass = if impact { full.mass } else { full.inertia() };
        let rows = mass.fixed_view::<2, 2>(1, 1).into_owned();
        let mut generalized = full.gap_jacobian.transpose() * normal;
        if *friction != Vector4::zeros() {
            let (phi, phid) = self.full_state(t, q, &Vector2::zeros());
            generalized += self.engine.linkage.tangents(&phi, &phid).jacobian.transpose() * friction;
        }
        let jump = rows.cholesky()?.solve(&generalized.fixed_rows::<2>(1).into_owned());
        let drive_impulse = (mass.fixed_view::<1, 2>(0, 1) * jump)[0] - generalized[0];
        Some(drive_impulse * self.speed(t))
    }
}

impl CrankTrain {
    /// The persistent contact forces' impulse on the piston per wall since the start, N·s.
    pub(crate) fn contact_impulse(&self) -> [f64; 2] {
        by_wall(&self.drive.stepper().contact_impulses())
    }
}

impl EnergyBalance for CrankTrain {
    /// Kinetic plus gravitational potential energy of the links.
    fn mechanical_energy(&self) -> f64 {
        let (phi, phid) = self.state();
        let (kinetic, potential) = self.engine().linkage.energy(&phi, &phid);
        kinetic + potential
    }

    /// The rates the crank train reports to the core (`books`) at the state now.
    fn power_flows(&self) -> PowerFlows {
        let rates = self.drive.stepper().rates();
        let (_, friction, _) = self.friction();
        let film = rates[FILM] + rates[IMPLICIT];
        PowerFlows { drive: rates[DRIVE], gas: rates[GAS], damping: rates[DAMPING], friction, film }
    }

    fn impulse_work(&self) -> f64 {
        self.impulse_work
    }
}

#[cfg(test)]
mod tests {
    use crate::dynamics::System;
    use crate::fmus::piston_slap::mechanisms;
    use crate::fmus::piston_slap::Parameters;
    use crate::models::crank_train::engine::PrescribedCrank;
    use nalgebra::{Matrix4, Vector2, Vector3, Vector4};

    /// The drive's impulse from the bordered full system `[M −e1; e1ᵀ 0] (Δφ̇, P_d) = (JᵀΛ, 0)`
    /// (an independent solve of the same mechanics), and the energy identity
    /// `ΔT_full = Λᵀ(ḣ⁻ + ḣ⁺)/2 + P_d ω` for an impulse on two corners at a tilted, moving state.
    #[test]
    fn impulse_work_is_the_crank_row_reaction_and_closes_the_energy_of_an_impact() {
        let p = Parameters::default();
        let mut engine = mechanisms::crank_train::engine(&Parameters { pressure_source: 1, ..p.clone() }).unwrap();
        engine.hold_pressure(crate::models::InputPolynomial::held(0.0));
        let sys = PrescribedCrank::new(engine, 0.7, 0.0, 125.66);
        let (t, q, qd) = (0.003, Vector2::new(-0.12, 4e-4), Vector2::new(-25.0, 3.0));
        let impulses = Vector4::new(0.02, 0.0, 0.0, 0.013);
        let work = sys.impulse_work((t, &q, &Vector2::zeros()), (&impulses, &Vector4::zeros()), true).unwrap();

        let (phi, phid) = sys.full_state(t, &q, &qd);
        let full = sys.evaluate_full(t, &q, &qd);
        let mut bordered = Matrix4::zeros();
        bordered.fixed_view_mut::<3, 3>(0, 0).copy_from(&full.mass);
        (bordered[(0, 3)], bordered[(3, 0)]) = (-1.0, 1.0);
        let rhs = full.gap_jacobian.transpose() * impulses;
        let solution = bordered.lu().solve(&Vector4::new(rhs[0], rhs[1], rhs[2], 0.0)).unwrap();
        assert!((work - solution[3] * 125.66).abs() < 1e-12 * work.abs(), "{work} vs {}", solution[3] * 125.66);

        let jump = Vector3::new(0.0, solution[1], solution[2]);
        let kinetic = |v: &Vector3<f64>| sys.engine.linkage.energy(&phi, v).0;
        let rate = |v: &Vector3<f64>| full.gap_jacobian * v;
        let plus = phid + jump;
        let reduced = sys.evaluate(t, &q, &qd);
        assert!((rate(&phid) - (reduced.gap_jacobian * qd + reduced.gap_time_rate)).norm() < 1e-12);
        let contact = impulses.dot(&(rate(&phid) + rate(&plus))) * 0.5;
        let gain = kinetic(&plus) - kinetic(&phid);
        assert!((gain - contact - work).abs() < 1e-12 * gain.abs().max(1.0), "ΔT {gain} vs {contact} + {work}");
        assert!(work.abs() > 0.1 * gain.abs(), "the drive's share must matter here: {work} of {gain}");
    }
}
