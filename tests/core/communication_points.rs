//! Communication points inside a step: with the system unchanged, `advance` serves them from the
//! step's dense output and lets the step run on, so the motion does not depend on where they fall.

use crate::common::testbeds::{Ball, Floor};
use nalgebra::Vector1;
use pistonslap::dynamics::{EventKind, Stepper, StepperOptions};

/// A ball dropped from 1 m onto a fixed floor, e = 0.5, until its bounces accumulate into contact.
fn ball() -> Stepper<Ball, 1, 1> {
    let ball = Ball { mass: 1.0, gravity: 9.81, restitution: 0.5, floor: Floor::Fixed };
    Stepper::new(ball, 0.0, Vector1::new(1.0), Vector1::zeros(), StepperOptions { step: 1e-2, ..Default::default() }).unwrap()
}

fn impact_times(s: &Stepper<Ball, 1, 1>) -> Vec<f64> {
    s.events().iter().filter(|e| e.kind == EventKind::Impact).map(|e| e.time).collect()
}

/// 3 s in one advance and in 3·10⁴ points of 0.1 ms: the same impacts, located alike (to ε_h over
/// the impact speed, 1e-8 s at the last bounces' 0.1 mm/s), at the times of the closed form
/// t_k = t_0 (1 + 2e + … + 2e^(k−1)) with t_0 = √(2/g), and the states at the points of the first
/// fall on its parabola; the points take no RK4 steps of their own.
#[test]
fn points_inside_steps_do_not_change_the_motion() {
    let mut whole = ball();
    whole.advance(3.0).unwrap();
    let mut points = ball();
    let t0 = (2.0 / 9.81_f64).sqrt();
    for k in 1..=30_000 {
        let t = k as f64 * 1e-4;
        points.advance(t).unwrap();
        assert_eq!(points.time(), t);
        if t < t0 {
            assert!((points.position()[0] - (1.0 - 0.5 * 9.81 * t * t)).abs() < 1e-12, "free fall at t = {t}");
        }
    }
    // The points cost no steps of their own: a few times the one advance's steps (the steps ending at an
    // impact are cut at a point), not one per point (3·10⁴).
    let (steps_whole, steps_points) = (whole.counts().accepted, points.counts().accepted);
    assert!(steps_points < 4 * steps_whole, "{steps_points} RK4 steps against {steps_whole}");
    let (a, b) = (impact_times(&whole), impact_times(&points));
    assert_eq!(a.len(), b.len());
    assert!(a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-8), "{a:?}\n{b:?}");
    let mut expected = t0;
    for (k, t) in a.iter().take(8).enumerate() {
        assert!((t - expected).abs() < 1e-9, "impact {k} at {t}, closed form {expected}");
        expected += 2.0 * t0 * 0.5_f64.powi(k as i32 + 1);
    }
}

/// A copy taken while a step runs past the current time (an FMU state saved there) continues as
/// the original, to the bit; a change of the system cuts the step there first.
#[test]
fn a_copy_inside_a_step_continues_to_the_bit_and_a_change_cuts_the_step() {
    let mut original = ball();
    original.advance(0.123).unwrap();
    let mut copy = original.clone();
    original.advance(2.0).unwrap();
    copy.advance(2.0).unwrap();
    assert_eq!(original.events(), copy.events());
    assert_eq!((original.position(), original.velocity()), (copy.position(), copy.velocity()));

    let mut changed = ball();
    changed.advance(0.123).unwrap();
    changed.system_mut().unwrap().gravity = 0.0;
    changed.advance(0.2).unwrap();
    let v = -9.81 * 0.123;
    assert!((changed.velocity()[0] - v).abs() < 1e-12, "no acceleration after the change");
    assert!((changed.position()[0] - (1.0 - 0.5 * 9.81 * 0.123 * 0.123 + v * 0.077)).abs() < 1e-12);
}

/// A served point read again at the point before it puts the stepper back to the bit (how a
/// refused communication point is undone without a copy); a served point that cannot be read
/// changes nothing.
#[test]
fn a_point_read_again_puts_the_stepper_back_to_the_bit() {
    let mut s = ball();
    s.advance(0.1234).unwrap();
    let before = format!("{s:?}");
    assert!(s.serves(0.1235), "the step from 0.12 s runs past 0.1235 s");
    s.advance(0.1235).unwrap();
    assert_ne!(format!("{s:?}"), before);
    s.serve(0.1234).unwrap();
    assert_eq!(format!("{s:?}"), before);
    assert!(s.serve(5.0).is_err() && s.serve(0.0).is_err());
    assert_eq!(format!("{s:?}"), before);
}

/// A stepper restored from bytes is checked before it serves a point: with options that cannot be
/// used, the point inside its step ahead is refused as a step would be.
#[test]
fn a_restored_stepper_with_bad_options_serves_no_point() {
    let mut s = ball();
    s.advance(0.1234).unwrap();
    assert!(s.serves(0.1235));
    let bytes = postcard::to_allocvec(&s).unwrap();
    let step = 1e-2_f64.to_le_bytes();
    let at = bytes.windows(8).position(|w| w == step).expect("the nominal step in the bytes");
    let mut bad = bytes.clone();
    bad[at..at + 8].copy_from_slice(&f64::NAN.to_le_bytes());
    let mut restored: Stepper<Ball, 1, 1> = postcard::from_bytes(&bad).unwrap();
    assert!(restored.options().step.is_nan(), "the patched field is the step");
    assert!(!restored.serves(0.1235));
    assert!(restored.advance(0.1235).is_err());
    let mut good: Stepper<Ball, 1, 1> = postcard::from_bytes(&bytes).unwrap();
    assert!(good.serves(0.1235) && good.advance(0.1235).is_ok());
}
