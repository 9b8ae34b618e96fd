use nalgebra::{SMatrix, SVector};

/// Everything one RK4 stage, one impact or one sliding solve needs, evaluated at `(t, q, q̇)`.
///
/// Conventions (A&K eqs 1, 2, 16, 18): `ḣ = J q̇ + ∂h/∂t` and `ḧ = J q̈ + d`, with `J = ∂h/∂q`.
/// With `h` a distance in metres and `M q̈ = f + Jᵀ λ`, the multiplier `λ` is the normal contact force.
#[derive(Clone, Debug, PartialEq)]
pub struct Evaluation<const N: usize, const M: usize> {
    /// `M(q,t)`: symmetric, positive definite inertia matrix.
    pub mass: SMatrix<f64, N, N>,
    /// `f(q,q̇,t)`: gyroscopic, damping, potential and exciting forces.
    pub force: SVector<f64, N>,
    /// `h(q,t)`: normal distance to each obstacle, ≥ 0 where admissible.
    pub gap: SVector<f64, M>,
    /// `J = ∂h/∂q`.
    pub gap_jacobian: SMatrix<f64, M, N>,
    /// `∂h/∂t`: non-zero for rheonomic (moving) constraints.
    pub gap_time_rate: SVector<f64, M>,
    /// `d = q̇ᵀ ∂²h/∂q² q̇ + 2 ∂²h/∂t∂q q̇ + ∂²h/∂t²` (eq 18).
    pub gap_bias: SVector<f64, M>,
}

/// An `N`-degree-of-freedom Lagrangian system with `M` unilateral frictionless constraints.
///
/// Inputs a host holds constant over a communication step live in the implementing type; the
/// stepper re-examines the contact state when they change (see `Stepper::system_mut`).
pub trait System<const N: usize, const M: usize> {
    /// Full evaluation at `(t, q, q̇)`; computes each trigonometric function once.
    fn evaluate(&self, t: f64, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> Evaluation<N, M>;

    /// `M` and `f` alone: all an RK4 stage needs while no constraint is held. A system whose
    /// constraint terms cost work of their own overrides it; the result must equal `evaluate`'s.
    fn inertia_and_force(&self, t: f64, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> (SMatrix<f64, N, N>, SVector<f64, N>) {
        let ev = self.evaluate(t, q, qd);
        (ev.mass, ev.force)
    }

    /// Lengths `L_k` (m per unit of coordinate `k`) that turn an error of coordinate `k` into a
    /// displacement of the mechanism. With constraints held, the adaptive step bounds `|L_k δq_k|`
    /// on the motion left along them, which the gaps do not see (a crank turning while the piston
    /// slides flat on the liner). Zero, the default: not measured.
    fn coordinate_lengths(&self) -> SVector<f64, N> {
        SVector::zeros()
    }

    /// Newton restitution coefficient `e_i ∈ [0, 1]` of constraint `i`.
    fn restitution(&self, constraint: usize) -> f64;
}
