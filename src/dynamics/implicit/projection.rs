//! The projection of the implicit term off held normals, and the evaluation an impact acts through (see the
//! module `implicit`).

use crate::dynamics::complementarity::{Contacts, Frame, Set};
use crate::dynamics::system::implicit_share;
use crate::dynamics::{DynamicsError, Evaluation, Powers};
use nalgebra::{SMatrix, SVector};

/// The evaluation and frame an impact at `t` acts through where `ev` has an implicit part: `ev`
/// without it. None where it has none: `ev` and its frame are the impact's.
#[allow(clippy::type_complexity)]
pub(in crate::dynamics) fn for_impact<const N: usize, const M: usize>(
    ev: &Evaluation<N, M>,
    t: f64,
) -> Result<Option<(Evaluation<N, M>, Frame<N, M>)>, DynamicsError> {
    if ev.implicit.is_none() {
        return Ok(None);
    }
    let bare = Evaluation { implicit: None, ..ev.clone() };
    let frame = Frame::new(&bare).ok_or(DynamicsError::SingularMass { time: t })?;
    Ok(Some((bare, frame)))
}

/// A held motion's evaluation with the implicit term projected (see the module).
pub(in crate::dynamics) struct Projected<const N: usize, const M: usize> {
    pub ev: Evaluation<N, M>,
    /// `P`.
    projector: SMatrix<f64, N, N>,
    /// `K`.
    implicit: SMatrix<f64, N, N>,
}

impl<const N: usize, const M: usize> Projected<N, M> {
    /// At `t`, the system's evaluation there `ev`, with `held` held.
    pub fn new(ev: &Evaluation<N, M>, t: f64, held: Set) -> Result<Self, DynamicsError> {
        let bare = Evaluation { implicit: None, ..ev.clone() };
        let implicit = ev.implicit.unwrap_or_else(SMatrix::zeros);
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
        let force = ev.force - taken * imposed;
        Ok(Self { ev: Evaluation { implicit: Some(taken * projector), force, ..bare }, projector, implicit })
    }

    /// The projection a held motion at `t` with `contacts` acts through: None unless they are projected.
    pub fn for_held(ev: &Evaluation<N, M>, t: f64, contacts: Contacts) -> Result<Option<Self>, DynamicsError> {
        if contacts.projected && contacts.held != 0 {
            Self::new(ev, t, contacts.held).map(Some)
        } else {
            Ok(None)
        }
    }

    /// The power the held contacts take over from the implicit force at `(q̇, q̈)`,
    /// `((Pᵀ K − K) q̈)·q̇`, W: the system's power of the implicit part, reckoned with `−K q̈`, plus this is
    /// what the force applied here takes.
    pub fn taken(&self, v: &SVector<f64, N>, acc: &SVector<f64, N>) -> f64 {
        ((self.projector.transpose() * self.implicit - self.implicit) * acc).dot(v)
    }

    /// What the implicit impulse `−Pᵀ K P Δq̇` of a jump `before → after` takes, its negative work
    /// on the mean velocity, J, in the whole channel alone (the system's channels assume `K`).
    pub fn by_jump(&self, before: &SVector<f64, N>, after: &SVector<f64, N>) -> Powers {
        let mean = (before + after) * 0.5;
        let impulse = self.projector.transpose() * self.implicit * self.projector * (after - before);
        implicit_share(mean.dot(&impulse))
    }

    /// The contact frame of the projected evaluation.
    pub fn frame(&self, t: f64) -> Result<Frame<N, M>, DynamicsError> {
        Frame::new(&self.ev).ok_or(DynamicsError::SingularMass { time: t })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::sample::acceleration;
    use crate::dynamics::test_random::{positive_definite, uniform};
    use nalgebra::{SMatrix, SVector};

    /// Random linkages with an implicit term up to 1e4 times their inertia, one or two constraints
    /// held: the held rows of `W_NN` and `W_NT` through the projection are those of `M` alone (to
    /// round-off of `K`), and without friction the held motion is the one through `M + K`, its
    /// normal force less the implicit term's normal share `(J M⁻¹ Jᵀ)⁻¹ J M⁻¹ K q̈`.
    #[test]
    fn the_held_rows_see_the_linkage_and_the_frictionless_motion_is_unchanged() {
        let mut random = uniform(32);
        for case in 0..200 {
            let bare = positive_definite::<3>(&mut random);
            let root = SMatrix::<f64, 3, 3>::from_fn(|_, _| random());
            let implicit = root * root.transpose() * libm::pow(10.0, 4.0 * (random() + 0.5));
            let ev = Evaluation::<3, 2> {
                mass: bare,
                implicit: Some(implicit),
                force: SVector::from_fn(|_, _| random()),
                gap: SVector::zeros(),
                gap_jacobian: SMatrix::from_fn(|_, _| random()),
                gap_time_rate: SVector::zeros(),
                gap_bias: SVector::from_fn(|_, _| random()),
            };
            let tangents = SMatrix::<f64, 2, 3>::from_fn(|_, _| random());
            let held = if case % 2 == 0 { 0b01 } else { 0b11 };
            let projected = Projected::new(&ev, 0.0, held).unwrap();
            let inverse = |m: SMatrix<f64, 3, 3>| m.try_inverse().unwrap();
            let (through, linkage) = (inverse(projected.ev.inertia()), inverse(bare));
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
