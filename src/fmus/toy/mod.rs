//! A toy FMU, built only for the tests: a first-order lag `ẏ = (u − y)/τ`, solved exactly over each step, on
//! a hand-written table. It shows what adding an FMU takes: this room, and its name in `fmus::registry!`
//! (`fmi/tests/registry.rs` drives it through the exported functions beside the shipped FMUs).

use crate::fmi::{self, Causality, Description, Kind, Model, Variable};
use serde::{Deserialize, Serialize};
use std::path::Path;

/// The lag's one parameter.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct LagParameters {
    /// τ, s.
    pub time_constant: f64,
}

impl Default for LagParameters {
    fn default() -> Self {
        Self { time_constant: 0.1 }
    }
}

/// The lag's one input.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct LagInputs {
    /// u, followed by y.
    pub u: f64,
}

/// The lag's one output.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct LagOutputs {
    /// y, with τ ẏ = u − y.
    pub y: f64,
}

/// The lag at a time.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Lag {
    time_constant: f64,
    time: f64,
    outputs: LagOutputs,
}

/// The type the FMI layer runs this FMU as.
pub type Fmu = Lag;

/// The toy's GUID.
pub const GUID: &str = "{toy-first-order-lag}";

static VARIABLES: [Variable; 3] = [
    Variable { name: "u", kind: Kind::Real, causality: Causality::Input, unit: "", start: "0", description: "input" },
    Variable { name: "y", kind: Kind::Real, causality: Causality::Output, unit: "", start: "", description: "lagged input" },
    Variable { name: "time_constant", kind: Kind::Real, causality: Causality::Parameter, unit: "s", start: "0.1", description: "τ" },
];

fn get_real(vr: u32, p: &LagParameters, i: &LagInputs, o: &LagOutputs) -> Option<f64> {
    [Some(i.u), Some(o.y), Some(p.time_constant)].get(vr as usize).copied().flatten()
}

fn real_mut<'a>(vr: u32, p: &'a mut LagParameters, i: &'a mut LagInputs) -> Option<&'a mut f64> {
    match vr {
        0 => Some(&mut i.u),
        2 => Some(&mut p.time_constant),
        _ => None,
    }
}

impl Model for Lag {
    const NAME: &'static str = "Lag";
    type Parameters = LagParameters;
    type Inputs = LagInputs;
    type Outputs = LagOutputs;
    type InputDerivatives = ();
    type Simulation = Lag;
    const DESCRIPTION: Description<LagParameters, LagInputs, LagOutputs> = Description {
        model_name: "Lag",
        guid: GUID,
        model_description_xml: "",
        fmi3_model_description_xml: "",
        variables: &VARIABLES,
        get_real,
        get_integer: |_, _, _, _| None,
        get_string: |_, _, _, _| None,
        real_mut,
        integer_mut: |_, _, _| None,
        string_mut: |_, _, _| None,
    };
    const MAX_INPUT_DERIVATIVE_ORDER: i32 = 0;
    const MAX_OUTPUT_DERIVATIVE_ORDER: i32 = 0;
    const INSTANCE_TAG: u64 = u64::from_le_bytes(*b"TOYLAGIN");
    const STATE_TAG: u64 = u64::from_le_bytes(*b"TOYLAGST");

    fn resolve(parameters: &LagParameters, _: Option<&Path>) -> LagParameters {
        parameters.clone()
    }
    fn validate(parameters: &LagParameters) -> Result<(), fmi::Error> {
        Ok(crate::models::check_real("time_constant", parameters.time_constant, None, None, true, "s")?)
    }
    fn preview(parameters: &LagParameters, _: &LagInputs, start_time: f64) -> Result<Lag, fmi::Error> {
        Ok(Lag { time_constant: parameters.time_constant, time: start_time, outputs: LagOutputs::default() })
    }
    fn start(parameters: &LagParameters, inputs: &LagInputs, start_time: f64) -> Result<Lag, fmi::Error> {
        Self::preview(parameters, inputs, start_time)
    }
    fn step(sim: &mut Lag, inputs: &LagInputs, _: &(), t_end: f64) -> Result<(), fmi::Error> {
        let decay = libm::exp(-(t_end - sim.time) / sim.time_constant);
        sim.outputs.y = inputs.u + (sim.outputs.y - inputs.u) * decay;
        sim.time = t_end;
        Ok(())
    }
    fn time(sim: &Lag) -> f64 {
        sim.time
    }
    fn outputs(sim: &Lag) -> &LagOutputs {
        &sim.outputs
    }
    fn check(sim: &Lag) -> Result<(), fmi::Error> {
        Ok(crate::models::check_real("time_constant", sim.time_constant, None, None, true, "s")?)
    }
    fn input_derivatives<'a>(_: &'a mut (), _: &str) -> Option<&'a mut [f64; 2]> {
        None
    }
    fn output_derivative(_: &Lag, _: u32, _: i32) -> Option<f64> {
        None
    }
}
