//! A host of the FMU's exported C functions in the same process, written in Rust so that a host's
//! own cost stays out of what is measured: shared by `benches/fmu.rs`, the allocation test and the
//! random designs run through the FMU (`fmu_designs.rs`).

use pistonslap::fmi::fixed_argument_logger;
use pistonslap::fmi::types::{fmi2CallbackFunctions, fmi2Component, fmi2FMUstate, Status, FMI2_CO_SIMULATION, FMI2_FALSE};
use pistonslap::fmi::{Causality, Kind};
use pistonslap::fmus::exports::*;
use pistonslap::fmus::piston_slap::{value_reference, DESCRIPTION, GUID, VARIABLES};
use pistonslap::fmus::piston_slap::{InputDerivatives, Inputs, Outputs, Parameters};
use std::cell::RefCell;
use std::ffi::{c_char, c_int, c_void, CStr, CString};

/// Receives `logger(env, name, status, category, "%s", message)` and keeps the messages of warnings and
/// errors in the host's `RefCell<Vec<String>>` at `env` (nothing else, so that steps do not allocate).
unsafe extern "C" fn keeping_logger(
    env: *mut c_void,
    _: *const c_char,
    status: c_int,
    _: *const c_char,
    _: *const c_char,
    message: *const c_char,
) {
    if status > 0 && !env.is_null() && !message.is_null() {
        // SAFETY: `env` is the host's boxed log, live while its instance is; the message a C string.
        let (log, message) = unsafe { (&*(env as *const RefCell<Vec<String>>), CStr::from_ptr(message)) };
        log.borrow_mut().push(message.to_string_lossy().into_owned());
    }
}

/// The value reference of variable `name`, which must exist.
pub fn vr(name: &str) -> u32 {
    value_reference(name).expect(name)
}

/// An instance initialized with a design's parameters, ready to step from t = 0.
pub struct Host {
    c: fmi2Component,
    _callbacks: Box<fmi2CallbackFunctions>,
    log: Box<RefCell<Vec<String>>>,
}

impl Host {
    /// The default design with the parameters `integers` and `reals` set by name; panics unless it
    /// is accepted, or where a name is not a parameter's (an input is set with `set_inputs`).
    pub fn new(integers: &[(&str, i32)], reals: &[(&str, f64)]) -> Self {
        let mut params = Parameters::default();
        let no_inputs = &mut Inputs::default();
        for n in integers.iter().map(|p| p.0).chain(reals.iter().map(|p| p.0)) {
            assert!(VARIABLES[vr(n) as usize].causality == Causality::Parameter, "{n} is not a parameter");
        }
        for &(n, v) in integers {
            *(DESCRIPTION.integer_mut)(vr(n), &mut params, no_inputs).expect(n) = v;
        }
        for &(n, v) in reals {
            *(DESCRIPTION.real_mut)(vr(n), &mut params, no_inputs).expect(n) = v;
        }
        Self::start(&params).unwrap_or_else(|e| panic!("{e}"))
    }

    /// An instance through fmi2Instantiate, fmi2SetupExperiment and initialization with every parameter
    /// of `params` set by name; a refusal as its status and log.
    pub fn start(params: &Parameters) -> Result<Self, String> {
        let mut log = Box::new(RefCell::new(Vec::new()));
        let callbacks = Box::new(fmi2CallbackFunctions {
            logger: Some(fixed_argument_logger(keeping_logger)),
            allocate_memory: Some(libc::calloc),
            free_memory: Some(libc::free),
            step_finished: None,
            component_environment: &mut *log as *mut RefCell<Vec<String>> as *mut c_void,
        });
        let (name, guid, resources) = (CString::new("host").unwrap(), CString::new(GUID).unwrap(), CString::new("file:///tmp").unwrap());
        // SAFETY: the pointers are to live locals; the instance, if any, is the host's from here on.
        let c = unsafe {
            fmi2Instantiate(name.as_ptr(), FMI2_CO_SIMULATION, guid.as_ptr(), resources.as_ptr(), &*callbacks, FMI2_FALSE, FMI2_FALSE)
        };
        if c.is_null() {
            return Err(format!("fmi2Instantiate refused: {:?}", log.borrow()));
        }
        let host = Self { c, _callbacks: callbacks, log };
        // SAFETY: the instance is this host's, live until `drop`.
        host.ok("fmi2SetupExperiment", unsafe { fmi2SetupExperiment(c, FMI2_FALSE, 0.0, 0.0, FMI2_FALSE, 0.0) })?;
        host.ok("fmi2EnterInitializationMode", unsafe { fmi2EnterInitializationMode(c) })?;
        let no = (&Inputs::default(), &Outputs::default());
        for (r, v) in (0u32..).zip(VARIABLES.iter()).filter(|(_, v)| v.causality == Causality::Parameter) {
            let r = value_reference(v.name).filter(|&by_name| by_name == r).expect(v.name);
            // SAFETY: each value lives over its call.
            let status = unsafe {
                match v.kind {
                    Kind::Real => fmi2SetReal(c, &r, 1, &(DESCRIPTION.get_real)(r, params, no.0, no.1).expect(v.name)),
                    Kind::Integer => fmi2SetInteger(c, &r, 1, &(DESCRIPTION.get_integer)(r, params, no.0, no.1).expect(v.name)),
                    Kind::String => {
                        let s = CString::new((DESCRIPTION.get_string)(r, params, no.0, no.1).expect(v.name)).map_err(|e| e.to_string())?;
                        fmi2SetString(c, &r, 1, &s.as_ptr())
                    }
                }
            };
            host.ok(v.name, status)?;
        }
        host.ok("fmi2ExitInitializationMode", unsafe { fmi2ExitInitializationMode(c) })?;
        Ok(host)
    }

