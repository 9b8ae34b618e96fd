//! Work and energy of the crank train: conservation in free-crank mode, the drive torque's work in
//! prescribed mode, the rigid slider-crank limit and the efficiency calibration (A&K eqs 40–54).

use crate::common::*;
use nalgebra::Vector3;
use pistonslap::fmus::piston_slap::mechanisms;
use pistonslap::fmus::piston_slap::Mechanism;
use pistonslap::fmus::piston_slap::{Inputs, Outputs, Parameters};
use pistonslap::models::crank_train::kinematics::SliderCrank;
use pistonslap::models::crank_train::linkage::{Linkage, Loads};
use pistonslap::models::gas::FourStrokePressure;
use pistonslap::models::{CrankTrain, EfficiencyTarget, EnergyBalance};
use std::f64::consts::PI;

fn conservative(crank_mode: i32) -> Parameters {
    Parameters {
        crank_mode,
        pressure_source: 1,
        damping_main: 0.0,
        damping_crank_pin: 0.0,
        damping_piston_pin: 0.0,
        ..Parameters::default()
    }
}

#[test]
fn free_crank_with_elastic_impacts_conserves_energy() {
    let params = Parameters { restitution: 1.0, ..conservative(2) };
    let inputs = Inputs { crank_speed: SPEED, gas_pressure: 0.0, load_torque: 0.0 };
    let mut model = CrankTrain::new(&params, 0.0).unwrap();
    let mut events = Vec::new();
    model.advance(&inputs, 1e-6, &mut events).unwrap();
    let start = model.mechanical_energy();
    let steps = 400;
    let mut worst: f64 = 0.0;
    for k in 1..=steps {
        model.advance(&inputs, 1e-6 + k as f64 * CYCLE / steps as f64, &mut events).unwrap();
        worst = worst.max((model.mechanical_energy() - start).abs());
    }
    let count = impacts(&events).count();
    // The lateral kinetic energy at stake in an impact: piston mass at the impact speeds seen.
    let fastest = impacts(&events).map(|e| e.normal_velocity_before).fold(0.0, f64::max);
    let lateral = 0.5 * params.piston_mass * fastest * fastest;
    eprintln!("free crank, e = 1: {count} impacts, energy {start:.3} J, worst drift {worst:.3e} J, lateral scale {lateral:.3e} J");
    assert!(count > 0, "the piston should hit the liner");
    assert!(worst < 1e-3 * lateral, "energy drift {worst} J against lateral impact energy {lateral} J");
    let lost: f64 = events.iter().map(|e| e.energy_lost).sum();
    assert!(lost.abs() < 1e-6 * lateral, "elastic impacts dissipated {lost} J");
}

#[test]
fn drive_work_equals_the_energy_change_without_contact() {
    // A bore so wide that the piston does not touch for the first 20 ms: rod and piston swing freely on
    // the turning crank (contact impulses would add drive work the sampled torque cannot show).
    let params = Parameters { bore: 0.11, ..conservative(1) };
    let inputs = Inputs { crank_speed: SPEED, ..Inputs::default() };
    let mut model = CrankTrain::new(&params, 0.0).unwrap();
    let mut events = Vec::new();
    let steps = 2000;
    let dt = 0.02 / steps as f64;
    let torque = |m: &CrankTrain| {
        let mut out = Outputs::default();
        m.write_outputs(&mut out);
        out.crank_torque
    };
    model.advance(&inputs, 1e-9, &mut events).unwrap();
    let start = model.mechanical_energy();
    let (mut work, mut previous, mut swing) = (0.0, torque(&model), 0.0f64);
    for k in 1..=steps {
        model.advance(&inputs, 1e-9 + k as f64 * dt, &mut events).unwrap();
        let now = torque(&model);
        work += 0.5 * (previous + now) * SPEED * dt;
        previous = now;
        swing = swing.max((model.mechanical_energy() - start).abs());
    }
    let change = model.mechanical_energy() - start;
    eprintln!("no contact: drive work {work:.6} J, energy change {change:.6} J, swing {swing:.3} J");
    assert!(events.is_empty(), "no contact expected, got {} events", events.len());
    assert!(swing > 1.0, "the test needs a real energy exchange");
    assert!((work - change).abs() < 1e-5 * swing, "work {work} J vs energy change {change} J");
}

