//! The event-driven integrator (A&K section 5, Fig. 1): RK4 with the contact set held between
//! events; at each event the impact law and the sliding law decide the new contact set.

use super::contact::{bit, contains, held_acceleration, members, select, solve_on, Frame, Set};
use super::events::{self, Bracket, EventLocator, Located, Start};
use super::inertia::Inertia;
use super::rk4::{self, Hermite5};
use super::{impact, Evaluation, System};
use nalgebra::{SMatrix, SVector};
use serde::{Deserialize, Serialize};
use std::cell::{Cell, OnceCell};
use std::fmt;

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

/// A free gap below `−PENETRATION_FACTOR · ε_h` at a communication point is a penetration (an
/// error); one above it is a closed constraint, resolved and projected like any other.
const PENETRATION_FACTOR: f64 = 100.0;

/// Newton steps `onto_contacts` takes at most (quadratic convergence: two or three reach round-off).
const MAX_PROJECTIONS: usize = 4;

/// The adaptive step's smallest size, as a fraction of the largest: a step this short is
/// accepted whatever its error estimate (it is then far below the nominal step's error).
const MIN_STEP_FRACTION: f64 = 1e-4;

/// How far ahead, in nominal steps, the sliding law looks to decide a tie (`Stepper::sliding_law`):
/// far enough that the trend outweighs round-off, near enough that it is the trend at the instant.
const TIE_PROBE: f64 = 1e-4;

/// Default bound on the events handled while the time advances by less than one nominal step
/// (see `Stepper::set_event_budget`).
pub const DEFAULT_EVENT_BUDGET: usize = 10_000;

/// Constraints that can be enumerated by the complementarity solvers (2^M supports).
const MAX_CONSTRAINTS: usize = 16;

/// Tolerances and the nominal step of the event-driven integrator.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StepperOptions {
    /// Nominal RK4 step h_RK4, s.
    pub step: f64,
    /// ε_h: accuracy of event location on a gap, in units of h.
    pub gap_tolerance: f64,
    /// ε_ḣ: post-impact normal velocity below which a constraint starts sliding.
    pub velocity_tolerance: f64,
    /// ε_λ: accuracy of release location on a multiplier.
    pub multiplier_tolerance: f64,
    /// Adaptive step: the bound on each step's local error, measured where it matters, on the
    /// gaps (`|J δq|` and `|J δq̇| · dt`, m); `step` is then the largest step. `None`: every step
    /// is `step` (A&K's scheme).
    pub local_error: Option<f64>,
}

impl StepperOptions {
    /// Why these options cannot be used, if they cannot.
    fn invalid(&self) -> Option<&'static str> {
        let positive = |x: f64| x.is_finite() && x > 0.0;
        if !positive(self.step) {
            Some("the step must be positive and finite")
        } else if ![self.gap_tolerance, self.velocity_tolerance, self.multiplier_tolerance].into_iter().chain(self.local_error).all(positive) {
            Some("the tolerances must be positive and finite")
        } else {
            None
        }
    }
}

/// The most RK4 steps one `advance` may take: 100 s of engine time at the default step, far beyond a
/// communication step, yet bounded.
const MAX_STEPS_PER_ADVANCE: f64 = 1e7;
const TOO_MANY_STEPS: &str = "the span needs more than 10⁷ RK4 steps";

impl Default for StepperOptions {
    fn default() -> Self {
        Self { step: 1e-5, gap_tolerance: 1e-12, velocity_tolerance: 1e-8, multiplier_tolerance: 1e-12, local_error: None }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum EventKind {
    /// A velocity jump by the generalized Newton law.
    Impact,
    /// Persistent contact begins.
    Slide,
    /// A multiplier reached zero: the constraint opens.
    Release,
}

/// One entry of the event record.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Event<const N: usize, const M: usize> {
    pub time: f64,
    pub kind: EventKind,
    pub constraint: usize,
    /// ḣ⁻ (negative when approaching).
    pub velocity_before: f64,
    /// ḣ⁺.
    pub velocity_after: f64,
    /// Energy dissipated by this constraint's impulse Λ (an impact, or the projection onto ḣ = 0
    /// when sliding starts): `−Λ (ḣ⁻ + ḣ⁺) / 2`, ≥ 0 for an approaching constraint. Equal to its
    /// share of `T⁻ − T⁺` for a fixed constraint; a moving one also does the work `−Λ ∂h/∂t` on
    /// the system (the drive's, not dissipated), which is not counted here.
    pub energy_lost: f64,
    /// Configuration at the event.
    pub q: SVector<f64, N>,
    /// The impulses Λ on every constraint of the impact or velocity projection that recorded this
    /// event, constraints held in contact included (they take reactions without an event of their
    /// own). One impact or projection may record several events: it carries its impulses on the
    /// first of them, zero on the others, so that sums over the record count each once. Zero for
    /// a release. With them `Δq̇ = M⁻¹ Jᵀ Λ` and the work of moving constraints `−Λ·∂h/∂t`.
    pub impulses: SVector<f64, M>,
}

/// The work `Stepper::advance` has done since the stepper was made (or restored: the counts are
/// not part of its state): what sets the run time, counted rather than timed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StepCounts {
    /// RK4 steps the step controller accepted, the one each event cuts short included.
    pub accepted: u64,
    /// RK4 steps it rejected for their local error and repeated shorter.
    pub rejected: u64,
    /// Events located inside a step: each needs at least one more RK4 step, landing on it.
    pub located: u64,
    /// RK4 steps that located them on the RK4 map (from the start of the step they lie in).
    pub locating: u64,
}

