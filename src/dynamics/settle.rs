//! What happens at an event: the contact set decided by the laws of `contact_laws.rs` and the
//! state put on it, with the events recorded (A&K Fig. 1 at a discontinuity point); and the drift
//! of held contacts removed between events.

use super::complementarity::{members, select, Contacts, Frame, Set};
use super::contact_laws::{energy_lost, impact, stick_jump, Jump, Tolerances};
use super::implicit::for_impact;
use super::sample::{frame_at, sample, sample_of, Sample};
use super::system::friction_of;
use super::{DynamicsError, Evaluation, Event, EventKind, Powers, Stepper, System, Terms};
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

/// Impacts at one instant, each turning back a constraint the last one's impulses pushed onto its
/// surface, beyond which the accumulation counts as unresolved (`DynamicsError::EventBudget`).
const IMPACT_ROUNDS: usize = 1000;

impl<S: System<N, M>, const N: usize, const M: usize> Stepper<S, N, M> {
    /// Keeps active constraints on the manifold against RK4 drift: once `h_A` or `ḣ_A` has drifted
    /// beyond `DRIFT_FRACTION` of its tolerance, one M-metric Newton projection of `q` onto
    /// `h_A = 0` and of `q̇` onto `ḣ_A = 0`. The drift is O(dt⁵) per step, so the order of the
    /// method is kept, and most steps need no projection (nor the evaluation it costs). `ev`: the
    /// evaluation at the state, if at hand; returns the one at the state afterwards, likewise.
    pub(super) fn stabilize(&mut self, ev: Option<Evaluation<N, M>>) -> Result<Option<Evaluation<N, M>>, DynamicsError> {
        if !self.drifted(&self.state) {
            return Ok(ev);
        }
        let (q, v) = self.onto_held(&self.state, ev)?;
        let t = self.state.t;
        let ev = self.system.evaluate(t, &q, &v);
        let booked = self.booked_jump(&ev, (t, &q), &self.state.v, &v);
        self.state = sample_of(&self.system, &ev, t, q, v, self.contacts)?.after(&self.state);
        self.state.energies += booked;
        Ok(Some(ev))
    }

    /// Whether a held constraint of `s` has drifted beyond `DRIFT_FRACTION` of its tolerances.
    pub(super) fn drifted(&self, s: &Sample<N, M>) -> bool {
        self.drifted_at(&s.gap, &s.hd)
    }

    /// Whether a held constraint with gaps `gap` and rates `hd` has drifted (see `drifted`).
    pub(super) fn drifted_at(&self, gap: &SVector<f64, M>, hd: &SVector<f64, M>) -> bool {
        let (gap_tol, rate_tol) = (DRIFT_FRACTION * self.options.gap_tolerance, DRIFT_FRACTION * self.options.velocity_tolerance);
        !members::<M>(self.contacts.held).all(|i| gap[i].abs() <= gap_tol && hd[i].abs() <= rate_tol)
    }

    /// `(q, q̇)` of `s` projected onto the held set's manifold, `h_A = 0` and `ḣ_A = 0`. `ev`: the
    /// evaluation at `s`, if at hand.
    #[allow(clippy::type_complexity)]
    pub(super) fn onto_held(
        &self,
        s: &Sample<N, M>,
        ev: Option<Evaluation<N, M>>,
    ) -> Result<(SVector<f64, N>, SVector<f64, N>), DynamicsError> {
        self.onto_held_at((s.t, &s.q, &s.v), ev)
    }

