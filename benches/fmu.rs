//! `cargo bench --bench fmu`: the FMU through its exported C functions, in process (a Rust host:
//! the host's own cost stays out of the figures). Real-time factor (simulated s per wall s) of the
//! default crank-train case at 1e-5 to 1e-2 s communication steps and of the roller variant; the
//! thesis study's wall time; the cost of one RK4 step against its floating-point work (counted
//! under callgrind, `fmu/flop_count.rs`), and the bound that cost and the default case's count of
//! steps set on its real-time factor; the lubricated skirt's CPU time per cycle at 1200 and 3000 rpm
//! against the dry model's, and its mass-conserving film's, flooded and on a limited oil supply, against
//! the Reynolds condition's.
//! Each figure is the median of several runs.

use pistonslap::dynamics::StepperOptions;
use pistonslap::fmus::piston_slap::mechanisms;
use pistonslap::fmus::piston_slap::{InputDerivatives, Inputs, Parameters};
use pistonslap::models::CrankTrain;
use std::time::Instant;

#[path = "fmu/flop_count.rs"]
mod flop_count;
// The host also serves the random designs run through the FMU, whose methods the benchmark does not call.
#[allow(dead_code)]
#[path = "../tests/common/fmu_host.rs"]
mod fmu_host;

use fmu_host::{vr, Host};
use pistonslap::fmus::piston_slap::Mechanism;

const RUNS: usize = 5;
/// Rounds of the communication-step runs (each a few tenths of a second).
const COMMUNICATION_ROUNDS: usize = 9;

/// Steps `host` to `stop` with communication step `h`, reading two outputs per step as a host
/// does; returns the wall time in seconds.
fn run(host: &Host, stop: f64, h: f64) -> f64 {
    run_on(libc::CLOCK_MONOTONIC, host, (0.0, stop), h)
}

/// As [`run`] from `from` to `stop`, the seconds read on `clock` (`CLOCK_THREAD_CPUTIME_ID`: the CPU
/// time of this thread, which other work on a shared machine slows less than the wall time).
fn run_on(clock: libc::clockid_t, host: &Host, (from, stop): (f64, f64), h: f64) -> f64 {
    let start = seconds(clock);
    let refs = [vr("crank_angle"), vr("side_force")];
    let mut out = [0.0; 2];
    for k in 0..((stop - from) / h).round() as usize {
        host.step(from + k as f64 * h, h, &refs, &mut out);
    }
    std::hint::black_box(out);
    seconds(clock) - start
}

/// The time on `clock`, s.
fn seconds(clock: libc::clockid_t) -> f64 {
    let mut t = libc::timespec { tv_sec: 0, tv_nsec: 0 };
    // SAFETY: `t` is a live timespec the call writes.
    let status = unsafe { libc::clock_gettime(clock, &mut t) };
    assert_eq!(status, 0, "clock_gettime");
    t.tv_sec as f64 + 1e-9 * t.tv_nsec as f64
}

fn median(mut x: Vec<f64>) -> f64 {
    x.sort_by(f64::total_cmp);
    x[x.len() / 2]
}

/// The median real-time factor of `stop` simulated seconds in steps of `h` (a fresh instance per
/// run), printed after `what`.
fn real_time_factor(what: &str, integers: &[(&str, i32)], reals: &[(&str, f64)], stop: f64, h: f64) {
    let factors = (0..RUNS).map(|_| stop / run(&Host::new(integers, reals), stop, h)).collect();
    println!("{what}: {:6.1}× real time", median(factors));
}

