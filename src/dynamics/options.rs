//! The integrator's tolerances and nominal step, and the bounds on its work.

use serde::{Deserialize, Serialize};

/// Default bound on the events handled while the time advances by less than `ACCUMULATION_WINDOW`
/// nominal steps (see `Stepper::set_event_budget`).
pub const DEFAULT_EVENT_BUDGET: usize = 10_000;

/// The span, in nominal steps, within which more events than the budget are an accumulation the
/// contact laws did not resolve: one piles its events up in a vanishing time, while the impacts of
/// a real motion, however fast (a rattle at hundreds of m/s across a clearance of microns), come
/// tens of nanoseconds apart or more. A window of whole steps would refuse such a rattle at some
/// communication steps and not at others.
pub const ACCUMULATION_WINDOW: f64 = 1e-3;

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
    pub(super) fn invalid(&self) -> Option<&'static str> {
        // Written out rather than iterated: served communication points check a restored stepper's
        // options, on their hot path.
        let positive = |x: f64| x > 0.0 && x < f64::INFINITY;
        if !positive(self.step) {
            Some("the step must be positive and finite")
        } else if !(positive(self.gap_tolerance)
            && positive(self.velocity_tolerance)
            && positive(self.multiplier_tolerance)
            && self.local_error.is_none_or(positive))
        {
            Some("the tolerances must be positive and finite")
        } else {
            None
        }
    }
}

/// The most RK4 steps one `advance` may take: 100 s at the default step, far beyond a
/// communication step, yet bounded.
pub(super) const MAX_STEPS_PER_ADVANCE: f64 = 1e7;
pub(super) const TOO_MANY_STEPS: &str = "the span needs more than 10⁷ RK4 steps";

impl Default for StepperOptions {
    fn default() -> Self {
        Self { step: 1e-5, gap_tolerance: 1e-12, velocity_tolerance: 1e-8, multiplier_tolerance: 1e-12, local_error: None }
    }
}

/// A free gap below `−PENETRATION_FACTOR · ε_h` at a communication point is a penetration (an
/// error); one above it is a closed constraint, resolved and projected like any other.
pub(super) const PENETRATION_FACTOR: f64 = 100.0;
