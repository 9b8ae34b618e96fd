//! Variant 2 (Farahanchi's roller slider crank) on the core: the thesis's statements that do not hang
//! on chaos details, with roller_forcing = 1 (f(τ) as printed, which produced the thesis's results).

use pistonslap::fmus::piston_slap::Mechanism;
use pistonslap::fmus::piston_slap::{Inputs, Outputs, Parameters};
use pistonslap::models::{EngineEvent, EngineEventKind, Forcing, Roller, RollerMechanism};
use std::f64::consts::PI;

/// The thesis's mechanism (section 4.1) in its own units: l = 1 m, M = 1 kg; with Ω = 1 rad/s the
/// FMU's parameters are ξ, α, β, λ and ρ.
fn thesis_case(lambda: f64, rho: f64, e: f64) -> Parameters {
    Parameters {
        model_variant: 2,
        roller_forcing: 1,
        crank_radius: 0.3030,
        rod_length: 1.0,
        rod_mass: 1.9,
        piston_mass: 1.0,
        rod_inertia: 0.4719,
        damping_crank_pin: lambda,
        piston_diameter: 0.08,
        bore: 0.08 + 2.0 * rho,
        restitution: e,
        ..Parameters::default()
    }
}

fn speed(omega: f64) -> Inputs {
    Inputs { crank_speed: omega, ..Inputs::default() }
}

/// Runs `cycles` crank revolutions at Ω, one communication step per revolution.
fn run(params: &Parameters, omega: f64, cycles: usize) -> (Roller, Vec<EngineEvent>) {
    let mut model = Roller::new(params, 0.0).unwrap();
    let mut events = Vec::new();
    for k in 1..=cycles {
        model.advance(&speed(omega), k as f64 * 2.0 * PI / omega, &mut events).unwrap();
    }
    (model, events)
}

fn cycle_of(event: &EngineEvent) -> usize {
    (event.time / (2.0 * PI)) as usize
}

fn impacts_after(events: &[EngineEvent], first_cycle: usize) -> Vec<&EngineEvent> {
    events.iter().filter(|e| e.kind == EngineEventKind::Impact && cycle_of(e) >= first_cycle).collect()
}

/// Smallest period p ≤ 8 (crank cycles) with which the impacts of cycles `from..to` recur: same walls,
/// crank angles within 1e-6 rad.
fn period(events: &[EngineEvent], from: usize, to: usize) -> Option<usize> {
    let pattern = |k: usize| -> Vec<(u8, f64)> {
        events
            .iter()
            .filter(|e| e.kind == EngineEventKind::Impact && cycle_of(e) == k)
            .map(|e| (e.corner, e.crank_angle % (2.0 * PI)))
            .collect()
    };
    (1..=8).find(|&p| {
        (from..to - p).all(|k| {
            let (a, b) = (pattern(k), pattern(k + p));
            a.len() == b.len() && a.iter().zip(&b).all(|(x, y)| x.0 == y.0 && (x.1 - y.1).abs() < 1e-6)
        })
    })
}

fn outputs(model: &Roller) -> Outputs {
    let mut out = Outputs::default();
    model.write_outputs(&mut out);
    out
}

