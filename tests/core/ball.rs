//! A ball dropped on a fixed floor: impact times and velocities in closed form, the accumulation
//! of impacts for e < 1, then resting contact with λ = m g.

use crate::common::testbeds::{Ball, Floor};
use nalgebra::Vector1;
use pistonslap::dynamics::{EventKind, Stepper, StepperOptions, ZENO_APEX_FACTOR};

const G: f64 = 9.81;
const HEIGHT: f64 = 1.0;

fn drop(restitution: f64, step: f64) -> Stepper<Ball, 1, 1> {
    let ball = Ball { mass: 2.0, gravity: G, restitution, floor: Floor::Fixed };
    let options = StepperOptions { step, ..Default::default() };
    Stepper::new(ball, 0.0, Vector1::new(HEIGHT), Vector1::zeros(), options).unwrap()
}

/// Closed form: first impact at t₁ = √(2H/g) with speed v₀ = √(2gH); the k-th rebound
/// leaves with eᵏ v₀ and flies 2 eᵏ v₀ / g.
fn impact_time(e: f64, k: i32) -> f64 {
    let v0 = (2.0 * G * HEIGHT).sqrt();
    (2.0 * HEIGHT / G).sqrt() + (1..=k).map(|j| 2.0 * e.powi(j) * v0 / G).sum::<f64>()
}

#[test]
fn elastic_ball_bounces_periodically() {
    let mut s = drop(1.0, 1e-3);
    s.advance(10.0).unwrap();
    assert_eq!(s.time(), 10.0);
    let v0 = (2.0 * G * HEIGHT).sqrt();
    let impacts: Vec<_> = s.events().iter().filter(|e| e.kind == EventKind::Impact).collect();
    assert_eq!(impacts.len(), 11, "t₁(2k+1) < 10 for k = 0..10");
    for (k, ev) in impacts.iter().enumerate() {
        let t = impact_time(1.0, k as i32);
        assert!((ev.time - t).abs() < 1e-10, "impact {k}: {} vs {t}", ev.time);
        assert!((ev.velocity_before + v0).abs() < 1e-9 && (ev.velocity_after - v0).abs() < 1e-9);
        assert!(ev.energy_lost.abs() < 1e-9);
        // Located within ε_h of the floor.
        assert!(ev.q[0].abs() <= 1e-12, "gap at impact {}", ev.q[0]);
    }
}

#[test]
fn inelastic_ball_accumulates_then_rests() {
    let e = 0.5;
    let mut s = drop(e, 1e-3);
    s.advance(3.0).unwrap();
    let v0 = (2.0 * G * HEIGHT).sqrt();
    let impacts: Vec<_> = s.events().iter().filter(|ev| ev.kind == EventKind::Impact).collect();
    for (k, ev) in impacts.iter().take(12).enumerate() {
        let t = impact_time(e, k as i32);
        assert!((ev.time - t).abs() < 1e-9, "impact {k}: {} vs {t}", ev.time);
        let before = -e.powi(k as i32) * v0;
        assert!((ev.velocity_before - before).abs() < 1e-9 * v0);
        assert!((ev.velocity_after + e * before).abs() < 1e-9 * v0);
        // eq 9 with W = 1/m; a velocity error δv makes a relative error 2δv/|v|.
        let lost = 0.5 * (1.0 - e * e) * before * before * 2.0;
        assert!((ev.energy_lost - lost).abs() < lost * 2.0 * 1e-9 * v0 / before.abs(), "impact {k}: lost {} vs {lost}", ev.energy_lost);
    }
    // The accumulation point t∞ = t₁ (1 + e)/(1 − e). The Zeno guard ends it when the rebound
    // apex u²/(2g) falls below ZENO_APEX_FACTOR·ε_h, giving up at most 2u/(g(1 − e)) of flights.
    let t_inf = (2.0 * HEIGHT / G).sqrt() * (1.0 + e) / (1.0 - e);
    let u_max = (2.0 * G * ZENO_APEX_FACTOR * 1e-12).sqrt() / e;
    let slides: Vec<_> = s.events().iter().filter(|ev| ev.kind == EventKind::Slide).collect();
    assert_eq!(slides.len(), 1);
    assert!(slides[0].time <= t_inf + 1e-9 && slides[0].time > t_inf - 2.0 * u_max / (G * (1.0 - e)), "slide at {}", slides[0].time);
    // Bounded work: log(u_max / v0) / log(e) + 1 impacts.
    assert!(impacts.len() <= (libm::log(u_max / v0) / libm::log(e)).ceil() as usize + 2, "{} impacts", impacts.len());
    // All the potential energy m g H went into the recorded impacts and the final projection.
    let lost: f64 = s.events().iter().map(|ev| ev.energy_lost).sum();
    assert!((lost - 2.0 * G * HEIGHT).abs() < 1e-9, "lost {lost}");
    // Resting contact: on the floor, at rest, λ = m g.
    assert!(s.in_contact(0));
    assert!(s.position()[0].abs() < 1e-12 && s.velocity()[0].abs() < 1e-12);
    assert!((s.multipliers()[0] - 2.0 * G).abs() < 1e-9);
    assert!(s.acceleration()[0].abs() < 1e-9);
}

#[test]
fn ball_at_rest_starts_in_contact() {
    let ball = Ball { mass: 1.5, gravity: G, restitution: 0.3, floor: Floor::Fixed };
    let mut s = Stepper::new(ball, 0.0, Vector1::zeros(), Vector1::zeros(), StepperOptions::default()).unwrap();
    assert!(s.in_contact(0));
    s.advance(0.01).unwrap();
    assert!((s.multipliers()[0] - 1.5 * G).abs() < 1e-12);
    assert_eq!(s.position()[0], 0.0);
}

/// The work counts of a fixed-step run: ⌊t₁/h⌋ + 1 steps to the impact (the last cut short by
/// it), ⌈(T − t₁)/h⌉ after it, one event located inside a step, by one RK4 step (RK4 is exact on
/// the parabola, so the dense-output estimate lands on the floor at once), nothing rejected.
#[test]
fn counts_the_steps_of_the_closed_form() {
    let (h, end) = (1e-3, 1.0);
    let mut s = drop(1.0, h);
    s.advance(end).unwrap();
    let t1 = impact_time(1.0, 0);
    let expected = (t1 / h).floor() + 1.0 + ((end - t1) / h).ceil();
    let counts = s.counts();
    assert_eq!((counts.accepted as f64, counts.rejected, counts.located, counts.locating), (expected, 0, 1, 1), "{counts:?}");
}
