//! The mechanisms PistonSlap runs, built from its parameters: the one place the FMU's contract becomes the
//! mechanisms' typed designs (`crank_train.rs`, `roller.rs`), after the checks of the crank train's declared
//! space (`design_space.rs`) and at running temperature (`running_geometry.rs`).

pub mod crank_train;
pub(crate) mod design_space;
pub mod roller;
mod running_geometry;

pub use running_geometry::RunningGeometry;

use super::outputs;
use super::{Inputs, Outputs, Parameters};
use crate::models::{CrankTrain, EngineEvent, EngineModel, InputPolynomial, ModelError, Roller, StepInputs};

/// An engine model as PistonSlap runs it: built from its parameters, advanced with its inputs.
pub trait Mechanism: EngineModel {
    /// The model at `start_time` in the initial state of ARCHITECTURE.md §4, or the refusal naming the
    /// offending parameter: the table's ranges (`Parameters::validate`) and the model's own conditions, the
    /// only validation a start makes.
    fn new(params: &Parameters, start_time: f64) -> Result<Self, ModelError>;

    /// Writes the kinematic and force outputs (everything but the impact statistics).
    fn write_outputs(&self, out: &mut Outputs);

    /// Advances to exactly `t_end` with `inputs` held, appending every event to `events`.
    fn advance(&mut self, inputs: &Inputs, t_end: f64, events: &mut Vec<EngineEvent>) -> Result<(), ModelError> {
        self.advance_interpolated(&held(inputs), t_end, events)
    }
}

/// `inputs` held over a step.
pub fn held(inputs: &Inputs) -> StepInputs {
    StepInputs {
        crank_speed: InputPolynomial::held(inputs.crank_speed),
        gas_pressure: InputPolynomial::held(inputs.gas_pressure),
        load_torque: InputPolynomial::held(inputs.load_torque),
    }
}

impl Mechanism for CrankTrain {
    fn new(params: &Parameters, start_time: f64) -> Result<Self, ModelError> {
        CrankTrain::of(crank_train::design(params)?, start_time)
    }

    fn write_outputs(&self, out: &mut Outputs) {
        outputs::crank_train::write(self, out);
    }
}

impl Mechanism for Roller {
    fn new(params: &Parameters, start_time: f64) -> Result<Self, ModelError> {
        Roller::with_design(roller::design(params)?, start_time)
    }

    fn write_outputs(&self, out: &mut Outputs) {
        outputs::roller::write(self, out);
    }
}
