//! What happens at an event: the contact set decided and the state put on it (A&K Fig. 1 at a
//! discontinuity point), and the drift of held contacts removed between events.

use super::contact::{contains, members, select, solve_on, ties, Frame, Set};
use super::friction::{Choice, Contacts, Mode, Tangential};
use super::inertia::Inertia;
use super::sample::{frame_at, friction_of, rk4_to, sample, sample_of, Sample};
use super::{impact, Absorbed, DynamicsError, Evaluation, Event, EventKind, Stepper, System};
use nalgebra::SVector;

/// Zeno guard: after an impact a closed constraint whose free flight would rise no higher than
/// `ZENO_APEX_FACTOR · ε_h` (apex `ḣ⁺² / (2|ḧ|)` with `ḧ < 0` the gap acceleration under the
/// current contact forces) is put into persistent contact instead of flying. Such a flight is
/// below what event location resolves, and with `e < 1` the bounces before it decay
/// geometrically, so an accumulation of impacts always ends in sliding after a bounded number of
/// events. The time given up is at most `2 ḣ⁺ / (|ḧ| (1 − e))` (≈ 6e-5 s for a ball under
/// gravity with e = 0.5 and the default ε_h).
pub const ZENO_APEX_FACTOR: f64 = 1e3;

/// Drift of a held constraint (as a fraction of ε_h on `h`, of ε_ḣ on `ḣ`) that `stabilize`
/// tolerates before it projects the state back onto the contact manifold.
const DRIFT_FRACTION: f64 = 0.1;

/// Newton steps `onto_contacts` takes at most (quadratic convergence: two or three reach round-off).
const MAX_PROJECTIONS: usize = 4;

/// How far ahead, in nominal steps, the sliding law looks to decide a tie (`Stepper::sliding_law`):
/// far enough that the trend outweighs round-off, near enough that it is the trend at the instant.
const TIE_PROBE: f64 = 1e-4;

/// What an impact does: the normal and tangential impulses, the velocity and `ḣ` after, and the
/// energy each constraint's impulses dissipate.
struct Jump<const N: usize, const M: usize> {
    normal: SVector<f64, M>,
    tangent: SVector<f64, M>,
    v: SVector<f64, N>,
    hd: SVector<f64, M>,
    lost: SVector<f64, M>,
    /// The part of `lost` the tangential impulses dissipate.
    friction_lost: SVector<f64, M>,
}

impl<S: System<N, M>, const N: usize, const M: usize> Stepper<S, N, M> {
    /// Keeps active constraints on the manifold against RK4 drift: once `h_A` or `ḣ_A` has drifted
    /// beyond `DRIFT_FRACTION` of its tolerance, one M-metric Newton projection of `q` onto
    /// `h_A = 0` and of `q̇` onto `ḣ_A = 0`. The drift is O(dt⁵) per step, so the order of the
    /// method is kept, and most steps need no projection (nor the evaluation it costs). `ev`: the
    /// evaluation at the state, if at hand; returns the one at the state afterwards, likewise.
    pub(super) fn stabilize(&mut self, ev: Option<Evaluation<N, M>>) -> Result<Option<Evaluation<N, M>>, DynamicsError> {
        let (s, active) = (&self.state, self.contacts.held);
        let (gap_tol, rate_tol) = (DRIFT_FRACTION * self.options.gap_tolerance, DRIFT_FRACTION * self.options.velocity_tolerance);
        if members::<M>(active).all(|i| s.gap[i].abs() <= gap_tol && s.hd[i].abs() <= rate_tol) {
            return Ok(ev);
        }
        let (t, v) = (s.t, s.v);
        let (q, ev, frame) = self.onto_contacts(t, s.q, &v, active, frame_at(&self.system, t, &s.q, &v, ev)?)?;
        let hd = ev.gap_jacobian * v + ev.gap_time_rate;
        let dependent = DynamicsError::DependentContacts { time: t, constraints: active };
        let (before, v) = (v, v + frame.projection(&hd, active).ok_or(dependent)?.0);
        let ev = self.system.evaluate(t, &q, &v);
        let absorbed = self.absorbed_by_jump(t, &q, &before, &v);
        self.state = sample_of(&self.system, &ev, t, q, v, self.contacts)?.after(&self.state);
        self.state.absorbed_work += absorbed;
        Ok(Some(ev))
    }

