//! Gas pressure on the piston crown: the built-in four-stroke curve, measured traces, and the
//! choice between them and the host's input.

mod curve;
mod source;
mod trace;

pub use curve::FourStrokePressure;
pub use source::GasPressure;
pub use trace::PressureTrace;
