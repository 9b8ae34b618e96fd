//! EngineCycle's run as the FMU steps it: the cycle model with the time reached and the outputs there.

use crate::models::{EngineCycle, EngineCycleOutputs, EngineCycleParameters, ModelError};
use serde::{Deserialize, Serialize};

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

    /// s, the time reached.
    pub fn time(&self) -> f64 {
        self.time
    }

    /// The outputs at `time()`.
    pub fn outputs(&self) -> &EngineCycleOutputs {
        &self.outputs
    }

    /// The outputs' first time derivatives.
    pub fn rates(&self) -> &EngineCycleOutputs {
        &self.rates
    }

    /// A restored run is consistent: the model its parameters make, a finite time, the outputs of that time.
    pub fn check(&self) -> Result<(), ModelError> {
        if EngineCycle::new(self.model.parameters(), self.model.start_time())? != self.model {
            return Err(ModelError("engine cycle state: the closed-cycle table is not the parameters' one".into()));
        }
        let (outputs, rates) = self.model.outputs(self.time);
        if !self.time.is_finite() || outputs != self.outputs || rates != self.rates {
            return Err(ModelError(format!("engine cycle state at {} s is inconsistent", self.time)));
        }
        Ok(())
    }
}
