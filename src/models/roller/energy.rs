//! The roller's energy balance, for the system the core integrates (eq 2.13 with its walls):
//! `a ψ'' = f(τ) − c(τ) ψ − λ ψ' + Jᵀλ_c`, energy `E = ½ a ψ'²` (times M l² Ω² in joules).
//! The prescribed crank works through the forcing `f − cψ`, and through the walls, which move
//! with the crank (`∂h/∂τ = ψ_max'`): while sliding at the rate `λ_cᵀ J ψ'`, and at an impulse Λ
//! by `−Λᵀ ∂h/∂τ`. The damper dissipates `λ ψ'²`; impacts their `energy_lost`.

use super::roller::{Roller, RollerSystem, LOWER, UPPER};
use crate::dynamics::{Event, System};
use crate::models::{EnergyBalance, PowerFlows};
use nalgebra::Vector1;

impl RollerSystem {
    /// Work the moving walls do through the impulses of one event, over M l² Ω².
    pub fn impulse_work(&self, event: &Event<1, 2>) -> f64 {
        -event.impulses.dot(&self.evaluate(event.time, &event.q, &Vector1::zeros()).gap_time_rate)
    }
}

impl Roller {
    /// J per unit of the thesis's energies (M l² Ω²).
    pub(crate) fn energy_scale(&self) -> f64 {
        self.piston_mass * (self.rod_length * self.crank_speed).powi(2)
    }
}

impl EnergyBalance for Roller {
    fn mechanical_energy(&self) -> f64 {
        let s = &self.stepper;
        0.5 * s.system().mechanism().inertia() * s.velocity()[0].powi(2) * self.energy_scale()
    }

    fn power_flows(&self) -> PowerFlows {
        let s = &self.stepper;
        let (sys, theta, psi, rate) = (s.system(), s.time(), s.position()[0], s.velocity()[0]);
        let at = sys.mechanism().at(theta);
        let forcing = at.forcing(sys.lambda) - at.stiffness() * psi;
        let walls = s.multipliers()[LOWER] - s.multipliers()[UPPER];
        // Rates per radian of crank angle, times Ω for per second.
        let watts = self.energy_scale() * self.crank_speed;
        PowerFlows {
            drive: (forcing + walls) * rate * watts,
            gas: 0.0,
            damping: sys.lambda * rate * rate * watts,
            friction: 0.0,
            film: 0.0,
        }
    }

    fn impulse_work(&self) -> f64 {
        self.impulse_work
    }
}
