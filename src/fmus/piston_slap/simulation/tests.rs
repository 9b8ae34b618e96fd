use super::test_model::{Shuttle, SHUTTLE_SPEED};
use super::*;
use crate::fmus::piston_slap::Mechanism;
use crate::models::{EngineModel, ModelError};
use std::path::PathBuf;

type Sim = Simulation<Shuttle>;

/// Half clearance c of the defaults: (0.08008 − 0.08)/2.
const C: f64 = 4e-5;

fn run(sim: &mut Sim, inputs: &Inputs, t_end: f64, h: f64) {
    let t0 = sim.time();
    let mut k = 1;
    while sim.time() < t_end {
        sim.step(inputs, (t0 + k as f64 * h).min(t_end)).unwrap();
        k += 1;
    }
}

/// Impact times of the shuttle from x = 0, ẋ = v0: t1 = c/v0, then 2c/(eᵏ v0) between impacts.
fn impact_times(e: f64, n: usize) -> Vec<f64> {
    let mut t = vec![C / SHUTTLE_SPEED];
    for k in 1..n {
        t.push(t[k - 1] + 2.0 * C / (e.powi(k as i32) * SHUTTLE_SPEED));
    }
    t
}

fn temp_path(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("pistonslap_{}_{name}.csv", std::process::id()))
}

#[test]
fn impact_statistics_match_the_closed_form() {
    let p = Parameters::default();
    let e = p.restitution;
    let times = impact_times(e, 4);
    assert!(times[2] < 0.1 && times[3] > 0.1, "three impacts before 0.1 s: {times:?}");
    let inputs = Inputs::default();
    let mut sim = Sim::new(&p, 0.0).unwrap();
    let mut in_steps = 0;
    let mut max_in_steps: f64 = 0.0;
    for k in 1..=100 {
        sim.step(&inputs, k as f64 * 1e-3).unwrap();
        in_steps += sim.outputs().impacts_in_step;
        max_in_steps = max_in_steps.max(sim.outputs().max_impact_velocity_in_step);
    }
    let out = sim.outputs();
    assert_eq!(out.impact_count, 3);
    assert_eq!(in_steps, 3);
    assert_eq!(max_in_steps, SHUTTLE_SPEED);
    assert!((out.impact_velocity - e * e * SHUTTLE_SPEED).abs() < 1e-15);
    assert_eq!(out.last_impact_corner, 3, "the third impact is on the +x wall again");
    let energy = 0.5 * p.piston_mass * SHUTTLE_SPEED.powi(2) * (1.0 - e.powi(6));
    assert!((out.impact_energy_total - energy).abs() < 1e-12 * energy, "{} vs {energy}", out.impact_energy_total);
    assert!((out.last_impact_crank_angle - inputs.crank_speed * times[2]).abs() < 1e-9);
    // The model's own outputs come through as well: after 0.1 s the shuttle heads for −c at e³v0.
    assert!((out.piston_lateral_velocity + e.powi(3) * SHUTTLE_SPEED).abs() < 1e-15);
}

#[test]
fn the_step_size_does_not_change_the_statistics() {
    let p = Parameters::default();
    let (mut fine, mut coarse) = (Sim::new(&p, 0.0).unwrap(), Sim::new(&p, 0.0).unwrap());
    run(&mut fine, &Inputs::default(), 0.1, 1e-4);
    run(&mut coarse, &Inputs::default(), 0.1, 0.03);
    let (f, c) = (fine.outputs(), coarse.outputs());
    assert_eq!(f.impact_count, c.impact_count);
    assert!((f.impact_energy_total - c.impact_energy_total).abs() < 1e-15);
    assert!((f.piston_lateral - c.piston_lateral).abs() < 1e-12);
}

#[test]
fn a_failed_step_leaves_the_simulation_as_it_was() {
    let mut sim = Sim::new(&Parameters::default(), 0.0).unwrap();
    run(&mut sim, &Inputs::default(), 0.01, 1e-3);
    let before = sim.clone();
    let failing = Inputs { gas_pressure: -1.0, ..Inputs::default() };
    let err = sim.step(&failing, 0.011).unwrap_err();
    assert!(err.0.contains("negative gas_pressure") && err.0.contains("t = 0.01"), "{err}");
    assert_eq!(sim, before);
    for bad in [f64::NAN, f64::INFINITY] {
        let nan = Inputs { crank_speed: bad, ..Inputs::default() };
        assert!(sim.step(&nan, 0.011).unwrap_err().0.contains("crank_speed"));
        assert_eq!(sim, before);
    }
    for t_end in [0.01, 0.005, f64::NAN] {
        assert!(sim.step(&Inputs::default(), t_end).is_err());
        assert_eq!(sim, before);
    }
}

