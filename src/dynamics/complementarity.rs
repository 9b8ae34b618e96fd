//! Constraint sets and the held set, and the complementarity solvers in the metric of the inertia
//! matrix: the Delassus matrix `W = J M⁻¹ Jᵀ`, the multipliers of persistent contact (A&K eqs
//! 15–20 for several constraints) and the small linear complementarity problems that both the
//! impact law and the sliding law reduce to (`contact_laws.rs`; with friction, `coulomb.rs`).

use super::inertia::Inertia;
use super::Evaluation;
use nalgebra::{Cholesky, SMatrix, SVector};
use serde::{Deserialize, Serialize};

/// A set of constraints as a bitmask: bit `i` is constraint `i` (serde-friendly, no heap).
pub(crate) type Set = u32;

pub(crate) fn bit(i: usize) -> Set {
    1 << i
}

pub(crate) fn contains(set: Set, i: usize) -> bool {
    set & bit(i) != 0
}

/// Indices in `set`, ascending.
pub(crate) fn members<const M: usize>(set: Set) -> impl Iterator<Item = usize> {
    (0..M).filter(move |&i| contains(set, i))
}

/// The set of indices `i < M` for which `pred(i)` holds.
pub(crate) fn select<const M: usize>(pred: impl Fn(usize) -> bool) -> Set {
    (0..M).filter(|&i| pred(i)).fold(0, |s, i| s | bit(i))
}

/// The held constraints and how each carries tangential force: `stick` at tangential rest, the
/// others slipping forward (`γ > 0`) or, in `back`, backward. Without friction only `held` is used.
/// `projected`: the held motion keeps a system's implicit inertia out of the held normals
/// (`implicit/`), where through it the contact problem had no solution.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub(crate) struct Contacts {
    pub held: Set,
    pub stick: Set,
    pub back: Set,
    pub projected: bool,
}

impl Contacts {
    pub fn frictionless(held: Set) -> Self {
        Self { held, stick: 0, back: 0, projected: false }
    }

    pub fn mode(&self, i: usize) -> Mode {
        if !contains(self.held, i) {
            Mode::Open
        } else if contains(self.stick, i) {
            Mode::Stick
        } else {
            Mode::Slip(if contains(self.back, i) { -1.0 } else { 1.0 })
        }
    }

    pub fn of<const M: usize>(modes: &[Mode; M]) -> Self {
        let set = |pred: fn(&Mode) -> bool| (0..M).filter(|&i| pred(&modes[i])).fold(0, |s, i| s | 1 << i);
        Self { held: set(|m| *m != Mode::Open), stick: set(|m| *m == Mode::Stick), back: set(|m| *m == Mode::Slip(-1.0)), projected: false }
    }
}

/// The state of one constraint in a contact problem.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Mode {
    Open,
    Stick,
    /// Slipping in the direction of the sign: `λ_T = −μ s λ_N`.
    Slip(f64),
}

/// A pivot of the Cholesky factor this small relative to its diagonal entry means the constraints
/// of the set are linearly dependent (e.g. more closed constraints than degrees of freedom).
pub(crate) const DEPENDENT_PIVOT: f64 = 1e-10;

/// Relative tolerance of the complementarity checks (against round-off, not physics).
pub(crate) const COMPLEMENTARITY_TOL: f64 = 1e-9;

/// The constraint geometry at one state.
pub(crate) struct Frame<const N: usize, const M: usize> {
    /// `M⁻¹ Jᵀ`: column `i` is the velocity change per unit impulse on constraint `i`.
    pub minv_jt: SMatrix<f64, N, M>,
    /// `W = J M⁻¹ Jᵀ`: the change of `ḣ` per unit impulse (symmetric, positive semi-definite).
    pub w: SMatrix<f64, M, M>,
    /// `M⁻¹ f`: the acceleration without contact forces.
    pub free_acc: SVector<f64, N>,
}

impl<const N: usize, const M: usize> Frame<N, M> {
    /// `None` when the inertia matrix is not positive definite.
    pub fn new(ev: &Evaluation<N, M>) -> Option<Self> {
        let inertia = Inertia::new(&ev.inertia())?;
        let minv_jt = inertia.solve(&ev.gap_jacobian.transpose());
        Some(Self { w: ev.gap_jacobian * minv_jt, minv_jt, free_acc: inertia.solve(&ev.force) })
    }

