//! Variant 2: Farahanchi's slider crank with a roller piston in a clearance (thesis ch. 2), on the
//! nonsmooth core.
//!
//! The core integrates the thesis's own dimensionless system (eqs 3.1–3.3): time is the crank angle
//! θ, the coordinate ψ, the constraints h_lower = ψ − ψ_min(θ) ≥ 0 (corner 3) and
//! h_upper = ψ_max(θ) − ψ ≥ 0 (corner 1). The core's restitution on ḣ is eq 2.17, restitution
//! relative to the moving wall. Working in θ makes the thesis's step (0.005) and sliding threshold
//! (|ψ' − ψ_max'| < 0.005 after an impact, Appendix B) hold at every crank speed; in SI that threshold
//! is a normal speed of 0.005 l Λ Ω. The thesis's threshold serves roller_forcing = 1; the corrected
//! model uses one proportional to the clearance (`SLIDING_THRESHOLD_PER_CLEARANCE`).
//!
//! The FMU's dimensional parameters map as ARCHITECTURE.md §4 says: ξ = r/l, α = m/M, β = J_r/(M l²),
//! ρ = Δ/l with Δ = (bore − piston_diameter)/2, λ = c₂/(M l² Ω) with Ω the `crank_speed` input. As in
//! the thesis there is no gravity, no gas force and no piston-pin damping, and the crank speed is
//! prescribed (crank_mode = 1 only). Lateral positions are linearized like the model: x = −l Λ ψ, so
//! the walls are at x = ∓Δ exactly. The sign is variant 1's (ARCHITECTURE.md §4): with the crank pin at
//! x = −r sin θ, the pin is at x = −r sin θ − l sin(ψ − φ) ≈ −l Λ ψ, so the thesis's upper wall
//! (ψ = ψ_max) is the x = −D/2 wall of corners 1 and 2, and the lower wall that of corners 3 and 4.

use super::forcing::{AtAngle, Forcing, RollerMechanism};
use crate::dynamics::{DynamicsError, Evaluation, Event, Stepper, StepperOptions, System};
use crate::models::numerics::LastValue;
use crate::models::{EngineEvent, EngineModel, ModelError, StepInputs, CYCLE};
use nalgebra::{SMatrix, SVector, Vector1, Vector2};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Turns the stepper's crank angle may reach before a block of them is taken off: its
/// round-off there (ulp 2e-12 rad) is far below the event tolerance, and runs shorter than it (the
/// thesis's 1530 cycles) compute bit for bit as with an unbounded angle. A wrap every turn
/// changes their last bits, and the chaotic transient of the thesis's periodic case
/// (λ, ρ, e) = (0.05, 0.015, 0.9) then lasts 122 cycles instead of 45, past the 100 within which
/// `analysis.classify` calls a response periodic.
const WRAP_TURNS: f64 = 2048.0;

/// Constraint index of the lower wall (ψ = ψ_min, x = +D/2, corner 3).
pub const LOWER: usize = 0;
/// Constraint index of the upper wall (ψ = ψ_max, x = −D/2, corner 1).
pub const UPPER: usize = 1;

/// The thesis's step (Appendix B), in radians of crank angle.
pub const THESIS_STEP: f64 = 0.005;
/// The thesis's sliding threshold on the post-impact relative rate |ψ' − ψ_wall'| (Appendix B), used with
/// roller_forcing = 1 so that the thesis's runs are reproduced.
pub const THESIS_SLIDING_THRESHOLD: f64 = 0.005;
/// With roller_forcing = 2 the threshold is this fraction of ρ. Rates are of order ρ per radian, and the
/// thesis's 0.005 is a third of them at its ρ = 0.015, but at an engine's ρ ~ 3e-4 it would exceed every
/// approach and turn each one into sliding; 1e-3 ρ leaves accumulations of impacts to the core's Zeno guard.
pub const SLIDING_THRESHOLD_PER_CLEARANCE: f64 = 1e-3;

/// Eqs 2.13–2.17 as a core `System`: time = crank angle, q = ψ, everything over M l² Ω².
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RollerSystem {
    /// Private: `last_angle` caches its terms.
    mechanism: RollerMechanism,
    /// ρ = Δ/l.
    pub rho: f64,
    /// λ = c₂/(M l² Ω), held with the crank speed.
    pub lambda: f64,
    /// Newton's restitution coefficient of the roller on the guide.
    pub restitution: f64,
    /// The mechanism's terms at the last crank angle evaluated (RK4's paired stages share it).
    #[serde(skip)]
    last_angle: LastValue<AtAngle>,
}