/// A step refused after the model advanced and the outputs were written (its impact cannot be
/// logged: the file is gone) puts the model and the outputs back.
#[test]
fn a_step_refused_after_the_model_advanced_leaves_the_simulation_as_it_was() {
    let path = temp_path("gone");
    let p = Parameters { impact_log: path.to_str().unwrap().into(), ..Parameters::default() };
    let mut sim = Sim::start(&p, 0.0).unwrap();
    run(&mut sim, &Inputs::default(), 0.003, 1e-3);
    let before = sim.clone();
    std::fs::remove_file(&path).unwrap();
    let err = sim.step(&Inputs::default(), 0.005).unwrap_err();
    assert!(err.0.contains("cannot open"), "the impact at 0.004 s: {err}");
    assert_eq!(sim, before);
    assert_eq!(sim.outputs(), before.outputs());
}

#[test]
fn bad_parameters_are_refused_by_name() {
    let p = Parameters { piston_mass: -1.0, ..Parameters::default() };
    let err: ModelError = Sim::new(&p, 0.0).unwrap_err();
    assert!(err.0.contains("piston_mass"), "{err}");
    assert!(Sim::new(&Parameters::default(), f64::NAN).is_err());
}

#[test]
fn the_impact_log_holds_the_rows_of_the_trajectory() {
    let path = temp_path("log");
    let p = Parameters { impact_log: path.to_str().unwrap().into(), ..Parameters::default() };
    let mut sim = Sim::start(&p, 0.0).unwrap();
    run(&mut sim, &Inputs::default(), 0.03, 1e-3);
    let saved = sim.clone();
    run(&mut sim, &Inputs::default(), 0.1, 1e-3);
    let text = std::fs::read_to_string(&path).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines[0].starts_with("# ") && lines[0].contains("[-360, 360)"), "{}", lines[0]);
    assert_eq!(
        lines[1],
        "time,crank_angle,kind,corner,normal_velocity_before,normal_velocity_after,energy_lost,position,crank_angle_deg,friction_energy_lost"
    );
    assert_eq!(lines.len(), 5);
    for (line, t) in lines[2..].iter().zip(impact_times(0.5, 3)) {
        let cols: Vec<&str> = line.split(',').collect();
        assert_eq!(cols.len(), 10);
        let (rad, deg): (f64, f64) = (cols[1].parse().unwrap(), cols[8].parse().unwrap());
        // the same angle from firing TDC: equal mod 720°, and within the cycle centred on firing TDC
        assert!((-360.0..360.0).contains(&deg) && ((rad.to_degrees() - deg) % 720.0).abs() < 1e-9, "{line}");
        assert_eq!(cols[2], "impact");
        assert!((cols[0].parse::<f64>().unwrap() - t).abs() < 1e-12, "{line} vs {t}");
    }
    // Restoring the state saved at 0.03 s (two impacts) cuts the third row away.
    saved.rewind_log().unwrap();
    assert_eq!(std::fs::read_to_string(&path).unwrap().lines().count(), 4);
    std::fs::remove_file(&path).unwrap();
    assert!(saved.rewind_log().is_err(), "the file is gone");
}

/// Two runs (restitution 0.5 and 0.3) logging to one path: the second's file holds its own rows, so the first's state,
/// restored over it, is refused (it would continue below rows that are not its own), and the file
/// is left as it was; the second's own state restores.
#[test]
fn a_state_restored_over_another_runs_log_is_refused() {
    let path = temp_path("shared_log");
    let p = Parameters { impact_log: path.to_str().unwrap().into(), ..Parameters::default() };
    let mut first = Sim::start(&p, 0.0).unwrap();
    run(&mut first, &Inputs::default(), 0.01, 1e-3);
    let mut second = Sim::start(&Parameters { restitution: 0.3, ..p }, 0.0).unwrap();
    run(&mut second, &Inputs::default(), 0.06, 2e-3);
    let own = second.clone();
    run(&mut second, &Inputs::default(), 0.1, 2e-3);
    let text = std::fs::read_to_string(&path).unwrap();
    let err = first.rewind_log().unwrap_err();
    assert!(err.0.contains("does not hold the rows of the restored state"), "{err}");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), text);
    own.rewind_log().unwrap();
    let restored = std::fs::read_to_string(&path).unwrap();
    assert!(text.starts_with(&restored) && restored.lines().count() > 1, "{restored}");
    std::fs::remove_file(&path).unwrap();
}

