//! Engine models on the core, one folder per concept: the crank train of Awrejcewicz & Kudra
//! (variant 1), Farahanchi's roller slider crank (variant 2), the gas pressure sources they share, the
//! partner FMU's engine cycle, and the numerics they have in common; the interface an FMU drives a
//! mechanism through.

pub mod crank_train;
pub mod engine_cycle;
mod engine_model;
mod error;
pub mod gas;
pub mod numerics;
pub mod roller;
pub mod skirt;

pub use crank_train::{CrankTrain, EfficiencyCalibration, EfficiencyTarget};
pub use engine_cycle::{CycleDesign, EngineCycle};
pub use engine_model::{EngineEvent, EngineEventKind, EngineModel, StepInputs, CYCLE};
pub use error::{check, check_integer, check_real, ModelError};
pub use numerics::{EnergyBalance, InputPolynomial, PowerFlows};
pub use roller::{Forcing, Jet, Roller, RollerDesign, RollerMechanism, RollerSystem, SlidingRegion};
