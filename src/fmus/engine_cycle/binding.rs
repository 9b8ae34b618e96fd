//! EngineCycle as the FMI layer runs it: the engine cycle model on its own variable table, with the
//! time derivatives of its outputs.

use super::contract::{Inputs, Outputs, Parameters};
use super::design::design;
use super::run::EngineCycleRun;
use super::variables::DESCRIPTION as TABLE;
use crate::fmi::{self, Causality, Description, Model};
use crate::models::EngineCycle;
use std::path::Path;

impl Model for EngineCycle {
    const NAME: &'static str = "EngineCycle";
    type Parameters = Parameters;
    type Inputs = Inputs;
    type Outputs = Outputs;
    type InputDerivatives = ();
    type Simulation = EngineCycleRun;
    const DESCRIPTION: Description<Parameters, Inputs, Outputs> = TABLE;
    const MAX_INPUT_DERIVATIVE_ORDER: i32 = 0;
    const MAX_OUTPUT_DERIVATIVE_ORDER: i32 = 1;
    const INSTANCE_TAG: u64 = u64::from_le_bytes(*b"ENGCYINS");
    const STATE_TAG: u64 = u64::from_le_bytes(*b"ENGCYSTA");

    fn resolve(parameters: &Parameters, _: Option<&Path>) -> Parameters {
        parameters.clone()
    }
    fn validate(parameters: &Parameters) -> Result<(), fmi::Error> {
        design(parameters)?;
        Ok(())
    }
    fn preview(parameters: &Parameters, _: &Inputs, start_time: f64) -> Result<EngineCycleRun, fmi::Error> {
        Ok(EngineCycleRun::new(parameters, start_time)?)
    }
    fn start(parameters: &Parameters, _: &Inputs, start_time: f64) -> Result<EngineCycleRun, fmi::Error> {
        Ok(EngineCycleRun::new(parameters, start_time)?)
    }
    fn step(sim: &mut EngineCycleRun, _: &Inputs, _: &(), t_end: f64) -> Result<(), fmi::Error> {
        Ok(sim.step(t_end)?)
    }
    fn time(sim: &EngineCycleRun) -> f64 {
        sim.time()
    }
    fn outputs(sim: &EngineCycleRun) -> &Outputs {
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
        (Self::DESCRIPTION.get_real)(vr, &Parameters::default(), &Inputs {}, sim.rates())
    }
}