#[test]
fn an_unwritable_log_path_is_an_error_at_start() {
    let p = Parameters { impact_log: "/nonexistent-dir/pistonslap/log.csv".into(), ..Parameters::default() };
    let err = Sim::start(&p, 0.0).unwrap_err();
    assert!(err.0.contains("impact_log"), "{err}");
    assert!(Sim::new(&p, 0.0).is_ok(), "new touches no file");
}

/// The shuttle's cycle figures in closed form: at the default 125.66 rad/s an engine cycle (4π) lasts
/// 0.1000029 s, and the impacts at 0.004, 0.020, 0.052 s (speeds v0, e v0, e² v0 on the +x, −x, +x
/// walls), 0.116 s (e³ v0, −x) and 0.244 s (e⁴ v0, +x) fall into cycles 0, 0, 0, 1, 2; an impact at
/// speed v dissipates ½ m v² (1 − e²). Every impact after the first lands on the other wall: a slap when
/// faster than the threshold.
#[test]
fn cycle_metrics_match_the_closed_form() {
    let p = Parameters { slap_threshold: 0.004, ..Parameters::default() };
    let (m, e, v0) = (p.piston_mass, p.restitution, SHUTTLE_SPEED);
    let energy = |k: i32| 0.5 * m * (e.powi(k) * v0).powi(2) * (1.0 - e * e);
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-15 * b.abs().max(1e-10);
    let inputs = Inputs::default();

    let mut sim = Sim::new(&p, 0.0).unwrap();
    run(&mut sim, &inputs, 0.1, 1e-3);
    let out = sim.outputs();
    assert_eq!((out.cycle_count, out.cycle_slap_events, out.cycle_impact_energy), (0, 0, 0.0), "no cycle complete at 0.1 s");
    run(&mut sim, &inputs, 0.101, 1e-3);
    let out = sim.outputs().clone();
    assert_eq!(out.cycle_count, 1);
    assert_eq!(out.cycle_impacts, 3);
    assert_eq!(out.cycle_slap_events, 1, "the first landing (v0) is no side change; e v0 exceeds 4 mm/s, e² v0 does not");
    assert_eq!((out.cycle_slaps_antithrust, out.cycle_slaps_thrust), (1, 0));
    assert!(close(out.cycle_slap_energy_antithrust, energy(1)) && close(out.cycle_max_slap_energy_antithrust, energy(1)));
    assert_eq!((out.cycle_slap_energy_thrust, out.cycle_max_slap_energy_thrust), (0.0, 0.0));
    assert!(close(out.cycle_impact_energy, energy(0) + energy(1) + energy(2)), "{out:?}");
    assert!(close(out.cycle_max_impact_energy_thrust, energy(0)), "{out:?}");
    assert!(close(out.cycle_max_impact_energy_antithrust, energy(1)), "{out:?}");
    run(&mut sim, &inputs, 0.201, 1e-3);
    let out = sim.outputs();
    assert_eq!((out.cycle_count, out.cycle_slap_events), (2, 0));
    assert!(close(out.cycle_impact_energy, energy(3)) && close(out.cycle_max_impact_energy_antithrust, energy(3)));
    assert_eq!(out.cycle_max_impact_energy_thrust, 0.0);

    // One step across several cycles reports the last complete one: cycle 2 (the impact at 0.244 s),
    // then cycle 3, which has none.
    for (t_end, cycles, thrust) in [(0.35, 3, energy(4)), (0.45, 4, 0.0)] {
        let mut long = Sim::new(&p, 0.0).unwrap();
        long.step(&inputs, t_end).unwrap();
        let out = long.outputs();
        assert_eq!(out.cycle_count, cycles, "{t_end} s");
        assert!(close(out.cycle_max_impact_energy_thrust, thrust) && close(out.cycle_impact_energy, thrust), "{out:?}");
        assert_eq!(out.cycle_max_impact_energy_antithrust, 0.0);
    }
}

#[test]
fn engine_torque_is_the_crank_torque_with_the_engine_sign() {
    let mut sim = crate::fmus::piston_slap::simulation::Simulation::<crate::fmus::piston_slap::simulation::ModelVariant>::new(
        &Parameters::default(),
        0.0,
    )
    .unwrap();
    for k in 1..=40 {
        sim.step(&Inputs::default(), k as f64 * 1e-3).unwrap();
        let out = sim.outputs();
        assert_eq!(out.engine_torque, -out.crank_torque);
    }
}

