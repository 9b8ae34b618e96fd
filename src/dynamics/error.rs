//! What the core cannot resolve, as a value.

use super::options::{ACCUMULATION_WINDOW, PENETRATION_FACTOR};
use std::fmt;

/// What the core cannot resolve, as a value. Constraint sets are bitmasks (bit i = constraint i);
/// `time` is the core's independent variable where it happened (s, or what `map_time` made it).
#[derive(Clone, Debug, PartialEq)]
pub enum DynamicsError {
    /// A state, force or multiplier became NaN or infinite.
    NonFinite {
        /// Where it happened.
        time: f64,
    },
    /// The inertia matrix is not positive definite.
    SingularMass {
        /// Where it happened.
        time: f64,
    },
    /// The constraints held closed have dependent gradients (more than the motion allows).
    DependentContacts {
        /// Where it happened.
        time: f64,
        /// The constraints held.
        constraints: u32,
    },
    /// The paper's "multiple impact exception": no impulses satisfy the generalized Newton law.
    MultipleImpact {
        /// Where it happened.
        time: f64,
        /// The closed constraints of the impact.
        constraints: u32,
    },
    /// No non-negative contact forces keep the closed constraints admissible.
    ContactUnresolved {
        /// Where it happened.
        time: f64,
        /// The candidates of persistent contact.
        constraints: u32,
    },
    /// A free constraint is violated by more than `PENETRATION_FACTOR · ε_h` at the start of a step.
    Penetration {
        /// Where it happened.
        time: f64,
        /// The violated constraint's index.
        constraint: usize,
        /// Its gap, m (negative).
        gap: f64,
    },
    /// More events than the budget while the time advanced by less than `ACCUMULATION_WINDOW`
    /// nominal steps (an unresolved accumulation).
    EventBudget {
        /// Where the budget ran out.
        time: f64,
        /// The budget.
        events: usize,
    },
    /// A refused argument: bad options, or an end time before the current time.
    InvalidArgument {
        /// The stepper's time when refused.
        time: f64,
        /// Why, in words.
        reason: &'static str,
    },
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
                write!(
                    f,
                    "at t = {time} s: the inertia matrix is not positive definite (a state gone non-finite, or a degenerate mechanism)"
                )
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
                write!(
                    f,
                    "at t = {time} s: more than {events} events within {ACCUMULATION_WINDOW} of a nominal step (accumulation not resolved)"
                )
            }
            InvalidArgument { time, reason } => write!(f, "at t = {time} s: {reason}"),
        }
    }
}

impl std::error::Error for DynamicsError {}

impl DynamicsError {
    /// The same error with its time mapped by `clock` (for a model whose core runs on another
    /// independent variable, such as an angle).
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
