//! The exported C symbols of `fmi_headers/fmi2Functions.h`: the common and Co-Simulation functions,
//! each a one-line call of its generic body in `abi.rs` with the shipped [`Engine`], written once in
//! `exports!`, which also makes the table [`Functions`] of them all.
#![allow(non_snake_case, clippy::missing_safety_doc)]

use super::abi;
use super::sibling;
use super::types::*;
use crate::simulation::Engine;
use std::ffi::{c_char, c_int, c_void, CStr};

/// Each function as a `#[no_mangle]` symbol that first hands the call to the sibling build when one
/// runs in this build's stead (`sibling.rs`), and as a field of [`Functions`].
macro_rules! exports {
    ($(fn $name:ident($($arg:ident: $ty:ty),*) $(-> $ret:ty)? $body:block)*) => {
        /// The exported functions as pointers: this build's own ([`Functions::NATIVE`]) or those of
        /// another copy of the library opened with `dlopen` (`sibling::open`).
        #[derive(Clone, Copy)]
        pub struct Functions {
            $(pub $name: unsafe extern "C" fn($($ty),*) $(-> $ret)?,)*
        }

        impl Functions {
            pub const NATIVE: Functions = Functions { $($name,)* };

            /// The functions of `library`, a handle from `dlopen`; `None` if one is missing.
            pub(super) unsafe fn load(library: *mut c_void) -> Option<Functions> {
                Some(Functions {
                    $($name: std::mem::transmute::<*mut c_void, unsafe extern "C" fn($($ty),*) $(-> $ret)?>(
                        symbol(library, concat!(stringify!($name), "\0"))?,
                    ),)*
                })
            }
        }

        $(
            #[no_mangle]
            pub unsafe extern "C" fn $name($($arg: $ty),*) $(-> $ret)? {
                if let Some(sibling) = sibling::functions() {
                    return (sibling.$name)($($arg),*);
                }
                $body
            }
        )*
    };
}

/// `dlsym(library, name)` for a NUL-terminated `name`, `None` when absent.
pub(super) unsafe fn symbol(library: *mut c_void, name: &str) -> Option<*mut c_void> {
    let address = libc::dlsym(library, CStr::from_bytes_with_nul(name.as_bytes()).ok()?.as_ptr());
    (!address.is_null()).then_some(address)
}

