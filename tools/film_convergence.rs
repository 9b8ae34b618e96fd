//! The lubricated default engine (`skirt_model = 2`) at a crank speed, one warm-up cycle and one
//! measured, for each film relaxation τ and film grid given: the thinnest film per side, the skirt
//! FMEP, the largest film side force and skirt friction force of the measured cycle, their
//! differences from the first configuration (the reference), printed as a markdown table (the wall
//! time per cycle on stderr). The tables of `documentation/validation/lubricated_skirt.md`:
//! `cargo run --release --example film_convergence -- RPM TAU:NC:NA [TAU:NC:NA …]`.

use pistonslap::fmus::piston_slap::Simulation;
use pistonslap::fmus::piston_slap::{Inputs, Parameters};
use std::time::Instant;

/// Communication points per cycle (0.5° of crank angle), where the extremes are sampled.
const POINTS: usize = 1440;

/// What one run measures over its second cycle.
struct Measured {
    /// Thinnest film, thrust and anti-thrust, m.
    film: [f64; 2],
    /// Skirt FMEP, Pa.
    fmep: f64,
    /// Largest |film_force|, N.
    side: f64,
    /// Largest |skirt_friction_force|, N.
    friction: f64,
    /// Wall time per cycle, s.
    wall: f64,
}

fn run(rpm: f64, relaxation: f64, grid: (i32, i32)) -> Measured {
    let speed = rpm * std::f64::consts::PI / 30.0;
    let inputs = Inputs { crank_speed: speed, ..Inputs::default() };
    let params = Parameters {
        skirt_model: 2,
        film_relaxation: relaxation,
        skirt_grid_circumferential: grid.0,
        skirt_grid_axial: grid.1,
        ..Parameters::default()
    };
    let mut sim: Simulation = Simulation::new(&params, 0.0).expect("the default engine");
    let dt = 4.0 * std::f64::consts::PI / speed / POINTS as f64;
    let mut m = Measured { film: [f64::INFINITY; 2], fmep: 0.0, side: 0.0, friction: 0.0, wall: 0.0 };
    let start = Instant::now();
    // Two points past the cycle's end: its FMEP is booked once the cycle boundary lies behind.
    for k in 1..=2 * POINTS + 2 {
        sim.step(&inputs, k as f64 * dt).expect("the default engine runs");
        if k <= POINTS || k > 2 * POINTS {
            continue;
        }
        let out = sim.outputs();
        m.film = [m.film[0].min(out.min_film_thickness_thrust), m.film[1].min(out.min_film_thickness_antithrust)];
        m.side = m.side.max(out.film_force.abs());
        m.friction = m.friction.max(out.skirt_friction_force.abs());
    }
    m.wall = start.elapsed().as_secs_f64() / 2.0;
    m.fmep = sim.outputs().cycle_skirt_fmep;
    m
}

fn main() {
    let mut args = std::env::args().skip(1);
    let rpm: f64 = args.next().and_then(|a| a.parse().ok()).expect("RPM first");
    let configurations: Vec<(f64, (i32, i32))> = args
        .map(|a| {
            let v: Vec<&str> = a.split(':').collect();
            let parse = |s: &str| s.parse::<f64>().expect("TAU:NC:NA");
            (parse(v[0]), (parse(v[1]) as i32, parse(v[2]) as i32))
        })
        .collect();
    println!("| {rpm} rpm, τ, grid | film thrust / anti-thrust | FMEP | peak side force | peak friction |");
    println!("|---|---|---|---|---|");
    let mut reference: Option<Measured> = None;
    for (tau, grid) in configurations {
        let m = run(rpm, tau, grid);
        let label = format!("{tau:e} s, {} × {}", grid.0, grid.1);
        match &reference {
            None => println!(
                "| {label} | {:.3} / {:.3} µm | {:.5} bar | {:.1} N | {:.2} N |",
                m.film[0] * 1e6,
                m.film[1] * 1e6,
                m.fmep * 1e-5,
                m.side,
                m.friction
            ),
            Some(r) => {
                let relative = |a: f64, b: f64| format!("{:+.2} %", 100.0 * (a / b - 1.0)).replace('-', "−");
                println!(
                    "| {label} | {} / {} | {} | {} | {} |",
                    relative(m.film[0], r.film[0]),
                    relative(m.film[1], r.film[1]),
                    relative(m.fmep, r.fmep),
                    relative(m.side, r.side),
                    relative(m.friction, r.friction)
                );
            }
        }
        eprintln!("{label}: {:.2} s wall per cycle", m.wall);
        reference.get_or_insert(m);
    }
}
