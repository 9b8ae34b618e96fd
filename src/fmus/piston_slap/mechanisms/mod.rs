//! The mechanisms PistonSlap runs, built from its parameters: the one place the FMU's contract becomes the
//! mechanisms' typed designs (`crank_train.rs`, `roller.rs`), after the checks of the crank train's declared
//! space (`design_space.rs`) and at running temperature (`running_geometry.rs`).

pub mod crank_train;
pub(crate) mod design_space;
pub mod roller;
mod running_geometry;

pub use running_geometry::RunningGeometry;

use crate::models::{CrankTrain, EngineModel, Inputs, ModelError, Parameters, Roller};

/// An engine model the façade builds from PistonSlap's parameters.
pub trait Mechanism: EngineModel {
    /// The model at `start_time` in the initial state of ARCHITECTURE.md §4, or the refusal naming the
    /// offending parameter: the table's ranges (`Parameters::validate`) and the model's own conditions, the
    /// only validation a start makes.
    fn new(params: &Parameters, start_time: f64) -> Result<Self, ModelError>;
}

impl Mechanism for CrankTrain {
    fn new(params: &Parameters, start_time: f64) -> Result<Self, ModelError> {
        CrankTrain::of(crank_train::design(params)?, start_time)
    }
}

impl Mechanism for Roller {
    fn new(params: &Parameters, start_time: f64) -> Result<Self, ModelError> {
        Roller::with_design(roller::design(params)?, start_time)
    }
}
