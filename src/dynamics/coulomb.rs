//! Coulomb friction at the constraints: planar contact, one tangent per constraint, along which
//! the slip velocity is `γ = J_T q̇ + ∂γ/∂t` and `γ̇ = J_T q̈ + d_T` ([`Tangents`]), and the
//! tangential force `λ_T` enters as `J_Tᵀ λ_T` beside the normal `J_Nᵀ λ_N`.
//!
//! The force laws (Pfeiffer & Glocker, *Multibody Dynamics with Unilateral Contacts*, 1996, ch. 5;
//! Glocker, *Set-Valued Force Laws*, 2001):
//! - **persistent contact**: `λ_N ≥ 0 ⊥ ḧ ≥ 0` as without friction; a constraint slipping
//!   (`γ ≠ 0`) carries `λ_T = −μ λ_N sign γ`; one at tangential rest (`γ = 0`) either sticks
//!   (`γ̇ = 0`, `|λ_T| ≤ μ λ_N`) or starts to slip (`λ_T = −μ λ_N sign γ̇`): the planar friction
//!   complementarity conditions, solved by enumerating the modes ([`Mode`]) of the constraints;
//! - **impacts**: Glocker's Newton–Coulomb law with the velocities `ξ_N = γ_N⁺ + ε γ_N⁻`,
//!   `ξ_T = γ_T⁺ + ε γ_T⁻` (the same ε, the system's restitution, in both directions and at
//!   every contact of the impact):
//!   `Λ_N ≥ 0 ⊥ ξ_N ≥ 0` and `−Λ_T ∈ μ Λ_N Sign ξ_T`. With `γ⁺ = γ⁻ + W Λ` (W over both
//!   directions, positive semi-definite) the kinetic energy changes by
//!   `ΔT = Λᵀξ / (1 + ε) − (1 − ε) ΛᵀWΛ / (2 (1 + ε))`, and `Λᵀξ = −Σ μ Λ_N |ξ_T| ≤ 0`: as the
//!   contacts of an impact share one ε it cannot create energy for any
//!   μ ≥ 0 and ε ∈ [0, 1] (C. Glocker, "Energetic consistency conditions for standard impacts",
//!   Multibody System Dynamics 29 (2013)). A sticking impact reverses `γ_T` by ε like `γ_N`;
//!   Newton's law with `ε_T = 0` instead is known to gain energy (Kane's example).
//!
//! Every solve here sits at an event but one: with friction the held acceleration of each RK4
//! stage is [`Tangential::solve`] with the modes held.

use super::complementarity::{Mode, COMPLEMENTARITY_TOL, DEPENDENT_PIVOT};
use super::inertia::Inertia;
use super::wedge::{wedged, Margin};
use super::{Evaluation, Tangents};
use nalgebra::{DMatrix, DVector, SMatrix, SVector};

/// What a contact problem may choose for each constraint.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Choice {
    /// Not part of the problem.
    Open,
    /// Open, or closed slipping with the known sign of `γ` (no check on the tangential row).
    Slipping(f64),
    /// Open, or closed and sticking or slipping either way, as the tangential row decides.
    AtRest,
}

/// The contact geometry of both directions at one state, in the metric of the inertia matrix.
pub(crate) struct Tangential<const N: usize, const M: usize> {
    /// `M⁻¹ J_Nᵀ`, `M⁻¹ J_Tᵀ`.
    normal: SMatrix<f64, N, M>,
    tangent: SMatrix<f64, N, M>,
    /// `J_N M⁻¹ J_Nᵀ`, `J_N M⁻¹ J_Tᵀ`, `J_T M⁻¹ J_Nᵀ`, `J_T M⁻¹ J_Tᵀ`.
    w: [[SMatrix<f64, M, M>; 2]; 2],
    mu: SVector<f64, M>,
    /// Whether a stick with more rows than degrees of freedom is solved (`wedge.rs`): only with the
    /// whole system at rest, where a wedge can hold; moving (a linkage turning through a dead
    /// centre, where the wedged body is at rest along its surface) it would have to stop the motion at once.
    wedge: bool,
}

/// A solution of a contact problem: the forces (or impulses) and the resulting normal and
/// tangential accelerations (or velocities ξ).
#[derive(Clone, Debug)]
pub(crate) struct Solution<const M: usize> {
    pub normal: SVector<f64, M>,
    pub tangent: SVector<f64, M>,
    pub y_normal: SVector<f64, M>,
    pub y_tangent: SVector<f64, M>,
}

