//! The adaptive step (`StepperOptions::local_error`): its error follows the tolerance, its cost
//! follows RK4's order, and a motion the held constraints fully determine runs at the largest step.

use crate::common::testbeds::{Ball, Counted, DoublePendulum, Floor};
use nalgebra::{Vector1, Vector2};
use pistonslap::dynamics::{EventKind, Stepper, StepperOptions};

/// A double pendulum swinging freely (its "gap" is the tip's distance from a far wall) for 1 s:
/// the tip's error against a fine fixed-step reference, and the evaluations spent.
fn swing(options: StepperOptions) -> (f64, u64) {
    let p = DoublePendulum { masses: [1.0, 0.5], lengths: [1.0, 0.7], gravity: 9.81, wall: 10.0, restitution: 1.0 };
    let run = |options: StepperOptions| {
        let mut s = Stepper::new(Counted::new(p.clone()), 0.0, Vector2::new(1.0, -0.5), Vector2::zeros(), options).unwrap();
        s.advance(1.0).unwrap();
        assert!(s.events().is_empty());
        (s.gaps()[0], s.system().evaluations.get())
    };
    let (reference, _) = run(StepperOptions { step: 1e-4, ..Default::default() });
    let (tip, evaluations) = run(options);
    ((tip - reference).abs(), evaluations)
}

/// The global error stays within the sum of the local bounds (≤ evaluations/4 steps, each within
/// the tolerance), falls with the tolerance, and the cost grows as tol^(−1/4): the estimate is
/// of order h⁴, so 100× tighter costs 100^¼ ≈ 3.2× more steps.
#[test]
fn error_follows_the_tolerance_at_the_cost_of_order_four() {
    let adaptive = |tol| swing(StepperOptions { step: 0.1, local_error: Some(tol), ..Default::default() });
    let (loose, tight) = (adaptive(1e-7), adaptive(1e-9));
    for ((error, evaluations), tol) in [(loose, 1e-7), (tight, 1e-9)] {
        assert!(error < tol * evaluations as f64 / 4.0, "error {error:e} with {evaluations} evaluations at {tol:e}");
    }
    assert!(tight.0 < loose.0 / 10.0, "errors {:e} then {:e}", loose.0, tight.0);
    let ratio = tight.1 as f64 / loose.1 as f64;
    assert!((2.5..4.0).contains(&ratio), "cost ratio {ratio} ({} and {} evaluations)", loose.1, tight.1);
}

/// At equal accuracy the adaptive step costs fewer evaluations than the best fixed step.
#[test]
fn adaptive_step_beats_the_fixed_step_at_equal_accuracy() {
    let (adaptive_error, adaptive_cost) = swing(StepperOptions { step: 0.1, local_error: Some(1e-9), ..Default::default() });
    let (fixed_error, fixed_cost) = [0.01, 0.005, 0.0025, 0.00125]
        .into_iter()
        .map(|step| swing(StepperOptions { step, ..Default::default() }))
        .find(|&(error, _)| error <= adaptive_error)
        .expect("a fixed step as accurate");
    assert!(
        adaptive_cost < fixed_cost,
        "adaptive {adaptive_cost} evaluations (error {adaptive_error:e}) vs fixed {fixed_cost} ({fixed_error:e})"
    );
}

/// A ball held on a floor that oscillates (its downward acceleration, 1 m/s², stays below g):
/// one degree of freedom, one held constraint, nothing left to integrate. The step grows to the
/// largest at once, and the ball still follows the floor to ε_h.
#[test]
fn a_fully_constrained_motion_takes_the_largest_step() {
    let floor = Floor::Oscillating { amplitude: 0.01, angular_frequency: 10.0 };
    let ball = Ball { mass: 1.0, gravity: 9.81, restitution: 0.5, floor };
    let (step, t_end) = (0.05, 2.0);
    let options = StepperOptions { step, local_error: Some(1e-12), ..Default::default() };
    let mut s = Stepper::new(Counted::new(ball), 0.0, Vector1::zeros(), Vector1::new(0.1), options).unwrap();
    s.advance(t_end).unwrap();
    assert!(s.in_contact(0) && s.events().iter().all(|e| e.kind != EventKind::Release));
    // Per step of the largest size: 3 stages, the end, and the projection back onto the floor
    // (2), the few more at the start; a step limited by error would need far more.
    let evaluations = s.system().evaluations.get();
    assert!(evaluations <= 6 * (t_end / step) as u64 + 10, "{evaluations} evaluations");
    let gap = s.gaps()[0];
    assert!(gap.abs() <= 1e-12, "gap {gap:e}");
}
