//! Forces a system absorbs (`System::powers`), on a ball with a stiff damper made linearly
//! implicit: the stiff mode relaxes over the step bound instead of m/c, the motion keeps the slow
//! (terminal) velocity, and the absorbed work closes the energy books with the impacts.

use crate::common::testbeds::{Ball, DampedBall, Floor};
use nalgebra::Vector1;
use pistonslap::dynamics::{EventKind, Stepper, StepperOptions};

const G: f64 = 9.81;

fn ball(restitution: f64) -> Ball {
    Ball { mass: 2.0, gravity: G, restitution, floor: Floor::Fixed }
}

fn energy(s: &Stepper<DampedBall, 1, 1>) -> f64 {
    let m = s.system().ball.mass;
    0.5 * m * s.velocity()[0] * s.velocity()[0] + m * G * s.position()[0]
}

/// With c = 0 nothing is added: the damped ball is the ball, event for event and bit for bit.
#[test]
fn without_damping_it_is_the_ball_to_the_bit() {
    let options = StepperOptions { step: 1e-3, ..Default::default() };
    let start = (Vector1::new(1.0), Vector1::new(0.0));
    let mut plain = Stepper::new(ball(0.5), 0.0, start.0, start.1, options.clone()).unwrap();
    let damped = DampedBall { ball: ball(0.5), damping: 0.0, relaxation: 1e-3 };
    let mut damped = Stepper::new(damped, 0.0, start.0, start.1, options).unwrap();
    plain.advance(2.0).unwrap();
    damped.advance(2.0).unwrap();
    assert!(plain.events().len() > 10);
    assert_eq!(plain.events(), damped.events());
    assert_eq!((plain.position(), plain.velocity()), (damped.position(), damped.velocity()));
    assert_eq!((damped.rates().unwrap(), damped.energies()), (Default::default(), Default::default()));
}

/// c/m = 1e8 (a time constant of 1e-8 s) under steps of τ/k, τ = 1e-4 s: RK4 alone is unstable
/// above 2.8e-8 s. Implicit, the thrown ball's velocity relaxes to the terminal −m g / c (to 1e-9
/// of it after 50 τ at k = 1: RK4's factor per step at λh = −1 is 0.375), in k steps per τ. The
/// energy the transient loses is the absorbed work up to RK4's error on the fast mode, which the
/// scheme does not resolve at λh = −1/k: measured 4.2e-2, 1.8e-3, 9.6e-5, 5.5e-6 of it at
/// k = 1, 2, 4, 8 (≈ k^−4.4).
#[test]
fn a_stiff_damper_relaxes_over_the_step_bound_to_the_terminal_velocity() {
    let (c, tau) = (2e8, 1e-4);
    let sys = DampedBall { ball: ball(0.5), damping: c, relaxation: tau };
    let terminal = -2.0 * G / c;
    let mut errors = Vec::new();
    for k in [1.0, 4.0, 8.0] {
        let options = StepperOptions { step: tau / k, ..Default::default() };
        let mut s = Stepper::new(sys.clone(), 0.0, Vector1::new(0.01), Vector1::new(-1.0), options).unwrap();
        let start = energy(&s);
        s.advance(50.0 * tau).unwrap();
        assert!((s.velocity()[0] - terminal).abs() < 1e-9 * terminal.abs(), "{} vs {terminal}", s.velocity()[0]);
        assert!(s.counts().accepted <= 50 * k as u64 + 1, "{:?}", s.counts());
        // The transient carried the ball (v₀ − v_t)(m/c + τ) down (τ-sized: the scheme's lag) and
        // the terminal velocity the rest of the way.
        let fallen = 0.01 - s.position()[0];
        let expected = (1.0 + terminal) * (2.0 / c + tau) - terminal * 50.0 * tau;
        assert!((fallen - expected).abs() < 0.3 * expected, "k = {k}: fell {fallen} m, {expected} m expected");
        let lost = start - energy(&s);
        errors.push((lost - s.energies()[0]).abs() / lost);
    }
    assert!(errors[0] < 0.05 && errors[1] < 2e-4 && errors[2] < 1e-5, "{errors:?}");
}

/// A ball dropped from 1 m with a moderate damper (c/m = 0.5 /s) bounces on the floor and comes to
/// rest on it, at every τ:
/// - the mechanical energy lost equals the impacts' losses plus the absorbed work, through the smooth
///   flight (stage quadrature), the impacts (jumps) and the resting contact at the end;
/// - the impacts act through m alone (`Evaluation::mass`): the damper, a finite force, takes no
///   impulse in them, and each loses `(1 − e²)/2 m ẏ⁻²` exactly (to 1e-12);
/// - the force channel (`Powers`' third: the damper's force `−c (ẏ + τ ÿ)`, by the steps' weights in
///   flight and its implicit share at the projections onto the resting contact) integrates to
///   `−c (Δy + τ (Δẏ − Σ Δẏ_impacts))` to 1e-9 N·s, and to the ball's momentum change less gravity's
///   and the floor's impulses (impacts and resting contact) to round-off (≤ 1e-12 of m g T).
#[test]
fn absorbed_work_and_force_close_the_energy_and_momentum_books() {
    for tau in [1e-4, 1e-3, 1e-2] {
        let sys = DampedBall { ball: ball(0.5), damping: 1.0, relaxation: tau };
        let options = StepperOptions { step: 1e-3, local_error: Some(1e-10), ..Default::default() };
        let mut s = Stepper::new(sys, 0.0, Vector1::new(1.0), Vector1::new(0.0), options).unwrap();
        let start = energy(&s);
        let (m, c, time) = (s.system().ball.mass, s.system().damping, 3.0);
        s.advance(time).unwrap();
        let impacts = s.events().iter().filter(|e| e.kind == EventKind::Impact).count();
        let lost: f64 = s.events().iter().map(|e| e.energy_lost).sum();
        let (absorbed, damper) = (s.energies()[0], s.energies()[2]);
        let balance = start - energy(&s) - lost - absorbed;
        let floor: f64 = s.events().iter().map(|e| e.impulses[0]).sum::<f64>() + s.contact_impulses()[0];
        let struck: f64 = s.events().iter().filter(|e| e.kind == EventKind::Impact).map(|e| e.velocity_after - e.velocity_before).sum();
        let closed_form = -c * (s.position()[0] - 1.0 + tau * (s.velocity()[0] - struck));
        for e in s.events().iter().filter(|e| e.kind == EventKind::Impact) {
            let newton = 0.5 * (1.0 - 0.25) * m * e.velocity_before * e.velocity_before;
            assert!((e.energy_lost - newton).abs() < 1e-12 * newton, "{} against {newton}", e.energy_lost);
        }
        let momentum = m * s.velocity()[0] + m * G * time - floor - damper;
        eprintln!(
            "τ = {tau}: {impacts} impacts, impacts {lost:.6} J, absorbed {absorbed:.6} J, residual {balance:.2e} J; \
             damper {damper:.12} N·s, momentum residual {momentum:.2e} N·s"
        );
        assert!(impacts > 5 && absorbed > 0.05 * start, "{impacts} {absorbed}");
        assert!(balance.abs() < 1e-8 * start, "residual {balance} J of {start} J");
        assert!((damper - closed_form).abs() < 1e-9, "{damper} against {closed_form}");
        assert!(momentum.abs() < 1e-12 * m * G * time, "{momentum}");
    }
}