/// The argument that makes this executable only take plain steps (the flop count's child run).
const PLAIN_STEPS: &str = "--plain-steps";
/// The argument that makes it only take `n` communication steps of `h` (the instruction count's child run).
const DO_STEPS: &str = "--do-steps";
/// The argument that runs the lubricated skirt's figures alone (`lubricated`).
const LUBRICATED: &str = "--lubricated";

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if let Some(steps) = args.iter().position(|a| a == PLAIN_STEPS).and_then(|i| args.get(i + 1)?.parse().ok()) {
        plain_steps(steps);
        return;
    }
    if let Some(i) = args.iter().position(|a| a == DO_STEPS) {
        let (h, n): (f64, usize) = (args[i + 1].parse().expect("a step"), args[i + 2].parse().expect("a count"));
        run(&Host::new(&[], &[]), n as f64 * h, h);
        return;
    }
    println!("machine: {}", machine());
    if args.iter().any(|a| a == LUBRICATED) {
        lubricated();
        return;
    }
    let cycle = 4.0 * std::f64::consts::PI / 125.66;
    let what = "roller variant, default parameters (1200 rpm), 10 cycles, step  1 ms";
    real_time_factor(what, &[("model_variant", 2)], &[], 10.0 * cycle, 1e-3);

    // Without contact (a wide bore) and with a fixed step (the FMU's is adaptive, its count not
    // seen from outside) every step is a plain RK4 step: wall time per step, through the model.
    let plain = median((0..10 * RUNS).map(|_| plain_steps(40) / 40.0).collect());
    let ghz = ghz();
    let work = plain_step_work();
    let limit = match work.clone() {
        Ok((instructions, flops)) => {
            let limit = flops / (2.0 * ghz * 1e9);
            println!(
                "crank train, one fixed RK4 step without contact: {:.2} µs, {instructions:.0} instructions, {flops:.0} flops \
                 (counted by callgrind: at 2 flops per cycle and {ghz:.1} GHz {:.2} µs), {:.1}× that limit",
                plain * 1e6,
                limit * 1e6,
                plain / limit
            );
            Some(limit)
        }
        Err(why) => {
            println!("crank train, one fixed RK4 step without contact: {:.2} µs (flops not counted: {why})", plain * 1e6);
            None
        }
    };
    least_work(cycle, plain, limit);
    lubricated();
    communication_steps(plain, work.ok().map(|(instructions, _)| instructions));
    thesis_study();
}

/// The lubricated skirt (`skirt_model = 2`, default film grid and relaxation) against the dry
/// default case, the mass-conserving film (`cavitation = 2`), flooded and on a limited supply
/// (`oil_supply = 2`, the default `liner_oil_film`), against the Reynolds condition's, and the elastic
/// skirt (`skirt_compliance = 1`, the built-in shell) against the rigid one, at 1200 and 3000 rpm,
/// through the C ABI at 1 ms steps over one whole cycle (the second: the first starts the film from
/// rest): the CPU time per cycle of each, the real-time factor it gives and the ratios, the median over
/// rounds (a ratio taken within a round, under one load of the machine).
/// `cargo bench --bench fmu -- --lubricated` runs these alone.
fn lubricated() {
    let h = 1e-3;
    let cases: [&[(&str, i32)]; 5] = [
        &[("skirt_model", 1)],
        &[("skirt_model", 2)],
        &[("skirt_model", 2), ("cavitation", 2)],
        &[("skirt_model", 2), ("cavitation", 2), ("oil_supply", 2)],
        &[("skirt_model", 2), ("skirt_compliance", 1)],
    ];
    for rpm in [1200.0, 3000.0] {
        let speed = rpm * std::f64::consts::PI / 30.0;
        let cycle = 4.0 * std::f64::consts::PI / speed;
        let second_cycle = |integers: &[(&str, i32)]| {
            let host = Host::new(integers, &[]);
            host.set_inputs(&Inputs { crank_speed: speed, ..Inputs::default() }, &InputDerivatives::default()).expect("a valid speed");
            run(&host, cycle, h);
            run_on(libc::CLOCK_THREAD_CPUTIME_ID, &host, (cycle, 2.0 * cycle), h)
        };
        let rounds: Vec<[f64; 5]> = (0..RUNS).map(|_| cases.map(second_cycle)).collect();
        let cpu = |k: usize| median(rounds.iter().map(|r| r[k]).collect());
        let ratio = |k: usize, of: usize| median(rounds.iter().map(|r| r[k] / r[of]).collect());
        println!(
            "crank train, default case at {rpm:.0} rpm, one cycle in 1 ms steps, CPU time: dry {:.2} ms ({:.0}× real time); \
             lubricated skirt {:.1} ms ({:.2}× real time), {:.1}× the dry model's; mass-conserving cavitation {:.1} ms \
             ({:.2}× real time), {:.2}× the Reynolds film's; on a limited supply {:.1} ms ({:.2}× real time), {:.2}× the \
             Reynolds film's; elastic skirt {:.1} ms ({:.2}× real time), {:.2}× the rigid skirt's",
            cpu(0) * 1e3,
            cycle / cpu(0),
            cpu(1) * 1e3,
            cycle / cpu(1),
            ratio(1, 0),
            cpu(2) * 1e3,
            cycle / cpu(2),
            ratio(2, 1),
            cpu(3) * 1e3,
            cycle / cpu(3),
            ratio(3, 1),
            cpu(4) * 1e3,
            cycle / cpu(4),
            ratio(4, 1)
        );
    }
}

