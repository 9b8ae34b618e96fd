//! Variant 1: crank, connecting rod and piston of Awrejcewicz & Kudra, the piston's four corners
//! against the liner: the linkage's equations, the two crank modes as systems for the core, the
//! model the FMU drives, its energy books, its declared design space and the efficiency calibration.

pub mod books;
// The file holds `CrankTrain`, the type the folder is named after.
#[allow(clippy::module_inception)]
mod crank_train;
mod drive;
pub mod efficiency;
mod energy;
pub mod engine;
pub mod kinematics;
pub mod linkage;
pub mod lubrication;
mod skirt_fields;
mod step_bounds;
mod step_film;

pub use crank_train::{CrankTrain, CrankTrainDesign, StartOffset};
pub use efficiency::{EfficiencyCalibration, EfficiencyTarget};
pub use step_bounds::{LOCAL_ERROR, MAX_STEP, MAX_STEP_ANGLE};
