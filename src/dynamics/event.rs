//! The event record and the work counts of `Stepper::advance`.

use nalgebra::SVector;
use serde::{Deserialize, Serialize};

/// What happened at an event.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum EventKind {
    /// A velocity jump by the generalized Newton law.
    Impact,
    /// Persistent contact begins.
    Slide,
    /// A multiplier reached zero: the constraint opens.
    Release,
    /// A constraint in persistent contact comes to tangential rest and sticks (with friction).
    Stick,
    /// A constraint in persistent contact starts to slip, from sticking or reversing (with friction).
    Slip,
}

/// One entry of the event record.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Event<const N: usize, const M: usize> {
    /// When it happened, in the core's independent variable.
    pub time: f64,
    /// What happened.
    pub kind: EventKind,
    /// The constraint's index.
    pub constraint: usize,
    /// ḣ⁻ (negative when approaching).
    pub velocity_before: f64,
    /// ḣ⁺.
    pub velocity_after: f64,
    /// Energy dissipated by this constraint's impulse Λ (an impact, or the projection onto ḣ = 0
    /// when sliding starts): `−Λ (ḣ⁻ + ḣ⁺) / 2`, ≥ 0 for an approaching constraint, plus with
    /// friction the tangential impulse's `−Λ_T (γ⁻ + γ⁺) / 2`. Equal to its
    /// share of `T⁻ − T⁺` for a fixed constraint; a moving one also does the work `−Λ ∂h/∂t` on
    /// the system (the drive's, not dissipated), which is not counted here.
    pub energy_lost: f64,
    /// The part of `energy_lost` the tangential (friction) impulse dissipates (0 without friction).
    pub friction_energy: f64,
    /// Configuration at the event.
    pub q: SVector<f64, N>,
    /// The impulses Λ on every constraint of the impact or velocity projection that recorded this
    /// event, constraints held in contact included (they take reactions without an event of their
    /// own). One impact or projection may record several events: it carries its impulses on the
    /// first of them, zero on the others, so that sums over the record count each once. Zero for
    /// a release. With them `Δq̇ = M⁻¹ (Jᵀ Λ + J_Tᵀ Λ_T)` and the work of moving constraints
    /// `−Λ·∂h/∂t − Λ_T·∂γ/∂t`.
    pub impulses: SVector<f64, M>,
    /// The tangential (friction) impulses `Λ_T` of the same impact, carried alike (zero without friction).
    pub friction_impulses: SVector<f64, M>,
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