impl<const N: usize, const M: usize> Tangential<N, M> {
    /// The geometry at the state of `ev`, with `inertia` its `M` factored and `mu` the friction
    /// coefficients.
    pub fn new(ev: &Evaluation<N, M>, tangents: &Tangents<N, M>, inertia: &Inertia<N>, mu: SVector<f64, M>) -> Self {
        let (jn, jt) = (&ev.gap_jacobian, &tangents.jacobian);
        let (normal, tangent) = (inertia.solve(&jn.transpose()), inertia.solve(&jt.transpose()));
        Self { w: [[jn * normal, jn * tangent], [jt * normal, jt * tangent]], normal, tangent, mu, wedge: false }
    }

    /// This geometry, solving a wedged stick where `wedge`.
    pub fn wedging(self, wedge: bool) -> Self {
        Self { wedge, ..self }
    }

    /// `new` with `M` factored here, and the acceleration without contact forces `M⁻¹ f`; `None`
    /// when `M` is not positive definite.
    pub fn at(ev: &Evaluation<N, M>, tangents: &Tangents<N, M>, mu: SVector<f64, M>) -> Option<(Self, SVector<f64, N>)> {
        let inertia = Inertia::new(&ev.inertia())?;
        Some((Self::new(ev, tangents, &inertia, mu), inertia.solve(&ev.force)))
    }

    /// `q̈` (or `Δq̇`) from the forces (impulses) of a solution and the acceleration without them.
    pub fn motion(&self, free: &SVector<f64, N>, s: &Solution<M>) -> SVector<f64, N> {
        free + self.normal * s.normal + self.tangent * s.tangent
    }