    /// The work the system's own forces take from the jump `before → after` at `(t, q)`, J.
    fn absorbed_by_jump(&self, t: f64, q: &SVector<f64, N>, before: &SVector<f64, N>, after: &SVector<f64, N>) -> Absorbed {
        if self.system.absorbs() {
            self.system.absorbed_by_jump(t, q, before, after)
        } else {
            Absorbed::zeros()
        }
    }

    /// `q` moved onto `h_S = 0` by Newton steps in the metric of `M` until every gap of `set` is
    /// within `DRIFT_FRACTION · ε_h` (each step leaves about the square of the last residual: a
    /// drift of microns after a long step held in contact needs two), with the evaluation and
    /// frame there. The velocity is left to the caller, to be projected with these gradients:
    /// those at the drifted configuration leave `ḣ` off by the change of `J` times `q̇`.
    fn onto_contacts(
        &self,
        t: f64,
        mut q: SVector<f64, N>,
        v: &SVector<f64, N>,
        set: Set,
        (mut ev, mut frame): (Evaluation<N, M>, Frame<N, M>),
    ) -> Result<(SVector<f64, N>, Evaluation<N, M>, Frame<N, M>), DynamicsError> {
        let tol = DRIFT_FRACTION * self.options.gap_tolerance;
        for _ in 0..MAX_PROJECTIONS {
            if members::<M>(set).all(|i| ev.gap[i].abs() <= tol) {
                break;
            }
            q += frame.projection(&ev.gap, set).ok_or(DynamicsError::DependentContacts { time: t, constraints: set })?.0;
            (ev, frame) = frame_at(&self.system, t, &q, v, None)?;
        }
        Ok((q, ev, frame))
    }

    /// Records one event per constraint of `set` at the current configuration; the first carries
    /// the normal and tangential `impulses` (see `Event::impulses`).
    fn record(
        &mut self,
        (kind, v): (EventKind, &SVector<f64, N>),
        set: Set,
        (hd, hd_after): (&SVector<f64, M>, &SVector<f64, M>),
        (lost, friction_lost): (&SVector<f64, M>, &SVector<f64, M>),
        impulses: (SVector<f64, M>, SVector<f64, M>),
    ) {
        let (time, q, mut carried) = (self.state.t, self.state.q, impulses);
        for i in members::<M>(set) {
            let (impulses, friction_impulses) = carried;
            let (velocity_before, velocity_after) = (hd[i], hd_after[i]);
            let (energy_lost, friction_energy) = (lost[i], friction_lost[i]);
            let event = Event {
                time,
                kind,
                constraint: i,
                velocity_before,
                velocity_after,
                energy_lost,
                friction_energy,
                q,
                v: *v,
                impulses,
                friction_impulses,
            };
            self.events.push(event);
            carried = (SVector::zeros(), SVector::zeros());
        }
    }

