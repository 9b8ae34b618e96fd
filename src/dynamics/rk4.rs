//! The classical fourth-order Runge–Kutta step for `q̈ = a(t, q, q̇)`, and the step of a sample with its contacts held and that step's local error estimate.

use super::complementarity::{Contacts, Frame, Set};
use super::implicit::on_path_totals;
use super::sample::{acceleration, dissipated, free_motion, motion, powers, sample, sample_of, Forces, Motion, Sample};
use super::system::friction_of;
use super::{DynamicsError, Evaluation, Powers, System};
use nalgebra::SVector;

/// One RK4 step of size `dt` from `(t0, q0, v0)`. `a0 = a(t0, q0, v0)` is passed in because the
/// previous step's end already computed it, so a step costs three new evaluations.
pub(crate) fn step<const N: usize, E>(
    mut accel: impl FnMut(f64, &SVector<f64, N>, &SVector<f64, N>) -> Result<SVector<f64, N>, E>,
    t0: f64,
    q0: &SVector<f64, N>,
    v0: &SVector<f64, N>,
    a0: &SVector<f64, N>,
    dt: f64,
) -> Result<Step<N>, E> {
    let half = 0.5 * dt;
    // Stage k: position slope v_k, velocity slope a_k.
    let v2 = v0 + a0 * half;
    let a2 = accel(t0 + half, &(q0 + v0 * half), &v2)?;
    let v3 = v0 + a2 * half;
    let a3 = accel(t0 + half, &(q0 + v2 * half), &v3)?;
    let v4 = v0 + a3 * dt;
    let a4 = accel(t0 + dt, &(q0 + v3 * dt), &v4)?;
    let sixth = dt / 6.0;
    let q1 = q0 + (v0 + (v2 + v3) * 2.0 + v4) * sixth;
    let v1 = v0 + (a0 + (a2 + a3) * 2.0 + a4) * sixth;
    Ok(Step { q: q1, v: v1, last_slopes: (v4, a4) })
}

/// The end of a step and its last stage's slopes `(q̇₄, q̈₄)`: with the slopes `(q̇, q̈)` at the
/// end they give the embedded third-order error estimate `dt/6 · (slope₄ − slope_end)` of the
/// step (the FSAL pair: RK4's weights with the end slope in place of the fourth stage's).
pub(crate) struct Step<const N: usize> {
    pub q: SVector<f64, N>,
    pub v: SVector<f64, N>,
    pub last_slopes: (SVector<f64, N>, SVector<f64, N>),
}

/// One RK4 step from `s0` to `t` with `contacts` held, and the end's evaluation.
pub(super) fn rk4_to<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    s0: &Sample<N, M>,
    t: f64,
    contacts: Contacts,
) -> Result<(Sample<N, M>, Evaluation<N, M>), DynamicsError> {
    let stepped = rk4_step(sys, s0, t, contacts, true)?;
    Ok((stepped.end, stepped.ev))
}

/// `rk4_to` for the step last taken from `s0`, cut at `t`: its stages take the terms that step
/// prepared (`System::begin_step` is not called), so that it integrates the same equations the
/// step's dense output came from, which the event search checked (terms prepared for the shorter
/// step can put a constraint through its surface where the dense output has it clear).
pub(super) fn rk4_cut<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    s0: &Sample<N, M>,
    t: f64,
    contacts: Contacts,
) -> Result<(Sample<N, M>, Evaluation<N, M>), DynamicsError> {
    let stepped = rk4_step(sys, s0, t, contacts, false)?;
    Ok((stepped.end, stepped.ev))
}

/// What `rk4_step` gives.
pub(super) struct Stepped<const N: usize, const M: usize> {
    /// The end and its evaluation.
    pub end: Sample<N, M>,
    pub ev: Evaluation<N, M>,
    /// The step's last slopes (for `local_error`).
    pub slopes: (SVector<f64, N>, SVector<f64, N>),
    /// The held contacts' forces at the third stage (zero in flight).
    pub middle: Forces<M>,
    /// The start as the stages see it where the system prepared terms for them with constraints
    /// held (none otherwise: the start is the caller's).
    pub start: Option<Sample<N, M>>,
    /// Whether the system prepared terms for this step (`System::begin_step`).
    pub prepared: bool,
}