/// The default case, 2 s simulated through the C ABI at the communication steps couplings use
/// (0.1°–1° of crank angle is 1.4e-5–1.4e-4 s at 1200 rpm) and at longer ones: real-time factor,
/// instructions per `fmi2DoStep` (callgrind), and the wall time against the RK4-step bound, the
/// RK4 steps the run took (counted by the core, through the model at the same steps) at the
/// plain step's cost `plain`. The step sizes take turns, round after round, so that the ratio of
/// two of them is taken within a round, both under the same load of the machine: its median over
/// the rounds.
///
/// Then a communication point at 1e-5 s (2 s at 1e-5 s steps, the median wall time per
/// `fmi2DoStep`, the host's two `fmi2GetReal` included) against one plain RK4 step of the same
/// model (`plain` s, `plain_instructions`), in time and in instructions, and the wall-time
/// ratio of 2 s at 1e-5 s steps to 2 s at 1e-3 s steps.
fn communication_steps(plain: f64, plain_instructions: Option<f64>) {
    let (stop, steps) = (2.0, [1e-5, 1e-4, 1e-3, 1e-2]);
    let rounds: Vec<Vec<f64>> = (0..COMMUNICATION_ROUNDS).map(|_| steps.map(|h| run(&Host::new(&[], &[]), stop, h)).to_vec()).collect();
    let mut fine_point = None;
    for (i, h) in steps.into_iter().enumerate() {
        let wall = median(rounds.iter().map(|r| r[i]).collect());
        let steps = rk4_steps(stop, h);
        let counted = do_step_instructions(h);
        if i == 0 {
            fine_point = Some((wall / (stop / h), counted.clone().ok()));
        }
        let instructions = counted.map_or_else(|why| format!("instructions not counted: {why}"), |n| format!("{n:.0} instructions"));
        println!(
            "crank train, default case, 2 s in steps of {h:.0e} s: {:6.1}× real time, {:.2} µs and {instructions} per fmi2DoStep, \
             {steps} RK4 steps: {:.1}× their cost as plain steps",
            stop / wall,
            wall / (stop / h) * 1e6,
            wall / (steps as f64 * plain)
        );
    }
    if let Some((point, instructions)) = fine_point {
        let counted = match (instructions, plain_instructions) {
            (Some(n), Some(plain_n)) => format!(", {n:.0} instructions against {plain_n:.0}: {:.2}×", n / plain_n),
            _ => String::new(),
        };
        println!(
            "crank train, default case, one communication point at 1e-5 s: {:.2} µs against one plain RK4 step's {:.2} µs: {:.2}×{counted}",
            point * 1e6,
            plain * 1e6,
            point / plain
        );
    }
    let ratio = median(rounds.iter().map(|r| r[0] / r[2]).collect());
    println!("wall time of 2 s at 1e-5 s steps against 1e-3 s steps: {ratio:.1}× (median of {COMMUNICATION_ROUNDS} rounds)");
}

/// RK4 steps (accepted, rejected and locating) of `stop` seconds of the default case in steps of `h`.
fn rk4_steps(stop: f64, h: f64) -> u64 {
    let mut model = CrankTrain::new(&Parameters::default(), 0.0).expect("default parameters");
    let (inputs, mut events) = (Inputs::default(), Vec::new());
    for k in 1..=(stop / h).round() as usize {
        model.advance(&inputs, k as f64 * h, &mut events).expect("default case");
        events.clear();
    }
    let c = model.step_counts();
    c.accepted + c.rejected + c.locating
}

/// Instructions per `fmi2DoStep` of the default case in steps of `h`: the difference between runs
/// of 200 and 400 steps, each counted under callgrind, so that start-up drops out.
fn do_step_instructions(h: f64) -> Result<f64, String> {
    let run = |n: u32| flop_count::count(&[DO_STEPS.to_string(), h.to_string(), n.to_string()]);
    let ((i1, _), (i2, _)) = (run(200)?, run(400)?);
    Ok((i2 - i1) as f64 / 200.0)
}

/// Wall time of `steps` fixed 1e-4 s RK4 steps of the default crank train in a wide bore, where
/// the tilting piston first reaches the liner after ≈ 4.3 ms.
fn plain_steps(steps: usize) -> f64 {
    let params = Parameters { bore: 0.11, ..Parameters::default() };
    let options = StepperOptions { step: 1e-4, ..StepperOptions::default() };
    let mut model = CrankTrain::with_options(mechanisms::crank_train::design(&params).expect("valid parameters"), 0.0, options)
        .expect("a finite start");
    let (inputs, mut events) = (Inputs::default(), Vec::new());
    let start = Instant::now();
    model.advance(&inputs, steps as f64 * 1e-4, &mut events).expect("no contact");
    assert!(events.is_empty(), "no contact yet");
    start.elapsed().as_secs_f64()
}

