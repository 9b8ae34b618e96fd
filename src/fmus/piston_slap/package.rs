//! What PistonSlap.fmu holds besides its binaries: its model description, its documentation with the geometry
//! sketch, and the example pressure traces (`pressure_source = 3`, `pressure_trace = "full_load.csv"`).

use super::variables::{FMI3_MODEL_DESCRIPTION_XML, MODEL_DESCRIPTION_XML, VARIABLES};
use crate::fmi::Package;

/// PistonSlap.fmu's contents.
pub const PACKAGE: Package = Package {
    name: "PistonSlap",
    model_description_xml: MODEL_DESCRIPTION_XML,
    fmi3_model_description_xml: FMI3_MODEL_DESCRIPTION_XML,
    variables: &VARIABLES,
    documentation: include_str!("../../../documentation/index.html"),
    files: &[
        ("documentation/geometry.svg", include_bytes!("../../../documentation/geometry.svg")),
        ("resources/README.txt", include_bytes!("../../../resources/README.txt")),
        ("resources/full_load.csv", include_bytes!("../../../resources/full_load.csv")),
        ("resources/motored.csv", include_bytes!("../../../resources/motored.csv")),
    ],
};
