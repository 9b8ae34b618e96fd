//! The engine cycle as a function of time: the crank angle of the prescribed speed, the pressure of the
//! closed part ([`super::closed_cycle`]) and of the gas exchange, the wall heat, and their time derivatives.
//!
//! With ϑ the crank angle reduced to [−π, 3π) about firing top dead centre (ϑ = 0 at crank angle 0 mod 4π):
//! - ϑ ∈ [−π, ϑ_EVO]: the closed cycle, intake valve closing at bottom dead centre with `p(−π) = p_intake`;
//! - blowdown, ϑ ∈ (ϑ_EVO, π]: `p = p_exhaust + (p(ϑ_EVO) − p_exhaust) cos²(π/2 (ϑ − ϑ_EVO)/(π − ϑ_EVO))`,
//!   continuous with zero slope at bottom dead centre;
//! - exhaust stroke, ϑ ∈ (π, 2π): `p_exhaust`; intake stroke, ϑ ∈ [2π, 3π): `p_intake`.
//!
//! The indicated torque is `(p − p_crankcase) dV/dϑ` (the work of the gas on the crank per radian), whose
//! integral over a cycle is IMEP · V_d. Heat flows to the walls over the closed part only: the wall heat since the
//! start time is the closed parts', its time derivative `dQ_w/dϑ · ω`.

use super::closed_cycle::{ClosedCycle, ClosedState};
use super::design::{CycleDesign, Volume};
use crate::models::{ModelError, CYCLE};
use serde::{Deserialize, Serialize};
use std::f64::consts::{FRAC_PI_2, PI};

/// The single-zone cycle: its design and the closed cycle.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct EngineCycle {
    design: CycleDesign,
    start_time: f64,
    closed: ClosedCycle,
}

impl EngineCycle {
    /// Validates the design and integrates the closed part of the cycle (refusing an implausible one).
    pub fn new(design: &CycleDesign, start_time: f64) -> Result<Self, ModelError> {
        design.validate()?;
        if !start_time.is_finite() {
            return Err(ModelError(format!("start time {start_time} s is not finite")));
        }
        let closed = ClosedCycle::new(design)?;
        Ok(Self { design: design.clone(), start_time, closed })
    }

    /// The design it was made with.
    pub fn design(&self) -> &CycleDesign {
        &self.design
    }

    /// s, the time the crank is at `crank_angle_start`.
    pub fn start_time(&self) -> f64 {
        self.start_time
    }

    /// The closed cycle: its charge and table.
    pub fn closed(&self) -> &ClosedCycle {
        &self.closed
    }

    /// The slider-crank volume at crank angle `theta`.
    pub fn volume(&self, theta: f64) -> Volume {
        self.design.volume(theta)
    }

    /// Absolute cylinder pressure p and dp/dϑ at crank angle `crank_angle` (any value; period 4π).
    pub fn pressure(&self, crank_angle: f64) -> (f64, f64) {
        let p = &self.design;
        let theta = (crank_angle + PI).rem_euclid(CYCLE) - PI;
        let evo = p.exhaust_valve_opening;
        if theta <= evo {
            let state = self.closed.state(theta);
            (state.p, state.dp)
        } else if theta <= PI {
            let p_evo = self.closed.state(evo).p;
            let phase = FRAC_PI_2 * (theta - evo) / (PI - evo);
            let (sin, cos) = libm::sincos(phase);
            let excess = p_evo - p.exhaust_pressure;
            (p.exhaust_pressure + excess * cos * cos, -excess * 2.0 * sin * cos * FRAC_PI_2 / (PI - evo))
        } else if theta < 2.0 * PI {
            (p.exhaust_pressure, 0.0)
        } else {
            (p.intake_pressure, 0.0)
        }
    }

    /// The wall heat since inlet valve closing of the cycle `crank_angle` lies in, J, with its first two
    /// crank-angle derivatives, plus the whole cycles' wall heat before it: a continuous function of the
    /// accumulated crank angle.
    pub fn wall_heat(&self, crank_angle: f64) -> (f64, f64, f64) {
        let evo = self.design.exhaust_valve_opening;
        let cycles = ((crank_angle + PI) / CYCLE).floor();
        let theta = crank_angle - cycles * CYCLE;
        let per_cycle = self.closed.state(evo).q;
        let (q, dq, d2q) = if theta <= evo {
            let ClosedState { q, dq, d2q, .. } = self.closed.state(theta);
            (q, dq, d2q)
        } else {
            (per_cycle, 0.0, 0.0)
        };
        (cycles * per_cycle + q, dq, d2q)
    }

    /// rad/s and rad/s²: the prescribed speed (constant, or the linear ramp) at time `t`.
    pub fn speed(&self, t: f64) -> (f64, f64) {
        let p = &self.design;
        let elapsed = t - self.start_time;
        if p.ramp_time > 0.0 && elapsed < p.ramp_time {
            let slope = (p.speed_end - p.speed_start) / p.ramp_time;
            (p.speed_start + slope * elapsed.max(0.0), if elapsed >= 0.0 { slope } else { 0.0 })
        } else if p.ramp_time > 0.0 {
            (p.speed_end, 0.0)
        } else {
            (p.speed_start, 0.0)
        }
    }

    /// rad, the crank angle at time `t`: the exact integral of [`Self::speed`].
    pub fn crank_angle(&self, t: f64) -> f64 {
        let p = &self.design;
        let elapsed = (t - self.start_time).max(0.0);
        if p.ramp_time > 0.0 {
            let ramp = elapsed.min(p.ramp_time);
            let slope = (p.speed_end - p.speed_start) / p.ramp_time;
            p.crank_angle_start + p.speed_start * ramp + 0.5 * slope * ramp * ramp + p.speed_end * (elapsed - ramp)
        } else {
            p.crank_angle_start + p.speed_start * elapsed
        }
    }

    /// Pa, indicated mean effective pressure ∮ p dV / V_d over one cycle, by the trapezoidal rule on
    /// `samples` equal crank-angle intervals.
    pub fn imep(&self, samples: usize) -> f64 {
        let h = CYCLE / samples as f64;
        let torque = |k: usize| {
            let theta = -PI + k as f64 * h;
            (self.pressure(theta).0 - self.design.crankcase_pressure) * self.volume(theta).dv
        };
        let work: f64 = (0..samples).map(|k| 0.5 * h * (torque(k) + torque(k + 1))).sum();
        work / self.design.displacement()
    }
}
