//! Coulomb friction in the core against closed forms: a block on a moving belt slips, then sticks
//! (the stick located as an event, the dissipated energy ½ m Δv²), a block pushed harder and
//! harder sticks, then slips once the push reaches μ m g, one that comes to rest while the
//! push still exceeds the cone slips back for an instant shorter than the step's samples, and a
//! rod flat on the floor slides on both ends, then sticks on both.

use crate::common::testbeds::{Block, Floor, Rod, Toggle};
use nalgebra::{Vector2, Vector3};
use pistonslap::dynamics::{EventKind, Stepper, StepperOptions};

const G: f64 = 9.81;

fn block(belt: f64, push_rate: f64, speed: f64) -> Stepper<Block, 2, 1> {
    block_from(0.0, belt, push_rate, speed)
}

fn block_from(t0: f64, belt: f64, push_rate: f64, speed: f64) -> Stepper<Block, 2, 1> {
    let block = Block { mass: 2.0, gravity: G, friction: 0.5, belt, push_rate, restitution: 0.5 };
    let options = StepperOptions { step: 1e-3, ..Default::default() };
    let s = Stepper::new(block, t0, Vector2::zeros(), Vector2::new(speed, 0.0), options).unwrap();
    assert!(s.in_contact(0), "resting on the belt");
    s
}

/// Thrown at 3 m/s onto a belt running at 1 m/s: the friction force −μ m g decelerates it at μ g
/// until t* = (3 − 1)/(μ g), x = 3 t − μ g t²/2; then it sticks and rides the belt. Friction
/// dissipates ½ m (3 − 1)² = 4 J, whatever μ.
#[test]
fn a_block_faster_than_its_belt_slips_then_sticks() {
    let mut s = block(1.0, 0.0, 3.0);
    let stick = 2.0 / (0.5 * G);
    for t in [0.1, 0.3, stick - 1e-3] {
        s.advance(t).unwrap();
        let x = 3.0 * t - 0.25 * G * t * t;
        assert!((s.position()[0] - x).abs() < 1e-12, "t {t}: x {} vs {x}", s.position()[0]);
        assert!((s.friction_forces()[0] + 0.5 * 2.0 * G).abs() < 1e-12, "slipping: λ_T = −μ λ_N");
        assert!(!s.sticking(0));
    }
    s.advance(1.0).unwrap();
    let sticks: Vec<f64> = s.events().iter().filter(|e| e.kind == EventKind::Stick).map(|e| e.time).collect();
    assert_eq!(sticks.len(), 1, "{:?}", s.events());
    assert!((sticks[0] - stick).abs() < 1e-9, "stick at {} vs {stick}", sticks[0]);
    assert!(s.sticking(0) && s.friction_forces()[0].abs() < 1e-12, "riding the belt needs no force");
    let x = 3.0 * stick - 0.25 * G * stick * stick + (1.0 - stick);
    assert!((s.position()[0] - x).abs() < 1e-9 && (s.velocity()[0] - 1.0).abs() < 1e-12, "{:?}", s.position());
    let (power, work) = s.friction_dissipation();
    assert_eq!(power, 0.0);
    assert!((work - 4.0).abs() < 1e-9, "dissipated {work} J");
}

/// At rest on a still belt and pushed by k t (k = 10 N/s): it sticks while k t ≤ μ m g, then
/// slips at t_s = μ m g / k with m ẍ = k (t − t_s), so x = k (t − t_s)³ / (6 m).
#[test]
fn a_block_pushed_ever_harder_sticks_then_slips() {
    let mut s = block(0.0, 10.0, 0.0);
    let slip = 0.5 * 2.0 * G / 10.0;
    s.advance(slip - 0.05).unwrap();
    assert!(s.sticking(0) && s.position()[0] == 0.0, "sticks: {:?}", s.position());
    assert!((s.friction_forces()[0] + 10.0 * s.time()).abs() < 1e-9, "holds the push: {}", s.friction_forces()[0]);
    s.advance(slip + 0.3).unwrap();
    let slips: Vec<f64> = s.events().iter().filter(|e| e.kind == EventKind::Slip).map(|e| e.time).collect();
    assert_eq!(slips.len(), 1, "{:?}", s.events());
    assert!((slips[0] - slip).abs() < 1e-9, "slips at {} vs {slip}", slips[0]);
    let x = 10.0 * 0.3_f64.powi(3) / 12.0;
    assert!((s.position()[0] / x - 1.0).abs() < 1e-6, "x {} vs {x}", s.position()[0]);
    assert!(!s.sticking(0) && (s.friction_forces()[0] + 0.5 * 2.0 * G).abs() < 1e-9);
}