    /// The forces of `modes` that zero the normal row of every closed constraint and the
    /// tangential row of every sticking one, with `b_N`, `b_T` the rows' values at zero force.
    /// Where there are more than `N` of those rows, they agree, and a stick is among them, the
    /// forces `wedge.rs` chooses; `None` for other dependent rows (a vanishing pivot).
    ///
    /// Sticking constraints whose tangents act alike (equal columns of `M⁻¹ J_Tᵀ`: one body at
    /// rest on one surface at several points) have dependent tangential rows: the motion fixes
    /// only the sum of their friction forces, which is solved for once and split in proportion to
    /// their normal forces, the split that keeps each as far inside its cone as the others.
    pub fn solve(&self, modes: &[Mode; M], b: (&SVector<f64, M>, &SVector<f64, M>)) -> Option<Solution<M>> {
        // The sticking constraint whose tangential unknown each sticking one shares (itself if none).
        let mut shares: [usize; M] = std::array::from_fn(|i| i);
        for i in 0..M {
            if modes[i] == Mode::Stick {
                let alike = |&j: &usize| {
                    let (a, c) = (self.tangent.column(i), self.tangent.column(j));
                    (a - c).amax() <= DEPENDENT_PIVOT * a.amax()
                };
                shares[i] = (0..i).filter(|&j| modes[j] == Mode::Stick && shares[j] == j).find(alike).unwrap_or(i);
            }
        }
        // Unknowns (constraint, direction: 0 normal, 1 tangential), each with its own row.
        let unknowns = move || {
            modes.iter().enumerate().flat_map(move |(i, mode)| {
                let directions: &[usize] = match mode {
                    Mode::Open => &[],
                    Mode::Slip(_) => &[0],
                    Mode::Stick if shares[i] != i => &[0],
                    Mode::Stick => &[0, 1],
                };
                directions.iter().map(move |&d| (i, d))
            })
        };
        // The response of row (i, d) to a unit of unknown (j, e): a slipping constraint's normal
        // force brings its friction −μ s along.
        let response = |(i, d): (usize, usize), (j, e): (usize, usize)| match (modes[j], e) {
            (Mode::Slip(s), 0) => self.w[d][0][(i, j)] - self.mu[j] * s * self.w[d][1][(i, j)],
            _ => self.w[d][e][(i, j)],
        };
        let rhs = |(i, d): (usize, usize)| -[b.0, b.1][d][i];
        let r = unknowns().count();
        let independent = (r <= N).then(|| {
            let mut a = SMatrix::<f64, N, N>::zeros();
            let mut y = SVector::<f64, N>::zeros();
            for (k, u) in unknowns().enumerate() {
                y[k] = rhs(u);
                for (l, v) in unknowns().enumerate() {
                    a[(k, l)] = response(u, v);
                }
            }
            gauss(a, y, r)
        });
        let (mut normal, mut tangent) = (SVector::<f64, M>::zeros(), SVector::<f64, M>::zeros());
        let mut assign = |(i, d): (usize, usize), x: f64| if d == 0 { normal[i] = x } else { tangent[i] = x };
        if let Some(x) = independent {
            let x = x?;
            unknowns().enumerate().for_each(|(k, u)| assign(u, x[k]));
        } else if self.wedge && unknowns().any(|(_, d)| d == 1) {
            // More rows than degrees of freedom with a stick among them (`wedge.rs`). Fewer rows
            // with a vanishing pivot are a singular pose (a dead centre), dependent at an instant
            // only: refused (`None`), so that the laws choose modes the motion can keep.
            let list: Vec<(usize, usize)> = unknowns().collect();
            let a = DMatrix::from_fn(r, r, |k, l| response(list[k], list[l]));
            let index = |u: (usize, usize)| list.iter().position(|&v| v == u);
            let margins: Vec<Margin> = (0..r)
                .flat_map(|k| match list[k] {
                    (_, 0) => vec![[(k, 1.0), (k, 0.0)]],
                    (i, _) => index((i, 0)).map_or(vec![], |n| vec![[(n, self.mu[i]), (k, -1.0)], [(n, self.mu[i]), (k, 1.0)]]),
                })
                .collect();
            let x = wedged(a, DVector::from_fn(r, |k, _| rhs(list[k])), &margins)?;
            list.iter().enumerate().for_each(|(k, &u)| assign(u, x[k]));
        } else {
            return None;
        }
        for (i, mode) in modes.iter().enumerate() {
            if let Mode::Slip(s) = mode {
                tangent[i] = -self.mu[i] * s * normal[i];
            }
        }
        for i in (0..M).filter(|&i| shares.iter().skip(i + 1).any(|&j| j == i)) {
            let group = || (0..M).filter(move |&j| modes[j] == Mode::Stick && shares[j] == i);
            let (total, load, count) = (tangent[i], group().map(|j| normal[j]).sum::<f64>(), group().count() as f64);
            for j in group() {
                tangent[j] = if load > 0.0 { total * normal[j] / load } else { total / count };
            }
        }
        let y = |d: usize| self.w[d][0] * normal + self.w[d][1] * tangent + [b.0, b.1][d];
        Some(Solution { y_normal: y(0), y_tangent: y(1), normal, tangent })
    }

