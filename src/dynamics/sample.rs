//! The state the loop carries between steps (a sample of the motion with its contact forces and
//! gap rates), and the motion the held contacts give at one state.

use super::complementarity::{contains, held_acceleration, Contacts, Frame, Mode, Set};
use super::coulomb::Tangential;
use super::implicit::Projected;
use super::inertia::Inertia;
use super::system::{friction_of, implicit_share};
use super::{Change, DynamicsError, Evaluation, Powers, System};
use nalgebra::{SMatrix, SVector};
use serde::{Deserialize, Serialize};

/// Everything the loop needs at one `(t, q, q̇)` with a given contact set.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(super) struct Sample<const N: usize, const M: usize> {
    pub(super) t: f64,
    pub(super) q: SVector<f64, N>,
    pub(super) v: SVector<f64, N>,
    pub(super) acc: SVector<f64, N>,
    pub(super) lambda: SVector<f64, M>,
    pub(super) gap: SVector<f64, M>,
    /// ḣ = J q̇ + ∂h/∂t.
    pub(super) hd: SVector<f64, M>,
    /// ḧ = J q̈ + d: with `h` and `ḣ` at both ends of a step it gives the gaps' own quintic
    /// extension, so that event search samples no configuration.
    pub(super) hdd: SVector<f64, M>,
    /// Slip velocity γ and tangential force λ_T (zero without friction).
    pub(super) slip: SVector<f64, M>,
    pub(super) friction: SVector<f64, M>,
    /// Energy friction has dissipated in persistent contact since the start, J: integrated with
    /// the steps (`rk4_step`), carried over where a state is replaced at the same time. (Impacts
    /// record their own share, `Event::friction_energy`.)
    pub(super) friction_work: f64,
    /// ∫ λ dt per constraint since the start, N·s: the persistent contact forces' impulse, by the
    /// same quadrature as `friction_work` (impacts record their own, `Event::impulses`).
    pub(super) contact_impulse: SVector<f64, M>,
    /// The rates the system reports here (`System::powers`), and their integrals since the start,
    /// integrated like `friction_work` and carried alike, with the jumps' shares
    /// (`Change::Jump`) added where they happen. Zero where the system reports none.
    pub(super) powers: Powers,
    pub(super) energies: Powers,
}

impl<const N: usize, const M: usize> Sample<N, M> {
    /// The power friction dissipates, `μ λ_N |γ|` summed: `|λ_T γ|` per constraint (a slipping
    /// constraint's force opposes γ; `−λ_T · γ` would carry γ's round-off around a slip reversal
    /// and a stick, −1e-9 W, as if friction did work).
    pub(super) fn friction_power(&self) -> f64 {
        dissipated(&self.friction, &self.slip)
    }

    /// This sample, continuing the friction work of `from`.
    pub(super) fn after(self, from: &Sample<N, M>) -> Self {
        Self { friction_work: from.friction_work, contact_impulse: from.contact_impulse, energies: from.energies, ..self }
    }
}

/// The power tangential forces `λ_T` dissipate at slip velocities `γ`, W (see `Sample::friction_power`).
pub(super) fn dissipated<const M: usize>(friction: &SVector<f64, M>, slip: &SVector<f64, M>) -> f64 {
    friction.zip_fold(slip, 0.0, |sum, f, g| sum + (f * g).abs())
}

/// A sample with the system's evaluation there (the impact and sliding laws and the drift
/// projection reuse it), or without one where none is at hand.
pub(super) type Evaluated<const N: usize, const M: usize> = (Sample<N, M>, Option<Evaluation<N, M>>);

/// Which function of constraint `i` an event watches: the gap of a free constraint, the normal
/// force of a held one, and with friction the slip `s γ` of one slipping in direction `s` or the
/// margin `μ λ_N − |λ_T|` to the friction cone of one sticking with friction coefficient `μ`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Watch {
    Gap,
    Multiplier,
    Slip(f64),
    Stick(f64),
}

impl Watch {
    /// What a step with `contacts` held watches: each free constraint's gap, each held one's
    /// normal force, and where `mu` gives friction each held one's slip (slipping) or margin to
    /// the friction cone (sticking).
    pub(super) fn all<const M: usize>(contacts: Contacts, mu: Option<SVector<f64, M>>) -> impl Iterator<Item = (usize, Watch)> + Clone {
        let normal = (0..M).map(move |i| (i, if contains(contacts.held, i) { Watch::Multiplier } else { Watch::Gap }));
        let tangential = mu.into_iter().flat_map(move |mu| {
            (0..M).filter_map(move |i| match contacts.mode(i) {
                _ if mu[i] == 0.0 => None,
                Mode::Open => None,
                Mode::Stick => Some((i, Watch::Stick(mu[i]))),
                Mode::Slip(s) => Some((i, Watch::Slip(s))),
            })
        });
        normal.chain(tangential)
    }
}

