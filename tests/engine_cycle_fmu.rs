//! EngineCycle through the crate's exported fmi2 functions: the same binary as PistonSlap makes an
//! EngineCycle instance when fmi2Instantiate gets EngineCycle's GUID, and both models' instances and
//! FMU states live side by side in one process without being mistaken for each other.

use pistonslap::fmi::fixed_argument_logger;
use pistonslap::fmi::types::{fmi2CallbackFunctions, fmi2Component, fmi2FMUstate, Status, FMI2_CO_SIMULATION, FMI2_FALSE, FMI2_TRUE};
use pistonslap::fmus::engine_cycle::EngineCycleRun;
use pistonslap::fmus::engine_cycle::Parameters as EngineCycleParameters;
use pistonslap::fmus::exports::*;
use pistonslap::fmus::{engine_cycle, piston_slap::GUID};
use std::ffi::{c_char, c_int, c_void, CString};

unsafe extern "C" fn quiet_logger(_: *mut c_void, _: *const c_char, _: c_int, _: *const c_char, _: *const c_char, _: *const c_char) {}

fn engine_vr(name: &str) -> u32 {
    engine_cycle::DESCRIPTION.value_reference(name).expect(name)
}

/// An instance of the model with `guid`, in initialization mode.
fn instantiate(guid: &str, callbacks: &fmi2CallbackFunctions) -> fmi2Component {
    let (name, guid, resources) = (CString::new("host").unwrap(), CString::new(guid).unwrap(), CString::new("file:///tmp").unwrap());
    // SAFETY: pointers to live locals; the instance is freed by the caller.
    unsafe {
        let c = fmi2Instantiate(name.as_ptr(), FMI2_CO_SIMULATION, guid.as_ptr(), resources.as_ptr(), callbacks, FMI2_FALSE, FMI2_FALSE);
        assert!(!c.is_null());
        assert_eq!(fmi2SetupExperiment(c, FMI2_FALSE, 0.0, 0.0, FMI2_FALSE, 0.0), Status::Ok);
        assert_eq!(fmi2EnterInitializationMode(c), Status::Ok);
        c
    }
}

fn callbacks() -> fmi2CallbackFunctions {
    fmi2CallbackFunctions {
        logger: Some(fixed_argument_logger(quiet_logger)),
        allocate_memory: None,
        free_memory: None,
        step_finished: None,
        component_environment: std::ptr::null_mut(),
    }
}

#[test]
fn engine_cycle_outputs_and_their_derivatives_are_the_models() {
    let callbacks = callbacks();
    let c = instantiate(engine_cycle::GUID, &callbacks);
    let ramp = [("speed_start", 100.0), ("speed_end", 200.0), ("ramp_time", 0.05), ("heat_release", 600.0)];
    let parameters =
        EngineCycleParameters { speed_start: 100.0, speed_end: 200.0, ramp_time: 0.05, heat_release: 600.0, ..Default::default() };
    let mut model = EngineCycleRun::new(&parameters, 0.0).unwrap();
    let names = ["crank_angle", "crank_speed", "cylinder_pressure", "gas_pressure", "indicated_torque"];
    let refs: Vec<u32> = names.iter().map(|n| engine_vr(n)).collect();
    let orders = [1; 5];
    // SAFETY: the instance is live until fmi2FreeInstance; the other pointers are to live locals.
    unsafe {
        for (name, value) in ramp {
            assert_eq!(fmi2SetReal(c, &engine_vr(name), 1, &value), Status::Ok, "{name}");
        }
        assert_eq!(fmi2ExitInitializationMode(c), Status::Ok);
        let (mut values, mut rates) = ([0.0; 5], [0.0; 5]);
        for k in 0..80 {
            let (t, h) = (k as f64 * 1e-3, 1e-3);
            assert_eq!(fmi2DoStep(c, t, h, FMI2_TRUE), Status::Ok);
            model.step(t + h).unwrap();
            assert_eq!(fmi2GetReal(c, refs.as_ptr(), 5, values.as_mut_ptr()), Status::Ok);
            assert_eq!(fmi2GetRealOutputDerivatives(c, refs.as_ptr(), 5, orders.as_ptr(), rates.as_mut_ptr()), Status::Ok);
            let (o, r) = (model.outputs(), model.rates());
            assert_eq!(values, [o.crank_angle, o.crank_speed, o.cylinder_pressure, o.gas_pressure, o.indicated_torque]);
            assert_eq!(rates, [r.crank_angle, r.crank_speed, r.cylinder_pressure, r.gas_pressure, r.indicated_torque]);
        }
        // The ramp ended at 0.05 s: 200 rad/s since, the angle ∫ω dt = 7.5 + 200 · 0.03.
        assert_eq!(values[1], 200.0);
        assert!((values[0] - 13.5).abs() < 1e-9, "{}", values[0]);
        // Order 2 is beyond maxOutputDerivativeOrder = 1; a parameter has no output derivative.
        assert_eq!(fmi2GetRealOutputDerivatives(c, refs.as_ptr(), 1, &2, rates.as_mut_ptr()), Status::Error);
        assert_eq!(fmi2GetRealOutputDerivatives(c, &engine_vr("bore"), 1, &1, rates.as_mut_ptr()), Status::Error);
        // EngineCycle has no inputs: nothing takes input derivatives.
        assert_eq!(fmi2SetRealInputDerivatives(c, &refs[1], 1, &1, &1.0), Status::Error);
        fmi2FreeInstance(c);
    }
}

