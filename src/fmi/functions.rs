//! The fmi2 functions, generic over the model so that one body serves PistonSlap, EngineCycle and the
//! test models; `exports.rs` gives them their C names, choosing the model by the instance's tag. The fmi3
//! functions whose arguments match an fmi2 function's share its body (each body is told which function the
//! host called, for the state machine and the log); `fmi3_functions.rs` holds the others.
//!
//! Each function turns the host's pointers into Rust values (`pointers.rs`) and hands them to the
//! instance inside [`call`], which consults the state machine's table, runs the instance's safe logic
//! inside `catch_unwind` (a panic is logged and returns fmi2Fatal), and logs every refusal.
#![allow(unsafe_code)]

use super::description::Kind;
use super::instance::{Instance, Model, Outcome, Refusal, Value};
use super::logger::Logger;
use super::pointers::{out, slice, slice_mut, string};
use super::reentry::Entered;
use super::snapshot::{snapshot, store, Snapshot};
use super::state_machine::Function;
use super::types::*;
use std::any::Any;
use std::ffi::{c_int, CStr, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::PathBuf;

/// What an `fmi2Component` points to. The tag ([`Model::INSTANCE_TAG`], first in a C layout, so
/// [`instance_tag`] reads it whatever the model) marks a live instance of that model: a pointer that is
/// not one of ours (or already freed, as far as its memory still says so) is refused instead of used.
#[repr(C)]
pub struct Component<E: Model> {
    tag: u64,
    pub instance: Instance<E>,
    /// Strings returned by fmi2GetString: valid until the next call on this instance.
    strings: Vec<CString>,
}

/// Runs `f` on the instance behind `c` if the state machine allows `function` in its state: refusals
/// are logged with the function's name, panics become fmi2Fatal.
///
/// # Safety
/// `c` is NULL, an instance of this model made by [`instantiate`], or memory readable as one.
unsafe fn call<E: Model>(c: fmi2Component, function: Function, f: impl FnOnce(&mut Component<E>) -> Outcome<Status>) -> Status {
    // Not logged: the logger is what called back in.
    let Some(_call) = Entered::new(c as usize) else {
        return Status::Error;
    };
    // SAFETY: the caller's contract; `component` checks NULL and the tag.
    let Some(component) = (unsafe { component::<E>(c) }) else {
        return Status::Error;
    };
    let outcome = catch_unwind(AssertUnwindSafe(|| {
        function.check(component.instance.mode()).map_err(Refusal::error)?;
        f(&mut *component)
    }));
    let name = function.name();
    match outcome {
        Ok(Ok(status)) => status,
        Ok(Err(refusal)) => {
            component.instance.logger.status(refusal.status, &format!("{name}: {}", refusal.message));
            refusal.status
        }
        Err(panic) => {
            component.instance.set_fatal();
            let message = format!("{name}: internal error (panic: {}); free this instance", panic_text(&*panic));
            component.instance.logger.status(Status::Fatal, &message);
            Status::Fatal
        }
    }
}

/// [`call`] for functions that only succeed with fmi2OK.
///
/// # Safety
/// As [`call`].
pub(super) unsafe fn run<E: Model>(c: fmi2Component, function: Function, f: impl FnOnce(&mut Component<E>) -> Outcome) -> Status {
    // SAFETY: the caller's contract.
    unsafe { call::<E>(c, function, |component| f(component).map(|()| Status::Ok)) }
}

/// # Safety
/// As [`call`].
unsafe fn component<'a, E: Model>(c: fmi2Component) -> Option<&'a mut Component<E>> {
    // SAFETY: NULL is checked by `instance_tag`; anything else is ours or readable memory (the contract).
    if unsafe { instance_tag(c) } != Some(E::INSTANCE_TAG) {
        return None;
    }
    // SAFETY: tagged as a live instance of this model.
    Some(unsafe { &mut *(c as *mut Component<E>) })
}

/// The tag of the instance behind `c` (which model made it), None for NULL.
///
/// # Safety
/// As [`call`], for any model: every `Component` starts with its `u64` tag.
pub unsafe fn instance_tag(c: fmi2Component) -> Option<u64> {
    // SAFETY: NULL is checked by `as_ref`; `Component` is `repr(C)` with the tag first.
    unsafe { (c as *const u64).as_ref().copied() }
}

/// Whether fmi2Instantiate's `guid` is the GUID of model `E` (false for NULL).
///
/// # Safety
/// `guid` is NULL or a NUL-terminated string.
pub unsafe fn has_guid<E: Model>(guid: fmi2String) -> bool {
    // SAFETY: the caller's contract.
    !guid.is_null() && unsafe { CStr::from_ptr(guid) }.to_bytes() == E::DESCRIPTION.guid.as_bytes()
}

fn panic_text(panic: &(dyn Any + Send)) -> &str {
    panic.downcast_ref::<&str>().copied().or_else(|| panic.downcast_ref::<String>().map(String::as_str)).unwrap_or("?")
}

fn boolean(b: fmi2Boolean) -> bool {
    b != FMI2_FALSE
}

/// Refuses a GUID (FMI 3.0: instantiation token, `what` names the argument) that is not `E`'s.
pub(super) fn check_guid<E: Model>(guid: &str, what: &str) -> Outcome {
    if guid == E::DESCRIPTION.guid {
        return Ok(());
    }
    Err(Refusal::error(format!(
        "{what} {guid} does not match this binary's {}: it instantiates {} only (each FMU of this crate carries its own copy)",
        E::DESCRIPTION.guid,
        E::NAME
    )))
}

/// The new instance of `E` once the host's arguments passed their checks (`checked`: the FMU's resources
/// directory), or NULL with the refusal logged as `function`'s.
pub(super) fn make<E: Model>(function: &str, logger: Logger, checked: Outcome<Option<PathBuf>>) -> fmi2Component {
    match checked {
        Ok(resources) => {
            let component = Component { tag: E::INSTANCE_TAG, instance: Instance::<E>::new(logger, resources), strings: Vec::new() };
            Box::into_raw(Box::new(component)) as fmi2Component
        }
        Err(refusal) => {
            logger.status(Status::Error, &format!("{function}: {}", refusal.message));
            std::ptr::null_mut()
        }
    }
}

/// # Safety
/// The pointers are NULL or valid as fmi2Instantiate's arguments (NUL-terminated strings, a callback
/// table whose logger may be called with its environment).
pub unsafe fn instantiate<E: Model>(
    name: fmi2String,
    fmu_type: c_int,
    guid: fmi2String,
    resource_location: fmi2String,
    functions: *const fmi2CallbackFunctions,
    logging_on: fmi2Boolean,
) -> fmi2Component {
    // SAFETY: NULL or the host's callback table.
    let Some(functions) = (unsafe { functions.as_ref() }) else {
        return std::ptr::null_mut();
    };
    let Some(callback) = functions.logger else {
        return std::ptr::null_mut();
    };
    let made = catch_unwind(AssertUnwindSafe(|| {
        // SAFETY: NULL or a NUL-terminated string (the contract).
        let shown = if name.is_null() { "(null)".into() } else { unsafe { CStr::from_ptr(name) }.to_string_lossy() };
        let logger = Logger::new(callback, functions.component_environment, &shown, boolean(logging_on));
        let check = || -> Outcome<Option<PathBuf>> {
            // SAFETY: the strings are NULL or NUL-terminated (the contract).
            let (name, guid, resources) =
                unsafe { (string(name, "instanceName")?, string(guid, "fmuGUID")?, string(resource_location, "fmuResourceLocation")?) };
            if name.is_empty() {
                return Err(Refusal::error("instanceName is empty"));
            }
            if fmu_type != FMI2_CO_SIMULATION {
                return Err(Refusal::error(format!(
                    "fmuType = {fmu_type} refused: {} is a Co-Simulation FMU (fmi2CoSimulation = {FMI2_CO_SIMULATION})",
                    E::NAME
                )));
            }
            check_guid::<E>(guid, "fmuGUID")?;
            if !resources.starts_with("file:") {
                return Err(Refusal::error(format!("fmuResourceLocation {resources:?} is not a file URI")));
            }
            // A host may unpack the FMU where no local path reaches it: bare file names then stay as given.
            Ok(super::resources::directory(resources))
        };
        make::<E>("fmi2Instantiate", logger, check())
    }));
    made.unwrap_or(std::ptr::null_mut())
}

/// # Safety
/// As [`call`]; `c` is not used again.
pub unsafe fn free_instance<E: Model>(c: fmi2Component) {
    // Freed from its own logger, the instance would vanish under the call that logs: kept instead.
    let Some(_call) = Entered::new(c as usize) else {
        return;
    };
    // SAFETY: the caller's contract.
    if let Some(component) = unsafe { component::<E>(c) } {
        component.tag = 0;
        // SAFETY: made by `Box::into_raw` in `instantiate`, tagged live until now.
        let owned = unsafe { Box::from_raw(component as *mut Component<E>) };
        // A panic while dropping must not cross into C; the memory is then leaked.
        let _ = catch_unwind(AssertUnwindSafe(move || drop(owned)));
    }
}

/// # Safety
/// As [`call`]; `categories` is NULL or points to `n` NULL or NUL-terminated strings.
pub unsafe fn set_debug_logging<E: Model>(
    function: Function,
    c: fmi2Component,
    on: fmi2Boolean,
    n: usize,
    categories: *const fmi2String,
) -> Status {
    // SAFETY: the caller's contract, for `c` and each pointer read.
    unsafe {
        run::<E>(c, function, |comp| {
            let names = slice(categories, n, "categories")?
                .iter()
                .map(|&s| string(s, "category").map(str::to_string))
                .collect::<Outcome<Vec<_>>>()?;
            comp.instance.logger.set_debug_logging(boolean(on), &names).map_err(Refusal::error)
        })
    }
}

/// # Safety
/// As [`call`].
pub unsafe fn setup_experiment<E: Model>(
    function: Function,
    c: fmi2Component,
    start: fmi2Real,
    stop_defined: fmi2Boolean,
    stop: fmi2Real,
) -> Status {
    // The tolerance is not used: the integrator's accuracy is fixed by its step and event tolerances.
    // SAFETY: the caller's contract.
    unsafe { run::<E>(c, function, |comp| comp.instance.setup_experiment(start, boolean(stop_defined).then_some(stop))) }
}

/// # Safety
/// As [`call`].
pub unsafe fn enter_initialization_mode<E: Model>(function: Function, c: fmi2Component) -> Status {
    // SAFETY: the caller's contract.
    unsafe { run::<E>(c, function, |comp| comp.instance.enter_initialization_mode()) }
}

/// # Safety
/// As [`call`].
pub unsafe fn exit_initialization_mode<E: Model>(function: Function, c: fmi2Component) -> Status {
    // SAFETY: the caller's contract.
    unsafe { run::<E>(c, function, |comp| comp.instance.exit_initialization_mode()) }
}

/// # Safety
/// As [`call`].
pub unsafe fn terminate<E: Model>(function: Function, c: fmi2Component) -> Status {
    // SAFETY: the caller's contract.
    unsafe { run::<E>(c, function, |comp| comp.instance.terminate()) }
}

/// # Safety
/// As [`call`].
pub unsafe fn reset<E: Model>(function: Function, c: fmi2Component) -> Status {
    // SAFETY: the caller's contract.
    unsafe { run::<E>(c, function, |comp| comp.instance.reset()) }
}

/// The generated reader of one variable kind (`Description::get_real`, …).
type Reader<E, T> = for<'a> fn(u32, &'a <E as Model>::Parameters, &'a <E as Model>::Inputs, &'a <E as Model>::Outputs) -> Option<T>;

