//! Variant 2: Farahanchi's linearized roller slider crank — its forcing in the thesis's
//! dimensionless variables, the model the FMU drives, and its energy books.

mod energy;
mod forcing;
// The file holds `Roller`, the type the folder is named after.
#[allow(clippy::module_inception)]
mod roller;

pub use forcing::{Forcing, Jet, RollerMechanism, SlidingRegion};
pub use roller::{
    Roller, RollerDesign, RollerSystem, LOWER, SLIDING_THRESHOLD_PER_CLEARANCE, THESIS_SLIDING_THRESHOLD, THESIS_STEP, UPPER,
};