/// What the core cannot resolve, as a value. Constraint sets are bitmasks (bit i = constraint i).
#[derive(Clone, Debug, PartialEq)]
pub enum DynamicsError {
    /// A state, force or multiplier became NaN or infinite.
    NonFinite { time: f64 },
    /// The inertia matrix is not positive definite.
    SingularMass { time: f64 },
    /// The constraints held closed have dependent gradients (more than the motion allows).
    DependentContacts { time: f64, constraints: u32 },
    /// The paper's "multiple impact exception": no impulses satisfy the generalized Newton law.
    MultipleImpact { time: f64, constraints: u32 },
    /// No non-negative contact forces keep the closed constraints admissible.
    ContactUnresolved { time: f64, constraints: u32 },
    /// A free constraint is violated by more than `PENETRATION_FACTOR · ε_h` at the start of a step.
    Penetration { time: f64, constraint: usize, gap: f64 },
    /// More events than the budget while the time advanced by less than one nominal step (an
    /// unresolved accumulation).
    EventBudget { time: f64, events: usize },
    /// A refused argument: bad options, or an end time before the current time.
    InvalidArgument { time: f64, reason: &'static str },
}

/// Prints a constraint bitmask as `{0, 2}`.
struct Constraints(u32);

impl fmt::Display for Constraints {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let list: Vec<String> = (0..32).filter(|i| self.0 & (1 << i) != 0).map(|i| i.to_string()).collect();
        write!(f, "{{{}}}", list.join(", "))
    }
}

impl fmt::Display for DynamicsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use DynamicsError::*;
        match *self {
            NonFinite { time } => write!(f, "at t = {time} s: the state became non-finite (NaN or infinity)"),
            // Physical inertia is positive definite at every finite state: the usual cause is an
            // overflow (a stage's state gone NaN), not the mechanism.
            SingularMass { time } => {
                write!(f, "at t = {time} s: the inertia matrix is not positive definite (a state gone non-finite, or a degenerate mechanism)")
            }
            DependentContacts { time, constraints } => {
                write!(f, "at t = {time} s: constraints {} held closed have dependent gradients", Constraints(constraints))
            }
            MultipleImpact { time, constraints } => write!(
                f,
                "at t = {time} s: multiple impact exception, no impulses on constraints {} satisfy the generalized Newton law",
                Constraints(constraints)
            ),
            ContactUnresolved { time, constraints } => write!(
                f,
                "at t = {time} s: no non-negative contact forces on constraints {} keep them admissible",
                Constraints(constraints)
            ),
            Penetration { time, constraint, gap } => {
                write!(f, "at t = {time} s: constraint {constraint} is violated, gap {gap:e} m (beyond {PENETRATION_FACTOR} ε_h)")
            }
            EventBudget { time, events } => {
                write!(f, "at t = {time} s: more than {events} events within one nominal step (accumulation not resolved)")
            }
            InvalidArgument { time, reason } => write!(f, "at t = {time} s: {reason}"),
        }
    }
}

impl std::error::Error for DynamicsError {}

impl DynamicsError {
    /// The same error with its time mapped by `clock` (for a model whose core runs on another
    /// independent variable, such as a crank angle).
    pub fn map_time(mut self, clock: impl FnOnce(f64) -> f64) -> Self {
        use DynamicsError::*;
        let (NonFinite { time }
        | SingularMass { time }
        | DependentContacts { time, .. }
        | MultipleImpact { time, .. }
        | ContactUnresolved { time, .. }
        | Penetration { time, .. }
        | EventBudget { time, .. }
        | InvalidArgument { time, .. }) = &mut self;
        *time = clock(*time);
        self
    }
}

/// Everything the loop needs at one `(t, q, q̇)` with a given contact set.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
struct Sample<const N: usize, const M: usize> {
    t: f64,
    q: SVector<f64, N>,
    v: SVector<f64, N>,
    acc: SVector<f64, N>,
    lambda: SVector<f64, M>,
    gap: SVector<f64, M>,
    /// ḣ = J q̇ + ∂h/∂t.
    hd: SVector<f64, M>,
    /// ḧ = J q̈ + d: with `h` and `ḣ` at both ends of a step it gives the gaps' own quintic
    /// extension, so that event search samples no configuration.
    hdd: SVector<f64, M>,
}

/// A sample with the system's evaluation there (the impact and sliding laws and the drift
/// projection reuse it), or without one where none is at hand.
type Evaluated<const N: usize, const M: usize> = (Sample<N, M>, Option<Evaluation<N, M>>);

/// Which function of constraint `i` an event watches.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Watch {
    Gap,
    Multiplier,
}

