//! The registry reaches every FMU through the exported functions: the toy FMU of the tests (`fmus/toy/`, one
//! registry line) beside the shipped ones, each instance made by its GUID and every later call going to the
//! FMU that made it.

use super::*;
use crate::fmus::exports::*;
use crate::fmus::{engine_cycle, toy};

/// An instance the exported fmi2Instantiate makes for `guid`, and the log it writes to.
fn instantiate(guid: &str) -> (fmi2Component, Box<Log>) {
    let log = Box::new(Log::default());
    let functions = callbacks(&log);
    let guid = CString::new(guid).unwrap();
    // SAFETY: live C strings and callbacks; the instance is freed by the caller.
    let c = unsafe { fmi2Instantiate(c"registry".as_ptr(), FMI2_CO_SIMULATION, guid.as_ptr(), RESOURCES.as_ptr(), &functions, 0, 0) };
    (c, log)
}

#[test]
fn each_guid_makes_its_own_fmu_and_later_calls_reach_it() {
    for (guid, tag) in [
        (toy::GUID, <toy::Fmu as Model>::INSTANCE_TAG),
        (engine_cycle::GUID, <engine_cycle::Fmu as Model>::INSTANCE_TAG),
        (GUID, <ModelVariant as Model>::INSTANCE_TAG),
    ] {
        let (c, _log) = instantiate(guid);
        // SAFETY: the instance just made; freed once.
        unsafe {
            assert_eq!(functions::instance_tag(c), Some(tag), "{guid}");
            fmi2FreeInstance(c);
        }
    }
    // A GUID no FMU claims goes to the last, which refuses it.
    let (c, log) = instantiate("{nobody}");
    assert!(c.is_null());
    assert!(log.lock().unwrap().iter().any(|m| m.2.contains("GUID")), "{:?}", log.lock().unwrap());
}

#[test]
fn the_toy_fmu_steps_through_the_exported_functions() {
    let (c, log) = instantiate(toy::GUID);
    let (u, y, tau) = (0, 1, 2);
    // SAFETY: the instance just made, its value references from its table; freed once at the end.
    unsafe {
        assert_eq!(fmi2SetReal(c, &tau, 1, &0.5), Status::Ok);
        assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), Status::Ok);
        assert_eq!(fmi2EnterInitializationMode(c), Status::Ok);
        assert_eq!(fmi2ExitInitializationMode(c), Status::Ok, "{:?}", log.lock().unwrap());
        assert_eq!(fmi2SetReal(c, &u, 1, &2.0), Status::Ok);
        assert_eq!(fmi2DoStep(c, 0.0, 0.25, 1), Status::Ok);
        let mut value = f64::NAN;
        assert_eq!(fmi2GetReal(c, &y, 1, &mut value), Status::Ok);
        // y(t) = u (1 − e^(−t/τ)) from y(0) = 0.
        assert!((value - 2.0 * (1.0 - libm::exp(-0.5))).abs() < 1e-15, "{value}");
        fmi2FreeInstance(c);
    }
}
