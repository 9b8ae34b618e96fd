//! PistonSlap as the FMI layer runs it: every engine model of [`Simulation`] (the shipped [`ModelVariant`]
//! and the test models) on PistonSlap's variable table.
//!
//! [`ModelVariant`]: super::ModelVariant

use super::simulation::Simulation;
use super::variables::DESCRIPTION as TABLE;
use super::Mechanism;
use crate::fmi::{self, Description, Logger, Model};
use crate::fmus::piston_slap::{InputDerivatives, Inputs, Outputs, Parameters};
use serde::{de::DeserializeOwned, Serialize};
use std::fmt::Debug;
use std::path::Path;

impl<E: Mechanism + Debug + Serialize + DeserializeOwned + 'static> Model for E {
    const NAME: &'static str = "PistonSlap";
    type Parameters = Parameters;
    type Inputs = Inputs;
    type Outputs = Outputs;
    type InputDerivatives = InputDerivatives;
    type Simulation = Simulation<E>;
    const DESCRIPTION: Description<Parameters, Inputs, Outputs> = TABLE;
    const MAX_INPUT_DERIVATIVE_ORDER: i32 = 2;
    const MAX_OUTPUT_DERIVATIVE_ORDER: i32 = 0;
    const INSTANCE_TAG: u64 = u64::from_le_bytes(*b"PSLAPINS");
    const STATE_TAG: u64 = u64::from_le_bytes(*b"PSLAPSTA");

    fn resolve(parameters: &Parameters, resources: Option<&Path>) -> Parameters {
        let trace = fmi::resolve_resource(&parameters.pressure_trace, resources);
        let compliance = fmi::resolve_resource(&parameters.skirt_compliance_file, resources);
        Parameters { pressure_trace: trace, skirt_compliance_file: compliance, ..parameters.clone() }
    }
    fn validate(parameters: &Parameters) -> Result<(), fmi::Error> {
        Ok(parameters.validate()?)
    }
    fn preview(parameters: &Parameters, inputs: &Inputs, start_time: f64) -> Result<Simulation<E>, fmi::Error> {
        let mut sim = Simulation::new(parameters, start_time)?;
        sim.prepare(inputs)?;
        Ok(sim)
    }
    fn start(parameters: &Parameters, inputs: &Inputs, start_time: f64) -> Result<Simulation<E>, fmi::Error> {
        let mut sim = Simulation::start(parameters, start_time)?;
        sim.prepare(inputs)?;
        Ok(sim)
    }
    fn step(sim: &mut Simulation<E>, inputs: &Inputs, derivatives: &InputDerivatives, t_end: f64) -> Result<(), fmi::Error> {
        Ok(sim.step_interpolated(inputs, derivatives, t_end)?)
    }
    fn log_step(sim: &Simulation<E>, logger: &Logger) {
        for e in sim.step_events() {
            logger.debug("logEvents", || {
                format!(
                    "{:?} of corner {} at t = {} s, crank angle {} rad: normal velocity {} → {} m/s, {} J lost",
                    e.kind, e.corner, e.time, e.crank_angle, e.normal_velocity_before, e.normal_velocity_after, e.energy_lost
                )
            });
        }
    }
    fn time(sim: &Simulation<E>) -> f64 {
        sim.time()
    }
    fn outputs(sim: &Simulation<E>) -> &Outputs {
        sim.outputs()
    }
    fn check(sim: &Simulation<E>) -> Result<(), fmi::Error> {
        Ok(sim.check()?)
    }
    fn foreign_files(sim: &Simulation<E>, parameters: &Parameters) -> Option<String> {
        sim.foreign_log(parameters)
    }
    fn rewind_files(sim: &Simulation<E>) -> Result<(), fmi::Error> {
        Ok(sim.rewind_log()?)
    }
    fn input_derivatives<'a>(derivatives: &'a mut InputDerivatives, name: &str) -> Option<&'a mut [f64; 2]> {
        derivatives.of_mut(name)
    }
    fn output_derivative(_: &Simulation<E>, _: u32, _: i32) -> Option<f64> {
        None
    }
}
