//! The Flores–Leine–Glocker slider crank (`designs::flores`) run for 0.2 s as an FMU host runs it: what
//! the benchmark's test (`tests/crank_train/flores_benchmark.rs`) asserts and its table
//! (`tools/flores_benchmark.rs`) prints.

use super::designs::flores;
use pistonslap::fmus::piston_slap::Mechanism;
use pistonslap::fmus::piston_slap::{Inputs, Outputs, Parameters};
use pistonslap::models::{CrankTrain, EnergyBalance, EngineEvent, EngineEventKind};
use std::f64::consts::PI;

/// The crank starts at 150 rad/s, unloaded, no gas.
pub const INPUTS: Inputs = Inputs { crank_speed: 150.0, gas_pressure: 0.0, load_torque: 0.0 };

/// The benchmark as published: μ = 0.01 at the corners, gravity 9.81 m/s² across the guide (Flores'
/// −y, PistonSlap's +x), the slider's tilt rate −0.01 rad/s at the start.
pub fn published() -> Parameters {
    Parameters { friction: 0.01, gravity_lateral: 9.81, piston_tilt_rate_start: -0.01, ..flores(0.0) }
}

/// One run's figures at 0.2 s.
pub struct Run {
    pub revolutions: f64,
    /// Kinetic energy at the start and at 0.2 s, J.
    pub kinetic: [f64; 2],
    /// Mechanical energy (kinetic and potential) at the start and at 0.2 s, J.
    pub mechanical: [f64; 2],
    /// `friction_energy_total` at 0.2 s: sliding and impact friction, J.
    pub friction: f64,
    pub events: Vec<EngineEvent>,
}

impl Run {
    /// What the impacts and sliding starts dissipated in their normal impulses, J.
    pub fn dissipated(&self) -> f64 {
        self.events.iter().map(|e| e.energy_lost).sum()
    }
    /// The friction the impacts dissipated, J.
    pub fn impact_friction(&self) -> f64 {
        self.events.iter().map(|e| e.friction_energy).sum()
    }
    /// Everything dissipated: impact losses and sliding friction, J.
    pub fn lost(&self) -> f64 {
        self.dissipated() + self.friction - self.impact_friction()
    }
    /// Impacts faster than `speed` on K1..K4.
    pub fn impacts_faster_than(&self, speed: f64) -> [usize; 4] {
        let mut count = [0; 4];
        for e in self.events.iter().filter(|e| e.kind == EngineEventKind::Impact && e.normal_velocity_before > speed) {
            count[e.corner as usize - 1] += 1;
        }
        count
    }
}

fn outputs(model: &CrankTrain) -> Outputs {
    let mut out = Outputs::default();
    model.write_outputs(&mut out);
    out
}

/// 0.2 s in communication steps of `step`, as an FMU host runs it.
pub fn run(params: &Parameters, step: f64) -> Run {
    let mut model = CrankTrain::new(params, 0.0).expect("the benchmark's parameters");
    let mut events = Vec::new();
    model.advance(&INPUTS, 0.0, &mut events).expect("the start");
    let (kinetic, mechanical) = (outputs(&model).kinetic_energy, model.mechanical_energy());
    for k in 1..=(0.2 / step).round() as usize {
        model.advance(&INPUTS, k as f64 * step, &mut events).unwrap_or_else(|e| panic!("step {step} s: {e}"));
    }
    let out = outputs(&model);
    Run {
        revolutions: out.crank_angle / (2.0 * PI),
        kinetic: [kinetic, out.kinetic_energy],
        mechanical: [mechanical, model.mechanical_energy()],
        friction: out.friction_energy_total,
        events,
    }
}