/// The default case's RK4 steps per cycle (counted by the core), and the real-time factor they
/// would allow if every step cost what a plain one does and nothing else (event search, impact
/// and sliding resolutions, projections, the FMU) cost anything: a bound the optimizations of
/// the core cannot pass.
fn least_work(cycle: f64, plain: f64, limit: Option<f64>) {
    let (cycles, h) = (10.0, 1e-2);
    let mut model = CrankTrain::new(&Parameters::default(), 0.0).expect("default parameters");
    let (inputs, mut events) = (Inputs::default(), Vec::new());
    for k in 1..=(cycles * cycle / h).round() as usize {
        model.advance(&inputs, k as f64 * h, &mut events).expect("default case");
    }
    let c = model.step_counts();
    let per_cycle = |n: u64| n as f64 / cycles;
    let least = per_cycle(c.accepted + c.located);
    let at_limit = limit.map_or(String::new(), |limit| format!("; at the flop limit of a step, {:.0}×", cycle / (least * limit)));
    println!(
        "crank train, default case at {:.0} ms steps, per cycle: {:.0} events recorded; RK4 steps {:.0} accepted, {:.0} rejected, \
         {:.0} locating the {:.0} events found inside a step; the least ({:.0} accepted + one landing per located event) at the \
         plain step's cost and nothing else: {:.3} ms per cycle, at most {:.0}× real time{at_limit}",
        h * 1e3,
        per_cycle(events.len() as u64),
        per_cycle(c.accepted),
        per_cycle(c.rejected),
        per_cycle(c.locating),
        per_cycle(c.located),
        per_cycle(c.accepted),
        least * plain * 1e3,
        cycle / (least * plain)
    );
}

/// Instructions and flops of one plain step: the difference between runs of 40 and 20 steps
/// (so that the start-up's work drops out), each counted under callgrind.
fn plain_step_work() -> Result<(f64, f64), String> {
    let run = |steps: u32| flop_count::count(&[PLAIN_STEPS.to_string(), steps.to_string()]);
    let ((i20, f20), (i40, f40)) = (run(20)?, run(40)?);
    Ok(((i40 - i20) as f64 / 20.0, (f40 - f20) as f64 / 20.0))
}

/// Nominal clock of the machine, GHz: half its BogoMIPS (what the kernel calibrates its delay
/// loop to, two per cycle on x86), or 2.3 where /proc/cpuinfo does not tell.
fn ghz() -> f64 {
    let bogomips = std::fs::read_to_string("/proc/cpuinfo").ok().and_then(|s| {
        s.lines().find(|l| l.to_lowercase().starts_with("bogomips")).and_then(|l| l.split(':').nth(1)?.trim().parse::<f64>().ok())
    });
    bogomips.map_or(2.3, |b| b / 2000.0)
}

/// The thesis study: THESIS_RUNS' 18 (λ, ρ) cases at e = 0.9 (python/pistonslap/analysis.py),
/// thesis units (l = 1, M = 1, Ω = 1, roller_forcing = 1). To keep the bench short each case runs
/// 1/10 of its 1530 crank cycles and the total is scaled by 10 (one run, not a median).
fn thesis_study() {
    let (xi, alpha, beta, diameter) = (0.3030, 1.9, 0.4719, 0.08);
    let fraction = 10.0;
    let stop = 1530.0 * 2.0 * std::f64::consts::PI / fraction;
    let mut wall = 0.0;
    for lam in [0.025, 0.05, 0.075, 0.15, 0.20, 0.25] {
        for rho in [0.010, 0.015, 0.020] {
            let reals = [
                ("crank_radius", xi),
                ("rod_length", 1.0),
                ("rod_mass", alpha),
                ("piston_mass", 1.0),
                ("rod_inertia", beta),
                ("damping_crank_pin", lam),
                ("piston_diameter", diameter),
                ("bore", diameter + 2.0 * rho),
                ("restitution", 0.9),
            ];
            let host = Host::new(&[("model_variant", 2), ("roller_forcing", 1)], &reals);
            host.set_inputs(&Inputs { crank_speed: 1.0, ..Inputs::default() }, &InputDerivatives::default()).expect("Ω = 1");
            wall += run(&host, stop, 2.0 * std::f64::consts::PI);
        }
    }
    println!(
        "thesis study (18 cases × 1530 crank cycles, one per communication step): {:.1} s wall (measured on 153 cycles each, ×10)",
        wall * fraction
    );
}

fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| s.lines().find(|l| l.starts_with("model name")).map(|l| l.split(':').nth(1).unwrap_or("").trim().to_string()))
        .unwrap_or_else(|| "unknown CPU".into());
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    format!(
        "{cpu}, {} logical CPUs, load average {}",
        std::thread::available_parallelism().map_or(0, |n| n.get()),
        load.split_whitespace().next().unwrap_or("?")
    )
}
