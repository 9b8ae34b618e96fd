//! `M⁻¹` applied to forces and constraint gradients: every RK4 stage, impact and sliding solve
//! needs it once per evaluation, so its cost is a large share of a step's.

use nalgebra::{Cholesky, Const, SMatrix};

/// A factored inertia matrix `M` (symmetric, positive definite).
///
/// For two and three degrees of freedom `M⁻¹` is formed by cofactors: one division, against the
/// Cholesky factor's chain of square roots and divisions that each solve repeats. Other sizes keep
/// the Cholesky factor, which for one degree of freedom is exact to the bit of a single division.
pub(crate) enum Inertia<const N: usize> {
    Inverse(SMatrix<f64, N, N>),
    Factor(Cholesky<f64, Const<N>>),
}

impl<const N: usize> Inertia<N> {
    /// `None` unless `M` is positive definite (every leading minor positive; NaN fails too).
    pub fn new(m: &SMatrix<f64, N, N>) -> Option<Self> {
        let m = |i: usize, j: usize| m[(i, j)];
        let inverse = match N {
            2 => {
                let det = m(0, 0) * m(1, 1) - m(0, 1) * m(0, 1);
                (m(0, 0) > 0.0 && det > 0.0).then(|| {
                    let r = 1.0 / det;
                    SMatrix::from_fn(|i, j| r * [[m(1, 1), -m(0, 1)], [-m(0, 1), m(0, 0)]][i][j])
                })
            }
            3 => {
                let minor = m(0, 0) * m(1, 1) - m(0, 1) * m(0, 1);
                let cofactors = [
                    [m(1, 1) * m(2, 2) - m(1, 2) * m(1, 2), m(0, 2) * m(1, 2) - m(0, 1) * m(2, 2), m(0, 1) * m(1, 2) - m(0, 2) * m(1, 1)],
                    [0.0, m(0, 0) * m(2, 2) - m(0, 2) * m(0, 2), m(0, 1) * m(0, 2) - m(0, 0) * m(1, 2)],
                    [0.0, 0.0, minor],
                ];
                let det = m(0, 0) * cofactors[0][0] + m(0, 1) * cofactors[0][1] + m(0, 2) * cofactors[0][2];
                (m(0, 0) > 0.0 && minor > 0.0 && det > 0.0).then(|| {
                    let r = 1.0 / det;
                    SMatrix::from_fn(|i, j| r * cofactors[i.min(j)][i.max(j)])
                })
            }
            _ => return Cholesky::new(SMatrix::from_fn(m)).map(Self::Factor),
        };
        inverse.map(Self::Inverse)
    }

    /// `M⁻¹ b`, column by column.
    pub fn solve<const C: usize>(&self, b: &SMatrix<f64, N, C>) -> SMatrix<f64, N, C> {
        match self {
            Self::Inverse(inverse) => inverse * b,
            Self::Factor(chol) => chol.solve(b),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_random::{positive_definite, uniform};
    use super::*;
    use nalgebra::{Matrix1, Matrix2, Matrix3, SVector};

    fn inverse_error<const N: usize>(m: SMatrix<f64, N, N>) -> f64 {
        let inertia = Inertia::new(&m).expect("positive definite");
        (m * inertia.solve(&SMatrix::<f64, N, N>::identity()) - SMatrix::<f64, N, N>::identity()).amax()
    }

    /// Random well-conditioned inertia matrices, and one whose masses differ by three decades, are
    /// inverted to round-off.
    #[test]
    fn inverts_positive_definite_matrices() {
        let mut random = uniform(7);
        for _ in 0..100 {
            assert!(inverse_error(positive_definite::<3>(&mut random)) < 1e-14);
            assert!(inverse_error(positive_definite::<2>(&mut random)) < 1e-14);
        }
        // Two bodies whose inertias differ by three decades.
        assert!(inverse_error(Matrix2::new(0.0291, 0.0006, 0.0006, 0.00104)) < 1e-14);
    }

    /// Indefinite, singular and NaN matrices are refused like the Cholesky factor refuses them.
    #[test]
    fn refuses_what_is_not_positive_definite() {
        assert!(Inertia::new(&Matrix2::new(1.0, 2.0, 2.0, 1.0)).is_none());
        assert!(Inertia::new(&Matrix2::new(-1.0, 0.0, 0.0, -1.0)).is_none());
        assert!(Inertia::new(&Matrix3::new(1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, -1.0)).is_none(), "det > 0 but not definite");
        assert!(Inertia::new(&Matrix3::new(1.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0)).is_none());
        assert!(Inertia::new(&Matrix2::new(f64::NAN, 0.0, 0.0, 1.0)).is_none());
        assert!(Inertia::new(&Matrix1::new(0.0)).is_none());
    }

    /// One degree of freedom keeps the Cholesky factor's arithmetic, bit for bit.
    #[test]
    fn one_degree_of_freedom_is_the_cholesky_solve() {
        for (m, f) in [(3.0, 1.0), (0.7, -2.3), (1.3e-3, 4.1e5)] {
            let b = SVector::<f64, 1>::new(f);
            let chol = Cholesky::new(Matrix1::new(m)).unwrap();
            assert_eq!(Inertia::new(&Matrix1::new(m)).unwrap().solve(&b), chol.solve(&b));
        }
    }
}
