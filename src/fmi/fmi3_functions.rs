//! The fmi3 functions whose arguments differ from their fmi2 twins': instantiation (a resource path, FMI 3.0's
//! logger, Event Mode and intermediate variables refused), the experiment given at
//! fmi3EnterInitializationMode, the values' count beside the value references (every variable is a scalar,
//! so the two counts must agree), the independent variable `time`, and fmi3DoStep's flags. Everything else
//! an fmi3 symbol does is its fmi2 twin's body in `functions.rs`.
#![allow(unsafe_code)]

use super::description::Kind;
use super::functions::{self, check_guid, make, run};
use super::instance::{Model, Outcome, Refusal};
use super::logger::Logger;
use super::pointers::{out, slice, slice_mut, string};
use super::state_machine::Function;
use super::types::*;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::PathBuf;

fn boolean(b: fmi3Boolean) -> bool {
    b != FMI3_FALSE
}

/// Every variable is a scalar: as many values as value references.
fn scalars(n_value_references: usize, n_values: usize) -> Outcome {
    if n_value_references == n_values {
        return Ok(());
    }
    Err(Refusal::error(format!("nValues = {n_values} for {n_value_references} value references: every variable is a scalar")))
}

/// Runs `f` once the counts passed [`scalars`].
///
/// # Safety
/// As `functions::call`.
unsafe fn with_scalars<E: Model>(function: Function, c: fmi3Instance, counts: (usize, usize), f: impl FnOnce() -> Status) -> Status {
    match scalars(counts.0, counts.1) {
        Ok(()) => f(),
        // SAFETY: the caller's contract.
        Err(refusal) => unsafe { run::<E>(c, function, |_| Err(refusal)) },
    }
}

/// # Safety
/// The pointers are NULL or valid as fmi3InstantiateCoSimulation's arguments (NUL-terminated strings, a
/// logger that may be called with `environment`).
#[allow(clippy::too_many_arguments)]
pub unsafe fn instantiate_co_simulation<E: Model>(
    name: fmi3String,
    token: fmi3String,
    resource_path: fmi3String,
    logging_on: fmi3Boolean,
    event_mode_used: fmi3Boolean,
    n_required_intermediate_variables: usize,
    environment: fmi3InstanceEnvironment,
    log_message: Option<fmi3LogMessageCallback>,
) -> fmi3Instance {
    let made = catch_unwind(AssertUnwindSafe(|| {
        let logger = Logger::fmi3(log_message, environment, boolean(logging_on));
        let check = || -> Outcome<Option<PathBuf>> {
            // SAFETY: the strings are NULL or NUL-terminated (the contract).
            let (name, token) = unsafe { (string(name, "instanceName")?, string(token, "instantiationToken")?) };
            if name.is_empty() {
                return Err(Refusal::error("instanceName is empty"));
            }
            check_guid::<E>(token, "instantiationToken")?;
            if boolean(event_mode_used) {
                return Err(Refusal::error(format!("eventModeUsed = true refused: {} has no Event Mode (hasEventMode = false)", E::NAME)));
            }
            if n_required_intermediate_variables > 0 {
                return Err(Refusal::error(format!(
                    "{n_required_intermediate_variables} requiredIntermediateVariables refused: {} provides no intermediate update",
                    E::NAME
                )));
            }
            if resource_path.is_null() {
                return Ok(None);
            }
            // SAFETY: NUL-terminated (the contract).
            let path = unsafe { string(resource_path, "resourcePath")? };
            Ok((!path.is_empty()).then(|| PathBuf::from(path)))
        };
        make::<E>("fmi3InstantiateCoSimulation", logger, check())
    }));
    made.unwrap_or(std::ptr::null_mut())
}

/// fmi3InstantiateModelExchange and fmi3InstantiateScheduledExecution (`function`): NULL, with the reason
/// logged.
///
/// # Safety
/// `log_message` is None or may be called with `environment`.
pub unsafe fn instantiate_other(
    function: &str,
    environment: fmi3InstanceEnvironment,
    log_message: Option<fmi3LogMessageCallback>,
) -> fmi3Instance {
    let message = format!("{function}: refused: the FMU implements Co-Simulation only (fmi3InstantiateCoSimulation)");
    let _ = catch_unwind(AssertUnwindSafe(|| Logger::fmi3(log_message, environment, true).status(Status::Error, &message)));
    std::ptr::null_mut()
}

/// # Safety
/// As `functions::call`.
pub unsafe fn enter_initialization_mode<E: Model>(
    function: Function,
    c: fmi3Instance,
    start: fmi3Float64,
    stop_defined: fmi3Boolean,
    stop: fmi3Float64,
) -> Status {
    // The tolerance is not used: the integrator's accuracy is fixed by its step and event tolerances.
    // SAFETY: the caller's contract.
    unsafe {
        run::<E>(c, function, |comp| {
            comp.instance.setup_experiment(start, boolean(stop_defined).then_some(stop))?;
            comp.instance.enter_initialization_mode()
        })
    }
}

