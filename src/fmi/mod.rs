//! The FMI 2.0 Co-Simulation interface: the only `unsafe` code of the crate.
//!
//! - `exports`: the `#[no_mangle]` fmi2* symbols, one line each;
//! - `abi`: their bodies, generic over the engine model: pointers in, `catch_unwind`, logging out;
//! - `reentry`: refuses a call into an instance from inside its own call (its logger calling back);
//! - `sibling`: the FMU's second build, for x86-64-v3 CPUs, chosen at run time;
//! - `instance`: the state machine and every check, in safe code;
//! - `description`: the variable table generated from `modelDescription/`;
//! - `state_bytes` and `codec`: the serialized FMU state.

mod abi;
mod codec;
pub mod description;
pub mod exports;
mod instance;
mod logger;
mod reentry;
pub mod sibling;
mod state_bytes;
pub mod types;

#[cfg(test)]
mod tests;