/// Fig 2.9 (λ = 0.35): with e = 0 the roller comes to slide on the upper wall and never leaves it,
/// and the core's contact force is eq 2.29's M l Ω² f_u(θ) all round the cycle.
#[test]
fn sliding_on_the_upper_wall_carries_the_eq_2_29_force() {
    let (lambda, rho) = (0.35, 0.01);
    let mut model = run(&thesis_case(lambda, rho, 0.0), 1.0, 2).0;
    let sc = RollerMechanism { xi: 0.3030, alpha: 1.9, beta: 0.4719, forcing: Forcing::Printed };
    let mut events = Vec::new();
    for k in 1..=100 {
        let t = 4.0 * PI + k as f64 * 2.0 * PI / 100.0;
        model.advance(&speed(1.0), t, &mut events).unwrap();
        let out = outputs(&model);
        let (fu, _) = sc.constraint_forces(t, lambda, rho);
        // The upper wall is the x = −D/2 wall of corner 1, as in variant 1 (DESIGN.md §4).
        assert_eq!((out.contact_state_1, out.contact_state_3), (1, 0), "t {t}");
        assert!((out.contact_force_1 - fu).abs() < 1e-9 * fu.abs().max(1.0), "t {t}: {} vs {fu}", out.contact_force_1);
        assert_eq!(out.side_force, out.contact_force_1);
        assert!((out.piston_lateral + rho).abs() < 1e-12);
    }
    assert!(events.is_empty());
}

/// The mapping onto SI: the same dimensionless case with l = 0.15 m, M = 0.4 kg at 1200 rpm gives the
/// same impacts at the same crank angles, with velocities scaled by l Ω and energies by M l² Ω².
#[test]
fn dimensional_parameters_map_onto_the_thesis_numbers() {
    let (lambda, rho, e) = (0.05, 0.015, 0.9);
    let reference = run(&thesis_case(lambda, rho, e), 1.0, 4).1;
    let (l, mass, omega) = (0.15, 0.4, 125.66);
    let params = Parameters {
        crank_radius: 0.3030 * l,
        rod_length: l,
        rod_mass: 1.9 * mass,
        piston_mass: mass,
        rod_inertia: 0.4719 * mass * l * l,
        damping_crank_pin: lambda * mass * l * l * omega,
        piston_diameter: 0.08,
        bore: 0.08 + 2.0 * rho * l,
        ..thesis_case(lambda, rho, e)
    };
    let scaled = run(&params, omega, 4).1;
    assert!(reference.len() > 10);
    assert_eq!(reference.len(), scaled.len());
    for (a, b) in reference.iter().zip(&scaled) {
        assert_eq!((a.kind, a.corner), (b.kind, b.corner));
        assert!((a.crank_angle - b.crank_angle).abs() < 1e-9);
        assert!((a.time / omega - b.time).abs() < 1e-9);
        assert!((a.normal_velocity_before * l * omega - b.normal_velocity_before).abs() < 1e-9 * l * omega);
        assert!((a.energy_lost * mass * (l * omega).powi(2) - b.energy_lost).abs() < 1e-9 * mass * (l * omega).powi(2));
        assert!((a.position * l - b.position).abs() < 1e-12);
    }
}

/// Section 4.3: (λ, ρ, e) = (0.05, 0.015, 0.9) is periodic (Figs 4.10, 4.18).
#[test]
fn thesis_periodic_case_is_periodic() {
    let events = run(&thesis_case(0.05, 0.015, 0.9), 1.0, 130).1;
    assert_eq!(period(&events, 100, 130), Some(1));
}

/// Section 4.4: at λ = 0.25 no impacts on the lower wall in steady state, and the motion is periodic
/// with sliding (Figs 4.34, 4.35).
#[test]
fn at_high_damping_the_lower_wall_is_not_hit() {
    let events = run(&thesis_case(0.25, 0.015, 0.9), 1.0, 100).1;
    let impacts = impacts_after(&events, 30);
    assert!(impacts.len() > 100);
    assert!(impacts.iter().all(|e| e.corner == 1), "the upper wall is corner 1's");
    assert!(events.iter().any(|e| e.kind == EngineEventKind::Slide && cycle_of(e) >= 30));
    assert!(period(&events, 70, 100).is_some());
}

/// Section 4.4: at (λ, ρ) = (0.05, 0.02) lowering e to 0.5 gives a periodic response with sliding
/// (Figs 4.39, 4.44).
#[test]
fn lower_restitution_makes_the_response_periodic_with_sliding() {
    let events = run(&thesis_case(0.05, 0.02, 0.5), 1.0, 130).1;
    assert!(period(&events, 100, 130).is_some());
    let slides = events.iter().filter(|e| e.kind == EngineEventKind::Slide && cycle_of(e) >= 30).count();
    assert!(slides >= 100, "{slides} slides in 100 cycles");
}