/// The shared body of fmi2GetReal, fmi2GetInteger and fmi3GetInt32.
///
/// # Safety
/// As [`call`]; `vr` and `value` are NULL or point to `n` elements.
unsafe fn get<E: Model, T: Copy>(
    c: fmi2Component,
    function: Function,
    kind: Kind,
    read: Reader<E, T>,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *mut T,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe { run::<E>(c, function, |comp| comp.instance.get(slice(vr, n, "vr")?, kind, read, slice_mut(value, n, "value")?, None)) }
}

/// # Safety
/// As [`get`].
pub unsafe fn get_real<E: Model>(
    function: Function,
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *mut fmi2Real,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe { get::<E, _>(c, function, Kind::Real, E::DESCRIPTION.get_real, vr, n, value) }
}

/// # Safety
/// As [`get`].
pub unsafe fn get_integer<E: Model>(
    function: Function,
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *mut fmi2Integer,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe { get::<E, _>(c, function, Kind::Integer, E::DESCRIPTION.get_integer, vr, n, value) }
}

/// # Safety
/// As [`get`].
pub unsafe fn get_string<E: Model>(
    function: Function,
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *mut fmi2String,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        run::<E>(c, function, |comp| {
            let (vrs, out) = (slice(vr, n, "vr")?, slice_mut(value, n, "value")?);
            let mut strings = vec![CString::default(); n];
            comp.instance.get(vrs, Kind::String, c_string_of::<E>, &mut strings, None)?;
            comp.strings = strings;
            for (o, s) in out.iter_mut().zip(&comp.strings) {
                *o = s.as_ptr();
            }
            Ok(())
        })
    }
}

