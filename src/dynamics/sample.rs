//! The state the loop carries between steps (a sample of the motion with its contact forces and
//! gap rates), and the RK4 step and its error estimate that make the next one.

use super::contact::{held_acceleration, Frame, Set};
use super::friction::{Contacts, Tangential};
use super::inertia::Inertia;
use super::{rk4, Absorbed, DynamicsError, Evaluation, System};
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
    /// The power the system's own forces take from the motion here (`System::absorbed_power`), W,
    /// and their work since the start, J, integrated like `friction_work` and carried alike, with
    /// the jumps' shares (`System::absorbed_by_jump`) added where they happen. Zero where the
    /// system does not absorb.
    pub(super) absorbed_power: Absorbed,
    pub(super) absorbed_work: Absorbed,
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
        Self { friction_work: from.friction_work, contact_impulse: from.contact_impulse, absorbed_work: from.absorbed_work, ..self }
    }
}

/// The power tangential forces `λ_T` dissipate at slip velocities `γ`, W (see `Sample::friction_power`).
fn dissipated<const M: usize>(friction: &SVector<f64, M>, slip: &SVector<f64, M>) -> f64 {
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

impl<const N: usize, const M: usize> Sample<N, M> {
    pub(super) fn watched(&self, i: usize, w: Watch) -> f64 {
        match w {
            Watch::Gap => self.gap[i],
            Watch::Multiplier => self.lambda[i],
            Watch::Slip(s) => s * self.slip[i],
            Watch::Stick(mu) => mu * self.lambda[i] - self.friction[i].abs(),
        }
    }
}

/// μ of each constraint, if any has friction: `None` keeps a frictionless system on the
/// frictionless paths, to the bit.
#[inline(always)]
pub(super) fn friction_of<S: System<N, M>, const N: usize, const M: usize>(sys: &S) -> Option<SVector<f64, M>> {
    let mu = SVector::<f64, M>::from_fn(|i, _| sys.friction(i));
    mu.iter().any(|&m| m != 0.0).then_some(mu)
}

/// What the held contacts give at one state: `q̈`, `λ_N`, `λ_T` and the slip velocities γ.
pub(super) struct Motion<const N: usize, const M: usize> {
    pub acc: SVector<f64, N>,
    pub lambda: SVector<f64, M>,
    pub friction: SVector<f64, M>,
    pub slip: SVector<f64, M>,
}

/// `Motion` at `(t, q, q̇)` with `contacts` held, from the evaluation there.
#[inline(always)]
pub(super) fn motion<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    ev: &Evaluation<N, M>,
    (t, q, v): (f64, &SVector<f64, N>, &SVector<f64, N>),
    contacts: Contacts,
) -> Result<Motion<N, M>, DynamicsError> {
    let Some(mu) = friction_of(sys) else {
        let (acc, lambda) = acceleration(ev, t, contacts.held)?;
        return Ok(Motion { acc, lambda, friction: SVector::zeros(), slip: SVector::zeros() });
    };
    let tangents = sys.tangents(t, q, v);
    let slip = tangents.slip(v);
    let (inertia, free_acc) = free_motion(&ev.mass, &ev.force, t)?;
    if contacts.held == 0 {
        return Ok(Motion { acc: free_acc, lambda: SVector::zeros(), friction: SVector::zeros(), slip });
    }
    let frame = Tangential::new(ev, &tangents, &inertia, mu);
    let modes = std::array::from_fn(|i| contacts.mode(i));
    let b = (Frame::gap_acceleration(ev, &free_acc), tangents.jacobian * free_acc + tangents.bias);
    let s = frame.solve(&modes, (&b.0, &b.1)).ok_or(DynamicsError::DependentContacts { time: t, constraints: contacts.held })?;
    Ok(Motion { acc: frame.motion(&free_acc, &s), lambda: s.normal, friction: s.tangent, slip })
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
    let (inertia, free_acc) = free_motion(&ev.mass, &ev.force, t)?;
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
    let Motion { acc, lambda, friction, slip } = motion(sys, ev, (t, &q, &v), contacts)?;
    let hd = ev.gap_jacobian * v + ev.gap_time_rate;
    let hdd = ev.gap_jacobian * acc + ev.gap_bias;
    let absorbed_power = if sys.absorbs() { sys.absorbed_power(t, &q, &v, &acc) } else { Absorbed::zeros() };
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
        absorbed_power,
        absorbed_work: Absorbed::zeros(),
    };
    // One sum clears every number (x · 0 is NaN exactly for an infinite or NaN x).
    let coordinates = (s.q * 0.0 + s.v * 0.0 + s.acc * 0.0).sum() + (s.absorbed_power * 0.0).sum();
    let constraints = (s.lambda * 0.0 + s.gap * 0.0 + s.hd * 0.0 + s.hdd * 0.0 + s.slip * 0.0 + s.friction * 0.0).sum();
    if coordinates + constraints == 0.0 {
        Ok(s)
    } else {
        Err(DynamicsError::NonFinite { time: t })
    }
}

