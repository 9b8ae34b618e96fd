//! A closed constraint approaching slower than ε_ḣ while its contact force would pull (sliding is
//! refused) must still get the impact law; otherwise it is penetrated at the next instant with
//! nothing to resolve it. Farahanchi's roller meets this with the thesis's large ε_ḣ = 0.005.

use crate::common::testbeds::{Ball, Floor};
use nalgebra::Vector1;
use pistonslap::dynamics::{EventKind, Stepper, StepperOptions};

/// A ball on the floor, pulled away from it (negative gravity), arriving at 0.05 m/s with
/// ε_ḣ = 0.1: it bounces with e · 0.05 and then flies off under the pull.
#[test]
fn slow_approach_against_a_pulling_contact_is_an_impact() {
    let ball = Ball { mass: 1.0, gravity: -1.0, restitution: 0.5, floor: Floor::Fixed };
    let options = StepperOptions { step: 1e-3, velocity_tolerance: 0.1, ..Default::default() };
    let mut s = Stepper::new(ball, 0.0, Vector1::zeros(), Vector1::new(-0.05), options).unwrap();
    s.advance(1.0).unwrap();
    let impacts: Vec<_> = s.events().iter().filter(|e| e.kind == EventKind::Impact).collect();
    assert_eq!(impacts.len(), 1);
    assert!((impacts[0].velocity_after - 0.025).abs() < 1e-12);
    assert!(!s.in_contact(0));
    // free flight from the bounce: y = 0.025 t + t²/2
    assert!((s.position()[0] - 0.525).abs() < 1e-9);
}
