//! Tests of the crank modes as core systems (`engine.rs`).

use super::*;
use crate::fmus::piston_slap::mechanisms;
use crate::fmus::piston_slap::Parameters;

fn prescribed() -> PrescribedCrank {
    PrescribedCrank::new(mechanisms::crank_train::engine(&Parameters::default()).unwrap(), 0.4, 0.01, 125.66)
}

/// The crank speeding up and the pressure rising along polynomials in time, as input derivatives give them.
fn ramping() -> PrescribedCrank {
    let mut sys = PrescribedCrank::new(
        mechanisms::crank_train::engine(&Parameters { pressure_source: 1, ..Parameters::default() }).unwrap(),
        0.4,
        0.01,
        1.0,
    );
    sys.hold_speed(InputPolynomial { time: 0.01, value: 125.66, slope: 3000.0, curvature: -2e5 });
    sys.engine.hold_pressure(InputPolynomial { time: 0.01, value: 2e6, slope: 4e8, curvature: 1e10 });
    sys
}

#[test]
fn rheonomic_gap_rates_match_finite_differences_in_time() {
    for sys in [prescribed(), ramping()] {
        rheonomic_gap_rates_of(&sys);
    }
}

fn rheonomic_gap_rates_of(sys: &PrescribedCrank) {
    let (t, q, qd) = (0.013, Vector2::new(-0.05, 0.0007), Vector2::new(-28.0, 3.0));
    let ev = sys.evaluate(t, &q, &qd);
    // ḣ = J q̇ + ∂h/∂t and d = d²/dτ² h(q + q̇τ, t + τ) along a path with q̈ = 0.
    let tau = 1e-7;
    let gaps = |t: f64, q: &Vector2<f64>| sys.evaluate(t, q, &Vector2::zeros()).gap;
    let path = |s: f64| gaps(t + s, &(q + qd * s));
    let rate = (path(tau) - path(-tau)) / (2.0 * tau);
    assert!((rate - (ev.gap_jacobian * qd + ev.gap_time_rate)).norm() < 1e-8, "{rate} vs {}", ev.gap_jacobian * qd + ev.gap_time_rate);
    let tau = 1e-5;
    let second = (path(tau) - 2.0 * path(0.0) + path(-tau)) / (tau * tau);
    assert!((second - ev.gap_bias).norm() < 1e-4 * ev.gap_bias.norm(), "{second} vs {}", ev.gap_bias);
    let column = |i: usize| {
        let step = Vector2::from_fn(|r, _| if r == i { 1e-6 } else { 0.0 });
        (gaps(t, &(q + step)) - gaps(t, &(q - step))) / 2e-6
    };
    assert!((column(0) - ev.gap_jacobian.column(0)).norm() < 1e-8);
    assert!((column(1) - ev.gap_jacobian.column(1)).norm() < 1e-8);
}

#[test]
fn the_crank_cache_never_changes_a_result() {
    // Repeated, alternating and new times, a held pressure changed at an unchanged time and a
    // new speed: every evaluation is that of a system that never evaluated before.
    for pressure_source in [1, 2] {
        let p = Parameters { pressure_source, ..Parameters::default() };
        let mut sys = PrescribedCrank::new(mechanisms::crank_train::engine(&p).unwrap(), 0.1, 0.0, 125.66);
        let (q, qd) = (Vector2::new(0.05, 0.001), Vector2::new(-30.0, 2.0));
        for (t, held, speed) in
            [(0.001, 2e6, 125.66), (0.001, 2e6, 125.66), (0.002, 2e6, 125.66), (0.001, 5e6, 125.66), (0.001, 1e6, 80.0), (0.003, 1e6, 80.0)]
        {
            sys.engine.hold_pressure(InputPolynomial::held(held));
            sys.hold_speed(InputPolynomial { time: 0.0, ..InputPolynomial::held(speed) });
            let fresh = PrescribedCrank::new(sys.engine.clone(), 0.1, 0.0, speed);
            assert_eq!(sys.evaluate(t, &q, &qd), fresh.evaluate(t, &q, &qd), "t {t}, held {held}, speed {speed}");
        }
    }
}