    /// The sliding law over `candidates` at `(t, q, q̇)`, with the tie rule: a candidate this
    /// instant leaves undecided (zero force and zero gap acceleration together, as where a
    /// contact opens, or where two corners trade places as the piston starts to pivot) takes the
    /// law's answer `TIE_PROBE` nominal steps later along the motion with this instant's support
    /// held. Every support consistent with the ties gives the same acceleration now, so the
    /// motions differ at second order and any of them shows the first-order trend that decides.
    /// A tie that persists there opens (the law's smallest support). Returns the contacts and q̈.
    fn sliding_law(
        &self,
        (t, q, v): (f64, &SVector<f64, N>, &SVector<f64, N>),
        ev: &Evaluation<N, M>,
        frame: &Frame<N, M>,
        candidates: Set,
    ) -> Result<(Contacts, SVector<f64, N>), DynamicsError> {
        if let Some(mu) = friction_of(&self.system) {
            return self.coulomb_law((t, q, v), ev, mu, candidates);
        }
        let eps = self.options.multiplier_tolerance;
        let unresolved = |time| DynamicsError::ContactUnresolved { time, constraints: candidates };
        let now = frame.sliding(ev, candidates, eps).ok_or(unresolved(t))?;
        let acc = |lambda: SVector<f64, M>| frame.free_acc + frame.minv_jt * lambda;
        if now.ties == 0 {
            return Ok((Contacts::frictionless(now.support), acc(now.lambda)));
        }
        let start = sample_of(&self.system, ev, t, *q, *v, Contacts::frictionless(now.support))?;
        let (_, ev_ahead) = rk4_to(&self.system, &start, t + TIE_PROBE * self.options.step, Contacts::frictionless(now.support))?;
        let frame_ahead = Frame::new(&ev_ahead).ok_or(DynamicsError::SingularMass { time: t })?;
        let ahead = frame_ahead.sliding(&ev_ahead, candidates, eps).ok_or(unresolved(t))?;
        if ahead.support == now.support {
            return Ok((Contacts::frictionless(now.support), acc(now.lambda)));
        }
        let free = Frame::gap_acceleration(ev, &frame.free_acc);
        let lambda =
            solve_on(&frame.w, &-free, ahead.support).ok_or(DynamicsError::DependentContacts { time: t, constraints: ahead.support })?;
        Ok((Contacts::frictionless(ahead.support), acc(lambda.map(|x| x.max(0.0)))))
    }

    /// The sliding law with Coulomb friction (`friction.rs`): the modes of the candidates by
    /// enumeration, a candidate slipping faster than ε_ḣ keeping its direction, one slower
    /// sticking or starting to slip as its tangential row decides; ties in the normal direction
    /// by the same rule as without friction.
    fn coulomb_law(
        &self,
        (t, q, v): (f64, &SVector<f64, N>, &SVector<f64, N>),
        ev: &Evaluation<N, M>,
        mu: SVector<f64, M>,
        candidates: Set,
    ) -> Result<(Contacts, SVector<f64, N>), DynamicsError> {
        let at = |t: f64, q: &SVector<f64, N>, v: &SVector<f64, N>, ev: &Evaluation<N, M>| {
            let tangents = self.system.tangents(t, q, v);
            let inertia = Inertia::new(&ev.mass).ok_or(DynamicsError::SingularMass { time: t })?;
            let free = inertia.solve(&ev.force);
            let b = (Frame::gap_acceleration(ev, &free), tangents.jacobian * free + tangents.bias);
            let scale = members::<M>(candidates).fold(0.0_f64, |s, i| {
                s.max((ev.gap_jacobian.row(i) * free)[0].abs() + ev.gap_bias[i].abs())
                    .max((tangents.jacobian.row(i) * free)[0].abs() + tangents.bias[i].abs())
            });
            Ok::<_, DynamicsError>((Tangential::new(ev, &tangents, &inertia, mu), free, b, scale, tangents.slip(v)))
        };
        let unresolved = DynamicsError::ContactUnresolved { time: t, constraints: candidates };
        let (frame, free, b, scale, slip) = at(t, q, v, ev)?;
        let choices = std::array::from_fn(|i| match (contains(candidates, i), slip[i]) {
            (false, _) => Choice::Open,
            (true, g) if g.abs() <= self.options.velocity_tolerance => Choice::AtRest,
            (true, g) => Choice::Slipping(g.signum()),
        });
        let (modes, now) = frame.enumerate(&choices, (&b.0, &b.1), scale).ok_or(unresolved.clone())?;
        let contacts = Contacts::of(&modes);
        let w = Frame::new(ev).ok_or(DynamicsError::SingularMass { time: t })?.w;
        let tied = ties(&w, (&now.normal, &now.y_normal), (candidates, contacts.held), scale, self.options.multiplier_tolerance);
        if tied == 0 {
            return Ok((contacts, frame.motion(&free, &now)));
        }
        let start = sample_of(&self.system, ev, t, *q, *v, contacts)?;
        let (s, ev_ahead) = rk4_to(&self.system, &start, t + TIE_PROBE * self.options.step, contacts)?;
        let (frame_ahead, _, b_ahead, scale_ahead, _) = at(s.t, &s.q, &s.v, &ev_ahead)?;
        let (ahead, _) = frame_ahead.enumerate(&choices, (&b_ahead.0, &b_ahead.1), scale_ahead).ok_or(unresolved)?;
        if Contacts::of(&ahead).held == contacts.held {
            return Ok((contacts, frame.motion(&free, &now)));
        }
        let dependent = DynamicsError::DependentContacts { time: t, constraints: Contacts::of(&ahead).held };
        let mut then = frame.solve(&ahead, (&b.0, &b.1)).ok_or(dependent)?;
        then.normal = then.normal.map(|x| x.max(0.0));
        for i in 0..M {
            if let Mode::Slip(s) = ahead[i] {
                then.tangent[i] = -mu[i] * s * then.normal[i];
            }
        }
        Ok((Contacts::of(&ahead), frame.motion(&free, &then)))
    }

