//! The held motion of a system whose inertia carries a force made linearly implicit (a stiff
//! damper `−D q̇` applied as `−D (q̇ + τ q̈)`, its `K = τ D` added to `M`; see
//! `System::powers`), with that implicit term kept out of the held constraints' normals.
//!
//! Through `M + K` the contact problem is the implicit term's, not the linkage's: where `K` ≫ `M`
//! along the held normals, `W_NN = J (M + K)⁻¹ Jᵀ` shrinks with `K` while friction's coupling
//! `W_NT` keeps its share, and the slipping contact problem can have no non-negative solution at
//! a friction far below the linkage's critical one (Painlevé's paradox made by a numerical
//! device). Along a held normal the rate is the constraint's, so the damper is not stiff there:
//! the implicit term is needed only in the motions the held contacts leave free. With `P` the
//! `M`-orthogonal projector onto `ker J_H` and `a_p = −M⁻¹ J_Hᵀ W⁻¹ d_H` the acceleration the held
//! gaps impose (every held `q̈` is `a_p + P q̈`), the held motion takes
//!
//! `(M + Pᵀ K P) q̈ = f − Pᵀ K a_p + J_Hᵀ λ + J_Tᵀ λ_T`:
//!
//! the implicit force `−Pᵀ K q̈` instead of `−K q̈`, the difference `(I − Pᵀ) K q̈` (along `J_Hᵀ`)
//! taken by the contact force. Since `P M⁻¹ J_Hᵀ = 0`, `(M + Pᵀ K P)⁻¹ J_Hᵀ = M⁻¹ J_Hᵀ`: the held
//! rows' `W_NN` and `W_NT` are the linkage's own, whose friction the design space keeps below its
//! critical coefficient. Without friction the motion is the one through `M + K`; only the normal
//! force leaves out the implicit term's normal share.

use super::complementarity::{Contacts, Frame, Set};
use super::contact_laws::{sliding_law, Tolerances};
use super::sample::motion;
use super::system::absorbed;
use super::{DynamicsError, Evaluation, Powers, Stepper, System};
use nalgebra::{SMatrix, SVector};

/// A held motion's evaluation with the implicit term projected (see the module).
pub(super) struct Projected<const N: usize, const M: usize> {
    pub ev: Evaluation<N, M>,
    /// `P`.
    projector: SMatrix<f64, N, N>,
    /// `K`.
    implicit: SMatrix<f64, N, N>,
}

impl<const N: usize, const M: usize> Projected<N, M> {
    /// At `(t, q, q̇)`, the system's evaluation there `ev`, with `held` held.
    pub fn new<S: System<N, M>>(
        sys: &S,
        ev: &Evaluation<N, M>,
        (t, q, v): (f64, &SVector<f64, N>, &SVector<f64, N>),
        held: Set,
    ) -> Result<Self, DynamicsError> {
        let bare = Evaluation { mass: sys.impact_mass(t, q, v, ev), ..ev.clone() };
        let implicit = ev.mass - bare.mass;
        let frame = Frame::new(&bare).ok_or(DynamicsError::SingularMass { time: t })?;
        let dependent = || DynamicsError::DependentContacts { time: t, constraints: held };
        let mut projector = SMatrix::<f64, N, N>::identity();
        for k in 0..N {
            // P = I − M⁻¹ J_Hᵀ W⁻¹ J_H, a column at a time.
            let along = frame.projection(&ev.gap_jacobian.column(k).into_owned(), held).ok_or_else(dependent)?.0;
            projector.set_column(k, &(projector.column(k) + along));
        }
        let imposed = frame.projection(&ev.gap_bias, held).ok_or_else(dependent)?.0;
        let taken = projector.transpose() * implicit;
        let (mass, force) = (bare.mass + taken * projector, ev.force - taken * imposed);
        Ok(Self { ev: Evaluation { mass, force, ..bare }, projector, implicit })
    }

    /// The power the held contacts take over from the implicit force at `(q̇, q̈)`,
    /// `((Pᵀ K − K) q̈)·q̇`, W: the system's absorbed power, reckoned with `−K q̈`, plus this is
    /// what the force applied here takes.
    pub fn taken(&self, v: &SVector<f64, N>, acc: &SVector<f64, N>) -> f64 {
        ((self.projector.transpose() * self.implicit - self.implicit) * acc).dot(v)
    }

    /// What the implicit impulse `−Pᵀ K P Δq̇` of a jump `before → after` takes, its negative work
    /// on the mean velocity, J, in the whole channel alone (the system's channels assume `K`).
    pub fn by_jump(&self, before: &SVector<f64, N>, after: &SVector<f64, N>) -> Powers {
        let mean = (before + after) * 0.5;
        let impulse = self.projector.transpose() * self.implicit * self.projector * (after - before);
        absorbed(mean.dot(&impulse))
    }

    /// The contact frame of the projected evaluation.
    pub fn frame(&self, t: f64) -> Result<Frame<N, M>, DynamicsError> {
        Frame::new(&self.ev).ok_or(DynamicsError::SingularMass { time: t })
    }
}