/// One RK4 step from `s0` to `t` with `contacts` held, and the end's evaluation.
pub(super) fn rk4_to<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    s0: &Sample<N, M>,
    t: f64,
    contacts: Contacts,
) -> Result<(Sample<N, M>, Evaluation<N, M>), DynamicsError> {
    let (s, ev, _) = rk4_step(sys, s0, t, contacts)?;
    Ok((s, ev))
}

/// `rk4_to`, with the end's evaluation and the step's last slopes (for `local_error`).
#[allow(clippy::type_complexity)]
#[inline(always)]
pub(super) fn rk4_step<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    s0: &Sample<N, M>,
    t: f64,
    contacts: Contacts,
) -> Result<(Sample<N, M>, Evaluation<N, M>, (SVector<f64, N>, SVector<f64, N>)), DynamicsError> {
    // A system that absorbs nothing gets a step without a trace of the absorbed power.
    if sys.absorbs() {
        rk4_step_of::<S, N, M, true>(sys, s0, t, contacts)
    } else {
        rk4_step_of::<S, N, M, false>(sys, s0, t, contacts)
    }
}

#[allow(clippy::type_complexity)]
#[inline(always)]
fn rk4_step_of<S: System<N, M>, const N: usize, const M: usize, const ABSORBS: bool>(
    sys: &S,
    s0: &Sample<N, M>,
    t: f64,
    contacts: Contacts,
) -> Result<(Sample<N, M>, Evaluation<N, M>, (SVector<f64, N>, SVector<f64, N>)), DynamicsError> {
    let dt = t - s0.t;
    // Three monomorphizations of the step: a flight's stages need `M` and `f` alone, and
    // frictionless held stages the normal forces alone, neither adding friction work; rubbing
    // stages keep the friction power at stages 2–4 (the first is `s0`'s) for its integral by the
    // step's own weights.
    // Held stages also keep λ at stages 2–4 for the contact impulse, by the same weights.
    let by_weights = |first: SVector<f64, M>, [_, a, b, c]: [SVector<f64, M>; 4]| (first + (a + b) * 2.0 + c) * (dt / 6.0);
    let mut lambdas = [SVector::<f64, M>::zeros(); 4];
    // The system's own absorbed power at stages 2–4, by the same weights, where it absorbs.
    let (mut absorbed, mut absorbing_stage) = ([Absorbed::zeros(); 4], 0);
    let mut absorb = |t, q: &SVector<f64, N>, v: &SVector<f64, N>, acc: &SVector<f64, N>| {
        if ABSORBS {
            absorbing_stage += 1;
            absorbed[absorbing_stage] = sys.absorbed_power(t, q, v, acc);
        }
    };
    let (step, work, impulse) = if contacts.held == 0 {
        let flight = |t, q: &SVector<f64, N>, v: &SVector<f64, N>| {
            let (mass, force) = sys.inertia_and_force(t, q, v);
            let acc = free_motion(&mass, &force, t)?.1;
            absorb(t, q, v, &acc);
            Ok(acc)
        };
        (rk4::step(flight, s0.t, &s0.q, &s0.v, &s0.acc, dt)?, s0.friction_work, s0.contact_impulse)
    } else if friction_of(sys).is_none() {
        let mut stage = 0;
        let held = |t, q: &SVector<f64, N>, v: &SVector<f64, N>| {
            let (acc, lambda) = acceleration(&sys.evaluate(t, q, v), t, contacts.held)?;
            absorb(t, q, v, &acc);
            stage += 1;
            lambdas[stage] = lambda;
            Ok(acc)
        };
        let step = rk4::step(held, s0.t, &s0.q, &s0.v, &s0.acc, dt)?;
        (step, s0.friction_work, s0.contact_impulse + by_weights(s0.lambda, lambdas))
    } else {
        let (mut powers, mut stage) = ([0.0; 4], 0);
        let rubbing = |t, q: &SVector<f64, N>, v: &SVector<f64, N>| {
            let m = motion(sys, &sys.evaluate(t, q, v), (t, q, v), contacts)?;
            absorb(t, q, v, &m.acc);
            stage += 1;
            powers[stage] = dissipated(&m.friction, &m.slip);
            lambdas[stage] = m.lambda;
            Ok(m.acc)
        };
        let step = rk4::step(rubbing, s0.t, &s0.q, &s0.v, &s0.acc, dt)?;
        let work = s0.friction_work + (s0.friction_power() + 2.0 * (powers[1] + powers[2]) + powers[3]) * (dt / 6.0);
        (step, work, s0.contact_impulse + by_weights(s0.lambda, lambdas))
    };
    let ev = sys.evaluate(t, &step.q, &step.v);
    let mut s = sample_of(sys, &ev, t, step.q, step.v, contacts)?;
    (s.friction_work, s.contact_impulse) = (work, impulse);
    s.absorbed_work = s0.absorbed_work;
    if ABSORBS {
        s.absorbed_work += (s0.absorbed_power + (absorbed[1] + absorbed[2]) * 2.0 + absorbed[3]) * (dt / 6.0);
    }
    Ok((s, ev, step.last_slopes))
}

