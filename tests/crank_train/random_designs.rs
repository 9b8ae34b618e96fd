//! Every physical design runs (DESIGN §5): seeded random engines and light sliders
//! (`common/designs.rs`) a few cycles each, none ending in an error. The light sliders have no
//! damping, gas or gravity, so their energy balance closes too: T(0) = T(end) + what the impacts
//! and sliding starts dissipated. `examples/random_designs` runs the same families by the thousand.

use crate::common::designs::{engine, rubbing_engine, rubbing_slider, run, slider, Design, Finished, Random};

const DESIGNS: u64 = 250;

/// Designs beyond the first `DESIGNS` that a larger sweep found failing once, kept here: slider 5223,
/// a corner at rest that the motion closes again before it lifts beyond ε_h.
const FOUND_BY_LARGER_SWEEPS: [u64; 1] = [5223];

fn failures(make: fn(&mut Random) -> Design, check: impl Fn(&Design, &Finished) -> Result<(), String>) -> Vec<String> {
    (0..DESIGNS)
        .chain(FOUND_BY_LARGER_SWEEPS)
        .filter_map(|seed| {
            let design = make(&mut Random::new(seed));
            run(&design).and_then(|finished| check(&design, &finished)).err().map(|e| format!("seed {seed}: {e}\n  {design:?}"))
        })
        .collect()
}

#[test]
fn random_engines_all_run() {
    let failed = failures(engine, |_, _| Ok(()));
    assert!(failed.is_empty(), "{} of {DESIGNS} failed:\n{}", failed.len(), failed.join("\n"));
}

fn balanced(_: &Design, f: &Finished) -> Result<(), String> {
    let balance = f.energy_balance();
    if balance.abs() < 1e-6 {
        Ok(())
    } else {
        Err(format!("energy balance off by {balance:e}"))
    }
}

#[test]
fn random_light_sliders_all_run_and_conserve_energy() {
    let failed = failures(slider, balanced);
    assert!(failed.is_empty(), "{} of {DESIGNS} failed:\n{}", failed.len(), failed.join("\n"));
}

/// With liner friction and a tilted cylinder.
#[test]
fn random_rubbing_engines_all_run() {
    let failed = failures(rubbing_engine, |_, _| Ok(()));
    assert!(failed.is_empty(), "{} of {DESIGNS} failed:\n{}", failed.len(), failed.join("\n"));
}

/// With liner friction: the balance counts what friction dissipated in sliding and in impacts.
#[test]
fn random_rubbing_sliders_all_run_and_balance_their_energy() {
    let failed = failures(rubbing_slider, balanced);
    assert!(failed.is_empty(), "{} of {DESIGNS} failed:\n{}", failed.len(), failed.join("\n"));
}
