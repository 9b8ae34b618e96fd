//! The Flores–Leine–Glocker slider crank with translational clearance (`../shared/benchmarks/
//! flores-slider-crank.md`, Siconos' `SliderCrank` example) on the crank train: the flat slider
//! against Siconos' published figures, the tilting slider at three communication steps.

use crate::common::designs::flores;
use crate::common::flores::{published, run, Run};
use pistonslap::fmus::piston_slap::Parameters;

/// The flat slider against Siconos Moreau–Jean extrapolated to h → 0: 2.890957 revolutions at
/// 0.2 s and 4.8013 % of the kinetic energy dissipated, to 1e-4; at h = 2e-7, 148 impacts faster
/// than 1 mm/s (34/34/40/40 on Flores' F1..F4, which are K2, K1, K4, K3), 102 faster than 1 cm/s
/// and 56 faster than 10 cm/s.
#[test]
fn flat_slider_matches_siconos() {
    let r = run(&flores(0.0), 1e-4);
    assert!((r.revolutions / 2.890957 - 1.0).abs() < 1e-4, "{} revolutions", r.revolutions);
    let percent = 100.0 * r.dissipated() / r.kinetic[0];
    assert!((percent / 4.8013 - 1.0).abs() < 1e-4, "{percent} % dissipated");
    assert_eq!(r.impacts_faster_than(1e-3), [34, 34, 40, 40]);
    assert_eq!(r.impacts_faster_than(1e-2).iter().sum::<usize>(), 102);
    assert_eq!(r.impacts_faster_than(1e-1).iter().sum::<usize>(), 56);
}

/// The initial kinetic energy in closed form: at top dead centre the pin is at rest, the crank
/// turns at ω about its axis and the rod at φ̇2 = −l1 ω / l2 about the pin:
/// T = ½ (J1 + m1 ey1²) ω² + ½ (J2 + m2 (l2 − ey2)²) φ̇2² (+ ½ J3 φ̇3² with a tilt rate).
#[test]
fn initial_kinetic_energy_is_the_closed_form() {
    let params = Parameters { piston_tilt_rate_start: -0.01, ..flores(0.0) };
    let r = run(&params, 1e-2);
    let (w, rod_rate) = (150.0, -0.153 * 150.0 / 0.306);
    let expected = 0.5 * (7.4e-5 + 0.038 * 0.0765_f64.powi(2)) * w * w
        + 0.5 * (5.9e-4 + 0.038 * 0.153_f64.powi(2)) * rod_rate * rod_rate
        + 0.5 * 2.7e-6 * 1e-4;
    assert!((r.kinetic[0] / expected - 1.0).abs() < 1e-14, "{} J against {expected} J", r.kinetic[0]);
}

/// The slider tilts (centre of mass 1 cm off the pin): it pivots on one corner while the other of
/// the same side lifts. It runs at 1e-3, 1e-4 and 1e-5 s steps with the same impacts and
/// revolutions, and the energy balance closes: T(0) = T(0.2 s) + the energy the impacts and
/// sliding starts dissipated (no damping, gas or gravity).
#[test]
fn tilting_slider_runs_and_converges_with_the_step() {
    let runs: Vec<Run> = [1e-3, 1e-4, 1e-5].into_iter().map(|step| run(&flores(0.01), step)).collect();
    for r in &runs {
        let balance = (r.kinetic[0] - r.kinetic[1] - r.dissipated()) / r.kinetic[0];
        assert!(balance.abs() < 1e-7, "energy balance off by {balance:e}");
        assert!((r.revolutions / runs[2].revolutions - 1.0).abs() < 1e-7, "{} against {}", r.revolutions, runs[2].revolutions);
        assert_eq!(r.impacts_faster_than(1e-3), runs[2].impacts_faster_than(1e-3));
    }
    assert!(runs[2].impacts_faster_than(1e-3).iter().sum::<usize>() > 100, "it does hit the liner");
}

/// The published case at 1e-3, 1e-4 and 1e-5 s communication steps: Siconos' revolutions and
/// dissipated fraction, the same motion at every step (the crank's revolutions agree to 1e-9, the
/// impacts one for one), and the energy balance closed by what the
/// impacts and the sliding friction dissipated: `E₀ − E = Σ impact losses + sliding friction`, with
/// E kinetic plus potential in the lateral gravity, to 1e-7 of E₀ (the frictionless slider closes
/// its balance to 5e-8 at 1e-5 s steps: the drift projections of the held contacts).
#[test]
fn published_case_converges_with_the_step_and_balances_its_energy() {
    let runs: Vec<(Run, f64)> = [1e-3_f64, 1e-4, 1e-5]
        .into_iter()
        .map(|step| {
            let r = run(&published(), step);
            let balance = (r.mechanical[0] - r.mechanical[1] - r.lost()) / r.mechanical[0];
            assert!(balance.abs() < 1e-7, "step {step}: balance {balance:e}");
            assert!(r.friction > 0.0 && r.impact_friction() > 0.0, "friction dissipates in sliding and impacts");
            let fraction = r.lost() / r.mechanical[0];
            (r, fraction)
        })
        .collect();
    let (first, fraction) = &runs[0];
    for (r, f) in &runs[1..] {
        assert!((r.revolutions - first.revolutions).abs() < 1e-9, "{} vs {}", r.revolutions, first.revolutions);
        assert!((f - fraction).abs() < 1e-8, "dissipated {f} vs {fraction}");
        assert_eq!(r.impacts_faster_than(1e-3), first.impacts_faster_than(1e-3));
    }
    // Siconos Moreau–Jean on the same case (its SliderCrank example with the published μ, gravity
    // and tilt rate; h = 1e-6 … 5e-8 s, run for this test): 2.87828, 2.87808, 2.87803 revolutions
    // at h = 2e-7, 1e-7, 5e-8 (≈ 2.87801 as h → 0) and 6.644, 6.668, 6.675 % of E₀ dissipated
    // (≈ 6.68 %). Its first-order error at those steps is ≈ 1e-4 of the revolutions.
    assert!((first.revolutions / 2.87801 - 1.0).abs() < 1e-4, "{} revolutions", first.revolutions);
    assert!((100.0 * fraction - 6.68).abs() < 0.03, "{} % dissipated", 100.0 * fraction);
    eprintln!(
        "published case: {:.9} revolutions, {:.5} % dissipated, impacts > 1 mm/s {:?}",
        first.revolutions,
        100.0 * fraction,
        first.impacts_faster_than(1e-3)
    );
}

/// Friction μ → 0 on the frictional paths (the core's friction solve with μ = 1e-12) gives the
/// frictionless flat slider: its revolutions to 1e-9, the same impacts.
#[test]
fn vanishing_friction_gives_the_frictionless_slider() {
    let (frictionless, tiny) = (run(&flores(0.0), 1e-4), run(&Parameters { friction: 1e-12, ..flores(0.0) }, 1e-4));
    assert!((tiny.revolutions - frictionless.revolutions).abs() < 1e-9, "{} vs {}", tiny.revolutions, frictionless.revolutions);
    assert_eq!(tiny.impacts_faster_than(1e-3), frictionless.impacts_faster_than(1e-3));
    assert!((tiny.dissipated() / frictionless.dissipated() - 1.0).abs() < 1e-8);
}
