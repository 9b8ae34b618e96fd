//! A host whose logger calls back into the instance that is logging: those calls are refused
//! (fmi2Error; fmi2FreeInstance does nothing) and the instance carries on, while the same logger
//! may call another instance.
#![allow(unsafe_code)]

use super::*;
use std::sync::atomic::{AtomicPtr, Ordering};

/// The instances the logger calls, and what its calls returned.
#[derive(Default)]
struct CallingBack {
    logging: AtomicPtr<c_void>,
    other: AtomicPtr<c_void>,
    statuses: Mutex<Vec<(&'static str, Status)>>,
}

/// Reads an output of the logging instance and of the other one, then tries to free the logging one.
unsafe extern "C" fn calling_back_logger(
    env: *mut c_void,
    _name: *const c_char,
    _status: c_int,
    _category: *const c_char,
    _format: *const c_char,
    _message: *const c_char,
) {
    let host = &*(env as *const CallingBack);
    let (logging, other) = (host.logging.load(Ordering::SeqCst), host.other.load(Ordering::SeqCst));
    let mut value = 0.0;
    let own = functions::get_real::<Shuttle>(Function::fmi2GetReal, logging, &vr("crank_angle"), 1, &mut value);
    let others = functions::get_real::<Shuttle>(Function::fmi2GetReal, other, &vr("crank_angle"), 1, &mut value);
    functions::free_instance::<Shuttle>(logging);
    host.statuses.lock().unwrap().extend([("own", own), ("other", others)]);
}

#[test]
fn a_logger_calling_back_into_its_instance_is_refused_and_the_instance_carries_on() {
    let other = ShuttleHost::initialized();
    let calling_back = Box::new(CallingBack::default());
    let functions = fmi2CallbackFunctions {
        logger: Some(fixed_argument_logger(calling_back_logger)),
        allocate_memory: None,
        free_memory: None,
        step_finished: None,
        component_environment: &*calling_back as *const CallingBack as *mut c_void,
    };
    let guid = CString::new(GUID).unwrap();
    // SAFETY: an instance this test made and has not freed; the other pointers are NULL or live locals.
    let c = unsafe {
        functions::instantiate::<Shuttle>(
            c"logging".as_ptr(),
            FMI2_CO_SIMULATION,
            guid.as_ptr(),
            RESOURCES.as_ptr(),
            &functions,
            FMI2_FALSE,
        )
    };
    assert!(!c.is_null());
    calling_back.logging.store(c, Ordering::SeqCst);
    calling_back.other.store(other.c, Ordering::SeqCst);
    let host = ShuttleHost { c, log: Box::default(), model: PhantomData };
    assert_eq!(host.setup(0.0, None), Status::Ok);
    assert_eq!(host.enter(), Status::Ok);
    assert_eq!(host.exit(), Status::Ok);

    // A refused step logs its error, and the logger calls back.
    assert_eq!(host.step(0.0, -1.0), Status::Error);
    assert_eq!(*calling_back.statuses.lock().unwrap(), [("own", Status::Error), ("other", Status::Ok)]);
    // Not freed: it steps on as the other does, and `host` frees it when dropped.
    for h in [&host, &other] {
        assert_eq!(h.step(0.0, 0.01), Status::Ok);
    }
    assert_eq!(host.output_bits(), other.output_bits());
}
