//! The C types of `fmi_headers/` on the Rust side: FMI 2.0's, then FMI 3.0's.
#![allow(non_camel_case_types)]

use std::ffi::{c_char, c_int, c_uint, c_void};

/// The instance handle given to the host by fmi2Instantiate.
pub type fmi2Component = *mut c_void;
/// The host's pointer passed back to its callbacks.
pub type fmi2ComponentEnvironment = *mut c_void;
/// A saved FMU state's handle (fmi2GetFMUstate).
pub type fmi2FMUstate = *mut c_void;
/// A variable's value reference: its position in the variable table.
pub type fmi2ValueReference = c_uint;
/// An FMI Real.
pub type fmi2Real = f64;
/// An FMI Integer.
pub type fmi2Integer = c_int;
/// An FMI Boolean: 0 false, anything else true.
pub type fmi2Boolean = c_int;
/// A NUL-terminated UTF-8 string owned by its giver.
pub type fmi2String = *const c_char;
/// A byte of a serialized FMU state.
pub type fmi2Byte = c_char;

/// fmi2True.
pub const FMI2_TRUE: fmi2Boolean = 1;
/// fmi2False.
pub const FMI2_FALSE: fmi2Boolean = 0;

/// fmi2Status. Only returned to C, never read from it, so a Rust enum is sound here.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// fmi2OK: done as asked.
    Ok = 0,
    /// fmi2Warning: done, with something the log explains.
    Warning = 1,
    /// fmi2Discard: the step was not completed; the instance stays usable.
    Discard = 2,
    /// fmi2Error: refused or failed; the instance needs a reset or a restored state.
    Error = 3,
    /// fmi2Fatal: no instance can be trusted any more.
    Fatal = 4,
    /// fmi2Pending: an asynchronous step is running (never returned: steps are synchronous).
    Pending = 5,
}

/// fmi2Type and fmi2StatusKind arrive from C as plain ints: a Rust enum with an out-of-range value
/// would be undefined behaviour.
/// fmi2CoSimulation, the only fmi2Type instantiated.
pub const FMI2_CO_SIMULATION: c_int = 1;
/// fmi2DoStepStatus.
pub const FMI2_DO_STEP_STATUS: c_int = 0;
/// fmi2PendingStatus.
pub const FMI2_PENDING_STATUS: c_int = 1;
/// fmi2LastSuccessfulTime.
pub const FMI2_LAST_SUCCESSFUL_TIME: c_int = 2;
/// fmi2Terminated.
pub const FMI2_TERMINATED: c_int = 3;

/// The host's logger: its environment, the instance name, the status, the log category and a printf format.
pub type fmi2CallbackLogger = unsafe extern "C" fn(
    env: fmi2ComponentEnvironment,
    instance_name: fmi2String,
    status: c_int,
    category: fmi2String,
    message: fmi2String,
    ...
);

/// The host's callbacks given to fmi2Instantiate.
#[repr(C)]
pub struct fmi2CallbackFunctions {
    /// Where messages go; none silences the instance.
    pub logger: Option<fmi2CallbackLogger>,
    /// calloc-like allocator (FMI 2.0 requires it; the FMU allocates with Rust's own allocator).
    pub allocate_memory: Option<unsafe extern "C" fn(usize, usize) -> *mut c_void>,
    /// Frees what `allocate_memory` gave.
    pub free_memory: Option<unsafe extern "C" fn(*mut c_void)>,
    /// Asynchronous step completion (unused: steps are synchronous).
    pub step_finished: Option<unsafe extern "C" fn(fmi2ComponentEnvironment, c_int)>,
    /// Passed back to `logger` and `step_finished`.
    pub component_environment: fmi2ComponentEnvironment,
}

/// The instance handle given to the host by fmi3InstantiateCoSimulation.
pub type fmi3Instance = *mut c_void;
/// The host's pointer passed back to its callbacks.
pub type fmi3InstanceEnvironment = *mut c_void;
/// A saved FMU state's handle (fmi3GetFMUState).
pub type fmi3FMUState = *mut c_void;
/// A variable's value reference.
pub type fmi3ValueReference = c_uint;
/// An FMI 3.0 Float64.
pub type fmi3Float64 = f64;
/// An FMI 3.0 Float32 (the tables have none).
pub type fmi3Float32 = f32;
/// An FMI 3.0 Int32.
pub type fmi3Int32 = i32;
/// An FMI 3.0 Int8 (the tables have none).
pub type fmi3Int8 = i8;
/// An FMI 3.0 UInt8 (the tables have none).
pub type fmi3UInt8 = u8;
/// An FMI 3.0 Int16 (the tables have none).
pub type fmi3Int16 = i16;
/// An FMI 3.0 UInt16 (the tables have none).
pub type fmi3UInt16 = u16;
/// An FMI 3.0 UInt32 (the tables have none).
pub type fmi3UInt32 = u32;
/// An FMI 3.0 Int64 (the tables have none).
pub type fmi3Int64 = i64;
/// An FMI 3.0 UInt64 (the tables have none).
pub type fmi3UInt64 = u64;
/// C's `bool`, read as a byte (0 false, anything else true): no byte from C is an invalid Rust value.
pub type fmi3Boolean = u8;
/// An FMI 3.0 Clock: a `bool`, as `fmi3Boolean`.
pub type fmi3Clock = u8;
/// A NUL-terminated UTF-8 string owned by its giver.
pub type fmi3String = *const c_char;
/// A byte of a serialized FMU state or of a Binary.
pub type fmi3Byte = u8;
/// A Binary variable's value: its bytes.
pub type fmi3Binary = *const fmi3Byte;
/// fmi3IntervalQualifier, an enum read as an int.
pub type fmi3IntervalQualifier = c_int;
/// fmi3DependencyKind, an enum read as an int.
pub type fmi3DependencyKind = c_int;

/// fmi3True as this layer writes it.
pub const FMI3_TRUE: fmi3Boolean = 1;
/// fmi3False.
pub const FMI3_FALSE: fmi3Boolean = 0;

/// The host's logger: its environment, the status, the log category and the message (no format).
pub type fmi3LogMessageCallback =
    unsafe extern "C" fn(env: fmi3InstanceEnvironment, status: c_int, category: fmi3String, message: fmi3String);

/// The host's intermediate-update callback (never called: providesIntermediateUpdate is false).
pub type fmi3IntermediateUpdateCallback = unsafe extern "C" fn(
    env: fmi3InstanceEnvironment,
    intermediate_update_time: fmi3Float64,
    intermediate_variable_set_requested: fmi3Boolean,
    intermediate_variable_get_allowed: fmi3Boolean,
    intermediate_step_finished: fmi3Boolean,
    can_return_early: fmi3Boolean,
    early_return_requested: *mut fmi3Boolean,
    early_return_time: *mut fmi3Float64,
);

/// Scheduled Execution's callbacks (never called: the FMU has no Scheduled Execution interface).
pub type fmi3ClockUpdateCallback = unsafe extern "C" fn(env: fmi3InstanceEnvironment);
/// See [`fmi3ClockUpdateCallback`].
pub type fmi3LockPreemptionCallback = unsafe extern "C" fn();
