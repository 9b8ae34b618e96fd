//! What EngineCycle.fmu holds besides its binaries: its model description and its documentation.

use super::variables::{FMI3_MODEL_DESCRIPTION_XML, MODEL_DESCRIPTION_XML, VARIABLES};
use crate::fmi::Package;

/// EngineCycle.fmu's contents.
pub const PACKAGE: Package = Package {
    name: "EngineCycle",
    model_description_xml: MODEL_DESCRIPTION_XML,
    fmi3_model_description_xml: FMI3_MODEL_DESCRIPTION_XML,
    variables: &VARIABLES,
    documentation: include_str!("../../../documentation/engine_cycle.html"),
    files: &[],
};
