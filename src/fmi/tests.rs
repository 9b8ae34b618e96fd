//! The FMI layer through its C-level functions (`functions`, which the exports call with the shipped
//! engine), driven with the test-only shuttle model whose impacts have closed-form times.
#![allow(unsafe_code)]

use super::description;
use super::fixed_argument_logger;
use super::functions;
use super::instance::Model;
use super::state_machine::Function;
use super::types::*;
use crate::fmus::piston_slap::simulation::test_model::{Shuttle, SHUTTLE_SPEED};
use crate::fmus::piston_slap::simulation::ModelVariant;
use crate::fmus::piston_slap::{self as slap, GUID, VARIABLES};
use std::ffi::{c_char, c_int, c_void, CStr, CString};
use std::marker::PhantomData;
use std::ptr::{null, null_mut};
use std::sync::Mutex;

type Log = Mutex<Vec<(c_int, String, String)>>;

/// Receives `logger(env, name, status, category, "%s", message)` (see `fixed_argument_logger`).
unsafe extern "C" fn test_logger(
    env: *mut c_void,
    _name: *const c_char,
    status: c_int,
    category: *const c_char,
    format: *const c_char,
    message: *const c_char,
) {
    assert_eq!(CStr::from_ptr(format).to_str(), Ok("%s"));
    let log = &*(env as *const Log);
    let text = |p| CStr::from_ptr(p).to_string_lossy().into_owned();
    log.lock().unwrap().push((status, text(category), text(message)));
}

fn callbacks(log: &Log) -> fmi2CallbackFunctions {
    fmi2CallbackFunctions {
        logger: Some(fixed_argument_logger(test_logger)),
        allocate_memory: None,
        free_memory: None,
        step_finished: None,
        component_environment: log as *const Log as *mut c_void,
    }
}

fn vr(name: &str) -> u32 {
    slap::value_reference(name).expect(name)
}

/// A host holding one instance of the FMU with engine model `E`.
struct Host<E: Model> {
    c: fmi2Component,
    log: Box<Log>,
    model: PhantomData<E>,
}

type ShuttleHost = Host<Shuttle>;

const RESOURCES: &CStr = c"file:///tmp/pistonslap/resources";

/// Variant 2 with the thesis's mechanism (ξ = 0.303, α = 1.9, β = 0.4719 with l = M = 1, ρ = 0.02,
/// λ = 0.05): the parameters the roller tests set.
const THESIS_MECHANISM: [(&str, f64); 7] = [
    ("crank_radius", 0.303),
    ("rod_length", 1.0),
    ("rod_mass", 1.9),
    ("piston_mass", 1.0),
    ("rod_inertia", 0.4719),
    ("damping_crank_pin", 0.05),
    ("bore", 0.12),
];

impl<E: Model> Host<E> {
    fn new() -> Self {
        Self::try_new(c"test", FMI2_CO_SIMULATION, &CString::new(GUID).unwrap(), RESOURCES.as_ptr()).unwrap()
    }

    fn try_new(name: &CStr, fmu_type: c_int, guid: &CStr, resources: *const c_char) -> Result<Self, String> {
        let log = Box::new(Log::default());
        let functions = callbacks(&log);
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        let c = unsafe { functions::instantiate::<E>(name.as_ptr(), fmu_type, guid.as_ptr(), resources, &functions, FMI2_FALSE) };
        if c.is_null() {
            Err(log.lock().unwrap().iter().map(|m| m.2.clone()).collect::<Vec<_>>().join("\n"))
        } else {
            Ok(Self { c, log, model: PhantomData })
        }
    }

    /// Instantiated → initialization mode → step mode at t = 0, stop time 1 s.
    fn initialized() -> Self {
        let host = Self::new();
        assert_eq!(host.setup(0.0, Some(1.0)), Status::Ok);
        assert_eq!(host.enter(), Status::Ok);
        assert_eq!(host.exit(), Status::Ok);
        host
    }

