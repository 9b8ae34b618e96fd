//! PistonSlap: piston secondary motion (piston slap) as an FMI 2.0 Co-Simulation FMU.
//!
//! Layers, each knowing only the one below it:
//! - [`dynamics`]: the nonsmooth core (RK4, events, impacts, sliding), generic over [`dynamics::System`];
//! - [`models`]: the crank train of Awrejcewicz & Kudra and Farahanchi's roller slider crank;
//! - [`fmus`]: each FMU in its own room (PistonSlap's run façade over the models, EngineCycle), and their registry;
//! - [`fmi`]: the exported `fmi2*` functions over the registry, naming no FMU; the only `unsafe` code.

#![deny(unsafe_code)]
#![warn(missing_docs)]
#![warn(clippy::undocumented_unsafe_blocks)]

pub mod dynamics;
pub mod fmi;
pub mod fmus;
pub mod models;
