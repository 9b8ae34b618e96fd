//! The exported C symbols of `fmi_headers/fmi2Functions.h`: the common and Co-Simulation functions,
//! each a call of its generic body in `functions.rs` with the shipped [`ModelVariant`].
#![allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]

use super::functions;
use super::types::*;
use crate::simulation::ModelVariant;
use std::ffi::{c_char, c_int};

#[no_mangle]
pub unsafe extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
    c"default".as_ptr()
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetVersion() -> *const c_char {
    c"2.0".as_ptr()
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetDebugLogging(c: fmi2Component, on: fmi2Boolean, n: usize, categories: *const fmi2String) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::set_debug_logging::<ModelVariant>(c, on, n, categories) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2Instantiate(
    name: fmi2String,
    fmu_type: c_int,
    guid: fmi2String,
    resource_location: fmi2String,
    functions: *const fmi2CallbackFunctions,
    _visible: fmi2Boolean,
    logging_on: fmi2Boolean,
) -> fmi2Component {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::instantiate::<ModelVariant>(name, fmu_type, guid, resource_location, functions, logging_on) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2FreeInstance(c: fmi2Component) {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::free_instance::<ModelVariant>(c) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetupExperiment(
    c: fmi2Component,
    _tolerance_defined: fmi2Boolean,
    _tolerance: fmi2Real,
    start: fmi2Real,
    stop_defined: fmi2Boolean,
    stop: fmi2Real,
) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::setup_experiment::<ModelVariant>(c, start, stop_defined, stop) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2EnterInitializationMode(c: fmi2Component) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::enter_initialization_mode::<ModelVariant>(c) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2ExitInitializationMode(c: fmi2Component) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::exit_initialization_mode::<ModelVariant>(c) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2Terminate(c: fmi2Component) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::terminate::<ModelVariant>(c) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2Reset(c: fmi2Component) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::reset::<ModelVariant>(c) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetReal(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *mut fmi2Real) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::get_real::<ModelVariant>(c, vr, n, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetInteger(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *mut fmi2Integer) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::get_integer::<ModelVariant>(c, vr, n, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetBoolean(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *mut fmi2Boolean) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::get_boolean::<ModelVariant>(c, vr, n, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetString(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *mut fmi2String) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::get_string::<ModelVariant>(c, vr, n, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetReal(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *const fmi2Real) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::set_real::<ModelVariant>(c, vr, n, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetInteger(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *const fmi2Integer) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::set_integer::<ModelVariant>(c, vr, n, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetBoolean(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *const fmi2Boolean) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::set_boolean::<ModelVariant>(c, vr, n, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetString(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *const fmi2String) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::set_string::<ModelVariant>(c, vr, n, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetFMUstate(c: fmi2Component, state: *mut fmi2FMUstate) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::get_fmu_state::<ModelVariant>(c, state) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetFMUstate(c: fmi2Component, state: fmi2FMUstate) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::set_fmu_state::<ModelVariant>(c, state) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2FreeFMUstate(c: fmi2Component, state: *mut fmi2FMUstate) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::free_fmu_state::<ModelVariant>(c, state) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SerializedFMUstateSize(c: fmi2Component, state: fmi2FMUstate, size: *mut usize) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::serialized_fmu_state_size::<ModelVariant>(c, state, size) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SerializeFMUstate(c: fmi2Component, state: fmi2FMUstate, buffer: *mut fmi2Byte, size: usize) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::serialize_fmu_state::<ModelVariant>(c, state, buffer, size) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
    c: fmi2Component,
    buffer: *const fmi2Byte,
    size: usize,
    state: *mut fmi2FMUstate,
) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::deserialize_fmu_state::<ModelVariant>(c, buffer, size, state) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetDirectionalDerivative(
    c: fmi2Component,
    _unknowns: *const fmi2ValueReference,
    _n_unknowns: usize,
    _knowns: *const fmi2ValueReference,
    _n_knowns: usize,
    _dv_known: *const fmi2Real,
    _dv_unknown: *mut fmi2Real,
) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::get_directional_derivative::<ModelVariant>(c) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetRealInputDerivatives(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    order: *const fmi2Integer,
    value: *const fmi2Real,
) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::set_real_input_derivatives::<ModelVariant>(c, vr, n, order, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetRealOutputDerivatives(
    c: fmi2Component,
    _vr: *const fmi2ValueReference,
    _n: usize,
    _order: *const fmi2Integer,
    _value: *mut fmi2Real,
) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::get_real_output_derivatives::<ModelVariant>(c) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2DoStep(c: fmi2Component, t: fmi2Real, h: fmi2Real, _no_set_prior: fmi2Boolean) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::do_step::<ModelVariant>(c, t, h) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2CancelStep(c: fmi2Component) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::cancel_step::<ModelVariant>(c) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetStatus(c: fmi2Component, kind: c_int, value: *mut c_int) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::get_status::<ModelVariant>(c, kind, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetRealStatus(c: fmi2Component, kind: c_int, value: *mut fmi2Real) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::get_real_status::<ModelVariant>(c, kind, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetIntegerStatus(c: fmi2Component, kind: c_int, value: *mut fmi2Integer) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::get_integer_status::<ModelVariant>(c, kind, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetBooleanStatus(c: fmi2Component, kind: c_int, value: *mut fmi2Boolean) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::get_boolean_status::<ModelVariant>(c, kind, value) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetStringStatus(c: fmi2Component, kind: c_int, value: *mut fmi2String) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { functions::get_string_status::<ModelVariant>(c, kind, value) }
}