/// fmi3GetFloat64: the table's Float64 variables and the independent variable `time`.
///
/// # Safety
/// As `functions::call`; `vr` and `value` are NULL or point to `n` and `n_values` elements.
pub unsafe fn get_float64<E: Model>(
    function: Function,
    c: fmi3Instance,
    vr: *const fmi3ValueReference,
    n: usize,
    value: *mut fmi3Float64,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        run::<E>(c, function, |comp| {
            scalars(n, n_values)?;
            let (vrs, values) = (slice(vr, n, "valueReferences")?, slice_mut(value, n, "values")?);
            let (time, now) = (E::DESCRIPTION.time_value_reference(), comp.instance.time());
            let read = |vr, p: &E::Parameters, i: &E::Inputs, o: &E::Outputs| {
                if vr == time {
                    Some(now)
                } else {
                    (E::DESCRIPTION.get_real)(vr, p, i, o)
                }
            };
            comp.instance.get(vrs, Kind::Real, read, values, Some(time))
        })
    }
}

/// # Safety
/// As [`get_float64`].
pub unsafe fn get_int32<E: Model>(
    function: Function,
    c: fmi3Instance,
    vr: *const fmi3ValueReference,
    n: usize,
    value: *mut fmi3Int32,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe { with_scalars::<E>(function, c, (n, n_values), || functions::get_integer::<E>(function, c, vr, n, value)) }
}

/// # Safety
/// As [`get_float64`].
pub unsafe fn get_string<E: Model>(
    function: Function,
    c: fmi3Instance,
    vr: *const fmi3ValueReference,
    n: usize,
    value: *mut fmi3String,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe { with_scalars::<E>(function, c, (n, n_values), || functions::get_string::<E>(function, c, vr, n, value)) }
}

/// # Safety
/// As [`get_float64`], `value` read.
pub unsafe fn set_float64<E: Model>(
    function: Function,
    c: fmi3Instance,
    vr: *const fmi3ValueReference,
    n: usize,
    value: *const fmi3Float64,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe { with_scalars::<E>(function, c, (n, n_values), || functions::set_real::<E>(function, c, vr, n, value)) }
}

/// # Safety
/// As [`get_float64`], `value` read.
pub unsafe fn set_int32<E: Model>(
    function: Function,
    c: fmi3Instance,
    vr: *const fmi3ValueReference,
    n: usize,
    value: *const fmi3Int32,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe { with_scalars::<E>(function, c, (n, n_values), || functions::set_integer::<E>(function, c, vr, n, value)) }
}

/// # Safety
/// As [`get_float64`], `value` read, each string NULL or NUL-terminated.
pub unsafe fn set_string<E: Model>(
    function: Function,
    c: fmi3Instance,
    vr: *const fmi3ValueReference,
    n: usize,
    value: *const fmi3String,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe { with_scalars::<E>(function, c, (n, n_values), || functions::set_string::<E>(function, c, vr, n, value)) }
}

/// The getters and setters of the types no table has (`kind`): any value reference refused.
///
/// # Safety
/// As `functions::call`; `vr` is NULL or points to `n` elements.
pub unsafe fn none_of_kind<E: Model>(function: Function, c: fmi3Instance, vr: *const fmi3ValueReference, n: usize, kind: &str) -> Status {
    // SAFETY: the caller's contract.
    unsafe { run::<E>(c, function, |comp| comp.instance.none_of_kind(slice(vr, n, "valueReferences")?, kind)) }
}

/// # Safety
/// As `functions::call`; `vr` and `order` are NULL or point to `n` elements, `value` to `n_values`.
pub unsafe fn get_output_derivatives<E: Model>(
    function: Function,
    c: fmi3Instance,
    vr: *const fmi3ValueReference,
    n: usize,
    order: *const fmi3Int32,
    value: *mut fmi3Float64,
    n_values: usize,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        with_scalars::<E>(function, c, (n, n_values), || functions::get_real_output_derivatives::<E>(function, c, vr, n, order, value))
    }
}

/// fmi3DoStep: FMI 2.0's step, then its flags. The step always reaches `t + h` (no early return), raises
/// no event for the host and never asks it to stop.
///
/// # Safety
/// As `functions::call`; the flags' pointers NULL or writable.
#[allow(clippy::too_many_arguments)]
pub unsafe fn do_step<E: Model>(
    function: Function,
    c: fmi3Instance,
    t: fmi3Float64,
    h: fmi3Float64,
    event_handling_needed: *mut fmi3Boolean,
    terminate_simulation: *mut fmi3Boolean,
    early_return: *mut fmi3Boolean,
    last_successful_time: *mut fmi3Float64,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        run::<E>(c, function, |comp| {
            let event = out(event_handling_needed, "eventHandlingNeeded")?;
            let terminate = out(terminate_simulation, "terminateSimulation")?;
            let early = out(early_return, "earlyReturn")?;
            let last = out(last_successful_time, "lastSuccessfulTime")?;
            comp.instance.do_step(t, h)?;
            (*event, *terminate, *early, *last) = (FMI3_FALSE, FMI3_FALSE, FMI3_FALSE, comp.instance.time());
            Ok(())
        })
    }
}
