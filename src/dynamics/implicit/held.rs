//! The stepper where an implicit part acts (see the module `implicit`).

use super::projection::Projected;
use crate::dynamics::complementarity::{Contacts, Frame, Set};
use crate::dynamics::contact_laws::{sliding_law, Tolerances};
use crate::dynamics::hermite::Hermite5;
use crate::dynamics::sample::{motion, sample, Sample};
use crate::dynamics::{Change, DynamicsError, Evaluation, Powers, Stepper, System};
use nalgebra::SVector;
/// The path's middle, besides the RK4 stage, is read for a held force's dips inside a step (`search.rs`)
/// where the evaluation at the step's end `ev` has an implicit part: thousands of times the inertia in the
/// fast modes, it magnifies the stage's offset from the path (a held force can be newtons above zero at the
/// stage and below it on the path).
pub(in crate::dynamics) fn stages_off_path<const N: usize, const M: usize>(ev: Option<&Evaluation<N, M>>) -> bool {
    ev.is_some_and(|ev| ev.implicit.is_some())
}

/// The evaluation and frame a jump onto held contacts goes through: the system's, or where the contacts are
/// projected, the projection's (they jump through the inertia their motion takes).
pub(in crate::dynamics) struct JumpThrough<const N: usize, const M: usize> {
    pub ev: Evaluation<N, M>,
    pub frame: Frame<N, M>,
    projected: Option<Projected<N, M>>,
}

impl<S: System<N, M>, const N: usize, const M: usize> Stepper<S, N, M> {
    /// The jump of `q̇` onto the held set `active` (`Frame::projection` of the gap rates `hd`) at `t`,
    /// `(ev, frame)` the evaluation and frame there. Projected held contacts move the velocity through `M`
    /// alone (the projected inertia's `M⁻¹ J_Hᵀ`), which the implicit part takes no impulse in.
    #[allow(clippy::type_complexity)]
    pub(in crate::dynamics) fn held_jump(
        &self,
        (ev, frame): (&Evaluation<N, M>, &Frame<N, M>),
        t: f64,
        hd: &SVector<f64, M>,
        active: Set,
    ) -> Result<Option<(SVector<f64, N>, SVector<f64, M>)>, DynamicsError> {
        Ok(if self.contacts.projected {
            Projected::new(ev, t, active)?.frame(t)?.projection(hd, active)
        } else {
            frame.projection(hd, active)
        })
    }

    /// What a jump onto `contacts` at `t` goes through, `(ev, frame)` the system's evaluation and frame there.
    pub(in crate::dynamics) fn jump_through(
        &self,
        contacts: Contacts,
        t: f64,
        (ev, frame): (Evaluation<N, M>, Frame<N, M>),
    ) -> Result<JumpThrough<N, M>, DynamicsError> {
        if !contacts.projected {
            return Ok(JumpThrough { ev, frame, projected: None });
        }
        let p = Projected::new(&ev, t, contacts.held)?;
        Ok(JumpThrough { ev: p.ev.clone(), frame: p.frame(t)?, projected: Some(p) })
    }

    /// What is booked of the jump `before → after` at `(t, q)` that went `through`: the projection's
    /// implicit impulse, or what the system books of it (`booked_jump`).
    pub(in crate::dynamics) fn jump_books(
        &self,
        through: &JumpThrough<N, M>,
        (t, q): (f64, &SVector<f64, N>),
        before: &SVector<f64, N>,
        after: &SVector<f64, N>,
    ) -> Powers {
        match &through.projected {
            Some(p) => p.by_jump(before, after),
            None => self.booked_jump(&through.ev, (t, q), before, after),
        }
    }

    /// What the system books of the jump `before → after` at `(t, q)` onto the held contacts
    /// (`Change::Jump`), where its evaluation there `ev` has an implicit part: only that part takes an
    /// impulse at a jump. None where the contacts are projected: see `held_jump`.
    pub(in crate::dynamics) fn booked_jump(
        &self,
        ev: &Evaluation<N, M>,
        (t, q): (f64, &SVector<f64, N>),
        before: &SVector<f64, N>,
        after: &SVector<f64, N>,
    ) -> Powers {
        if S::POWERS && ev.implicit.is_some() && !self.contacts.projected {
            self.system.powers(t, q, Change::Jump { before, after })
        } else {
            Powers::zeros()
        }
    }

