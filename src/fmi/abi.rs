//! The C side of every fmi2* function, generic over the engine model so that tests drive the same
//! pointer handling with a test model; `exports.rs` instantiates it with the shipped `Engine`.
//!
//! Each function turns pointers into Rust values (a NULL where data is needed is refused), runs the
//! instance's safe logic inside `catch_unwind` (a panic is logged and returns fmi2Fatal), and logs
//! every refusal through the host's logger.

use super::description::GUID;
use super::description::{self, Kind};
use super::instance::{
    Core, Instance, Model, Outcome, Refusal, Value, GET, INPUT_DERIVATIVES, OUTPUT_DERIVATIVES,
    SET, STATE, STATUS,
};
use super::logger::Logger;
use super::reentry::Entered;
use super::sibling;
use super::types::*;
use crate::models::{Inputs, Outputs, Parameters};
use std::any::Any;
use std::ffi::{c_int, CStr, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Marks live instances and FMU states: a pointer that is not one of ours (or already freed, as far as
/// its memory still says so) is refused instead of used.
const INSTANCE_TAG: u64 = u64::from_le_bytes(*b"PSLAPINS");
const STATE_TAG: u64 = u64::from_le_bytes(*b"PSLAPSTA");

/// What an `fmi2Component` points to.
pub struct Component<E> {
    tag: u64,
    pub instance: Instance<E>,
    /// Strings returned by fmi2GetString: valid until the next call on this instance.
    strings: Vec<CString>,
}

/// What an `fmi2FMUstate` points to.
struct Snapshot<E> {
    tag: u64,
    core: Core<E>,
}

/// Runs `f` on the instance behind `c`: refusals are logged, panics become fmi2Fatal.
unsafe fn call<E: Model>(
    c: fmi2Component,
    function: &str,
    f: impl FnOnce(&mut Component<E>) -> Outcome<Status>,
) -> Status {
    // Not logged: the logger is what called back in.
    let Some(_call) = Entered::new(c as usize) else {
        return Status::Error;
    };
    let Some(component) = component::<E>(c) else {
        return Status::Error;
    };
    match catch_unwind(AssertUnwindSafe(|| f(&mut *component))) {
        Ok(Ok(status)) => status,
        Ok(Err(refusal)) => {
            component
                .instance
                .logger
                .status(refusal.status, &format!("{function}: {}", refusal.message));
            refusal.status
        }
        Err(panic) => {
            component.instance.set_fatal();
            let message = format!(
                "{function}: internal error (panic: {}); free this instance",
                panic_text(&*panic)
            );
            component.instance.logger.status(Status::Fatal, &message);
            Status::Fatal
        }
    }
}

/// `call` for functions that only succeed with fmi2OK.
unsafe fn run<E: Model>(
    c: fmi2Component,
    function: &str,
    f: impl FnOnce(&mut Component<E>) -> Outcome,
) -> Status {
    call::<E>(c, function, |component| f(component).map(|()| Status::Ok))
}

unsafe fn component<'a, E>(c: fmi2Component) -> Option<&'a mut Component<E>> {
    let component = (c as *mut Component<E>).as_mut()?;
    (component.tag == INSTANCE_TAG).then_some(component)
}

fn panic_text(panic: &(dyn Any + Send)) -> &str {
    panic
        .downcast_ref::<&str>()
        .copied()
        .or_else(|| panic.downcast_ref::<String>().map(String::as_str))
        .unwrap_or("?")
}

/// The `n` elements at `ptr`; NULL is refused unless `n` is 0.
unsafe fn slice<'a, T>(ptr: *const T, n: usize, what: &str) -> Outcome<&'a [T]> {
    if n == 0 {
        return Ok(&[]);
    }
    if ptr.is_null() || n > isize::MAX as usize / std::mem::size_of::<T>().max(1) {
        return Err(Refusal::error(format!(
            "{what} is NULL (or its length {n} impossible)"
        )));
    }
    Ok(std::slice::from_raw_parts(ptr, n))
}

unsafe fn slice_mut<'a, T>(ptr: *mut T, n: usize, what: &str) -> Outcome<&'a mut [T]> {
    slice(ptr as *const T, n, what)?;
    Ok(if n == 0 {
        &mut []
    } else {
        std::slice::from_raw_parts_mut(ptr, n)
    })
}

unsafe fn out<'a, T>(ptr: *mut T, what: &str) -> Outcome<&'a mut T> {
    ptr.as_mut()
        .ok_or_else(|| Refusal::error(format!("{what} is NULL")))
}

unsafe fn string<'a>(s: fmi2String, what: &str) -> Outcome<&'a str> {
    if s.is_null() {
        return Err(Refusal::error(format!("{what} is NULL")));
    }
    CStr::from_ptr(s)
        .to_str()
        .map_err(|_| Refusal::error(format!("{what} is not UTF-8")))
}

unsafe fn snapshot<'a, E>(state: fmi2FMUstate) -> Outcome<&'a mut Snapshot<E>> {
    match (state as *mut Snapshot<E>).as_mut() {
        None => Err(Refusal::error("FMUstate is NULL")),
        Some(s) if s.tag != STATE_TAG => Err(Refusal::error(
            "FMUstate was not made by this FMU (or is freed)",
        )),
        Some(s) => Ok(s),
    }
}

/// Stores `core` in `*state`: into the FMU state already there, or a new one when it is NULL.
unsafe fn store<E>(state: *mut fmi2FMUstate, core: Core<E>) -> Outcome {
    let state = out(state, "FMUstate pointer")?;
    if state.is_null() {
        *state = Box::into_raw(Box::new(Snapshot {
            tag: STATE_TAG,
            core,
        })) as fmi2FMUstate;
    } else {
        snapshot::<E>(*state)?.core = core;
    }
    Ok(())
}

fn boolean(b: fmi2Boolean) -> bool {
    b != FMI2_FALSE
}

pub unsafe fn instantiate<E: Model>(
    name: fmi2String,
    fmu_type: c_int,
    guid: fmi2String,
    resource_location: fmi2String,
    functions: *const fmi2CallbackFunctions,
    logging_on: fmi2Boolean,
) -> fmi2Component {
    let Some(functions) = functions.as_ref() else {
        return std::ptr::null_mut();
    };
    let Some(callback) = functions.logger else {
        return std::ptr::null_mut();
    };
    let made = catch_unwind(AssertUnwindSafe(|| {
        let shown = if name.is_null() {
            "(null)".into()
        } else {
            CStr::from_ptr(name).to_string_lossy()
        };
        let logger = Logger::new(
            callback,
            functions.component_environment,
            &shown,
            boolean(logging_on),
        );
        let check = || -> Outcome {
            if string(name, "instanceName")?.is_empty() {
                return Err(Refusal::error("instanceName is empty"));
            }
            if fmu_type != FMI2_CO_SIMULATION {
                return Err(Refusal::error(format!(
                    "fmuType = {fmu_type} refused: PistonSlap is a Co-Simulation FMU (fmi2CoSimulation = {FMI2_CO_SIMULATION})"
                )));
            }
            let guid = string(guid, "fmuGUID")?;
            if guid != GUID {
                return Err(Refusal::error(format!(
                    "fmuGUID {guid} does not match this binary's {GUID}"
                )));
            }
            let resources = string(resource_location, "fmuResourceLocation")?;
            if !resources.starts_with("file:") {
                return Err(Refusal::error(format!(
                    "fmuResourceLocation {resources:?} is not a file URI"
                )));
            }
            Ok(())
        };
        match check() {
            Ok(()) => {
                logger.debug("logBuild", sibling::description);
                let component = Component {
                    tag: INSTANCE_TAG,
                    instance: Instance::<E>::new(logger),
                    strings: Vec::new(),
                };
                Box::into_raw(Box::new(component)) as fmi2Component
            }
            Err(refusal) => {
                logger.status(
                    Status::Error,
                    &format!("fmi2Instantiate: {}", refusal.message),
                );
                std::ptr::null_mut()
            }
        }
    }));
    made.unwrap_or(std::ptr::null_mut())
}

pub unsafe fn free_instance<E: Model>(c: fmi2Component) {
    // Freed from its own logger, the instance would vanish under the call that logs: kept instead.
    let Some(_call) = Entered::new(c as usize) else {
        return;
    };
    if let Some(component) = component::<E>(c) {
        component.tag = 0;
        let owned = Box::from_raw(component as *mut Component<E>);
        // A panic while dropping must not cross into C; the memory is then leaked.
        let _ = catch_unwind(AssertUnwindSafe(move || drop(owned)));
    }
}

pub unsafe fn set_debug_logging<E: Model>(
    c: fmi2Component,
    on: fmi2Boolean,
    n: usize,
    categories: *const fmi2String,
) -> Status {
    run::<E>(c, "fmi2SetDebugLogging", |comp| {
        comp.instance.require("fmi2SetDebugLogging", STATE)?;
        let names = slice(categories, n, "categories")?
            .iter()
            .map(|&s| string(s, "category").map(str::to_string))
            .collect::<Outcome<Vec<_>>>()?;
        comp.instance
            .logger
            .set_debug_logging(boolean(on), &names)
            .map_err(Refusal::error)
    })
}

pub unsafe fn setup_experiment<E: Model>(
    c: fmi2Component,
    _tolerance_defined: fmi2Boolean,
    _tolerance: fmi2Real,
    start: fmi2Real,
    stop_defined: fmi2Boolean,
    stop: fmi2Real,
) -> Status {
    // The tolerance is not used: the integrator's accuracy is fixed by its step and event tolerances.
    run::<E>(c, "fmi2SetupExperiment", |comp| {
        comp.instance
            .setup_experiment(start, boolean(stop_defined).then_some(stop))
    })
}

pub unsafe fn enter_initialization_mode<E: Model>(c: fmi2Component) -> Status {
    run::<E>(c, "fmi2EnterInitializationMode", |comp| {
        comp.instance.enter_initialization_mode()
    })
}

pub unsafe fn exit_initialization_mode<E: Model>(c: fmi2Component) -> Status {
    run::<E>(c, "fmi2ExitInitializationMode", |comp| {
        comp.instance.exit_initialization_mode()
    })
}

pub unsafe fn terminate<E: Model>(c: fmi2Component) -> Status {
    run::<E>(c, "fmi2Terminate", |comp| comp.instance.terminate())
}

pub unsafe fn reset<E: Model>(c: fmi2Component) -> Status {
    run::<E>(c, "fmi2Reset", |comp| comp.instance.reset())
}

/// The generated reader of one variable kind (`description::get_real`, …).
type Reader<T> = for<'a> fn(u32, &'a Parameters, &'a Inputs, &'a Outputs) -> Option<T>;

/// The shared body of fmi2GetReal and fmi2GetInteger.
unsafe fn get<E: Model, T: Copy>(
    c: fmi2Component,
    function: &str,
    kind: Kind,
    read: Reader<T>,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *mut T,
) -> Status {
    run::<E>(c, function, |comp| {
        let vrs = slice(vr, n, "vr")?;
        let out = slice_mut(value, n, "value")?;
        comp.instance.get(function, vrs, kind, read, out)
    })
}

pub unsafe fn get_real<E: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *mut fmi2Real,
) -> Status {
    get::<E, _>(
        c,
        "fmi2GetReal",
        Kind::Real,
        description::get_real,
        vr,
        n,
        value,
    )
}

