//! EngineCycle's variable contract: its parameters, (no) inputs and outputs, in SI units, generated with their
//! documentation, defaults, range checks and output check from `modelDescription/engine_cycle.xml`.

use crate::models::{check_integer, check_real, ModelError};
use serde::{Deserialize, Serialize};

include!(concat!(env!("OUT_DIR"), "/engine_cycle_contract.rs"));

parameters_struct! {
    /// The engine cycle's parameters.
    #[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
    pub struct Parameters {}
}

inputs_struct! {
    /// EngineCycle has no inputs: its speed comes from the parameters.
    #[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
    pub struct Inputs {}
}

outputs_struct! {
    /// The values a host reads, with their time derivatives.
    #[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
    pub struct Outputs {}
}