/// A String variable as C string (strings set from C have no interior NUL).
fn c_string_of<E: Model>(vr: u32, p: &E::Parameters, i: &E::Inputs, o: &E::Outputs) -> Option<CString> {
    (E::DESCRIPTION.get_string)(vr, p, i, o).map(|s| CString::new(s).unwrap_or_default())
}

/// # Safety
/// As [`get`].
pub unsafe fn get_boolean<E: Model>(
    function: Function,
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *mut fmi2Boolean,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        run::<E>(c, function, |comp| {
            slice_mut(value, n, "value")?;
            comp.instance.none_of_kind(slice(vr, n, "vr")?, "Boolean")
        })
    }
}

/// The shared body of the fmi2Set* functions: pair each value reference with its value, then set all.
///
/// # Safety
/// As [`call`]; `vr` and `value` are NULL or point to `n` elements.
unsafe fn set<E: Model, T: Copy>(
    c: fmi2Component,
    function: Function,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *const T,
    convert: impl Fn(T) -> Outcome<Value<'static>>,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        run::<E>(c, function, |comp| {
            let (vrs, values) = (slice(vr, n, "vr")?, slice(value, n, "value")?);
            let pairs = vrs.iter().zip(values).map(|(&vr, &v)| Ok((vr, convert(v)?))).collect::<Outcome<Vec<_>>>()?;
            comp.instance.set(&pairs)
        })
    }
}