pub unsafe fn get_integer<E: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *mut fmi2Integer,
) -> Status {
    get::<E, _>(
        c,
        "fmi2GetInteger",
        Kind::Integer,
        description::get_integer,
        vr,
        n,
        value,
    )
}

pub unsafe fn get_string<E: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *mut fmi2String,
) -> Status {
    run::<E>(c, "fmi2GetString", |comp| {
        let vrs = slice(vr, n, "vr")?;
        let out = slice_mut(value, n, "value")?;
        let mut strings = vec![CString::default(); n];
        comp.instance
            .get("fmi2GetString", vrs, Kind::String, c_string_of, &mut strings)?;
        comp.strings = strings;
        for (o, s) in out.iter_mut().zip(&comp.strings) {
            *o = s.as_ptr();
        }
        Ok(())
    })
}

/// A String variable as C string (strings set from C have no interior NUL).
fn c_string_of(vr: u32, p: &Parameters, i: &Inputs, o: &Outputs) -> Option<CString> {
    description::get_string(vr, p, i, o).map(|s| CString::new(s).unwrap_or_default())
}

pub unsafe fn get_boolean<E: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *mut fmi2Boolean,
) -> Status {
    run::<E>(c, "fmi2GetBoolean", |comp| {
        slice_mut(value, n, "value")?;
        comp.instance
            .booleans("fmi2GetBoolean", GET, slice(vr, n, "vr")?)
    })
}