impl<S: System<N, M>, const N: usize, const M: usize> Stepper<S, N, M> {
    /// The law of persistent contact over `candidates` at `(t, q, q̇)` (`sliding_law`); where the
    /// system's implicit inertia leaves it without a solution, the law with that inertia projected
    /// off every candidate's normal: the normal rows are then the linkage's own, and its answer is
    /// the contact problem of the linkage with the film's forces at the instant's rates. The set it
    /// holds is held with the projection off its own normals. A candidate it opens that the film's
    /// implicit term pushes back (where the linkage leaves the liner while the film's relaxation
    /// returns it) closes again along the motion, and the laws decide anew at that event.
    /// Returns the contacts and `q̈` of their motion.
    pub(super) fn persistent_law(
        &self,
        tol: Tolerances,
        (t, q, v): (f64, &SVector<f64, N>, &SVector<f64, N>),
        (ev, frame): (&Evaluation<N, M>, &Frame<N, M>),
        candidates: Set,
    ) -> Result<(Contacts, SVector<f64, N>), DynamicsError> {
        let probe = |contacts, steps| self.probe((t, q, v), ev, contacts, steps);
        let through_implicit = sliding_law(&self.system, tol, (t, q, v), (ev, frame), candidates, &probe);
        if !self.system.absorbs() || !matches!(through_implicit, Err(DynamicsError::ContactUnresolved { .. })) {
            return through_implicit;
        }
        let projected = Projected::new(&self.system, ev, (t, q, v), candidates)?;
        let probe = |contacts: Contacts, steps| {
            let contacts = Contacts { projected: true, ..contacts };
            let (t, q, v, ev) = self.probe((t, q, v), ev, contacts, steps)?;
            Ok((t, q, v, Projected::new(&self.system, &ev, (t, &q, &v), candidates)?.ev))
        };
        let (contacts, _) = sliding_law(&self.system, tol, (t, q, v), (&projected.ev, &projected.frame(t)?), candidates, &probe)?;
        let contacts = Contacts { projected: contacts.held != 0, ..contacts };
        Ok((contacts, motion(&self.system, ev, (t, q, v), contacts)?.acc))
    }
}

#[cfg(test)]
mod tests {
    use super::super::sample::acceleration;
    use super::super::test_random::{positive_definite, uniform};
    use super::*;
    use nalgebra::{SMatrix, SVector};

    /// A linkage of inertia `M` whose evaluation adds an implicit `K` (`M + K`, `impact_mass` `M`).
    struct Implicit {
        ev: Evaluation<3, 2>,
        bare: SMatrix<f64, 3, 3>,
    }

    impl System<3, 2> for Implicit {
        fn evaluate(&self, _: f64, _: &SVector<f64, 3>, _: &SVector<f64, 3>) -> Evaluation<3, 2> {
            self.ev.clone()
        }
        fn impact_mass(&self, _: f64, _: &SVector<f64, 3>, _: &SVector<f64, 3>, _: &Evaluation<3, 2>) -> SMatrix<f64, 3, 3> {
            self.bare
        }
        fn restitution(&self) -> f64 {
            0.0
        }
    }

    /// Random linkages with an implicit term up to 1e4 times their inertia, one or two constraints
    /// held: the held rows of `W_NN` and `W_NT` through the projection are the linkage's own (to
    /// round-off of `K`), and without friction the held motion is the one through `M + K`, its
    /// normal force less the implicit term's normal share `(J M⁻¹ Jᵀ)⁻¹ J M⁻¹ K q̈`.
    #[test]
    fn the_held_rows_see_the_linkage_and_the_frictionless_motion_is_unchanged() {
        let mut random = uniform(32);
        for case in 0..200 {
            let bare = positive_definite::<3>(&mut random);
            let root = SMatrix::<f64, 3, 3>::from_fn(|_, _| random());
            let implicit = root * root.transpose() * libm::pow(10.0, 4.0 * (random() + 0.5));
            let ev = Evaluation {
                mass: bare + implicit,
                force: SVector::from_fn(|_, _| random()),
                gap: SVector::zeros(),
                gap_jacobian: SMatrix::from_fn(|_, _| random()),
                gap_time_rate: SVector::zeros(),
                gap_bias: SVector::from_fn(|_, _| random()),
            };
            let tangents = SMatrix::<f64, 2, 3>::from_fn(|_, _| random());
            let held = if case % 2 == 0 { 0b01 } else { 0b11 };
            let sys = Implicit { ev: ev.clone(), bare };
            let zero = SVector::<f64, 3>::zeros();
            let projected = Projected::new(&sys, &ev, (0.0, &zero, &zero), held).unwrap();
            let inverse = |m: SMatrix<f64, 3, 3>| m.try_inverse().unwrap();
            let (through, linkage) = (inverse(projected.ev.mass), inverse(bare));
            let scale = implicit.amax() / bare.amax();
            for i in (0..2).filter(|&i| held >> i & 1 == 1) {
                let row = ev.gap_jacobian.row(i);
                for (a, b) in [
                    (row * through * ev.gap_jacobian.transpose(), row * linkage * ev.gap_jacobian.transpose()),
                    (row * through * tangents.transpose(), row * linkage * tangents.transpose()),
                ] {
                    assert!((a - b).amax() <= 1e-13 * scale * b.amax().max(1.0), "case {case}: {a} against {b}");
                }
            }
            let (acc, normal) = acceleration(&projected.ev, 0.0, held).unwrap();
            let (acc_implicit, normal_implicit) = acceleration(&ev, 0.0, held).unwrap();
            assert!((acc - acc_implicit).amax() <= 1e-10 * acc_implicit.amax(), "case {case}: {acc} against {acc_implicit}");
            let j = SMatrix::<f64, 2, 3>::from_fn(|r, c| if held >> r & 1 == 1 { ev.gap_jacobian[(r, c)] } else { 0.0 });
            let w =
                j * linkage * j.transpose() + SMatrix::<f64, 2, 2>::from_fn(|r, c| if r == c && held >> r & 1 == 0 { 1.0 } else { 0.0 });
            let share = w.try_inverse().unwrap() * j * linkage * implicit * acc_implicit;
            assert!((normal - (normal_implicit - share)).amax() <= 1e-9 * normal_implicit.amax(), "case {case}: {normal}");
        }
    }
}