/// # Safety
/// As [`set`].
pub unsafe fn set_real<E: Model>(
    function: Function,
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *const fmi2Real,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe { set::<E, _>(c, function, vr, n, value, |v| Ok(Value::Real(v))) }
}

/// # Safety
/// As [`set`].
pub unsafe fn set_integer<E: Model>(
    function: Function,
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *const fmi2Integer,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe { set::<E, _>(c, function, vr, n, value, |v| Ok(Value::Integer(v))) }
}

/// # Safety
/// As [`set`]; each string is NULL or NUL-terminated.
pub unsafe fn set_string<E: Model>(
    function: Function,
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *const fmi2String,
) -> Status {
    // The strings live until the host's next call; `set` copies them before returning.
    // SAFETY: the caller's contract.
    unsafe { set::<E, _>(c, function, vr, n, value, |v| string(v, "value").map(Value::String)) }
}

/// # Safety
/// As [`set`].
pub unsafe fn set_boolean<E: Model>(
    function: Function,
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    value: *const fmi2Boolean,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        run::<E>(c, function, |comp| {
            slice(value, n, "value")?;
            comp.instance.none_of_kind(slice(vr, n, "vr")?, "Boolean")
        })
    }
}

/// # Safety
/// As [`call`]; `state` as [`store`] takes it.
pub unsafe fn get_fmu_state<E: Model>(function: Function, c: fmi2Component, state: *mut fmi2FMUstate) -> Status {
    // SAFETY: the caller's contract.
    unsafe { run::<E>(c, function, |comp| store(state, comp.instance.state())) }
}

