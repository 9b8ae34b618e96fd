//! Numerics the models share: cheap sines of small angles, the last value of a costly function,
//! inputs as polynomials over a step, and the energy books' terms.

mod energy_balance;
mod input_polynomial;
mod last_value;
pub(crate) mod trig;

pub use energy_balance::{EnergyBalance, PowerFlows};
pub use input_polynomial::InputPolynomial;
pub(crate) use last_value::LastValue;

/// `x.floor() as i64`, exactly (saturating, NaN to 0), without the call `floor` is on baseline
/// x86-64, which has no rounding instruction: the conversion truncates toward zero, one less where
/// that went up. The cycle counts of every communication point take it.
pub fn floor_to_i64(x: f64) -> i64 {
    let whole = x as i64;
    if whole as f64 > x {
        whole.saturating_sub(1)
    } else {
        whole
    }
}

#[cfg(test)]
mod tests {
    use super::floor_to_i64;

    #[test]
    fn floor_to_i64_is_floor_as_i64() {
        let special = [0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 1.0 - f64::EPSILON, -1.0 + f64::EPSILON, 4.5e15, -4.5e15, 2f64.powi(52) + 1.0];
        let edges =
            [2f64.powi(53), 2f64.powi(63), -2f64.powi(63), 1e300, -1e300, f64::INFINITY, f64::NEG_INFINITY, f64::NAN, f64::MIN_POSITIVE];
        let mut xs: Vec<f64> = special.iter().chain(&edges).flat_map(|&x| [x, x.next_up(), x.next_down()]).collect();
        let mut x = 1e-3_f64;
        while x < 1e20 {
            xs.extend([x, -x, x.next_up(), -x.next_down()]);
            x *= 1.0007;
        }
        for x in xs {
            assert_eq!(floor_to_i64(x), x.floor() as i64, "{x:e}");
        }
    }
}
