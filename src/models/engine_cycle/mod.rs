//! The partner engine model: a single-zone four-stroke cycle (Heywood, *Internal Combustion Engine
//! Fundamentals*, 1988, ch. 2, 4, 9 and 12) with temperature-dependent gas properties and wall heat transfer,
//! driving PistonSlap with crank speed and gas pressure. No FFI, no FMI words.

mod closed_cycle;
mod contract;
mod cycle;
mod heat_transfer;
mod parameters;
#[cfg(test)]
mod tests;
mod thermo;

pub use closed_cycle::{wiebe, ClosedCycle, ClosedState, PEAK_PRESSURE_LIMIT, PEAK_TEMPERATURE_LIMIT};
pub use contract::{EngineCycleInputs, EngineCycleOutputs, EngineCycleParameters};
pub use cycle::EngineCycle;
pub use heat_transfer::Correlation;
pub use parameters::Volume;
pub use thermo::{stoichiometric_fuel_air, Charge, Mixture};
