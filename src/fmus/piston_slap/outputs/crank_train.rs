//! The crank train's outputs: the pin's and the piston's motion, the corners' contact and friction
//! forces, the crank's torque and speed, the energy books' totals and the running clearance; the
//! skirt's against the liner in `skirt.rs`.

use super::skirt;
use crate::fmus::piston_slap::Outputs;
use crate::models::crank_train::books::{DAMPING, DRIVE, GAS};
use crate::models::CrankTrain;
use std::f64::consts::PI;

/// Writes everything but the impact statistics.
pub(in crate::fmus::piston_slap) fn write(model: &CrankTrain, out: &mut Outputs) {
    // The sines and cosines once, of the angle within the cycle (what the stepper holds; at a point
    // those its evaluation took).
    let (phi, phid) = model.state_within_cycle();
    let stepper = model.drive.stepper();
    let trig = stepper.link_angles(&phi);
    let linkage = &model.engine().linkage;
    let (pin, gaps) = linkage.pin_and_gaps(&trig);
    let (forces, in_contact) = model.contacts();
    let (friction, friction_power, friction_energy) = model.friction();
    out.piston_lateral = pin.x;
    // ẋ_O3 = −l1 cos φ1 φ̇1 − l2 cos φ2 φ̇2.
    out.piston_lateral_velocity = -model.geometry.crank_radius * trig.cos[0] * phid[0] - model.geometry.rod_length * trig.cos[1] * phid[1];
    out.piston_tilt = phi[2];
    out.piston_tilt_rate = phid[2];
    out.lateral_kinetic_energy = linkage.lateral_kinetic_energy(&trig, &phid);
    // The piston axis at a corner pair's height is midway between the two corners, whose gaps
    // from their walls are D/2 + x (K1, K2) and D/2 − x (K3, K4).
    out.skirt_top_lateral = 0.5 * (gaps[0] - gaps[2]);
    out.skirt_bottom_lateral = 0.5 * (gaps[1] - gaps[3]);
    out.gas_pressure_acting = stepper.gas_pressure(phi[0]);
    out.piston_axial = pin.y;
    out.crank_angle = phi[0] + 4.0 * PI * model.cycles;
    out.rod_angle = phi[1];
    out.crank_torque = stepper.crank_torque(&forces, &friction);
    [out.contact_state_1, out.contact_state_2, out.contact_state_3, out.contact_state_4] = in_contact.map(i32::from);
    [out.contact_force_1, out.contact_force_2, out.contact_force_3, out.contact_force_4] = [forces[0], forces[1], forces[2], forces[3]];
    out.crank_speed_actual = stepper.crank_speed(phid[0]);
    (out.kinetic_energy, out.potential_energy) = linkage.energy_with(&trig, &phi, &phid);
    let contact = model.contact_impulse();
    out.liner_impulse_total = std::array::from_fn(|w| contact[w] + model.impact_impulse[w]);
    [out.friction_force_1, out.friction_force_2, out.friction_force_3, out.friction_force_4] = friction.into();
    (out.friction_power, out.friction_energy_total) = (friction_power, friction_energy);
    let books = stepper.energies();
    out.drive_work_total = books[DRIVE] + model.impulse_work;
    (out.gas_work_total, out.damping_energy_total) = (books[GAS], books[DAMPING]);
    out.running_clearance = model.running_clearance;
    skirt::write(model, (&phi, &trig, &phid), &gaps, &forces, out);
}
