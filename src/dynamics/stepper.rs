//! The event-driven integrator (A&K section 5, Fig. 1): RK4 with the contact set held between
//! events; at each event the impact law and the sliding law decide the new contact set
//! (`settle`), found by the event search (`search`).

use super::complementarity::{bit, contains, select, Contacts};
use super::hermite::Hermite5;
use super::options::{MAX_STEPS_PER_ADVANCE, PENETRATION_FACTOR, TOO_MANY_STEPS};
use super::rk4::{local_error, rk4_cut, rk4_step, rk4_to, Stepped};
use super::sample::{motion, powers, sample, sample_of, sample_rated, Evaluated, Forces, Sample};
use super::{
    DynamicsError, Evaluation, Event, Powers, StepBounds, StepCounts, StepperOptions, System, Terms, ACCUMULATION_WINDOW,
    DEFAULT_EVENT_BUDGET,
};
use nalgebra::SVector;
use serde::{Deserialize, Serialize};
use std::cell::Cell;

/// How a step ends: clear of events, or at the first one.
pub(super) enum StepEnd<const N: usize, const M: usize> {
    /// No event: the step's end, with its evaluation.
    Clear(Evaluated<N, M>),
    /// The state where `constraint` crossed, on the RK4 map within tolerance.
    Event { at: Evaluated<N, M>, constraint: usize },
}

/// A step taken past the end of the last `advance`: its end, and the sample at that end time.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(super) struct Ahead<const N: usize, const M: usize> {
    end: Sample<N, M>,
    now: Sample<N, M>,
}

/// The adaptive step's smallest size, as a fraction of the largest: a step this short is
/// accepted whatever its error estimate (it is then far below the nominal step's error).
const MIN_STEP_FRACTION: f64 = 1e-4;

/// How close to a step's start, in ulps of the time, an event is at the start for the rule that takes
/// a step with prepared terms again shorter (`Stepper::step`): the event search locates a crossing the
/// laws left at zero a few ulps on (a held contact's release, down to one ulp after the start).
const START_ULPS: f64 = 16.0;

/// Constraints that can be enumerated by the complementarity solvers (2^M supports).
const MAX_CONSTRAINTS: usize = 16;

/// The event-driven integrator: owns the system and its state.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Stepper<S, const N: usize, const M: usize> {
    pub(super) system: S,
    pub(super) options: StepperOptions,
    pub(super) event_budget: usize,
    /// The adaptive step's next size (≤ `options.step`).
    pub(super) step_size: f64,
    /// Constraints in persistent contact, and how each carries friction.
    pub(super) contacts: Contacts,
    pub(super) state: Sample<N, M>,
    /// An accepted, event-free step beyond the last `advance`'s end, kept while the system does not
    /// change: the next communication points inside it are served from its dense output.
    pub(super) ahead: Option<Ahead<N, M>>,
    /// An event found past the end of an `advance` by a step that was then taken again, cut short:
    /// no step runs past an end across it while the system does not change.
    pub(super) event_ahead: Option<f64>,
    /// The system may have changed since the contact set was last resolved (`system_mut`, `shift`):
    /// the next `advance` re-examines it first. Saved with the state, so a restored stepper
    /// continues as the original would.
    pub(super) changed: bool,
    pub(super) events: Vec<Event<N, M>>,
    /// A cell: the event search that takes the locating steps only reads the stepper.
    #[serde(skip)]
    pub(super) counts: Cell<StepCounts>,
    /// The options and contact set passed `invalid` (in `new` or an `advance`); not saved, so a
    /// stepper restored from bytes is checked again before it serves a point.
    #[serde(skip)]
    checked: bool,
}

impl<S: System<N, M>, const N: usize, const M: usize> Stepper<S, N, M> {
    /// Starts at `(t0, q0, q̇0)`. Constraints closed at the start are resolved as at any event
    /// (impact if approaching, sliding if the contact force is non-negative), and recorded.
    pub fn new(system: S, t0: f64, q0: SVector<f64, N>, qd0: SVector<f64, N>, options: StepperOptions) -> Result<Self, DynamicsError> {
        let reason = if M > MAX_CONSTRAINTS {
            Some("too many constraints for the complementarity solver (at most 16)")
        } else if !t0.is_finite() {
            Some("the start time must be finite")
        } else {
            options.invalid()
        };
        if let Some(reason) = reason {
            return Err(DynamicsError::InvalidArgument { time: t0, reason });
        }
        let state = sample(&system, t0, q0, qd0, Contacts::default())?;
        let mut stepper = Self {
            system,
            step_size: options.step,
            options,
            event_budget: DEFAULT_EVENT_BUDGET,
            contacts: Contacts::default(),
            state,
            ahead: None,
            event_ahead: None,
            changed: true,
            events: Vec::new(),
            counts: Cell::default(),
            checked: true,
        };
        stepper.reexamine()?;
        Ok(stepper)
    }

