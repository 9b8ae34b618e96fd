//! Variant 2: Farahanchi's linearized roller slider crank — its forcing in the thesis's
//! dimensionless variables, the model the FMU drives, and its energy books.

mod energy;
mod forcing;
mod model;

pub use forcing::{Forcing, Jet, RollerMechanism, SlidingRegion};
pub use model::{Roller, RollerSystem, LOWER, SLIDING_THRESHOLD_PER_CLEARANCE, THESIS_SLIDING_THRESHOLD, THESIS_STEP, UPPER};
