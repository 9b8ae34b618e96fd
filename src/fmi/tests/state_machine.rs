//! Every fmi2 function of the common and Co-Simulation parts, called in every state an instance can be
//! in, against the FMI 2.0 standard's table of allowed calls (§4.2.4, state machine of the calling
//! sequence from master to slave), transcribed below. An allowed call does its work (fmi2OK or the
//! status the FMU documents); a forbidden one returns fmi2Error, logs why and changes nothing.
//!
//! Run with the shipped engine (Fatal is unreachable there: no input makes it panic) and with the test
//! shuttle, whose `load_torque` = 42 panics, for the Fatal column.
#![allow(unsafe_code)]

use super::*;
use crate::fmi::functions::Component;
use crate::fmi::state_machine::Mode;
use crate::fmus::exports;
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::mem::ManuallyDrop;

/// The system allocator, counting per thread the bytes given back (tests run in parallel threads).
struct CountingFrees;

thread_local! {
    static FREED: Cell<usize> = const { Cell::new(0) };
}

// SAFETY: forwards every call to the system allocator unchanged; it only counts.
unsafe impl GlobalAlloc for CountingFrees {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: the caller's contract, passed on.
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        FREED.with(|n| n.set(n.get() + layout.size()));
        // SAFETY: the caller's contract, passed on.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static COUNTING_FREES: CountingFrees = CountingFrees;

/// Bytes this thread gave back while running `f`.
fn freed_bytes(f: impl FnOnce()) -> usize {
    let before = FREED.with(Cell::get);
    f();
    FREED.with(Cell::get) - before
}

/// Columns of [`TABLE`]. The standard's stepInProgress, stepFailed and stepCanceled cannot occur:
/// fmi2DoStep is synchronous and never returns fmi2Pending or fmi2Discard. Its "start and end" column
/// only allows fmi2Instantiate (and the two instance-free queries).
const STATES: [Mode; 6] = [Mode::Instantiated, Mode::InitializationMode, Mode::StepComplete, Mode::Terminated, Mode::Error, Mode::Fatal];

/// The standard's table for these states: `x` = the call is allowed.
#[rustfmt::skip]
const TABLE: &[(&str, &str)] = &[
    //                                 Inst Init Step Term Err  Fatal
    ("fmi2GetTypesPlatform",          "x    x    x    x    x    x"),
    ("fmi2GetVersion",                "x    x    x    x    x    x"),
    ("fmi2SetDebugLogging",           "x    x    x    x    x    ."),
    ("fmi2SetupExperiment",           "x    .    .    .    .    ."),
    ("fmi2EnterInitializationMode",   "x    .    .    .    .    ."),
    ("fmi2ExitInitializationMode",    ".    x    .    .    .    ."),
    ("fmi2Terminate",                 ".    .    x    .    .    ."),
    ("fmi2Reset",                     "x    x    x    x    x    ."),
    ("fmi2GetReal",                   ".    x    x    x    x    ."),
    ("fmi2GetInteger",                ".    x    x    x    x    ."),
    ("fmi2GetBoolean",                ".    x    x    x    x    ."),
    ("fmi2GetString",                 ".    x    x    x    x    ."),
    ("fmi2SetReal",                   "x    x    x    .    .    ."),
    ("fmi2SetInteger",                "x    x    x    .    .    ."),
    ("fmi2SetBoolean",                "x    x    x    .    .    ."),
    ("fmi2SetString",                 "x    x    x    .    .    ."),
    ("fmi2GetFMUstate",               "x    x    x    x    x    ."),
    ("fmi2SetFMUstate",               "x    x    x    x    x    ."),
    ("fmi2FreeFMUstate",              "x    x    x    x    x    ."),
    ("fmi2SerializedFMUstateSize",    "x    x    x    x    x    ."),
    ("fmi2SerializeFMUstate",         "x    x    x    x    x    ."),
    ("fmi2DeSerializeFMUstate",       "x    x    x    x    x    ."),
    ("fmi2GetDirectionalDerivative",  ".    x    x    x    x    ."),
    ("fmi2SetRealInputDerivatives",   "x    x    x    .    .    ."),
    ("fmi2GetRealOutputDerivatives",  ".    .    x    x    x    ."),
    ("fmi2DoStep",                    ".    .    x    .    .    ."),
    ("fmi2CancelStep",                ".    .    .    .    .    ."),
    ("fmi2GetStatus",                 ".    .    x    x    .    ."),
    ("fmi2GetRealStatus",             ".    .    x    x    .    ."),
    ("fmi2GetIntegerStatus",          ".    .    x    x    .    ."),
    ("fmi2GetBooleanStatus",          ".    .    x    x    .    ."),
    ("fmi2GetStringStatus",           ".    .    x    x    .    ."),
];

/// How a model under test is configured and driven into the Error and Fatal states.
struct Subject<E: Model> {
    /// Called in Instantiated, before anything else.
    configure: fn(&Host<E>),
    /// Sets an input that makes the next fmi2DoStep fail (fmi2Error).
    break_step: fn(&Host<E>),
    /// Sets an input that makes the next fmi2DoStep panic (fmi2Fatal), where one exists.
    panic_step: Option<fn(&Host<E>)>,
}

/// The communication step that brings an instance into StepComplete; the next one starts at its end.
const H: f64 = 1e-3;

/// A fresh instance driven into `state` through the C ABI.
fn reach<E: Model>(subject: &Subject<E>, state: Mode) -> Host<E> {
    let host = Host::<E>::new();
    (subject.configure)(&host);
    if state != Mode::Instantiated {
        assert_eq!(host.setup(0.0, Some(1.0)), Status::Ok);
        assert_eq!(host.enter(), Status::Ok);
    }
    if !matches!(state, Mode::Instantiated | Mode::InitializationMode) {
        assert_eq!(host.exit(), Status::Ok, "{:?}", host.messages());
        assert_eq!(host.step(0.0, H), Status::Ok, "{:?}", host.messages());
    }
    match state {
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        Mode::Terminated => assert_eq!(unsafe { functions::terminate::<E>(Function::fmi2Terminate, host.c) }, Status::Ok),
        Mode::Error => {
            (subject.break_step)(&host);
            assert_eq!(host.step(H, H), Status::Error);
        }
        Mode::Fatal => {
            (subject.panic_step.expect("a way to panic"))(&host);
            assert_eq!(host.step(H, H), Status::Fatal);
        }
        _ => {}
    }
    assert_eq!(mode(&host), state);
    host.log.lock().unwrap().clear();
    host
}

fn mode<E: Model>(host: &Host<E>) -> Mode {
    // SAFETY: `host.c` is a live instance of `E` made by `functions::instantiate::<E>`.
    unsafe { (*(host.c as *const Component<E>)).instance.mode() }
}

/// What an allowed call returns: fmi2OK, or a documented status with a message saying why.
type Expected = (Status, Option<&'static str>);
const OK: Expected = (Status::Ok, None);

/// Calls `function` with arguments that are valid apart from the state; `donor` (in StepComplete)
/// lends FMU states. Returns the status and what the call returns where it is allowed.
fn call<E: Model>(host: &Host<E>, donor: &Host<E>, function: &str) -> (Status, Expected) {
    let c = host.c;
    let in_step_mode = mode(host) == Mode::StepComplete;
    let (mut real, mut int, mut boolean, mut string) = ([0.0; 3], [0; 2], [0; 1], [null(); 1]);
    let reals = [vr("crank_speed"), vr("restitution"), vr("crank_angle")];
    let integers = [vr("model_variant"), vr("impact_count")];
    // PistonSlap has no Integer or String input: in step mode only an empty list is settable.
    let fixed = |vrs: &[u32]| if in_step_mode { 0 } else { vrs.len() };
    let crank_mode = [vr("crank_mode")];
    let impact_log = [vr("impact_log")];
    let no_value = (Status::Discard, Some("has no value"));
    // SAFETY: a NUL-terminated string the FMU returned, valid until its next call.
    let c_string = |p: *const c_char| unsafe { CStr::from_ptr(p) }.to_str().unwrap();
    let constant = |ok: bool| (if ok { Status::Ok } else { Status::Error }, OK);
    // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
    unsafe {
        match function {
            "fmi2GetTypesPlatform" => constant(c_string(exports::fmi2GetTypesPlatform()) == "default"),
            "fmi2GetVersion" => constant(c_string(exports::fmi2GetVersion()) == "2.0"),
            "fmi2SetDebugLogging" => (functions::set_debug_logging::<E>(Function::fmi2SetDebugLogging, c, FMI2_TRUE, 0, null()), OK),
            "fmi2SetupExperiment" => (host.setup(0.0, Some(1.0)), OK),
            "fmi2EnterInitializationMode" => (host.enter(), OK),
            "fmi2ExitInitializationMode" => (host.exit(), OK),
            "fmi2Terminate" => (functions::terminate::<E>(Function::fmi2Terminate, c), OK),
            "fmi2Reset" => (functions::reset::<E>(Function::fmi2Reset, c), OK),
            "fmi2GetReal" => (functions::get_real::<E>(Function::fmi2GetReal, c, reals.as_ptr(), 3, real.as_mut_ptr()), OK),
            "fmi2GetInteger" => (functions::get_integer::<E>(Function::fmi2GetInteger, c, integers.as_ptr(), 2, int.as_mut_ptr()), OK),
            "fmi2GetBoolean" => (functions::get_boolean::<E>(Function::fmi2GetBoolean, c, null(), 0, boolean.as_mut_ptr()), OK),
            "fmi2GetString" => (functions::get_string::<E>(Function::fmi2GetString, c, impact_log.as_ptr(), 1, string.as_mut_ptr()), OK),
            "fmi2SetReal" => (functions::set_real::<E>(Function::fmi2SetReal, c, reals.as_ptr(), 1, &100.0), OK),
            "fmi2SetInteger" => (functions::set_integer::<E>(Function::fmi2SetInteger, c, crank_mode.as_ptr(), fixed(&crank_mode), &1), OK),
            "fmi2SetBoolean" => (functions::set_boolean::<E>(Function::fmi2SetBoolean, c, null(), 0, null()), OK),
            "fmi2SetString" => {
                let empty = [c"".as_ptr()];
                (functions::set_string::<E>(Function::fmi2SetString, c, impact_log.as_ptr(), fixed(&impact_log), empty.as_ptr()), OK)
            }
            "fmi2GetFMUstate" => {
                let mut state = null_mut();
                let status = functions::get_fmu_state::<E>(Function::fmi2GetFMUstate, c, &mut state);
                assert_eq!(status == Status::Ok, !state.is_null());
                if !state.is_null() {
                    donor.free_state(state);
                }
                (status, OK)
            }
            "fmi2SetFMUstate" => {
                let state = donor.get_state();
                let status = host.set_state(state);
                donor.free_state(state);
                (status, OK)
            }
            "fmi2FreeFMUstate" => {
                let mut state = donor.get_state();
                let status = functions::free_fmu_state::<E>(Function::fmi2FreeFMUstate, c, &mut state);
                assert_eq!(status == Status::Ok, state.is_null());
                if !state.is_null() {
                    donor.free_state(state);
                }
                (status, OK)
            }
            "fmi2SerializedFMUstateSize" => {
                let (state, mut size) = (donor.get_state(), 0);
                let status = functions::serialized_fmu_state_size::<E>(Function::fmi2SerializedFMUstateSize, c, state, &mut size);
                donor.free_state(state);
                (status, OK)
            }
            "fmi2SerializeFMUstate" => {
                let state = donor.get_state();
                let mut bytes = vec![0 as c_char; donor.serialize(state).len()];
                let status =
                    functions::serialize_fmu_state::<E>(Function::fmi2SerializeFMUstate, c, state, bytes.as_mut_ptr().cast(), bytes.len());
                donor.free_state(state);
                (status, OK)
            }
            "fmi2DeSerializeFMUstate" => {
                let state = donor.get_state();
                let bytes = donor.serialize(state);
                donor.free_state(state);
                let (status, copy) = host.deserialize(&bytes);
                if !copy.is_null() {
                    donor.free_state(copy);
                }
                (status, OK)
            }
            "fmi2GetDirectionalDerivative" => (
                functions::get_directional_derivative::<E>(Function::fmi2GetDirectionalDerivative, c),
                (Status::Error, Some("providesDirectionalDerivative = false")),
            ),
            "fmi2SetRealInputDerivatives" => {
                (functions::set_real_input_derivatives::<E>(Function::fmi2SetRealInputDerivatives, c, reals.as_ptr(), 1, &1, &50.0), OK)
            }
            "fmi2GetRealOutputDerivatives" => (
                functions::get_real_output_derivatives::<E>(Function::fmi2GetRealOutputDerivatives, c, &reals[2], 1, &1, real.as_mut_ptr()),
                (Status::Error, Some("maxOutputDerivativeOrder = 0")),
            ),
            "fmi2DoStep" => (host.step(H, H), OK),
            "fmi2CancelStep" => (functions::cancel_step::<E>(Function::fmi2CancelStep, c), OK),
            "fmi2GetStatus" => (functions::get_status::<E>(Function::fmi2GetStatus, c, FMI2_DO_STEP_STATUS, &mut int[0]), no_value),
            "fmi2GetRealStatus" => {
                (functions::get_real_status::<E>(Function::fmi2GetRealStatus, c, FMI2_LAST_SUCCESSFUL_TIME, &mut real[0]), OK)
            }
            "fmi2GetIntegerStatus" => {
                (functions::get_integer_status::<E>(Function::fmi2GetIntegerStatus, c, FMI2_DO_STEP_STATUS, &mut int[0]), no_value)
            }
            "fmi2GetBooleanStatus" => {
                (functions::get_boolean_status::<E>(Function::fmi2GetBooleanStatus, c, FMI2_TERMINATED, &mut boolean[0]), OK)
            }
            "fmi2GetStringStatus" => {
                (functions::get_string_status::<E>(Function::fmi2GetStringStatus, c, FMI2_PENDING_STATUS, &mut string[0]), no_value)
            }
            other => panic!("no call for {other}"),
        }
    }
}

/// What identifies the instance's state: its mode and, where the standard lets it be read, its bytes.
fn snapshot<E: Model>(host: &Host<E>) -> (Mode, Option<Vec<u8>>) {
    let mode = mode(host);
    let bytes = (mode != Mode::Fatal).then(|| {
        let state = host.get_state();
        let bytes = host.serialize(state);
        host.free_state(state);
        bytes
    });
    (mode, bytes)
}

/// Checks every cell of the table; returns the number of cells checked.
fn check_table<E: Model>(subject: &Subject<E>) -> usize {
    let donor = reach(subject, Mode::StepComplete);
    let mut cells = 0;
    for (column, &state) in STATES.iter().enumerate() {
        if state == Mode::Fatal && subject.panic_step.is_none() {
            continue;
        }
        for (function, row) in TABLE {
            let allowed = row.split_whitespace().nth(column) == Some("x");
            let host = reach(subject, state);
            let before = snapshot(&host);
            let (status, (expected, why)) = call(&host, &donor, function);
            let log = host.log.lock().unwrap().clone();
            let cell = format!("{function} in {state}: {status:?}, log {log:?}");
            if allowed {
                assert_eq!(status, expected, "{cell}");
                match why {
                    None => assert!(log.is_empty(), "{cell}"),
                    Some(why) => assert!(log.iter().any(|m| m.2.contains(why)), "{cell}"),
                }
            } else {
                assert_eq!(status, Status::Error, "{cell}");
                // fmi2CancelStep is allowed in no state that can occur: in a live one its refusal says so.
                let refusal = format!("{function}: not allowed in state {state}");
                let why = |m: &str| m.contains(&refusal) || (*function == "fmi2CancelStep" && m.contains("never a step in progress"));
                assert!(log.len() == 1 && log[0].0 == Status::Error as c_int && why(&log[0].2), "{cell}");
                assert_eq!(snapshot(&host), before, "{cell}: the state changed");
            }
            cells += 1;
        }
    }
    cells
}

/// fmi2FreeInstance is a void function: it cannot refuse, so it releases the instance in every state,
/// Fatal included (the standard allows no call after fmi2Fatal; leaking would help no host): the
/// memory it gives back is at least the instance's own, and it logs nothing.
fn free_in_every_state<E: Model>(subject: &Subject<E>) {
    for state in STATES {
        if state == Mode::Fatal && subject.panic_step.is_none() {
            continue;
        }
        let host = ManuallyDrop::new(reach(subject, state));
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        let freed = freed_bytes(|| unsafe { functions::free_instance::<E>(host.c) });
        assert!(freed >= std::mem::size_of::<Component<E>>(), "{state}: {freed} bytes freed");
        assert!(host.messages().is_empty(), "{state}: {:?}", host.messages());
        // SAFETY: the instance is freed; only the log box is left to drop, once.
        drop(unsafe { std::ptr::read(&host.log) });
    }
}

fn shuttle() -> Subject<Shuttle> {
    Subject {
        configure: |_| {},
        break_step: |host| assert_eq!(host.set_real("gas_pressure", -1.0), Status::Ok),
        panic_step: Some(|host| assert_eq!(host.set_real("load_torque", 42.0), Status::Ok)),
    }
}

/// The roller variant, which refuses to step at crank_speed 0 (the crank train steps at any speed).
fn engine() -> Subject<ModelVariant> {
    Subject {
        configure: |host| assert_eq!(host.set_integer("model_variant", 2), Status::Ok),
        break_step: |host| assert_eq!(host.set_real("crank_speed", 0.0), Status::Ok),
        panic_step: None,
    }
}

#[test]
fn every_call_in_every_state_follows_the_standards_table() {
    assert_eq!(check_table(&shuttle()), STATES.len() * TABLE.len());
    assert_eq!(check_table(&engine()), (STATES.len() - 1) * TABLE.len());
}

#[test]
fn free_instance_releases_in_every_state() {
    free_in_every_state(&shuttle());
    free_in_every_state(&engine());
}
