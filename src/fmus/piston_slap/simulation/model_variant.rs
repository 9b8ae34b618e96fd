//! The model variants behind one type, chosen by `model_variant`: 1 → crank train (Awrejcewicz &
//! Kudra), 2 → roller slider crank (Farahanchi).

use super::super::Mechanism;
use crate::fmus::piston_slap::{Outputs, Parameters};
use crate::models::skirt::PressureMap;
use crate::models::{CrankTrain, EngineEvent, EngineModel, ModelError, Roller, StepInputs};
use serde::{Deserialize, Serialize};

/// The engine model the FMU runs (one per instance, so the variants' size difference costs nothing).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[allow(clippy::large_enum_variant)]
pub enum ModelVariant {
    /// `model_variant = 1`.
    CrankTrain(CrankTrain),
    /// `model_variant = 2`.
    Roller(Roller),
}

/// `$call` on whichever variant `$self` holds, bound to `$m`.
macro_rules! on_variant {
    ($self:ident, $m:ident => $call:expr) => {
        match $self {
            ModelVariant::CrankTrain($m) => $call,
            ModelVariant::Roller($m) => $call,
        }
    };
}

impl Mechanism for ModelVariant {
    fn new(params: &Parameters, start_time: f64) -> Result<Self, ModelError> {
        match params.model_variant {
            1 => CrankTrain::new(params, start_time).map(ModelVariant::CrankTrain),
            2 => Roller::new(params, start_time).map(ModelVariant::Roller),
            other => Err(ModelError(format!("model_variant = {other} is not one of 1..=2"))),
        }
    }

    fn write_outputs(&self, out: &mut Outputs) {
        on_variant!(self, m => m.write_outputs(out))
    }
}

impl EngineModel for ModelVariant {
    fn advance_interpolated(&mut self, inputs: &StepInputs, t_end: f64, events: &mut Vec<EngineEvent>) -> Result<(), ModelError> {
        on_variant!(self, m => m.advance_interpolated(inputs, t_end, events))
    }

    fn prepare(&mut self, inputs: &StepInputs) -> Result<(), ModelError> {
        on_variant!(self, m => m.prepare(inputs))
    }

    fn pressure_map(&self) -> Option<PressureMap> {
        on_variant!(self, m => m.pressure_map())
    }

    fn serve(&mut self, inputs: &StepInputs, t_end: f64) -> Option<Result<(), ModelError>> {
        on_variant!(self, m => m.serve(inputs, t_end))
    }

    fn serve_again(&mut self, t: f64) -> Result<(), ModelError> {
        on_variant!(self, m => m.serve_again(t))
    }
}
