//! Two constraints closed at once: the complementarity impact law (DESIGN §6.4) and persistent
//! contact on both, against hand-solved cases.

use crate::common::testbeds::{Floor, Rod, Wedge};
use nalgebra::{Vector2, Vector3};
use pistonslap::dynamics::{EventKind, Stepper, StepperOptions};

/// Floor `y ≥ 0` and a wall with inward normal at 60° to it (interior angle 120°): n₁·n₂ = ½.
fn wedge(gravity: Vector2<f64>, restitution: f64) -> Wedge {
    let n2 = Vector2::new(3f64.sqrt() / 2.0, 0.5);
    Wedge { mass: 1.0, gravity, normals: [Vector2::new(0.0, 1.0), n2], restitution }
}

fn at_corner(w: Wedge, v: Vector2<f64>) -> Stepper<Wedge, 2, 2> {
    Stepper::new(w, 0.0, Vector2::zeros(), v, StepperOptions::default()).unwrap()
}

/// Arriving at the corner along the bisector, W = [[1, ½], [½, 1]] and ġ⁻ = −(√3/2)(1, 1):
/// both impulses Λ = (1 + e)(√3/2)/(3/2) push, and the velocity reverses: q̇⁺ = −e q̇⁻.
#[test]
fn corner_impact_along_the_bisector_reverses() {
    for e in [1.0, 0.4] {
        let w = wedge(Vector2::zeros(), e);
        let inward = -(w.normals[0] + w.normals[1]).normalize();
        let s = at_corner(w, inward);
        let impacts: Vec<_> = s.events().iter().filter(|ev| ev.kind == EventKind::Impact).collect();
        assert_eq!(impacts.len(), 2);
        assert!((s.velocity() + inward * e).norm() < 1e-14, "e = {e}: {}", s.velocity());
        let lost: f64 = impacts.iter().map(|ev| ev.energy_lost).sum();
        assert!((lost - 0.5 * (1.0 - e * e)).abs() < 1e-14, "T⁻ − T⁺ = (1 − e²)/2");
        // One impact, two events: the first carries both impulses, the second none.
        let each = (1.0 + e) * (3f64.sqrt() / 2.0) / 1.5;
        assert!((impacts[0].impulses - Vector2::new(each, each)).norm() < 1e-14, "{}", impacts[0].impulses);
        assert_eq!(impacts[1].impulses, Vector2::zeros());
    }
}

/// ġ⁻ = (−1, −0.1): solving both as equalities would need Λ₂ = −(4/3)(0.8) < 0 (a pull). The
/// complementarity law drops wall 2: Λ = (2, 0), q̇⁺ = q̇⁻ + 2 n₁, and wall 2 separates with
/// ġ₂⁺ = −0.1 + ½·2 = 0.9.
#[test]
fn corner_impact_drops_the_pulling_constraint() {
    let w = wedge(Vector2::zeros(), 1.0);
    let v = Vector2::new(0.4 / (3f64.sqrt() / 2.0), -1.0);
    let s = at_corner(w, v);
    let impacts: Vec<_> = s.events().iter().filter(|ev| ev.kind == EventKind::Impact).collect();
    assert_eq!(impacts.len(), 2, "both approached");
    assert!((s.velocity() - (v + Vector2::new(0.0, 2.0))).norm() < 1e-14);
    let wall = impacts.iter().find(|ev| ev.constraint == 1).unwrap();
    assert!((wall.velocity_before + 0.1).abs() < 1e-14 && (wall.velocity_after - 0.9).abs() < 1e-14);
    assert_eq!(wall.energy_lost, 0.0, "no impulse on the wall");
}

/// At rest in the corner with gravity along the bisector, m g = λ₁ n₁ + λ₂ n₂ with λ₁ = λ₂ = g/√3.
#[test]
fn resting_in_the_corner_uses_both_constraints() {
    let w = wedge(Vector2::zeros(), 0.5);
    let down = -(w.normals[0] + w.normals[1]).normalize() * 9.81;
    let mut s = at_corner(Wedge { gravity: down, ..w }, Vector2::zeros());
    s.advance(0.1).unwrap();
    assert!(s.in_contact(0) && s.in_contact(1));
    let lambda = 9.81 / 3f64.sqrt();
    assert!((s.multipliers() - Vector2::new(lambda, lambda)).norm() < 1e-12);
    assert!(s.position().norm() < 1e-15 && s.velocity().norm() < 1e-15);
}

