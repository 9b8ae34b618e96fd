//! EngineCycle.fmu's room: its contract (generated from `modelDescription/engine_cycle.xml`), the engine cycle model
//! (`crate::models::engine_cycle`) built from it and bound to the FMI layer, its run (`EngineCycleRun`) and outputs,
//! its variable table and its package.

mod binding;
mod contract;
mod design;
mod package;
mod run;
#[cfg(test)]
mod tests;
mod variables;

pub use contract::{Inputs, Outputs, Parameters};
pub use design::design;
pub use package::PACKAGE;
pub use run::EngineCycleRun;
pub use variables::{DESCRIPTION, GUID, MODEL_DESCRIPTION_XML, VARIABLES};

/// The type the FMI layer runs this FMU as.
pub type Fmu = crate::models::EngineCycle;
