//! PistonSlap's parameters as the roller's typed design, with the conditions of the thesis's model (prescribed speed, no skirt, a small clearance, the
//! nominal start, frictionless walls, a vertical cylinder), each refused by the parameter's name.

use super::running_geometry::RunningGeometry;
use super::Parameters;
use crate::models::{Forcing, ModelError, RollerDesign, RollerMechanism};

/// The roller of `params`: the table's ranges, then the model's conditions, at running temperature.
pub fn design(params: &Parameters) -> Result<RollerDesign, ModelError> {
    let variant = |e: ModelError| ModelError(format!("model_variant 2: {e}"));
    params.validate().map_err(variant)?;
    // The bore and piston diameter at their running temperatures.
    let p = &RunningGeometry::apply(params).map_err(variant)?;
    let clearance = (p.bore - p.piston_diameter) / 2.0;
    require(p.crank_mode == 1, "crank_mode", "1 (the thesis's crank turns at a prescribed speed)")?;
    require(p.skirt_model == 1, "skirt_model", "1 (the roller has no skirt to lubricate)")?;
    // The model is linear in ψ ≤ ρ/Λ: beyond a few degrees it no longer describes the mechanism.
    require(clearance <= 0.05 * p.rod_length, "bore", "larger than piston_diameter by at most 10 % of rod_length")?;
    for (name, value) in [
        ("piston_lateral_start", p.piston_lateral_start),
        ("piston_lateral_velocity_start", p.piston_lateral_velocity_start),
        ("piston_tilt_start", p.piston_tilt_start),
        ("piston_tilt_rate_start", p.piston_tilt_rate_start),
        ("friction", p.friction),
        ("gravity_lateral", p.gravity_lateral),
    ] {
        require(
            value == 0.0,
            name,
            "0 (the roller starts on its nominal path, ψ = ψ' = 0; its walls are frictionless and its cylinder vertical)",
        )?;
    }
    let (l, mass) = (p.rod_length, p.piston_mass);
    Ok(RollerDesign {
        mechanism: RollerMechanism {
            xi: p.crank_radius / l,
            alpha: p.rod_mass / mass,
            beta: p.rod_inertia / (mass * l * l),
            forcing: if p.roller_forcing == 1 { Forcing::Printed } else { Forcing::Corrected },
        },
        half_clearance: clearance,
        restitution: p.restitution,
        crank_angle: p.crank_angle_start,
        crank_radius: p.crank_radius,
        rod_length: l,
        piston_mass: mass,
        damping: p.damping_crank_pin,
        crank_inertia: p.crank_inertia + p.crank_mass * p.crank_com * p.crank_com,
    })
}

fn require(ok: bool, name: &str, range: &str) -> Result<(), ModelError> {
    if ok {
        Ok(())
    } else {
        Err(ModelError(format!("model_variant 2: parameter {name} must be {range}")))
    }
}
