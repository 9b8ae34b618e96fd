//! RK4 converges with order 4 between events; events are located within ε_h.

use crate::common::testbeds::{Ball, DoublePendulum, Floor};
use nalgebra::{Vector1, Vector2};
use pistonslap::dynamics::{EventKind, Stepper, StepperOptions, System};

fn pendulum(wall: f64, restitution: f64) -> DoublePendulum {
    DoublePendulum { masses: [1.0, 0.5], lengths: [1.0, 0.7], gravity: 9.81, wall, restitution }
}

fn swing(step: f64, t_end: f64) -> Vector2<f64> {
    let q0 = Vector2::new(0.3, 0.2);
    let mut s = Stepper::new(pendulum(10.0, 1.0), 0.0, q0, Vector2::zeros(), StepperOptions { step, ..Default::default() }).unwrap();
    s.advance(t_end).unwrap();
    assert!(s.events().is_empty(), "the wall is out of reach");
    *s.position()
}

/// A free double pendulum (no contact): the global error falls by 2⁴ = 16 when the step halves
/// (measured 16.9, 16.5, 16.3 for steps 40 → 5 ms; larger swings reach this only at smaller steps).
#[test]
fn rk4_has_order_four() {
    let t_end = 1.0;
    let reference = swing(0.04 / 256.0, t_end);
    let errors: Vec<f64> = [0.04, 0.02, 0.01, 0.005].iter().map(|&h| (swing(h, t_end) - reference).norm()).collect();
    for pair in errors.windows(2) {
        let ratio = pair[0] / pair[1];
        assert!((14.5..17.5).contains(&ratio), "error ratio {ratio} (errors {errors:?})");
    }
}

/// The impacts of a double pendulum against a wall, located on the dense output and confirmed on
/// the RK4 map, lie within ε_h (1e-12 m) of the wall.
#[test]
fn impacts_are_located_on_the_wall() {
    let q0 = Vector2::new(0.6, 0.9);
    let mut s = Stepper::new(pendulum(-0.3, 0.8), 0.0, q0, Vector2::zeros(), StepperOptions { step: 1e-3, ..Default::default() }).unwrap();
    s.advance(5.0).unwrap();
    let impacts: Vec<_> = s.events().iter().filter(|ev| ev.kind == EventKind::Impact).collect();
    assert!(impacts.len() >= 4, "{} impacts", impacts.len());
    for ev in impacts {
        let gap = s.system().evaluate(ev.time, &ev.q, &Vector2::zeros()).gap[0];
        assert!(gap.abs() <= 1e-12, "gap {gap:e} at {}", ev.time);
    }
}

/// A crossing and return inside one step (both ends of the step admissible): a ball thrown down
/// at 1 m/s from 1 mm against an upward pull of 100 m/s² would dip 4 mm below the floor within
/// the first 20 ms of a 50 ms step. Closed form: y = y₀ − v t + a t²/2 reaches 0 at
/// t = (v − √(v² − 2 a y₀))/a with ḣ⁻ = −√(v² − 2 a y₀).
#[test]
fn a_dip_inside_one_step_is_found() {
    let (y0, v, a) = (1e-3, 1.0, 100.0);
    let ball = Ball { mass: 1.0, gravity: -a, restitution: 0.5, floor: Floor::Fixed };
    let mut s = Stepper::new(ball, 0.0, Vector1::new(y0), Vector1::new(-v), StepperOptions { step: 0.05, ..Default::default() }).unwrap();
    s.advance(0.05).unwrap();
    let root = (v * v - 2.0 * a * y0).sqrt();
    let ev = s.events().first().expect("the dip is an impact");
    assert_eq!(ev.kind, EventKind::Impact);
    assert!((ev.time - (v - root) / a).abs() < 1e-13, "at {}", ev.time);
    assert!((ev.velocity_before + root).abs() < 1e-10);
}
