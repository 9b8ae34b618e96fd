//! The model variants behind one type: `model_variant` 1 → crank train, 2 → roller slider crank.
//! Each variant wires itself in here when its model lands (a variant, an arm in each match).

use crate::models::{EngineEvent, EngineModel, Inputs, ModelError, Outputs, Parameters};
use serde::{Deserialize, Serialize};

/// The engine model the FMU runs, chosen by `model_variant`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Engine {}

impl EngineModel for Engine {
    fn new(params: &Parameters, _start_time: f64) -> Result<Self, ModelError> {
        let name = match params.model_variant {
            1 => "1 (crank train)",
            2 => "2 (roller slider crank)",
            other => {
                return Err(ModelError(format!(
                    "model_variant = {other} is not one of 1..=2"
                )))
            }
        };
        Err(ModelError(format!(
            "model_variant = {name} is not available in this build"
        )))
    }

    fn advance(
        &mut self,
        _inputs: &Inputs,
        _t_end: f64,
        _events: &mut Vec<EngineEvent>,
    ) -> Result<(), ModelError> {
        match *self {}
    }

    fn write_outputs(&self, _out: &mut Outputs) {
        match *self {}
    }
}
