//! The fmi3 symbols as an FMI 3.0 host calls them, on the toy FMU (`fmus/toy/`): instantiation and its refusals,
//! the experiment at fmi3EnterInitializationMode, the independent variable, the values' count, doStep's flags,
//! the state machine's names, and the refusals of what the FMUs declare absent, each logged through FMI 3.0's
//! logger.

use super::*;
use crate::fmus::exports::*;
use crate::fmus::toy;

/// Receives FMI 3.0's `logMessage(env, status, category, message)`.
unsafe extern "C" fn log_message(env: fmi3InstanceEnvironment, status: c_int, category: fmi3String, message: fmi3String) {
    let log = &*(env as *const Log);
    let text = |p| CStr::from_ptr(p).to_string_lossy().into_owned();
    log.lock().unwrap().push((status, text(category), text(message)));
}

/// An instance fmi3InstantiateCoSimulation makes for `token` (Event Mode asked for or not), and its log.
fn instantiate(token: &str, event_mode_used: bool) -> (fmi3Instance, Box<Log>) {
    let log = Box::new(Log::default());
    let token = CString::new(token).unwrap();
    let environment = &*log as *const Log as *mut c_void;
    // SAFETY: live C strings and logger; the instance is freed by the caller.
    let c = unsafe {
        fmi3InstantiateCoSimulation(
            c"fmi3".as_ptr(),
            token.as_ptr(),
            c"/tmp/pistonslap/resources/".as_ptr(),
            FMI3_FALSE,
            FMI3_TRUE,
            u8::from(event_mode_used),
            FMI3_TRUE,
            null(),
            0,
            environment,
            Some(log_message),
            None,
        )
    };
    (c, log)
}

fn logged(log: &Log, part: &str) -> bool {
    log.lock().unwrap().iter().any(|(status, _, message)| *status == Status::Error as c_int && message.contains(part))
}

#[test]
fn the_toy_fmu_runs_through_the_fmi3_functions_as_through_the_fmi2_ones() {
    let (c, log) = instantiate(toy::GUID, false);
    assert!(!c.is_null(), "{:?}", log.lock().unwrap());
    let (u, y, tau, time) = (0, 1, 2, 3);
    let (mut event, mut terminate, mut early, mut reached) = (FMI3_TRUE, FMI3_TRUE, FMI3_TRUE, f64::NAN);
    let mut value = f64::NAN;
    // SAFETY: the instance just made, its value references from its table; freed once at the end.
    unsafe {
        assert_eq!(fmi3SetFloat64(c, &tau, 1, &0.5, 1), Status::Ok);
        assert_eq!(fmi3EnterInitializationMode(c, FMI3_FALSE, 0.0, 1.0, FMI3_TRUE, 2.0), Status::Ok);
        assert_eq!(fmi3GetFloat64(c, &time, 1, &mut value, 1), Status::Ok);
        assert_eq!(value, 1.0, "time is the start time before the run");
        assert_eq!(fmi3ExitInitializationMode(c), Status::Ok, "{:?}", log.lock().unwrap());
        assert_eq!(fmi3SetFloat64(c, &u, 1, &2.0, 1), Status::Ok);
        assert_eq!(fmi3DoStep(c, 1.0, 0.25, FMI3_TRUE, &mut event, &mut terminate, &mut early, &mut reached), Status::Ok);
        assert_eq!((event, terminate, early, reached), (FMI3_FALSE, FMI3_FALSE, FMI3_FALSE, 1.25));
        let (vrs, mut values) = ([y, time], [f64::NAN; 2]);
        assert_eq!(fmi3GetFloat64(c, vrs.as_ptr(), 2, values.as_mut_ptr(), 2), Status::Ok);
        // y(t) = u (1 − e^(−t/τ)) from y(0) = 0, as through fmi2DoStep.
        assert!((values[0] - 2.0 * (1.0 - libm::exp(-0.5))).abs() < 1e-15 && values[1] == 1.25, "{values:?}");
        // The stop time holds; the values' count must match; time is not settable.
        assert_eq!(fmi3DoStep(c, 1.25, 1.0, FMI3_TRUE, &mut event, &mut terminate, &mut early, &mut reached), Status::Error);
        assert!(logged(&log, "fmi3DoStep: step to 2.25 s goes beyond stopTime = 2 s"));
        assert_eq!(fmi3GetFloat64(c, vrs.as_ptr(), 2, values.as_mut_ptr(), 1), Status::Error);
        assert!(logged(&log, "fmi3GetFloat64: nValues = 1 for 2 value references: every variable is a scalar"));
        assert_eq!(fmi3SetFloat64(c, &time, 1, &0.0, 1), Status::Error);
        // The state machine speaks FMI 3.0.
        assert_eq!(fmi3EnterInitializationMode(c, FMI3_FALSE, 0.0, 0.0, FMI3_FALSE, 0.0), Status::Error);
        assert!(logged(&log, "fmi3EnterInitializationMode: not allowed in state StepMode (allowed in: Instantiated)"));
        assert_eq!(fmi3Terminate(c), Status::Ok);
        assert_eq!(fmi3Reset(c), Status::Ok);
        fmi3FreeInstance(c);
    }
}

#[test]
fn what_the_fmus_declare_absent_is_refused_with_the_reason() {
    let (c, log) = instantiate(toy::GUID, false);
    let (vr, mut boolean, mut n) = (0, FMI3_FALSE, 0_usize);
    // SAFETY: the instance just made; freed once at the end.
    unsafe {
        assert_eq!(fmi3EnterInitializationMode(c, FMI3_FALSE, 0.0, 0.0, FMI3_FALSE, 0.0), Status::Ok);
        assert_eq!(fmi3GetBoolean(c, &vr, 1, &mut boolean, 1), Status::Error);
        assert!(logged(&log, "fmi3GetBoolean: u (value reference 0) is a Real variable, not Boolean"));
        assert_eq!(fmi3GetInt8(c, null(), 0, null_mut(), 0), Status::Ok, "nothing asked");
        assert_eq!(fmi3EnterEventMode(c), Status::Error);
        assert!(logged(&log, "fmi3EnterEventMode: no Event Mode (hasEventMode = false)"));
        assert_eq!(fmi3GetNumberOfContinuousStates(c, &mut n), Status::Error);
        assert!(logged(&log, "fmi3GetNumberOfContinuousStates: Model Exchange only"));
        fmi3FreeInstance(c);
    }
    // A token no FMU claims, Event Mode, and the other interface types are refused at instantiation.
    let (c, log) = instantiate("{nobody}", false);
    assert!(c.is_null() && logged(&log, "fmi3InstantiateCoSimulation: instantiationToken {nobody} does not match"));
    let (c, log) = instantiate(toy::GUID, true);
    assert!(c.is_null() && logged(&log, "eventModeUsed = true refused: Lag has no Event Mode"));
    let environment = &*log as *const Log as *mut c_void;
    // SAFETY: live C strings and logger.
    let c = unsafe { fmi3InstantiateModelExchange(c"me".as_ptr(), null(), null(), FMI3_FALSE, FMI3_FALSE, environment, Some(log_message)) };
    assert!(c.is_null() && logged(&log, "fmi3InstantiateModelExchange: refused: the FMU implements Co-Simulation only"));
}
