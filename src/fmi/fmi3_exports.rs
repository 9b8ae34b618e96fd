//! The exported C symbols of FMI 3.0 (`fmi_headers/fmi3Functions.h`), written beside the fmi2 ones into the
//! same module by [`super::exports!`]: every function of the standard, since hosts bind them all. Co-Simulation
//! runs through the bodies the fmi2 functions use (`functions.rs`) or, where the arguments differ,
//! `fmi3_functions.rs`; what the model descriptions declare absent (Event Mode, Configuration Mode, clocks,
//! dependencies, derivatives, Model Exchange, Scheduled Execution) is refused with the reason.

/// `fmi3_exports!([fmu types…])`: the fmi3 symbols, at the invoking module.
macro_rules! fmi3_exports {
    ($fmus:tt) => {
        /// "3.0".
        #[no_mangle]
        pub unsafe extern "C" fn fmi3GetVersion() -> *const c_char {
            c"3.0".as_ptr()
        }

        /// A new Co-Simulation instance of the FMU whose instantiation token is given (its GUID), or null
        /// (a stamped copy refuses a foreign token). Event Mode and intermediate variables are refused; early
        /// return is never taken.
        #[no_mangle]
        pub unsafe extern "C" fn fmi3InstantiateCoSimulation(
            name: fmi3String,
            token: fmi3String,
            resource_path: fmi3String,
            _visible: fmi3Boolean,
            logging_on: fmi3Boolean,
            event_mode_used: fmi3Boolean,
            _early_return_allowed: fmi3Boolean,
            _required_intermediate_variables: *const fmi3ValueReference,
            n_required_intermediate_variables: usize,
            environment: fmi3InstanceEnvironment,
            log_message: Option<fmi3LogMessageCallback>,
            _intermediate_update: Option<fmi3IntermediateUpdateCallback>,
        ) -> fmi3Instance {
            // SAFETY: the host keeps the FMI 3.0 calling contract, which is the body's contract.
            unsafe {
                let stamp = $crate::fmi::identity::stamped();
                let stamp = stamp.as_deref();
                $crate::fmi::registry::by_identity!(
                    $fmus stamp, token, M => $crate::fmi::fmi3_functions::instantiate_co_simulation::<M>(
                        name, token, resource_path, logging_on, event_mode_used, n_required_intermediate_variables, environment, log_message
                    )
                )
            }
        }

        /// Null: the FMUs implement Co-Simulation only.
        #[no_mangle]
        pub unsafe extern "C" fn fmi3InstantiateModelExchange(
            _name: fmi3String,
            _token: fmi3String,
            _resource_path: fmi3String,
            _visible: fmi3Boolean,
            _logging_on: fmi3Boolean,
            environment: fmi3InstanceEnvironment,
            log_message: Option<fmi3LogMessageCallback>,
        ) -> fmi3Instance {
            // SAFETY: the host's logger and environment (the FMI 3.0 calling contract).
            unsafe { $crate::fmi::fmi3_functions::instantiate_other("fmi3InstantiateModelExchange", environment, log_message) }
        }

        /// Null: the FMUs implement Co-Simulation only.
        #[no_mangle]
        pub unsafe extern "C" fn fmi3InstantiateScheduledExecution(
            _name: fmi3String,
            _token: fmi3String,
            _resource_path: fmi3String,
            _visible: fmi3Boolean,
            _logging_on: fmi3Boolean,
            environment: fmi3InstanceEnvironment,
            log_message: Option<fmi3LogMessageCallback>,
            _clock_update: Option<fmi3ClockUpdateCallback>,
            _lock_preemption: Option<fmi3LockPreemptionCallback>,
            _unlock_preemption: Option<fmi3LockPreemptionCallback>,
        ) -> fmi3Instance {
            // SAFETY: the host's logger and environment (the FMI 3.0 calling contract).
            unsafe { $crate::fmi::fmi3_functions::instantiate_other("fmi3InstantiateScheduledExecution", environment, log_message) }
        }

        /// Frees the instance and everything it holds.
        #[no_mangle]
        pub unsafe extern "C" fn fmi3FreeInstance(c: fmi3Instance) {
            // SAFETY: the host keeps the FMI 3.0 calling contract, which is the body's contract.
            unsafe {
                let tag = $crate::fmi::functions::instance_tag(c);
                $crate::fmi::registry::by_tag!($fmus tag, M => $crate::fmi::functions::free_instance::<M>(c))
            }
        }

        $crate::fmi::exports!(@forward $fmus
            /// Switches logging on or off, for all categories or the ones listed.
            fn fmi3SetDebugLogging(c: fmi3Instance, on: fmi3Boolean, n: usize, categories: *const fmi3String) -> Status
                => functions::set_debug_logging(c, on.into(), n, categories);
            /// Start time and optional stop time (the tolerance is not used: steps are event-exact); parameters
            /// may then be set until fmi3ExitInitializationMode.
            fn fmi3EnterInitializationMode(
                c: fmi3Instance,
                _tolerance_defined: fmi3Boolean,
                _tolerance: fmi3Float64,
                start: fmi3Float64,
                stop_defined: fmi3Boolean,
                stop: fmi3Float64,
            ) -> Status => fmi3_functions::enter_initialization_mode(c, start, stop_defined, stop);
            /// Validates the parameters and builds the model; the instance is then in Step Mode.
            fn fmi3ExitInitializationMode(c: fmi3Instance) -> Status => functions::exit_initialization_mode(c);
            /// Ends the run; the outputs stay readable.
            fn fmi3Terminate(c: fmi3Instance) -> Status => functions::terminate(c);
            /// Back to the state after instantiation, the start values restored.
            fn fmi3Reset(c: fmi3Instance) -> Status => functions::reset(c);
            /// Reads Float64 variables and the independent variable time.
            fn fmi3GetFloat64(c: fmi3Instance, vr: *const fmi3ValueReference, n: usize, value: *mut fmi3Float64, n_values: usize) -> Status
                => fmi3_functions::get_float64(c, vr, n, value, n_values);
            /// Reads Int32 variables.
            fn fmi3GetInt32(c: fmi3Instance, vr: *const fmi3ValueReference, n: usize, value: *mut fmi3Int32, n_values: usize) -> Status
                => fmi3_functions::get_int32(c, vr, n, value, n_values);
            /// Reads String variables; the strings live until the next call on the instance.
            fn fmi3GetString(c: fmi3Instance, vr: *const fmi3ValueReference, n: usize, value: *mut fmi3String, n_values: usize) -> Status
                => fmi3_functions::get_string(c, vr, n, value, n_values);
            /// Sets Float64 parameters (until initialization ends) or inputs.
            fn fmi3SetFloat64(c: fmi3Instance, vr: *const fmi3ValueReference, n: usize, value: *const fmi3Float64, n_values: usize) -> Status
                => fmi3_functions::set_float64(c, vr, n, value, n_values);
            /// Sets Int32 parameters.
            fn fmi3SetInt32(c: fmi3Instance, vr: *const fmi3ValueReference, n: usize, value: *const fmi3Int32, n_values: usize) -> Status
                => fmi3_functions::set_int32(c, vr, n, value, n_values);
            /// Sets String parameters.
            fn fmi3SetString(c: fmi3Instance, vr: *const fmi3ValueReference, n: usize, value: *const fmi3String, n_values: usize) -> Status
                => fmi3_functions::set_string(c, vr, n, value, n_values);
            /// Saves the whole state into a new or the given state handle.
            fn fmi3GetFMUState(c: fmi3Instance, state: *mut fmi3FMUState) -> Status => functions::get_fmu_state(c, state);
            /// Restores a state saved by this FMU.
            fn fmi3SetFMUState(c: fmi3Instance, state: fmi3FMUState) -> Status => functions::set_fmu_state(c, state);
            /// Frees a saved state and nulls the handle.
            fn fmi3FreeFMUState(c: fmi3Instance, state: *mut fmi3FMUState) -> Status => functions::free_fmu_state(c, state);
            /// The byte size of a saved state's serialized form.
            fn fmi3SerializedFMUStateSize(c: fmi3Instance, state: fmi3FMUState, size: *mut usize) -> Status
                => functions::serialized_fmu_state_size(c, state, size);
            /// Writes a saved state into the host's buffer (the bytes of FMI 2.0's fmi2SerializeFMUstate).
            fn fmi3SerializeFMUState(c: fmi3Instance, state: fmi3FMUState, buffer: *mut fmi3Byte, size: usize) -> Status
                => functions::serialize_fmu_state(c, state, buffer, size);
            /// A saved state from bytes; foreign, truncated or corrupted bytes are refused.
            fn fmi3DeserializeFMUState(c: fmi3Instance, buffer: *const fmi3Byte, size: usize, state: *mut fmi3FMUState) -> Status
                => functions::deserialize_fmu_state(c, buffer, size, state);
            /// Time derivatives of Float64 outputs at the current time, where the model has them.
            fn fmi3GetOutputDerivatives(
                c: fmi3Instance,
                vr: *const fmi3ValueReference,
                n: usize,
                order: *const fmi3Int32,
                value: *mut fmi3Float64,
                n_values: usize,
            ) -> Status => fmi3_functions::get_output_derivatives(c, vr, n, order, value, n_values);
            /// Advances from t by h, always to t + h; a failed step returns fmi3Error with the reason in the log.
            fn fmi3DoStep(
                c: fmi3Instance,
                t: fmi3Float64,
                h: fmi3Float64,
                _no_set_prior: fmi3Boolean,
                event_handling_needed: *mut fmi3Boolean,
                terminate_simulation: *mut fmi3Boolean,
                early_return: *mut fmi3Boolean,
                last_successful_time: *mut fmi3Float64,
            ) -> Status => fmi3_functions::do_step(c, t, h, event_handling_needed, terminate_simulation, early_return, last_successful_time);
        );

        $crate::fmi::fmi3_exports!(@absent $fmus
            fmi3GetFloat32(_value: *mut fmi3Float32) "Float32";
            fmi3GetInt8(_value: *mut fmi3Int8) "Int8";
            fmi3GetUInt8(_value: *mut fmi3UInt8) "UInt8";
            fmi3GetInt16(_value: *mut fmi3Int16) "Int16";
            fmi3GetUInt16(_value: *mut fmi3UInt16) "UInt16";
            fmi3GetUInt32(_value: *mut fmi3UInt32) "UInt32";
            fmi3GetInt64(_value: *mut fmi3Int64) "Int64";
            fmi3GetUInt64(_value: *mut fmi3UInt64) "UInt64";
            fmi3GetBoolean(_value: *mut fmi3Boolean) "Boolean";
            fmi3SetFloat32(_value: *const fmi3Float32) "Float32";
            fmi3SetInt8(_value: *const fmi3Int8) "Int8";
            fmi3SetUInt8(_value: *const fmi3UInt8) "UInt8";
            fmi3SetInt16(_value: *const fmi3Int16) "Int16";
            fmi3SetUInt16(_value: *const fmi3UInt16) "UInt16";
            fmi3SetUInt32(_value: *const fmi3UInt32) "UInt32";
            fmi3SetInt64(_value: *const fmi3Int64) "Int64";
            fmi3SetUInt64(_value: *const fmi3UInt64) "UInt64";
            fmi3SetBoolean(_value: *const fmi3Boolean) "Boolean";
        );

        $crate::fmi::exports!(@forward $fmus
            /// The tables have no Binary variable: any value reference is refused.
            fn fmi3GetBinary(c: fmi3Instance, vr: *const fmi3ValueReference, n: usize, _sizes: *mut usize, _value: *mut fmi3Binary, _n_values: usize) -> Status
                => fmi3_functions::none_of_kind(c, vr, n, "Binary");
            /// The tables have no Binary variable: any value reference is refused.
            fn fmi3SetBinary(c: fmi3Instance, vr: *const fmi3ValueReference, n: usize, _sizes: *const usize, _value: *const fmi3Binary, _n_values: usize) -> Status
                => fmi3_functions::none_of_kind(c, vr, n, "Binary");
            /// The tables have no Clock: any value reference is refused.
            fn fmi3GetClock(c: fmi3Instance, vr: *const fmi3ValueReference, n: usize, _value: *mut fmi3Clock) -> Status
                => fmi3_functions::none_of_kind(c, vr, n, "Clock");
            /// The tables have no Clock: any value reference is refused.
            fn fmi3SetClock(c: fmi3Instance, vr: *const fmi3ValueReference, n: usize, _value: *const fmi3Clock) -> Status
                => fmi3_functions::none_of_kind(c, vr, n, "Clock");
        );

        $crate::fmi::exports!(@forward $fmus
            /// Not provided (hasEventMode = false).
            fn fmi3EnterEventMode(c: fmi3Instance) -> Status => functions::refuse(c, "no Event Mode (hasEventMode = false)");
            /// Not provided (hasEventMode = false): fmi3ExitInitializationMode enters Step Mode.
            fn fmi3EnterStepMode(c: fmi3Instance) -> Status
                => functions::refuse(c, "no Event Mode to leave (hasEventMode = false): fmi3ExitInitializationMode enters Step Mode");
            /// Not provided (hasEventMode = false).
            fn fmi3UpdateDiscreteStates(
                c: fmi3Instance,
                _discrete_states_need_update: *mut fmi3Boolean,
                _terminate_simulation: *mut fmi3Boolean,
                _nominals_changed: *mut fmi3Boolean,
                _values_changed: *mut fmi3Boolean,
                _next_event_time_defined: *mut fmi3Boolean,
                _next_event_time: *mut fmi3Float64,
            ) -> Status => functions::refuse(c, "no Event Mode (hasEventMode = false)");
            /// Not provided: the FMUs have no clocks.
            fn fmi3EvaluateDiscreteStates(c: fmi3Instance) -> Status => functions::refuse(c, "no clocks");
            /// Not provided: the FMUs have no structural parameters.
            fn fmi3EnterConfigurationMode(c: fmi3Instance) -> Status => functions::refuse(c, "no structural parameters");
            /// Not provided: the FMUs have no structural parameters.
            fn fmi3ExitConfigurationMode(c: fmi3Instance) -> Status => functions::refuse(c, "no structural parameters");
            /// Not provided: the dependencies are in the model description's ModelStructure.
            fn fmi3GetNumberOfVariableDependencies(c: fmi3Instance, _vr: fmi3ValueReference, _n: *mut usize) -> Status
                => functions::refuse(c, "not provided: the dependencies are in modelDescription.xml");
            /// Not provided: the dependencies are in the model description's ModelStructure.
            fn fmi3GetVariableDependencies(
                c: fmi3Instance,
                _dependent: fmi3ValueReference,
                _element_indices_of_dependent: *mut usize,
                _independents: *mut fmi3ValueReference,
                _element_indices_of_independents: *mut usize,
                _kinds: *mut fmi3DependencyKind,
                _n: usize,
            ) -> Status => functions::refuse(c, "not provided: the dependencies are in modelDescription.xml");
            /// Not provided (providesDirectionalDerivatives = false).
            fn fmi3GetDirectionalDerivative(
                c: fmi3Instance,
                _unknowns: *const fmi3ValueReference,
                _n_unknowns: usize,
                _knowns: *const fmi3ValueReference,
                _n_knowns: usize,
                _seed: *const fmi3Float64,
                _n_seed: usize,
                _sensitivity: *mut fmi3Float64,
                _n_sensitivity: usize,
            ) -> Status => functions::refuse(c, "not provided (providesDirectionalDerivatives = false)");
            /// Not provided (providesAdjointDerivatives = false).
            fn fmi3GetAdjointDerivative(
                c: fmi3Instance,
                _unknowns: *const fmi3ValueReference,
                _n_unknowns: usize,
                _knowns: *const fmi3ValueReference,
                _n_knowns: usize,
                _seed: *const fmi3Float64,
                _n_seed: usize,
                _sensitivity: *mut fmi3Float64,
                _n_sensitivity: usize,
            ) -> Status => functions::refuse(c, "not provided (providesAdjointDerivatives = false)");
            /// Not provided: the FMUs have no clocks.
            fn fmi3GetIntervalDecimal(c: fmi3Instance, _vr: *const fmi3ValueReference, _n: usize, _intervals: *mut fmi3Float64, _qualifiers: *mut fmi3IntervalQualifier) -> Status
                => functions::refuse(c, "no clocks");
            /// Not provided: the FMUs have no clocks.
            fn fmi3GetIntervalFraction(
                c: fmi3Instance,
                _vr: *const fmi3ValueReference,
                _n: usize,
                _counters: *mut fmi3UInt64,
                _resolutions: *mut fmi3UInt64,
                _qualifiers: *mut fmi3IntervalQualifier,
            ) -> Status => functions::refuse(c, "no clocks");
            /// Not provided: the FMUs have no clocks.
            fn fmi3GetShiftDecimal(c: fmi3Instance, _vr: *const fmi3ValueReference, _n: usize, _shifts: *mut fmi3Float64) -> Status
                => functions::refuse(c, "no clocks");
            /// Not provided: the FMUs have no clocks.
            fn fmi3GetShiftFraction(c: fmi3Instance, _vr: *const fmi3ValueReference, _n: usize, _counters: *mut fmi3UInt64, _resolutions: *mut fmi3UInt64) -> Status
                => functions::refuse(c, "no clocks");
            /// Not provided: the FMUs have no clocks.
            fn fmi3SetIntervalDecimal(c: fmi3Instance, _vr: *const fmi3ValueReference, _n: usize, _intervals: *const fmi3Float64) -> Status
                => functions::refuse(c, "no clocks");
            /// Not provided: the FMUs have no clocks.
            fn fmi3SetIntervalFraction(c: fmi3Instance, _vr: *const fmi3ValueReference, _n: usize, _counters: *const fmi3UInt64, _resolutions: *const fmi3UInt64) -> Status
                => functions::refuse(c, "no clocks");
            /// Not provided: the FMUs have no clocks.
            fn fmi3SetShiftDecimal(c: fmi3Instance, _vr: *const fmi3ValueReference, _n: usize, _shifts: *const fmi3Float64) -> Status
                => functions::refuse(c, "no clocks");
            /// Not provided: the FMUs have no clocks.
            fn fmi3SetShiftFraction(c: fmi3Instance, _vr: *const fmi3ValueReference, _n: usize, _counters: *const fmi3UInt64, _resolutions: *const fmi3UInt64) -> Status
                => functions::refuse(c, "no clocks");
            /// Model Exchange only.
            fn fmi3EnterContinuousTimeMode(c: fmi3Instance) -> Status => functions::refuse(c, "Model Exchange only");
            /// Model Exchange only.
            fn fmi3CompletedIntegratorStep(c: fmi3Instance, _no_set_prior: fmi3Boolean, _enter_event_mode: *mut fmi3Boolean, _terminate_simulation: *mut fmi3Boolean) -> Status
                => functions::refuse(c, "Model Exchange only");
            /// Model Exchange only.
            fn fmi3SetTime(c: fmi3Instance, _time: fmi3Float64) -> Status => functions::refuse(c, "Model Exchange only");
            /// Model Exchange only.
            fn fmi3SetContinuousStates(c: fmi3Instance, _x: *const fmi3Float64, _n: usize) -> Status => functions::refuse(c, "Model Exchange only");
            /// Model Exchange only.
            fn fmi3GetContinuousStateDerivatives(c: fmi3Instance, _dx: *mut fmi3Float64, _n: usize) -> Status => functions::refuse(c, "Model Exchange only");
            /// Model Exchange only.
            fn fmi3GetEventIndicators(c: fmi3Instance, _z: *mut fmi3Float64, _n: usize) -> Status => functions::refuse(c, "Model Exchange only");
            /// Model Exchange only.
            fn fmi3GetContinuousStates(c: fmi3Instance, _x: *mut fmi3Float64, _n: usize) -> Status => functions::refuse(c, "Model Exchange only");
            /// Model Exchange only.
            fn fmi3GetNominalsOfContinuousStates(c: fmi3Instance, _nominals: *mut fmi3Float64, _n: usize) -> Status
                => functions::refuse(c, "Model Exchange only");
            /// Model Exchange only.
            fn fmi3GetNumberOfEventIndicators(c: fmi3Instance, _n: *mut usize) -> Status => functions::refuse(c, "Model Exchange only");
            /// Model Exchange only.
            fn fmi3GetNumberOfContinuousStates(c: fmi3Instance, _n: *mut usize) -> Status => functions::refuse(c, "Model Exchange only");
            /// Scheduled Execution only.
            fn fmi3ActivateModelPartition(c: fmi3Instance, _clock: fmi3ValueReference, _activation_time: fmi3Float64) -> Status
                => functions::refuse(c, "Scheduled Execution only");
        );
    };
    // The getters and setters of the types no table has: `name(value pointer) "type"`.
    (@absent $fmus:tt $($name:ident($value:ident: $ty:ty) $kind:literal;)*) => {
        $crate::fmi::exports!(@forward $fmus $(
            #[doc = concat!("The tables have no ", $kind, " variable: any value reference is refused.")]
            fn $name(c: fmi3Instance, vr: *const fmi3ValueReference, n: usize, $value: $ty, _n_values: usize) -> Status
                => fmi3_functions::none_of_kind(c, vr, n, $kind);
        )*);
    };
}
pub(crate) use fmi3_exports;