    /// The impact over `closed`: the generalized Newton law, or with friction the Newton–Coulomb
    /// law (`friction.rs`).
    fn impact(
        &self,
        (t, q, v): (f64, &SVector<f64, N>, &SVector<f64, N>),
        ev: &Evaluation<N, M>,
        frame: &Frame<N, M>,
        closed: Set,
    ) -> Result<Jump<N, M>, DynamicsError> {
        let refused = DynamicsError::MultipleImpact { time: t, constraints: closed };
        let e = SVector::<f64, M>::from_fn(|i, _| self.system.restitution(i));
        let hd = ev.gap_jacobian * v + ev.gap_time_rate;
        let Some(mu) = friction_of(&self.system) else {
            let impulse = impact::newton_impulses(frame, &hd, &e, closed).ok_or(refused)?;
            let hd_plus = hd + frame.w * impulse;
            let lost = impact::energy_lost(&impulse, &hd, &hd_plus);
            return Ok(Jump {
                normal: impulse,
                tangent: SVector::zeros(),
                v: v + frame.minv_jt * impulse,
                hd: hd_plus,
                lost,
                friction_lost: SVector::zeros(),
            });
        };
        let tangents = self.system.tangents(t, q, v);
        let inertia = Inertia::new(&ev.mass).ok_or(DynamicsError::SingularMass { time: t })?;
        let coulomb = Tangential::new(ev, &tangents, &inertia, mu);
        let slip = tangents.slip(v);
        // ξ = γ⁺ + ε γ⁻ in both directions, ε = e for an approaching constraint, 0 for another
        // closed one (as without friction).
        let eps = SVector::<f64, M>::from_fn(|i, _| if hd[i] < 0.0 { e[i] } else { 0.0 });
        let b = (hd + eps.component_mul(&hd), slip + eps.component_mul(&slip));
        let choices = std::array::from_fn(|i| if contains(closed, i) { Choice::AtRest } else { Choice::Open });
        let scale = members::<M>(closed).fold(0.0_f64, |s, i| s.max(hd[i].abs()).max(slip[i].abs()));
        let (_, jump) = coulomb.enumerate(&choices, (&b.0, &b.1), scale).ok_or(refused)?;
        let v_plus = coulomb.motion(v, &jump);
        let hd_plus = ev.gap_jacobian * v_plus + ev.gap_time_rate;
        let lost = impact::energy_lost(&jump.normal, &hd, &hd_plus) + impact::energy_lost(&jump.tangent, &slip, &tangents.slip(&v_plus));
        // Friction's share: −Λ_T ξ_T / (1 + ε) = μ Λ_N |ξ_T| / (1 + ε) ≥ 0, the term the Coulomb
        // law contributes to ΔT (friction.rs); the work of Λ_T on the mean slip, −Λ_T (γ⁻ + γ⁺)/2,
        // can be negative where the impulses couple the normal and tangential motion.
        let xi = tangents.slip(&v_plus) + eps.component_mul(&slip);
        let friction_lost = SVector::<f64, M>::from_fn(|i, _| -jump.tangent[i] * xi[i] / (1.0 + eps[i]));
        Ok(Jump { normal: jump.normal, tangent: jump.tangent, v: v_plus, hd: hd_plus, lost, friction_lost })
    }

