//! A host of the FMU's exported C functions in the same process, written in Rust so that a host's
//! own cost stays out of what is measured: shared by `benches/fmu.rs` and the allocation test.

use pistonslap::fmi::exports::*;
use pistonslap::fmi::fixed_argument_logger;
use pistonslap::fmi::types::{fmi2CallbackFunctions, fmi2Component, Status, FMI2_CO_SIMULATION, FMI2_FALSE};
use pistonslap::fmus::piston_slap::{value_reference, GUID};
use std::ffi::{c_char, c_int, c_void, CString};

/// Receives `logger(env, name, status, category, "%s", message)` and drops it.
unsafe extern "C" fn quiet_logger(_: *mut c_void, _: *const c_char, _: c_int, _: *const c_char, _: *const c_char, _: *const c_char) {}

/// The value reference of variable `name`, which must exist.
pub fn vr(name: &str) -> u32 {
    value_reference(name).expect(name)
}

fn ok(status: Status, what: &str) {
    assert_eq!(status, Status::Ok, "{what}");
}

/// An instance initialized with `integers` and `reals` set, ready to step from t = 0.
pub struct Host {
    c: fmi2Component,
    _callbacks: Box<fmi2CallbackFunctions>,
}

impl Host {
    pub fn new(integers: &[(&str, i32)], reals: &[(&str, f64)]) -> Self {
        let callbacks = Box::new(fmi2CallbackFunctions {
            logger: Some(fixed_argument_logger(quiet_logger)),
            allocate_memory: Some(libc::calloc),
            free_memory: Some(libc::free),
            step_finished: None,
            component_environment: std::ptr::null_mut(),
        });
        let (name, guid, resources) = (CString::new("host").unwrap(), CString::new(GUID).unwrap(), CString::new("file:///tmp").unwrap());
        // SAFETY: the instance is this host's, live until `drop`; the other pointers are to live locals.
        unsafe {
            let c =
                fmi2Instantiate(name.as_ptr(), FMI2_CO_SIMULATION, guid.as_ptr(), resources.as_ptr(), &*callbacks, FMI2_FALSE, FMI2_FALSE);
            assert!(!c.is_null(), "instantiate");
            ok(fmi2SetupExperiment(c, FMI2_FALSE, 0.0, 0.0, FMI2_FALSE, 0.0), "setup");
            ok(fmi2EnterInitializationMode(c), "enter initialization");
            for &(n, v) in integers {
                ok(fmi2SetInteger(c, &vr(n), 1, &v), n);
            }
            for &(n, v) in reals {
                ok(fmi2SetReal(c, &vr(n), 1, &v), n);
            }
            ok(fmi2ExitInitializationMode(c), "exit initialization");
            Self { c, _callbacks: callbacks }
        }
    }

    /// fmi2DoStep from `t` over `h`, then fmi2GetReal of `refs` into `out`, as a host does.
    pub fn step(&self, t: f64, h: f64, refs: &[u32], out: &mut [f64]) {
        assert_eq!(refs.len(), out.len());
        // SAFETY: the instance is this host's, live until `drop`; the other pointers are to live locals.
        unsafe {
            ok(fmi2DoStep(self.c, t, h, 1), "doStep");
            ok(fmi2GetReal(self.c, refs.as_ptr(), refs.len(), out.as_mut_ptr()), "getReal");
        }
    }
}

impl Drop for Host {
    fn drop(&mut self) {
        // SAFETY: the instance is this host's, live until `drop`; the other pointers are to live locals.
        unsafe { fmi2FreeInstance(self.c) }
    }
}
