//! Tests of the crank modes as core systems (`drive.rs`).

use super::*;
use crate::models::Parameters;

fn prescribed() -> PrescribedCrank {
    PrescribedCrank::new(Engine::new(&Parameters::default()).unwrap(), 0.4, 0.01, 125.66)
}

/// The crank speeding up and the pressure rising along polynomials in time, as input derivatives give them.
fn ramping() -> PrescribedCrank {
    let mut sys = PrescribedCrank::new(Engine::new(&Parameters { pressure_source: 1, ..Parameters::default() }).unwrap(), 0.4, 0.01, 1.0);
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
        let mut sys = PrescribedCrank::new(Engine::new(&p).unwrap(), 0.1, 0.0, 125.66);
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
fn the_point_row_never_changes_a_drive_torque() {
    let (t, q, qd, qdd) = (0.013, Vector2::new(-0.05, 0.0007), Vector2::new(-28.0, 3.0), Vector2::new(-3000.0, 50.0));
    let forces = (Vector4::new(120.0, 0.0, 0.0, 35.0), Vector4::new(3.0, 0.0, 0.0, -1.0));
    let mut sys = ramping();
    for (pressure, speed) in [(2e6, 125.66), (5e6, 125.66), (5e6, 80.0)] {
        sys.engine.hold_pressure(InputPolynomial { time: 0.01, value: pressure, slope: 4e8, curvature: 0.0 });
        sys.hold_speed(InputPolynomial { time: 0.01, value: speed, slope: 3000.0, curvature: 0.0 });
        let fresh = PrescribedCrank { point_row: LastValue::default(), ..sys.clone() };
        assert_eq!(sys.evaluate_point(t, &q, &qd), fresh.evaluate(t, &q, &qd));
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

/// On the lubricated skirt each corner sits on the profiled edge of its side (`Linkage::on_profile`): at
/// every pose its gap is the film thickness at that edge on the thrust axis, on a barrel with ovality and
/// pin offset, to round-off; a piston tilted onto its top thrust corner touches the liner exactly where
/// the thrust side's film reaches zero, where the papers' corner (on d/2) lies the top drop inside the liner.
#[test]
fn the_lubricated_corners_touch_where_the_film_at_their_edge_is_zero() {
    // 13 circumferential nodes: a closed column at θ = 0 and π, where the corners are.
    let p = Parameters {
        skirt_model: 2,
        skirt_profile: "parabola 10e-6 20e-6".into(),
        skirt_ovality: 30e-6,
        pin_offset: 1e-3,
        skirt_grid_circumferential: 13,
        ..Parameters::default()
    };
    let engine = Engine::new(&p).unwrap();
    let dry = Engine::new(&Parameters { skirt_model: 1, ..p.clone() }).unwrap();
    let lubrication = engine.lubrication.as_ref().unwrap();
    let (l1, l2) = (p.crank_radius, p.rod_length);
    // (map side, its row: the top edge or the bottom) of K1..K4.
    let edges = [(1, 0), (1, 1), (0, 0), (0, 1)];
    let film_at_corners = |phi: &Vector3<f64>| {
        let map = lubrication.pressure_map((phi, &LinkAngles::new(phi)), &Vector3::new(125.0, -30.0, 0.5));
        edges.map(|(side, bottom)| {
            let s = &map.sides[side];
            let (columns, rows) = (s.angle.len(), s.position.len());
            let centre = columns / 2;
            assert!((libm::cos(s.angle[centre]).abs() - 1.0).abs() < 1e-15);
            s.film[if bottom == 1 { rows - 1 } else { 0 } * columns + centre]
        })
    };
    // The rod angle that puts the pin at x (l2 sin φ2 = −(x + l1 sin φ1)).
    let rod = |phi1: f64, x: f64| libm::asin(-(x + l1 * libm::sin(phi1)) / l2);
    // Poses within the clearance: the pin off its centred position x = a by δ, tilted.
    for (phi1, offset, tilt) in [(0.3, -20e-6, 2e-4), (2.0, 10e-6, -4e-4), (4.0, 0.0, 0.0), (5.5, 30e-6, 6e-4)] {
        let phi = Vector3::new(phi1, rod(phi1, p.pin_offset + offset), tilt);
        let (gaps, film) = (engine.linkage.gaps(&phi), film_at_corners(&phi));
        for k in 0..4 {
            assert!((gaps[k] - film[k]).abs() < 1e-15, "K{}: gap {} film {}", k + 1, gaps[k], film[k]);
        }
    }
    // Tilted clockwise, the top thrust corner K3 leads: the rod angle that puts it on the liner (its gap
    // falls one for one as the pin moves toward +x).
    let (phi1, tilt) = (0.5, -1e-3);
    let start = Vector3::new(phi1, 0.0, tilt);
    let x = -l1 * libm::sin(phi1) + engine.linkage.gaps(&start)[2];
    let phi = Vector3::new(phi1, rod(phi1, x), tilt);
    let gap = engine.linkage.gaps(&phi)[2];
    assert!(gap.abs() < 1e-15, "{gap}");
    let thrust = lubrication.pressure_map((&phi, &LinkAngles::new(&phi)), &Vector3::zeros()).sides[0].film.clone();
    let thinnest = thrust.iter().copied().fold(f64::INFINITY, f64::min);
    assert!(thinnest.abs() < 1e-15 && film_at_corners(&phi)[2].abs() < 1e-15, "{thinnest}");
    // The papers' corner lies the top drop further out, across the tilted axis: 10 µm cos φ3.
    assert!((dry.linkage.gaps(&phi)[2] + 10e-6 * libm::cos(tilt)).abs() < 1e-15, "{}", dry.linkage.gaps(&phi)[2]);
}