    fn setup(&self, start: f64, stop: Option<f64>) -> Status {
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        unsafe {
            functions::setup_experiment::<E>(Function::fmi2SetupExperiment, self.c, start, stop.is_some() as c_int, stop.unwrap_or(0.0))
        }
    }
    fn enter(&self) -> Status {
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        unsafe { functions::enter_initialization_mode::<E>(Function::fmi2EnterInitializationMode, self.c) }
    }
    fn exit(&self) -> Status {
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        unsafe { functions::exit_initialization_mode::<E>(Function::fmi2ExitInitializationMode, self.c) }
    }
    fn step(&self, t: f64, h: f64) -> Status {
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        unsafe { functions::do_step::<E>(Function::fmi2DoStep, self.c, t, h) }
    }
    fn set_real(&self, name: &str, value: f64) -> Status {
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        unsafe { functions::set_real::<E>(Function::fmi2SetReal, self.c, &vr(name), 1, &value) }
    }
    fn set_integer(&self, name: &str, value: i32) -> Status {
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        unsafe { functions::set_integer::<E>(Function::fmi2SetInteger, self.c, &vr(name), 1, &value) }
    }
    fn real(&self, name: &str) -> f64 {
        let mut value = f64::NAN;
        assert_eq!(
            // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
            unsafe { functions::get_real::<E>(Function::fmi2GetReal, self.c, &vr(name), 1, &mut value) },
            Status::Ok,
            "{name}"
        );
        value
    }
    fn integer(&self, name: &str) -> i32 {
        let mut value = -1;
        assert_eq!(
            // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
            unsafe { functions::get_integer::<E>(Function::fmi2GetInteger, self.c, &vr(name), 1, &mut value) },
            Status::Ok,
            "{name}"
        );
        value
    }
    /// Every Real and Integer output, as bits: for bit-identical comparisons.
    fn output_bits(&self) -> Vec<u64> {
        VARIABLES
            .iter()
            .filter(|v| v.causality == description::Causality::Output)
            .map(|v| match v.kind {
                description::Kind::Real => self.real(v.name).to_bits(),
                _ => self.integer(v.name) as u64,
            })
            .collect()
    }
    fn get_state(&self) -> fmi2FMUstate {
        let mut state = null_mut();
        assert_eq!(
            // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
            unsafe { functions::get_fmu_state::<E>(Function::fmi2GetFMUstate, self.c, &mut state) },
            Status::Ok
        );
        state
    }
    fn set_state(&self, state: fmi2FMUstate) -> Status {
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        unsafe { functions::set_fmu_state::<E>(Function::fmi2SetFMUstate, self.c, state) }
    }
    fn free_state(&self, mut state: fmi2FMUstate) {
        assert_eq!(
            // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
            unsafe { functions::free_fmu_state::<E>(Function::fmi2FreeFMUstate, self.c, &mut state) },
            Status::Ok
        );
        assert!(state.is_null());
    }
    fn serialize(&self, state: fmi2FMUstate) -> Vec<u8> {
        let mut size = 0;
        assert_eq!(
            // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
            unsafe { functions::serialized_fmu_state_size::<E>(Function::fmi2SerializedFMUstateSize, self.c, state, &mut size) },
            Status::Ok
        );
        let mut bytes = vec![0u8; size];
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        let status =
            unsafe { functions::serialize_fmu_state::<E>(Function::fmi2SerializeFMUstate, self.c, state, bytes.as_mut_ptr(), size) };
        assert_eq!(status, Status::Ok);
        bytes
    }
    fn deserialize(&self, bytes: &[u8]) -> (Status, fmi2FMUstate) {
        let mut state = null_mut();
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        let status = unsafe {
            functions::deserialize_fmu_state::<E>(Function::fmi2DeSerializeFMUstate, self.c, bytes.as_ptr(), bytes.len(), &mut state)
        };
        (status, state)
    }
    fn run(&self, from: f64, to: f64, h: f64) {
        let n = ((to - from) / h).round() as usize;
        for k in 0..n {
            let t = from + k as f64 * h;
            assert_eq!(self.step(t, h), Status::Ok, "step at {t}: {:?}", self.messages());
        }
    }
    fn messages(&self) -> Vec<String> {
        self.log.lock().unwrap().iter().map(|m| m.2.clone()).collect()
    }
    /// The last message logged, which must exist and contain `part`.
    fn logged(&self, part: &str) {
        let last = self.log.lock().unwrap().last().cloned();
        let (status, category, message) = last.unwrap_or_else(|| panic!("nothing logged, expected {part:?}"));
        assert!(message.contains(part), "{message:?} should contain {part:?}");
        assert!(status == Status::Error as c_int || status == Status::Fatal as c_int || category == "logEvents");
    }
}

