//! `cargo bench --bench core`: RK4 steps/s and events/s of the nonsmooth core on the testbeds,
//! and the cost of locating events by dense output (Illinois) against what the paper's step halving
//! would need.
//! Each figure is the median of several runs; evaluations are counted by a wrapping system.

use nalgebra::{SVector, Vector1, Vector2, Vector3};
#[path = "../tests/common/testbeds.rs"]
mod testbeds;

use pistonslap::dynamics::{EventKind, Stepper, StepperOptions, System};
use std::time::{Duration, Instant};
use testbeds::{Ball, Counted, DoublePendulum, Floor, Rod};

const RUNS: usize = 7;

struct Outcome {
    time: Duration,
    steps: f64,
    events: usize,
    evaluations: u64,
    /// The evaluations the paper's step halving needs to locate the same impacts: per impact,
    /// 4 per RK4 step times the log₂(h |ḣ⁻| / ε_h) halvings that narrow a step of h to the time
    /// the gap takes to cross its tolerance.
    halving_bound: f64,
}

fn run<S: System<N, M> + Clone, const N: usize, const M: usize>(
    system: &S,
    q0: SVector<f64, N>,
    v0: SVector<f64, N>,
    step: f64,
    t_end: f64,
) -> Outcome {
    let mut times = Vec::new();
    let mut last = None;
    for _ in 0..RUNS {
        let counted = Counted::new(system.clone());
        let start = Instant::now();
        let mut s = Stepper::new(counted, 0.0, q0, v0, StepperOptions { step, ..Default::default() }).expect("valid start");
        s.advance(t_end).expect("bench run");
        times.push(start.elapsed());
        last = Some(s);
    }
    times.sort();
    let s = last.expect("RUNS > 0");
    let tolerance = s.options().gap_tolerance;
    let halving_bound = s
        .events()
        .iter()
        .filter(|ev| ev.kind == EventKind::Impact)
        .map(|ev| 4.0 * libm::log2(step * ev.velocity_before.abs() / tolerance).max(1.0))
        .sum();
    Outcome {
        time: times[RUNS / 2],
        steps: t_end / step,
        events: s.events().len(),
        evaluations: s.system().evaluations.get(),
        halving_bound,
    }
}

fn report(name: &str, o: &Outcome) {
    let secs = o.time.as_secs_f64();
    println!(
        "{name:<42} {:>8.2} ms  {:>7.2} M steps/s  {:>9.0} events/s  ({} events, {:.0} evaluations/step)",
        secs * 1e3,
        o.steps / secs / 1e6,
        o.events as f64 / secs,
        o.events,
        o.evaluations as f64 / o.steps
    );
}

fn main() {
    println!("median of {RUNS} runs; steps are nominal (t_end / h_RK4)");
    let free = DoublePendulum { masses: [1.0, 0.5], lengths: [1.0, 0.7], gravity: 9.81, wall: 10.0, restitution: 1.0 };
    report("double pendulum, free (2 DOF)", &run(&free, Vector2::new(1.0, -0.5), Vector2::zeros(), 1e-3, 100.0));
    let rod = Rod { mass: 1.0, length: 1.0, gravity: 9.81, restitution: 0.5, friction: 0.0, floor: Floor::Fixed };
    report(
        "rod tumbling to rest, e = 0.5 (3 DOF, 2 ends)",
        &run(&rod, Vector3::new(0.0, 1.0, 0.3), Vector3::new(0.5, 0.0, 4.0), 1e-4, 10.0),
    );
    let ball_in = Ball { mass: 1.0, gravity: 9.81, restitution: 0.5, floor: Floor::Fixed };
    report("ball, e = 0.5, accumulation then rest", &run(&ball_in, Vector1::new(1.0), Vector1::zeros(), 1e-3, 5.0));

    println!("\nevent location: dense output (Illinois) against the step halving of A&K Fig. 1");
    let ball = Ball { mass: 1.0, gravity: 9.81, restitution: 1.0, floor: Floor::Fixed };
    let wall = DoublePendulum { masses: [1.0, 1.0], lengths: [1.0, 1.0], gravity: 9.81, wall: -0.3, restitution: 1.0 };
    let shake = Ball { mass: 1.0, gravity: 9.81, restitution: 0.8, floor: Floor::Oscillating { amplitude: 0.01, angular_frequency: 50.0 } };
    let cases = [
        ("ball, e = 1", run(&ball, Vector1::new(1.0), Vector1::zeros(), 1e-2, 500.0)),
        ("double pendulum vs wall, e = 1", run(&wall, Vector2::new(0.6, 0.9), Vector2::zeros(), 1e-2, 500.0)),
        ("ball on shaking floor, e = 0.8", run(&shake, Vector1::zeros(), Vector1::new(0.5), 1e-3, 50.0)),
    ];
    for (name, outcome) in cases {
        report(name, &outcome);
        // Evaluations beyond the 4 per nominal step that plain stepping costs.
        let located = outcome.evaluations as f64 - 4.0 * outcome.steps;
        println!(
            "  -> location: {:.1} evaluations/event; step halving would need {:.1} ({:.1}x)",
            located / outcome.events.max(1) as f64,
            outcome.halving_bound / outcome.events.max(1) as f64,
            outcome.halving_bound / located
        );
    }
}
