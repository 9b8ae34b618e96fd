//! The partner engine model: a single-zone four-stroke cycle of the textbook kind (Heywood, *Internal
//! Combustion Engine Fundamentals*, ch. 2 and 9), driving PistonSlap with crank speed and gas pressure.
//! No FFI, no FMI words.
//!
//! With ϑ the crank angle reduced to [−π, 3π) about firing top dead centre (ϑ = 0 at crank angle 0 mod 4π):
//!
//! - compression and expansion, ϑ ∈ [−π, ϑ_EVO]: closed cylinder, intake valve closing at bottom dead centre
//!   with `p(−π) = p_intake`; the first law with a polytropic exponent n in place of γ,
//!   `dp/dϑ = −n p/V dV/dϑ + (n − 1)/V dQ/dϑ`, so that without heat release `p Vⁿ` is constant;
//!   `Q = Q_fuel x_b` with the Wiebe burn fraction `x_b = 1 − exp(−a ((ϑ − ϑ_s)/Δϑ)^(m+1))` for ϑ ≥ ϑ_s
//!   (Heywood eq 9.23, a = 5, m = 2);
//! - blowdown, ϑ ∈ (ϑ_EVO, π]: `p = p_exhaust + (p(ϑ_EVO) − p_exhaust) cos²(π/2 (ϑ − ϑ_EVO)/(π − ϑ_EVO))`,
//!   continuous with zero slope at bottom dead centre;
//! - exhaust stroke, ϑ ∈ (π, 2π): `p_exhaust`; intake stroke, ϑ ∈ [2π, 3π): `p_intake`.
//!
//! `V(ϑ) = V_c + A s(ϑ)` is the slider-crank volume (Heywood eq 2.6) with `A = π B²/4`, crank radius
//! `r = S/2`, `s = r + l − r cos ϑ − √(l² − r² sin²ϑ)` and `V_c = A S/(ε − 1)`.
//!
//! The closed part depends on the crank angle only (no heat transfer, no speed dependence), so it is
//! integrated once (RK4 in ϑ on a 0.1° grid) and read back by cubic Hermite interpolation: the pressure is
//! C¹ in the closed part, the outputs at any time cost one table look-up.
//!
//! The indicated torque is `(p − p_crankcase) dV/dϑ` (the work of the gas on the crank per radian), whose
//! integral over a cycle is IMEP · V_d.

use super::parameters::check_real;
use super::{ModelError, CYCLE};
use serde::{Deserialize, Serialize};
use std::f64::consts::{FRAC_PI_2, PI};

const WIEBE_EFFICIENCY: f64 = 5.0;
const WIEBE_FORM: i32 = 2;
/// Grid of the closed-cycle table, rad (0.1°).
const TABLE_SPACING: f64 = PI / 1800.0;

/// The engine cycle's parameters, SI units.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct EngineCycleParameters {
    /// m, cylinder bore B.
    pub bore: f64,
    /// m, stroke S (twice the crank radius).
    pub stroke: f64,
    /// m, connecting-rod length l (> S/2).
    pub rod_length: f64,
    /// ε = (V_c + V_d)/V_c, > 1.
    pub compression_ratio: f64,
    /// n of the compression and expansion, > 1.
    pub polytropic_exponent: f64,
    /// Pa, absolute, during the intake stroke and at intake valve closing.
    pub intake_pressure: f64,
    /// Pa, absolute, during the exhaust stroke.
    pub exhaust_pressure: f64,
    /// Pa, absolute; `gas_pressure` = cylinder pressure − this.
    pub crankcase_pressure: f64,
    /// J per cycle released by combustion (0: motored).
    pub heat_release: f64,
    /// rad, start of combustion ϑ_s relative to firing TDC.
    pub burn_start: f64,
    /// rad, combustion duration Δϑ.
    pub burn_duration: f64,
    /// rad, exhaust valve opening ϑ_EVO after firing TDC, in (0, π).
    pub exhaust_valve_opening: f64,
    /// rad/s, crank speed at the start time.
    pub speed_start: f64,
    /// rad/s, crank speed at the end of the ramp.
    pub speed_end: f64,
    /// s, duration of the linear ramp from `speed_start` to `speed_end` (0: constant `speed_start`).
    pub ramp_time: f64,
    /// rad, crank angle at the start time.
    pub crank_angle_start: f64,
}

/// EngineCycle has no inputs: its speed comes from the parameters.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct EngineCycleInputs {}