/// Either model serves most points of its default case at 1e-5 s from the step ahead (the
/// crank train's adaptive steps reach 1 ms, the roller's fixed ones 40 µs), as `advance` would to
/// the bit, and reading the point before again puts it back to the bit (as an FMU state saves it:
/// the caches of the crank's terms are not state), so the step copies nothing.
#[test]
fn a_served_point_is_undone_by_reading_the_point_before_again() {
    for (model_variant, least) in [(1, 1500), (2, 1000)] {
        let mut model = ModelVariant::new(&Parameters { model_variant, ..Parameters::default() }, 0.0).unwrap();
        let (inputs, derivatives, mut events) = (Inputs::default(), InputDerivatives::default(), Vec::new());
        let mut served = 0;
        for k in 1..=2000 {
            let (t0, t1) = ((k - 1) as f64 * 1e-5, k as f64 * 1e-5);
            let before = postcard::to_allocvec(&model).unwrap();
            let mut advanced = model.clone();
            advanced.advance(&inputs, t1, &mut events).unwrap();
            if let Some(result) = model.serve(&derivatives.polynomials(&inputs, t0), t1) {
                result.unwrap();
                assert_eq!(postcard::to_allocvec(&model).unwrap(), postcard::to_allocvec(&advanced).unwrap(), "{model_variant} at {t1} s");
                model.serve_again(t0).unwrap();
                assert_eq!(postcard::to_allocvec(&model).unwrap(), before, "{model_variant} at {t1} s");
                served += 1;
            }
            model.advance(&inputs, t1, &mut events).unwrap();
        }
        assert!(served > least, "variant {model_variant}: {served} of 2000 points served");
    }
}

/// The shuttle's landings alternate walls from its second impact on (the first only finds a wall), each
/// with the kinetic energy ½ m (eᵏ v0)² it arrives with and the loss (1 − e²) of it its one impact
/// takes, ending where the next starts; a cycle (−360° to 360° about firing TDC, 0.1 s) is complete
/// once its last landing has ended, with its largest landing per wall.
#[test]
fn landings_of_the_shuttle_match_the_closed_form() {
    let path = temp_path("landings");
    let p = Parameters { landing_log: path.to_str().unwrap().into(), restitution: 0.9, ..Parameters::default() };
    let (e, m) = (p.restitution, p.piston_mass);
    let times = impact_times(e, 12);
    let mut sim = Sim::start(&p, 0.0).unwrap();
    run(&mut sim, &Inputs::default(), 0.08, 1e-3);
    let text = std::fs::read_to_string(&path).unwrap();
    let rows: Vec<Vec<&str>> = text.lines().skip(2).map(|l| l.split(',').collect()).collect();
    let ended = times.iter().filter(|&&t| t <= 0.08).count() - 2;
    assert_eq!(rows.len(), ended, "{text}");
    let number = |s: &str| s.parse::<f64>().unwrap();
    for (k, row) in rows.iter().enumerate() {
        let arriving = 0.5 * m * (e.powi(k as i32 + 1) * SHUTTLE_SPEED).powi(2);
        assert!((number(row[0]) - times[k + 1]).abs() < 1e-12, "{row:?}");
        assert_eq!(row[2], ["antithrust", "thrust"][k % 2], "{row:?}");
        assert_eq!(row[3], "top");
        assert!((number(row[4]) - arriving).abs() < 1e-12 * arriving, "{row:?}");
        assert!((number(row[6]) - (1.0 - e * e) * arriving).abs() < 1e-12 * arriving, "{row:?}");
        assert_eq!(row[10], "1");
        assert!((number(row[11]) - times[k + 2]).abs() < 1e-12, "{row:?}");
    }
    // Cycle 0 (to t = 0.05 s) ends with the landing in progress there; its largest landings per wall
    // are its first on each.
    let out = sim.outputs();
    let in_cycle = times.iter().skip(1).filter(|&&t| t < 0.05).count() as i32;
    assert_eq!(out.cycle_landings_antithrust + out.cycle_landings_thrust, in_cycle);
    let first = |k: i32| 0.5 * m * (e.powi(k) * SHUTTLE_SPEED).powi(2);
    assert!((out.cycle_landing_energy_antithrust - first(1)).abs() < 1e-12 * first(1));
    assert!((out.cycle_landing_energy_thrust - first(2)).abs() < 1e-12 * first(2));
    assert!((out.cycle_landing_loss_thrust - (1.0 - e * e) * first(2)).abs() < 1e-12 * first(2));
    let angle = Inputs::default().crank_speed * times[2];
    assert!((out.cycle_landing_crank_angle_thrust - angle).abs() < 1e-9, "{} vs {angle}", out.cycle_landing_crank_angle_thrust);
    std::fs::remove_file(path).unwrap();
}