/// The shared body of the fmi2Set* functions: pair each value reference with its value, then set all.
unsafe fn set<E: Model, T: Copy>(
    c: fmi2Component,
    function: &str,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *const T,
    convert: impl Fn(T) -> Outcome<Value<'static>>,
) -> Status {
    run::<E>(c, function, |comp| {
        let vrs = slice(vr, n, "vr")?;
        let values = slice(value, n, "value")?;
        let pairs = vrs
            .iter()
            .zip(values)
            .map(|(&vr, &v)| Ok((vr, convert(v)?)))
            .collect::<Outcome<Vec<_>>>()?;
        comp.instance.set(function, &pairs)
    })
}

pub unsafe fn set_real<E: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *const fmi2Real,
) -> Status {
    set::<E, _>(c, "fmi2SetReal", vr, n, value, |v| Ok(Value::Real(v)))
}

pub unsafe fn set_integer<E: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *const fmi2Integer,
) -> Status {
    set::<E, _>(c, "fmi2SetInteger", vr, n, value, |v| Ok(Value::Integer(v)))
}

pub unsafe fn set_string<E: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *const fmi2String,
) -> Status {
    // The strings live until the host's next call; `set` copies them before returning.
    set::<E, _>(c, "fmi2SetString", vr, n, value, |v| {
        string(v, "value").map(Value::String)
    })
}

