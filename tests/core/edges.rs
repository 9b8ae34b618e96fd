//! Held inputs changed between steps, and what the core refuses: errors are values.

use crate::common::testbeds::{Ball, DoublePendulum, Floor};
use nalgebra::{Vector1, Vector2};
use pistonslap::dynamics::{DynamicsError, EventKind, Stepper, StepperOptions, ACCUMULATION_WINDOW};

const G: f64 = 9.81;

fn resting(floor: Floor) -> Stepper<Ball, 1, 1> {
    let ball = Ball { mass: 1.0, gravity: G, restitution: 0.5, floor };
    let s = Stepper::new(ball, 0.0, Vector1::zeros(), Vector1::zeros(), StepperOptions { step: 1e-3, ..Default::default() }).unwrap();
    assert!(s.in_contact(0));
    s
}

/// The floor under a resting ball starts moving up at u: the held contact now approaches with
/// ḣ = −u, so the next advance starts with an impact, v⁺ = (1 + e) u.
#[test]
fn changed_input_makes_an_active_contact_impact() {
    let mut s = resting(Floor::Moving { velocity: 0.0 });
    s.system_mut().unwrap().floor = Floor::Moving { velocity: 0.4 };
    s.advance(1e-3).unwrap();
    let ev = s.events().iter().find(|ev| ev.kind == EventKind::Impact).expect("impact");
    assert_eq!(ev.time, 0.0);
    assert!((ev.velocity_before + 0.4).abs() < 1e-15 && (ev.velocity_after - 0.2).abs() < 1e-15);
    assert!(!s.in_contact(0));
    // Free flight after: v = 0.6 − g t.
    assert!((s.velocity()[0] - (0.6 - G * 1e-3)).abs() < 1e-12);
}

/// Gravity reversed under a resting ball: the multiplier would pull, so the contact is released
/// at once and the ball falls upward: y = g t²/2.
#[test]
fn changed_input_releases_a_pulling_contact() {
    let mut s = resting(Floor::Fixed);
    s.advance(0.05).unwrap();
    s.system_mut().unwrap().gravity = -G;
    s.advance(0.15).unwrap();
    let ev = s.events().iter().find(|ev| ev.kind == EventKind::Release).expect("release");
    assert_eq!(ev.time, 0.05);
    assert!((s.position()[0] - 0.5 * G * 0.1 * 0.1).abs() < 1e-12);
}

#[test]
fn advance_ends_exactly_at_the_end_time() {
    let mut s = resting(Floor::Fixed);
    for t in [0.0, 1e-4, 0.0123456789, 0.1 + 0.2] {
        s.advance(t).unwrap();
        assert_eq!(s.time(), t);
    }
    assert!(matches!(s.advance(0.1), Err(DynamicsError::InvalidArgument { .. })));
}

#[test]
fn more_events_than_the_budget_within_the_accumulation_window_are_an_error_and_a_long_span_is_not() {
    // An elastic ball dropped from 1 m bounces every 2√(2/g) = 0.903 s, eleven times in 10 s; RK4
    // integrates its parabolas exactly at any step, so the nominal step only sets the window,
    // `ACCUMULATION_WINDOW` of it.
    let ball = Ball { mass: 1.0, gravity: G, restitution: 1.0, floor: Floor::Fixed };
    let run = |window: f64| {
        let options = StepperOptions { step: window / ACCUMULATION_WINDOW, ..Default::default() };
        let mut s = Stepper::new(ball.clone(), 0.0, Vector1::new(1.0), Vector1::zeros(), options).unwrap();
        s.set_event_budget(3);
        s.advance(10.0).map(|()| s.events().len())
    };
    // All eleven in one 10 s window: the fourth is refused.
    let err = run(10.0).unwrap_err();
    assert!(matches!(err, DynamicsError::EventBudget { events: 3, time, .. } if (time - 0.4515 - 3.0 * 0.9031).abs() < 1e-3), "{err}");
    assert!(err.to_string().contains("more than 3 events within 0.001 of a nominal step"), "{err}");
    // At most one per 0.5 s window: all eleven in one advance.
    assert_eq!(run(0.5).unwrap(), 11);
}

#[test]
fn inadmissible_and_non_finite_states_are_errors() {
    let ball = Ball { mass: 1.0, gravity: G, restitution: 1.0, floor: Floor::Fixed };
    let err = Stepper::new(ball.clone(), 0.5, Vector1::new(-1e-6), Vector1::zeros(), StepperOptions::default()).unwrap_err();
    assert_eq!(err, DynamicsError::Penetration { time: 0.5, constraint: 0, gap: -1e-6 });
    assert!(err.to_string().contains("t = 0.5 s") && err.to_string().contains("constraint 0"));

    let mut s = Stepper::new(ball, 0.0, Vector1::new(1.0), Vector1::zeros(), StepperOptions::default()).unwrap();
    s.system_mut().unwrap().gravity = f64::NAN;
    assert!(matches!(s.advance(0.1), Err(DynamicsError::NonFinite { time }) if time == 0.0));

    // Finite but overflowing forces: a stage's angles go NaN, and M(q) with them. The message
    // names that cause (the check stays out of the RK4 stages, whose evaluation it would keep from
    // being inlined).
    let pendulum = DoublePendulum { masses: [1.0, 0.5], lengths: [1.0, 0.7], gravity: 1e300, wall: 10.0, restitution: 1.0 };
    let mut s = Stepper::new(pendulum, 0.0, Vector2::new(0.3, 0.2), Vector2::zeros(), StepperOptions::default()).unwrap();
    let err = s.advance(0.1).unwrap_err();
    assert!(err.to_string().contains("non-finite"), "{err}");

    // At t = 1e12 s a 10 µs step is below the float resolution (1.2e-4 s): refused, not a hang.
    let ball = Ball { mass: 1.0, gravity: G, restitution: 1.0, floor: Floor::Fixed };
    let mut s = Stepper::new(ball, 1e12, Vector1::new(1.0), Vector1::zeros(), StepperOptions::default()).unwrap();
    assert!(matches!(s.advance(1e12 + 1.0), Err(DynamicsError::InvalidArgument { .. })));

    let bad = StepperOptions { step: 0.0, ..Default::default() };
    let ball = Ball { mass: 1.0, gravity: G, restitution: 1.0, floor: Floor::Fixed };
    assert!(matches!(Stepper::new(ball, 0.0, Vector1::new(1.0), Vector1::zeros(), bad), Err(DynamicsError::InvalidArgument { .. })));
}

/// The FMU saves and restores the stepper by value: a clone continues exactly like the original.
#[test]
fn a_cloned_stepper_continues_identically() {
    fn plain_value<T: Clone + serde::Serialize + serde::de::DeserializeOwned>(_: &T) {}
    let ball = Ball { mass: 1.0, gravity: G, restitution: 0.7, floor: Floor::Oscillating { amplitude: 0.01, angular_frequency: 40.0 } };
    let mut a = Stepper::new(ball, 0.0, Vector1::new(0.05), Vector1::zeros(), StepperOptions { step: 1e-3, ..Default::default() }).unwrap();
    a.advance(0.7).unwrap();
    let mut b = a.clone();
    plain_value(&b);
    a.advance(2.0).unwrap();
    b.advance(2.0).unwrap();
    assert_eq!((a.position(), a.velocity(), a.events()), (b.position(), b.velocity(), b.events()));
}
