//! What the FMI layer needs of a model, so that one glue serves every FMU of the crate (as Reference-FMUs'
//! `fmi2Functions.c` serves every model): its variable table and a simulation to start, step and save.
//! Two implementations: PistonSlap (every engine model of [`Simulation`], the shipped [`ModelVariant`]
//! and the test models) and the partner [`EngineCycle`]. Safe code.
//!
//! [`ModelVariant`]: crate::simulation::ModelVariant

use super::description::{self, Description};
use super::logger::Logger;
use crate::models::{
    EngineCycle, EngineCycleInputs, EngineCycleOutputs, EngineCycleParameters, EngineCycleRun, EngineModel, InputDerivatives, Inputs,
    ModelError, Outputs, Parameters,
};
use crate::simulation::Simulation;
use serde::{de::DeserializeOwned, Serialize};
use std::fmt::Debug;
use std::path::Path;

/// A model the FMI layer can run as an FMU.
pub trait Model: Sized + Clone + Debug + 'static {
    /// The FMU's name in messages.
    const NAME: &'static str;
    type Parameters: Clone + Debug + Default + Serialize + DeserializeOwned + 'static;
    type Inputs: Clone + Debug + Default + Serialize + DeserializeOwned + 'static;
    type Outputs: Default + 'static;
    /// The input derivatives fmi2SetRealInputDerivatives sets, saved with the FMU state.
    type InputDerivatives: Clone + Debug + Default + Serialize + DeserializeOwned;
    /// The running simulation an FMU state saves.
    type Simulation: Clone + Debug + Serialize + DeserializeOwned;
    /// The variable table generated from the model's `modelDescription/` file.
    const DESCRIPTION: Description<Self::Parameters, Self::Inputs, Self::Outputs>;
    /// The highest order fmi2SetRealInputDerivatives takes (0: none).
    const MAX_INPUT_DERIVATIVE_ORDER: i32;
    /// The highest order fmi2GetRealOutputDerivatives gives (0: none), as the XML declares.
    const MAX_OUTPUT_DERIVATIVE_ORDER: i32;
    /// Mark live instances and FMU states of this model: a pointer of another model is refused.
    const INSTANCE_TAG: u64;
    const STATE_TAG: u64;

    /// The parameters with bare file names turned into their paths in the FMU's `resources/`.
    fn resolve(parameters: &Self::Parameters, resources: Option<&Path>) -> Self::Parameters;
    /// The parameters' own checks (ranges and relations), naming the parameter.
    fn validate(parameters: &Self::Parameters) -> Result<(), ModelError>;
    /// The simulation at `start_time`, touching no file: its outputs are the initial ones, of the
    /// state the first step starts from with `inputs` (a free crank at its start speed).
    fn preview(parameters: &Self::Parameters, inputs: &Self::Inputs, start_time: f64) -> Result<Self::Simulation, ModelError>;
    /// The simulation fmi2ExitInitializationMode starts (opening its files), prepared as `preview`'s.
    fn start(parameters: &Self::Parameters, inputs: &Self::Inputs, start_time: f64) -> Result<Self::Simulation, ModelError>;
    /// Advances to `t_end` with the inputs following their derivatives.
    fn step(sim: &mut Self::Simulation, inputs: &Self::Inputs, derivatives: &Self::InputDerivatives, t_end: f64) -> Result<(), ModelError>;
    /// Logs what happened during the last step (category `logEvents`).
    fn log_step(sim: &Self::Simulation, logger: &Logger);
    fn time(sim: &Self::Simulation) -> f64;
    fn outputs(sim: &Self::Simulation) -> &Self::Outputs;
    /// A restored simulation is one the parameters can make.
    fn check(sim: &Self::Simulation) -> Result<(), ModelError>;
    /// The file the instance's parameters write to ("" when none): a restored state may cut only it.
    fn own_log(parameters: &Self::Parameters) -> &str;
    /// The file a simulation writes to, if any.
    fn log_path(sim: &Self::Simulation) -> Option<&str>;
    /// Cuts that file back to what the simulation has written.
    fn rewind_log(sim: &Self::Simulation) -> Result<(), ModelError>;
    /// The derivatives of the input called `name`, None when it has none.
    fn input_derivatives<'a>(derivatives: &'a mut Self::InputDerivatives, name: &str) -> Option<&'a mut [f64; 2]>;
    /// The `order`-th time derivative of output `vr` now (1 ≤ order ≤ MAX_OUTPUT_DERIVATIVE_ORDER).
    fn output_derivative(sim: &Self::Simulation, vr: u32, order: i32) -> Option<f64>;
}