impl<E: Model> Drop for Host<E> {
    fn drop(&mut self) {
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        unsafe { functions::free_instance::<E>(self.c) }
    }
}

#[test]
fn a_full_cycle_gives_the_closed_form_impacts() {
    let host = ShuttleHost::initialized();
    assert_eq!(host.real("piston_lateral_velocity"), SHUTTLE_SPEED);
    host.run(0.0, 0.1, 1e-3);
    // Impacts at 4, 20 and 52 ms with e = 0.5 (see the shuttle): three, the last on the +x wall.
    assert_eq!(host.integer("impact_count"), 3);
    assert_eq!(host.integer("last_impact_corner"), 3);
    assert!((host.real("impact_velocity") - 0.25 * SHUTTLE_SPEED).abs() < 1e-15);
    // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
    assert_eq!(unsafe { functions::terminate::<Shuttle>(Function::fmi2Terminate, host.c) }, Status::Ok);
    assert_eq!(host.integer("impact_count"), 3, "outputs stay readable after fmi2Terminate");
    assert!(host.messages().is_empty(), "{:?}", host.messages());
}

#[test]
fn calls_in_states_the_standard_forbids_are_refused_and_change_nothing() {
    let host = ShuttleHost::new();
    assert_eq!(host.step(0.0, 1e-3), Status::Error);
    host.logged("fmi2DoStep: not allowed in state Instantiated");
    assert_eq!(host.exit(), Status::Error);
    let mut x = 0.0;
    assert_eq!(
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        unsafe { functions::get_real::<Shuttle>(Function::fmi2GetReal, host.c, &vr("crank_angle"), 1, &mut x) },
        Status::Error
    );
    // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
    assert_eq!(unsafe { functions::terminate::<Shuttle>(Function::fmi2Terminate, host.c) }, Status::Error);
    assert_eq!(host.enter(), Status::Ok);
    assert_eq!(host.setup(0.0, None), Status::Error, "setup only before initialization");
    assert_eq!(host.enter(), Status::Error);
    assert_eq!(host.exit(), Status::Ok);
    assert_eq!(host.set_real("restitution", 0.9), Status::Error);
    host.logged("fixed parameter");
    assert_eq!(host.real("restitution"), 0.5);
    assert_eq!(host.set_real("crank_speed", 100.0), Status::Ok, "inputs may be set in step mode");
    assert_eq!(
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        unsafe { functions::cancel_step::<Shuttle>(Function::fmi2CancelStep, host.c) },
        Status::Error
    );
    // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
    assert_eq!(unsafe { functions::terminate::<Shuttle>(Function::fmi2Terminate, host.c) }, Status::Ok);
    assert_eq!(host.step(0.0, 1e-3), Status::Error);
    host.logged("not allowed in state Terminated");
    // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
    assert_eq!(unsafe { functions::reset::<Shuttle>(Function::fmi2Reset, host.c) }, Status::Ok);
    assert_eq!(host.setup(0.0, None), Status::Ok, "back to instantiated after fmi2Reset");
    assert_eq!(host.enter(), Status::Ok);
    assert_eq!(host.exit(), Status::Ok);
    assert_eq!(host.step(0.0, 1e-3), Status::Ok);
}