// The name the generated defaults and range checks (from modelDescription/variables_engine_cycle.xml) address.
type Parameters = EngineCycleParameters;
include!(concat!(env!("OUT_DIR"), "/engine_cycle_parameter_defaults.rs"));

impl EngineCycleParameters {
    /// Every value finite and within its table range (modelDescription/variables_engine_cycle.xml), and a rod longer
    /// than the crank radius; the message names the parameter.
    pub fn validate(&self) -> Result<(), ModelError> {
        self.check_ranges()?;
        for (name, value) in [("compression_ratio", self.compression_ratio), ("polytropic_exponent", self.polytropic_exponent)] {
            if value <= 1.0 {
                return Err(ModelError(format!("{name} = {value} is out of range: must be > 1")));
            }
        }
        if self.burn_start <= -PI {
            return Err(ModelError(format!("burn_start = {} rad is out of range: must be > −π", self.burn_start)));
        }
        if self.exhaust_valve_opening >= PI {
            return Err(ModelError(format!("exhaust_valve_opening = {} rad is out of range: must be < π", self.exhaust_valve_opening)));
        }
        if self.rod_length <= 0.5 * self.stroke {
            return Err(ModelError(format!(
                "rod_length = {} m is out of range: must be > stroke/2 = {} m",
                self.rod_length,
                0.5 * self.stroke
            )));
        }
        Ok(())
    }

    /// m², piston crown area A = π B²/4.
    pub fn area(&self) -> f64 {
        0.25 * PI * self.bore * self.bore
    }

    /// m³, displaced volume V_d = A S.
    pub fn displacement(&self) -> f64 {
        self.area() * self.stroke
    }
}

/// Cylinder volume V and its first two derivatives with respect to the crank angle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Volume {
    /// m³.
    pub v: f64,
    /// m³/rad.
    pub dv: f64,
    /// m³/rad².
    pub d2v: f64,
}

/// The values a host reads, with their time derivatives.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct EngineCycleOutputs {
    /// rad, accumulated.
    pub crank_angle: f64,
    /// rad/s.
    pub crank_speed: f64,
    /// Pa, absolute.
    pub cylinder_pressure: f64,
    /// Pa, cylinder minus crankcase.
    pub gas_pressure: f64,
    /// N·m.
    pub indicated_torque: f64,
}

/// The single-zone cycle: the parameters and the closed-cycle pressure table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct EngineCycle {
    parameters: EngineCycleParameters,
    start_time: f64,
    /// (p, dp/dϑ) at ϑ = −π + k · TABLE_SPACING, up to and including the first node past ϑ_EVO.
    table: Vec<(f64, f64)>,
}

impl EngineCycle {
    /// Validates the parameters and integrates the closed part of the cycle.
    pub fn new(parameters: &EngineCycleParameters, start_time: f64) -> Result<Self, ModelError> {
        parameters.validate()?;
        if !start_time.is_finite() {
            return Err(ModelError(format!("start time {start_time} s is not finite")));
        }
        let mut model = Self { parameters: parameters.clone(), start_time, table: Vec::new() };
        let nodes = ((parameters.exhaust_valve_opening + PI) / TABLE_SPACING).ceil() as usize + 1;
        let mut p = parameters.intake_pressure;
        model.table.reserve(nodes);
        for k in 0..nodes {
            let theta = -PI + k as f64 * TABLE_SPACING;
            model.table.push((p, model.closed_slope(theta, p)));
            let h = TABLE_SPACING;
            let k1 = model.closed_slope(theta, p);
            let k2 = model.closed_slope(theta + 0.5 * h, p + 0.5 * h * k1);
            let k3 = model.closed_slope(theta + 0.5 * h, p + 0.5 * h * k2);
            let k4 = model.closed_slope(theta + h, p + h * k3);
            p += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        }
        if model.table.iter().any(|(p, dp)| !(p.is_finite() && dp.is_finite() && *p > 0.0)) {
            return Err(ModelError("the closed-cycle pressure is not finite and positive: check heat_release".into()));
        }
        Ok(model)
    }

    pub fn parameters(&self) -> &EngineCycleParameters {
        &self.parameters
    }

    /// The slider-crank volume at crank angle `theta`.
    pub fn volume(&self, theta: f64) -> Volume {
        let p = &self.parameters;
        let (r, l, area) = (0.5 * p.stroke, p.rod_length, p.area());
        let (sin, cos) = libm::sincos(theta);
        let root = (l * l - r * r * sin * sin).sqrt();
        let s = r + l - r * cos - root;
        let ds = r * sin + r * r * sin * cos / root;
        let d2s = r * cos + r * r * ((cos * cos - sin * sin) / root + r * r * sin * sin * cos * cos / root.powi(3));
        let clearance = p.displacement() / (p.compression_ratio - 1.0);
        Volume { v: clearance + area * s, dv: area * ds, d2v: area * d2s }
    }