    /// `status` unless fmi2OK: then what was called, the status and the messages logged.
    fn ok(&self, what: &str, status: Status) -> Result<(), String> {
        match status {
            Status::Ok => Ok(()),
            _ => Err(format!("{what}: {status:?} {:?}", self.log.borrow_mut().drain(..).collect::<Vec<_>>())),
        }
    }

    /// Sets every input by name (fmi2SetReal), then the derivatives that are not zero
    /// (fmi2SetRealInputDerivatives, orders 1 and 2): a new value ends the derivatives set before.
    pub fn set_inputs(&self, inputs: &Inputs, derivatives: &InputDerivatives) -> Result<(), String> {
        for (name, value, slopes) in derivatives.with_values(inputs) {
            let r = vr(name);
            // SAFETY: the instance is this host's; the values live over the calls.
            self.ok(name, unsafe { fmi2SetReal(self.c, &r, 1, &value) })?;
            for (order, d) in (1..).zip(slopes).filter(|&(_, d)| d != 0.0) {
                self.ok(name, unsafe { fmi2SetRealInputDerivatives(self.c, &r, 1, &order, &d) })?;
            }
        }
        Ok(())
    }

    /// fmi2DoStep from `t` over `h`.
    pub fn do_step(&self, t: f64, h: f64) -> Result<(), String> {
        // SAFETY: the instance is this host's.
        self.ok("fmi2DoStep", unsafe { fmi2DoStep(self.c, t, h, 1) })
    }

    /// fmi2DoStep from `t` over `h`, then fmi2GetReal of `refs` into `out`, as a host does.
    pub fn step(&self, t: f64, h: f64, refs: &[u32], out: &mut [f64]) {
        assert_eq!(refs.len(), out.len());
        self.do_step(t, h).unwrap_or_else(|e| panic!("{e}"));
        // SAFETY: the instance is this host's; `out` holds `refs.len()` values.
        self.ok("fmi2GetReal", unsafe { fmi2GetReal(self.c, refs.as_ptr(), refs.len(), out.as_mut_ptr()) })
            .unwrap_or_else(|e| panic!("{e}"));
    }

    /// Every Real and Integer output (fmi2GetReal, fmi2GetInteger), indexed by value reference
    /// (NaN where a variable is neither an output nor a number).
    pub fn outputs(&self) -> Result<Vec<f64>, String> {
        let mut values = vec![f64::NAN; VARIABLES.len()];
        for (r, v) in (0u32..).zip(VARIABLES.iter()).filter(|(_, v)| v.causality == Causality::Output) {
            let (mut real, mut integer) = (0.0, 0);
            // SAFETY: the instance is this host's; each value lives over its call.
            match v.kind {
                Kind::Real => self.ok(v.name, unsafe { fmi2GetReal(self.c, &r, 1, &mut real) })?,
                Kind::Integer => self.ok(v.name, unsafe { fmi2GetInteger(self.c, &r, 1, &mut integer) })?,
                Kind::String => continue,
            }
            values[r as usize] = if v.kind == Kind::Real { real } else { f64::from(integer) };
        }
        Ok(values)
    }

    /// The instance's state as a host stores it: fmi2GetFMUstate, fmi2SerializeFMUstate, fmi2FreeFMUstate.
    pub fn saved(&self) -> Result<Vec<u8>, String> {
        let mut state: fmi2FMUstate = std::ptr::null_mut();
        let mut size = 0;
        // SAFETY: the instance is this host's; the state is freed before return; the buffer holds `size` bytes.
        unsafe {
            self.ok("fmi2GetFMUstate", fmi2GetFMUstate(self.c, &mut state))?;
            self.ok("fmi2SerializedFMUstateSize", fmi2SerializedFMUstateSize(self.c, state, &mut size))?;
            let mut bytes = vec![0u8; size];
            let saved = self.ok("fmi2SerializeFMUstate", fmi2SerializeFMUstate(self.c, state, bytes.as_mut_ptr().cast(), size));
            self.ok("fmi2FreeFMUstate", fmi2FreeFMUstate(self.c, &mut state))?;
            saved.map(|()| bytes)
        }
    }

    /// Restores a state `saved` (by this or another instance): fmi2DeSerializeFMUstate, fmi2SetFMUstate,
    /// fmi2FreeFMUstate.
    pub fn restore(&self, bytes: &[u8]) -> Result<(), String> {
        let mut state: fmi2FMUstate = std::ptr::null_mut();
        // SAFETY: the instance is this host's; the state is freed before return.
        unsafe {
            self.ok("fmi2DeSerializeFMUstate", fmi2DeSerializeFMUstate(self.c, bytes.as_ptr().cast(), bytes.len(), &mut state))?;
            let set = self.ok("fmi2SetFMUstate", fmi2SetFMUstate(self.c, state));
            self.ok("fmi2FreeFMUstate", fmi2FreeFMUstate(self.c, &mut state))?;
            set
        }
    }
}

impl Drop for Host {
    fn drop(&mut self) {
        // SAFETY: the instance is this host's, live until here.
        unsafe { fmi2FreeInstance(self.c) }
    }
}