/// Drive torque of the rigid slider crank (no clearance, no tilt) at constant speed ω, from the virtual
/// work of the linkage equations along the one admissible direction Φ′ = (1, φ2′, 0).
fn rigid_torque(linkage: &Linkage, geometry: &SliderCrank, angle: f64, speed: f64, gas_force: f64) -> f64 {
    let s = geometry.at(angle);
    let direction = Vector3::new(1.0, s.rod_rate, 0.0);
    let phi = Vector3::new(angle, s.rod_angle, 0.0);
    let ev = linkage.evaluate(&phi, &(direction * speed), Loads { gas_force, load_torque: 0.0 });
    let acceleration = Vector3::new(0.0, s.rod_curvature * speed * speed, 0.0);
    direction.dot(&(ev.mass * acceleration - ev.force))
}

#[test]
fn tiny_clearance_follows_the_rigid_slider_crank() {
    let params = Parameters { bore: 0.080002, restitution: 0.0, ..Parameters::default() };
    let inputs = Inputs { crank_speed: SPEED, ..Inputs::default() };
    let trace = run(&params, &inputs, 1, 1, 1440);
    let linkage = mechanisms::crank_train::linkage(&params);
    let geometry = SliderCrank { crank_radius: params.crank_radius, rod_length: params.rod_length, pin_offset: 0.0 };
    let curve = FourStrokePressure::new(params.peak_pressure, params.rod_length / params.crank_radius);
    let area = 0.25 * PI * params.piston_diameter.powi(2);
    let (mut squared_error, mut squared) = (0.0, 0.0);
    let mut worst_rod: f64 = 0.0;
    for out in &trace.samples {
        let expected = rigid_torque(&linkage, &geometry, out.crank_angle, SPEED, curve.gauge(out.crank_angle) * area);
        squared_error += (out.crank_torque - expected).powi(2);
        squared += expected.powi(2);
        worst_rod = worst_rod.max((out.rod_angle - geometry.at(out.crank_angle).rod_angle).abs());
    }
    let relative = (squared_error / squared).sqrt();
    eprintln!(
        "D − d = 2 µm: rms torque deviation {:.2e} of rms torque {:.1} N·m; worst rod angle deviation {worst_rod:.2e} rad",
        relative,
        (squared / trace.samples.len() as f64).sqrt()
    );
    assert!(relative < 0.02, "drive torque departs from the rigid slider crank by {relative}");
    // The pin stays within the clearance: |Δφ2| ≤ (D − d) / (2 l2 cos φ2) plus the tilt's share.
    assert!(worst_rod < 2e-5, "rod angle deviates by {worst_rod} rad");
}

#[test]
fn calibrated_load_and_damping_balance_the_gas_work_over_a_cycle() {
    let base = Parameters { crank_mode: 2, ..Parameters::default() };
    let geometry = SliderCrank { crank_radius: base.crank_radius, rod_length: base.rod_length, pin_offset: 0.0 };
    let curve = FourStrokePressure::new(base.peak_pressure, base.rod_length / base.crank_radius);
    let area = 0.25 * PI * base.piston_diameter.powi(2);
    let cal = EfficiencyTarget::default().calibrate(&geometry, area, |a| curve.gauge(a)).unwrap();
    eprintln!("built-in curve: L_F = {:.1} J, M0 = {:.2} N·m, c1 = {:.5} N·m·s", cal.gas_work, cal.load_torque, cal.damping[0]);
    let params = Parameters { damping_main: cal.damping[0], damping_crank_pin: cal.damping[1], damping_piston_pin: cal.damping[2], ..base };
    let inputs = Inputs { crank_speed: SPEED, gas_pressure: 0.0, load_torque: cal.load_torque };
    let mut model = CrankTrain::new(&params, 0.0).unwrap();
    let mut events = Vec::new();
    model.advance(&inputs, 1e-9, &mut events).unwrap();
    let start = model.mechanical_energy();
    // One cycle: step until the crank passes 4π, then interpolate the energy to exactly 4π (the speed
    // at firing TDC is not the mean speed, so the time of one cycle is not 4π/Ω).
    let dt = 1e-5;
    let (mut angle, mut energy) = (model.state().0[0], start);
    let mut k = 1;
    let imbalance = loop {
        model.advance(&inputs, 1e-9 + k as f64 * dt, &mut events).unwrap();
        let (next_angle, next_energy) = (model.state().0[0], model.mechanical_energy());
        if next_angle >= 4.0 * PI {
            let w = (4.0 * PI - angle) / (next_angle - angle);
            break energy + w * (next_energy - energy) - start;
        }
        (angle, energy, k) = (next_angle, next_energy, k + 1);
    };
    eprintln!("energy change over one cycle {imbalance:.3} J ({:.3}% of L_F)", 100.0 * imbalance / cal.gas_work);
    // A 10% error in c1 would leave 1.5% of L_F; in M0, 8.5%.
    assert!(imbalance.abs() < 0.005 * cal.gas_work, "cycle energy imbalance {imbalance} J of {} J", cal.gas_work);
}