    /// The first consistent modes for `choices`, by enumeration: fewest closed constraints
    /// first (as the frictionless law), and first among modes that decide beyond round-off (a
    /// slip from rest whose tangential acceleration has its direction, a stick strictly inside its
    /// cone): a body at rest on several points sticks rather than slips nowhere. Where none
    /// decides so, modes that hold exactly (a slip's acceleration in its direction however small,
    /// a stick within its cone): at a dead centre, where the slip reverses with a linkage's
    /// geometry and friction hardly changes its acceleration (a stick there is dependent), the
    /// slip the motion takes, not the one it leaves, which would be watched crossing at once.
    /// Only then modes at the edge, slipping before sticking (at the edge of the friction cone
    /// both are consistent, and the slip is what follows). `scale`: the magnitude of the rows'
    /// terms before cancellation, for the round-off tolerances.
    pub fn enumerate(
        &self,
        choices: &[Choice; M],
        b: (&SVector<f64, M>, &SVector<f64, M>),
        scale: f64,
    ) -> Option<([Mode; M], Solution<M>)> {
        let options = |c: Choice, mu: f64| -> &'static [Mode] {
            match c {
                Choice::Open => &[Mode::Open],
                Choice::Slipping(s) if s < 0.0 => &[Mode::Open, Mode::Slip(-1.0)],
                Choice::Slipping(_) => &[Mode::Open, Mode::Slip(1.0)],
                // Without friction the tangential row carries no force: nothing to choose.
                Choice::AtRest if mu == 0.0 => &[Mode::Open, Mode::Slip(1.0)],
                Choice::AtRest => &[Mode::Open, Mode::Slip(1.0), Mode::Slip(-1.0), Mode::Stick],
            }
        };
        let lists: [&[Mode]; M] = std::array::from_fn(|i| options(choices[i], self.mu[i]));
        let w_max = (0..M).filter(|&i| choices[i] != Choice::Open).fold(0.0_f64, |s, i| s.max(self.w[0][0][(i, i)]));
        let tol_y = COMPLEMENTARITY_TOL * scale + f64::MIN_POSITIVE;
        let tol_x = if w_max > 0.0 { tol_y / w_max } else { tol_y };
        // `edge`: the margin a stick's cone and a starting slip's acceleration may fall short by.
        let consistent = |modes: &[Mode; M], s: &Solution<M>, (edge_x, edge_y): (f64, f64)| {
            (0..M).all(|i| match modes[i] {
                Mode::Open => choices[i] == Choice::Open || s.y_normal[i] >= -tol_y,
                Mode::Stick => s.normal[i] >= -tol_x && s.tangent[i].abs() <= self.mu[i] * s.normal[i] + edge_x,
                Mode::Slip(sign) => {
                    s.normal[i] >= -tol_x && (choices[i] != Choice::AtRest || self.mu[i] == 0.0 || sign * s.y_tangent[i] >= -edge_y)
                }
            })
        };
        for edge in [(-tol_x, -tol_y), (0.0, 0.0), (tol_x, tol_y)] {
            for closed in 0..=M {
                let mut index = [0_usize; M];
                loop {
                    let modes: [Mode; M] = std::array::from_fn(|i| lists[i][index[i]]);
                    if modes.iter().filter(|m| **m != Mode::Open).count() == closed {
                        if let Some(s) = self.solve(&modes, b).filter(|s| consistent(&modes, s, edge)) {
                            return Some((modes, s));
                        }
                    }
                    // The next combination (an odometer over the lists).
                    let Some(k) = (0..M).find(|&k| index[k] + 1 < lists[k].len()) else { break };
                    index[k] += 1;
                    index[..k].iter_mut().for_each(|x| *x = 0);
                }
            }
        }
        None
    }
}

/// Solves the leading `r × r` block of `a x = rhs` by Gaussian elimination with partial pivoting
/// (the block is not symmetric: friction couples the directions one way). `None` when a pivot
/// vanishes against the block's largest entry: dependent rows.
fn gauss<const N: usize>(mut a: SMatrix<f64, N, N>, mut rhs: SVector<f64, N>, r: usize) -> Option<SVector<f64, N>> {
    let largest = (0..r).flat_map(|k| (0..r).map(move |l| (k, l))).fold(0.0_f64, |m, (k, l)| m.max(a[(k, l)].abs()));
    for k in 0..r {
        let p = (k..r).max_by(|&i, &j| a[(i, k)].abs().total_cmp(&a[(j, k)].abs()))?;
        // (A NaN pivot fails too.)
        if a[(p, k)].abs().partial_cmp(&(DEPENDENT_PIVOT * largest)) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        a.swap_rows(k, p);
        rhs.swap_rows(k, p);
        for i in k + 1..r {
            let factor = a[(i, k)] / a[(k, k)];
            for l in k..r {
                a[(i, l)] -= factor * a[(k, l)];
            }
            rhs[i] -= factor * rhs[k];
        }
    }
    let mut x = SVector::<f64, N>::zeros();
    for k in (0..r).rev() {
        x[k] = (rhs[k] - (k + 1..r).map(|l| a[(k, l)] * x[l]).sum::<f64>()) / a[(k, k)];
    }
    Some(x)
}

#[cfg(test)]
mod tests {
    use super::super::test_random::{positive_definite, uniform};
    use super::*;
    use nalgebra::{SMatrix, SVector};

