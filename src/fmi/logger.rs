//! Messages to the host's logger callback (FMI 2.0's or FMI 3.0's), filtered by fmi2SetDebugLogging and
//! fmi3SetDebugLogging.
#![allow(unsafe_code)]

use super::description::LOG_CATEGORIES;
use super::types::{fmi2CallbackLogger, fmi2ComponentEnvironment, fmi2String, fmi3LogMessageCallback, Status};
use std::ffi::{c_int, CString};

/// A logger callback written with fixed arguments only (variadic definitions are unstable in Rust):
/// `env, instance name, status, category, format, message`.
pub type FixedArgumentLogger = unsafe extern "C" fn(fmi2ComponentEnvironment, fmi2String, c_int, fmi2String, fmi2String, fmi2String);

/// `logger` as the FMI's variadic callback type, for hosts written in Rust (the tests, the benchmark).
/// Sound for this FMU, which always logs through the format `"%s"` with the message as the one
/// variadic argument: on the C ABI that argument arrives where a sixth fixed one would.
pub fn fixed_argument_logger(logger: FixedArgumentLogger) -> fmi2CallbackLogger {
    // SAFETY: both are `extern "C"` function pointers; the calls this FMU makes pass exactly the
    // arguments `logger` reads (see above).
    unsafe { std::mem::transmute::<FixedArgumentLogger, fmi2CallbackLogger>(logger) }
}

/// The host's callback, as the FMI version of the instantiating function gives it.
enum Callback {
    /// FMI 2.0's variadic logger, told the instance's name.
    Fmi2 { callback: fmi2CallbackLogger, instance_name: CString },
    /// FMI 3.0's logger; none silences the instance.
    Fmi3(Option<fmi3LogMessageCallback>),
}

/// Where an instance's messages go: the host's callback with its environment pointer.
pub struct Logger {
    callback: Callback,
    environment: fmi2ComponentEnvironment,
    /// Per category of `LOG_CATEGORIES`: whether debug logging is on for it.
    enabled: [bool; LOG_CATEGORIES.len()],
}

impl Logger {
    /// A logger calling the host's FMI 2.0 `callback` for instance `instance_name`, every category on or off.
    pub fn new(callback: fmi2CallbackLogger, environment: fmi2ComponentEnvironment, instance_name: &str, on: bool) -> Self {
        let callback = Callback::Fmi2 { callback, instance_name: c_string(instance_name) };
        Self { callback, environment, enabled: [on; LOG_CATEGORIES.len()] }
    }

    /// A logger calling the host's FMI 3.0 `callback` (none: silent), every category on or off.
    pub fn fmi3(callback: Option<fmi3LogMessageCallback>, environment: fmi2ComponentEnvironment, on: bool) -> Self {
        Self { callback: Callback::Fmi3(callback), environment, enabled: [on; LOG_CATEGORIES.len()] }
    }

    /// fmi2SetDebugLogging: no categories = all of them; an unknown name is refused, nothing changed.
    pub fn set_debug_logging(&mut self, on: bool, categories: &[String]) -> Result<(), String> {
        if categories.is_empty() {
            self.enabled = [on; LOG_CATEGORIES.len()];
            return Ok(());
        }
        let mut enabled = self.enabled;
        for name in categories {
            let i = LOG_CATEGORIES
                .iter()
                .position(|c| c == name)
                .ok_or_else(|| format!("unknown log category {name:?}; known: {}", LOG_CATEGORIES.join(", ")))?;
            enabled[i] = on;
        }
        self.enabled = enabled;
        Ok(())
    }

    /// Errors and fatal errors always reach the host: a refused call must say why.
    pub fn status(&self, status: Status, message: &str) {
        let category = if status == Status::Fatal { "logStatusFatal" } else { "logStatusError" };
        self.send(status, category, message);
    }

    /// A debug message, written and sent only when its category is enabled (a step's events
    /// would otherwise each cost a formatted string nobody reads).
    pub fn debug(&self, category: &str, message: impl FnOnce() -> String) {
        if LOG_CATEGORIES.iter().zip(self.enabled).any(|(c, on)| on && *c == category) {
            self.send(Status::Ok, category, &message());
        }
    }

    fn send(&self, status: Status, category: &str, message: &str) {
        let (category, message) = (c_string(category), c_string(message));
        match &self.callback {
            // The message goes through "%s": a '%' in it must not be read as a format directive.
            // SAFETY: the callback and environment are the host's, given at fmi2Instantiate; the strings
            // are NUL-terminated and outlive the call.
            Callback::Fmi2 { callback, instance_name } => unsafe {
                callback(self.environment, instance_name.as_ptr(), status as c_int, category.as_ptr(), c"%s".as_ptr(), message.as_ptr());
            },
            // SAFETY: as above, given at fmi3InstantiateCoSimulation; FMI 3.0's message is no format.
            Callback::Fmi3(Some(callback)) => unsafe { callback(self.environment, status as c_int, category.as_ptr(), message.as_ptr()) },
            Callback::Fmi3(None) => {}
        }
    }
}

/// A C string of `s`, with any interior NUL replaced (messages may quote host input).
fn c_string(s: &str) -> CString {
    CString::new(s.replace('\0', "\u{2400}")).unwrap_or_default()
}