    /// The law of persistent contact over `candidates` at `(t, q, q̇)` (`sliding_law`); where the
    /// system's implicit inertia leaves it without a solution, the law with that inertia projected
    /// off every candidate's normal (`implicit/`): the normal rows are then those of `M` alone, and
    /// its answer is the contact problem of the motion with the stiff force at the instant's rates. The set it
    /// holds is held with the projection off its own normals. A candidate it opens that the
    /// implicit term pushes back (leaving its surface under `M` while the force's relaxation returns it)
    /// closes again along the motion, and the laws decide anew at that event.
    /// Returns the contacts and `q̈` of their motion.
    pub(in crate::dynamics) fn persistent_law(
        &self,
        tol: Tolerances,
        (t, q, v): (f64, &SVector<f64, N>, &SVector<f64, N>),
        (ev, frame): (&Evaluation<N, M>, &Frame<N, M>),
        candidates: Set,
    ) -> Result<(Contacts, SVector<f64, N>), DynamicsError> {
        let probe = |contacts, steps| self.probe((t, q, v), ev, contacts, steps);
        let through_implicit = sliding_law(&self.system, tol, (t, q, v), (ev, frame), candidates, &probe);
        if ev.implicit.is_none() || !matches!(through_implicit, Err(DynamicsError::ContactUnresolved { .. })) {
            return through_implicit;
        }
        let projected = Projected::new(ev, t, candidates)?;
        let probe = |contacts: Contacts, steps| {
            let contacts = Contacts { projected: true, ..contacts };
            let (t, q, v, ev) = self.probe((t, q, v), ev, contacts, steps)?;
            Ok((t, q, v, Projected::new(&ev, t, candidates)?.ev))
        };
        let (contacts, _) = sliding_law(&self.system, tol, (t, q, v), (&projected.ev, &projected.frame(t)?), candidates, &probe)?;
        let contacts = Contacts { projected: contacts.held != 0, ..contacts };
        Ok((contacts, motion(&self.system, ev, (t, q, v), contacts)?.acc))
    }
}

/// The totals of a held step `s0 → s` whose end evaluation `ev` has an implicit part, by
/// Simpson's rule on the step's path (its quintic dense output, whose middle lies on the held
/// constraints to the step's order): the system's rates, the contact impulse and the friction work.
/// The stages leave the held constraints by ≈ q̈ dt²/8, where a stiff force, steep in the gap, reads
/// many times what the path has: the motion, held, does not feel it (the contact force takes it),
/// but rates and forces taken at the stages book it. Where the middle's inertia is singular to
/// round-off, the stages' totals stand; they stand as well for a flight or a system without an implicit part.
pub(in crate::dynamics) fn on_path_totals<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    s0: &Sample<N, M>,
    s: &mut Sample<N, M>,
    ev: &Evaluation<N, M>,
    contacts: Contacts,
) {
    if ev.implicit.is_none() || contacts.held == 0 {
        return;
    }
    let dt = s.t - s0.t;
    let path = Hermite5 { t0: s0.t, dt, q0: s0.q, v0: s0.v, a0: s0.acc, q1: s.q, v1: s.v, a1: s.acc };
    let (q, v) = path.at(s0.t + 0.5 * dt);
    let Ok(mid) = sample(sys, s0.t + 0.5 * dt, q, v, contacts) else {
        return;
    };
    let sixth = dt / 6.0;
    s.energies = s0.energies + (s0.powers + mid.powers * 4.0 + s.powers) * sixth;
    s.contact_impulse = s0.contact_impulse + (s0.lambda + mid.lambda * 4.0 + s.lambda) * sixth;
    s.friction_work = s0.friction_work + (s0.friction_power() + 4.0 * mid.friction_power() + s.friction_power()) * sixth;
}