impl<const N: usize, const M: usize> Sample<N, M> {
    fn watched(&self, i: usize, w: Watch) -> f64 {
        match w {
            Watch::Gap => self.gap[i],
            Watch::Multiplier => self.lambda[i],
        }
    }
}

/// The evaluation at `(t, q, q̇)` and its contact frame; `known`: that evaluation, if at hand.
fn frame_at<S: System<N, M>, const N: usize, const M: usize>(
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
fn acceleration<const N: usize, const M: usize>(
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
fn free_motion<const N: usize>(mass: &SMatrix<f64, N, N>, force: &SVector<f64, N>, t: f64) -> Result<(Inertia<N>, SVector<f64, N>), DynamicsError> {
    let inertia = Inertia::new(mass).ok_or(DynamicsError::SingularMass { time: t })?;
    let acc = inertia.solve(force);
    Ok((inertia, acc))
}

fn sample<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    t: f64,
    q: SVector<f64, N>,
    v: SVector<f64, N>,
    active: Set,
) -> Result<Sample<N, M>, DynamicsError> {
    sample_of(&sys.evaluate(t, &q, &v), t, q, v, active)
}

/// The sample at `(t, q, q̇)` from its evaluation `ev` (borrowed: callers use it again, and a
/// moved evaluation is a copy that showed in the profile). Inlined, like `rk4_step`, so that the
/// sample is built where the caller keeps it: returned through `Result`, it was copied by `memcpy`.
#[inline(always)]
fn sample_of<const N: usize, const M: usize>(
    ev: &Evaluation<N, M>,
    t: f64,
    q: SVector<f64, N>,
    v: SVector<f64, N>,
    active: Set,
) -> Result<Sample<N, M>, DynamicsError> {
    let (acc, lambda) = acceleration(ev, t, active)?;
    let hd = ev.gap_jacobian * v + ev.gap_time_rate;
    let hdd = ev.gap_jacobian * acc + ev.gap_bias;
    let s = Sample { t, q, v, acc, lambda, gap: ev.gap, hd, hdd };
    let finite = |x: &[f64]| x.iter().all(|v| v.is_finite());
    if [s.q.as_slice(), s.v.as_slice(), s.acc.as_slice(), s.lambda.as_slice(), s.gap.as_slice(), s.hd.as_slice(), s.hdd.as_slice()]
        .into_iter()
        .all(finite)
    {
        Ok(s)
    } else {
        Err(DynamicsError::NonFinite { time: t })
    }
}

/// One RK4 step from `s0` to `t` with the contact set `active` held, and the end's evaluation.
fn rk4_to<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    s0: &Sample<N, M>,
    t: f64,
    active: Set,
) -> Result<(Sample<N, M>, Evaluation<N, M>), DynamicsError> {
    let (s, ev, _) = rk4_step(sys, s0, t, active)?;
    Ok((s, ev))
}

/// `rk4_to`, with the end's evaluation and the step's last slopes (for `local_error`).
#[allow(clippy::type_complexity)]
#[inline(always)]
fn rk4_step<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    s0: &Sample<N, M>,
    t: f64,
    active: Set,
) -> Result<(Sample<N, M>, Evaluation<N, M>, (SVector<f64, N>, SVector<f64, N>)), DynamicsError> {
    let accel = |t, q: &SVector<f64, N>, v: &SVector<f64, N>| {
        if active == 0 {
            let (mass, force) = sys.inertia_and_force(t, q, v);
            Ok(free_motion(&mass, &force, t)?.1)
        } else {
            Ok(acceleration(&sys.evaluate(t, q, v), t, active)?.0)
        }
    };
    let step = rk4::step(accel, s0.t, &s0.q, &s0.v, &s0.acc, t - s0.t)?;
    let ev = sys.evaluate(t, &step.q, &step.v);
    let s = sample_of(&ev, t, step.q, step.v, active)?;
    Ok((s, ev, step.last_slopes))
}

