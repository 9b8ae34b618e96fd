//! Dry against lubricated skirt (`skirt_model` 1 and 2) on the default engine at a crank speed:
//! per engine cycle after the first, the largest impact velocity, the slap energy per wall, the
//! piston–liner friction mean effective pressure, the smallest film per side, the film's largest
//! side force and friction force; the wall time as a real-time factor. The figures of
//! `documentation/design/lubricated_skirt.md`:
//! `cargo run --release --example skirt_study -- [rpm] [cycles] [film_relaxation] [step] [grid across] [grid along]`.

use pistonslap::fmus::piston_slap::Simulation;
use pistonslap::models::{Inputs, Parameters};
use std::time::Instant;

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
        let (mut fastest, mut thinnest, mut side, mut friction, mut completed) = (0.0_f64, [f64::INFINITY; 2], 0.0_f64, 0.0_f64, 0);
        for k in 1..=steps {
            sim.step(&inputs, k as f64 * step).expect("the default engine runs");
            let out = sim.outputs();
            if out.crank_angle < 4.0 * std::f64::consts::PI {
                continue;
            }
            fastest = fastest.max(out.max_impact_velocity_in_step);
            thinnest = [thinnest[0].min(out.min_film_thickness_thrust), thinnest[1].min(out.min_film_thickness_antithrust)];
            side = side.max(out.film_force.abs());
            friction = friction.max(out.skirt_friction_force.abs());
            if out.cycle_count > completed {
                completed = out.cycle_count;
                if completed >= 2 {
                    println!(
                        "  cycle {completed}: slap energy anti-thrust {:.6e} J, thrust {:.6e} J, FMEP {:.6} bar, film {:.6e} J total",
                        out.cycle_slap_energy_antithrust,
                        out.cycle_slap_energy_thrust,
                        out.cycle_skirt_fmep * 1e-5,
                        out.film_energy_total
                    );
                }
            }
        }
        let wall = start.elapsed().as_secs_f64();
        println!(
            "{rpm} rpm, skirt_model {skirt_model}: largest impact {fastest:.6} m/s, thinnest film thrust {:.4} µm, anti-thrust {:.4} µm, \
             film side force up to {side:.2} N, skirt friction up to {friction:.3} N; {:.2}× real time",
            thinnest[0] * 1e6,
            thinnest[1] * 1e6,
            steps as f64 * step / wall
        );
    }
}