#[test]
fn null_pointers_unknown_references_and_wrong_types_are_refused() {
    let host = ShuttleHost::initialized();
    let mut x = 0.0;
    let mut i = 0;
    // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
    unsafe {
        assert_eq!(functions::do_step::<Shuttle>(Function::fmi2DoStep, null_mut(), 0.0, 1e-3), Status::Error);
        assert_eq!(functions::get_real::<Shuttle>(Function::fmi2GetReal, host.c, null(), 1, &mut x), Status::Error);
        host.logged("vr is NULL");
        assert_eq!(functions::get_real::<Shuttle>(Function::fmi2GetReal, host.c, &vr("crank_angle"), 1, null_mut()), Status::Error);
        assert_eq!(functions::set_real::<Shuttle>(Function::fmi2SetReal, host.c, &vr("crank_speed"), 1, null()), Status::Error);
        assert_eq!(functions::get_real::<Shuttle>(Function::fmi2GetReal, host.c, null(), 0, null_mut()), Status::Ok, "nothing asked");
        assert_eq!(functions::get_real::<Shuttle>(Function::fmi2GetReal, host.c, &9999, 1, &mut x), Status::Error);
        host.logged("unknown value reference 9999");
        assert_eq!(functions::get_integer::<Shuttle>(Function::fmi2GetInteger, host.c, &vr("crank_angle"), 1, &mut i), Status::Error);
        host.logged("not Integer");
        let mut b = 0;
        assert_eq!(functions::get_boolean::<Shuttle>(Function::fmi2GetBoolean, host.c, &vr("crank_angle"), 1, &mut b), Status::Error);
        assert_eq!(functions::set_boolean::<Shuttle>(Function::fmi2SetBoolean, host.c, &0, 1, &1), Status::Error);
        assert_eq!(functions::set_string::<Shuttle>(Function::fmi2SetString, host.c, &vr("impact_log"), 1, &null()), Status::Error);
        let mut state = null_mut();
        assert_eq!(functions::get_fmu_state::<Shuttle>(Function::fmi2GetFMUstate, host.c, null_mut()), Status::Error);
        assert_eq!(functions::set_fmu_state::<Shuttle>(Function::fmi2SetFMUstate, host.c, null_mut()), Status::Error);
        assert_eq!(
            functions::free_fmu_state::<Shuttle>(Function::fmi2FreeFMUstate, host.c, &mut state),
            Status::Ok,
            "freeing NULL is a no-op"
        );
        assert_eq!(
            functions::serialized_fmu_state_size::<Shuttle>(Function::fmi2SerializedFMUstateSize, host.c, null_mut(), &mut 0),
            Status::Error
        );
        let mut fake = [0u64; 8];
        assert_eq!(
            functions::set_fmu_state::<Shuttle>(Function::fmi2SetFMUstate, host.c, fake.as_mut_ptr() as fmi2FMUstate),
            Status::Error
        );
        host.logged("not made by this FMU");
        assert_eq!(functions::get_status::<Shuttle>(Function::fmi2GetStatus, host.c, FMI2_DO_STEP_STATUS, null_mut()), Status::Error);
    }
    assert_eq!(host.set_real("impact_velocity", 1.0), Status::Error);
    host.logged("is an output");
    // A mixed list is all or nothing: the valid first value is not applied.
    let (vrs, values) = ([vr("crank_speed"), 9999], [50.0, 1.0]);
    assert_eq!(
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        unsafe { functions::set_real::<Shuttle>(Function::fmi2SetReal, host.c, vrs.as_ptr(), 2, values.as_ptr()) },
        Status::Error
    );
    assert_eq!(host.real("crank_speed"), 125.66);
}

