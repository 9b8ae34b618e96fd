//! EngineCycle's run as the FMU steps it: the cycle model with the time reached and the outputs there.

use super::contract::{Outputs, Parameters};
use super::design::design;
use crate::models::{EngineCycle, ModelError};
use serde::{Deserialize, Serialize};

/// The engine cycle advancing in time as a co-simulation slave: the model, the time and the outputs
/// with their time derivatives at that time.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct EngineCycleRun {
    model: EngineCycle,
    time: f64,
    outputs: Outputs,
    rates: Outputs,
}

impl EngineCycleRun {
    /// At `start_time`, with the parameters validated.
    pub fn new(parameters: &Parameters, start_time: f64) -> Result<Self, ModelError> {
        let model = EngineCycle::new(&design(parameters)?, start_time)?;
        let (outputs, rates) = outputs(&model, start_time);
        Ok(Self { model, time: start_time, outputs, rates })
    }

    /// To `t_end` (> the current time): the outputs are closed-form functions of time.
    pub fn step(&mut self, t_end: f64) -> Result<(), ModelError> {
        if !(t_end.is_finite() && t_end > self.time) {
            return Err(ModelError(format!("cannot step from {} s to {t_end} s", self.time)));
        }
        (self.outputs, self.rates) = outputs(&self.model, t_end);
        self.time = t_end;
        Ok(())
    }

    /// s, the time reached.
    pub fn time(&self) -> f64 {
        self.time
    }

    /// The outputs at `time()`.
    pub fn outputs(&self) -> &Outputs {
        &self.outputs
    }

    /// The outputs' first time derivatives.
    pub fn rates(&self) -> &Outputs {
        &self.rates
    }

    /// A restored run is consistent: the model its design makes, a finite time, the outputs of that time.
    pub fn check(&self) -> Result<(), ModelError> {
        if EngineCycle::new(self.model.design(), self.model.start_time())? != self.model {
            return Err(ModelError("engine cycle state: the closed-cycle table is not the parameters' one".into()));
        }
        let (outputs, rates) = outputs(&self.model, self.time);
        if !self.time.is_finite() || outputs != self.outputs || rates != self.rates {
            return Err(ModelError(format!("engine cycle state at {} s is inconsistent", self.time)));
        }
        Ok(())
    }
}

/// The outputs of `model` at time `t` and their first time derivatives. `wall_heat_total` is the wall heat since
/// the start time, `wall_heat_flux` its time derivative `dQ_w/dϑ · ω`.
pub fn outputs(model: &EngineCycle, t: f64) -> (Outputs, Outputs) {
    let crank_angle = model.crank_angle(t);
    let (speed, acceleration) = model.speed(t);
    let (pressure, slope) = model.pressure(crank_angle);
    let vol = model.volume(crank_angle);
    let gauge = pressure - model.design().crankcase_pressure;
    let (q, dq, d2q) = model.wall_heat(crank_angle);
    let q_start = model.wall_heat(model.design().crank_angle_start).0;
    let value = Outputs {
        crank_angle,
        crank_speed: speed,
        cylinder_pressure: pressure,
        gas_pressure: gauge,
        indicated_torque: gauge * vol.dv,
        wall_heat_flux: dq * speed,
        wall_heat_total: q - q_start,
    };
    let rate = Outputs {
        crank_angle: speed,
        crank_speed: acceleration,
        cylinder_pressure: slope * speed,
        gas_pressure: slope * speed,
        indicated_torque: (slope * vol.dv + gauge * vol.d2v) * speed,
        wall_heat_flux: d2q * speed * speed + dq * acceleration,
        wall_heat_total: dq * speed,
    };
    (value, rate)
}