/// A rod landing flat on both ends at once: W = (1/m)[[4, −2], [−2, 4]], the symmetric impulses
/// m(1 + e)v/2 each, so it bounces flat with ẏ⁺ = e v and no spin. (A sequence of single impacts
/// at either end would set it spinning.)
#[test]
fn rod_landing_flat_bounces_flat() {
    let (v, e, gap) = (1.5, 0.7, 1e-3);
    let rod = Rod { mass: 2.0, length: 1.0, gravity: 0.0, restitution: e, friction: 0.0, floor: Floor::Fixed };
    let mut s = Stepper::new(
        rod,
        0.0,
        Vector3::new(0.0, gap, 0.0),
        Vector3::new(0.0, -v, 0.0),
        StepperOptions { step: 1e-4, ..Default::default() },
    )
    .unwrap();
    s.advance(2e-3).unwrap();
    let impacts: Vec<_> = s.events().iter().filter(|ev| ev.kind == EventKind::Impact).collect();
    assert_eq!(impacts.len(), 2);
    assert!(impacts.iter().all(|ev| (ev.time - gap / v).abs() < 1e-12 && (ev.velocity_after - e * v).abs() < 1e-12));
    assert!((s.velocity() - Vector3::new(0.0, e * v, 0.0)).norm() < 1e-12);
}

/// A tumbling rod dropped on the floor bounces, accumulates impacts at both ends and comes to
/// rest flat (sin θ = 0) on both: λ = (mg/2, mg/2). The floor is frictionless, so ẋ never changes.
#[test]
fn tumbling_rod_comes_to_rest_on_both_ends() {
    let (m, g) = (1.2, 9.81);
    let rod = Rod { mass: m, length: 1.0, gravity: g, restitution: 0.5, friction: 0.0, floor: Floor::Fixed };
    let mut s = Stepper::new(
        rod,
        0.0,
        Vector3::new(0.0, 1.0, 0.3),
        Vector3::new(0.5, 0.0, 4.0),
        StepperOptions { step: 1e-4, ..Default::default() },
    )
    .unwrap();
    s.advance(3.0).unwrap();
    assert!(s.in_contact(0) && s.in_contact(1), "events: {}", s.events().len());
    assert!((s.multipliers() - Vector2::new(0.5 * m * g, 0.5 * m * g)).norm() < 1e-9, "λ = {}", s.multipliers());
    let (q, v) = (s.position(), s.velocity());
    assert!(q[1].abs() < 1e-12 && libm::sin(q[2]).abs() < 1e-12);
    assert!((v - Vector3::new(0.5, 0.0, 0.0)).norm() < 1e-12, "v = {v}");
    assert!((q[0] - 1.5).abs() < 1e-9, "x = ẋ t");
    // Energy balance: T + V at the start (y = 1, ẋ = 0.5, θ̇ = 4, I = m/12) less the final ½ m ẋ²
    // is what the recorded events dissipated.
    let lost: f64 = s.events().iter().map(|ev| ev.energy_lost).sum();
    let initial = 0.5 * m * 0.25 + 0.5 * (m / 12.0) * 16.0 + m * g * 1.0;
    assert!((lost - (initial - 0.5 * m * 0.25)).abs() < 1e-9, "lost {lost}");
}

/// A rod lying flat on a floor shaking as A sin(Ωt): each end carries λ = m (g + ÿ_f)/2 and both
/// leave together when g + ÿ_f = 0, at sin Ω t_r = g/(AΩ²): two multipliers crossing zero at once.
#[test]
fn rod_on_a_shaking_floor_leaves_on_both_ends_at_once() {
    let (m, g, a, w) = (0.8, 9.81, 0.01, 50.0);
    let floor = Floor::Oscillating { amplitude: a, angular_frequency: w };
    let rod = Rod { mass: m, length: 1.0, gravity: g, restitution: 0.5, friction: 0.0, floor };
    let mut s =
        Stepper::new(rod, 0.0, Vector3::zeros(), Vector3::new(0.0, a * w, 0.0), StepperOptions { step: 1e-4, ..Default::default() })
            .unwrap();
    assert!(s.in_contact(0) && s.in_contact(1));
    s.advance(0.004).unwrap();
    let lambda = 0.5 * m * (g - a * w * w * libm::sin(w * 0.004));
    assert!((s.multipliers() - Vector2::new(lambda, lambda)).norm() < 1e-9, "λ = {}", s.multipliers());
    s.advance(0.01).unwrap();
    let t_r = libm::asin(g / (a * w * w)) / w;
    let releases: Vec<_> = s.events().iter().filter(|ev| ev.kind == EventKind::Release).collect();
    assert_eq!(releases.len(), 2);
    assert!(releases.iter().all(|ev| (ev.time - t_r).abs() < 1e-12), "{releases:?} vs {t_r}");
    assert!(!s.in_contact(0) && !s.in_contact(1));
    assert!(s.velocity()[2].abs() < 1e-9, "no spin from a symmetric release");
}
