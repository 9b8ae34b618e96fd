//! What the outputs at a communication point say against the model, read from the variable table by name:
//! the same checks whether the outputs come from the model's `Outputs` (`designs.rs`) or through the
//! FMU's fmi2GetReal and fmi2GetInteger (`fmu_designs.rs`).

use pistonslap::fmi::{Causality, Kind};
use pistonslap::fmus::piston_slap::mechanisms::RunningGeometry;
use pistonslap::fmus::piston_slap::{value_reference, DESCRIPTION, VARIABLES};
use pistonslap::fmus::piston_slap::{Inputs, Outputs, Parameters};

/// Deepest a corner may lie outside the bore at a communication point, m: ten times the depth the core
/// refuses at a step's end (measured: 2.6e-10 m at points read from the dense output).
pub const GAP_TOLERANCE: f64 = 1e-9;

/// Outputs that are never negative: speeds of impacts, powers and energies (the impact energies below).
const NON_NEGATIVE: [&str; 5] =
    ["impact_velocity", "max_impact_velocity_in_step", "friction_power", "friction_energy_total", "kinetic_energy"];

/// Totals and counts since the start, which never decrease (energies by more than a relative 1e-12, the
/// round-off of a sum that a step cut at a communication point recomputes; the impact energy below).
const NEVER_DECREASING: [&str; 2] = ["impact_count", "friction_energy_total"];

/// J, how far below zero the impact energy of a step may read: an impact's loss −Λᵀ(ḣ⁻ + ḣ⁺)/2 is
/// (1 − e)/(2(1 + e)) ΛᵀWΛ ≥ 0 with one e for every corner, and exactly 0 at e = 1, where the
/// computed value is round-off of either sign of terms Λ ḣ ≈ 2 m v² (−3.5e-20 J in 10⁴ designs
/// through the FMU, at 1.7e-9 of the kinetic energy left after the step); there it may not exceed
/// a 1e-9 part of the larger of the kinetic energy and the piston's m v² at the step's fastest impact.
fn impact_round_off(p: &Parameters, now: &[f64]) -> f64 {
    if p.restitution == 1.0 {
        let impact = p.piston_mass * get(now, "max_impact_velocity_in_step").powi(2);
        1e-9 * get(now, "kinetic_energy").max(impact)
    } else {
        0.0
    }
}

/// Every Real and Integer output indexed by value reference, as `Host::outputs` reads them.
pub fn of(out: &Outputs) -> Vec<f64> {
    let (p, i) = (&Parameters::default(), &Inputs::default());
    (0u32..)
        .zip(VARIABLES.iter())
        .map(|(r, v)| match (v.causality, v.kind) {
            (Causality::Output, Kind::Real) => (DESCRIPTION.get_real)(r, p, i, out).unwrap_or(f64::NAN),
            (Causality::Output, Kind::Integer) => (DESCRIPTION.get_integer)(r, p, i, out).map_or(f64::NAN, f64::from),
            _ => f64::NAN,
        })
        .collect()
}

fn get(values: &[f64], name: &str) -> f64 {
    values[value_reference(name).expect(name) as usize]
}

/// The gaps of the corners to the bore, m, from the outputs alone. Variant 1: K1..K4 from `piston_lateral`
/// and `piston_tilt` by the documented corner geometry (DESIGN.md §3: K1, K2 on the −D/2 wall at the
/// pin's height and `skirt_length` below it, the pin `pin_offset` toward +x). Variant 2: the roller's `piston_lateral` against the walls at
/// ∓(bore − piston_diameter)/2. Both with the diameters at their running temperatures.
pub fn corner_gaps(p: &Parameters, values: &[f64]) -> Vec<f64> {
    let (lateral, tilt) = (get(values, "piston_lateral"), get(values, "piston_tilt"));
    let hot = RunningGeometry::of(p);
    if p.model_variant == 2 {
        let clearance = (hot.bore - hot.piston_diameter) / 2.0;
        return vec![clearance + lateral, clearance - lateral];
    }
    let (half, a, h, s) = (hot.piston_diameter / 2.0, p.pin_offset, p.pin_height, p.skirt_length);
    let corners = [(h, -(half + a), 1.0), (h - s, -(half + a), 1.0), (h, half - a, -1.0), (h - s, half - a, -1.0)];
    let (sin, cos) = (libm::sin(tilt), libm::cos(tilt));
    corners.iter().map(|&(z, w, side)| hot.bore / 2.0 + side * (lateral - z * sin + w * cos)).collect()
}

/// What the outputs `now` after `before` of a design with parameters `p` say against the model, if
/// anything: a corner outside the bore beyond `GAP_TOLERANCE`, a negative contact force in contact, a
/// negative speed, power or energy, a total or count that decreased.
pub fn contradiction(p: &Parameters, before: &[f64], now: &[f64]) -> Option<String> {
    let gap = corner_gaps(p, now).into_iter().fold(f64::INFINITY, f64::min);
    let force = |i: usize| get(now, &format!("contact_force_{i}"));
    if gap < -GAP_TOLERANCE {
        Some(format!("a corner {gap:e} m outside the bore by the outputs"))
    } else if let Some(i) = (1..=4).find(|&i| get(now, &format!("contact_state_{i}")) == 1.0 && force(i) < 0.0) {
        Some(format!("contact_force_{i} = {} N in contact", force(i)))
    } else if let Some(n) = NON_NEGATIVE.iter().find(|n| get(now, n) < 0.0) {
        Some(format!("{n} = {}", get(now, n)))
    } else if get(now, "impact_energy_in_step") < -impact_round_off(p, now) {
        Some(format!("impact_energy_in_step = {} J beyond round-off ({:e} J)", get(now, "impact_energy_in_step"), impact_round_off(p, now)))
    } else if get(now, "impact_energy_total") < get(before, "impact_energy_total") - impact_round_off(p, now) {
        Some(format!("impact_energy_total fell to {} from {} J", get(now, "impact_energy_total"), get(before, "impact_energy_total")))
    } else {
        let decreased = |n: &&&str| get(now, n) < get(before, n) * (1.0 - 1e-12);
        NEVER_DECREASING.iter().find(decreased).map(|n| format!("{n} fell to {} from {}", get(now, n), get(before, n)))
    }
}
