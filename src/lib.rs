//! PistonSlap: piston secondary motion (piston slap) as an FMI 2.0 Co-Simulation FMU.
//!
//! Layers, each knowing only the one below it:
//! - [`dynamics`]: the nonsmooth core (RK4, events, impacts, sliding), generic over [`dynamics::System`];
//! - [`models`]: the crank train of Awrejcewicz & Kudra and Farahanchi's roller slider crank;
//! - `fmi`: the exported `fmi2*` functions, the only `unsafe` code.

#![deny(unsafe_code)]
#![warn(clippy::undocumented_unsafe_blocks)]

pub mod dynamics;
pub mod fmi;
pub mod models;
pub mod simulation;