    /// `(q, q̇)` at `t` projected onto the held set's manifold (see `onto_held`). `ev` may be the
    /// configuration's terms alone (`System::evaluate_terms`, `Terms::Configuration`): the projection reads no more,
    /// and evaluates no more at the configurations it moves through.
    #[allow(clippy::type_complexity)]
    pub(super) fn onto_held_at(
        &self,
        (t, q, v): (f64, &SVector<f64, N>, &SVector<f64, N>),
        ev: Option<Evaluation<N, M>>,
    ) -> Result<(SVector<f64, N>, SVector<f64, N>), DynamicsError> {
        let (mut q, v, active) = (*q, *v, self.contacts.held);
        let mut ev = ev.unwrap_or_else(|| self.system.evaluate_terms(t, &q, &v, Terms::Configuration));
        let mut frame = Frame::new(&ev).ok_or(DynamicsError::SingularMass { time: t })?;
        let configuration = |q: &SVector<f64, N>| self.system.evaluate_terms(t, q, &v, Terms::Configuration);
        self.onto_contacts(t, &mut q, active, configuration, (&mut ev, &mut frame))?;
        let hd = ev.gap_jacobian * v + ev.gap_time_rate;
        let dependent = DynamicsError::DependentContacts { time: t, constraints: active };
        let jump = self.held_jump((&ev, &frame), t, &hd, active)?;
        Ok((q, v + jump.ok_or(dependent)?.0))
    }

