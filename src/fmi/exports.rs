//! The exported C symbols of `fmi_headers/fmi2Functions.h`: the common and Co-Simulation functions, each a
//! call of its generic body in `functions.rs` for one FMU of a registry; beside them FMI 3.0's
//! (`fmi3_exports.rs`), so that one library is both versions' binary. The layer names no FMU: the rooms'
//! registry (`crate::fmus`) invokes [`exports!`] with its list, which writes the symbols there. One binary
//! serves every FMU of the list: a copy the packer stamped (`identity`) makes instances of its own FMU only,
//! refusing any other GUID; an unstamped library makes an instance for the FMU whose GUID fmi2Instantiate gets
//! (`registry::by_identity!`). Every later call goes to the FMU whose tag the instance carries
//! (`registry::by_tag!`).

/// `exports!([room, …])` writes the module `exports` of the fmi2* and fmi3* symbols (`fmi3_exports.rs`) at the
/// invoking module, for the FMUs `super::room::Fmu` (each a [`crate::fmi::Model`]) in the registry's order.
macro_rules! exports {
    ([$($room:ident),+ $(,)?]) => {
        $crate::fmi::exports!(@module [$(super::$room::Fmu),+]);
    };
    (@module $fmus:tt) => {
        /// The exported fmi2* and fmi3* symbols, each forwarding to its generic body for the instance's FMU.
        #[allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]
        pub mod exports {
            use $crate::fmi::functions;
            use $crate::fmi::types::*;
            use std::ffi::{c_char, c_int};

            /// "default": the types of the standard headers.
            #[no_mangle]
            pub unsafe extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
                c"default".as_ptr()
            }

            /// "2.0".
            #[no_mangle]
            pub unsafe extern "C" fn fmi2GetVersion() -> *const c_char {
                c"2.0".as_ptr()
            }

            /// A new instance of the FMU whose GUID is given, or null (a stamped copy refuses a foreign GUID).
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
                    let stamp = $crate::fmi::identity::stamped();
                    let stamp = stamp.as_deref();
                    $crate::fmi::registry::by_identity!(
                        $fmus stamp, guid, M => functions::instantiate::<M>(name, fmu_type, guid, resource_location, functions, logging_on)
                    )
                }
            }

            /// Frees the instance and everything it holds.
            #[no_mangle]
            pub unsafe extern "C" fn fmi2FreeInstance(c: fmi2Component) {
                // SAFETY: the host keeps the FMI 2.0 calling contract, which is the body's contract.
                unsafe {
                    let tag = functions::instance_tag(c);
                    $crate::fmi::registry::by_tag!($fmus tag, M => functions::free_instance::<M>(c))
                }
            }

            $crate::fmi::exports!(@forward $fmus
                /// Switches logging on or off, for all categories or the ones listed.
                fn fmi2SetDebugLogging(
                    c: fmi2Component,
                    on: fmi2Boolean,
                    n: usize,
                    categories: *const fmi2String,
                ) -> Status => functions::set_debug_logging(c, on, n, categories);
                /// Frees the instance and everything it holds.
                /// Start time and optional stop time (the tolerance is not used: steps are event-exact).
                fn fmi2SetupExperiment(
                    c: fmi2Component,
                    _tolerance_defined: fmi2Boolean,
                    _tolerance: fmi2Real,
                    start: fmi2Real,
                    stop_defined: fmi2Boolean,
                    stop: fmi2Real,
                ) -> Status => functions::setup_experiment(c, start, stop_defined, stop);
                /// Parameters and start values may be set until fmi2ExitInitializationMode.
                fn fmi2EnterInitializationMode(c: fmi2Component) -> Status => functions::enter_initialization_mode(c);
                /// Validates the parameters and builds the model; a refusal names the parameter and the reason.
                fn fmi2ExitInitializationMode(c: fmi2Component) -> Status => functions::exit_initialization_mode(c);
                /// Ends the run; the outputs stay readable.
                fn fmi2Terminate(c: fmi2Component) -> Status => functions::terminate(c);
                /// Back to the state after fmi2Instantiate, the start values restored.
                fn fmi2Reset(c: fmi2Component) -> Status => functions::reset(c);
                /// Reads Real variables by value reference.
                fn fmi2GetReal(c: fmi2Component, vr: *const fmi2ValueReference, n: usize, value: *mut fmi2Real) -> Status => functions::get_real(c, vr, n, value);
                /// Reads Integer variables by value reference.
                fn fmi2GetInteger(
                    c: fmi2Component,
                    vr: *const fmi2ValueReference,
                    n: usize,
                    value: *mut fmi2Integer,
                ) -> Status => functions::get_integer(c, vr, n, value);
                /// Reads Boolean variables (the tables have none).
                fn fmi2GetBoolean(
                    c: fmi2Component,
                    vr: *const fmi2ValueReference,
                    n: usize,
                    value: *mut fmi2Boolean,
                ) -> Status => functions::get_boolean(c, vr, n, value);
                /// Reads String variables; the strings live until the next call on the instance.
                fn fmi2GetString(
                    c: fmi2Component,
                    vr: *const fmi2ValueReference,
                    n: usize,
                    value: *mut fmi2String,
                ) -> Status => functions::get_string(c, vr, n, value);
                /// Sets Real parameters (until initialization ends) or inputs.
                fn fmi2SetReal(
                    c: fmi2Component,
                    vr: *const fmi2ValueReference,
                    n: usize,
                    value: *const fmi2Real,
                ) -> Status => functions::set_real(c, vr, n, value);
                /// Sets Integer parameters.
                fn fmi2SetInteger(
                    c: fmi2Component,
                    vr: *const fmi2ValueReference,
                    n: usize,
                    value: *const fmi2Integer,
                ) -> Status => functions::set_integer(c, vr, n, value);
                /// Sets Boolean variables (the tables have none).
                fn fmi2SetBoolean(
                    c: fmi2Component,
                    vr: *const fmi2ValueReference,
                    n: usize,
                    value: *const fmi2Boolean,
                ) -> Status => functions::set_boolean(c, vr, n, value);
                /// Sets String parameters.
                fn fmi2SetString(
                    c: fmi2Component,
                    vr: *const fmi2ValueReference,
                    n: usize,
                    value: *const fmi2String,
                ) -> Status => functions::set_string(c, vr, n, value);
                /// Saves the whole state into a new or the given state handle.
                fn fmi2GetFMUstate(c: fmi2Component, state: *mut fmi2FMUstate) -> Status => functions::get_fmu_state(c, state);
                /// Restores a state saved by this FMU.
                fn fmi2SetFMUstate(c: fmi2Component, state: fmi2FMUstate) -> Status => functions::set_fmu_state(c, state);
                /// Frees a saved state and nulls the handle.
                fn fmi2FreeFMUstate(c: fmi2Component, state: *mut fmi2FMUstate) -> Status => functions::free_fmu_state(c, state);
                /// The byte size of a saved state's serialized form.
                fn fmi2SerializedFMUstateSize(
                    c: fmi2Component,
                    state: fmi2FMUstate,
                    size: *mut usize,
                ) -> Status => functions::serialized_fmu_state_size(c, state, size);
                /// Writes a saved state into the host's buffer (the layout is `state_bytes`').
                fn fmi2SerializeFMUstate(
                    c: fmi2Component,
                    state: fmi2FMUstate,
                    buffer: *mut fmi2Byte,
                    size: usize,
                ) -> Status => functions::serialize_fmu_state(c, state, buffer.cast(), size);
                /// A saved state from bytes; foreign, truncated or corrupted bytes are refused.
                fn fmi2DeSerializeFMUstate(
                    c: fmi2Component,
                    buffer: *const fmi2Byte,
                    size: usize,
                    state: *mut fmi2FMUstate,
                ) -> Status => functions::deserialize_fmu_state(c, buffer.cast(), size, state);
                /// Not provided (providesDirectionalDerivative is false).
                fn fmi2GetDirectionalDerivative(
                    c: fmi2Component,
                    _unknowns: *const fmi2ValueReference,
                    _n_unknowns: usize,
                    _knowns: *const fmi2ValueReference,
                    _n_knowns: usize,
                    _dv_known: *const fmi2Real,
                    _dv_unknown: *mut fmi2Real,
                ) -> Status => functions::get_directional_derivative(c);
                /// Time derivatives (order 1 or 2) of Real inputs at the start of the next step.
                fn fmi2SetRealInputDerivatives(
                    c: fmi2Component,
                    vr: *const fmi2ValueReference,
                    n: usize,
                    order: *const fmi2Integer,
                    value: *const fmi2Real,
                ) -> Status => functions::set_real_input_derivatives(c, vr, n, order, value);
                /// Time derivatives of Real outputs at the current time, where the model has them.
                fn fmi2GetRealOutputDerivatives(
                    c: fmi2Component,
                    vr: *const fmi2ValueReference,
                    n: usize,
                    order: *const fmi2Integer,
                    value: *mut fmi2Real,
                ) -> Status => functions::get_real_output_derivatives(c, vr, n, order, value);
                /// Advances from t by h; a failed step returns fmi2Error with the reason in the log.
                fn fmi2DoStep(c: fmi2Component, t: fmi2Real, h: fmi2Real, _no_set_prior: fmi2Boolean) -> Status => functions::do_step(c, t, h);
                /// Steps are synchronous: there is nothing to cancel.
                fn fmi2CancelStep(c: fmi2Component) -> Status => functions::cancel_step(c);
                /// Status of asynchronous stepping (steps are synchronous).
                fn fmi2GetStatus(c: fmi2Component, kind: c_int, value: *mut c_int) -> Status => functions::get_status(c, kind, value);
                /// fmi2LastSuccessfulTime: the time reached.
                fn fmi2GetRealStatus(c: fmi2Component, kind: c_int, value: *mut fmi2Real) -> Status => functions::get_real_status(c, kind, value);
                /// No Integer status is defined.
                fn fmi2GetIntegerStatus(c: fmi2Component, kind: c_int, value: *mut fmi2Integer) -> Status => functions::get_integer_status(c, kind, value);
                /// fmi2Terminated: false, the FMU never asks the host to stop.
                fn fmi2GetBooleanStatus(c: fmi2Component, kind: c_int, value: *mut fmi2Boolean) -> Status => functions::get_boolean_status(c, kind, value);
                /// No String status is defined.
                fn fmi2GetStringStatus(c: fmi2Component, kind: c_int, value: *mut fmi2String) -> Status => functions::get_string_status(c, kind, value);
            );

            $crate::fmi::fmi3_exports!($fmus);
        }
    };
    // The exported functions that only forward to their generic body for the instance's FMU, telling it which
    // function the host called (the state machine's entry of the same name): each has the host's FMI 2.0 or
    // FMI 3.0 calling contract, which is the contract of its body in `functions.rs` or `fmi3_functions.rs`.
    (@forward $fmus:tt $(
        $(#[$doc:meta])*
        fn $name:ident($c:ident: $c_ty:ty $(, $arg:ident: $ty:ty)* $(,)?) -> Status => $module:ident::$f:ident($($pass:expr),*);
    )*) => {$(
        $(#[$doc])*
        #[no_mangle]
        pub unsafe extern "C" fn $name($c: $c_ty $(, $arg: $ty)*) -> Status {
            // SAFETY: the host keeps the FMI calling contract, which is each body's contract.
            unsafe {
                let tag = $crate::fmi::functions::instance_tag($c);
                $crate::fmi::registry::by_tag!($fmus tag, M => $crate::fmi::$module::$f::<M>($crate::fmi::state_machine::Function::$name, $($pass),*))
            }
        }
    )*};
}
pub(crate) use exports;