#[test]
fn bad_engine_parameters_are_refused_at_exit_initialization() {
    let callbacks = callbacks();
    let c = instantiate(engine_cycle::GUID, &callbacks);
    // SAFETY: the instance is live until fmi2FreeInstance; the other pointers are to live locals.
    unsafe {
        assert_eq!(fmi2SetReal(c, &engine_vr("rod_length"), 1, &0.03), Status::Ok);
        assert_eq!(fmi2ExitInitializationMode(c), Status::Error);
        fmi2FreeInstance(c);
    }
}

#[test]
fn both_models_live_side_by_side_and_refuse_each_others_states() {
    let callbacks = callbacks();
    let (engine, slap) = (instantiate(engine_cycle::GUID, &callbacks), instantiate(GUID, &callbacks));
    // SAFETY: the instances are live until fmi2FreeInstance, the states until fmi2FreeFMUstate.
    unsafe {
        assert_eq!(fmi2ExitInitializationMode(engine), Status::Ok);
        assert_eq!(fmi2ExitInitializationMode(slap), Status::Ok);
        assert_eq!(fmi2DoStep(engine, 0.0, 1e-3, FMI2_TRUE), Status::Ok);
        assert_eq!(fmi2DoStep(slap, 0.0, 1e-3, FMI2_TRUE), Status::Ok);
        let (mut engine_state, mut slap_state): (fmi2FMUstate, fmi2FMUstate) = (std::ptr::null_mut(), std::ptr::null_mut());
        assert_eq!(fmi2GetFMUstate(engine, &mut engine_state), Status::Ok);
        assert_eq!(fmi2GetFMUstate(slap, &mut slap_state), Status::Ok);
        assert_eq!(fmi2SetFMUstate(engine, slap_state), Status::Error);
        assert_eq!(fmi2SetFMUstate(slap, engine_state), Status::Error);
        // Serialized states carry their model's GUID.
        let mut size = 0;
        assert_eq!(fmi2SerializedFMUstateSize(engine, engine_state, &mut size), Status::Ok);
        let mut bytes = vec![0u8; size];
        assert_eq!(fmi2SerializeFMUstate(engine, engine_state, bytes.as_mut_ptr() as *mut c_char, size), Status::Ok);
        let mut copy: fmi2FMUstate = std::ptr::null_mut();
        assert_eq!(fmi2DeSerializeFMUstate(slap, bytes.as_ptr() as *const c_char, size, &mut copy), Status::Error);
        assert_eq!(fmi2DeSerializeFMUstate(engine, bytes.as_ptr() as *const c_char, size, &mut copy), Status::Ok);
        assert_eq!(fmi2SetFMUstate(engine, copy), Status::Ok);
        // PistonSlap's own calls are unchanged: its output derivatives stay unsupported.
        let mut rate = 0.0;
        assert_eq!(fmi2GetRealOutputDerivatives(slap, &0, 1, &1, &mut rate), Status::Error);
        for (c, mut state) in [(engine, engine_state), (engine, copy), (slap, slap_state)] {
            assert_eq!(fmi2FreeFMUstate(c, &mut state), Status::Ok);
        }
        fmi2FreeInstance(engine);
        fmi2FreeInstance(slap);
    }
}