    /// Advances to exactly `t_end`, appending to the event record. Re-examines the contact set first
    /// if `system_mut` may have changed held inputs (an active constraint now approaching → impact);
    /// otherwise the last step left it resolved, and a communication point costs nothing here.
    ///
    /// Where nothing changed since the last `advance`, its last step may run past `t_end`: the
    /// state at `t_end` is then read from the step's quintic extension (the accessors show it), and
    /// the step goes on at the next call; a change through `system_mut` first puts the state at
    /// `t_end` on the RK4 map, as if the step had stopped there.
    pub fn advance(&mut self, t_end: f64) -> Result<(), DynamicsError> {
        if !t_end.is_finite() || t_end < self.time() {
            return Err(DynamicsError::InvalidArgument {
                time: self.time(),
                reason: "the end time is before the current time or not finite",
            });
        }
        if let Some(reason) = self.invalid(t_end) {
            return Err(DynamicsError::InvalidArgument { time: self.time(), reason });
        }
        self.checked = true;
        // Inputs that changed here are likely to change at the next point too: no step past it then.
        let beyond = !self.changed;
        if self.changed {
            self.reexamine()?;
        }
        // Events are counted per window of `ACCUMULATION_WINDOW` nominal steps: an accumulation
        // piles them up in a vanishing time, while a long span of ordinary impacts only needs more
        // windows.
        let (mut handled, mut steps, mut window_start) = (0, 0.0, self.state.t);
        // The last event left time, contact set and record as they were, or brought time and
        // contact set back to where they were before the event preceding it (`first_event`).
        let mut unmoved = false;
        let mut preceding: Option<(f64, Contacts)> = None;
        loop {
            if let Some(ahead) = &self.ahead {
                if t_end < ahead.end.t {
                    return self.serve(t_end);
                }
                if let Some(ahead) = self.ahead.take() {
                    self.state = ahead.end;
                }
            }
            if self.state.t >= t_end {
                return Ok(());
            }
            // The adaptive step may be far below the nominal one: its work is bounded here.
            steps += 1.0;
            if steps > MAX_STEPS_PER_ADVANCE {
                return Err(DynamicsError::InvalidArgument { time: self.state.t, reason: TOO_MANY_STEPS });
            }
            let before = (self.state.t, self.contacts, self.events.len());
            let event = self.step(t_end, beyond, unmoved)?;
            let now = (self.state.t, self.contacts);
            unmoved = event && (before == (now.0, now.1, self.events.len()) || preceding == Some(now));
            preceding = event.then_some((before.0, before.1));
            // A step that ran past `t_end` has the state there already.
            if self.ahead.is_some() {
                return Ok(());
            }
            if event {
                if self.state.t - window_start >= ACCUMULATION_WINDOW * self.options.step {
                    (handled, window_start) = (0, self.state.t);
                }
                handled += 1;
                if handled > self.event_budget {
                    return Err(DynamicsError::EventBudget { time: self.state.t, events: self.event_budget });
                }
            }
        }
    }

