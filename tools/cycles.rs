//! The default case of either engine model for N engine cycles (0.1 s at 1200 rpm) at 10 ms
//! communication steps, through the model's `advance` (no FMU): wall time, real-time factor,
//! events, and a hash of every event's time, speed and energy, which shows whether a change to
//! the core left the results bit-identical. Under callgrind it gives the instruction counts of
//! `benches/README.md`:
//! `cargo run --release --example cycles -- 100 [roller]`,
//! `valgrind --tool=callgrind target/release/examples/cycles 10`.

use pistonslap::fmus::piston_slap::Mechanism;
use pistonslap::fmus::piston_slap::{Inputs, Parameters};
use pistonslap::models::{CrankTrain, Roller};
use std::time::Instant;

const CYCLE: f64 = 0.1;
const STEP: f64 = 0.01;

fn run<M: Mechanism>(params: &Parameters, cycles: usize) {
    let (inputs, mut events) = (Inputs::default(), Vec::new());
    let mut model = M::new(params, 0.0).expect("default parameters");
    let (mut count, mut hash) = (0, 0u64);
    let steps = (cycles as f64 * CYCLE / STEP).round() as usize;
    let start = Instant::now();
    for k in 1..=steps {
        events.clear();
        model.advance(&inputs, k as f64 * STEP, &mut events).expect("default case");
        count += events.len();
        for e in &events {
            let bits = [e.time, e.normal_velocity_before, e.energy_lost].map(f64::to_bits);
            hash = hash.rotate_left(5) ^ bits[0] ^ bits[1].rotate_left(17) ^ bits[2].rotate_left(31);
        }
    }
    let wall = start.elapsed().as_secs_f64();
    let simulated = steps as f64 * STEP;
    println!("{cycles} cycles: {:.1} ms wall, {:.0}× real time, {count} events, event hash {hash:016x}", wall * 1e3, simulated / wall);
}

fn main() {
    let mut args = std::env::args().skip(1);
    let cycles = args.next().map_or(10, |n| n.parse().expect("a number of cycles"));
    match args.next().as_deref() {
        Some("roller") => run::<Roller>(&Parameters { model_variant: 2, ..Parameters::default() }, cycles),
        None => run::<CrankTrain>(&Parameters::default(), cycles),
        Some(other) => panic!("unknown model {other:?}: give nothing (crank train) or 'roller'"),
    }
}