    /// `ḧ = J q̈ + d` for the acceleration `acc`.
    pub fn gap_acceleration(ev: &Evaluation<N, M>, acc: &SVector<f64, N>) -> SVector<f64, M> {
        ev.gap_jacobian * acc + ev.gap_bias
    }

    /// The M-metric projection that zeroes `r` on `set`: `δ = −M⁻¹ J_Sᵀ W_SS⁻¹ r_S` (applied to
    /// `q` with `r = h` it is a Newton step onto the constraint manifold, to `q̇` with `r = ḣ`
    /// an inelastic impulse). Also returns the impulse `W_SS⁻¹ r_S` (with its sign flipped).
    pub fn projection(&self, r: &SVector<f64, M>, set: Set) -> Option<(SVector<f64, N>, SVector<f64, M>)> {
        let impulse = -solve_on(&self.w, r, set)?;
        Some((self.minv_jt * impulse, impulse))
    }

    /// The sliding law over `candidates`: `λ ≥ 0`, `ḧ = W λ + ḧ_free ≥ 0`, `λᵢ ḧᵢ = 0`.
    /// The complementarity tolerance scales with the terms of `ḧ_free = J M⁻¹ f + d`, which
    /// cancel where a contact is about to open. `force_tolerance` (ε_λ, N) is the force below
    /// which a contact counts as unloaded whatever the scale.
    pub fn sliding(&self, ev: &Evaluation<N, M>, candidates: Set, force_tolerance: f64) -> Option<Sliding<M>> {
        let drive = ev.gap_jacobian * self.free_acc;
        let scale = members::<M>(candidates).fold(0.0_f64, |s, i| s.max(drive[i].abs() + ev.gap_bias[i].abs()));
        let b = drive + ev.gap_bias;
        let (lambda, support) = solve_lcp(&self.w, &b, candidates, scale)?;
        let gap_acc = self.w * lambda + b;
        let ties = ties(&self.w, (&lambda, &gap_acc), (candidates, support), scale, force_tolerance);
        Some(Sliding { lambda, support, ties })
    }
}

/// The candidates of a sliding-law solution `(λ, ḧ)` with closed set `support` that lie within
/// the tie margin: in the support with a force, or outside it with a gap acceleration, near zero.
pub(crate) fn ties<const M: usize>(
    w: &SMatrix<f64, M, M>,
    (lambda, gap_acc): (&SVector<f64, M>, &SVector<f64, M>),
    (candidates, support): (Set, Set),
    scale: f64,
    force_tolerance: f64,
) -> Set {
    let (tie_force, w_max) = tie_margin(w, candidates, scale, force_tolerance);
    candidates & select::<M>(|i| if contains(support, i) { lambda[i] <= tie_force } else { gap_acc[i] <= tie_force * w_max })
}

/// The tie margin on a force over `candidates`, N, and the largest `Wᵢᵢ` among them.
pub(crate) fn tie_margin<const M: usize>(w: &SMatrix<f64, M, M>, candidates: Set, scale: f64, force_tolerance: f64) -> (f64, f64) {
    let w_max = members::<M>(candidates).fold(0.0_f64, |s, i| s.max(w[(i, i)]));
    ((TIE_FRACTION * scale / w_max).max(TIE_FORCE_FACTOR * force_tolerance), w_max)
}

/// Margin of an undecided contact, relative to the scale of the sliding law's terms: a contact
/// whose force and gap acceleration both lie within it at an instant (a contact about to open,
/// or two trading places as a body starts to pivot) is decided by the law a moment later.
const TIE_FRACTION: f64 = 1e-6;

/// The same margin on the force, in units of ε_λ: a release is located to within ε_λ of zero force.
const TIE_FORCE_FACTOR: f64 = 10.0;

/// A solution of the sliding law.
pub(crate) struct Sliding<const M: usize> {
    /// λ ≥ 0, zero outside the support.
    pub lambda: SVector<f64, M>,
    /// The constraints that stay closed.
    pub support: Set,
    /// The candidates whose state this instant does not decide: in the support with a force, or
    /// outside it with a gap acceleration, within the tie margin of zero.
    pub ties: Set,
}