/// The local error of the RK4 step `s0 → s1` on the gaps, m: the embedded third-order estimate
/// `(δq, δq̇)` mapped through `J`, the velocity part as the gap error it makes over the step.
/// With constraints held, only the error along their manifold counts: `stabilize` removes the
/// rest (a fully constrained motion has no error left at all).
fn local_error<const N: usize, const M: usize>(
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

/// The event-driven integrator: owns the system and its state.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Stepper<S, const N: usize, const M: usize> {
    system: S,
    options: StepperOptions,
    locator: EventLocator,
    event_budget: usize,
    /// The adaptive step's next size (≤ `options.step`).
    step_size: f64,
    /// Constraints in persistent contact (bitmask).
    active: u32,
    state: Sample<N, M>,
    events: Vec<Event<N, M>>,
    /// A cell: the event search that takes the locating steps only reads the stepper.
    #[serde(skip)]
    counts: Cell<StepCounts>,
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
        let state = sample(&system, t0, q0, qd0, 0)?;
        let mut stepper = Self {
            system,
            step_size: options.step,
            options,
            locator: EventLocator::default(),
            event_budget: DEFAULT_EVENT_BUDGET,
            active: 0,
            state,
            events: Vec::new(),
            counts: Cell::default(),
        };
        stepper.reexamine()?;
        Ok(stepper)
    }

    /// Advances to exactly `t_end`, appending to the event record. Re-examines the contact set first,
    /// since `system_mut` may have changed held inputs (an active constraint now approaching → impact).
    pub fn advance(&mut self, t_end: f64) -> Result<(), DynamicsError> {
        if !t_end.is_finite() || t_end < self.state.t {
            return Err(DynamicsError::InvalidArgument { time: self.state.t, reason: "the end time is before the current time or not finite" });
        }
        // A stepper restored from bytes is trusted no more than its caller: valid options, and a
        // bounded amount of work below.
        let reason = self.options.invalid().or_else(|| (self.active >> M != 0).then_some("the contact set names constraints that do not exist")).or_else(|| {
            ((t_end - self.state.t) / self.options.step > MAX_STEPS_PER_ADVANCE).then_some(TOO_MANY_STEPS)
        });
        if let Some(reason) = reason {
            return Err(DynamicsError::InvalidArgument { time: self.state.t, reason });
        }
        self.reexamine()?;
        // Events are counted per window of one nominal step: an accumulation piles them up in a
        // vanishing time, while a long span of ordinary impacts only needs more windows.
        let (mut handled, mut steps, mut window_start) = (0, 0.0, self.state.t);
        while self.state.t < t_end {
            // The adaptive step may be far below the nominal one: its work is bounded here.
            steps += 1.0;
            if steps > MAX_STEPS_PER_ADVANCE {
                return Err(DynamicsError::InvalidArgument { time: self.state.t, reason: TOO_MANY_STEPS });
            }
            if self.step(t_end)? {
                if self.state.t - window_start >= self.options.step {
                    (handled, window_start) = (0, self.state.t);
                }
                handled += 1;
                if handled > self.event_budget {
                    return Err(DynamicsError::EventBudget { time: self.state.t, events: self.event_budget });
                }
            }
        }
        Ok(())
    }

    pub fn time(&self) -> f64 {
        self.state.t
    }
    pub fn position(&self) -> &SVector<f64, N> {
        &self.state.q
    }
    pub fn velocity(&self) -> &SVector<f64, N> {
        &self.state.v
    }
    /// q̈ at the current state with the current contact set (as of `new` or the last `advance`).
    pub fn acceleration(&self) -> SVector<f64, N> {
        self.state.acc
    }
    /// Whether constraint `i` is in persistent (sliding) contact.
    pub fn in_contact(&self, i: usize) -> bool {
        i < M && contains(self.active, i)
    }
    /// λ at the current state (0 for open constraints).
    pub fn multipliers(&self) -> SVector<f64, M> {
        self.state.lambda
    }
    /// `h(q, t)` at the current state.
    pub fn gaps(&self) -> SVector<f64, M> {
        self.state.gap
    }
    /// `ḣ = J q̇ + ∂h/∂t` at the current state.
    pub fn gap_rates(&self) -> SVector<f64, M> {
        self.state.hd
    }
    /// `T = ½ q̇ᵀ M q̇` at the current state.
    pub fn kinetic_energy(&self) -> f64 {
        let s = &self.state;
        0.5 * s.v.dot(&(self.system.evaluate(s.t, &s.q, &s.v).mass * s.v))
    }
    pub fn events(&self) -> &[Event<N, M>] {
        &self.events
    }
    pub fn counts(&self) -> StepCounts {
        self.counts.get()
    }
    fn count(&self, add: impl FnOnce(&mut StepCounts)) {
        let mut counts = self.counts.get();
        add(&mut counts);
        self.counts.set(counts);
    }
    pub fn clear_events(&mut self) {
        self.events.clear();
    }
    pub fn system(&self) -> &S {
        &self.system
    }
    pub fn system_mut(&mut self) -> &mut S {
        &mut self.system
    }
    pub fn options(&self) -> &StepperOptions {
        &self.options
    }
    pub fn locator(&self) -> EventLocator {
        self.locator
    }
    /// Chooses how events are located (default: dense output).
    pub fn set_locator(&mut self, locator: EventLocator) {
        self.locator = locator;
    }
    /// Bounds the events handled while the time advances by less than one nominal step (default
    /// `DEFAULT_EVENT_BUDGET`); beyond it `advance` returns `DynamicsError::EventBudget` instead of
    /// spinning.
    pub fn set_event_budget(&mut self, events: usize) {
        self.event_budget = events;
    }

    /// Moves the state by a symmetry of the system, `(t, q) → (t + dt, q + dq)` with `h`, `f` and
    /// `M` unchanged by it (a whole period of a crank angle, in time or in a coordinate). The
    /// motion and the contact set are the same; what changes is the round-off that a growing `t`
    /// or `q` carries into the gaps, near the event tolerance after long runs.
    pub fn shift(&mut self, dt: f64, dq: &SVector<f64, N>) -> Result<(), DynamicsError> {
        let s = &self.state;
        if !(dt.is_finite() && dq.iter().all(|x| x.is_finite())) {
            return Err(DynamicsError::InvalidArgument { time: s.t, reason: "the shift must be finite" });
        }
        self.state = sample(&self.system, s.t + dt, s.q + dq, s.v, self.active)?;
        Ok(())
    }

    /// Refreshes the state after possible changes through `system_mut` and resolves every
    /// closed constraint: an active one now approaching gets an impact, a pulling one is released.
    fn reexamine(&mut self) -> Result<(), DynamicsError> {
        let s = &self.state;
        let ev = self.system.evaluate(s.t, &s.q, &s.v);
        self.state = sample_of(&ev, s.t, s.q, s.v, self.active)?;
        let eps = self.options.gap_tolerance;
        // A free gap a little below −ε_h is closed, not violated: steps end anywhere down to −ε_h,
        // and the drift projection of the active set moves the others by round-off; `settle`
        // puts it back on h = 0. Only a gap far beyond what the event search leaves is refused.
        if let Some(i) = (0..M).find(|&i| !contains(self.active, i) && self.state.gap[i] < -PENETRATION_FACTOR * eps) {
            return Err(DynamicsError::Penetration { time: self.state.t, constraint: i, gap: self.state.gap[i] });
        }
        let closed = self.active | select::<M>(|i| self.state.gap[i] <= eps);
        // In flight there is nothing to resolve (at every communication point: worth skipping).
        if closed == 0 {
            return Ok(());
        }
        self.settle(closed, Some(ev))
    }

    /// The RK4 step from the current state towards `t_end`: of the nominal size, or (adaptive) of
    /// the controller's size, shrunk until its local error is within `local_error`; the next
    /// size follows from this step's error (the usual `(tol/err)^¼` rule, bounded growth).
    fn trial_step(&mut self, t_end: f64) -> Result<(Sample<N, M>, Evaluation<N, M>), DynamicsError> {
        let (t0, max, tol) = (self.state.t, self.options.step, self.options.local_error);
        let min = max * MIN_STEP_FRACTION;
        loop {
            // Also repairs a size restored from bytes.
            let size = if self.step_size >= min { self.step_size.min(max) } else { max };
            let t1 = if t_end - t0 <= size { t_end } else { t0 + size };
            if t1 <= t0 {
                return Err(DynamicsError::InvalidArgument { time: t0, reason: "the step is below the time resolution at this time" });
            }
            let (s1, ev, slopes) = rk4_step(&self.system, &self.state, t1, self.active)?;
            let Some(tol) = tol else { return Ok((s1, ev)) };
            let ratio = local_error(&self.state, (&s1, &ev), slopes, self.active, &self.system.coordinate_lengths())? / tol;
            if ratio.is_nan() {
                return Err(DynamicsError::NonFinite { time: t1 });
            }
            let dt = t1 - t0;
            // ratio^(-1/4) by two square roots: `powf` cost 5 % of the crank train's run time.
            let next = (dt * (0.9 / ratio.sqrt().sqrt()).clamp(0.2, 4.0)).clamp(min, max);
            if ratio <= 1.0 || size <= min {
                // A step cut short by `t_end` says nothing against a longer one.
                self.step_size = if t1 == t_end { next.max(size) } else { next };
                return Ok((s1, ev));
            }
            self.count(|c| c.rejected += 1);
            self.step_size = next;
        }
    }

    /// One RK4 step towards `t_end`, stopping at the first event. Returns whether an event was handled.
    fn step(&mut self, t_end: f64) -> Result<bool, DynamicsError> {
        let (s1, ev1) = self.trial_step(t_end)?;
        self.count(|c| c.accepted += 1);
        let active = self.active;
        match self.first_event((s1, Some(ev1)))? {
            Ok((s1, ev)) => {
                self.state = s1;
                if active != 0 {
                    self.stabilize(ev)?;
                }
                Ok(false)
            }
            Err(((s, mut ev), i, _)) => {
                self.state = s;
                // The event state lies inside a step, off the manifold of the held set by the
                // step's drift; the impact and sliding laws see the held constraints at rest.
                if active != 0 {
                    ev = self.stabilize(ev)?;
                }
                let closed = self.active | bit(i) | select::<M>(|j| self.state.gap[j] <= self.options.gap_tolerance);
                self.settle(closed, ev)?;
                Ok(true)
            }
        }
    }

    fn tolerance(&self, watch: Watch) -> f64 {
        match watch {
            Watch::Gap => self.options.gap_tolerance,
            Watch::Multiplier => self.options.multiplier_tolerance,
        }
    }

    /// The earliest event in the step `self.state → s1`: `Ok(s1)` if none, else `Err` with the
    /// state at the event (on the RK4 map, within tolerance) and what crossed.
    #[allow(clippy::type_complexity)]
    fn first_event(
        &self,
        s1: Evaluated<N, M>,
    ) -> Result<Result<Evaluated<N, M>, (Evaluated<N, M>, usize, Watch)>, DynamicsError> {
        let (sys, s0, active) = (&self.system, &self.state, self.active);
        let watch_of = |i| if contains(active, i) { Watch::Multiplier } else { Watch::Gap };
        let step_end = &s1.0;
        // The step's quintic extensions, of the gaps and of the configuration, built once a scan
        // needs them (most steps scan nothing).
        let (gaps, configuration) = (OnceCell::new(), OnceCell::new());
        let on_dense = |t: f64, i: usize, w: Watch| -> Result<f64, DynamicsError> {
            let e = step_end;
            match w {
                Watch::Gap => Ok(gaps
                    .get_or_init(|| Hermite5 { t0: s0.t, dt: e.t - s0.t, q0: s0.gap, v0: s0.hd, a0: s0.hdd, q1: e.gap, v1: e.hd, a1: e.hdd })
                    .position_of(i, t)),
                Watch::Multiplier => {
                    let dense = configuration
                        .get_or_init(|| Hermite5 { t0: s0.t, dt: e.t - s0.t, q0: s0.q, v0: s0.v, a0: s0.acc, q1: e.q, v1: e.v, a1: e.acc });
                    let (q, v) = dense.at(t);
                    let lambda = acceleration(&sys.evaluate(t, &q, &v), t, active)?.1[i];
                    if lambda.is_finite() {
                        Ok(lambda)
                    } else {
                        Err(DynamicsError::NonFinite { time: t })
                    }
                }
            }
        };
        // A located event is checked against the others at its own state; if one of them has
        // already crossed there, the search repeats on the shorter step, to that state (at most M times).
        let mut located: Option<Evaluated<N, M>> = None;
        for _ in 0..=M {
            let mut earliest: Option<(f64, usize, Watch, Start)> = None;
            for i in 0..M {
                let w = watch_of(i);
                let tol = self.tolerance(w);
                let e = located.as_ref().map_or(step_end, |l| &l.0);
                let (g0, g1) = (s0.watched(i, w), e.watched(i, w));
                let dip = w == Watch::Gap && s0.hd[i] < 0.0 && e.hd[i] > 0.0 && g0.min(g1) < 2.0 * (e.t - s0.t) * -s0.hd[i];
                if g1 >= -tol && !dip {
                    continue;
                }
                let start = match self.locator {
                    EventLocator::DenseOutput => {
                        let rising = w == Watch::Gap && s0.hd[i] > 0.0;
                        events::first_crossing(|t| on_dense(t, i, w), (s0.t, g0), (e.t, g1), tol, rising)?
                    }
                    EventLocator::StepHalving if g1 < -tol && g0 > 0.0 => {
                        Some(Start::Within(Bracket { lo: s0.t, g_lo: g0, hi: e.t, g_hi: g1 }))
                    }
                    EventLocator::StepHalving if g1 < -tol => Some(Start::Immediate),
                    EventLocator::StepHalving => None,
                };
                let estimate = match start {
                    None => continue,
                    Some(Start::Immediate) => s0.t,
                    Some(Start::Within(br)) => match self.locator {
                        EventLocator::DenseOutput => pick(events::illinois(|t| on_dense(t, i, w), br, 0.25 * tol, None)?, w),
                        EventLocator::StepHalving => br.lo, // located on the RK4 map below
                    },
                };
                if earliest.is_none_or(|(t, ..)| estimate < t) {
                    earliest = Some((estimate, i, w, start.expect("matched above")));
                }
            }
            let Some((estimate, i, w, start)) = earliest else { return Ok(Ok(located.unwrap_or(s1))) };
            let br = match start {
                Start::Immediate => return Ok(Err(((s0.clone(), None), i, w))),
                Start::Within(br) => br,
            };
            let (s, ev) = self.locate_on_rk4(br, estimate, i, w)?;
            let crossed_before = (0..M).any(|j| j != i && s.watched(j, watch_of(j)) < -self.tolerance(watch_of(j)));
            if !crossed_before {
                return Ok(Err(((s, Some(ev)), i, w)));
            }
            located = Some((s, Some(ev)));
        }
        // Only reachable with round-off ties between constraints: take the last located state.
        let end = located.unwrap_or(s1);
        let j = (0..M).find(|&j| end.0.watched(j, watch_of(j)) < 0.0).unwrap_or(0);
        Ok(Err((end, j, watch_of(j))))
    }

    /// The state where `g_i` crosses zero, on the RK4 map from the step start: Illinois started
    /// at the dense-output estimate (usually accepted at once), or bisection (step halving).
    fn locate_on_rk4(&self, br: Bracket, estimate: f64, i: usize, w: Watch) -> Result<(Sample<N, M>, Evaluation<N, M>), DynamicsError> {
        let (sys, s0, active) = (&self.system, &self.state, self.active);
        let tol = self.tolerance(w);
        let mut last: Option<(Sample<N, M>, Evaluation<N, M>)> = None;
        self.count(|c| c.located += 1);
        let locating = |t: f64| {
            self.count(|c| c.locating += 1);
            rk4_to(sys, s0, t, active)
        };
        let mut g = |t: f64| -> Result<f64, DynamicsError> {
            let s = locating(t)?;
            let gt = s.0.watched(i, w);
            last = Some(s);
            Ok(gt)
        };
        let located = match self.locator {
            EventLocator::DenseOutput => events::illinois(&mut g, br, tol, Some(estimate))?,
            EventLocator::StepHalving => events::bisect(&mut g, br, tol)?,
        };
        let t = pick(located, w);
        match last {
            Some(s) if s.0.t == t => Ok(s),
            _ => locating(t),
        }
    }

    /// Keeps active constraints on the manifold against RK4 drift: once `h_A` or `ḣ_A` has drifted
    /// beyond `DRIFT_FRACTION` of its tolerance, one M-metric Newton projection of `q` onto
    /// `h_A = 0` and of `q̇` onto `ḣ_A = 0`. The drift is O(dt⁵) per step, so the order of the
    /// method is kept, and most steps need no projection (nor the evaluation it costs). `ev`: the
    /// evaluation at the state, if at hand; returns the one at the state afterwards, likewise.
    fn stabilize(&mut self, ev: Option<Evaluation<N, M>>) -> Result<Option<Evaluation<N, M>>, DynamicsError> {
        let (s, active) = (&self.state, self.active);
        let (gap_tol, rate_tol) = (DRIFT_FRACTION * self.options.gap_tolerance, DRIFT_FRACTION * self.options.velocity_tolerance);
        if members::<M>(active).all(|i| s.gap[i].abs() <= gap_tol && s.hd[i].abs() <= rate_tol) {
            return Ok(ev);
        }
        let (t, v) = (s.t, s.v);
        let (q, ev, frame) = self.onto_contacts(t, s.q, &v, active, frame_at(&self.system, t, &s.q, &v, ev)?)?;
        let hd = ev.gap_jacobian * v + ev.gap_time_rate;
        let dependent = DynamicsError::DependentContacts { time: t, constraints: active };
        let v = v + frame.projection(&hd, active).ok_or(dependent)?.0;
        let ev = self.system.evaluate(t, &q, &v);
        self.state = sample_of(&ev, t, q, v, active)?;
        Ok(Some(ev))
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
    /// `impulses` (see `Event::impulses`).
    fn record(&mut self, kind: EventKind, set: Set, hd: &SVector<f64, M>, hd_after: &SVector<f64, M>, lost: &SVector<f64, M>, impulses: SVector<f64, M>) {
        let (time, q, mut carried) = (self.state.t, self.state.q, impulses);
        for i in members::<M>(set) {
            let (velocity_before, velocity_after, energy_lost) = (hd[i], hd_after[i], lost[i]);
            self.events.push(Event { time, kind, constraint: i, velocity_before, velocity_after, energy_lost, q, impulses: carried });
            carried = SVector::zeros();
        }
    }

    /// The sliding law over `candidates` at `(t, q, q̇)`, with the tie rule: a candidate this
    /// instant leaves undecided (zero force and zero gap acceleration together, as where a
    /// contact opens, or where two corners trade places as the piston starts to pivot) takes the
    /// law's answer `TIE_PROBE` nominal steps later along the motion with this instant's support
    /// held. Every support consistent with the ties gives the same acceleration now, so the
    /// motions differ at second order and any of them shows the first-order trend that decides.
    /// A tie that persists there opens (the law's smallest support). Returns `λ` now and the support.
    fn sliding_law(
        &self,
        (t, q, v): (f64, &SVector<f64, N>, &SVector<f64, N>),
        ev: &Evaluation<N, M>,
        frame: &Frame<N, M>,
        candidates: Set,
    ) -> Result<(SVector<f64, M>, Set), DynamicsError> {
        let eps = self.options.multiplier_tolerance;
        let unresolved = |time| DynamicsError::ContactUnresolved { time, constraints: candidates };
        let now = frame.sliding(ev, candidates, eps).ok_or(unresolved(t))?;
        if now.ties == 0 {
            return Ok((now.lambda, now.support));
        }
        let start = sample_of(ev, t, *q, *v, now.support)?;
        let (_, ev_ahead) = rk4_to(&self.system, &start, t + TIE_PROBE * self.options.step, now.support)?;
        let frame_ahead = Frame::new(&ev_ahead).ok_or(DynamicsError::SingularMass { time: t })?;
        let ahead = frame_ahead.sliding(&ev_ahead, candidates, eps).ok_or(unresolved(t))?;
        if ahead.support == now.support {
            return Ok((now.lambda, now.support));
        }
        let free = Frame::gap_acceleration(ev, &frame.free_acc);
        let lambda = solve_on(&frame.w, &-free, ahead.support)
            .ok_or(DynamicsError::DependentContacts { time: t, constraints: ahead.support })?;
        Ok((lambda.map(|x| x.max(0.0)), ahead.support))
    }

    /// Resolves the closed constraints at the current instant (Fig. 1 at a discontinuity point):
    /// 1. if any approaches (`ḣ < −ε_ḣ`), the generalized Newton impact over all of `closed`;
    /// 2. persistent contact for those now at rest (`|ḣ| < ε_ḣ`, or caught by the Zeno guard)
    ///    as the sliding complementarity problem over all of them decides (`sliding_law`): one
    ///    whose multiplier just crossed zero is not released on its own word, since the others'
    ///    forces change with it; one still approaching (−ε_ḣ ≤ ḣ < 0) that sliding refuses gets
    ///    the impact of 1. after all;
    /// 3. projection of `q` and `q̇` onto the new active set, which becomes the held set.
    ///
    /// `known`: the system's evaluation at the current state, if the caller has it.
    fn settle(&mut self, closed: Set, known: Option<Evaluation<N, M>>) -> Result<(), DynamicsError> {
        let Sample { t, q, mut v, .. } = self.state;
        let was_active = self.active;
        let opts = self.options.clone();
        let (mut ev, mut frame) = frame_at(&self.system, t, &q, &v, known)?;
        let mut hd = ev.gap_jacobian * v + ev.gap_time_rate;

        let mut approaching = closed & select::<M>(|i| hd[i] < -opts.velocity_tolerance);
        let mut impacted: Set = 0;
        let zeno_apex = ZENO_APEX_FACTOR * opts.gap_tolerance;
        let support = loop {
            if approaching != 0 {
                let e = SVector::<f64, M>::from_fn(|i, _| self.system.restitution(i));
                let impulse = impact::newton_impulses(&frame, &hd, &e, closed)
                    .ok_or(DynamicsError::MultipleImpact { time: t, constraints: closed })?;
                let v_plus = v + frame.minv_jt * impulse;
                let hd_plus = hd + frame.w * impulse;
                let lost = impact::energy_lost(&impulse, &hd, &hd_plus);
                // Recorded: every approaching constraint, and any other not held in contact that
                // took a real impulse (one that changes its own ḣ by more than ε_ḣ). A held one
                // pushed harder keeps ḣ = 0 on both sides: a reaction that dissipates nothing, not
                // an impact (counting it would inflate the impact statistics with zero speeds).
                let pushed = !was_active & select::<M>(|i| impulse[i] * frame.w[(i, i)] > opts.velocity_tolerance);
                self.record(EventKind::Impact, closed & (approaching | pushed), &hd, &hd_plus, &lost, impulse);
                (v, hd) = (v_plus, hd_plus);
                (ev, frame) = frame_at(&self.system, t, &q, &v, None)?;
                impacted |= approaching;
            }

            let mut candidates = closed & select::<M>(|i| hd[i] < opts.velocity_tolerance);
            let support = loop {
                let (lambda, support) = self.sliding_law((t, &q, &v), &ev, &frame, candidates)?;
                let hdd = Frame::gap_acceleration(&ev, &(frame.free_acc + frame.minv_jt * lambda));
                let zeno = closed & !candidates & select::<M>(|i| hd[i] > 0.0 && hdd[i] < 0.0 && hd[i] * hd[i] < -2.0 * zeno_apex * hdd[i]);
                if zeno == 0 {
                    break support;
                }
                candidates |= zeno;
            };
            // An approach slower than ε_ḣ that sliding refuses (its force would pull) still needs
            // the impact law, or the gap closes at the next instant with nothing to resolve it.
            // A constraint leaving persistent contact has ḣ = 0 up to round-off: no impact.
            let grazing = closed & !support & !impacted & !was_active & select::<M>(|i| hd[i] < 0.0);
            if grazing == 0 {
                break support;
            }
            approaching = grazing;
        };

        // The new contacts are put on the manifold, and with them any closed constraint that
        // opens a hair below zero (the drift of a step held in contact, or of a projection onto
        // its neighbours), so that it leaves from h = 0, not from an apparent penetration; where
        // that set is dependent, the contacts alone.
        let below = closed & !support & select::<M>(|i| ev.gap[i] < -opts.gap_tolerance);
        let onto = if members::<M>(support | below).count() <= N { support | below } else { support };
        let state = if onto == 0 {
            // Nothing held or moved: q and q̇ are those `ev` was made at (after any impact).
            sample_of(&ev, t, q, v, 0)?
        } else {
            let (q, ev, frame) = self.onto_contacts(t, q, &v, onto, (ev, frame))?;
            let hd = ev.gap_jacobian * v + ev.gap_time_rate;
            let (dv, impulse) = frame.projection(&hd, support).ok_or(DynamicsError::DependentContacts { time: t, constraints: support })?;
            let hd_after = hd + frame.w * impulse;
            let lost = impact::energy_lost(&impulse, &hd, &hd_after);
            self.record(EventKind::Slide, support & !was_active, &hd, &hd_after, &lost, impulse);
            sample(&self.system, t, q, v + dv, support)?
        };
        self.record(EventKind::Release, was_active & !support, &hd, &hd, &SVector::zeros(), SVector::zeros());
        self.active = support;
        self.state = state;
        Ok(())
    }
}

/// The time of a located crossing; a collapsed bracket resolves to its admissible end: before
/// the gap crossing (h ≥ 0), after the multiplier crossing (λ ≤ 0, so the release is real).
fn pick(located: Located, w: Watch) -> f64 {
    match (located, w) {
        (Located::Root(t), _) => t,
        (Located::Collapsed(br), Watch::Gap) => br.lo,
        (Located::Collapsed(br), Watch::Multiplier) => br.hi,
    }
}