/// Section 4.3: average impact velocities grow with the clearance ρ (λ = 0.05, e = 0.9). They do on
/// the upper wall, where the impacts are the hardest; on the lower wall they fall here, as ever more
/// impacts there come in low-speed sequences.
#[test]
fn impact_velocities_grow_with_the_clearance() {
    let mean = |rho: f64| {
        let events = run(&thesis_case(0.05, rho, 0.9), 1.0, 200).1;
        let impacts: Vec<_> = impacts_after(&events, 30).into_iter().filter(|e| e.corner == 1).collect();
        impacts.iter().map(|e| e.normal_velocity_before).sum::<f64>() / impacts.len() as f64
    };
    let (small, middle, large) = (mean(0.01), mean(0.015), mean(0.02));
    assert!(small < middle && middle < large, "{small} {middle} {large}");
}

/// Impacts obey eq 2.17 (restitution on the speed relative to the moving wall), the piston stays
/// between the walls, and the impact log speaks the FMU's corners.
#[test]
fn impacts_reflect_the_relative_speed_and_keep_the_piston_inside() {
    let (rho, e) = (0.02, 0.7);
    let mut model = Roller::new(&thesis_case(0.1, rho, e), 0.0).unwrap();
    let mut events = Vec::new();
    for k in 1..=2000 {
        model.advance(&speed(1.0), k as f64 * 0.01, &mut events).unwrap();
        let out = outputs(&model);
        assert!(out.piston_lateral.abs() <= rho + 1e-12);
    }
    let impacts = impacts_after(&events, 0);
    assert!(impacts.len() > 5);
    for i in impacts {
        assert!(i.corner == 1 || i.corner == 3);
        assert!(i.normal_velocity_before > 0.0);
        assert!((i.normal_velocity_after - e * i.normal_velocity_before).abs() < 1e-12);
        assert!(i.energy_lost > 0.0);
        assert!((0.0..4.0 * PI).contains(&i.crank_angle));
    }
}

/// A new crank speed rescales ψ' = ψ̇/Ω so that ψ̇ is continuous. At θ = π/2 (Λ' = 0) the lateral
/// velocity l (Λ' θ̇ ψ + Λ ψ̇) is l Λ ψ̇ and must not jump either.
#[test]
fn a_crank_speed_change_keeps_the_lateral_velocity() {
    let mut model = Roller::new(&thesis_case(0.05, 0.02, 0.9), 0.0).unwrap();
    let mut events = Vec::new();
    model.advance(&speed(100.0), 4.5 * PI / 100.0, &mut events).unwrap();
    let before = outputs(&model);
    assert_eq!(before.contact_state_1 + before.contact_state_3, 0);
    model.advance(&speed(150.0), 4.5 * PI / 100.0 + 1e-9, &mut events).unwrap();
    let after = outputs(&model);
    assert!(before.piston_lateral_velocity.abs() > 1e-3);
    // 1e-9 s of acceleration (~2e3 m/s²) changes it by ~2e-6 m/s; not rescaling would change it by half
    assert!((after.piston_lateral_velocity - before.piston_lateral_velocity).abs() < 1e-3 * before.piston_lateral_velocity.abs());
}