/// The drive torque from the row a point's evaluation kept is the one computed afresh, also
/// after the pressure and the speed changed at the same state.
#[test]
fn the_kept_row_never_changes_a_drive_torque() {
    let (t, q, qd, qdd) = (0.013, Vector2::new(-0.05, 0.0007), Vector2::new(-28.0, 3.0), Vector2::new(-3000.0, 50.0));
    let forces = (Vector4::new(120.0, 0.0, 0.0, 35.0), Vector4::new(3.0, 0.0, 0.0, -1.0));
    let mut sys = ramping();
    for (pressure, speed) in [(2e6, 125.66), (5e6, 125.66), (5e6, 80.0)] {
        sys.engine.hold_pressure(InputPolynomial { time: 0.01, value: pressure, slope: 4e8, curvature: 0.0 });
        sys.hold_speed(InputPolynomial { time: 0.01, value: speed, slope: 3000.0, curvature: 0.0 });
        let fresh = PrescribedCrank { row: LastValue::default(), ..sys.clone() };
        assert_eq!(sys.evaluate_terms(t, &q, &qd, Terms::Point), fresh.evaluate(t, &q, &qd));
        let torque = sys.drive_torque(t, (&q, &qd, &qdd), (&forces.0, &forces.1));
        assert_eq!(torque.to_bits(), fresh.drive_torque(t, (&q, &qd, &qdd), (&forces.0, &forces.1)).to_bits(), "{pressure} {speed}");
    }
}

#[test]
fn inertia_and_force_are_those_of_the_full_evaluation() {
    let sys = ramping();
    let free =
        FreeCrank { engine: sys.engine.clone(), load_torque: InputPolynomial { time: 0.0, value: 12.0, slope: 100.0, curvature: 0.0 } };
    for (t, q, qd) in
        [(0.013, Vector2::new(-0.05, 0.0007), Vector2::new(-28.0, 3.0)), (0.071, Vector2::new(0.2, -0.01), Vector2::new(5.0, -40.0))]
    {
        let ev = sys.evaluate(t, &q, &qd);
        assert_eq!(sys.inertia_and_force(t, &q, &qd), (ev.mass, ev.force));
        let (phi, phid) = sys.full_state(t, &q, &qd);
        let ev = free.evaluate(t, &phi, &phid);
        assert_eq!(free.inertia_and_force(t, &phi, &phid), (ev.mass, ev.force));
    }
}

#[test]
fn speed_change_keeps_the_crank_angle_continuous() {
    let mut sys = prescribed();
    let before = sys.crank_angle(0.02);
    sys.hold_speed(InputPolynomial { time: 0.02, ..InputPolynomial::held(50.0) });
    assert_eq!(sys.crank_angle(0.02), before);
    assert!((sys.crank_angle(0.03) - (before + 0.5)).abs() < 1e-14);
    // A ramp ω = 50 + 1000 (t − 0.03) from 0.03 s: φ1 gains 50 τ + 500 τ², and a later held speed continues from there.
    sys.hold_speed(InputPolynomial { time: 0.03, value: 50.0, slope: 1000.0, curvature: 0.0 });
    assert!((sys.crank_angle(0.04) - (before + 0.5 + 0.5 + 0.05)).abs() < 1e-13);
    assert_eq!((sys.speed(0.04), sys.acceleration(0.04)), (60.0, 1000.0));
    sys.hold_speed(InputPolynomial { time: 0.04, ..InputPolynomial::held(60.0) });
    assert!((sys.crank_angle(0.05) - (before + 1.05 + 0.6)).abs() < 1e-13);
}

#[test]
fn drive_torque_balances_the_crank_row_of_the_free_equations() {
    // With φ̈ = (ω̇, q̈) and the drive torque added to the load, the free system's crank row holds; the
    // rod and piston rows hold with q̈ from the reduced system.
    for sys in [prescribed(), ramping()] {
        let (t, q, qd, qdd) = (0.02, Vector2::new(0.1, -0.001), Vector2::new(20.0, 1.0), Vector2::new(-3000.0, 50.0));
        let forces = Vector4::new(120.0, 0.0, 0.0, 35.0);
        let torque = sys.drive_torque(t, (&q, &qd, &qdd), (&forces, &Vector4::zeros()));
        let (phi, phid) = sys.full_state(t, &q, &qd);
        let free = FreeCrank { engine: sys.engine.clone(), load_torque: InputPolynomial::held(-torque) }.evaluate(t, &phi, &phid);
        let phidd = Vector3::new(sys.acceleration(t), qdd[0], qdd[1]);
        let residual = free.mass * phidd - free.force - free.gap_jacobian.transpose() * forces;
        assert!(residual[0].abs() < 1e-9 * torque.abs().max(1.0), "residual {residual}");
        let reduced = sys.evaluate(t, &q, &qd);
        let rows = reduced.mass * qdd - reduced.force - reduced.gap_jacobian.transpose() * forces;
        assert!((rows - residual.fixed_rows::<2>(1)).norm() < 1e-9 * free.force.norm(), "{rows} vs {residual}");
    }
}
