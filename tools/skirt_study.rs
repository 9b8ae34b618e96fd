//! Dry against lubricated skirt (`skirt_model` 1 and 2) on the default engine at a crank speed,
//! over the engine cycles after the first: the largest impact velocity, the last cycle's slap
//! energy per wall and piston–liner friction mean effective pressure, the thinnest film per side,
//! the film's largest side force and friction force, printed as a markdown table (the wall time,
//! as a real-time factor, on stderr). The table of `documentation/validation/lubricated_skirt.md`:
//! `cargo run --release --example skirt_study -- [rpm] [cycles] [film_relaxation] [step] [grid across] [grid along]`.

use pistonslap::fmus::piston_slap::Simulation;
use pistonslap::fmus::piston_slap::{Inputs, Parameters};
use std::time::Instant;

/// What a run measures after its first cycle.
struct Measured {
    /// Largest impact velocity, m/s.
    fastest: f64,
    /// The last completed cycle's slap energy, anti-thrust and thrust, J.
    slap: [f64; 2],
    /// The last completed cycle's skirt FMEP, Pa.
    fmep: f64,
    /// Thinnest film, thrust and anti-thrust, m.
    thinnest: [f64; 2],
    /// Largest |film_force| and |skirt_friction_force|, N.
    side: f64,
    friction: f64,
}

fn main() {
    let mut args = std::env::args().skip(1).map(|a| a.parse::<f64>().expect("a number"));
    let rpm = args.next().unwrap_or(1200.0);
    let cycles = args.next().unwrap_or(3.0) as usize;
    let relaxation = args.next().unwrap_or(Parameters::default().film_relaxation);
    let step = args.next().unwrap_or(1e-4);
    let defaults = Parameters::default();
    let grid = [
        args.next().map_or(defaults.skirt_grid_circumferential, |n| n as i32),
        args.next().map_or(defaults.skirt_grid_axial, |n| n as i32),
    ];
    let speed = rpm * std::f64::consts::PI / 30.0;
    let inputs = Inputs { crank_speed: speed, ..Inputs::default() };
    let mut runs = Vec::new();
    for skirt_model in [1, 2] {
        let params = Parameters {
            skirt_model,
            film_relaxation: relaxation,
            skirt_grid_circumferential: grid[0],
            skirt_grid_axial: grid[1],
            ..Parameters::default()
        };
        let mut sim: Simulation = Simulation::new(&params, 0.0).expect("the default engine");
        let cycle = 4.0 * std::f64::consts::PI / speed;
        let steps = (cycles as f64 * cycle / step).ceil() as usize;
        let start = Instant::now();
        let mut m = Measured { fastest: 0.0, slap: [0.0; 2], fmep: 0.0, thinnest: [f64::INFINITY; 2], side: 0.0, friction: 0.0 };
        for k in 1..=steps {
            sim.step(&inputs, k as f64 * step).expect("the default engine runs");
            let out = sim.outputs();
            if out.crank_angle < 4.0 * std::f64::consts::PI {
                continue;
            }
            m.fastest = m.fastest.max(out.max_impact_velocity_in_step);
            m.thinnest = [m.thinnest[0].min(out.min_film_thickness_thrust), m.thinnest[1].min(out.min_film_thickness_antithrust)];
            m.side = m.side.max(out.film_force.abs());
            m.friction = m.friction.max(out.skirt_friction_force.abs());
            m.slap = [out.cycle_slap_energy_antithrust, out.cycle_slap_energy_thrust];
            m.fmep = out.cycle_skirt_fmep;
        }
        eprintln!("{rpm} rpm, skirt_model {skirt_model}: {:.2}× real time", steps as f64 * step / start.elapsed().as_secs_f64());
        runs.push(m);
    }
    let row = |label: &str, cell: &dyn Fn(&Measured) -> String| println!("| {label} | {} | {} |", cell(&runs[0]), cell(&runs[1]));
    // A dry corner's gap in contact is zero to the contact tolerance, either side of it.
    let um = |m: f64| format!("{:.2} µm", m * 1e6).replace("-0.00", "0.00");
    let joules = |e: f64| if e == 0.0 { "0".to_string() } else { format!("{e:.3e}") };
    println!("| {rpm} rpm, cycles 2–{cycles} | dry | lubricated |");
    println!("|---|---|---|");
    row("largest impact velocity", &|m| if m.fastest > 0.0 { format!("{:.3} m/s", m.fastest) } else { "none".to_string() });
    row("slap energy of the last cycle, anti-thrust / thrust", &|m| format!("{} / {} J", joules(m.slap[0]), joules(m.slap[1])));
    row("skirt FMEP", &|m| format!("{:.5} bar", m.fmep * 1e-5));
    row("thinnest film, thrust / anti-thrust", &|m| format!("{} / {}", um(m.thinnest[0]), um(m.thinnest[1])));
    row("film side force, peak", &|m| format!("{:.1} N", m.side));
    row("skirt friction force, peak", &|m| format!("{:.2} N", m.friction));
}