/// At an engine's scale (the FMU's defaults: ρ ≈ 2.7e-4, λ ≈ 5e-3 at 1200 rpm) the corrected model's
/// sliding threshold scales with the clearance: the piston bounces before it slides, and the impacts
/// of an accumulation fall geometrically by e until sliding takes over.
#[test]
fn engine_scale_piston_bounces_before_it_slides() {
    let params = Parameters { model_variant: 2, ..Parameters::default() };
    let mut model = Roller::new(&params, 0.0).unwrap();
    let mut events = Vec::new();
    model.advance(&speed(125.66), 0.05, &mut events).unwrap();
    let first_slide = events.iter().position(|e| e.kind == EngineEventKind::Slide).unwrap();
    assert!(first_slide >= 3, "{:?}", &events[..first_slide + 1]);
    for pair in events[..first_slide].windows(2) {
        assert_eq!(pair[0].kind, EngineEventKind::Impact);
        if pair[1].kind == EngineEventKind::Impact && pair[1].corner == pair[0].corner {
            assert!(pair[1].normal_velocity_before < pair[0].normal_velocity_before);
        }
    }
    assert!(events[0].normal_velocity_before > 1e-3);
}

/// Bad parameters and inputs are refused with the parameter named.
#[test]
fn refuses_what_the_model_cannot_do() {
    let bad = |p: Parameters, name: &str| {
        let message = Roller::new(&p, 0.0).unwrap_err().0;
        assert!(message.contains(name), "{message}");
    };
    bad(Parameters { crank_mode: 2, ..thesis_case(0.05, 0.01, 0.9) }, "crank_mode");
    bad(Parameters { roller_forcing: 3, ..thesis_case(0.05, 0.01, 0.9) }, "roller_forcing");
    bad(Parameters { bore: 0.079, ..thesis_case(0.05, 0.01, 0.9) }, "bore");
    bad(Parameters { restitution: 1.5, ..thesis_case(0.05, 0.01, 0.9) }, "restitution");
    let mut model = Roller::new(&thesis_case(0.05, 0.01, 0.9), 0.0).unwrap();
    assert!(model.advance(&speed(0.0), 1.0, &mut Vec::new()).unwrap_err().0.contains("crank_speed"));
}

/// The core runs on the crank angle; its errors reach the host on the engine's clock. A span of
/// 10³ s needs 2.5·10⁷ steps of 0.005 rad, more than one step may take: refused at t = 1 s, where
/// the crank angle is 125.66 rad.
#[test]
fn core_errors_give_the_engine_time() {
    let mut model = Roller::new(&thesis_case(0.05, 0.01, 0.9), 0.0).unwrap();
    model.advance(&speed(125.66), 1.0, &mut Vec::new()).unwrap();
    let message = model.advance(&speed(125.66), 1001.0, &mut Vec::new()).unwrap_err().0;
    assert!(message.contains("at t = 1 s") && message.contains("10⁷ RK4 steps"), "{message}");
}

/// The roller's walls stand at the running clearance: the thesis case's ρ = 0.015 (bore 0.11 m on an 80 mm piston)
/// with the piston grown by 0.08 × 21e-6 × 80 = 134.4 µm and the bore by 0.11 × 11e-6 × 80 = 96.8 µm (100 °C
/// from 20 °C) runs as the cold design of those diameters, with a running clearance of 0.03 m − 37.6 µm.
#[test]
fn the_roller_runs_at_its_running_clearance() {
    let cold = thesis_case(0.05, 0.015, 0.9);
    let hot = Parameters { piston_temperature: 373.15, liner_temperature: 373.15, ..cold.clone() };
    let grown = Parameters { bore: 0.11 + 96.8e-6, piston_diameter: 0.08 + 134.4e-6, ..cold };
    let (hot_run, grown_run) = (run(&hot, 1.0, 4), run(&grown, 1.0, 4));
    assert_eq!(hot_run.1.len(), grown_run.1.len());
    for (a, b) in hot_run.1.iter().zip(&grown_run.1) {
        assert!((a.crank_angle - b.crank_angle).abs() < 1e-9 && (a.normal_velocity_before - b.normal_velocity_before).abs() < 1e-9);
    }
    assert!((outputs(&hot_run.0).running_clearance - (0.03 - 37.6e-6)).abs() < 1e-15);
}
