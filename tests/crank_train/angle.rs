//! The crank angle output accumulates (DESIGN.md §4) while the models keep the angle they
//! integrate bounded against round-off: within one cycle (4π, the crank train), below 2048 turns
//! (the roller).

use pistonslap::fmus::piston_slap::Mechanism;
use pistonslap::fmus::piston_slap::{Inputs, Outputs, Parameters};
use pistonslap::models::{CrankTrain, Roller};
use std::f64::consts::PI;

/// The crank angle output after each of `steps` communication steps of `dt`.
fn angles<Mo: Mechanism>(params: &Parameters, inputs: &Inputs, dt: f64, steps: usize) -> Vec<f64> {
    let mut model = Mo::new(params, 0.0).unwrap();
    (1..=steps)
        .map(|k| {
            model.advance(inputs, k as f64 * dt, &mut Vec::new()).unwrap();
            let mut out = Outputs::default();
            model.write_outputs(&mut out);
            out.crank_angle
        })
        .collect()
}

/// A prescribed crank's angle is ω t: the crank train's after several restarts within the first
/// cycle, the roller's across the block of 2048 turns its stepper takes off.
#[test]
fn prescribed_angles_accumulate() {
    let inputs = Inputs::default();
    let turn = 2.0 * PI / inputs.crank_speed;
    let crank_train = (0.01, angles::<CrankTrain>(&Parameters::default(), &inputs, 0.01, 25));
    let roller = (turn, angles::<Roller>(&Parameters { model_variant: 2, ..Parameters::default() }, &inputs, turn, 2100));
    for (name, (dt, angles)) in [("crank train", crank_train), ("roller", roller)] {
        for (k, angle) in angles.iter().enumerate() {
            let expected = inputs.crank_speed * (k + 1) as f64 * dt;
            assert!((angle - expected).abs() < 1e-9 * expected, "{name}, step {k}: {angle} rad, expected {expected}");
        }
    }
}

/// A free crank's angle, a coordinate shifted by whole cycles inside, is continuous in the
/// output: past 4π after 2.5 cycles, rising by the crank speed's step each step.
#[test]
fn free_crank_angle_accumulates() {
    let inputs = Inputs::default();
    let params = Parameters { crank_mode: 2, ..Parameters::default() };
    let dt = 1e-3;
    let steps = (2.5 * 4.0 * PI / inputs.crank_speed / dt) as usize;
    let angles = angles::<CrankTrain>(&params, &inputs, dt, steps);
    assert!(angles[steps - 1] > 2.2 * 4.0 * PI, "after 2.5 cycles: {} rad", angles[steps - 1]);
    for pair in angles.windows(2) {
        let rise = (pair[1] - pair[0]) / (inputs.crank_speed * dt);
        assert!((0.5..1.5).contains(&rise), "the angle went from {} to {} rad in one step", pair[0], pair[1]);
    }
}