/// Sliding forward against the push k t (k = 10⁴ N/s, from t₀ = −10 ms) on a still belt, it comes
/// to rest at t_r = t_c − δ, just before the push enters the friction cone at t_c = −μ m g / k
/// (δ = 50 µs): it slips back, m v̇ = k t + μ m g, so v = k (t − t_r)(t − t_2) / (2 m) with the
/// slip ending at t_2 = t_c + δ, where the push is within the cone and the block sticks; it slips
/// forward again at −t_c. The backward slip (100 µs, |v| ≤ k δ² / (2 m) = 6.25 µm/s) ends
/// before the step's first sample: it is located, not taken for a reversal at its own start.
#[test]
fn a_block_at_rest_beyond_the_cone_slips_back_for_an_instant_then_sticks() {
    let (m, k, t0, delta) = (2.0, 1e4, -0.01, 5e-5);
    let cone = 0.5 * m * G;
    let t_c = -cone / k;
    let (t_r, t_2) = (t_c - delta, t_c + delta);
    // v(t) = v0 + (k (t² − t0²)/2 − μ m g (t − t0)) / m, zero at t_r.
    let v0 = -(0.5 * k * (t_r * t_r - t0 * t0) - cone * (t_r - t0)) / m;
    let x = |t: f64| v0 * (t - t0) + (k * ((t.powi(3) - t0.powi(3)) / 3.0 - t0 * t0 * (t - t0)) / 2.0 - cone * (t - t0).powi(2) / 2.0) / m;
    let back = 2.0 * k * delta.powi(3) / (3.0 * m);
    let mut s = block_from(t0, 0.0, k, v0);
    s.advance(0.0).unwrap();
    assert!(s.sticking(0) && (s.position()[0] - (x(t_r) - back)).abs() < 1e-12, "x {} vs {}", s.position()[0], x(t_r) - back);
    s.advance(2e-3).unwrap();
    let changes: Vec<(EventKind, f64)> =
        s.events().iter().filter(|e| matches!(e.kind, EventKind::Slip | EventKind::Stick)).map(|e| (e.kind, e.time)).collect();
    let expected = [(EventKind::Slip, t_r), (EventKind::Stick, t_2), (EventKind::Slip, -t_c)];
    assert_eq!(changes.len(), 3, "{changes:?}");
    for ((kind, t), (kind_expected, t_expected)) in changes.iter().zip(expected) {
        assert!(*kind == kind_expected && (t - t_expected).abs() < 1e-9, "{kind:?} at {t} vs {kind_expected:?} at {t_expected}");
    }
    let (_, work) = s.friction_dissipation();
    let slid = x(t_r) + back + (s.position()[0] - (x(t_r) - back));
    assert!((work - cone * slid).abs() < 1e-9 * work, "friction work {work} J vs μ m g × {slid} m");
}

