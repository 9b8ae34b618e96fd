//! The roller slider crank's outputs: the piston's lateral motion from the rod's swing, the two walls'
//! contact forces, the crank's torque and the kinetic energy, in the crank train's units.

use crate::fmus::piston_slap::Outputs;
use crate::models::roller::{LOWER, UPPER};
use crate::models::Roller;
use std::f64::consts::PI;

/// Writes everything but the impact statistics.
pub(in crate::fmus::piston_slap) fn write(model: &Roller, out: &mut Outputs) {
    let theta = model.stepper.time();
    let psi = model.stepper.position()[0];
    let dpsi = model.stepper.velocity()[0];
    let omega = model.crank_speed;
    let mechanism = model.mechanism();
    let at = mechanism.at(theta);
    let cos_phi = at.cos_phi;
    let l = model.rod_length;
    // Wall force F = M l Ω² λ_core / Λ (the core's multiplier acts on ψ, the wall on y = l Λ ψ).
    let forces = model.stepper.multipliers() * (model.piston_mass * l * omega * omega / cos_phi.value);
    out.piston_lateral = -l * cos_phi.value * psi;
    out.piston_lateral_velocity = -l * omega * (cos_phi.d1 * psi + cos_phi.value * dpsi);
    out.piston_tilt = 0.0;
    // A point slider without gas: its axis is the pin's at every height.
    out.skirt_top_lateral = out.piston_lateral;
    out.skirt_bottom_lateral = out.piston_lateral;
    out.gas_pressure_acting = 0.0;
    out.piston_axial = model.axial_position(theta, psi);
    out.crank_angle = theta + 2.0 * PI * model.turns;
    out.rod_angle = psi - at.rod_angle().value;
    let psi_jet = [psi, dpsi, model.stepper.acceleration()[0]];
    let lambda = model.stepper.system().lambda;
    out.crank_torque = mechanism.drive_torque(theta, psi_jet, lambda) * model.piston_mass * (l * omega).powi(2);
    out.contact_state_1 = i32::from(model.stepper.in_contact(UPPER));
    out.contact_state_2 = 0;
    out.contact_state_3 = i32::from(model.stepper.in_contact(LOWER));
    out.contact_state_4 = 0;
    out.contact_force_1 = forces[UPPER];
    out.contact_force_2 = 0.0;
    out.contact_force_3 = forces[LOWER];
    out.contact_force_4 = 0.0;
    // The −D/2 wall (upper) pushes toward +x.
    out.side_force = forces[UPPER] - forces[LOWER];
    [out.liner_force_antithrust, out.liner_force_thrust] = [forces[UPPER], forces[LOWER]];
    out.lateral_kinetic_energy = 0.5 * model.piston_mass * out.piston_lateral_velocity * out.piston_lateral_velocity;
    out.crank_speed_actual = omega;
    out.running_clearance = 2.0 * model.stepper.system().rho * l;
    out.kinetic_energy = mechanism.kinetic_energy(theta, psi, dpsi) * model.energy_scale() + 0.5 * model.crank_inertia * omega * omega;
}