impl RollerSystem {
    /// The dimensionless mechanism.
    pub fn mechanism(&self) -> &RollerMechanism {
        &self.mechanism
    }
}

impl System<1, 2> for RollerSystem {
    fn evaluate(&self, t: f64, q: &Vector1<f64>, qd: &Vector1<f64>) -> Evaluation<1, 2> {
        let at = self.last_angle.get_or([t], || self.mechanism.at(t));
        let limit = at.psi_max(self.rho);
        let force = at.forcing(self.lambda) - self.lambda * qd[0] - at.stiffness() * q[0];
        Evaluation {
            mass: SMatrix::<f64, 1, 1>::new(self.mechanism.inertia()),
            implicit: None,
            force: Vector1::new(force),
            gap: Vector2::new(limit.value + q[0], limit.value - q[0]),
            gap_jacobian: SMatrix::<f64, 2, 1>::new(1.0, -1.0),
            gap_time_rate: Vector2::new(limit.d1, limit.d1),
            gap_bias: Vector2::new(limit.d2, limit.d2),
        }
    }

    fn restitution(&self) -> f64 {
        self.restitution
    }
}

/// The roller slider crank as the FMU drives it: SI in and out, the thesis's variables inside.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Roller {
    pub(crate) stepper: Stepper<RollerSystem, 1, 2>,
    options: StepperOptions,
    crank_radius: f64,
    pub(crate) rod_length: f64,
    pub(crate) piston_mass: f64,
    damping: f64,
    /// The crank's moment of inertia about its axis, J1 + m1 ey1², kg·m² (for the kinetic energy).
    pub(crate) crank_inertia: f64,
    /// Held crank speed Ω, rad/s; 0 before the first step.
    pub(crate) crank_speed: f64,
    /// SI time at the stepper's current crank angle.
    time: f64,
    /// Work the moving walls have done through impulses since the start, J (`EnergyBalance`).
    pub(super) impulse_work: f64,
    /// Whole turns (2π) taken off the stepper's crank angle (`keep_angle_bounded`).
    pub(crate) turns: f64,
    /// The time and crank angle before the last point served from the step ahead (`serve_again`).
    #[serde(skip)]
    served_from: Option<(f64, f64)>,
}

/// What a [`Roller`] is built from, SI: a design within the model's conditions (`design::roller`).
#[derive(Clone, Debug)]
pub struct RollerDesign {
    /// ξ, α, β and the forcing.
    pub mechanism: RollerMechanism,
    /// Δ, the radial clearance at running temperature, m.
    pub half_clearance: f64,
    /// e.
    pub restitution: f64,
    /// The crank angle at the start time, rad.
    pub crank_angle: f64,
    /// r, m.
    pub crank_radius: f64,
    /// l, m.
    pub rod_length: f64,
    /// M, kg.
    pub piston_mass: f64,
    /// c2, N·m·s.
    pub damping: f64,
    /// The crank's moment of inertia about its axis, J1 + m1 ey1², kg·m².
    pub crank_inertia: f64,
}

/// A core error with its time on the engine's clock: the core's time is the crank angle, which
/// `clock` turns into seconds.
fn core_error(error: DynamicsError, clock: impl FnOnce(f64) -> f64) -> ModelError {
    ModelError(format!("model_variant 2: {}", error.map_time(clock)))
}

/// Corner number of the impact log for a constraint index.
pub fn corner(constraint: usize) -> u8 {
    if constraint == UPPER {
        1
    } else {
        3
    }
}

impl Roller {
    /// The core's stepper in thesis units (for analysis and tests).
    pub fn stepper(&self) -> &Stepper<RollerSystem, 1, 2> {
        &self.stepper
    }

    pub(crate) fn mechanism(&self) -> &RollerMechanism {
        self.stepper.system().mechanism()
    }

    /// Metres of lateral motion per radian of ψ, and m/s of normal speed per unit of ḣ in θ-time.
    fn lateral_scale(&self, theta: f64) -> f64 {
        self.rod_length * self.mechanism().at(theta).cos_phi.value
    }

