//! The FMI 2.0 and FMI 3.0 Co-Simulation interfaces, one body per function serving both where their
//! arguments agree: the only `unsafe` code of the crate.
//!
//! - `exports`: the macro that writes the `#[no_mangle]` fmi2* symbols for a registry's FMUs (the rooms'
//!   registry invokes it), each a call of its body in `functions`;
//! - `functions`: the bodies, generic over the engine model: pointers in (`pointers`), the state
//!   machine's check, `catch_unwind`, logging out; `fmi3_functions`, FMI 3.0's where its arguments differ;
//! - `fmi3_exports`: the fmi3* symbols `exports` writes beside the fmi2* ones;
//! - `state_machine`: the states and the one table of the states each function is allowed in;
//! - `reentry`: refuses a call into an instance from inside its own call (its logger calling back);
//! - `registry`: dispatch over the FMUs the symbols were written for, naming none;
//! - `identity`: which FMU a copy of the binary belongs to (stamped by the packer);
//! - `model`: what the layer needs of a model (each FMU's room implements it); `error`: what a model answers
//!   when it refuses or fails;
//! - `package`: what the packer needs of an FMU;
//! - `instance`: what each function does, in safe code;
//! - `resources`: the FMU's resources directory and the lookup of bare file names in it;
//! - `description`: the variable table generated from `modelDescription/`;
//! - `snapshot`: what an FMU state points to; `state_bytes`: the serialized FMU state.

pub mod description;
mod error;
mod exports;
mod fmi3_exports;
pub(crate) mod fmi3_functions;
pub(crate) mod functions;
pub mod identity;
mod instance;
mod logger;
mod model;
mod package;
mod pointers;
mod reentry;
pub(crate) mod registry;
mod resources;
mod snapshot;
mod state_bytes;
pub(crate) mod state_machine;
pub mod types;

pub use description::{Causality, Description, Kind, Variable};
pub use error::Error;
pub(crate) use exports::exports;
pub(crate) use fmi3_exports::fmi3_exports;
pub use logger::{fixed_argument_logger, FixedArgumentLogger, Logger};
pub use model::Model;
pub use package::Package;
pub use resources::resolve as resolve_resource;

#[cfg(test)]
mod tests;