/// A uniform rod (2 kg, 1 m) lying flat on the floor, thrown along its axis at 2 m/s, μ = 0.4:
/// the friction at its ends acts on the line of its centre, so each end carries m g / 2 and it
/// slides to rest at t* = v₀/(μ g), x* = v₀²/(2 μ g), dissipating ½ m v₀²; then both ends stick
/// (how the zero friction force splits between them is not determined, its sum is: zero) and it
/// stays there.
#[test]
fn a_rod_flat_on_the_floor_slides_then_sticks_on_both_ends() {
    let (m, mu, v0) = (2.0, 0.4, 2.0);
    let rod = Rod { mass: m, length: 1.0, gravity: G, restitution: 0.5, friction: mu, floor: Floor::Fixed };
    let options = StepperOptions { step: 1e-3, ..Default::default() };
    let mut s = Stepper::new(rod, 0.0, Vector3::zeros(), Vector3::new(v0, 0.0, 0.0), options).unwrap();
    assert!(s.in_contact(0) && s.in_contact(1), "lying on both ends");
    let rest = v0 / (mu * G);
    for t in [0.1, 0.3, rest - 1e-3] {
        s.advance(t).unwrap();
        let x = v0 * t - 0.5 * mu * G * t * t;
        assert!((s.position()[0] - x).abs() < 1e-12 && s.position()[2].abs() < 1e-12, "t {t}: {:?} vs x {x}", s.position());
        for (i, f) in s.friction_forces().iter().enumerate() {
            assert!((f + 0.5 * mu * m * G).abs() < 1e-9, "t {t}: end {i} carries λ_T {f}, not −μ m g / 2");
        }
    }
    s.advance(2.0).unwrap();
    let sticks: Vec<f64> = s.events().iter().filter(|e| e.kind == EventKind::Stick).map(|e| e.time).collect();
    assert!(!sticks.is_empty() && sticks.iter().all(|t| (t - rest).abs() < 1e-9), "sticks at {sticks:?}, not {rest}");
    assert!(s.sticking(0) && s.sticking(1), "both ends stick");
    assert!(s.velocity().norm() < 1e-12 && s.friction_forces().sum().abs() < 1e-9, "{:?}, {:?}", s.velocity(), s.friction_forces());
    let x = v0 * v0 / (2.0 * mu * G);
    assert!((s.position()[0] - x).abs() < 1e-9 && s.position()[2].abs() < 1e-12, "{:?} vs x {x}", s.position());
    let (_, work) = s.friction_dissipation();
    assert!((work - 0.5 * m * v0 * v0).abs() < 1e-9, "dissipated {work} J");
}

/// A flywheel (I = 1e-4 kg·m²) drives a 2 kg block on the floor (μ = 0.5) through a lever L sin φ
/// (`Toggle`, L = 5 cm), 1e-5 rad before the dead centre. Turning at 1e-4 rad/s it slips the block at
/// 5e-11 m/s, within ε_ḣ: neither slip is consistent (friction, μ m g L sin φ on the flywheel,
/// reverses either), and the stick's rows are dependent to 5e-9. The stick taken stops the
/// flywheel by its tangential impulse (an impact without collision): it stays at rest where it
/// was, as real friction stops it within I φ̇² / (2 μ m g L |sin φ|) = 1e-7 rad, and friction has
/// dissipated its kinetic energy. Turning at 1 rad/s it passes the dead centre, the block's slip
/// reversing there with the lever, and friction takes μ m g times the distance slid.
#[test]
fn a_flywheel_creeping_into_a_dead_centre_is_stopped_by_the_stick_a_fast_one_passes() {
    let toggle = Toggle { inertia: 1e-4, mass: 2.0, lever: 0.05, gravity: G, friction: 0.5 };
    let phi0 = -1e-5;
    let options = StepperOptions { step: 1e-4, ..Default::default() };
    let start = |speed: f64| Stepper::new(toggle.clone(), 0.0, Vector2::new(phi0, 0.0), Vector2::new(speed, 0.0), options.clone()).unwrap();

    let slow = 1e-4;
    let mut s = start(slow);
    s.advance(0.01).unwrap();
    assert!(s.sticking(0) && s.velocity()[0] == 0.0 && s.position()[0] == phi0, "{:?}, {:?}", s.position(), s.velocity());
    let stop: f64 = s.events().iter().map(|e| e.friction_energy).sum();
    let kinetic = 0.5 * toggle.inertia_at(phi0) * slow * slow;
    assert!((stop - kinetic).abs() < 1e-9 * kinetic, "the stop dissipated {stop:e} J, the flywheel had {kinetic:e} J");

    let fast = 1.0;
    let mut s = start(fast);
    let t = 1e-3;
    s.advance(t).unwrap();
    let phi = s.position()[0];
    assert!(phi > 0.9 * fast * t && !s.sticking(0), "passed the dead centre: φ {phi}");
    let slid = toggle.lever * ((1.0 - libm::cos(phi0)) + (1.0 - libm::cos(phi)));
    let (_, work) = s.friction_dissipation();
    let cone = 0.5 * toggle.mass * G;
    assert!((work - cone * slid).abs() < 1e-6 * cone * slid, "friction work {work:e} J vs μ m g × {slid:e} m");
    let kinetic = |phi: f64, speed: f64| 0.5 * toggle.inertia_at(phi) * speed * speed;
    let lost = kinetic(phi0, fast) - kinetic(phi, s.velocity()[0]);
    assert!((lost - work).abs() < 1e-6 * work, "kinetic energy lost {lost:e} J vs friction work {work:e} J");
}