/// The local error of the RK4 step `s0 → s1` on the gaps, m: the embedded third-order estimate
/// `(δq, δq̇)` mapped through `J`, the velocity part as the gap error it makes over the step.
/// With constraints held, only the error along their manifold counts: `stabilize` removes the
/// rest (a fully constrained motion has no error left at all).
pub(super) fn local_error<const N: usize, const M: usize>(
    s0: &Sample<N, M>,
    (s1, ev): (&Sample<N, M>, &Evaluation<N, M>),
    (v4, a4): (SVector<f64, N>, SVector<f64, N>),
    active: Set,
    lengths: &SVector<f64, N>,
) -> Result<f64, DynamicsError> {
    let (t, dt) = (s1.t, s1.t - s0.t);
    let (mut dq, mut dv) = ((v4 - s1.v) * (dt / 6.0), (a4 - s1.acc) * (dt / 6.0));
    let on_gaps = |dq: &SVector<f64, N>, dv: &SVector<f64, N>| (ev.gap_jacobian * dq).amax().max((ev.gap_jacobian * dv).amax() * dt);
    if active == 0 {
        return Ok(on_gaps(&dq, &dv));
    }
    let frame = Frame::new(ev).ok_or(DynamicsError::SingularMass { time: t })?;
    let dependent = || DynamicsError::DependentContacts { time: t, constraints: active };
    dq += frame.projection(&(ev.gap_jacobian * dq), active).ok_or_else(dependent)?.0;
    dv += frame.projection(&(ev.gap_jacobian * dv), active).ok_or_else(dependent)?.0;
    let along = lengths.component_mul(&dq).amax().max(lengths.component_mul(&dv).amax() * dt);
    Ok(on_gaps(&dq, &dv).max(along))
}
