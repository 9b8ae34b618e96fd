//! PistonSlap.fmu's room: the mechanisms built from its parameters ([`mechanisms`]), the run façade over them
//! ([`Simulation`]), its binding to the FMI layer, its variable table and its package.

mod binding;
mod contract;
pub mod mechanisms;
mod outputs;
mod package;
pub mod simulation;
mod variables;

pub use contract::{InputDerivatives, Inputs, Outputs, Parameters};
pub use mechanisms::Mechanism;
pub use package::PACKAGE;
pub use simulation::{ModelVariant, Simulation};
pub use variables::{value_reference, variable, DESCRIPTION, GUID, MODEL_DESCRIPTION_XML, VARIABLES};

/// The type the FMI layer runs this FMU as.
pub type Fmu = ModelVariant;
