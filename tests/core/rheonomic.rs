//! Moving constraints: ∂h/∂t in the impact law (eq 7) and ∂²h/∂t² in the sliding law (eq 18).

use crate::common::testbeds::{Ball, Floor};
use nalgebra::Vector1;
use pistonslap::dynamics::{EventKind, Stepper, StepperOptions};

fn ball(gravity: f64, restitution: f64, floor: Floor, y: f64, v: f64) -> Stepper<Ball, 1, 1> {
    let ball = Ball { mass: 1.0, gravity, restitution, floor };
    Stepper::new(ball, 0.0, Vector1::new(y), Vector1::new(v), StepperOptions { step: 1e-3, ..Default::default() }).unwrap()
}

/// A wall moving at speed u meets a ball of speed v: ḣ⁺ = −e ḣ⁻ with ḣ = v − u, so
/// v⁺ = (1 + e) u − e v. The energy dissipated is the loss in the wall's frame,
/// ½ m (1 − e²) (v − u)², not T⁻ − T⁺ = ½ m (v² − v⁺²), which also holds the wall's work
/// (negative in the first case: the wall speeds the ball up): the wall's work −Λ ∂h/∂t.
#[test]
fn moving_wall_enters_the_impact_law() {
    let e = 0.5;
    // (wall speed u, ball start y, ball speed v, impact time y/(u − v) with the wall at u·t)
    for (u, y, v) in [(0.5, 1.0, 0.0), (-1.0, 1.0, -2.0)] {
        let mut s = ball(0.0, e, Floor::Moving { velocity: u }, y, v);
        s.advance(3.0).unwrap();
        let impacts: Vec<_> = s.events().iter().filter(|ev| ev.kind == EventKind::Impact).collect();
        assert_eq!(impacts.len(), 1);
        let ev = impacts[0];
        let v_plus = (1.0 + e) * u - e * v;
        assert!((ev.time - y / (u - v)).abs() < 1e-12, "impact at {}", ev.time);
        assert!((ev.velocity_before - (v - u)).abs() < 1e-12);
        assert!((ev.velocity_after + e * (v - u)).abs() < 1e-12);
        let lost = 0.5 * (1.0 - e * e) * (v - u) * (v - u);
        assert!((ev.energy_lost - lost).abs() < 1e-12, "dissipated {} vs {lost}", ev.energy_lost);
        let wall_work = 0.5 * (v_plus * v_plus - v * v) + lost;
        assert!(wall_work.abs() > 0.1, "the wall must do work for this case to tell the formulas apart");
        // The recorded impulse m (v⁺ − v), and the wall's work through it −Λ ∂h/∂t = Λ u.
        assert!((ev.impulses[0] - (v_plus - v)).abs() < 1e-12, "impulse {}", ev.impulses[0]);
        assert!((ev.impulses[0] * u - wall_work).abs() < 1e-12);
        assert!((s.velocity()[0] - v_plus).abs() < 1e-12);
    }
}

/// A ball resting on a floor oscillating as A sin(Ωt) feels λ = m (g + ÿ_f) = m (g − AΩ² sin Ωt)
/// and leaves the floor when this reaches zero: sin Ω t_r = g / (AΩ²).
#[test]
fn oscillating_floor_releases_the_ball_when_the_force_vanishes() {
    let (g, a, w) = (9.81, 0.01, 50.0);
    let mut s = ball(g, 0.5, Floor::Oscillating { amplitude: a, angular_frequency: w }, 0.0, a * w);
    assert!(s.in_contact(0), "starts at rest on the floor");
    s.advance(0.004).unwrap();
    assert!((s.multipliers()[0] - (g - a * w * w * libm::sin(w * 0.004))).abs() < 1e-9);
    assert!((s.position()[0] - a * libm::sin(w * 0.004)).abs() < 1e-12, "tracks the floor");
    s.advance(0.02).unwrap();
    let release = s.events().iter().find(|ev| ev.kind == EventKind::Release).expect("released");
    let t_r = libm::asin(g / (a * w * w)) / w;
    assert!((release.time - t_r).abs() < 1e-12, "release at {} vs {t_r}", release.time);
}

/// A ball bouncing on a table vibrating with period P = 0.5 s (peak acceleration 1.6 g): shifted
/// back by 3P halfway (the core's `shift`, a symmetry of the system), it meets the same impacts
/// 3P earlier in its new time.
#[test]
fn a_shift_by_a_period_keeps_the_motion() {
    let floor = Floor::Oscillating { amplitude: 0.1, angular_frequency: 4.0 * std::f64::consts::PI };
    let (mut whole, mut shifted) = (ball(9.81, 0.5, floor, 0.3, 0.0), ball(9.81, 0.5, floor, 0.3, 0.0));
    whole.advance(5.0).unwrap();
    shifted.advance(2.5).unwrap();
    let before = shifted.events().len();
    shifted.shift(-1.5, &Vector1::zeros()).unwrap();
    shifted.advance(3.5).unwrap();
    let impacts = |s: &Stepper<Ball, 1, 1>| s.events().iter().filter(|ev| ev.kind == EventKind::Impact).count();
    assert!(
        before > 5 && impacts(&whole) > before + 5,
        "impacts on both sides of the shift: {} of {} events, {before} before",
        impacts(&whole),
        whole.events().len()
    );
    assert_eq!(whole.events().len(), shifted.events().len());
    for (k, (a, b)) in whole.events().iter().zip(shifted.events()).enumerate() {
        let offset = if k < before { 0.0 } else { 1.5 };
        assert_eq!(a.kind, b.kind);
        assert!((a.time - (b.time + offset)).abs() < 1e-9, "event {k}: {} vs {} + {offset}", a.time, b.time);
        assert!((a.velocity_before - b.velocity_before).abs() < 1e-9);
    }
    assert!((whole.position() - shifted.position()).amax() < 1e-9 && (whole.velocity() - shifted.velocity()).amax() < 1e-9);
}