impl<const N: usize, const M: usize> Sample<N, M> {
    pub(super) fn watched(&self, i: usize, w: Watch) -> f64 {
        match w {
            Watch::Gap => self.gap[i],
            _ => Forces { lambda: self.lambda, friction: self.friction, slip: self.slip }.watched(i, w),
        }
    }
}

/// The contact forces and slips of a held set at one state: at a step's middle (its third RK4
/// stage, at `t₀ + h/2`, which computes them anyway) they show a force or slip that dips through
/// zero and back inside the step, which the values at its ends miss.
#[derive(Clone, Copy, Debug)]
pub(super) struct Forces<const M: usize> {
    pub lambda: SVector<f64, M>,
    pub friction: SVector<f64, M>,
    pub slip: SVector<f64, M>,
}

impl<const M: usize> Forces<M> {
    pub(super) fn zeros() -> Self {
        Self { lambda: SVector::zeros(), friction: SVector::zeros(), slip: SVector::zeros() }
    }

    /// The function `w` watches of a held constraint `i` (a gap is not here: +∞, never crossed).
    pub(super) fn watched(&self, i: usize, w: Watch) -> f64 {
        match w {
            Watch::Gap => f64::INFINITY,
            Watch::Multiplier => self.lambda[i],
            Watch::Slip(s) => s * self.slip[i],
            Watch::Stick(mu) => mu * self.lambda[i] - self.friction[i].abs(),
        }
    }
}

/// What the held contacts give at one state: `q̈`, `λ_N`, `λ_T` and the slip velocities γ; and
/// the power they take over from the system's implicit force (`Projected::taken`, zero unless
/// `Contacts::projected`).
pub(super) struct Motion<const N: usize, const M: usize> {
    pub acc: SVector<f64, N>,
    pub lambda: SVector<f64, M>,
    pub friction: SVector<f64, M>,
    pub slip: SVector<f64, M>,
    pub taken: f64,
}

impl<const N: usize, const M: usize> Motion<N, M> {
    /// The free motion with the acceleration `acc`.
    #[inline(always)]
    pub(super) fn free(acc: SVector<f64, N>) -> Self {
        Self { acc, lambda: SVector::zeros(), friction: SVector::zeros(), slip: SVector::zeros(), taken: 0.0 }
    }
}

/// The system's rates at `(t, q, q̇)` with the motion `m` the held contacts give there, the power
/// `m.taken` from its implicit part by projected held contacts added to that part's channel.
#[inline(always)]
pub(super) fn powers<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    (t, q, v): (f64, &SVector<f64, N>, &SVector<f64, N>),
    m: &Motion<N, M>,
) -> Powers {
    sys.powers(t, q, Change::Rates { v, acc: &m.acc, forces: (&m.lambda, &m.friction) }) + implicit_share(m.taken)
}

/// `Motion` at `(t, q, q̇)` with `contacts` held, from the evaluation there: through the projection where
/// the contacts are projected, with the power they take over from the implicit force.
#[inline(always)]
pub(super) fn motion<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    ev: &Evaluation<N, M>,
    (t, q, v): (f64, &SVector<f64, N>, &SVector<f64, N>),
    contacts: Contacts,
) -> Result<Motion<N, M>, DynamicsError> {
    let Some(projected) = Projected::for_held(ev, t, contacts)? else {
        return motion_through(sys, ev, (t, q, v), contacts);
    };
    let m = motion_through(sys, &projected.ev, (t, q, v), contacts)?;
    Ok(Motion { taken: projected.taken(v, &m.acc), ..m })
}

/// `Motion` with the inertia and force of `ev` as they are.
#[inline(always)]
fn motion_through<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    ev: &Evaluation<N, M>,
    (t, q, v): (f64, &SVector<f64, N>, &SVector<f64, N>),
    contacts: Contacts,
) -> Result<Motion<N, M>, DynamicsError> {
    let Some(mu) = friction_of(sys) else {
        let (acc, lambda) = acceleration(ev, t, contacts.held)?;
        return Ok(Motion { acc, lambda, friction: SVector::zeros(), slip: SVector::zeros(), taken: 0.0 });
    };
    let tangents = sys.tangents(t, q, v);
    let slip = tangents.slip(v);
    let (inertia, free_acc) = free_motion(&ev.inertia(), &ev.force, t)?;
    if contacts.held == 0 {
        return Ok(Motion { acc: free_acc, lambda: SVector::zeros(), friction: SVector::zeros(), slip, taken: 0.0 });
    }
    // A wedge held is one the laws found at rest.
    let frame = Tangential::new(ev, &tangents, &inertia, mu).wedging(true);
    let modes = std::array::from_fn(|i| contacts.mode(i));
    let b = (Frame::gap_acceleration(ev, &free_acc), tangents.jacobian * free_acc + tangents.bias);
    let s = frame.solve(&modes, (&b.0, &b.1)).ok_or(DynamicsError::DependentContacts { time: t, constraints: contacts.held })?;
    Ok(Motion { acc: frame.motion(&free_acc, &s), lambda: s.normal, friction: s.tangent, slip, taken: 0.0 })
}

