//! Instances in parallel threads are independent: eight of the shipped engine give results
//! bit-identical to the same runs one by one (every output after every step, and the serialized FMU
//! state at the end), and instances of the same case agree bit for bit. (No global mutable state:
//! each instance owns everything it computes with.)

use super::*;
use std::sync::Barrier;

/// One run: variant, restitution, crank speed (rad/s) and communication step (s).
type Run = (i32, f64, f64, f64);

/// Both variants, different restitutions, speeds and steps, so that no two traces coincide.
const RUNS: [Run; 8] = [
    (1, 0.5, 125.66, 1e-3),
    (1, 0.9, 125.66, 2e-3),
    (1, 0.0, 200.0, 1e-3),
    (1, 0.5, 80.0, 5e-4),
    (2, 0.9, 60.0, 1e-3),
    (2, 0.5, 60.0, 2e-3),
    (2, 0.0, 90.0, 1e-3),
    (2, 0.7, 40.0, 5e-4),
];

const DURATION: f64 = 0.04;

/// Every output's bits after every step, and the final serialized state.
type Trace = (Vec<Vec<u64>>, Vec<u8>);

fn trace(&(variant, restitution, speed, h): &Run, start: &Barrier) -> Trace {
    let host = Host::<ModelVariant>::new();
    assert_eq!(host.set_integer("model_variant", variant), Status::Ok);
    assert_eq!(host.set_real("restitution", restitution), Status::Ok);
    assert_eq!(host.set_real("crank_speed", speed), Status::Ok);
    if variant == 2 {
        // The thesis's mechanism, which slaps within a few crank turns.
        for (name, value) in THESIS_MECHANISM {
            assert_eq!(host.set_real(name, value), Status::Ok, "{name}");
        }
    }
    assert_eq!(host.setup(0.0, None), Status::Ok);
    assert_eq!(host.enter(), Status::Ok);
    assert_eq!(host.exit(), Status::Ok, "{:?}", host.messages());
    start.wait();
    let steps = (DURATION / h).round() as usize;
    let outputs = (0..steps)
        .map(|k| {
            assert_eq!(host.step(k as f64 * h, h), Status::Ok, "{:?}", host.messages());
            host.output_bits()
        })
        .collect();
    let state = host.get_state();
    let bytes = host.serialize(state);
    host.free_state(state);
    (outputs, bytes)
}

#[test]
fn eight_instances_in_parallel_threads_match_the_runs_one_by_one() {
    let alone: Vec<Trace> = RUNS.iter().map(|run| trace(run, &Barrier::new(1))).collect();
    let start = Barrier::new(RUNS.len());
    let parallel: Vec<Trace> = std::thread::scope(|scope| {
        let threads: Vec<_> = RUNS.iter().map(|run| scope.spawn(|| trace(run, &start))).collect();
        threads.into_iter().map(|t| t.join().unwrap()).collect()
    });
    for (k, (a, p)) in alone.iter().zip(&parallel).enumerate() {
        assert!(a == p, "run {k} {:?} differs in a thread", RUNS[k]);
    }
    // The comparison means something: the runs differ from each other and every one has impacts.
    let impact_count =
        VARIABLES.iter().filter(|v| v.causality == description::Causality::Output).position(|v| v.name == "impact_count").unwrap();
    for (k, (outputs, _)) in alone.iter().enumerate() {
        assert!(outputs.last().unwrap()[impact_count] > 0, "run {k} has no impact");
        assert!(alone[..k].iter().all(|other| other.1 != alone[k].1), "run {k} repeats another");
    }
}

#[test]
fn instances_in_threads_are_independent() {
    let results: Vec<Vec<u64>> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..4)
            .map(|k| {
                scope.spawn(move || {
                    let host = ShuttleHost::initialized();
                    host.run(0.0, 0.1, [1e-3, 2e-3, 5e-3, 1e-2][k]);
                    (host.integer("impact_count"), host.real("impact_energy_total").to_bits())
                })
            })
            .collect();
        handles
            .into_iter()
            .map(|h| {
                let (n, e) = h.join().unwrap();
                vec![n as u64, e]
            })
            .collect()
    });
    assert!(results.iter().all(|r| r[0] == 3), "{results:?}");
    let energies: Vec<f64> = results.iter().map(|r| f64::from_bits(r[1])).collect();
    assert!(energies.iter().all(|e| (e - energies[0]).abs() < 1e-18), "{energies:?}");
}

#[test]
fn engine_instances_in_threads_agree_bit_for_bit() {
    let results: Vec<Vec<u64>> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..3)
            .map(|_| {
                scope.spawn(|| {
                    let host = Host::<ModelVariant>::initialized();
                    host.run(0.0, 0.03, 1e-3);
                    host.output_bits()
                })
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    });
    assert!(results.iter().all(|r| *r == results[0]));
}
