//! Runs N seeded random designs of each family (`tests/common/designs.rs`) and reports every one
//! that fails, and the worst energy balance of the families nothing does work on, without and with
//! liner friction: the sweep behind the suite's smaller random-design test. The families named
//! "fmu …" run through the FMU's C functions in process (`tests/common/fmu_designs.rs`) and report the
//! designs that fail and the number the FMU refused.
//! `cargo run --release --example random_designs -- 2000 [first_seed [family]]`

#[path = "../tests/common/designs.rs"]
mod designs;
#[path = "../tests/common/fmu_designs.rs"]
mod fmu_designs;
#[allow(dead_code)]
#[path = "../tests/common/fmu_host.rs"]
mod fmu_host;
#[path = "../tests/common/output_checks.rs"]
mod output_checks;

use designs::{
    declared, declared_conservative, declared_ramped, elastic_engine, engine, limited_supply_engine, lubricated_declared,
    lubricated_engine, mass_conserving_engine, roller, rubbing_engine, rubbing_slider, run, slider, Design, Random,
};
use fmu_designs::NotRun;
use std::time::Instant;

fn main() {
    let only = std::env::args().nth(3);
    let args: Vec<u64> = std::env::args().skip(1).take(2).map(|a| a.parse().expect("a whole number")).collect();
    let (n, first) = (args.first().copied().unwrap_or(1000), args.get(1).copied().unwrap_or(0));
    let families = [
        ("engine", engine as fn(&mut Random) -> designs::Design),
        ("slider", slider),
        ("rubbing engine", rubbing_engine),
        ("rubbing slider", rubbing_slider),
        ("declared", declared),
        ("declared ramped", declared_ramped),
        ("declared conservative", declared_conservative),
        ("lubricated engine", lubricated_engine),
        ("lubricated declared", lubricated_declared),
        ("mass-conserving engine", mass_conserving_engine),
        ("limited supply engine", limited_supply_engine),
        ("elastic engine", elastic_engine),
    ];
    let through_the_fmu =
        [("fmu declared", declared as fn(&mut Random) -> Design), ("fmu declared ramped", declared_ramped), ("fmu roller", roller)];
    for (family, make) in through_the_fmu.into_iter().filter(|(family, _)| only.as_deref().is_none_or(|o| o == *family)) {
        let (start, mut failed, mut refused, mut steps) = (Instant::now(), 0, 0, 0);
        for seed in first..first + n {
            let design = make(&mut Random::new(seed));
            match fmu_designs::run(&design) {
                Ok(taken) => steps += taken,
                Err(NotRun::Refused(e)) => {
                    refused += 1;
                    println!("{family} seed {seed} refused: {e}");
                }
                Err(NotRun::Failed(e)) => {
                    failed += 1;
                    println!("{family} seed {seed}: {e}\n  {design:?}");
                }
            }
        }
        let elapsed = start.elapsed().as_secs_f64();
        println!(
            "{family}: {n} designs from seed {first}, {failed} failed, {refused} refused, {steps} communication steps, {elapsed:.1} s"
        );
    }
    for (family, make) in families.into_iter().filter(|(family, _)| only.as_deref().is_none_or(|o| o == *family)) {
        // The worst |energy balance| of the designs without and with liner friction, and their seeds.
        let (start, mut failed, mut events, mut worst) = (Instant::now(), 0, 0, [(0.0_f64, 0); 2]);
        for seed in first..first + n {
            let design = make(&mut Random::new(seed));
            match run(&design) {
                Ok(finished) => {
                    events += finished.events.len();
                    let rubbing = usize::from(design.params.friction > 0.0);
                    let balance = finished.energy_balance().abs();
                    if balance > worst[rubbing].0 {
                        worst[rubbing] = (balance, seed);
                    }
                }
                Err(e) => {
                    failed += 1;
                    println!("{family} seed {seed}: {e}\n  {design:?}");
                }
            }
        }
        let elapsed = start.elapsed().as_secs_f64();
        // Only the sliders and the conservative declared designs are free of damping, gas and gravity:
        // the engines' balance holds their work.
        let balance = if family.ends_with("slider") || family.ends_with("conservative") {
            let [(without, a), (with, b)] = worst;
            format!(", worst |energy balance| {without:.1e} frictionless (seed {a}), {with:.1e} with friction (seed {b})")
        } else {
            String::new()
        };
        println!("{family}: {n} designs, {failed} failed, {events} events{balance}, {elapsed:.1} s");
    }
}
