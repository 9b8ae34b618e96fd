//! Contact transitions decided by the contact problem over the whole closed set (DESIGN §5): two
//! contacts that reach zero force at the same instant, and a gap a hair below zero.

use crate::common::testbeds::{Ball, Floor, Plank};
use nalgebra::{Vector1, Vector2};
use pistonslap::dynamics::{DynamicsError, EventKind, Stepper, StepperOptions};

/// A plank of 1 kg and 1 m (I = 1/12 kg·m², a = 0.5 m), lifted at 10 N/s past its weight at t = 0,
/// resting on both ends from t = −0.05 s.
fn plank(torque_rate: f64) -> Stepper<Plank, 2, 2> {
    let plank = Plank { mass: 1.0, inertia: 1.0 / 12.0, half_length: 0.5, gravity: 9.81, lift_rate: 10.0, torque_rate };
    let options = StepperOptions { step: 1e-3, ..Default::default() };
    let mut s = Stepper::new(plank, -0.05, Vector2::zeros(), Vector2::zeros(), options).unwrap();
    assert!(s.in_contact(0) && s.in_contact(1), "at rest on both ends");
    s.clear_events();
    s.advance(0.05).unwrap();
    s
}

fn kinds(s: &Stepper<Plank, 2, 2>) -> Vec<(EventKind, usize)> {
    s.events().iter().map(|e| (e.kind, e.constraint)).collect()
}

/// Torque rate c = 3 N·m/s, between k I/(m a) = 5/3 and k a = 5: held on both ends, both forces
/// would turn negative after t = 0 (λ = (−k t ± c t/a)/2), yet pivoting on the left end is the
/// only consistent continuation (flying off both would drive the left end into the floor,
/// pivoting on the right would need a pulling force). On the left end, (I + m a²) θ̈ = (c + k a) t
/// and λ = m a θ̈ − k t give θ = 4 t³ and λ = 2 t to leading order in θ.
#[test]
fn both_forces_vanishing_together_pivot_on_one_end() {
    let s = plank(3.0);
    assert_eq!(kinds(&s), vec![(EventKind::Release, 1)], "one release, no impact");
    assert!(s.in_contact(0) && !s.in_contact(1));
    let t = s.time();
    let (theta, lambda) = (s.position()[1], s.multipliers()[0]);
    assert!((theta / (4.0 * t.powi(3)) - 1.0).abs() < 1e-5, "θ = {theta:e}, 4t³ = {:e}", 4.0 * t.powi(3));
    assert!((lambda / (2.0 * t) - 1.0).abs() < 1e-5, "λ = {lambda}");
    assert!(s.gaps()[0].abs() < 1e-12 && s.gaps()[1] > 0.0);
}

/// The mirror image: a torque the other way pivots the plank on its right end.
#[test]
fn the_opposite_torque_pivots_on_the_other_end() {
    let s = plank(-3.0);
    assert_eq!(kinds(&s), vec![(EventKind::Release, 0)]);
    assert!(!s.in_contact(0) && s.in_contact(1));
    assert!((s.position()[1] / (-4.0 * s.time().powi(3)) - 1.0).abs() < 1e-5);
}

/// Torque rate c = 1 < 5/3: the free flight (ÿ = k t/m, θ̈ = c t/I) lifts both ends, the left by
/// (k/(6m) − c a/(6I)) t³ = 2t³/3 > 0: both open and nothing hits again.
#[test]
fn a_weak_torque_lifts_both_ends() {
    let s = plank(1.0);
    assert_eq!(kinds(&s), vec![(EventKind::Release, 0), (EventKind::Release, 1)]);
    let t = s.time();
    assert!((s.position()[0] - 10.0 * t.powi(3) / 6.0).abs() < 1e-12);
    assert!((s.position()[1] - 2.0 * t.powi(3)).abs() < 1e-12);
    assert!((s.gaps()[0] - 2.0 * t.powi(3) / 3.0).abs() < 1e-9, "left end rises by 2t³/3");
}

/// A gap a hair below zero where the event search can leave one (here 50 ε_h) is closed and
/// projected onto the floor; well beyond it (200 ε_h) it is a penetration, named.
#[test]
fn a_hair_below_zero_is_projected_and_a_real_penetration_refused() {
    let ball = Ball { mass: 1.0, gravity: 9.81, restitution: 0.5, floor: Floor::Fixed };
    let eps = StepperOptions::default().gap_tolerance;
    let s = Stepper::new(ball.clone(), 0.0, Vector1::new(-50.0 * eps), Vector1::zeros(), StepperOptions::default()).unwrap();
    assert!(s.in_contact(0) && s.gaps()[0].abs() <= 0.1 * eps, "gap {:e}", s.gaps()[0]);
    assert!((s.multipliers()[0] - 9.81).abs() < 1e-12);
    let err = Stepper::new(ball, 0.0, Vector1::new(-200.0 * eps), Vector1::zeros(), StepperOptions::default()).unwrap_err();
    assert!(matches!(err, DynamicsError::Penetration { constraint: 0, .. }), "{err}");
}