impl<E: EngineModel + Debug + Serialize + DeserializeOwned + 'static> Model for E {
    const NAME: &'static str = "PistonSlap";
    type Parameters = Parameters;
    type Inputs = Inputs;
    type Outputs = Outputs;
    type InputDerivatives = InputDerivatives;
    type Simulation = Simulation<E>;
    const DESCRIPTION: Description<Parameters, Inputs, Outputs> = description::PISTON_SLAP;
    const MAX_INPUT_DERIVATIVE_ORDER: i32 = 2;
    const MAX_OUTPUT_DERIVATIVE_ORDER: i32 = 0;
    const INSTANCE_TAG: u64 = u64::from_le_bytes(*b"PSLAPINS");
    const STATE_TAG: u64 = u64::from_le_bytes(*b"PSLAPSTA");

    fn resolve(parameters: &Parameters, resources: Option<&Path>) -> Parameters {
        let trace = super::resources::resolve(&parameters.pressure_trace, resources);
        Parameters { pressure_trace: trace, ..parameters.clone() }
    }
    fn validate(parameters: &Parameters) -> Result<(), ModelError> {
        parameters.validate()
    }
    fn preview(parameters: &Parameters, inputs: &Inputs, start_time: f64) -> Result<Simulation<E>, ModelError> {
        let mut sim = Simulation::new(parameters, start_time)?;
        sim.prepare(inputs)?;
        Ok(sim)
    }
    fn start(parameters: &Parameters, inputs: &Inputs, start_time: f64) -> Result<Simulation<E>, ModelError> {
        let mut sim = Simulation::start(parameters, start_time)?;
        sim.prepare(inputs)?;
        Ok(sim)
    }
    fn step(sim: &mut Simulation<E>, inputs: &Inputs, derivatives: &InputDerivatives, t_end: f64) -> Result<(), ModelError> {
        sim.step_interpolated(inputs, derivatives, t_end)
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
    fn check(sim: &Simulation<E>) -> Result<(), ModelError> {
        sim.check()
    }
    fn own_log(parameters: &Parameters) -> &str {
        &parameters.impact_log
    }
    fn log_path(sim: &Simulation<E>) -> Option<&str> {
        sim.log_path()
    }
    fn rewind_log(sim: &Simulation<E>) -> Result<(), ModelError> {
        sim.rewind_log()
    }
    fn input_derivatives<'a>(derivatives: &'a mut InputDerivatives, name: &str) -> Option<&'a mut [f64; 2]> {
        derivatives.of_mut(name)
    }
    fn output_derivative(_: &Simulation<E>, _: u32, _: i32) -> Option<f64> {
        None
    }
}

impl Model for EngineCycle {
    const NAME: &'static str = "EngineCycle";
    type Parameters = EngineCycleParameters;
    type Inputs = EngineCycleInputs;
    type Outputs = EngineCycleOutputs;
    type InputDerivatives = ();
    type Simulation = EngineCycleRun;
    const DESCRIPTION: Description<EngineCycleParameters, EngineCycleInputs, EngineCycleOutputs> = description::engine_cycle::DESCRIPTION;
    const MAX_INPUT_DERIVATIVE_ORDER: i32 = 0;
    const MAX_OUTPUT_DERIVATIVE_ORDER: i32 = 1;
    const INSTANCE_TAG: u64 = u64::from_le_bytes(*b"ENGCYINS");
    const STATE_TAG: u64 = u64::from_le_bytes(*b"ENGCYSTA");

    fn resolve(parameters: &EngineCycleParameters, _: Option<&Path>) -> EngineCycleParameters {
        parameters.clone()
    }
    fn validate(parameters: &EngineCycleParameters) -> Result<(), ModelError> {
        parameters.validate()
    }
    fn preview(parameters: &EngineCycleParameters, _: &EngineCycleInputs, start_time: f64) -> Result<EngineCycleRun, ModelError> {
        EngineCycleRun::new(parameters, start_time)
    }
    fn start(parameters: &EngineCycleParameters, _: &EngineCycleInputs, start_time: f64) -> Result<EngineCycleRun, ModelError> {
        EngineCycleRun::new(parameters, start_time)
    }
    fn step(sim: &mut EngineCycleRun, _: &EngineCycleInputs, _: &(), t_end: f64) -> Result<(), ModelError> {
        sim.step(t_end)
    }
    fn log_step(_: &EngineCycleRun, _: &Logger) {}
    fn time(sim: &EngineCycleRun) -> f64 {
        sim.time()
    }
    fn outputs(sim: &EngineCycleRun) -> &EngineCycleOutputs {
        sim.outputs()
    }
    fn check(sim: &EngineCycleRun) -> Result<(), ModelError> {
        sim.check()
    }
    fn own_log(_: &EngineCycleParameters) -> &str {
        ""
    }
    fn log_path(_: &EngineCycleRun) -> Option<&str> {
        None
    }
    fn rewind_log(_: &EngineCycleRun) -> Result<(), ModelError> {
        Ok(())
    }
    fn input_derivatives<'a>(_: &'a mut (), _: &str) -> Option<&'a mut [f64; 2]> {
        None
    }
    fn output_derivative(sim: &EngineCycleRun, vr: u32, order: i32) -> Option<f64> {
        // The rates are an Outputs value: read with the same generated dispatch as the outputs.
        let output = Self::DESCRIPTION.variable(vr).is_some_and(|v| v.causality == description::Causality::Output);
        if order != 1 || !output {
            return None;
        }
        (Self::DESCRIPTION.get_real)(vr, &EngineCycleParameters::default(), &EngineCycleInputs {}, sim.rates())
    }
}