/// Acceleration and multipliers with the set `active` held closed (eqs 15–20): `ḧ_A = 0` gives
/// `W_AA λ_A = −(J_A M⁻¹ f + d_A)`, then `q̈ = M⁻¹ (f + J_Aᵀ λ_A)`; `inertia` is `M` factored and
/// `free_acc = M⁻¹ f`. This is most of the integrator's work while a body slides: with one or
/// two constraints held only their rows of `W` are formed and solved in closed form, in the
/// operations (and so to the bit) of the general path, which the frame takes for more. `None`
/// when the active constraints are dependent.
pub(crate) fn held_acceleration<const N: usize, const M: usize>(
    ev: &Evaluation<N, M>,
    inertia: &Inertia<N>,
    free_acc: SVector<f64, N>,
    active: Set,
) -> Option<(SVector<f64, N>, SVector<f64, M>)> {
    let mut held = members::<M>(active);
    let (Some(a), second, None) = (held.next(), held.next(), held.next()) else {
        let minv_jt = inertia.solve(&ev.gap_jacobian.transpose());
        let lambda = solve_on(&(ev.gap_jacobian * minv_jt), &-Frame::gap_acceleration(ev, &free_acc), active)?;
        return Some((free_acc + minv_jt * lambda, lambda));
    };
    let column = |i: usize| inertia.solve(&ev.gap_jacobian.row(i).transpose());
    let dot = |i: usize, x: &SVector<f64, N>| (1..N).fold(ev.gap_jacobian[(i, 0)] * x[0], |sum, k| sum + ev.gap_jacobian[(i, k)] * x[k]);
    let rhs = |i: usize| -(dot(i, &free_acc) + ev.gap_bias[i]);
    let dependent = |pivot: f64, diagonal: f64| pivot <= DEPENDENT_PIVOT * diagonal;
    let mut lambda = SVector::<f64, M>::zeros();
    let c_a = column(a);
    let w_aa = dot(a, &c_a);
    // (A NaN goes on, to be refused as non-finite by the caller.)
    if w_aa <= 0.0 {
        return None;
    }
    let l_aa = w_aa.sqrt();
    let Some(b) = second else {
        lambda[a] = rhs(a) / l_aa / l_aa;
        return Some((free_acc + c_a * lambda[a], lambda));
    };
    let c_b = column(b);
    let (w_ba, w_bb) = (dot(b, &c_a), dot(b, &c_b));
    let l_ba = w_ba / l_aa;
    let pivot = w_bb - l_ba * l_ba;
    if dependent(pivot, w_bb) {
        return None;
    }
    let l_bb = pivot.sqrt();
    let y_a = rhs(a) / l_aa;
    let y_b = (rhs(b) - l_ba * y_a) / l_bb;
    lambda[b] = y_b / l_bb;
    lambda[a] = (y_a - l_ba * lambda[b]) / l_aa;
    Some((free_acc + (c_a * lambda[a] + c_b * lambda[b]), lambda))
}