    /// Why `advance(t_end)` is refused after its time checks, if it is. A stepper restored from
    /// bytes is trusted no more than its caller: valid options, and a bounded amount of work.
    fn invalid(&self, t_end: f64) -> Option<&'static str> {
        self.options
            .invalid()
            .or_else(|| {
                let c = self.contacts;
                (c.held >> M != 0 || (c.stick | c.back) & !c.held != 0).then_some("the contact set names constraints that do not exist")
            })
            .or_else(|| ((t_end - self.state.t) / self.options.step > MAX_STEPS_PER_ADVANCE).then_some(TOO_MANY_STEPS))
    }

    /// Whether `advance(t_end)` would only read the state at `t_end` from the step ahead: it is then
    /// `serve(t_end)`. Once checked, options and contact set stay valid (only the stepper's own
    /// logic changes them), and a point inside a step is within a step's work.
    pub fn serves(&self, t_end: f64) -> bool {
        !self.changed
            && self.ahead.as_ref().is_some_and(|a| self.time() <= t_end && t_end < a.end.t)
            && (self.checked || self.invalid(t_end).is_none())
    }

    /// Reads the state at `t` from the step ahead, in place and all or nothing (a failure changes
    /// nothing). `t` may lie before the current time: reading the point before a served one again
    /// puts the stepper back exactly as it was there, the point being a function of the step.
    pub fn serve(&mut self, t: f64) -> Result<(), DynamicsError> {
        let reason = match &self.ahead {
            Some(ahead) if self.state.t <= t && t < ahead.end.t => {
                // Written once the sample is complete and finite: a failure changes nothing.
                let now = self.point(&ahead.end, t)?;
                if let Some(ahead) = &mut self.ahead {
                    ahead.now = now;
                }
                return Ok(());
            }
            Some(_) => "the time is outside the step ahead",
            None => "no step ahead to read the state from",
        };
        Err(DynamicsError::InvalidArgument { time: self.time(), reason })
    }

    /// The sample at `t` inside the step from the current state to `end`, on the held set's
    /// manifold: the step's quintic extension leaves a held gap off zero by its interpolation
    /// error, O(dt⁶) (1e-9 m on a 1 m lever at 450 rad/s and 0.13 rad steps), which the step's end
    /// removes by projection; the point is projected likewise.
    ///
    /// The drift is judged from the configuration's terms at the interpolated state (its gaps and
    /// `ḣ`, what the sample there would hold; `System::evaluate_terms`, `Terms::Configuration`), which the projection
    /// starts from: a point evaluates the system in full once, at the state it shows.
    #[inline(always)]
    fn point(&self, end: &Sample<N, M>, t: f64) -> Result<Sample<N, M>, DynamicsError> {
        let (s0, contacts) = (&self.state, self.contacts);
        let dense = Hermite5 { t0: s0.t, dt: end.t - s0.t, q0: s0.q, v0: s0.v, a0: s0.acc, q1: end.q, v1: end.v, a1: end.acc };
        let (q, v) = dense.at(t);
        let at = self.system.evaluate_terms(t, &q, &v, Terms::Configuration);
        let (q, v) = if self.drifted_at(&at.gap, &(at.gap_jacobian * v + at.gap_time_rate)) {
            self.onto_held_at((t, &q, &v), Some(at))?
        } else {
            (q, v)
        };
        let ev = self.system.evaluate_terms(t, &q, &v, Terms::Point);
        let mut s = sample_rated(&self.system, &ev, (t, q, v), contacts, false)?;
        (s.friction_work, s.contact_impulse, s.energies) = interpolated_totals(s0, end, t);
        Ok(s)
    }

    /// Puts the state at the current time on the RK4 map (the step ahead cut there), so that the
    /// system may change from it.
    fn settle_ahead(&mut self) -> Result<(), DynamicsError> {
        if let Some(ahead) = self.ahead.take() {
            let (mut s, ev) = rk4_cut(&self.system, &self.state, ahead.now.t, self.contacts)?;
            self.count(|c| c.accepted += 1);
            // The friction work goes on from what the served point showed: the cut step's own
            // quadrature differs from the step's interpolation by its truncation error, and a
            // total the host has read must not fall, not even by that round-off.
            s.friction_work = ahead.now.friction_work;
            self.state = s;
            if self.contacts.held != 0 {
                self.stabilize(Some(ev))?;
            }
        }
        Ok(())
    }

    /// The state `steps` nominal steps after `(t, q, q̇)`, with `contacts` held, by one RK4 step from
    /// there (`ev`: the evaluation at the start): how the laws of persistent contact look ahead to
    /// decide a tie (`contact_laws::Probe`). The look-ahead leaves the system prepared for a step
    /// from `(t, q, q̇)` (`System::begin_step` of length zero): the state the laws settle on, and
    /// the outputs there, are evaluated with terms prepared at that state, not half a probe later
    /// (a held force read +1.8 N with the probe's terms, −0.03 N with its own).
    #[allow(clippy::type_complexity)]
    pub(super) fn probe(
        &self,
        (t, q, v): (f64, &SVector<f64, N>, &SVector<f64, N>),
        ev: &Evaluation<N, M>,
        contacts: Contacts,
        steps: f64,
    ) -> Result<(f64, SVector<f64, N>, SVector<f64, N>, Evaluation<N, M>), DynamicsError> {
        let start = sample_of(&self.system, ev, t, *q, *v, contacts)?;
        let (s, ev) = rk4_to(&self.system, &start, t + steps * self.options.step, contacts)?;
        self.system.begin_step(t, (q, v, &start.acc), 0.0);
        Ok((s.t, s.q, s.v, ev))
    }

    /// The state the accessors show: at the end of the last `advance`.
    fn current(&self) -> &Sample<N, M> {
        self.ahead.as_ref().map_or(&self.state, |a| &a.now)
    }

    /// The current time.
    pub fn time(&self) -> f64 {
        self.current().t
    }
    /// `q` at the current state.
    pub fn position(&self) -> &SVector<f64, N> {
        &self.current().q
    }
    /// `q̇` at the current state.
    pub fn velocity(&self) -> &SVector<f64, N> {
        &self.current().v
    }
    /// q̈ at the current state with the current contact set (as of `new` or the last `advance`).
    pub fn acceleration(&self) -> SVector<f64, N> {
        self.current().acc
    }
    /// Whether constraint `i` is in persistent (sliding) contact.
    pub fn in_contact(&self, i: usize) -> bool {
        i < M && contains(self.contacts.held, i)
    }
    /// λ at the current state (0 for open constraints). A held constraint pulls only where the
    /// laws left it so at a decision: held through a flight below the event resolution, or a tie,
    /// its force growing first. Inside a step that started so, it shows 0, what the surface exerts
    /// through the flight; a held constraint pulling otherwise shows its force as it is.
    pub fn multipliers(&self) -> SVector<f64, M> {
        let start = &self.state.lambda;
        self.current().lambda.zip_map(start, |now, start| if start < 0.0 { now.max(0.0) } else { now })
    }
    /// The tangential (friction) forces λ_T at the current state (0 without friction).
    pub fn friction_forces(&self) -> SVector<f64, M> {
        self.current().friction
    }
    /// The slip velocities γ at the current state (0 without friction).
    pub fn slip_velocities(&self) -> SVector<f64, M> {
        self.current().slip
    }
    /// The power friction dissipates now, W, and the energy it has dissipated in persistent
    /// contact since the start, J, by the steps' quadrature (impacts: `Event::friction_energy`).
    pub fn friction_dissipation(&self) -> (f64, f64) {
        let s = self.current();
        (s.friction_power(), s.friction_work)
    }
    /// The integrals since the start of the rates the system reports (`System::powers`,
    /// `Change::Jump`; zero where it reports none).
    pub fn energies(&self) -> Powers {
        self.current().energies
    }
    /// The rates the system reports now (`System::powers`; zero where it reports none). A point
    /// read from the step ahead has them computed here, from its state and contacts.
    pub fn rates(&self) -> Result<Powers, DynamicsError> {
        match &self.ahead {
            Some(Ahead { now: s, .. }) if S::POWERS => {
                let (t, q, v) = (s.t, &s.q, &s.v);
                let m = motion(&self.system, &self.system.evaluate_terms(t, q, v, Terms::Point), (t, q, v), self.contacts)?;
                Ok(powers(&self.system, (t, q, v), &m))
            }
            _ => Ok(self.current().powers),
        }
    }
    /// ∫ λ dt per constraint since the start, N·s: the impulse of the persistent contact forces
    /// (impacts: `Event::impulses`).
    pub fn contact_impulses(&self) -> SVector<f64, M> {
        self.current().contact_impulse
    }
    /// Whether constraint `i` sticks (held, at tangential rest, with friction).
    pub fn sticking(&self, i: usize) -> bool {
        i < M && contains(self.contacts.stick, i)
    }
    /// `h(q, t)` at the current state.
    pub fn gaps(&self) -> SVector<f64, M> {
        self.current().gap
    }
    /// `ḣ = J q̇ + ∂h/∂t` at the current state.
    pub fn gap_rates(&self) -> SVector<f64, M> {
        self.current().hd
    }
    /// `T = ½ q̇ᵀ M q̇` at the current state.
    pub fn kinetic_energy(&self) -> f64 {
        let s = self.current();
        0.5 * s.v.dot(&(self.system.evaluate(s.t, &s.q, &s.v).mass * s.v))
    }
    /// The event record since the start or the last `clear_events`, in order.
    pub fn events(&self) -> &[Event<N, M>] {
        &self.events
    }
    /// The work done since the stepper was made or restored.
    pub fn counts(&self) -> StepCounts {
        self.counts.get()
    }
    pub(super) fn count(&self, add: impl FnOnce(&mut StepCounts)) {
        let mut counts = self.counts.get();
        add(&mut counts);
        self.counts.set(counts);
    }
    /// Empties the event record (the state is untouched).
    pub fn clear_events(&mut self) {
        self.events.clear();
    }
    /// The system integrated.
    pub fn system(&self) -> &S {
        &self.system
    }
    /// The system, to change what it holds (inputs); the next `advance` re-examines the contacts.
    /// A step that ran past the current time is cut there first, with the system as it was.
    pub fn system_mut(&mut self) -> Result<&mut S, DynamicsError> {
        self.settle_ahead()?;
        self.event_ahead = None;
        self.changed = true;
        Ok(&mut self.system)
    }
    /// The tolerances and nominal step.
    pub fn options(&self) -> &StepperOptions {
        &self.options
    }
    /// Bounds the events handled while the time advances by less than `ACCUMULATION_WINDOW`
    /// nominal steps (default `DEFAULT_EVENT_BUDGET`); beyond it `advance` returns
    /// `DynamicsError::EventBudget` instead of spinning.
    pub fn set_event_budget(&mut self, events: usize) {
        self.event_budget = events;
    }

    /// Moves the state by a symmetry of the system, `(t, q) → (t + dt, q + dq)` with `h`, `f` and
    /// `M` unchanged by it (a whole period of an angle, in time or in a coordinate). The
    /// motion and the contact set are the same; what changes is the round-off that a growing `t`
    /// or `q` carries into the gaps, near the event tolerance after long runs.
    pub fn shift(&mut self, dt: f64, dq: &SVector<f64, N>) -> Result<(), DynamicsError> {
        self.settle_ahead()?;
        self.event_ahead = None;
        let s = &self.state;
        if !(dt.is_finite() && dq.iter().all(|x| x.is_finite())) {
            return Err(DynamicsError::InvalidArgument { time: s.t, reason: "the shift must be finite" });
        }
        self.state = sample(&self.system, s.t + dt, s.q + dq, s.v, self.contacts)?.after(s);
        self.changed = true;
        Ok(())
    }

    /// Refreshes the state after possible changes through `system_mut` and resolves every
    /// closed constraint: an active one now approaching gets an impact, a pulling one is released.
    fn reexamine(&mut self) -> Result<(), DynamicsError> {
        self.changed = false;
        let s = &self.state;
        let ev = self.system.evaluate(s.t, &s.q, &s.v);
        self.state = sample_of(&self.system, &ev, s.t, s.q, s.v, self.contacts)?.after(s);
        let eps = self.options.gap_tolerance;
        // A free gap a little below −ε_h is closed, not violated: steps end anywhere down to −ε_h,
        // and the drift projection of the active set moves the others by round-off; `settle`
        // puts it back on h = 0. Only a gap far beyond what the event search leaves is refused.
        if let Some(i) = (0..M).find(|&i| !contains(self.contacts.held, i) && self.state.gap[i] < -PENETRATION_FACTOR * eps) {
            return Err(DynamicsError::Penetration { time: self.state.t, constraint: i, gap: self.state.gap[i] });
        }
        let closed = self.contacts.held | select::<M>(|i| self.state.gap[i] <= eps);
        // In flight there is nothing to resolve.
        if closed == 0 {
            return Ok(());
        }
        self.settle(closed, 0, Some(ev))
    }

    /// What bounds an RK4 step from the current state: the system's bounds, the largest step the
    /// smaller of its and the options'.
    fn bounds(&self) -> StepBounds {
        let s = &self.state;
        let bounds = self.system.step_bounds(s.t, &s.v, &s.gap);
        StepBounds { largest: self.options.step.min(bounds.largest), ..bounds }
    }

    /// The adaptive step's smallest size from the current state, s.
    fn smallest_step(&self) -> f64 {
        self.bounds().largest * MIN_STEP_FRACTION
    }

    /// The RK4 step from the current state towards `t_end`: of the nominal size, or (adaptive) of
    /// the controller's size, shrunk until its local error is within `local_error`; the next
    /// size follows from this step's error (the usual `(tol/err)^¼` rule, bounded growth).
    /// `beyond`: the step may end past `t_end` (it is then not cut short there).
    /// Returns the step's end, its evaluation, the held forces at its middle and whether the
    /// system prepared terms for it.
    #[allow(clippy::type_complexity)]
    fn trial_step(&mut self, t_end: f64, beyond: bool) -> Result<(Sample<N, M>, Evaluation<N, M>, Forces<M>, bool), DynamicsError> {
        let (t0, bounds) = (self.state.t, self.bounds());
        let (max, tol) = (bounds.largest, self.options.local_error.map(|e| e * bounds.error_scale));
        let min = max * MIN_STEP_FRACTION;
        loop {
            // Also repairs a size restored from bytes.
            let size = if self.step_size >= min { self.step_size.min(max) } else { max };
            let across_event = self.event_ahead.is_some_and(|te| te > t0 && t0 + size >= te);
            let t1 = if (!beyond || across_event) && t_end - t0 <= size { t_end } else { t0 + size };
            if t1 <= t0 {
                return Err(DynamicsError::InvalidArgument { time: t0, reason: "the step is below the time resolution at this time" });
            }
            let Stepped { end: s1, ev, slopes, middle, start, prepared } = rk4_step(&self.system, &self.state, t1, self.contacts, true)?;
            if let Some(start) = start {
                self.state = start;
            }
            let Some(tol) = tol else { return Ok((s1, ev, middle, prepared)) };
            let ratio = local_error(&self.state, (&s1, &ev), slopes, self.contacts.held, &self.system.coordinate_lengths())? / tol;
            if ratio.is_nan() {
                return Err(DynamicsError::NonFinite { time: t1 });
            }
            let dt = t1 - t0;
            // ratio^(-1/4) by two square roots, far cheaper than `powf`.
            let next = (dt * (0.9 / ratio.sqrt().sqrt()).clamp(0.2, 4.0)).clamp(min, max);
            if ratio <= 1.0 || size <= min {
                // A step cut short by `t_end` says nothing against a longer one.
                self.step_size = if t1 == t_end { next.max(size) } else { next };
                return Ok((s1, ev, middle, prepared));
            }
            self.count(|c| c.rejected += 1);
            self.step_size = next;
        }
    }

    /// One RK4 step towards `t_end`, stopping at the first event. Returns whether an event was handled.
    /// `beyond`: an event-free step may end past `t_end`, kept as the step ahead; one with an event
    /// past `t_end` is taken again, cut short there.
    /// `unmoved`: as `first_event` takes it.
    fn step(&mut self, t_end: f64, beyond: bool, unmoved: bool) -> Result<bool, DynamicsError> {
        let (s1, ev1, middle, prepared) = self.trial_step(t_end, beyond)?;
        self.count(|c| c.accepted += 1);
        let (active, tried) = (self.contacts.held, s1.t - self.state.t);
        match self.first_event((s1, Some(ev1)), &middle, unmoved)? {
            // A step whose stages take terms the system prepared for it (`System::begin_step`) finds
            // an event at its very start: the laws decided there with the terms of the step that
            // located it, and this step reads its start with terms prepared further on. A held
            // stick or slip can turn on the difference (a stick and the slip it started can undo each
            // other at the same instant without end), and where the prepared terms are a
            // linearisation whose acceleration jumps within the step, a constraint the laws just left
            // at rest, accelerating off its surface, can be found below it at once while a shorter
            // step shows it rising; held, it would pull and be released again at the same instant.
            // The step is taken again a quarter as long (down to the smallest step, with the adaptive
            // step): a shorter step's terms are nearer the laws'.
            StepEnd::Event { at: (s, _), .. }
                if s.t - self.state.t <= START_ULPS * f64::EPSILON * self.state.t.abs()
                    && prepared
                    && self.options.local_error.is_some()
                    && 0.25 * tried >= self.smallest_step() =>
            {
                self.count(|c| c.rejected += 1);
                self.step_size = 0.25 * tried;
                self.step(t_end, beyond, unmoved)
            }
            StepEnd::Clear((s1, ev)) if s1.t > t_end => {
                let start = std::mem::replace(&mut self.state, s1);
                if active != 0 {
                    self.stabilize(ev)?;
                }
                let end = std::mem::replace(&mut self.state, start);
                let now = self.point(&end, t_end)?;
                self.ahead = Some(Ahead { end, now });
                Ok(false)
            }
            StepEnd::Clear((s1, ev)) => {
                self.state = s1;
                if active != 0 {
                    self.stabilize(ev)?;
                }
                Ok(false)
            }
            StepEnd::Event { at: (s, _), .. } if s.t > t_end => {
                self.event_ahead = Some(s.t);
                self.step(t_end, false, unmoved)
            }
            StepEnd::Event { at: (s, mut ev), constraint: i } => {
                // A free constraint crossing at the very start of the step: the last decision left it
                // open at rest, and the motion closes it again before it lifts beyond ε_h (a flight
                // below the event resolution, at an order the sliding law does not see): it is held.
                let hold = if s.t == self.state.t && !contains(active, i) { bit(i) } else { 0 };
                self.state = s;
                // The event state lies inside a step, off the manifold of the held set by the
                // step's drift; the impact and sliding laws see the held constraints at rest.
                if active != 0 {
                    ev = self.stabilize(ev)?;
                }
                let closed = self.contacts.held | bit(i) | select::<M>(|j| self.state.gap[j] <= self.options.gap_tolerance);
                self.settle(closed, hold, ev)?;
                Ok(true)
            }
        }
    }
}

