//! The Co-Simulation state machine of FMI 2.0 (standard §4.2.4) and FMI 3.0 (§4.2, without Event Mode):
//! the states a synchronous FMU can be in and, in one table, the states in which each fmi2 and fmi3
//! function may be called on an instance. The functions' common wrapper (`functions::call`) consults it
//! before every call, so no function checks its state itself (Reference-FMUs' `MASK_fmi2X` table and
//! `BEGIN_FUNCTION`). FMI 3.0's Step Mode is FMI 2.0's stepComplete; its Event Mode, Configuration Mode and
//! Model Exchange's and Scheduled Execution's states never occur (the FMUs declare none of them).

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

impl Mode {
    /// The state's name in the standard of `version` (2 or 3).
    fn name(self, version: u8) -> String {
        match (self, version) {
            (StepComplete, 3) => "StepMode".to_string(),
            _ => self.to_string(),
        }
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
        /// An fmi2 or fmi3 function that takes an instance (the instantiating functions and FreeInstance aside).
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
    fmi3SetDebugLogging: LIVE,
    fmi3EnterInitializationMode: CONFIGURE,
    fmi3ExitInitializationMode: &[InitializationMode],
    fmi3Terminate: STEP,
    fmi3Reset: LIVE,
    fmi3GetFloat64: GET,
    fmi3GetInt32: GET,
    fmi3GetString: GET,
    fmi3SetFloat64: SET,
    fmi3SetInt32: SET,
    fmi3SetString: SET,
    fmi3GetFMUState: LIVE,
    fmi3SetFMUState: LIVE,
    fmi3FreeFMUState: LIVE,
    fmi3SerializedFMUStateSize: LIVE,
    fmi3SerializeFMUState: LIVE,
    fmi3DeserializeFMUState: LIVE,
    fmi3GetOutputDerivatives: OUTPUT_DERIVATIVES,
    fmi3DoStep: STEP,
    // The types no table has: any value reference is refused by its kind.
    fmi3GetFloat32: GET,
    fmi3GetInt8: GET,
    fmi3GetUInt8: GET,
    fmi3GetInt16: GET,
    fmi3GetUInt16: GET,
    fmi3GetUInt32: GET,
    fmi3GetInt64: GET,
    fmi3GetUInt64: GET,
    fmi3GetBoolean: GET,
    fmi3GetBinary: GET,
    fmi3GetClock: GET,
    fmi3SetFloat32: SET,
    fmi3SetInt8: SET,
    fmi3SetUInt8: SET,
    fmi3SetInt16: SET,
    fmi3SetUInt16: SET,
    fmi3SetUInt32: SET,
    fmi3SetInt64: SET,
    fmi3SetUInt64: SET,
    fmi3SetBoolean: SET,
    fmi3SetBinary: SET,
    fmi3SetClock: SET,
    // What the FMUs declare absent (Event Mode, Configuration Mode, clocks, dependencies, derivatives,
    // Model Exchange, Scheduled Execution): accepted in every live state so that the refusal can say why.
    fmi3EnterEventMode: LIVE,
    fmi3EnterStepMode: LIVE,
    fmi3UpdateDiscreteStates: LIVE,
    fmi3EvaluateDiscreteStates: LIVE,
    fmi3EnterConfigurationMode: LIVE,
    fmi3ExitConfigurationMode: LIVE,
    fmi3GetNumberOfVariableDependencies: LIVE,
    fmi3GetVariableDependencies: LIVE,
    fmi3GetDirectionalDerivative: LIVE,
    fmi3GetAdjointDerivative: LIVE,
    fmi3GetIntervalDecimal: LIVE,
    fmi3GetIntervalFraction: LIVE,
    fmi3GetShiftDecimal: LIVE,
    fmi3GetShiftFraction: LIVE,
    fmi3SetIntervalDecimal: LIVE,
    fmi3SetIntervalFraction: LIVE,
    fmi3SetShiftDecimal: LIVE,
    fmi3SetShiftFraction: LIVE,
    fmi3EnterContinuousTimeMode: LIVE,
    fmi3CompletedIntegratorStep: LIVE,
    fmi3SetTime: LIVE,
    fmi3SetContinuousStates: LIVE,
    fmi3GetContinuousStateDerivatives: LIVE,
    fmi3GetEventIndicators: LIVE,
    fmi3GetContinuousStates: LIVE,
    fmi3GetNominalsOfContinuousStates: LIVE,
    fmi3GetNumberOfEventIndicators: LIVE,
    fmi3GetNumberOfContinuousStates: LIVE,
    fmi3ActivateModelPartition: LIVE,
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

    /// 2 for an fmi2 function, 3 for an fmi3 one.
    pub fn version(self) -> u8 {
        if self.name().starts_with("fmi3") {
            3
        } else {
            2
        }
    }

    #[cold]
    fn refusal(self, mode: Mode) -> String {
        let version = self.version();
        let names: Vec<String> = self.allowed().iter().map(|m| m.name(version)).collect();
        format!("not allowed in state {} (allowed in: {})", mode.name(version), names.join(", "))
    }
}
