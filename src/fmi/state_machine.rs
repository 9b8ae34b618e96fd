//! The FMI 2.0 Co-Simulation state machine (standard §4.2.4): the states a synchronous FMU can be in
//! and, in one table, the states in which each fmi2 function may be called on an instance. The
//! functions' common wrapper (`functions::call`) consults it before every call, so no function checks
//! its state itself (Reference-FMUs' `MASK_fmi2X` table and `BEGIN_FUNCTION`).

use std::fmt;

/// The states of the standard's Co-Simulation state machine that a synchronous FMU can be in (named
/// as in the standard). stepInProgress, stepFailed and stepCanceled cannot occur: fmi2DoStep is
/// synchronous and never returns fmi2Discard.
#[allow(clippy::enum_variant_names)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Instantiated,
    InitializationMode,
    StepComplete,
    Terminated,
    Error,
    Fatal,
}

impl fmt::Display for Mode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(self, f)
    }
}

use Mode::*;

/// Every state but Fatal, after which only fmi2FreeInstance is allowed.
const LIVE: &[Mode] = &[Instantiated, InitializationMode, StepComplete, Terminated, Error];
const CONFIGURE: &[Mode] = &[Instantiated];
const GET: &[Mode] = &[InitializationMode, StepComplete, Terminated, Error];
const SET: &[Mode] = &[Instantiated, InitializationMode, StepComplete];
const STEP: &[Mode] = &[StepComplete];
const STATUS: &[Mode] = &[StepComplete, Terminated];
const OUTPUT_DERIVATIVES: &[Mode] = &[StepComplete, Terminated, Error];

/// The table: each function on an instance with the states that allow it.
macro_rules! table {
    ($($function:ident: $allowed:expr,)*) => {
        /// An fmi2 function that takes an instance (fmi2Instantiate and fmi2FreeInstance aside).
        #[allow(non_camel_case_types, clippy::enum_variant_names)]
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        pub enum Function {
            $($function,)*
        }

        impl Function {
            /// The function's C name.
            pub fn name(self) -> &'static str {
                match self {
                    $(Function::$function => stringify!($function),)*
                }
            }

            /// The states in which the standard allows the call.
            pub fn allowed(self) -> &'static [Mode] {
                match self {
                    $(Function::$function => $allowed,)*
                }
            }
        }
    };
}

table! {
    fmi2SetDebugLogging: LIVE,
    fmi2SetupExperiment: CONFIGURE,
    fmi2EnterInitializationMode: CONFIGURE,
    fmi2ExitInitializationMode: &[InitializationMode],
    fmi2Terminate: STEP,
    fmi2Reset: LIVE,
    fmi2GetReal: GET,
    fmi2GetInteger: GET,
    fmi2GetBoolean: GET,
    fmi2GetString: GET,
    fmi2SetReal: SET,
    fmi2SetInteger: SET,
    fmi2SetBoolean: SET,
    fmi2SetString: SET,
    fmi2GetFMUstate: LIVE,
    fmi2SetFMUstate: LIVE,
    fmi2FreeFMUstate: LIVE,
    fmi2SerializedFMUstateSize: LIVE,
    fmi2SerializeFMUstate: LIVE,
    fmi2DeSerializeFMUstate: LIVE,
    fmi2GetDirectionalDerivative: GET,
    fmi2SetRealInputDerivatives: SET,
    fmi2GetRealOutputDerivatives: OUTPUT_DERIVATIVES,
    fmi2DoStep: STEP,
    // Allowed only in stepInProgress, which a synchronous fmi2DoStep never leaves behind: accepted
    // here in every live state so that the refusal can say why.
    fmi2CancelStep: LIVE,
    fmi2GetStatus: STATUS,
    fmi2GetRealStatus: STATUS,
    fmi2GetIntegerStatus: STATUS,
    fmi2GetBooleanStatus: STATUS,
    fmi2GetStringStatus: STATUS,
}

impl Function {
    /// Whether the call is allowed in `mode`; `Err` says why not. Inlined, the message apart:
    /// every call of a host asks.
    #[inline]
    pub fn check(self, mode: Mode) -> Result<(), String> {
        if self.allowed().contains(&mode) {
            Ok(())
        } else {
            Err(self.refusal(mode))
        }
    }

    #[cold]
    fn refusal(self, mode: Mode) -> String {
        let names: Vec<String> = self.allowed().iter().map(Mode::to_string).collect();
        format!("not allowed in state {mode} (allowed in: {})", names.join(", "))
    }
}