exports! {
    fn fmi2GetTypesPlatform() -> *const c_char {
        c"default".as_ptr()
    }

    fn fmi2GetVersion() -> *const c_char {
        c"2.0".as_ptr()
    }

    fn fmi2SetDebugLogging(c: fmi2Component, on: fmi2Boolean, n: usize, categories: *const fmi2String) -> Status {
        abi::set_debug_logging::<Engine>(c, on, n, categories)
    }

    fn fmi2Instantiate(
        name: fmi2String,
        fmu_type: c_int,
        guid: fmi2String,
        resource_location: fmi2String,
        functions: *const fmi2CallbackFunctions,
        visible: fmi2Boolean,
        logging_on: fmi2Boolean
    ) -> fmi2Component {
        abi::instantiate::<Engine>(name, fmu_type, guid, resource_location, functions, logging_on)
    }

    fn fmi2FreeInstance(c: fmi2Component) {
        abi::free_instance::<Engine>(c)
    }

    fn fmi2SetupExperiment(
        c: fmi2Component,
        tolerance_defined: fmi2Boolean,
        tolerance: fmi2Real,
        start: fmi2Real,
        stop_defined: fmi2Boolean,
        stop: fmi2Real
    ) -> Status {
        abi::setup_experiment::<Engine>(c, tolerance_defined, tolerance, start, stop_defined, stop)
    }

    fn fmi2EnterInitializationMode(c: fmi2Component) -> Status {
        abi::enter_initialization_mode::<Engine>(c)
    }

    fn fmi2ExitInitializationMode(c: fmi2Component) -> Status {
        abi::exit_initialization_mode::<Engine>(c)
    }

    fn fmi2Terminate(c: fmi2Component) -> Status {
        abi::terminate::<Engine>(c)
    }

    fn fmi2Reset(c: fmi2Component) -> Status {
        abi::reset::<Engine>(c)
    }

    fn fmi2GetReal(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *mut fmi2Real) -> Status {
        abi::get_real::<Engine>(c, vr, n, value)
    }

    fn fmi2GetInteger(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *mut fmi2Integer) -> Status {
        abi::get_integer::<Engine>(c, vr, n, value)
    }

    fn fmi2GetBoolean(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *mut fmi2Boolean) -> Status {
        abi::get_boolean::<Engine>(c, vr, n, value)
    }

    fn fmi2GetString(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *mut fmi2String) -> Status {
        abi::get_string::<Engine>(c, vr, n, value)
    }

    fn fmi2SetReal(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *const fmi2Real) -> Status {
        abi::set_real::<Engine>(c, vr, n, value)
    }

    fn fmi2SetInteger(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *const fmi2Integer) -> Status {
        abi::set_integer::<Engine>(c, vr, n, value)
    }

    fn fmi2SetBoolean(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *const fmi2Boolean) -> Status {
        abi::set_boolean::<Engine>(c, vr, n, value)
    }

    fn fmi2SetString(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *const fmi2String) -> Status {
        abi::set_string::<Engine>(c, vr, n, value)
    }

    fn fmi2GetFMUstate(c: fmi2Component, state: *mut fmi2FMUstate) -> Status {
        abi::get_fmu_state::<Engine>(c, state)
    }

    fn fmi2SetFMUstate(c: fmi2Component, state: fmi2FMUstate) -> Status {
        abi::set_fmu_state::<Engine>(c, state)
    }

    fn fmi2FreeFMUstate(c: fmi2Component, state: *mut fmi2FMUstate) -> Status {
        abi::free_fmu_state::<Engine>(c, state)
    }

    fn fmi2SerializedFMUstateSize(c: fmi2Component, state: fmi2FMUstate, size: *mut usize) -> Status {
        abi::serialized_fmu_state_size::<Engine>(c, state, size)
    }

    fn fmi2SerializeFMUstate(c: fmi2Component, state: fmi2FMUstate, buffer: *mut fmi2Byte, size: usize) -> Status {
        abi::serialize_fmu_state::<Engine>(c, state, buffer, size)
    }

    fn fmi2DeSerializeFMUstate(c: fmi2Component, buffer: *const fmi2Byte, size: usize, state: *mut fmi2FMUstate) -> Status {
        abi::deserialize_fmu_state::<Engine>(c, buffer, size, state)
    }

    fn fmi2GetDirectionalDerivative(
        c: fmi2Component,
        unknowns: *const fmi2ValueReference,
        n_unknowns: usize,
        knowns: *const fmi2ValueReference,
        n_knowns: usize,
        dv_known: *const fmi2Real,
        dv_unknown: *mut fmi2Real
    ) -> Status {
        abi::get_directional_derivative::<Engine>(c)
    }

    fn fmi2SetRealInputDerivatives(
        c: fmi2Component,
        vr: *const fmi2ValueReference,
        n: usize,
        order: *const fmi2Integer,
        value: *const fmi2Real
    ) -> Status {
        abi::set_real_input_derivatives::<Engine>(c)
    }

    fn fmi2GetRealOutputDerivatives(
        c: fmi2Component,
        vr: *const fmi2ValueReference,
        n: usize,
        order: *const fmi2Integer,
        value: *mut fmi2Real
    ) -> Status {
        abi::get_real_output_derivatives::<Engine>(c)
    }

    fn fmi2DoStep(c: fmi2Component, t: fmi2Real, h: fmi2Real, no_set_prior: fmi2Boolean) -> Status {
        abi::do_step::<Engine>(c, t, h)
    }

    fn fmi2CancelStep(c: fmi2Component) -> Status {
        abi::cancel_step::<Engine>(c)
    }

    fn fmi2GetStatus(c: fmi2Component, kind: c_int, value: *mut c_int) -> Status {
        abi::get_status::<Engine>(c, kind, value)
    }

    fn fmi2GetRealStatus(c: fmi2Component, kind: c_int, value: *mut fmi2Real) -> Status {
        abi::get_real_status::<Engine>(c, kind, value)
    }

    fn fmi2GetIntegerStatus(c: fmi2Component, kind: c_int, value: *mut fmi2Integer) -> Status {
        abi::get_integer_status::<Engine>(c, kind, value)
    }

    fn fmi2GetBooleanStatus(c: fmi2Component, kind: c_int, value: *mut fmi2Boolean) -> Status {
        abi::get_boolean_status::<Engine>(c, kind, value)
    }

    fn fmi2GetStringStatus(c: fmi2Component, kind: c_int, value: *mut fmi2String) -> Status {
        abi::get_string_status::<Engine>(c, kind, value)
    }
}
