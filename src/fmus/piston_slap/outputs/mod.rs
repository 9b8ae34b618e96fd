//! The outputs each mechanism writes into PistonSlap's contract (everything but the impact
//! statistics, which the façade takes from the event record).

pub(super) mod crank_train;
pub(super) mod roller;
mod skirt;
