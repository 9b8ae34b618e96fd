//! The Flores–Leine–Glocker slider crank with translational clearance (`tests/common/designs.rs`
//! `flores`, the mapping; `tests/crank_train/flores_benchmark.rs`, the assertions) run for 0.2 s at
//! communication steps of 1e-3, 1e-4 and 1e-5 s, printed as the two tables of
//! `documentation/validation/flores_benchmark.md` beside Siconos' Moreau–Jean figures:
//! `cargo run --release --example flores_benchmark`.

#[allow(dead_code)]
#[path = "../tests/common/designs.rs"]
mod designs;
#[path = "../tests/common/flores.rs"]
mod flores;
#[allow(dead_code)]
#[path = "../tests/common/output_checks.rs"]
mod output_checks;

use flores::{published, run, Run};
use pistonslap::fmus::piston_slap::Parameters;

/// The communication steps, s.
const STEPS: [f64; 3] = [1e-3, 1e-4, 1e-5];

/// A row: the label, the figure at each step, the reference.
fn row(label: &str, runs: &[Run], figure: impl Fn(&Run) -> String, reference: &str) {
    let cells: Vec<String> = runs.iter().map(figure).collect();
    println!("| {label} | {} | {reference} |", cells.join(" | "));
}

fn header(reference: &str) {
    println!("| | PistonSlap, 1e-3 s steps | 1e-4 s | 1e-5 s | {reference} |");
    println!("|---|---|---|---|---|");
}

fn main() {
    let runs = |params: Parameters| -> Vec<Run> { STEPS.iter().map(|&step| run(&params, step)).collect() };
    let percent = |r: &Run| 100.0 * r.lost() / r.mechanical[0];

    let flat = runs(designs::flores(0.0));
    let tilting = runs(designs::flores(0.01));
    header("Siconos Moreau–Jean, h → 0");
    row("flat slider: revolutions", &flat, |r| format!("{:.7}", r.revolutions), "2.890957");
    row("flat slider: kinetic energy dissipated", &flat, |r| format!("{:.5} %", percent(r)), "4.8013 %");
    let corners = |r: &Run| r.impacts_faster_than(1e-3).map(|n| n.to_string()).join("/");
    row("flat slider: impacts > 1 mm/s on K1/K2/K3/K4", &flat, corners, "34/34/40/40 (F2/F1/F4/F3)");
    let faster = |r: &Run| {
        let count = |v| r.impacts_faster_than(v).iter().sum::<usize>();
        format!("{}, {}", count(1e-2), count(1e-1))
    };
    row("flat slider: impacts > 1 cm/s, > 10 cm/s", &flat, faster, "102, 56");
    row("tilting slider (centre of mass 1 cm off the pin): revolutions", &tilting, |r| format!("{:.7}", r.revolutions), "runs");
    let tilted = |r: &Run| format!("{:.5} %, {}", percent(r), r.impacts_faster_than(1e-3).iter().sum::<usize>());
    row("tilting slider: dissipated, impacts > 1 mm/s", &tilting, tilted, "");

    println!();
    let published = published();
    let gravity_only = Parameters { friction: 0.0, ..published.clone() };
    let friction_only = Parameters { gravity_lateral: 0.0, ..published.clone() };
    let published = runs(published);
    header("Siconos Moreau–Jean (h = 2e-7, 1e-7, 5e-8 s → 0)");
    row("revolutions", &published, |r| format!("{:.6}", r.revolutions), "2.87828, 2.87808, 2.87803 → ≈ 2.87801");
    row("energy dissipated (of kinetic + potential)", &published, |r| format!("{:.3} %", percent(r)), "6.644, 6.668, 6.675 % → ≈ 6.68 %");
    row("final kinetic energy / initial", &published, |r| format!("{:.5}", r.kinetic[1] / r.kinetic[0]), "≈ 0.9385");
    let both = |r: &Run| format!("{:.5}, {:.2} %", r.revolutions, percent(r));
    row("gravity only (μ = 0): revolutions, dissipated", &runs(gravity_only), both, "≈ 2.8929, 4.58 %");
    row("friction only (no gravity): revolutions, dissipated", &runs(friction_only), both, "≈ 2.8762, 7.07 %");
}
