//! A&K section 8 through the FMU's model interface: 1200 rpm, 8 MPa peak gauge pressure (built-in
//! four-stroke curve), prescribed crank speed.

use crate::common::*;
use pistonslap::fmus::piston_slap::{Inputs, Parameters};
use pistonslap::models::gas::FourStrokePressure;

fn paper(restitution: f64, bore: f64) -> Parameters {
    Parameters { restitution, bore, ..Parameters::default() }
}

fn inputs() -> Inputs {
    Inputs { crank_speed: SPEED, ..Inputs::default() }
}

/// Contact forces are non-negative in every sample, and zero on open corners.
fn assert_forces_admissible(trace: &Trace) {
    for out in &trace.samples {
        for (force, closed) in forces(out).into_iter().zip(states(out)) {
            assert!(force >= 0.0, "negative contact force {force} N at {} rad", out.crank_angle);
            assert!(closed || force == 0.0, "force {force} N on an open corner");
        }
    }
}

#[test]
fn plastic_impacts_give_six_side_changes_per_cycle_and_mostly_adjoining() {
    let trace = run(&paper(0.0, 0.08008), &inputs(), 2, 2, 1440);
    let changes = side_changes(&trace);
    let fraction = adjoining_fraction(&trace);
    eprintln!("e = 0, D = 0.08008: side changes at {changes:.1?} deg; adjoining {:.0}% of the time", 100.0 * fraction);
    assert_eq!(changes.len(), 12, "six side changes per cycle over two cycles: {changes:.1?}");
    // Steady: the second cycle repeats the first.
    for k in 0..6 {
        assert!((changes[k] - changes[k + 6]).abs() < 2.0, "{changes:.1?}");
    }
    assert!(fraction > 0.5, "adjoining only {fraction}");
    assert_forces_admissible(&trace);
}

#[test]
fn partly_elastic_impacts_bounce_a_few_times_before_each_sliding_phase() {
    let trace = run(&paper(0.5, 0.08008), &inputs(), 2, 2, 1440);
    let changes = side_changes(&trace);
    let landings = impacts_per_landing(&trace.events);
    eprintln!("e = 0.5, D = 0.08008: side changes at {changes:.1?} deg; impacts per landing {landings:?}");
    assert_eq!(changes.len(), 12, "{changes:.1?}");
    let bouncing = landings.iter().filter(|&&n| n >= 2).count();
    assert!(bouncing * 2 >= landings.len(), "most landings should bounce: {landings:?}");
    assert!(landings.iter().all(|&n| n < 100), "accumulation must end in sliding: {landings:?}");
    assert_forces_admissible(&trace);
}

#[test]
fn large_clearance_elastic_impacts_stay_bounded_at_the_same_phases() {
    let plastic = run(&paper(0.0, 0.08008), &inputs(), 2, 1, 1440);
    let reference = side_changes(&plastic);
    let params = paper(0.9, 0.08040);
    let trace = run(&params, &inputs(), 2, 2, 1440);
    // No blow-up: the largest side force of the cycle, acting on the piston alone across the whole
    // clearance, bounds the lateral speed it can build: v = √(2 F (D − d) / m3).
    let side = plastic.samples.iter().map(|o| o.side_force.abs()).fold(0.0, f64::max);
    let scale = (2.0 * side * (params.bore - params.piston_diameter) / params.piston_mass).sqrt();
    let speeds: Vec<f64> = impacts(&trace.events).map(|e| e.normal_velocity_before).collect();
    let max = speeds.iter().cloned().fold(0.0, f64::max);
    let landings = impacts_per_landing(&trace.events);
    eprintln!(
        "e = 0.9, D = 0.08040: {} impacts in 2 cycles, max impact velocity {max:.3} m/s (bound {scale:.3} from side force \
         {side:.0} N), impacts per landing {landings:?}, side changes at {:.1?}",
        speeds.len(),
        side_changes(&trace)
    );
    assert!(max > 0.0 && max < scale, "impact velocity {max} m/s against bound {scale}");
    // Each side change of the plastic case has impacts within 40° of crank angle.
    for angle in reference {
        let near = impacts(&trace.events).any(|e| {
            let d = (e.crank_angle.to_degrees() - angle).rem_euclid(720.0);
            d.min(720.0 - d) < 40.0
        });
        assert!(near, "no impact near {angle:.1} deg");
    }
    assert!(landings.iter().all(|&n| n < 500), "accumulation must end in sliding: {landings:?}");
    assert_forces_admissible(&trace);
}

#[test]
fn host_pressure_gauge_reproduces_the_built_in_curve_and_absolute_pressure_loses_two_side_changes() {
    // DESIGN.md §6.3: the gas force needs the pressure difference across the piston. The host feeds
    // the built-in curve through `gas_pressure`, held over 0.5° steps; then the same plus 1 bar.
    let built_in = side_changes(&run(&paper(0.0, 0.08008), &inputs(), 2, 1, 1440));
    let params = Parameters { pressure_source: 1, ..paper(0.0, 0.08008) };
    let curve = FourStrokePressure::new(params.peak_pressure, params.rod_length / params.crank_radius);
    let host = |offset: f64| {
        let trace = run_with(&params, |angle| Inputs { gas_pressure: curve.gauge(angle) + offset, ..inputs() }, 2, 1, 1440);
        side_changes(&trace)
    };
    let (gauge, absolute) = (host(0.0), host(1e5));
    eprintln!("host pressure: gauge {gauge:.1?}, absolute {absolute:.1?}");
    assert_eq!(gauge.len(), built_in.len());
    for (a, b) in gauge.iter().zip(&built_in) {
        assert!((a - b).abs() < 2.0, "gauge input {gauge:.1?} vs built-in {built_in:.1?}");
    }
    assert_eq!(absolute.len(), 4, "{absolute:.1?}");
}
