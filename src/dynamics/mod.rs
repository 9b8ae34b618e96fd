//! The nonsmooth core: a Lagrangian system `M(q,t) q̈ = f(q,q̇,t)` with unilateral constraints
//! `h(q,t) ≥ 0`, integrated by RK4 between events, with impacts (generalized Newton law) and sliding
//! (KKT multipliers) handled as in Awrejcewicz & Kudra, sections 2–5. No FFI, no FMI words here.

mod stepper;
mod system;

pub use stepper::{DynamicsError, Event, EventKind, Stepper, StepperOptions};
pub use system::{Evaluation, System};