    /// `q` moved onto `h_S = 0` by Newton steps in the metric of `M` until every gap of `set` is
    /// within `DRIFT_FRACTION · ε_h` (each step leaves about the square of the last residual: a
    /// drift of microns after a long step held in contact needs two), with the evaluation
    /// (`evaluate` at the configuration) and frame there. The velocity is left to the caller, to be
    /// projected with these gradients: those at the drifted configuration leave `ḣ` off by the
    /// change of `J` times `q̇`.
    ///
    /// In place (`q` and the evaluation and frame at it): they are large, and a projection at a
    /// communication point moves no copies of them.
    fn onto_contacts(
        &self,
        t: f64,
        q: &mut SVector<f64, N>,
        set: Set,
        evaluate: impl Fn(&SVector<f64, N>) -> Evaluation<N, M>,
        (ev, frame): (&mut Evaluation<N, M>, &mut Frame<N, M>),
    ) -> Result<(), DynamicsError> {
        let tol = DRIFT_FRACTION * self.options.gap_tolerance;
        for _ in 0..MAX_PROJECTIONS {
            if members::<M>(set).all(|i| ev.gap[i].abs() <= tol) {
                break;
            }
            *q += frame.projection(&ev.gap, set).ok_or(DynamicsError::DependentContacts { time: t, constraints: set })?.0;
            *ev = evaluate(q);
            *frame = Frame::new(ev).ok_or(DynamicsError::SingularMass { time: t })?;
        }
        Ok(())
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

    /// Resolves the closed constraints at the current instant (Fig. 1 at a discontinuity point):
    /// 1. if any approaches (`ḣ < −ε_ḣ`), the generalized Newton impact over all of `closed`
    ///    (with friction, Newton–Coulomb), again while it leaves one approaching;
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
        let tol = Tolerances { velocity: opts.velocity_tolerance, multiplier: opts.multiplier_tolerance };
        let (mut ev, mut frame) = frame_at(&self.system, t, &q, &v, known)?;
        let mut hd = ev.gap_jacobian * v + ev.gap_time_rate;

        let mut approaching = closed & select::<M>(|i| hd[i] < -opts.velocity_tolerance);
        let mut booked = Powers::zeros();
        let mut impacted: Set = 0;
        let zeno_apex = ZENO_APEX_FACTOR * opts.gap_tolerance;
        let contacts = loop {
            let mut rounds = 0;
            while approaching != 0 {
                // The impact law over every closed constraint, with one `e`, so that it dissipates
                // (`newton_impulses`): one leaving its surface may return at up to e times its
                // speed, and strikes it in the next round.
                let bare = for_impact(&ev, t)?;
                let (impact_ev, impact_frame) = bare.as_ref().map_or((&ev, &frame), |(ev, frame)| (ev, frame));
                let jump = impact(&self.system, (t, &q, &v), impact_ev, impact_frame, closed)?;
                // Recorded: the approaching constraints. Another closed one that takes an impulse
                // (held, at rest, or leaving) is pushed, not struck: its share of the losses goes with its
                // friction share to the first recorded event, so that the record's losses add up.
                let recorded = approaching;
                let (mut lost, mut friction_lost) = (jump.lost, jump.friction_lost);
                let (first, unrecorded) = (recorded.trailing_zeros() as usize, closed & !recorded);
                // (A held one's normal share is round-off of ḣ = 0, left out without friction.)
                let moved = if jump.friction_lost == SVector::<f64, M>::zeros() { unrecorded & !was_active } else { unrecorded };
                for i in members::<M>(moved) {
                    (lost[first], friction_lost[first]) = (lost[first] + lost[i], friction_lost[first] + friction_lost[i]);
                }
                self.record((EventKind::Impact, &v), recorded, (&hd, &jump.hd), (&lost, &friction_lost), (jump.normal, jump.tangent));
                (v, hd) = (jump.v, jump.hd);
                (ev, frame) = frame_at(&self.system, t, &q, &v, None)?;
                impacted |= approaching;
                // Turned back: approaching now, not before. One still approaching that was struck
                // is what the law accepts within its tolerance; persistent contact takes it.
                approaching = closed & !approaching & select::<M>(|i| hd[i] < -opts.velocity_tolerance);
                rounds += 1;
                if rounds > IMPACT_ROUNDS {
                    return Err(DynamicsError::EventBudget { time: t, events: IMPACT_ROUNDS });
                }
            }

            let mut candidates = closed & ((hold & !impacted) | select::<M>(|i| hd[i] < opts.velocity_tolerance));
            let contacts = loop {
                let (contacts, acc) = self.persistent_law(tol, (t, &q, &v), (&ev, &frame), candidates)?;
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
        let mut stick_losses = (SVector::zeros(), SVector::zeros());
        let state = if onto == 0 {
            // Nothing held or moved: q and q̇ are those `ev` was made at (after any impact).
            sample_of(&self.system, &ev, t, q, v, contacts)?
        } else {
            let (mut q, mut ev, mut frame) = (q, ev, frame);
            self.onto_contacts(t, &mut q, onto, |q| self.system.evaluate(t, q, &v), (&mut ev, &mut frame))?;
            let hd = ev.gap_jacobian * v + ev.gap_time_rate;
            let through = self.jump_through(contacts, t, (ev, frame))?;
            let jump = match stick_jump(&self.system, tol, (t, &q, &v), &through.ev, contacts) {
                Some(jump) => jump,
                None => {
                    let (dv, normal) =
                        through.frame.projection(&hd, support).ok_or(DynamicsError::DependentContacts { time: t, constraints: support })?;
                    let hd_after = hd + through.frame.w * normal;
                    let lost = energy_lost(&normal, &hd, &hd_after);
                    Jump { normal, tangent: SVector::zeros(), v: v + dv, hd: hd_after, lost, friction_lost: SVector::zeros() }
                }
            };
            let losses = (&jump.lost, &jump.friction_lost);
            self.record((EventKind::Slide, &v), support & !was_active, (&hd, &jump.hd), losses, (jump.normal, jump.tangent));
            stick_losses = (jump.lost, jump.friction_lost);
            booked += self.jump_books(&through, (t, &q), &v, &jump.v);
            sample(&self.system, t, q, jump.v, contacts)?
        };
        let none = SVector::zeros();
        self.record((EventKind::Release, &v), was_active & !support, (&hd, &hd), (&none, &none), (none, none));
        // With friction: constraints held before and after that came to stick, or started to slip.
        let kept = was_active & support;
        let (stuck, slipping) =
            (kept & contacts.stick & !before.stick, kept & !contacts.stick & (before.stick | (before.back ^ contacts.back)));
        // Those that came to stick carry what stopping their slip dissipated (`stick_jump`).
        self.record((EventKind::Stick, &v), stuck, (&hd, &hd), (&stick_losses.0, &stick_losses.1), (none, none));
        self.record((EventKind::Slip, &v), slipping, (&hd, &hd), (&none, &none), (none, none));
        self.contacts = contacts;
        self.state = state.after(&self.state);
        self.state.energies += booked;
        Ok(())
    }
}