/// On the dry crank train each landing starts at an impact or slide on the other wall than the last
/// landing's, and its loss is the sum of its impacts' losses on its wall (normal and friction) until
/// the next landing starts, as the impact log lists them.
#[test]
fn dry_landings_lose_what_their_impacts_dissipate() {
    let (landings, impacts) = (temp_path("dry_landings"), temp_path("dry_impacts"));
    let p = Parameters {
        landing_log: landings.to_str().unwrap().into(),
        impact_log: impacts.to_str().unwrap().into(),
        friction: 0.1,
        ..Parameters::default()
    };
    let mut sim = Simulation::<ModelVariant>::start(&p, 0.0).unwrap();
    let inputs = Inputs::default();
    for k in 1..=3000 {
        sim.step(&inputs, k as f64 * 1e-4).unwrap();
    }
    let read = |path: &PathBuf| -> Vec<Vec<String>> {
        let text = std::fs::read_to_string(path).unwrap();
        text.lines().skip(2).map(|l| l.split(',').map(str::to_string).collect()).collect()
    };
    let number = |s: &str| s.parse::<f64>().unwrap();
    let (landed, events) = (read(&landings), read(&impacts));
    assert!(landed.len() >= 10, "three cycles land on both walls several times: {}", landed.len());
    let mut walls_alternate = true;
    for (k, l) in landed.iter().enumerate() {
        let (start, end, wall) = (number(&l[0]), number(&l[11]), l[2].as_str());
        let on_wall = |e: &&Vec<String>| (e[3] == "3" || e[3] == "4") == (wall == "thrust");
        let within = |e: &&Vec<String>| (start..end).contains(&number(&e[0]));
        let first = events.iter().filter(within).find(|e| (e[2] == "impact" || e[2] == "slide") && on_wall(e)).unwrap();
        assert_eq!(number(&first[0]), start, "{l:?}");
        let lost: f64 =
            events.iter().filter(within).filter(on_wall).filter(|e| e[2] == "impact").map(|e| number(&e[6]) + number(&e[9])).sum();
        assert!((number(&l[6]) - lost).abs() <= 1e-12 * lost.max(1e-9), "{l:?}: {lost}");
        assert_eq!(number(&l[10]) as usize, events.iter().filter(within).filter(on_wall).filter(|e| e[2] == "impact").count());
        walls_alternate &= k == 0 || landed[k - 1][2] != l[2];
    }
    assert!(walls_alternate);
    let out = sim.outputs();
    assert!(out.cycle_landings_thrust > 0 && out.cycle_landings_antithrust > 0);
    assert!(out.cycle_landing_energy_thrust > 0.0 && out.cycle_landing_loss_thrust > 0.0);
    std::fs::remove_file(landings).unwrap();
    std::fs::remove_file(impacts).unwrap();
}

/// On oil the piston lands without impacts: the film carries it, and each landing is found where
/// the other wall's load comes to exceed the carrying wall's, the film taking energy from the
/// lateral motion and tilt.
#[test]
fn lubricated_landings_are_found_where_the_walls_loads_cross() {
    let path = temp_path("oil_landings");
    let p = Parameters { landing_log: path.to_str().unwrap().into(), skirt_model: 2, ..Parameters::default() };
    let mut sim = Simulation::<ModelVariant>::start(&p, 0.0).unwrap();
    let inputs = Inputs::default();
    for k in 1..=2000 {
        sim.step(&inputs, k as f64 * 1e-4).unwrap();
    }
    let text = std::fs::read_to_string(&path).unwrap();
    let out = sim.outputs();
    assert_eq!(out.impact_count, 0);
    // Three side changes a wall a cycle; the largest landing is the thrust wall's after firing TDC, several
    // times any anti-thrust landing, where the film takes a share of its energy before the wall's load
    // peaks (the rest is the piston rocking on it) and the load rises at over 1 kN/ms.
    assert_eq!((out.cycle_landings_thrust, out.cycle_landings_antithrust), (3, 3), "{text}");
    let (energy, loss) = (out.cycle_landing_energy_thrust, out.cycle_landing_loss_thrust);
    assert!(energy > 5.0 * out.cycle_landing_energy_antithrust && loss > 0.2 * energy && loss <= energy, "{text}");
    assert!((0.0..0.35).contains(&out.cycle_landing_crank_angle_thrust), "{text}");
    assert!(out.cycle_max_liner_force_rate_thrust > 1e6 && out.cycle_max_liner_force_thrust > 1e3, "{text}");
    std::fs::remove_file(path).unwrap();
}
