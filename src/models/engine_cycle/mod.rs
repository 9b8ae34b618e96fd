//! The partner engine model: a single-zone four-stroke cycle (Heywood, *Internal Combustion Engine
//! Fundamentals*, 1988, ch. 2, 4, 9 and 12) with temperature-dependent gas properties and wall heat transfer,
//! giving the crank speed and the gas pressure a piston model is driven by. No FFI, no FMI words.

mod closed_cycle;
mod cycle;
mod design;
mod heat_transfer;
mod thermo;

pub use closed_cycle::{wiebe, ClosedCycle, ClosedState, PEAK_PRESSURE_LIMIT, PEAK_TEMPERATURE_LIMIT};
pub use cycle::EngineCycle;
pub use design::{CycleDesign, Volume};
pub use heat_transfer::Correlation;
pub use thermo::{stoichiometric_fuel_air, Charge, Mixture};
