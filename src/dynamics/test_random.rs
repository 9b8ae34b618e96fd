//! Reproducible random inputs for the core's unit tests, without a dependency.

use nalgebra::SMatrix;

/// Uniform numbers in [−½, ½) from a 64-bit linear congruential generator (Knuth's MMIX constants).
pub(crate) fn uniform(mut seed: u64) -> impl FnMut() -> f64 {
    move || {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    }
}

/// A symmetric positive definite `L Lᵀ`, `L` lower triangular with its diagonal in [1, 1.5).
pub(crate) fn positive_definite<const N: usize>(random: &mut impl FnMut() -> f64) -> SMatrix<f64, N, N> {
    let l = SMatrix::<f64, N, N>::from_fn(|i, j| {
        if i == j {
            1.0 + random().abs()
        } else if i > j {
            random()
        } else {
            0.0
        }
    });
    l * l.transpose()
}