pub unsafe fn set_boolean<E: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *const fmi2Boolean,
) -> Status {
    run::<E>(c, "fmi2SetBoolean", |comp| {
        slice(value, n, "value")?;
        comp.instance
            .booleans("fmi2SetBoolean", SET, slice(vr, n, "vr")?)
    })
}

pub unsafe fn get_fmu_state<E: Model>(c: fmi2Component, state: *mut fmi2FMUstate) -> Status {
    run::<E>(c, "fmi2GetFMUstate", |comp| {
        store(state, comp.instance.state("fmi2GetFMUstate")?)
    })
}

pub unsafe fn set_fmu_state<E: Model>(c: fmi2Component, state: fmi2FMUstate) -> Status {
    run::<E>(c, "fmi2SetFMUstate", |comp| {
        comp.instance.set_state(&snapshot::<E>(state)?.core)
    })
}

pub unsafe fn free_fmu_state<E: Model>(c: fmi2Component, state: *mut fmi2FMUstate) -> Status {
    run::<E>(c, "fmi2FreeFMUstate", |comp| {
        comp.instance.require("fmi2FreeFMUstate", STATE)?;
        let state = out(state, "FMUstate pointer")?;
        if !state.is_null() {
            let s = snapshot::<E>(*state)?;
            s.tag = 0;
            drop(Box::from_raw(s as *mut Snapshot<E>));
            *state = std::ptr::null_mut();
        }
        Ok(())
    })
}

pub unsafe fn serialized_fmu_state_size<E: Model>(
    c: fmi2Component,
    state: fmi2FMUstate,
    size: *mut usize,
) -> Status {
    run::<E>(c, "fmi2SerializedFMUstateSize", |comp| {
        let bytes = comp
            .instance
            .serialize("fmi2SerializedFMUstateSize", &snapshot::<E>(state)?.core)?;
        *out(size, "size")? = bytes.len();
        Ok(())
    })
}

pub unsafe fn serialize_fmu_state<E: Model>(
    c: fmi2Component,
    state: fmi2FMUstate,
    buffer: *mut fmi2Byte,
    size: usize,
) -> Status {
    run::<E>(c, "fmi2SerializeFMUstate", |comp| {
        let bytes = comp
            .instance
            .serialize("fmi2SerializeFMUstate", &snapshot::<E>(state)?.core)?;
        if size < bytes.len() {
            return Err(Refusal::error(format!(
                "buffer of {size} bytes, the state needs {}",
                bytes.len()
            )));
        }
        let buffer = slice_mut(buffer as *mut u8, bytes.len(), "serializedState")?;
        buffer.copy_from_slice(&bytes);
        Ok(())
    })
}

pub unsafe fn deserialize_fmu_state<E: Model>(
    c: fmi2Component,
    buffer: *const fmi2Byte,
    size: usize,
    state: *mut fmi2FMUstate,
) -> Status {
    run::<E>(c, "fmi2DeSerializeFMUstate", |comp| {
        let bytes = slice(buffer as *const u8, size, "serializedState")?;
        let core = comp.instance.deserialize(bytes)?;
        store(state, core)
    })
}