/// The evaluation at `(t, q, q̇)` and its contact frame; `known`: that evaluation, if at hand.
pub(super) fn frame_at<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    t: f64,
    q: &SVector<f64, N>,
    v: &SVector<f64, N>,
    known: Option<Evaluation<N, M>>,
) -> Result<(Evaluation<N, M>, Frame<N, M>), DynamicsError> {
    let ev = known.unwrap_or_else(|| sys.evaluate(t, q, v));
    let frame = Frame::new(&ev).ok_or(DynamicsError::SingularMass { time: t })?;
    Ok((ev, frame))
}

/// `q̈` and `λ` with the set `active` held; free flight needs only `M⁻¹ f`.
pub(super) fn acceleration<const N: usize, const M: usize>(
    ev: &Evaluation<N, M>,
    t: f64,
    active: Set,
) -> Result<(SVector<f64, N>, SVector<f64, M>), DynamicsError> {
    let (inertia, free_acc) = free_motion(&ev.inertia(), &ev.force, t)?;
    if active == 0 {
        return Ok((free_acc, SVector::zeros()));
    }
    held_acceleration(ev, &inertia, free_acc, active).ok_or(DynamicsError::DependentContacts { time: t, constraints: active })
}

/// `M⁻¹` and the acceleration `M⁻¹ f` with no constraint held.
pub(super) fn free_motion<const N: usize>(
    mass: &SMatrix<f64, N, N>,
    force: &SVector<f64, N>,
    t: f64,
) -> Result<(Inertia<N>, SVector<f64, N>), DynamicsError> {
    let inertia = Inertia::new(mass).ok_or(DynamicsError::SingularMass { time: t })?;
    let acc = inertia.solve(force);
    Ok((inertia, acc))
}

pub(super) fn sample<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    t: f64,
    q: SVector<f64, N>,
    v: SVector<f64, N>,
    contacts: Contacts,
) -> Result<Sample<N, M>, DynamicsError> {
    sample_of(sys, &sys.evaluate(t, &q, &v), t, q, v, contacts)
}

/// The sample at `(t, q, q̇)` from its evaluation `ev` (borrowed: callers use it again, and a
/// moved evaluation is a copy). Inlined, like `rk4_step`, so that the sample is built where the
/// caller keeps it rather than copied out of the `Result`.
#[inline(always)]
pub(super) fn sample_of<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    ev: &Evaluation<N, M>,
    t: f64,
    q: SVector<f64, N>,
    v: SVector<f64, N>,
    contacts: Contacts,
) -> Result<Sample<N, M>, DynamicsError> {
    sample_rated(sys, ev, (t, q, v), contacts, S::POWERS)
}

/// [`sample_of`] with the system's rates (`System::powers`) only where `rates` (zero otherwise): a
/// communication point's are computed when asked (`Stepper::rates`), since no step integrates them.
#[inline(always)]
pub(super) fn sample_rated<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    ev: &Evaluation<N, M>,
    (t, q, v): (f64, SVector<f64, N>, SVector<f64, N>),
    contacts: Contacts,
    rates: bool,
) -> Result<Sample<N, M>, DynamicsError> {
    let m = motion(sys, ev, (t, &q, &v), contacts)?;
    let powers = if rates { powers(sys, (t, &q, &v), &m) } else { Powers::zeros() };
    let Motion { acc, lambda, friction, slip, .. } = m;
    let hd = ev.gap_jacobian * v + ev.gap_time_rate;
    let hdd = ev.gap_jacobian * acc + ev.gap_bias;
    let s = Sample {
        t,
        q,
        v,
        acc,
        lambda,
        gap: ev.gap,
        hd,
        hdd,
        slip,
        friction,
        friction_work: 0.0,
        contact_impulse: SVector::zeros(),
        powers,
        energies: Powers::zeros(),
    };
    // One sum clears every number (x · 0 is NaN exactly for an infinite or NaN x).
    let coordinates = (s.q * 0.0 + s.v * 0.0 + s.acc * 0.0).sum() + (s.powers * 0.0).sum();
    let constraints = (s.lambda * 0.0 + s.gap * 0.0 + s.hd * 0.0 + s.hdd * 0.0 + s.slip * 0.0 + s.friction * 0.0).sum();
    if coordinates + constraints == 0.0 {
        Ok(s)
    } else {
        Err(DynamicsError::NonFinite { time: t })
    }
}
