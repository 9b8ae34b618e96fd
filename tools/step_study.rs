//! Accuracy study behind `crank_train::MAX_STEP` and `LOCAL_ERROR`: the default crank-train case
//! (1200 rpm, built-in pressure, e = 0.5) with fixed and adaptive RK4 steps against a 2.5 µs
//! fixed-step reference; impacts faster than 0.1 mm/s are compared in order.
//! `cargo run --release --example step_study [cycles]`.

use pistonslap::dynamics::StepperOptions;
use pistonslap::fmus::piston_slap::{mechanisms, Mechanism};
use pistonslap::fmus::piston_slap::{Inputs, Parameters};
use pistonslap::models::{CrankTrain, EngineEvent, EngineEventKind};

fn run(options: StepperOptions, cycles: f64) -> (Vec<EngineEvent>, f64) {
    let inputs = Inputs::default();
    let mut m = CrankTrain::with_options(mechanisms::crank_train::design(&Parameters::default()).unwrap(), 0.0, options).unwrap();
    let mut ev = Vec::new();
    let cycle = 4.0 * std::f64::consts::PI / inputs.crank_speed;
    let t0 = std::time::Instant::now();
    let n = (cycles * 100.0) as usize;
    for k in 1..=n {
        m.advance(&inputs, k as f64 * cycle / 100.0, &mut ev).unwrap();
    }
    (ev.into_iter().filter(|e| e.kind == EngineEventKind::Impact && e.normal_velocity_before > 1e-4).collect(), t0.elapsed().as_secs_f64())
}

fn main() {
    let cycles: f64 = std::env::args().nth(1).map(|s| s.parse().unwrap()).unwrap_or(1.0);
    let (reference, _) = run(StepperOptions { step: 2.5e-6, ..Default::default() }, cycles);
    println!("reference, fixed 2.5e-6 s: {} impacts > 0.1 mm/s", reference.len());
    let fixed = [1e-5, 1e-4, 2e-4].map(|step| (format!("fixed {step:e} s"), StepperOptions { step, ..Default::default() }));
    let adaptive = [1e-12, 1e-11, 1e-10].map(|tol| {
        let options = StepperOptions { step: 1e-3, local_error: Some(tol), ..Default::default() };
        (format!("adaptive ≤ 1e-3 s, {tol:e} m"), options)
    });
    for (name, options) in fixed.into_iter().chain(adaptive) {
        let (ev, wall) = run(options, cycles);
        let n = ev.len().min(reference.len());
        let dt = (0..n).map(|i| (ev[i].time - reference[i].time).abs()).fold(0.0, f64::max);
        let dv = (0..n)
            .map(|i| (ev[i].normal_velocity_before - reference[i].normal_velocity_before).abs() / reference[i].normal_velocity_before)
            .fold(0.0, f64::max);
        let corner = (0..n).all(|i| ev[i].corner == reference[i].corner);
        println!("{name}: {} impacts, corners same {corner}, max |Δt| {dt:.2e} s, max rel Δv {dv:.2e}, wall {wall:.3} s", ev.len());
    }
}
