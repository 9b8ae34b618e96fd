//! `cargo bench --bench film`: time per `Skirt::loads` call (the lubricated skirt's Reynolds solve on
//! both sides with its loads per unit rate, `Skirt::linearise`, then the loads, asperities and Couette
//! shear at the motion, `Skirt::loads_with`) over a cycle of motions, at the default grid and its neighbours,
//! against the evaluation's flop count. Each figure is the median of several runs.

use pistonslap::models::skirt::{Skirt, SkirtDesign, SkirtMotion, SkirtProfile};
use std::hint::black_box;
use std::time::Instant;

const RUNS: usize = 7;

/// A cycle of plausible motions at 1200 rpm: the pin swinging across most of the 40 µm clearance and
/// tilting, sliding at the stroke's speed.
fn motions() -> Vec<SkirtMotion> {
    let (clearance, omega) = (40e-6, 1200.0 / 60.0 * 2.0 * std::f64::consts::PI);
    (0..360)
        .map(|k| {
            let t = (k as f64).to_radians();
            let (s, c) = (libm::sin(t), libm::cos(t));
            SkirtMotion {
                lateral: 0.8 * clearance * s,
                tilt: 3e-4 * c,
                lateral_rate: 0.8 * clearance * c * omega,
                tilt_rate: -3e-4 * s * omega,
                sliding_speed: 0.04 * omega * libm::sin(t + 0.3),
            }
        })
        .collect()
}

fn main() {
    let motions = motions();
    println!(
        "median of {RUNS} runs over {} motions of a 1200 rpm cycle (default engine geometry, 70° arcs, 20/10 µm barrel)",
        motions.len()
    );
    for grid in [(8, 12), SkirtDesign::DEFAULT_GRID, (16, 24), (32, 48)] {
        let mut design = SkirtDesign::new(0.04004, 0.04, 0.08, 0.04, 0.0, 70f64.to_radians(), 0.01);
        design.profile = SkirtProfile::Parabola { top_drop: 20e-6, bottom_drop: 10e-6 };
        design.grid = grid;
        let skirt = Skirt::new(design).expect("valid design");
        let mut times = Vec::new();
        let mut factorisations = 0;
        for _ in 0..RUNS {
            factorisations = 0;
            let start = Instant::now();
            for m in &motions {
                factorisations += black_box(skirt.loads(black_box(m))).factorisations.iter().sum::<usize>();
            }
            times.push(start.elapsed().as_secs_f64() / motions.len() as f64);
        }
        times.sort_by(f64::total_cmp);
        let time = times[RUNS / 2];
        // Flops: a band Cholesky of n unknowns, half band b, takes ≈ n·b² (n·b²/2 multiply-adds); a
        // forward or back substitution 2·n·b. Each active-set step factorises and substitutes the
        // pressure's right-hand side forward and back; each side's last set substitutes forward the
        // four of `FilmLinear`'s loads per unit rate.
        // An upper bound: a partial refactorisation and the cavitated rows' work are less.
        let (n, b) = ((grid.0 * grid.1) as f64, grid.0.min(grid.1) as f64);
        let per_call = factorisations as f64 / motions.len() as f64;
        let flops = per_call * (n * b * b + 2.0 * 2.0 * n * b) + 2.0 * 4.0 * 2.0 * n * b;
        let marker = if grid == SkirtDesign::DEFAULT_GRID { " (default)" } else { "" };
        println!(
            "grid {:>2}×{:<2}{marker:<10} {:>8.1} µs/call  {:>4.2} factorisations/call  {:>6.2} Mflop/call  {:>5.2} Gflop/s",
            grid.0,
            grid.1,
            time * 1e6,
            per_call,
            flops * 1e-6,
            flops / time * 1e-9
        );
    }
}
