//! Cost of the crank train's model side on the default case (1200 rpm, built-in pressure):
//! ns per `System::evaluate` call of both crank modes, at states spread
//! over one engine cycle near the nominal slider-crank motion, and the wall time of 10 cycles of
//! the whole model at 10 ms communication steps. Medians of several runs.
//! `cargo run --release --example eval_cost`.

use nalgebra::{SVector, Vector2, Vector3};
use pistonslap::dynamics::System;
use pistonslap::fmus::piston_slap::mechanisms;
use pistonslap::fmus::piston_slap::Mechanism;
use pistonslap::fmus::piston_slap::{Inputs, Parameters};
use pistonslap::models::crank_train::engine::{FreeCrank, PrescribedCrank};
use pistonslap::models::crank_train::kinematics::SliderCrank;
use pistonslap::models::{CrankTrain, InputPolynomial};
use std::hint::black_box;
use std::time::Instant;

/// Many short runs: on a loaded machine the minimum is the run nobody interrupted.
const RUNS: usize = 61;
const STATES: usize = 1000;
const SWEEPS: usize = 20;

/// Median and minimum (the figure least disturbed by other load on the machine).
fn median(mut x: Vec<f64>) -> (f64, f64) {
    x.sort_by(f64::total_cmp);
    (x[x.len() / 2], x[0])
}

/// Median and minimum ns per call of `f` over all states.
fn ns_per_call<T>(states: &[T], f: impl Fn(&T) -> f64) -> (f64, f64) {
    median(
        (0..RUNS)
            .map(|_| {
                let start = Instant::now();
                let mut sum = 0.0;
                for _ in 0..SWEEPS {
                    for s in states {
                        sum += f(black_box(s));
                    }
                }
                black_box(sum);
                start.elapsed().as_secs_f64() * 1e9 / (SWEEPS * states.len()) as f64
            })
            .collect(),
    )
}

/// (t, q, q̇) for the prescribed crank and (q, q̇) for the free crank: the nominal motion over
/// one cycle with a rocking piston and a perturbed rod, so no term vanishes.
fn states(p: &Parameters, speed: f64) -> Vec<(f64, SVector<f64, 3>, SVector<f64, 3>)> {
    let geometry = SliderCrank { crank_radius: p.crank_radius, rod_length: p.rod_length, pin_offset: p.pin_offset };
    let cycle = 4.0 * std::f64::consts::PI / speed;
    (0..STATES)
        .map(|k| {
            let t = cycle * k as f64 / STATES as f64;
            let angle = p.crank_angle_start + speed * t;
            let s = geometry.at(angle);
            let rock = libm::sin(7.0 * angle);
            (
                t,
                Vector3::new(angle, s.rod_angle + 1e-4 * rock, 2e-3 * rock),
                Vector3::new(speed, s.rod_rate * speed, 14.0 * speed * 2e-3 * libm::cos(rock)),
            )
        })
        .collect()
}

fn main() {
    let p = Parameters::default();
    let speed = Inputs::default().crank_speed;
    let states = states(&p, speed);
    let prescribed = PrescribedCrank::new(mechanisms::crank_train::engine(&p).expect("default engine"), p.crank_angle_start, 0.0, speed);
    let reduced = |x: &SVector<f64, 3>| Vector2::new(x[1], x[2]);
    let evaluate = ns_per_call(&states, |(t, q, qd)| prescribed.evaluate(*t, &reduced(q), &reduced(qd)).gap_bias[0]);
    println!("prescribed crank: evaluate {:6.1} ns (min {:6.1})", evaluate.0, evaluate.1);
    let free = FreeCrank { engine: mechanisms::crank_train::engine(&p).expect("default engine"), load_torque: InputPolynomial::held(20.0) };
    let evaluate = ns_per_call(&states, |(_, q, qd)| free.evaluate(0.0, q, qd).gap_bias[0]);
    println!("free crank:       evaluate {:6.1} ns (min {:6.1})", evaluate.0, evaluate.1);

    // The run is deterministic, so each communication step does the same work in every run: the
    // sum of the steps' fastest times is the wall time of an undisturbed run.
    let inputs = Inputs::default();
    let cycle = 4.0 * std::f64::consts::PI / inputs.crank_speed;
    let steps = (10.0 * cycle / 1e-2).round() as usize;
    let mut fastest = vec![f64::INFINITY; steps];
    let totals: Vec<f64> = (0..RUNS / 3)
        .map(|_| {
            let mut m = CrankTrain::new(&p, 0.0).expect("default parameters");
            let mut events = Vec::new();
            let mut total = 0.0;
            for (k, best) in fastest.iter_mut().enumerate() {
                let start = Instant::now();
                m.advance(&inputs, (k + 1) as f64 * 1e-2, &mut events).expect("default case");
                let wall = start.elapsed().as_secs_f64();
                *best = best.min(wall);
                total += wall;
            }
            total
        })
        .collect();
    let (median_wall, undisturbed) = (median(totals).0, fastest.iter().sum::<f64>());
    println!(
        "default case, 10 cycles ({:.3} s) at 10 ms steps: {:.2} ms wall (undisturbed {:.2}), {:.0}× real time (undisturbed {:.0}×)",
        10.0 * cycle,
        median_wall * 1e3,
        undisturbed * 1e3,
        10.0 * cycle / median_wall,
        10.0 * cycle / undisturbed
    );
}
