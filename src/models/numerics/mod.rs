//! Numerics the models share: cheap sines of small angles, the last value of a costly function,
//! inputs as polynomials over a step, and the energy books' terms.

mod energy_balance;
mod input_polynomial;
mod last_value;
pub(crate) mod trig;

pub use energy_balance::{EnergyBalance, PowerFlows};
pub use input_polynomial::InputPolynomial;
pub(crate) use last_value::LastValue;