    /// J/rad, dQ/dϑ of the Wiebe heat release at ϑ (about firing TDC).
    fn heat_release_rate(&self, theta: f64) -> f64 {
        let p = &self.parameters;
        let x = (theta - p.burn_start) / p.burn_duration;
        if x <= 0.0 || p.heat_release == 0.0 {
            return 0.0;
        }
        let xm = x.powi(WIEBE_FORM);
        let rate = WIEBE_EFFICIENCY * f64::from(WIEBE_FORM + 1) / p.burn_duration * xm * libm::exp(-WIEBE_EFFICIENCY * xm * x);
        p.heat_release * rate
    }

    /// dp/dϑ of the closed cylinder (first law with the polytropic exponent).
    fn closed_slope(&self, theta: f64, pressure: f64) -> f64 {
        let n = self.parameters.polytropic_exponent;
        let vol = self.volume(theta);
        (-n * pressure * vol.dv + (n - 1.0) * self.heat_release_rate(theta)) / vol.v
    }

    /// Absolute cylinder pressure p and dp/dϑ at crank angle `crank_angle` (any value; period 4π).
    pub fn pressure(&self, crank_angle: f64) -> (f64, f64) {
        let p = &self.parameters;
        let theta = (crank_angle + PI).rem_euclid(CYCLE) - PI;
        let evo = p.exhaust_valve_opening;
        if theta <= evo {
            self.closed_pressure(theta)
        } else if theta <= PI {
            let (p_evo, _) = self.closed_pressure(evo);
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

    /// The closed-cycle table, cubic Hermite between its nodes.
    fn closed_pressure(&self, theta: f64) -> (f64, f64) {
        let u = ((theta + PI) / TABLE_SPACING).max(0.0);
        let k = (u.floor() as usize).min(self.table.len() - 2);
        let t = u - k as f64;
        let ((p0, d0), (p1, d1)) = (self.table[k], self.table[k + 1]);
        let h = TABLE_SPACING;
        let (t2, t3) = (t * t, t * t * t);
        let value = (2.0 * t3 - 3.0 * t2 + 1.0) * p0 + (t3 - 2.0 * t2 + t) * h * d0 + (-2.0 * t3 + 3.0 * t2) * p1 + (t3 - t2) * h * d1;
        let slope =
            ((6.0 * t2 - 6.0 * t) * p0 + (6.0 * t2 - 6.0 * t) * -p1) / h + (3.0 * t2 - 4.0 * t + 1.0) * d0 + (3.0 * t2 - 2.0 * t) * d1;
        (value, slope)
    }

    /// rad/s and rad/s²: the prescribed speed (constant, or the linear ramp) at time `t`.
    pub fn speed(&self, t: f64) -> (f64, f64) {
        let p = &self.parameters;
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
        let p = &self.parameters;
        let elapsed = (t - self.start_time).max(0.0);
        if p.ramp_time > 0.0 {
            let ramp = elapsed.min(p.ramp_time);
            let slope = (p.speed_end - p.speed_start) / p.ramp_time;
            p.crank_angle_start + p.speed_start * ramp + 0.5 * slope * ramp * ramp + p.speed_end * (elapsed - ramp)
        } else {
            p.crank_angle_start + p.speed_start * elapsed
        }
    }

    /// The outputs at time `t` and their first time derivatives.
    pub fn outputs(&self, t: f64) -> (EngineCycleOutputs, EngineCycleOutputs) {
        let crank_angle = self.crank_angle(t);
        let (speed, acceleration) = self.speed(t);
        let (pressure, slope) = self.pressure(crank_angle);
        let vol = self.volume(crank_angle);
        let gauge = pressure - self.parameters.crankcase_pressure;
        let value = EngineCycleOutputs {
            crank_angle,
            crank_speed: speed,
            cylinder_pressure: pressure,
            gas_pressure: gauge,
            indicated_torque: gauge * vol.dv,
        };
        let rate = EngineCycleOutputs {
            crank_angle: speed,
            crank_speed: acceleration,
            cylinder_pressure: slope * speed,
            gas_pressure: slope * speed,
            indicated_torque: (slope * vol.dv + gauge * vol.d2v) * speed,
        };
        (value, rate)
    }

    /// Pa, indicated mean effective pressure ∮ p dV / V_d over one cycle, by the trapezoidal rule on
    /// `samples` equal crank-angle intervals.
    pub fn imep(&self, samples: usize) -> f64 {
        let h = CYCLE / samples as f64;
        let torque = |k: usize| {
            let theta = -PI + k as f64 * h;
            (self.pressure(theta).0 - self.parameters.crankcase_pressure) * self.volume(theta).dv
        };
        let work: f64 = (0..samples).map(|k| 0.5 * h * (torque(k) + torque(k + 1))).sum();
        work / self.parameters.displacement()
    }
}

/// The engine cycle advancing in time as a co-simulation slave: the model, the time and the outputs
/// with their time derivatives at that time.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct EngineCycleRun {
    model: EngineCycle,
    time: f64,
    outputs: EngineCycleOutputs,
    rates: EngineCycleOutputs,
}

impl EngineCycleRun {
    /// At `start_time`, with the parameters validated.
    pub fn new(parameters: &EngineCycleParameters, start_time: f64) -> Result<Self, ModelError> {
        let model = EngineCycle::new(parameters, start_time)?;
        let (outputs, rates) = model.outputs(start_time);
        Ok(Self { model, time: start_time, outputs, rates })
    }