    /// Newton–Coulomb impacts on random systems (3 degrees of freedom, one or two contacts
    /// approaching together, coupled inertia and directions) at μ up to 3 and every ε: a solution
    /// exists, satisfies the law, and the kinetic energy never grows; the work of the impulses
    /// `Λᵀ(γ⁻ + γ⁺)/2` is the change of `½ q̇ᵀ M q̇`.
    #[test]
    fn newton_coulomb_impacts_never_create_energy() {
        let mut random = uniform(2026);
        let mut solved = 0;
        for case in 0..2000 {
            let mass: SMatrix<f64, 3, 3> = positive_definite(&mut random);
            let ev = Evaluation::<3, 2> {
                mass,
                implicit: None,
                force: SVector::zeros(),
                gap: SVector::zeros(),
                gap_jacobian: SMatrix::from_fn(|_, _| random()),
                gap_time_rate: SVector::zeros(),
                gap_bias: SVector::zeros(),
            };
            let tangents = Tangents { jacobian: SMatrix::from_fn(|_, _| random()), time_rate: SVector::zeros(), bias: SVector::zeros() };
            let (mu, eps) = (3.0 * (random() + 0.5), random() + 0.5);
            let inertia = Inertia::new(&mass).unwrap();
            let frame = Tangential::new(&ev, &tangents, &inertia, SVector::from_element(mu));
            let v = SVector::<f64, 3>::from_fn(|_, _| random());
            let (hd, slip) = (ev.gap_jacobian * v, tangents.slip(&v));
            let both = case % 2 == 0;
            if hd[0] >= 0.0 || (both && hd[1] >= 0.0) {
                continue;
            }
            let choices = [Choice::AtRest, if both { Choice::AtRest } else { Choice::Open }];
            let b = (hd * (1.0 + eps), slip * (1.0 + eps));
            let scale = hd.amax().max(slip.amax());
            let (modes, jump) = frame.enumerate(&choices, (&b.0, &b.1), scale).unwrap_or_else(|| panic!("case {case}: no solution"));
            let v_plus = frame.motion(&v, &jump);
            let kinetic = |v: &SVector<f64, 3>| 0.5 * v.dot(&(mass * v));
            let gain = kinetic(&v_plus) - kinetic(&v);
            let work = 0.5 * (jump.normal.dot(&(hd + ev.gap_jacobian * v_plus)) + jump.tangent.dot(&(slip + tangents.slip(&v_plus))));
            assert!(gain <= 1e-12 * kinetic(&v), "case {case}: μ {mu}, ε {eps}, {modes:?}: the impact gains {gain:e} J");
            assert!((gain - work).abs() <= 1e-12 * kinetic(&v), "case {case}: ΔT {gain:e} against the impulses' work {work:e}");
            for i in (0..2).filter(|&i| modes[i] != Mode::Open) {
                assert!(jump.normal[i] >= 0.0 && jump.tangent[i].abs() <= mu * jump.normal[i] * (1.0 + 1e-12), "case {case}: {jump:?}");
            }
            solved += 1;
        }
        assert!(solved > 500, "{solved} impacts");
    }

    /// A slipping contact's friction enters its own normal row: for one contact the normal force is
    /// `−b_N / (W_NN − μ s W_NT)` and `λ_T = −μ s λ_N`.
    #[test]
    fn one_slipping_contact_in_closed_form() {
        let ev = Evaluation::<2, 1> {
            mass: SMatrix::from_row_slice(&[2.0, 0.3, 0.3, 1.0]),
            implicit: None,
            force: SVector::zeros(),
            gap: SVector::zeros(),
            gap_jacobian: SMatrix::from_row_slice(&[0.2, 1.0]),
            gap_time_rate: SVector::zeros(),
            gap_bias: SVector::zeros(),
        };
        let tangents = Tangents { jacobian: SMatrix::from_row_slice(&[1.0, -0.4]), time_rate: SVector::zeros(), bias: SVector::zeros() };
        let inertia = Inertia::new(&ev.mass).unwrap();
        let frame = Tangential::new(&ev, &tangents, &inertia, SVector::from_element(0.3));
        let b = (SVector::from_element(-2.0), SVector::from_element(0.7));
        let s = frame.solve(&[Mode::Slip(-1.0)], (&b.0, &b.1)).unwrap();
        let (w_nn, w_nt) = (frame.w[0][0][(0, 0)], frame.w[0][1][(0, 0)]);
        let normal = 2.0 / (w_nn + 0.3 * w_nt);
        assert!((s.normal[0] - normal).abs() < 1e-14 * normal && (s.tangent[0] - 0.3 * normal).abs() < 1e-14 * normal);
        assert!(s.y_normal[0].abs() < 1e-14);
    }
}