/// Solves `W_SS x_S = r_S` with `x = 0` outside `S`, without heap: the rows and columns outside
/// `S` are replaced by the identity. `None` when `W_SS` is singular.
pub(crate) fn solve_on<const M: usize>(w: &SMatrix<f64, M, M>, r: &SVector<f64, M>, set: Set) -> Option<SVector<f64, M>> {
    // No constraint, one or two (most calls: the impact and sliding laws, the projections onto two
    // constraints held together): the factor's operations written out, to the bit the same (the identity
    // outside `S` adds only zeros to them).
    let mut x = SVector::<f64, M>::zeros();
    let mut indices = members::<M>(set);
    match (indices.next(), indices.next(), indices.next()) {
        (None, ..) => return Some(x),
        (Some(a), None, _) => {
            let w_aa = w[(a, a)];
            if w_aa.is_nan() || w_aa <= 0.0 {
                return None;
            }
            let l = w_aa.sqrt();
            x[a] = r[a] / l / l;
            return Some(x);
        }
        (Some(a), Some(b), None) => {
            let w_aa = w[(a, a)];
            if w_aa.is_nan() || w_aa <= 0.0 {
                return None;
            }
            let l_aa = w_aa.sqrt();
            // The factor reads the lower triangle: W's round-off need not be symmetric.
            let l_ba = w[(b, a)] / l_aa;
            let pivot = w[(b, b)] - l_ba * l_ba;
            if pivot.is_nan() || pivot <= 0.0 {
                return None;
            }
            let l_bb = pivot.sqrt();
            if l_aa * l_aa <= DEPENDENT_PIVOT * w_aa || l_bb * l_bb <= DEPENDENT_PIVOT * w[(b, b)] {
                return None;
            }
            let y_a = r[a] / l_aa;
            let y_b = (r[b] - l_ba * y_a) / l_bb;
            x[b] = y_b / l_bb;
            x[a] = (y_a - l_ba * x[b]) / l_aa;
            return Some(x);
        }
        _ => {}
    }
    let mut a = SMatrix::<f64, M, M>::identity();
    let mut rhs = SVector::<f64, M>::zeros();
    for i in members::<M>(set) {
        rhs[i] = r[i];
        for j in members::<M>(set) {
            a[(i, j)] = w[(i, j)];
        }
    }
    let chol = Cholesky::new(a)?;
    let l = chol.l_dirty();
    if members::<M>(set).any(|i| l[(i, i)] * l[(i, i)] <= DEPENDENT_PIVOT * w[(i, i)]) {
        return None;
    }
    Some(chol.solve(&rhs))
}

