//! The nonsmooth core: a Lagrangian system `M(q,t) q̈ = f(q,q̇,t)` with unilateral constraints
//! `h(q,t) ≥ 0`, integrated by RK4 between events, with impacts (generalized Newton law) and sliding
//! (KKT multipliers) handled as in Awrejcewicz & Kudra, sections 2–5. No FFI, no FMI words here.

mod contact;
mod events;
mod impact;
mod rk4;
mod stepper;
mod system;
pub mod testbeds;

pub use events::EventLocator;
pub use stepper::{DynamicsError, Event, EventKind, Stepper, StepperOptions, DEFAULT_EVENT_BUDGET, ZENO_APEX_FACTOR};
pub use system::{Evaluation, System};