    /// Resolves the closed constraints at the current instant (Fig. 1 at a discontinuity point):
    /// 1. if any approaches (`ḣ < −ε_ḣ`), the generalized Newton impact over all of `closed`
    ///    (with friction, Newton–Coulomb);
    /// 2. persistent contact for those now at rest (`|ḣ| < ε_ḣ`, or caught by the Zeno guard)
    ///    as the sliding complementarity problem over all of them decides (`sliding_law`): one
    ///    whose multiplier just crossed zero is not released on its own word, since the others'
    ///    forces change with it; one still approaching (−ε_ḣ ≤ ḣ < 0) that sliding refuses gets
    ///    the impact of 1. after all; with friction the same problem decides who sticks and who
    ///    slips which way;
    /// 3. projection of `q` and `q̇` onto the new active set, which becomes the held set.
    ///
    /// Constraints in `hold` (a flight the motion ends below the event resolution) stay in contact
    /// whatever the sliding law says, their `ḣ` put to zero, unless an impact sent them off.
    /// `known`: the system's evaluation at the current state, if the caller has it.
    pub(super) fn settle(&mut self, closed: Set, hold: Set, known: Option<Evaluation<N, M>>) -> Result<(), DynamicsError> {
        self.event_ahead = None;
        let Sample { t, q, mut v, .. } = self.state;
        let before = self.contacts;
        let was_active = before.held;
        let opts = self.options.clone();
        let (mut ev, mut frame) = frame_at(&self.system, t, &q, &v, known)?;
        let mut hd = ev.gap_jacobian * v + ev.gap_time_rate;

        let mut approaching = closed & select::<M>(|i| hd[i] < -opts.velocity_tolerance);
        let mut absorbed = Absorbed::zeros();
        let mut impacted: Set = 0;
        let zeno_apex = ZENO_APEX_FACTOR * opts.gap_tolerance;
        let contacts = loop {
            if approaching != 0 {
                let jump = self.impact((t, &q, &v), &ev, &frame, closed)?;
                // Recorded: the approaching constraints. Another closed one that takes an impulse
                // (held, at rest, or moving off the liner) is pushed, not struck: its share of the
                // losses, −Λᵢ (ḣ⁻ᵢ + ḣ⁺ᵢ)/2 ≤ 0 as it leaves faster, goes with its friction share to
                // the first recorded event, so that the record's losses add up and each is ≥ 0.
                let recorded = approaching;
                let (mut lost, mut friction_lost) = (jump.lost, jump.friction_lost);
                let (first, unrecorded) = (recorded.trailing_zeros() as usize, closed & !recorded);
                // (A held one's normal share is round-off of ḣ = 0, left out without friction.)
                let moved = if jump.friction_lost == SVector::<f64, M>::zeros() { unrecorded & !was_active } else { unrecorded };
                for i in members::<M>(moved) {
                    (lost[first], friction_lost[first]) = (lost[first] + lost[i], friction_lost[first] + friction_lost[i]);
                }
                self.record((EventKind::Impact, &v), recorded, (&hd, &jump.hd), (&lost, &friction_lost), (jump.normal, jump.tangent));
                absorbed += self.absorbed_by_jump(t, &q, &v, &jump.v);
                (v, hd) = (jump.v, jump.hd);
                (ev, frame) = frame_at(&self.system, t, &q, &v, None)?;
                impacted |= approaching;
            }

            let mut candidates = closed & ((hold & !impacted) | select::<M>(|i| hd[i] < opts.velocity_tolerance));
            let contacts = loop {
                let (contacts, acc) = self.sliding_law((t, &q, &v), &ev, &frame, candidates)?;
                // A held one the law would open slips the way it moves along the surface.
                let forced = hold & candidates & !contacts.held;
                let backward = if forced != 0 && friction_of(&self.system).is_some() {
                    let slip = self.system.tangents(t, &q, &v).slip(&v);
                    forced & select::<M>(|i| slip[i] < 0.0)
                } else {
                    0
                };
                let contacts = Contacts { held: contacts.held | forced, back: contacts.back | backward, ..contacts };
                let hdd = Frame::gap_acceleration(&ev, &acc);
                let zeno = closed & !candidates & select::<M>(|i| hd[i] > 0.0 && hdd[i] < 0.0 && hd[i] * hd[i] < -2.0 * zeno_apex * hdd[i]);
                if zeno == 0 {
                    break contacts;
                }
                candidates |= zeno;
            };
            // An approach slower than ε_ḣ that sliding refuses (its force would pull) still needs
            // the impact law, or the gap closes at the next instant with nothing to resolve it.
            // A constraint leaving persistent contact has ḣ = 0 up to round-off: no impact.
            let grazing = closed & !contacts.held & !impacted & !was_active & select::<M>(|i| hd[i] < 0.0);
            if grazing == 0 {
                break contacts;
            }
            approaching = grazing;
        };
        let support = contacts.held;

        // The new contacts are put on the manifold, and with them any closed constraint that
        // opens a hair below zero (the drift of a step held in contact, or of a projection onto
        // its neighbours), so that it leaves from h = 0, not from an apparent penetration; where
        // that set is dependent, the contacts alone.
        let below = closed & !support & select::<M>(|i| ev.gap[i] < -opts.gap_tolerance);
        let onto = if members::<M>(support | below).count() <= N { support | below } else { support };
        let state = if onto == 0 {
            // Nothing held or moved: q and q̇ are those `ev` was made at (after any impact).
            sample_of(&self.system, &ev, t, q, v, contacts)?
        } else {
            let (q, ev, frame) = self.onto_contacts(t, q, &v, onto, (ev, frame))?;
            let hd = ev.gap_jacobian * v + ev.gap_time_rate;
            let (dv, impulse) = frame.projection(&hd, support).ok_or(DynamicsError::DependentContacts { time: t, constraints: support })?;
            let hd_after = hd + frame.w * impulse;
            let lost = impact::energy_lost(&impulse, &hd, &hd_after);
            self.record(
                (EventKind::Slide, &v),
                support & !was_active,
                (&hd, &hd_after),
                (&lost, &SVector::zeros()),
                (impulse, SVector::zeros()),
            );
            absorbed += self.absorbed_by_jump(t, &q, &v, &(v + dv));
            sample(&self.system, t, q, v + dv, contacts)?
        };
        let none = SVector::zeros();
        self.record((EventKind::Release, &v), was_active & !support, (&hd, &hd), (&none, &none), (none, none));
        // With friction: constraints held before and after that came to stick, or started to slip.
        let kept = was_active & support;
        let (stuck, slipping) =
            (kept & contacts.stick & !before.stick, kept & !contacts.stick & (before.stick | (before.back ^ contacts.back)));
        self.record((EventKind::Stick, &v), stuck, (&hd, &hd), (&none, &none), (none, none));
        self.record((EventKind::Slip, &v), slipping, (&hd, &hd), (&none, &none), (none, none));
        self.contacts = contacts;
        self.state = state.after(&self.state);
        self.state.absorbed_work += absorbed;
        Ok(())
    }
}
