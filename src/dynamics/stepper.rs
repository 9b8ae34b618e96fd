//! INTERFACE STUB (session coordinator): the signatures every other module codes against.
//! The core helper replaces the bodies (and may split the file into rk4/events/impact/contact).
#![allow(unused_variables)]

use super::System;
use nalgebra::SVector;
use serde::{Deserialize, Serialize};
use std::fmt;
use std::marker::PhantomData;

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
}

impl Default for StepperOptions {
    fn default() -> Self {
        Self { step: 1e-5, gap_tolerance: 1e-12, velocity_tolerance: 1e-8, multiplier_tolerance: 1e-12 }
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
pub struct Event<const N: usize> {
    pub time: f64,
    pub kind: EventKind,
    pub constraint: usize,
    /// ḣ⁻ (negative when approaching).
    pub velocity_before: f64,
    /// ḣ⁺.
    pub velocity_after: f64,
    /// ½q̇⁻ᵀMq̇⁻ − ½q̇⁺ᵀMq̇⁺.
    pub energy_lost: f64,
    /// Configuration at the event.
    pub q: SVector<f64, N>,
}

/// What the core cannot resolve, as a value.
#[derive(Clone, Debug, PartialEq)]
pub enum DynamicsError {
    NonFinite { time: f64 },
}

impl fmt::Display for DynamicsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{self:?}")
    }
}

impl std::error::Error for DynamicsError {}

/// The event-driven integrator: owns the system and its state.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Stepper<S, const N: usize, const M: usize> {
    system: S,
    _todo: PhantomData<[f64; N]>,
}

impl<S: System<N, M>, const N: usize, const M: usize> Stepper<S, N, M> {
    pub fn new(system: S, t0: f64, q0: SVector<f64, N>, qd0: SVector<f64, N>, options: StepperOptions) -> Result<Self, DynamicsError> {
        todo!()
    }
    /// Advances to exactly `t_end`, appending to the event record. Re-examines the contact set first,
    /// since `system_mut` may have changed held inputs (an active constraint now approaching → impact).
    pub fn advance(&mut self, t_end: f64) -> Result<(), DynamicsError> {
        todo!()
    }
    pub fn time(&self) -> f64 {
        todo!()
    }
    pub fn position(&self) -> &SVector<f64, N> {
        todo!()
    }
    pub fn velocity(&self) -> &SVector<f64, N> {
        todo!()
    }
    /// q̈ at the current state with the current contact set.
    pub fn acceleration(&self) -> SVector<f64, N> {
        todo!()
    }
    /// Whether constraint `i` is in persistent (sliding) contact.
    pub fn in_contact(&self, i: usize) -> bool {
        todo!()
    }
    /// λ at the current state (0 for open constraints).
    pub fn multipliers(&self) -> SVector<f64, M> {
        todo!()
    }
    pub fn events(&self) -> &[Event<N>] {
        todo!()
    }
    pub fn clear_events(&mut self) {
        todo!()
    }
    pub fn system(&self) -> &S {
        &self.system
    }
    pub fn system_mut(&mut self) -> &mut S {
        &mut self.system
    }
}
