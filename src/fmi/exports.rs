//! The exported C symbols of `fmi_headers/fmi2Functions.h`: the common and Co-Simulation functions,
//! each a call of its generic body in `functions.rs` for one FMU of the registry (`crate::fmus::registry!`).
//! One binary serves every FMU of the crate: a copy the packer stamped ([`identity`]) makes instances of its
//! own FMU only, refusing any other GUID; an unstamped library makes an instance for the FMU whose GUID
//! fmi2Instantiate gets (`registry::by_identity!`). Every later call goes to the FMU whose tag the instance
//! carries (`registry::by_tag!`).
#![allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]

use super::functions;
use super::identity;
use super::registry::{by_identity, by_tag};
use super::types::*;
use crate::fmus::registry;
use std::ffi::{c_char, c_int};

/// `functions::$f::<M>($args)` for the FMU M that made instance `$c`; expands inside the caller's
/// `unsafe` block.
macro_rules! by_model {
    ($c:expr, $f:ident($($arg:expr),*)) => {{
        let tag = functions::instance_tag($c);
        registry!(by_tag!(tag, M => functions::$f::<M>($($arg),*)))
    }};
}

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
    unsafe { by_model!(c, set_debug_logging(c, on, n, categories)) }
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
    unsafe {
        let stamp = identity::stamped();
        let stamp = stamp.as_deref();
        registry!(
            by_identity!(stamp, guid, M => functions::instantiate::<M>(name, fmu_type, guid, resource_location, functions, logging_on))
        )
    }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2FreeInstance(c: fmi2Component) {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, free_instance(c)) }
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
    unsafe { by_model!(c, setup_experiment(c, start, stop_defined, stop)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2EnterInitializationMode(c: fmi2Component) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, enter_initialization_mode(c)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2ExitInitializationMode(c: fmi2Component) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, exit_initialization_mode(c)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2Terminate(c: fmi2Component) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, terminate(c)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2Reset(c: fmi2Component) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, reset(c)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetReal(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *mut fmi2Real) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, get_real(c, vr, n, value)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetInteger(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *mut fmi2Integer) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, get_integer(c, vr, n, value)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetBoolean(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *mut fmi2Boolean) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, get_boolean(c, vr, n, value)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetString(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *mut fmi2String) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, get_string(c, vr, n, value)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetReal(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *const fmi2Real) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, set_real(c, vr, n, value)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetInteger(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *const fmi2Integer) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, set_integer(c, vr, n, value)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetBoolean(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *const fmi2Boolean) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, set_boolean(c, vr, n, value)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetString(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *const fmi2String) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, set_string(c, vr, n, value)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetFMUstate(c: fmi2Component, state: *mut fmi2FMUstate) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, get_fmu_state(c, state)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SetFMUstate(c: fmi2Component, state: fmi2FMUstate) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, set_fmu_state(c, state)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2FreeFMUstate(c: fmi2Component, state: *mut fmi2FMUstate) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, free_fmu_state(c, state)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SerializedFMUstateSize(c: fmi2Component, state: fmi2FMUstate, size: *mut usize) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, serialized_fmu_state_size(c, state, size)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2SerializeFMUstate(c: fmi2Component, state: fmi2FMUstate, buffer: *mut fmi2Byte, size: usize) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, serialize_fmu_state(c, state, buffer, size)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
    c: fmi2Component,
    buffer: *const fmi2Byte,
    size: usize,
    state: *mut fmi2FMUstate,
) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, deserialize_fmu_state(c, buffer, size, state)) }
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
    unsafe { by_model!(c, get_directional_derivative(c)) }
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
    unsafe { by_model!(c, set_real_input_derivatives(c, vr, n, order, value)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetRealOutputDerivatives(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    order: *const fmi2Integer,
    value: *mut fmi2Real,
) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, get_real_output_derivatives(c, vr, n, order, value)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2DoStep(c: fmi2Component, t: fmi2Real, h: fmi2Real, _no_set_prior: fmi2Boolean) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, do_step(c, t, h)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2CancelStep(c: fmi2Component) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, cancel_step(c)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetStatus(c: fmi2Component, kind: c_int, value: *mut c_int) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, get_status(c, kind, value)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetRealStatus(c: fmi2Component, kind: c_int, value: *mut fmi2Real) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, get_real_status(c, kind, value)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetIntegerStatus(c: fmi2Component, kind: c_int, value: *mut fmi2Integer) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, get_integer_status(c, kind, value)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetBooleanStatus(c: fmi2Component, kind: c_int, value: *mut fmi2Boolean) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, get_boolean_status(c, kind, value)) }
}

#[no_mangle]
pub unsafe extern "C" fn fmi2GetStringStatus(c: fmi2Component, kind: c_int, value: *mut fmi2String) -> Status {
    // SAFETY: the host keeps the FMI 2.0 calling contract, which is each body's contract.
    unsafe { by_model!(c, get_string_status(c, kind, value)) }
}
