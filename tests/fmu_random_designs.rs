//! Random designs of every model option run through the FMU's C functions in process
//! (`common/fmu_designs.rs`), every output checked at every communication step and a state restored
//! halfway continued bit for bit; `make designs` runs 10⁴ of each (`tools/random_designs.rs`).

use crate::common::designs::{declared, declared_ramped, roller, Design, Random};
use crate::common::fmu_designs::{run, NotRun};

/// Each of the first `n` designs `make` draws that fails through the FMU, with its seed, and how many
/// the FMU refused at initialization.
fn failures(n: u64, make: fn(&mut Random) -> Design) -> (Vec<String>, u64) {
    let (mut failed, mut refused) = (Vec::new(), 0);
    for seed in 0..n {
        let design = make(&mut Random::new(seed));
        match run(&design) {
            Ok(_) => {}
            Err(NotRun::Refused(_)) => refused += 1,
            Err(NotRun::Failed(e)) => failed.push(format!("seed {seed}: {e}\n  {design:?}")),
        }
    }
    (failed, refused)
}

fn all_run(n: u64, make: fn(&mut Random) -> Design) {
    let (failed, refused) = failures(n, make);
    assert!(failed.is_empty(), "{} of {n} failed:\n{}", failed.len(), failed.join("\n"));
    // The generators redraw what the model refuses: the FMU, which builds the same model, refuses none.
    assert_eq!(refused, 0, "the FMU refused {refused} of {n} designs the model accepts");
}

/// Crank train (model_variant 1), every crank mode and pressure source.
#[test]
fn declared_designs_run_through_the_fmu() {
    all_run(60, declared);
}

/// Crank train, inputs ramping (fmi2SetRealInputDerivatives), communication steps of variable length.
#[test]
fn declared_designs_with_ramping_inputs_run_through_the_fmu() {
    all_run(60, declared_ramped);
}

/// The roller (model_variant 2), either forcing, communication steps of variable length.
#[test]
fn roller_designs_run_through_the_fmu() {
    all_run(60, roller);
}