/// The linear complementarity problem `x ≥ 0`, `y = W x + b ≥ 0`, `xᵢ yᵢ = 0` over `set`
/// (`x = 0` outside it), by enumerating the supports `S ⊆ set` from the smallest. For `W`
/// positive definite on `set` the solution is unique; supports with dependent constraints are
/// skipped. `M ≤ 4` in our models, so this is at most 16 tiny solves. Returns `x` and its support.
/// `scale` is the magnitude of `b` before cancellation: the checks tolerate round-off of it.
pub(crate) fn solve_lcp<const M: usize>(
    w: &SMatrix<f64, M, M>,
    b: &SVector<f64, M>,
    set: Set,
    scale: f64,
) -> Option<(SVector<f64, M>, Set)> {
    let w_max = members::<M>(set).fold(0.0_f64, |s, i| s.max(w[(i, i)]));
    let tol_y = COMPLEMENTARITY_TOL * scale + f64::MIN_POSITIVE;
    let tol_x = if w_max > 0.0 { tol_y / w_max } else { tol_y };
    for size in 0..=set.count_ones() {
        let mut support = set;
        loop {
            if support.count_ones() == size {
                if let Some(x) = solve_on(w, &-b, support) {
                    let y = w * x + b;
                    let pushes = members::<M>(support).all(|i| x[i] >= -tol_x);
                    let admissible = members::<M>(set & !support).all(|i| y[i] >= -tol_y);
                    if pushes && admissible {
                        return Some((x.map(|v| v.max(0.0)), support));
                    }
                }
            }
            if support == 0 {
                break;
            }
            support = (support - 1) & set;
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::super::test_random::{positive_definite, uniform};
    use super::*;
    use nalgebra::{Matrix2, Vector2};

    /// `solve_on` over two constraints gives the factor of `W_SS` padded with the identity to the bit,
    /// and refuses where it does (a dependent pair, a pair whose factor is not positive).
    #[test]
    fn two_constraints_solve_as_the_padded_factor_does() {
        let mut random = uniform(2024);
        let padded = |w: &SMatrix<f64, 4, 4>, r: &SVector<f64, 4>, set: Set| {
            let (mut a, mut rhs) = (SMatrix::<f64, 4, 4>::identity(), SVector::<f64, 4>::zeros());
            for i in members::<4>(set) {
                rhs[i] = r[i];
                for k in members::<4>(set) {
                    a[(i, k)] = w[(i, k)];
                }
            }
            let chol = Cholesky::new(a)?;
            let l = chol.l_dirty();
            (!members::<4>(set).any(|i| l[(i, i)] * l[(i, i)] <= DEPENDENT_PIVOT * w[(i, i)])).then(|| chol.solve(&rhs))
        };
        let bits = |x: Option<SVector<f64, 4>>| x.map(|x| x.map(f64::to_bits));
        for round in 0..300 {
            // J M⁻¹ Jᵀ as the frames form it (its round-off not symmetric); every third a repeated row.
            let mut j = SMatrix::<f64, 4, 3>::from_fn(|_, _| random());
            if round % 3 == 0 {
                j.set_row(2, &j.row(1).into_owned());
            }
            let w = j * positive_definite::<3>(&mut random) * j.transpose();
            let r = SVector::<f64, 4>::from_fn(|_, _| random());
            for set in (1..16_u32).filter(|s| s.count_ones() == 2) {
                assert_eq!(bits(solve_on(&w, &r, set)), bits(padded(&w, &r, set)), "set {set:b}");
            }
            let negative = -w;
            assert_eq!(solve_on(&negative, &r, 0b11), None);
        }
    }

    /// The closed-form solve for one or two held constraints gives the general path's result to
    /// the bit (so taking it changed no trajectory), and refuses dependent sets like it.
    #[test]
    fn held_acceleration_is_the_general_solve() {
        let mut random = uniform(12345);
        for _ in 0..200 {
            let ev = Evaluation::<3, 4> {
                mass: positive_definite(&mut random),
                implicit: None,
                force: SVector::from_fn(|_, _| random()),
                gap: SVector::zeros(),
                gap_jacobian: SMatrix::from_fn(|_, _| random()),
                gap_time_rate: SVector::zeros(),
                gap_bias: SVector::from_fn(|_, _| random()),
            };
            let frame = Frame::new(&ev).unwrap();
            let inertia = Inertia::new(&ev.mass).unwrap();
            for active in 1..16_u32 {
                let lambda = solve_on(&frame.w, &-Frame::gap_acceleration(&ev, &frame.free_acc), active);
                let general = lambda.map(|lambda| (frame.free_acc + frame.minv_jt * lambda, lambda));
                assert!(general.is_some() || active.count_ones() > 3, "set {active:b}: three random rows in 3D are independent");
                assert_eq!(held_acceleration(&ev, &inertia, frame.free_acc, active), general, "set {active:b}");
            }
        }
        let dependent = Evaluation::<2, 2> {
            mass: Matrix2::identity(),
            implicit: None,
            force: Vector2::zeros(),
            gap: Vector2::zeros(),
            gap_jacobian: Matrix2::new(1.0, 2.0, 2.0, 4.0),
            gap_time_rate: Vector2::zeros(),
            gap_bias: Vector2::zeros(),
        };
        let inertia = Inertia::new(&dependent.mass).unwrap();
        assert_eq!(held_acceleration(&dependent, &inertia, Vector2::zeros(), 0b11), None);
    }

    /// Hand-solved 2×2 LCPs: both active, one active, none.
    #[test]
    fn lcp_small_cases() {
        let w = Matrix2::new(2.0, 1.0, 1.0, 2.0);
        // b = (−3, −3): x = (1, 1), y = 0.
        let (x, s) = solve_lcp(&w, &Vector2::new(-3.0, -3.0), 0b11, 3.0).unwrap();
        assert_eq!(s, 0b11);
        assert!((x - Vector2::new(1.0, 1.0)).norm() < 1e-14);
        // b = (−2, 0.5): x = (1, 0), y2 = 1.5 ≥ 0; the equality solve would give x2 < 0.
        let (x, s) = solve_lcp(&w, &Vector2::new(-2.0, 0.5), 0b11, 2.0).unwrap();
        assert_eq!(s, 0b01);
        assert!((x - Vector2::new(1.0, 0.0)).norm() < 1e-14);
        // b ≥ 0: nothing pushes.
        assert_eq!(solve_lcp(&w, &Vector2::new(1.0, 0.0), 0b11, 1.0).unwrap().1, 0);
        // Dependent constraints: only the subsets with one of them are tried.
        let rank1 = Matrix2::new(1.0, 1.0, 1.0, 1.0);
        let (x, s) = solve_lcp(&rank1, &Vector2::new(-1.0, -1.0), 0b11, 1.0).unwrap();
        assert_eq!(s.count_ones(), 1);
        assert!((x.sum() - 1.0).abs() < 1e-14);
    }
}