/// Refused capabilities the XML declares absent: checked for state first, like any call.
unsafe fn unsupported<E: Model>(
    c: fmi2Component,
    function: &str,
    allowed: &[super::instance::Mode],
    why: &str,
) -> Status {
    run::<E>(c, function, |comp| {
        comp.instance.require(function, allowed)?;
        Err(Refusal::error(why))
    })
}

pub unsafe fn get_directional_derivative<E: Model>(c: fmi2Component) -> Status {
    unsupported::<E>(
        c,
        "fmi2GetDirectionalDerivative",
        GET,
        "not provided (providesDirectionalDerivative = false)",
    )
}

pub unsafe fn set_real_input_derivatives<E: Model>(c: fmi2Component) -> Status {
    unsupported::<E>(
        c,
        "fmi2SetRealInputDerivatives",
        INPUT_DERIVATIVES,
        "inputs are held over a step (canInterpolateInputs = false)",
    )
}

pub unsafe fn get_real_output_derivatives<E: Model>(c: fmi2Component) -> Status {
    unsupported::<E>(
        c,
        "fmi2GetRealOutputDerivatives",
        OUTPUT_DERIVATIVES,
        "not provided (maxOutputDerivativeOrder = 0)",
    )
}

pub unsafe fn do_step<E: Model>(c: fmi2Component, t: fmi2Real, h: fmi2Real) -> Status {
    run::<E>(c, "fmi2DoStep", |comp| comp.instance.do_step(t, h))
}

pub unsafe fn cancel_step<E: Model>(c: fmi2Component) -> Status {
    unsupported::<E>(
        c,
        "fmi2CancelStep",
        // Allowed only in stepInProgress, a state a synchronous fmi2DoStep never leaves behind:
        // in any live state the refusal says why.
        STATE,
        "fmi2DoStep is synchronous: there is never a step in progress to cancel",
    )
}

/// The fmi2Get*Status functions: `answer` gives the value for the kinds this FMU defines.
unsafe fn status<E: Model, T>(
    c: fmi2Component,
    function: &str,
    kind: c_int,
    value: *mut T,
    answer: impl FnOnce(&Instance<E>, c_int) -> Option<T>,
) -> Status {
    run::<E>(c, function, |comp| {
        comp.instance.require(function, STATUS)?;
        let value = out(value, "value")?;
        *value = answer(&comp.instance, kind).ok_or_else(|| {
            Refusal::discard(format!(
                "status kind {kind} has no value: fmi2DoStep is synchronous and never pending"
            ))
        })?;
        Ok(())
    })
}

pub unsafe fn get_status<E: Model>(c: fmi2Component, kind: c_int, value: *mut c_int) -> Status {
    status::<E, c_int>(c, "fmi2GetStatus", kind, value, |_, _| None)
}

pub unsafe fn get_real_status<E: Model>(
    c: fmi2Component,
    kind: c_int,
    value: *mut fmi2Real,
) -> Status {
    status::<E, fmi2Real>(c, "fmi2GetRealStatus", kind, value, |inst, kind| {
        (kind == FMI2_LAST_SUCCESSFUL_TIME).then(|| inst.time())
    })
}

pub unsafe fn get_integer_status<E: Model>(
    c: fmi2Component,
    kind: c_int,
    value: *mut fmi2Integer,
) -> Status {
    status::<E, fmi2Integer>(c, "fmi2GetIntegerStatus", kind, value, |_, _| None)
}

pub unsafe fn get_boolean_status<E: Model>(
    c: fmi2Component,
    kind: c_int,
    value: *mut fmi2Boolean,
) -> Status {
    // The FMU never asks the master to stop.
    status::<E, fmi2Boolean>(c, "fmi2GetBooleanStatus", kind, value, |_, kind| {
        (kind == FMI2_TERMINATED).then_some(FMI2_FALSE)
    })
}

pub unsafe fn get_string_status<E: Model>(
    c: fmi2Component,
    kind: c_int,
    value: *mut fmi2String,
) -> Status {
    status::<E, fmi2String>(c, "fmi2GetStringStatus", kind, value, |_, _| None)
}
