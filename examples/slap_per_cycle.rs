//! Using the crate without an FMI host: the default engine at a crank speed of your choice, stepped at
//! 1 ms as a host would, printing per engine cycle what the FMU's `cycle_*` outputs report — the slaps
//! per wall and the largest slap energy — and the energy all its impacts dissipated.
//! `cargo run --release --example slap_per_cycle -- [rpm] [cycles]` (default 3000 rpm, 4 cycles).

use pistonslap::fmus::piston_slap::Simulation;
use pistonslap::fmus::piston_slap::{Inputs, Parameters};
use std::f64::consts::PI;

fn main() {
    let mut args = std::env::args().skip(1).map(|a| a.parse::<f64>());
    let (rpm, cycles) = match (args.next().unwrap_or(Ok(3000.0)), args.next().unwrap_or(Ok(4.0))) {
        (Ok(rpm), Ok(cycles)) if rpm > 0.0 && cycles >= 1.0 => (rpm, cycles as usize),
        _ => {
            eprintln!("usage: slap_per_cycle [rpm > 0] [cycles ≥ 1]");
            std::process::exit(2);
        }
    };
    let inputs = Inputs { crank_speed: rpm * PI / 30.0, ..Inputs::default() };
    let mut sim: Simulation = Simulation::new(&Parameters::default(), 0.0).unwrap_or_else(|e| {
        eprintln!("{e}");
        std::process::exit(2);
    });
    let (step, cycle_time) = (1e-3, 4.0 * PI / inputs.crank_speed);
    let steps = (cycles as f64 * cycle_time / step).ceil() as usize;
    println!("cycle  slaps anti-thrust/thrust  largest slap energy anti-thrust/thrust [mJ]  impact energy [mJ]");
    let mut reported = 0;
    for k in 1..=steps {
        if let Err(e) = sim.step(&inputs, k as f64 * step) {
            eprintln!("t = {:.4} s: {e}", sim.time());
            std::process::exit(1);
        }
        // The cycle outputs describe the last completed cycle: print each once, when it completes.
        let out = sim.outputs();
        if out.cycle_count > reported {
            reported = out.cycle_count;
            println!(
                "{:5}  {:11} / {:<6}  {:22.3} / {:<19.3}  {:.3}",
                out.cycle_count,
                out.cycle_slaps_antithrust,
                out.cycle_slaps_thrust,
                out.cycle_max_slap_energy_antithrust * 1e3,
                out.cycle_max_slap_energy_thrust * 1e3,
                out.cycle_impact_energy * 1e3
            );
        }
    }
}
