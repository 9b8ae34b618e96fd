//! Runs the crank train through its `EngineModel` interface, sampling outputs once per communication
//! step, and measures what A&K section 8 reports: side changes, contact phases, impacts per landing.
#![allow(dead_code)]

pub mod designs;
pub mod flores;
pub mod fmu_designs;
pub mod fmu_host;
pub mod output_checks;
pub mod testbeds;

use pistonslap::fmus::piston_slap::Mechanism;
use pistonslap::fmus::piston_slap::{Inputs, Outputs, Parameters};
use pistonslap::models::{CrankTrain, EngineEvent, EngineEventKind};
use std::f64::consts::PI;

/// 1200 rpm.
pub const SPEED: f64 = 1200.0 * PI / 30.0;
/// One four-stroke cycle at 1200 rpm, s.
pub const CYCLE: f64 = 4.0 * PI / SPEED;

pub struct Trace {
    pub samples: Vec<Outputs>,
    pub events: Vec<EngineEvent>,
}

/// Simulates `cycles` four-stroke cycles after `warm_up` cycles, sampling every `per_cycle`-th of a cycle.
pub fn run(params: &Parameters, inputs: &Inputs, warm_up: usize, cycles: usize, per_cycle: usize) -> Trace {
    run_with(params, |_| inputs.clone(), warm_up, cycles, per_cycle)
}

/// As [`run`], with the inputs of each step chosen from the crank angle at its start (a host's
/// zero-order hold).
pub fn run_with(params: &Parameters, inputs: impl Fn(f64) -> Inputs, warm_up: usize, cycles: usize, per_cycle: usize) -> Trace {
    let mut model = CrankTrain::new(params, 0.0).expect("parameters accepted");
    let dt = CYCLE / per_cycle as f64;
    let mut events = Vec::new();
    let mut samples = Vec::new();
    for k in 1..=(warm_up + cycles) * per_cycle {
        if k == warm_up * per_cycle + 1 {
            events.clear();
        }
        let held = inputs(model.state().0[0]);
        model.advance(&held, k as f64 * dt, &mut events).expect("step");
        if k > warm_up * per_cycle {
            let mut out = Outputs::default();
            model.write_outputs(&mut out);
            samples.push(out);
        }
    }
    Trace { samples, events }
}

pub fn states(out: &Outputs) -> [bool; 4] {
    [out.contact_state_1, out.contact_state_2, out.contact_state_3, out.contact_state_4].map(|s| s == 1)
}

pub fn forces(out: &Outputs) -> [f64; 4] {
    [out.contact_force_1, out.contact_force_2, out.contact_force_3, out.contact_force_4]
}

/// The wall the piston adjoins: −1 (K1/K2 in persistent contact only), +1 (K3/K4 only), None otherwise.
pub fn wall(out: &Outputs) -> Option<i8> {
    let s = states(out);
    match (s[0] || s[1], s[2] || s[3]) {
        (true, false) => Some(-1),
        (false, true) => Some(1),
        _ => None,
    }
}

/// Changes of the adjoined wall over a trace of whole steady cycles, taken as periodic (the wall at the
/// start is the last one adjoined), as the angles (deg, mod 720) at which they happen.
pub fn side_changes(trace: &Trace) -> Vec<f64> {
    let mut last = trace.samples.iter().rev().find_map(wall);
    let mut changes = Vec::new();
    for out in &trace.samples {
        if let Some(w) = wall(out) {
            if last.is_some_and(|l| l != w) {
                changes.push(out.crank_angle.rem_euclid(4.0 * PI).to_degrees());
            }
            last = Some(w);
        }
    }
    changes
}

/// Fraction of samples in which the piston adjoins some wall.
pub fn adjoining_fraction(trace: &Trace) -> f64 {
    trace.samples.iter().filter(|o| states(o).iter().any(|&s| s)).count() as f64 / trace.samples.len() as f64
}

/// Impacts before each sliding start (one entry per landing: the impacts since the previous slide or
/// release, all on the wall of the landing).
pub fn impacts_per_landing(events: &[EngineEvent]) -> Vec<usize> {
    let mut count = 0;
    let mut landings = Vec::new();
    for e in events {
        match e.kind {
            EngineEventKind::Impact => count += 1,
            EngineEventKind::Slide => {
                landings.push(count);
                count = 0;
            }
            EngineEventKind::Release => count = 0,
            EngineEventKind::Stick | EngineEventKind::Slip => {}
        }
    }
    landings
}

pub fn impacts(events: &[EngineEvent]) -> impl Iterator<Item = &EngineEvent> {
    events.iter().filter(|e| e.kind == EngineEventKind::Impact)
}

/// The crank train's energy books between two communication points, from the outputs there (read
/// by name): the mechanical energy lost, and what the drive (or load) and the gas did less the joint
/// damping, against what was dissipated.
pub struct ClosedBooks {
    /// Δ(kinetic_energy + potential_energy) lost less the film's relaxation work (Δfilm_relaxation_work), J.
    pub lost: f64,
    /// Δ(drive_work_total + gas_work_total − damping_energy_total), J.
    pub work: f64,
    /// Δdissipated_energy_total, J.
    pub dissipated: f64,
    /// |Δdrive_work_total| + |Δgas_work_total| + Δdamping_energy_total: the energy that flowed, J.
    pub gross: f64,
    /// `lost + work − dissipated`, J: zero where the books close.
    pub residual: f64,
}

impl ClosedBooks {
    pub fn between(start: impl Fn(&str) -> f64, end: impl Fn(&str) -> f64) -> Self {
        let delta = |names: &[&str], sign: f64| names.iter().map(|n| sign * (end(n) - start(n))).sum::<f64>();
        let lost = delta(&["kinetic_energy", "potential_energy", "film_relaxation_work"], -1.0);
        let work = delta(&["drive_work_total", "gas_work_total"], 1.0) - delta(&["damping_energy_total"], 1.0);
        let dissipated = delta(&["dissipated_energy_total"], 1.0);
        let gross = ["drive_work_total", "gas_work_total", "damping_energy_total"].iter().map(|&n| delta(&[n], 1.0).abs()).sum();
        Self { lost, work, dissipated, gross, residual: lost + work - dissipated }
    }
}
