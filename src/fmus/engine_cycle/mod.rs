//! EngineCycle.fmu's room: the engine cycle model (`crate::models::engine_cycle`) bound to the FMI layer, its
//! run (`EngineCycleRun`), its variable table and its package.

mod binding;
mod package;
mod run;
mod variables;

pub use package::PACKAGE;
pub use run::EngineCycleRun;
pub use variables::{DESCRIPTION, GUID, MODEL_DESCRIPTION_XML, VARIABLES};

/// The type the FMI layer runs this FMU as.
pub type Fmu = crate::models::EngineCycle;