/// The totals a step integrates (friction work, contact impulse, the system's reported energies) at `t` inside the
/// step from `s0` to `end`, interpolated from their values and rates at the ends.
fn interpolated_totals<const N: usize, const M: usize>(s0: &Sample<N, M>, end: &Sample<N, M>, t: f64) -> (f64, SVector<f64, M>, Powers) {
    let friction_work = if end.friction_work != s0.friction_work {
        // The friction work by the cubic Hermite of its values and rates (the powers) at the ends,
        // the rates scaled down where they would make it fall or overshoot (Fritsch–Carlson:
        // monotone where (h p₀)² + (h p₁)² ≤ 9 (w₁ − w₀)²), so that it never decreases.
        let (h, x) = (end.t - s0.t, (t - s0.t) / (end.t - s0.t));
        let (x2, x3) = (x * x, x * x * x);
        let (rise, mut slopes) = (end.friction_work - s0.friction_work, [h * s0.friction_power(), h * end.friction_power()]);
        let norm = libm::hypot(slopes[0], slopes[1]);
        if norm > 3.0 * rise {
            slopes = slopes.map(|m| m * (3.0 * rise).max(0.0) / norm);
        }
        (2.0 * x3 - 3.0 * x2 + 1.0) * s0.friction_work
            + (x3 - 2.0 * x2 + x) * slopes[0]
            + (3.0 * x2 - 2.0 * x3) * end.friction_work
            + (x3 - x2) * slopes[1]
    } else {
        s0.friction_work
    };
    // The contact impulse and the reported energies by the cubic Hermite of their values and rates
    // (the forces, the powers) at the ends.
    let weights = |h: f64| {
        let x = (t - s0.t) / h;
        let (x2, x3) = (x * x, x * x * x);
        [2.0 * x3 - 3.0 * x2 + 1.0, (x3 - 2.0 * x2 + x) * h, 3.0 * x2 - 2.0 * x3, (x3 - x2) * h]
    };
    let contact_impulse = if end.contact_impulse != s0.contact_impulse {
        let [a, b, c, d] = weights(end.t - s0.t);
        s0.contact_impulse * a + s0.lambda * b + end.contact_impulse * c + end.lambda * d
    } else {
        s0.contact_impulse
    };
    let energies = if end.energies != s0.energies {
        let [a, b, c, d] = weights(end.t - s0.t);
        s0.energies * a + s0.powers * b + end.energies * c + end.powers * d
    } else {
        s0.energies
    };
    (friction_work, contact_impulse, energies)
}