#[test]
fn non_finite_inputs_bad_steps_and_wrong_times_leave_the_state_unchanged() {
    let host = ShuttleHost::initialized();
    host.run(0.0, 0.01, 1e-3);
    let before = host.output_bits();
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert_eq!(host.set_real("crank_speed", bad), Status::Error);
        host.logged("must be finite");
        assert_eq!(host.real("crank_speed"), 125.66);
    }
    for (t, h, why) in [
        (0.01, 0.0, "must be finite and > 0"),
        (0.01, -1e-3, "must be finite and > 0"),
        (0.01, f64::NAN, "must be finite and > 0"),
        (0.01, f64::INFINITY, "must be finite and > 0"),
        (0.0, 1e-3, "is not the FMU's current time"),
        (0.02, 1e-3, "is not the FMU's current time"),
        (f64::NAN, 1e-3, "is not the FMU's current time"),
        (0.01, 5.0, "beyond stopTime"),
    ] {
        assert_eq!(host.step(t, h), Status::Error, "t = {t}, h = {h}");
        host.logged(why);
    }
    assert_eq!(host.output_bits(), before);
    // A host's accumulated round-off in the communication point is tolerated.
    assert_eq!(host.step(0.01 + 1e-15, 1e-3), Status::Ok);
}

#[test]
fn instantiate_checks_its_arguments() {
    let guid = CString::new(GUID).unwrap();
    let refused = |name: &CStr, fmu_type, guid: &CStr, resources: *const c_char, why: &str| {
        let err = ShuttleHost::try_new(name, fmu_type, guid, resources).err().expect(why);
        assert!(err.contains(why), "{err:?} should contain {why:?}");
    };
    refused(c"test", FMI2_CO_SIMULATION, c"{00000000-0000-0000-0000-000000000000}", RESOURCES.as_ptr(), "does not match");
    refused(c"test", 0, &guid, RESOURCES.as_ptr(), "Co-Simulation");
    refused(c"test", FMI2_CO_SIMULATION, &guid, null(), "fmuResourceLocation is NULL");
    refused(c"test", FMI2_CO_SIMULATION, &guid, c"http://example.com/r".as_ptr(), "not a file URI");
    refused(c"", FMI2_CO_SIMULATION, &guid, RESOURCES.as_ptr(), "instanceName is empty");
    let log = Log::default();
    let mut functions = callbacks(&log);
    // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
    unsafe {
        let c = functions::instantiate::<Shuttle>(null(), 1, guid.as_ptr(), RESOURCES.as_ptr(), &functions, 0);
        assert!(c.is_null());
        assert!(functions::instantiate::<Shuttle>(c"x".as_ptr(), 1, guid.as_ptr(), RESOURCES.as_ptr(), null(), 0).is_null());
        functions.logger = None;
        assert!(functions::instantiate::<Shuttle>(c"x".as_ptr(), 1, guid.as_ptr(), RESOURCES.as_ptr(), &functions, 0).is_null());
        functions::free_instance::<Shuttle>(null_mut());
    }
}

#[test]
fn bad_parameters_are_refused_at_exit_initialization_mode_by_name() {
    let host = ShuttleHost::new();
    assert_eq!(host.enter(), Status::Ok);
    assert_eq!(host.set_real("piston_mass", -0.4), Status::Ok, "ranges are checked at exit");
    let mut x = 0.0;
    // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
    let status = unsafe { functions::get_real::<Shuttle>(Function::fmi2GetReal, host.c, &vr("piston_lateral"), 1, &mut x) };
    assert_eq!(status, Status::Error, "no initial outputs from bad parameters");
    assert_eq!(host.exit(), Status::Error);
    host.logged("piston_mass");
    assert_eq!(host.step(0.0, 1e-3), Status::Error);
    host.logged("state Error");
    // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
    assert_eq!(unsafe { functions::reset::<Shuttle>(Function::fmi2Reset, host.c) }, Status::Ok);
    assert_eq!(host.enter(), Status::Ok);
    assert_eq!(host.set_integer("model_variant", 3), Status::Ok);
    assert_eq!(host.exit(), Status::Error);
    host.logged("model_variant");
}

