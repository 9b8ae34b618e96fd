//! Variant 1: crank, connecting rod and piston of Awrejcewicz & Kudra, the piston's four corners
//! against the liner: the linkage's equations, the two crank modes as systems for the core, the
//! model the FMU drives, its energy books, its declared design space and the efficiency calibration.

pub mod books;
mod crank_stepper;
mod design_space;
pub mod drive;
pub mod efficiency;
mod energy;
pub mod kinematics;
pub mod linkage;
pub mod lubrication;
mod model;
mod skirt_outputs;
mod step_film;

pub use efficiency::{EfficiencyCalibration, EfficiencyTarget};
pub use model::{CrankTrain, LOCAL_ERROR, MAX_STEP, MAX_STEP_ANGLE};