    /// Pin position along the cylinder axis: r cos θ + l cos(φ − ψ).
    pub(crate) fn axial_position(&self, theta: f64, psi: f64) -> f64 {
        let phi = self.mechanism().at(theta).rod_angle().value;
        self.crank_radius * libm::cos(theta) + self.rod_length * libm::cos(phi - psi)
    }

    /// [`core_error`] between steps, where the core's crank angle is the one at `self.time`.
    fn error_now(&self) -> impl FnOnce(DynamicsError) -> ModelError {
        let now = self.time;
        move |e| core_error(e, |_| now)
    }

    /// Holds a new crank speed: λ changes with Ω, and ψ' = ψ̇/Ω is rescaled so ψ̇ stays continuous.
    fn hold_crank_speed(&mut self, omega: f64) -> Result<(), ModelError> {
        if omega == self.crank_speed {
            return Ok(());
        }
        let mut system = self.stepper.system().clone();
        system.lambda = self.damping / (self.piston_mass * self.rod_length * self.rod_length * omega);
        let rate = if self.crank_speed > 0.0 { self.crank_speed / omega } else { 0.0 };
        let (theta, q, qd) = (self.stepper.time(), *self.stepper.position(), *self.stepper.velocity() * rate);
        self.stepper = Stepper::new(system, theta, q, qd, self.options.clone()).map_err(self.error_now())?;
        self.crank_speed = omega;
        Ok(())
    }

    /// Keeps the stepper's time, the crank angle, below `WRAP_TURNS` turns by taking whole blocks
    /// of them off (the model has period 2π in it): left to grow, its round-off reaches the gaps
    /// near the event tolerance (θ ≈ 6e6 rad, ulp 1e-9, after 10⁶ revolutions).
    fn keep_angle_bounded(&mut self) -> Result<(), ModelError> {
        let turns = self.turns_to_take_off();
        if turns != 0.0 {
            self.stepper.shift(-2.0 * PI * turns, &SVector::zeros()).map_err(self.error_now())?;
            self.turns += turns;
        }
        Ok(())
    }

    /// The whole turns `keep_angle_bounded` would take off the crank angle now.
    fn turns_to_take_off(&self) -> f64 {
        (self.stepper.time() / (2.0 * PI * WRAP_TURNS)).floor() * WRAP_TURNS
    }

    /// The crank speed the inputs hold over a step, refused unless finite, positive and without
    /// derivatives (the thesis's equations are in crank angle at constant speed).
    fn held_speed(inputs: &StepInputs) -> Result<f64, ModelError> {
        let speed = &inputs.crank_speed;
        if [speed.slope, speed.curvature] != [0.0; 2] {
            return Err(ModelError(format!(
                "model_variant 2 holds crank_speed over a step (its equations are in crank angle at constant speed): \
                 derivatives {:?} refused",
                [speed.slope, speed.curvature]
            )));
        }
        let omega = speed.value;
        if !(omega.is_finite() && omega > 0.0) {
            return Err(ModelError(format!("model_variant 2: crank_speed must be finite and > 0, got {omega}")));
        }
        Ok(omega)
    }

    /// The crank angle at `t_end` at the held speed, and a core error's time on the engine's clock
    /// from the current time on.
    fn angle_and_clock(&self, t_end: f64) -> (f64, impl Fn(DynamicsError) -> ModelError) {
        let (theta_start, now, omega) = (self.stepper.time(), self.time, self.crank_speed);
        (theta_start + omega * (t_end - now), move |e| core_error(e, |theta| now + (theta - theta_start) / omega))
    }

    fn engine_event(&self, event: &Event<1, 2>, theta_start: f64) -> EngineEvent {
        let omega = self.crank_speed;
        let speed = self.lateral_scale(event.time) * omega;
        let before = -event.velocity_before * speed;
        EngineEvent {
            time: self.time + (event.time - theta_start) / omega,
            // The turns taken off come in even blocks: the angle within a cycle is unchanged.
            crank_angle: event.time.rem_euclid(CYCLE),
            cycle: ((event.time + 2.0 * PI * self.turns) / CYCLE).floor() as i64,
            kind: event.kind.into(),
            corner: corner(event.constraint),
            normal_velocity_before: before,
            normal_velocity_after: event.velocity_after * speed,
            energy_lost: event.energy_lost * self.energy_scale(),
            friction_energy: 0.0,
            position: self.axial_position(event.time, event.q[0]),
            // The slider moves across the bore only: its normal speed is its lateral speed.
            lateral_kinetic_energy: 0.5 * self.piston_mass * before * before,
        }
    }
}

