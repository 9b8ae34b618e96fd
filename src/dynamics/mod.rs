//! The nonsmooth core: a Lagrangian system `M(q,t) q̈ = f(q,q̇,t)` with unilateral constraints
//! `h(q,t) ≥ 0`, integrated by RK4 between events, with impacts (generalized Newton law) and sliding
//! (KKT multipliers) handled as in Awrejcewicz & Kudra, sections 2–5. No FFI, no FMI words here.
//!
//! One `Stepper::advance` (A&K Fig. 1):
//! - RK4 steps of the nominal size with the active (sliding) set held: `q̈` and `λ` from the
//!   saddle-point system of eqs 17–20 (`complementarity.rs`); after each step in contact, `q` and `q̇`
//!   are projected back onto `h_A = 0`, `ḣ_A = 0` (drift control);
//! - events: a free gap falling below `−ε_h`, an active multiplier below `−ε_λ`, located by
//!   Illinois on a quintic Hermite extension of the step (of the gaps themselves, from `h`, `ḣ`,
//!   `ḧ` at its ends; of `q` for the multipliers) and confirmed on the RK4 map
//!   (where the paper halves the step: `benches/core.rs` counts what that would cost);
//! - at an event, the closed set (gaps within `ε_h`) is resolved together: the generalized Newton
//!   impact as a complementarity problem (ARCHITECTURE.md §6.4; exactly eq 11 for one constraint), then
//!   persistent contact for the constraints at rest as the sliding complementarity problem over
//!   all of them decides, a tie (zero force and zero gap acceleration) by the same problem a moment
//!   later along the motion (`contact_laws.rs`, applied by `settle.rs`); the Zeno guard
//!   ([`ZENO_APEX_FACTOR`]) turns an accumulation of impacts into sliding, and an event budget per
//!   thousandth of a nominal step turns anything else into an error;
//! - where the system did not change since the last `advance`, its last step may run past the
//!   end: the end's state comes from the step's quintic extension, and the step goes on next time.
//!
//! Constraint sets are bitmasks, all matrices are fixed-size: no heap use but the event record and
//! a wedged stick's dependent rows (`wedge.rs`), whose count may exceed the degrees of freedom.
//!
//! The files, from the loop down: `stepper.rs` (the loop, the state it keeps, the accessors),
//! `search.rs` (the event search of one step) over `root_finding.rs` (scan, Illinois),
//! `settle.rs` (an event resolved, drift removed) over `contact_laws.rs` (the impact law and the
//! laws of persistent contact), which reduce to `complementarity.rs` (constraint sets, the held
//! set, `W`, the held acceleration, the LCP) and `coulomb.rs` (the friction problems by
//! enumeration, `wedge.rs` where a stick's rows are dependent); `implicit/` (the implicit part of a
//! stiff force, all the core does with it: impacts through `M` alone, the held motion with the implicit
//! inertia kept off the held normals where through it the law has no solution, the jumps' books, a held
//! step's totals on its path); `rk4.rs` (the RK4 step of a sample, its error estimate) and `hermite.rs`
//! (its quintic extension) over `sample.rs` (the state the loop carries); `inertia.rs` (`M⁻¹`); `system.rs`,
//! `options.rs`, `event.rs`, `error.rs` (what the core takes, is told, records and refuses). The
//! closed-form systems the tests and benches run it on are `tests/common/testbeds.rs`.

mod complementarity;
mod contact_laws;
mod coulomb;
mod error;
mod event;
mod hermite;
mod implicit;
mod inertia;
mod options;
mod rk4;
mod root_finding;
mod sample;
mod search;
mod settle;
mod stepper;
mod system;
#[cfg(test)]
mod test_random;
mod wedge;

pub use error::DynamicsError;
pub use event::{Event, EventKind, StepCounts};
pub use options::{StepperOptions, ACCUMULATION_WINDOW, DEFAULT_EVENT_BUDGET};
pub use settle::ZENO_APEX_FACTOR;
pub use stepper::Stepper;
pub use system::{Change, Evaluation, Powers, StepBounds, System, Tangents, Terms};