    /// To `t_end` (> the current time): the outputs are closed-form functions of time.
    pub fn step(&mut self, t_end: f64) -> Result<(), ModelError> {
        if !(t_end.is_finite() && t_end > self.time) {
            return Err(ModelError(format!("cannot step from {} s to {t_end} s", self.time)));
        }
        (self.outputs, self.rates) = self.model.outputs(t_end);
        self.time = t_end;
        Ok(())
    }

    pub fn time(&self) -> f64 {
        self.time
    }

    pub fn outputs(&self) -> &EngineCycleOutputs {
        &self.outputs
    }

    /// The outputs' first time derivatives.
    pub fn rates(&self) -> &EngineCycleOutputs {
        &self.rates
    }

    /// A restored run is consistent: the model its parameters make, a finite time, the outputs of that time.
    pub fn check(&self) -> Result<(), ModelError> {
        if EngineCycle::new(&self.model.parameters, self.model.start_time)? != self.model {
            return Err(ModelError("engine cycle state: the pressure table is not the parameters' one".into()));
        }
        let (outputs, rates) = self.model.outputs(self.time);
        if !self.time.is_finite() || outputs != self.outputs || rates != self.rates {
            return Err(ModelError(format!("engine cycle state at {} s is inconsistent", self.time)));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn motored() -> EngineCycle {
        let parameters = EngineCycleParameters { heat_release: 0.0, ..Default::default() };
        EngineCycle::new(&parameters, 0.0).unwrap()
    }

    #[test]
    fn motored_pressure_follows_p_v_to_the_n_constant() {
        let model = motored();
        let p = model.parameters().clone();
        let v_ivc = model.volume(-PI).v;
        let mut worst: f64 = 0.0;
        for k in 0..=20_000 {
            let theta = -PI + (PI + p.exhaust_valve_opening) * k as f64 / 20_000.0;
            let exact = p.intake_pressure * libm::pow(v_ivc / model.volume(theta).v, p.polytropic_exponent);
            worst = worst.max((model.pressure(theta).0 / exact - 1.0).abs());
        }
        println!("motored cycle: largest relative error against p Vⁿ = const {worst:.2e}");
        assert!(worst < 1e-8, "largest relative error {worst:e}");
        // The compression end pressure of the closed form: p_intake ε^n.
        let tdc = p.intake_pressure * libm::pow(p.compression_ratio, p.polytropic_exponent);
        assert!((model.pressure(0.0).0 / tdc - 1.0).abs() < 1e-8);
    }

    #[test]
    fn motored_cycle_is_a_loss_and_fired_cycle_does_work() {
        // Motored: compression and expansion cancel, the blowdown of the still-compressed charge and the
        // pumping loops are losses, so IMEP is small and negative.
        let imep = motored().imep(14_400);
        assert!(imep < 0.0 && imep > -0.5e5, "motored IMEP {imep} Pa");
        let fired = EngineCycle::new(&EngineCycleParameters::default(), 0.0).unwrap();
        let imep = fired.imep(14_400);
        assert!(imep > 5e5 && imep < 15e5, "fired IMEP {imep} Pa");
    }

    #[test]
    fn pressure_slope_is_the_derivative_of_the_pressure() {
        let model = EngineCycle::new(&EngineCycleParameters::default(), 0.0).unwrap();
        let h = 1e-6;
        for k in 0..400 {
            let theta = -PI + 0.0123 + k as f64 * CYCLE / 400.0;
            let numeric = (model.pressure(theta + h).0 - model.pressure(theta - h).0) / (2.0 * h);
            let (p, slope) = model.pressure(theta);
            assert!((numeric - slope).abs() <= 1e-5 * p.max(1e5) + 1e-4 * slope.abs(), "at {theta}: {slope} vs {numeric}");
        }
    }

    #[test]
    fn output_derivatives_are_time_derivatives_of_the_outputs() {
        let parameters = EngineCycleParameters { speed_start: 100.0, speed_end: 200.0, ramp_time: 0.5, ..Default::default() };
        let model = EngineCycle::new(&parameters, 0.1).unwrap();
        let h = 1e-7;
        for k in 0..200 {
            let t = 0.1 + 0.0017 + k as f64 * 0.0031;
            let (_, rate) = model.outputs(t);
            let (up, down) = (model.outputs(t + h).0, model.outputs(t - h).0);
            let numeric = |f: fn(&EngineCycleOutputs) -> f64| (f(&up) - f(&down)) / (2.0 * h);
            assert!((numeric(|o| o.crank_angle) - rate.crank_angle).abs() < 1e-6);
            assert!((numeric(|o| o.crank_speed) - rate.crank_speed).abs() < 1e-3);
            let dp = numeric(|o| o.gas_pressure);
            assert!((dp - rate.gas_pressure).abs() <= 1e-4 * rate.gas_pressure.abs() + 1e3, "t = {t}: {dp} vs {}", rate.gas_pressure);
            let dq = numeric(|o| o.indicated_torque);
            assert!((dq - rate.indicated_torque).abs() <= 1e-4 * rate.indicated_torque.abs() + 1e-1, "t = {t}");
        }
    }

    #[test]
    fn ramp_speed_integrates_to_the_crank_angle() {
        let parameters = EngineCycleParameters { speed_start: 100.0, speed_end: 300.0, ramp_time: 1.0, ..Default::default() };
        let model = EngineCycle::new(&parameters, 0.0).unwrap();
        // ∫ ω dt over the ramp = (100 + 300)/2 · 1 s, then 300 rad/s.
        assert!((model.crank_angle(1.0) - 200.0).abs() < 1e-12);
        assert!((model.crank_angle(2.0) - 500.0).abs() < 1e-12);
        assert_eq!(model.speed(0.5), (200.0, 200.0));
    }

    fn refusal(parameters: &EngineCycleParameters) -> String {
        EngineCycle::new(parameters, 0.0).err().map(|e| e.0).unwrap_or_default()
    }

    #[test]
    fn bad_parameters_are_refused_by_name() {
        let parameters = EngineCycleParameters { rod_length: 0.03, ..Default::default() };
        assert!(refusal(&parameters).contains("rod_length"));
        let parameters = EngineCycleParameters { exhaust_valve_opening: 4.0, ..Default::default() };
        assert!(refusal(&parameters).contains("exhaust_valve_opening"));
        let parameters = EngineCycleParameters { compression_ratio: 1.0, ..Default::default() };
        assert!(refusal(&parameters).contains("compression_ratio"));
        let parameters = EngineCycleParameters { heat_release: f64::NAN, ..Default::default() };
        assert!(refusal(&parameters).contains("heat_release"));
    }

    #[test]
    fn report_fired_default_case() {
        let fired = EngineCycle::new(&EngineCycleParameters::default(), 0.0).unwrap();
        let (peak, at) = (0..7200)
            .map(|k| (fired.pressure(-PI + k as f64 * CYCLE / 7200.0).0, -180.0 + k as f64 * 0.1))
            .fold((0.0, 0.0), |best, x| if x.0 > best.0 { x } else { best });
        println!("fired default: IMEP {:.3} bar, peak {:.2} bar at {at:.1}° after firing TDC", fired.imep(14_400) / 1e5, peak / 1e5);
        // Combustion raises the peak well above the motored compression pressure p_intake ε^n, after TDC.
        let p = fired.parameters();
        let motored = p.intake_pressure * libm::pow(p.compression_ratio, p.polytropic_exponent);
        assert!(peak > 1.3 * motored && peak < 200e5 && at > 0.0 && at < 30.0, "peak {peak} Pa at {at}°");
    }
}