/// # Safety
/// As [`call`]; `state` as [`snapshot`] takes it.
pub unsafe fn set_fmu_state<E: Model>(function: Function, c: fmi2Component, state: fmi2FMUstate) -> Status {
    // SAFETY: the caller's contract.
    unsafe { run::<E>(c, function, |comp| comp.instance.set_state(&snapshot::<E>(state)?.core)) }
}

/// # Safety
/// As [`call`]; `state` as [`store`] takes it; the FMU state is not used again.
pub unsafe fn free_fmu_state<E: Model>(function: Function, c: fmi2Component, state: *mut fmi2FMUstate) -> Status {
    // SAFETY: the caller's contract; a live FMU state was made by `Box::into_raw` in `store`.
    unsafe {
        run::<E>(c, function, |_| {
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
}

/// # Safety
/// As [`call`]; `state` as [`snapshot`] takes it; `size` NULL or writable.
pub unsafe fn serialized_fmu_state_size<E: Model>(function: Function, c: fmi2Component, state: fmi2FMUstate, size: *mut usize) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        run::<E>(c, function, |_| {
            *out(size, "size")? = snapshot::<E>(state)?.bytes()?.len();
            Ok(())
        })
    }
}

/// # Safety
/// As [`call`]; `state` as [`snapshot`] takes it; `buffer` NULL or `size` writable bytes.
pub unsafe fn serialize_fmu_state<E: Model>(
    function: Function,
    c: fmi2Component,
    state: fmi2FMUstate,
    buffer: *mut u8,
    size: usize,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        run::<E>(c, function, |_| {
            let bytes = snapshot::<E>(state)?.bytes()?;
            if size < bytes.len() {
                return Err(Refusal::error(format!("buffer of {size} bytes, the state needs {}", bytes.len())));
            }
            slice_mut(buffer, bytes.len(), "serializedState")?.copy_from_slice(bytes);
            Ok(())
        })
    }
}

/// # Safety
/// As [`call`]; `buffer` NULL or `size` readable bytes; `state` as [`store`] takes it.
pub unsafe fn deserialize_fmu_state<E: Model>(
    function: Function,
    c: fmi2Component,
    buffer: *const u8,
    size: usize,
    state: *mut fmi2FMUstate,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        run::<E>(c, function, |comp| {
            let core = comp.instance.deserialize(slice(buffer, size, "serializedState")?)?;
            store(state, core)
        })
    }
}

/// Refuses the call with `why` (after the state check, like any call): a capability the XML declares absent,
/// or arguments the FMU cannot take.
///
/// # Safety
/// As [`call`].
pub unsafe fn refuse<E: Model>(function: Function, c: fmi2Component, why: &str) -> Status {
    // SAFETY: the caller's contract.
    unsafe { run::<E>(c, function, |_| Err(Refusal::error(why))) }
}

/// # Safety
/// As [`call`].
pub unsafe fn get_directional_derivative<E: Model>(function: Function, c: fmi2Component) -> Status {
    // SAFETY: the caller's contract.
    unsafe { refuse::<E>(function, c, "not provided (providesDirectionalDerivative = false)") }
}

/// # Safety
/// As [`call`]; `vr`, `order` and `value` are NULL or point to `n` elements.
pub unsafe fn set_real_input_derivatives<E: Model>(
    function: Function,
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    order: *const fmi2Integer,
    value: *const fmi2Real,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        run::<E>(c, function, |comp| {
            let (vrs, orders, values) = (slice(vr, n, "vr")?, slice(order, n, "order")?, slice(value, n, "value")?);
            comp.instance.set_input_derivatives(vrs, orders, values)
        })
    }
}