#[test]
fn a_panic_is_contained_as_fatal() {
    let host = ShuttleHost::initialized();
    assert_eq!(host.set_real("load_torque", 42.0), Status::Ok);
    assert_eq!(host.step(0.0, 1e-3), Status::Fatal);
    host.logged("internal error (panic");
    let mut x = 0.0;
    assert_eq!(
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        unsafe { functions::get_real::<Shuttle>(Function::fmi2GetReal, host.c, &vr("crank_angle"), 1, &mut x) },
        Status::Error
    );
    assert_eq!(
        // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
        unsafe { functions::reset::<Shuttle>(Function::fmi2Reset, host.c) },
        Status::Error,
        "fatal: only fmi2FreeInstance"
    );
}

#[test]
fn strings_status_queries_and_debug_logging() {
    let host = ShuttleHost::new();
    let path = std::env::temp_dir().join(format!("pistonslap_fmi_{}.csv", std::process::id()));
    let path_c = CString::new(path.to_str().unwrap()).unwrap();
    // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
    unsafe {
        assert_eq!(functions::set_string::<Shuttle>(Function::fmi2SetString, host.c, &vr("impact_log"), 1, &path_c.as_ptr()), Status::Ok);
        let on = [c"logEvents".as_ptr()];
        assert_eq!(functions::set_debug_logging::<Shuttle>(Function::fmi2SetDebugLogging, host.c, FMI2_TRUE, 1, on.as_ptr()), Status::Ok);
        let unknown = [c"logEverything".as_ptr()];
        assert_eq!(
            functions::set_debug_logging::<Shuttle>(Function::fmi2SetDebugLogging, host.c, FMI2_TRUE, 1, unknown.as_ptr()),
            Status::Error
        );
    }
    assert_eq!(host.enter(), Status::Ok);
    assert_eq!(host.exit(), Status::Ok);
    let mut s: fmi2String = null();
    // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
    unsafe {
        assert_eq!(functions::get_string::<Shuttle>(Function::fmi2GetString, host.c, &vr("impact_log"), 1, &mut s), Status::Ok);
        assert_eq!(CStr::from_ptr(s), path_c.as_c_str());
    }
    host.run(0.0, 0.005, 1e-3);
    host.logged("Impact");
    assert_eq!(std::fs::read_to_string(&path).unwrap().lines().count(), 3, "the two header lines and the impact at 4 ms");
    // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
    unsafe {
        let mut t = 0.0;
        assert_eq!(
            functions::get_real_status::<Shuttle>(Function::fmi2GetRealStatus, host.c, FMI2_LAST_SUCCESSFUL_TIME, &mut t),
            Status::Ok
        );
        assert!((t - 0.005).abs() < 1e-15);
        let mut status = 0;
        assert_eq!(functions::get_status::<Shuttle>(Function::fmi2GetStatus, host.c, FMI2_DO_STEP_STATUS, &mut status), Status::Discard);
        assert_eq!(functions::get_status::<Shuttle>(Function::fmi2GetStatus, host.c, FMI2_PENDING_STATUS, &mut status), Status::Discard);
        let mut terminated = FMI2_TRUE;
        assert_eq!(
            functions::get_boolean_status::<Shuttle>(Function::fmi2GetBooleanStatus, host.c, FMI2_TERMINATED, &mut terminated),
            Status::Ok
        );
        assert_eq!(terminated, FMI2_FALSE);
        assert_eq!(functions::get_directional_derivative::<Shuttle>(Function::fmi2GetDirectionalDerivative, host.c), Status::Error);
        let mut rate = 0.0;
        assert_eq!(
            functions::get_real_output_derivatives::<Shuttle>(
                Function::fmi2GetRealOutputDerivatives,
                host.c,
                &vr("crank_angle"),
                1,
                &1,
                &mut rate
            ),
            Status::Error
        );
    }
    std::fs::remove_file(&path).unwrap();
}

mod fmi3;
mod fmu_state;
mod fuzz;
mod reentry;
mod registry;
mod state_machine;
mod threads;