impl Roller {
    /// The roller of `design` at `start_time`, on its nominal path (ψ = ψ' = 0).
    pub fn with_design(design: RollerDesign, start_time: f64) -> Result<Self, ModelError> {
        if !start_time.is_finite() {
            return Err(ModelError(format!("model_variant 2: the start time ({start_time} s) must be finite")));
        }
        let d = design;
        let system = RollerSystem {
            mechanism: d.mechanism,
            rho: d.half_clearance / d.rod_length,
            lambda: 0.0,
            restitution: d.restitution,
            last_angle: LastValue::default(),
        };
        let velocity_tolerance = match system.mechanism.forcing {
            Forcing::Printed => THESIS_SLIDING_THRESHOLD,
            Forcing::Corrected => SLIDING_THRESHOLD_PER_CLEARANCE * system.rho,
        };
        let options = StepperOptions { step: THESIS_STEP, velocity_tolerance, ..StepperOptions::default() };
        let stepper = Stepper::new(system, d.crank_angle, SVector::zeros(), SVector::zeros(), options.clone())
            .map_err(|e| core_error(e, |_| start_time))?;
        Ok(Self {
            stepper,
            options,
            crank_radius: d.crank_radius,
            rod_length: d.rod_length,
            piston_mass: d.piston_mass,
            damping: d.damping,
            crank_inertia: d.crank_inertia,
            crank_speed: 0.0,
            time: start_time,
            impulse_work: 0.0,
            turns: 0.0,
            served_from: None,
        })
    }
}

impl EngineModel for Roller {
    /// The thesis's equations are in crank-angle time at a constant Ω: a crank speed derivative is
    /// refused; the gas pressure and load torque do not act on this model.
    fn advance_interpolated(&mut self, inputs: &StepInputs, t_end: f64, events: &mut Vec<EngineEvent>) -> Result<(), ModelError> {
        let omega = Self::held_speed(inputs)?;
        if t_end <= self.time {
            return Ok(());
        }
        self.hold_crank_speed(omega)?;
        self.keep_angle_bounded()?;
        let theta_start = self.stepper.time();
        self.stepper.clear_events();
        let (theta_end, clock) = self.angle_and_clock(t_end);
        self.stepper.advance(theta_end).map_err(clock)?;
        events.extend(self.stepper.events().iter().map(|e| self.engine_event(e, theta_start)));
        let system = self.stepper.system();
        self.impulse_work += self.stepper.events().iter().map(|e| system.impulse_work(e)).sum::<f64>() * self.energy_scale();
        self.stepper.clear_events();
        self.time = t_end;
        Ok(())
    }

    /// With the crank speed held as it is, no turns to take off and the step ahead past `t_end`,
    /// `advance_interpolated` would only have the stepper serve the point.
    fn serve(&mut self, inputs: &StepInputs, t_end: f64) -> Option<Result<(), ModelError>> {
        let omega = match Self::held_speed(inputs) {
            Ok(omega) => omega,
            Err(e) => return Some(Err(e)),
        };
        let (theta_end, clock) = self.angle_and_clock(t_end);
        if !(omega == self.crank_speed && t_end > self.time && self.turns_to_take_off() == 0.0 && self.stepper.serves(theta_end)) {
            return None;
        }
        let before = (self.time, self.stepper.time());
        let served = self.stepper.serve(theta_end).map_err(clock);
        if served.is_ok() {
            (self.time, self.served_from) = (t_end, Some(before));
        }
        Some(served)
    }

    fn serve_again(&mut self, t: f64) -> Result<(), ModelError> {
        match self.served_from {
            Some((time, theta)) if time == t => {
                self.stepper.serve(theta).map_err(|e| core_error(e, |_| t))?;
                self.time = time;
                Ok(())
            }
            _ => Err(ModelError(format!("model_variant 2: no point served from t = {t} s to read again"))),
        }
    }
}
