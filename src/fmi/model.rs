//! What the FMI layer needs of a model, so that one glue serves every FMU of the crate (as Reference-FMUs'
//! `fmi2Functions.c` serves every model): its variable table and a simulation to start, step and save.
//! Each FMU's room implements it; the layer reaches them through the symbols the rooms' registry has
//! [`super::exports!`] write, and names none. Safe code.

use super::description::Description;
use super::error::Error;
use super::logger::Logger;
use serde::{de::DeserializeOwned, Serialize};
use std::fmt::Debug;
use std::path::Path;

/// A model the FMI layer can run as an FMU.
pub trait Model: Sized + Clone + Debug + 'static {
    /// The FMU's name in messages.
    const NAME: &'static str;
    /// The parameters, one field per parameter of the table.
    type Parameters: Clone + Debug + Default + Serialize + DeserializeOwned + 'static;
    /// The inputs, one field per input of the table.
    type Inputs: Clone + Debug + Default + Serialize + DeserializeOwned + 'static;
    /// The outputs, one field per output of the table.
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
    /// Mark live instances and FMU states of this model: a pointer of another model is refused. The state
    /// tag's bytes also open the model's serialized states.
    const INSTANCE_TAG: u64;
    /// See `INSTANCE_TAG`.
    const STATE_TAG: u64;

    /// The parameters with bare file names turned into their paths in the FMU's `resources/`.
    fn resolve(parameters: &Self::Parameters, resources: Option<&Path>) -> Self::Parameters;
    /// The parameters' own checks (ranges and relations), naming the parameter.
    fn validate(parameters: &Self::Parameters) -> Result<(), Error>;
    /// The simulation at `start_time`, touching no file: its outputs are the initial ones, of the
    /// state the first step starts from with `inputs` (a free crank at its start speed).
    fn preview(parameters: &Self::Parameters, inputs: &Self::Inputs, start_time: f64) -> Result<Self::Simulation, Error>;
    /// The simulation fmi2ExitInitializationMode starts (opening its files), prepared as `preview`'s.
    fn start(parameters: &Self::Parameters, inputs: &Self::Inputs, start_time: f64) -> Result<Self::Simulation, Error>;
    /// Advances to `t_end` with the inputs following their derivatives.
    fn step(sim: &mut Self::Simulation, inputs: &Self::Inputs, derivatives: &Self::InputDerivatives, t_end: f64) -> Result<(), Error>;
    /// Logs what happened during the last step (category `logEvents`); a model without events logs nothing.
    fn log_step(_sim: &Self::Simulation, _logger: &Logger) {}
    /// s, the time the simulation has reached.
    fn time(sim: &Self::Simulation) -> f64;
    /// The outputs at that time.
    fn outputs(sim: &Self::Simulation) -> &Self::Outputs;
    /// A restored simulation is one the parameters can make.
    fn check(sim: &Self::Simulation) -> Result<(), Error>;
    /// Why a restored simulation may not cut the files it writes: a file the instance's parameters
    /// do not name (a restored state may cut only the instance's own), None when it may. A model that
    /// writes no file has none.
    fn foreign_files(_sim: &Self::Simulation, _parameters: &Self::Parameters) -> Option<String> {
        None
    }
    /// Cuts the files the simulation writes back to what it has written (after a restore).
    fn rewind_files(_sim: &Self::Simulation) -> Result<(), Error> {
        Ok(())
    }
    /// The derivatives of the input called `name`, None when it has none.
    fn input_derivatives<'a>(derivatives: &'a mut Self::InputDerivatives, name: &str) -> Option<&'a mut [f64; 2]>;
    /// The `order`-th time derivative of output `vr` now (1 ≤ order ≤ MAX_OUTPUT_DERIVATIVE_ORDER).
    fn output_derivative(sim: &Self::Simulation, vr: u32, order: i32) -> Option<f64>;
}