/// # Safety
/// As [`call`]; `vr`, `order` and `value` are NULL or point to `n` elements.
pub unsafe fn get_real_output_derivatives<E: Model>(
    function: Function,
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    n: usize,
    order: *const fmi2Integer,
    value: *mut fmi2Real,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        run::<E>(c, function, |comp| {
            let (vrs, orders, out) = (slice(vr, n, "vr")?, slice(order, n, "order")?, slice_mut(value, n, "value")?);
            comp.instance.output_derivatives(vrs, orders, out)
        })
    }
}

/// # Safety
/// As [`call`].
pub unsafe fn do_step<E: Model>(function: Function, c: fmi2Component, t: fmi2Real, h: fmi2Real) -> Status {
    // SAFETY: the caller's contract.
    unsafe { run::<E>(c, function, |comp| comp.instance.do_step(t, h)) }
}

/// # Safety
/// As [`call`].
pub unsafe fn cancel_step<E: Model>(function: Function, c: fmi2Component) -> Status {
    // SAFETY: the caller's contract.
    unsafe { refuse::<E>(function, c, "fmi2DoStep is synchronous: there is never a step in progress to cancel") }
}

/// The fmi2Get*Status functions: `answer` gives the value for the kinds this FMU defines.
///
/// # Safety
/// As [`call`]; `value` NULL or writable.
unsafe fn status<E: Model, T>(
    c: fmi2Component,
    function: Function,
    kind: c_int,
    value: *mut T,
    answer: impl FnOnce(&Instance<E>, c_int) -> Option<T>,
) -> Status {
    // SAFETY: the caller's contract.
    unsafe {
        run::<E>(c, function, |comp| {
            let value = out(value, "value")?;
            *value = answer(&comp.instance, kind)
                .ok_or_else(|| Refusal::discard(format!("status kind {kind} has no value: fmi2DoStep is synchronous and never pending")))?;
            Ok(())
        })
    }
}

/// # Safety
/// As [`status`].
pub unsafe fn get_status<E: Model>(function: Function, c: fmi2Component, kind: c_int, value: *mut c_int) -> Status {
    // SAFETY: the caller's contract.
    unsafe { status::<E, c_int>(c, function, kind, value, |_, _| None) }
}

/// # Safety
/// As [`status`].
pub unsafe fn get_real_status<E: Model>(function: Function, c: fmi2Component, kind: c_int, value: *mut fmi2Real) -> Status {
    // SAFETY: the caller's contract.
    unsafe { status::<E, fmi2Real>(c, function, kind, value, |inst, kind| (kind == FMI2_LAST_SUCCESSFUL_TIME).then(|| inst.time())) }
}

/// # Safety
/// As [`status`].
pub unsafe fn get_integer_status<E: Model>(function: Function, c: fmi2Component, kind: c_int, value: *mut fmi2Integer) -> Status {
    // SAFETY: the caller's contract.
    unsafe { status::<E, fmi2Integer>(c, function, kind, value, |_, _| None) }
}

/// # Safety
/// As [`status`].
pub unsafe fn get_boolean_status<E: Model>(function: Function, c: fmi2Component, kind: c_int, value: *mut fmi2Boolean) -> Status {
    // The FMU never asks the master to stop.
    // SAFETY: the caller's contract.
    unsafe { status::<E, fmi2Boolean>(c, function, kind, value, |_, kind| (kind == FMI2_TERMINATED).then_some(FMI2_FALSE)) }
}

/// # Safety
/// As [`status`].
pub unsafe fn get_string_status<E: Model>(function: Function, c: fmi2Component, kind: c_int, value: *mut fmi2String) -> Status {
    // SAFETY: the caller's contract.
    unsafe { status::<E, fmi2String>(c, function, kind, value, |_, _| None) }
}