/// `rk4_to`, with what `Stepped` adds; `prepare`: whether the step prepares its own terms
/// (`System::begin_step`), false for a step cut short (`rk4_cut`).
#[inline(always)]
pub(super) fn rk4_step<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    s0: &Sample<N, M>,
    t: f64,
    contacts: Contacts,
    prepare: bool,
) -> Result<Stepped<N, M>, DynamicsError> {
    let dt = t - s0.t;
    let prepared = prepare && sys.begin_step(s0.t, (&s0.q, &s0.v, &s0.acc), dt);
    // Terms prepared for this step: with a constraint held, the start is evaluated again with them,
    // so that the first stage, the event search's start and the dense output take the terms the
    // other stages take (a held force can be the small difference of two large ones, which the
    // terms of the step before can put on the other side of zero). In flight the first stage keeps
    // the step before's, an O(dt) difference like the other stages' linearisation.
    let refreshed = if prepared && contacts.held != 0 { Some(sample(sys, s0.t, s0.q, s0.v, contacts)?.after(s0)) } else { None };
    let s0 = refreshed.as_ref().unwrap_or(s0);
    // Three monomorphizations of the step: a flight's stages need `M` and `f` alone, and
    // frictionless held stages the normal forces alone, neither adding friction work; rubbing
    // stages keep the friction power at stages 2–4 (the first is `s0`'s) for its integral by the
    // step's own weights.
    // Held stages also keep λ at stages 2–4 for the contact impulse, by the same weights.
    let by_weights = |first: SVector<f64, M>, [_, a, b, c]: [SVector<f64, M>; 4]| (first + (a + b) * 2.0 + c) * (dt / 6.0);
    let mut lambdas = [SVector::<f64, M>::zeros(); 4];
    let mut middle = Forces::zeros();
    // The system's rates at stages 2–4, by the same weights, where it reports them (held with an
    // implicit force, on the step's path where its middle can be evaluated: `on_path_totals`).
    let (mut rates, mut rate_stage) = ([Powers::zeros(); 4], 0);
    let mut report = |t, q: &SVector<f64, N>, v: &SVector<f64, N>, m: &Motion<N, M>| {
        if S::POWERS {
            rate_stage += 1;
            rates[rate_stage] = powers(sys, (t, q, v), m);
        }
    };
    let (end, work, impulse) = if contacts.held == 0 {
        let flight = |t, q: &SVector<f64, N>, v: &SVector<f64, N>| {
            let (mass, force) = sys.inertia_and_force(t, q, v);
            let acc = free_motion(&mass, &force, t)?.1;
            if S::POWERS {
                report(t, q, v, &Motion::free(acc));
            }
            Ok(acc)
        };
        (step(flight, s0.t, &s0.q, &s0.v, &s0.acc, dt)?, s0.friction_work, s0.contact_impulse)
    } else if friction_of(sys).is_none() {
        let mut stage = 0;
        let held = |t, q: &SVector<f64, N>, v: &SVector<f64, N>| {
            let (acc, lambda) = acceleration(&sys.evaluate(t, q, v), t, contacts.held)?;
            if S::POWERS {
                report(t, q, v, &Motion { lambda, ..Motion::free(acc) });
            }
            stage += 1;
            lambdas[stage] = lambda;
            Ok(acc)
        };
        let end = step(held, s0.t, &s0.q, &s0.v, &s0.acc, dt)?;
        middle.lambda = lambdas[2];
        (end, s0.friction_work, s0.contact_impulse + by_weights(s0.lambda, lambdas))
    } else {
        let (mut powers, mut stage) = ([0.0; 4], 0);
        let rubbing = |t, q: &SVector<f64, N>, v: &SVector<f64, N>| {
            let m = motion(sys, &sys.evaluate(t, q, v), (t, q, v), contacts)?;
            report(t, q, v, &m);
            stage += 1;
            powers[stage] = dissipated(&m.friction, &m.slip);
            lambdas[stage] = m.lambda;
            if stage == 2 {
                middle = Forces { lambda: m.lambda, friction: m.friction, slip: m.slip };
            }
            Ok(m.acc)
        };
        let end = step(rubbing, s0.t, &s0.q, &s0.v, &s0.acc, dt)?;
        let work = s0.friction_work + (s0.friction_power() + 2.0 * (powers[1] + powers[2]) + powers[3]) * (dt / 6.0);
        (end, work, s0.contact_impulse + by_weights(s0.lambda, lambdas))
    };
    let ev = sys.evaluate(t, &end.q, &end.v);
    let mut s = sample_of(sys, &ev, t, end.q, end.v, contacts)?;
    (s.friction_work, s.contact_impulse) = (work, impulse);
    s.energies = s0.energies;
    if S::POWERS {
        s.energies += (s0.powers + (rates[1] + rates[2]) * 2.0 + rates[3]) * (dt / 6.0);
    }
    on_path_totals(sys, s0, &mut s, &ev, contacts);
    Ok(Stepped { end: s, ev, slopes: end.last_slopes, middle, start: refreshed, prepared })
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
