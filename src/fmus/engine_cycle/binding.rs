//! EngineCycle as the FMI layer runs it: the engine cycle model on its own variable table, with the
//! time derivatives of its outputs.

use super::run::EngineCycleRun;
use super::variables::DESCRIPTION as TABLE;
use crate::fmi::{self, Causality, Description, Model};
use crate::models::{EngineCycle, EngineCycleInputs, EngineCycleOutputs, EngineCycleParameters};
use std::path::Path;

impl Model for EngineCycle {
    const NAME: &'static str = "EngineCycle";
    type Parameters = EngineCycleParameters;
    type Inputs = EngineCycleInputs;
    type Outputs = EngineCycleOutputs;
    type InputDerivatives = ();
    type Simulation = EngineCycleRun;
    const DESCRIPTION: Description<EngineCycleParameters, EngineCycleInputs, EngineCycleOutputs> = TABLE;
    const MAX_INPUT_DERIVATIVE_ORDER: i32 = 0;
    const MAX_OUTPUT_DERIVATIVE_ORDER: i32 = 1;
    const INSTANCE_TAG: u64 = u64::from_le_bytes(*b"ENGCYINS");
    const STATE_TAG: u64 = u64::from_le_bytes(*b"ENGCYSTA");

    fn resolve(parameters: &EngineCycleParameters, _: Option<&Path>) -> EngineCycleParameters {
        parameters.clone()
    }
    fn validate(parameters: &EngineCycleParameters) -> Result<(), fmi::Error> {
        Ok(parameters.validate()?)
    }
    fn preview(parameters: &EngineCycleParameters, _: &EngineCycleInputs, start_time: f64) -> Result<EngineCycleRun, fmi::Error> {
        Ok(EngineCycleRun::new(parameters, start_time)?)
    }
    fn start(parameters: &EngineCycleParameters, _: &EngineCycleInputs, start_time: f64) -> Result<EngineCycleRun, fmi::Error> {
        Ok(EngineCycleRun::new(parameters, start_time)?)
    }
    fn step(sim: &mut EngineCycleRun, _: &EngineCycleInputs, _: &(), t_end: f64) -> Result<(), fmi::Error> {
        Ok(sim.step(t_end)?)
    }
    fn time(sim: &EngineCycleRun) -> f64 {
        sim.time()
    }
    fn outputs(sim: &EngineCycleRun) -> &EngineCycleOutputs {
        sim.outputs()
    }
    fn check(sim: &EngineCycleRun) -> Result<(), fmi::Error> {
        Ok(sim.check()?)
    }
    fn input_derivatives<'a>(_: &'a mut (), _: &str) -> Option<&'a mut [f64; 2]> {
        None
    }
    fn output_derivative(sim: &EngineCycleRun, vr: u32, order: i32) -> Option<f64> {
        // The rates are an Outputs value: read with the same generated dispatch as the outputs.
        let output = Self::DESCRIPTION.variable(vr).is_some_and(|v| v.causality == Causality::Output);
        if order != 1 || !output {
            return None;
        }
        (Self::DESCRIPTION.get_real)(vr, &EngineCycleParameters::default(), &EngineCycleInputs {}, sim.rates())
    }
}
