//! One FMU instance, in safe code: what each fmi2 function does once the state machine
//! (`state_machine.rs`) has allowed the call.
//!
//! A bad argument or an unknown value reference is *refused*: `Err` with a message, nothing changed.
//! A *failure* of the model (parameters refused at fmi2ExitInitializationMode, a step that cannot be
//! computed) puts the instance in the error state, as the standard says; its state is still the one
//! before the call, so fmi2SetFMUstate or fmi2Reset continue from there.

use super::description::{Causality, Kind, Variable};
use super::logger::Logger;
pub use super::model::Model;
use super::state_bytes;
use super::state_machine::Mode::{self, *};
use super::types::Status;
use serde::{Deserialize, Serialize};
use std::path::PathBuf;

/// A refused or failed call: the status to return and the message to log.
#[derive(Debug, Clone, PartialEq)]
pub struct Refusal {
    pub status: Status,
    pub message: String,
}

impl Refusal {
    pub fn error(message: impl Into<String>) -> Self {
        Self { status: Status::Error, message: message.into() }
    }
    pub fn discard(message: impl Into<String>) -> Self {
        Self { status: Status::Discard, message: message.into() }
    }
}

pub type Outcome<T = ()> = Result<T, Refusal>;

/// Where the instance is in its life, with the data each phase has.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(bound = "")]
enum Phase<E: Model> {
    Instantiated,
    InitializationMode,
    StepComplete(E::Simulation),
    Terminated(E::Simulation),
}

/// Everything an FMU state saves: phase, experiment, variables, simulation.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Core<E: Model> {
    phase: Phase<E>,
    start_time: f64,
    stop_time: Option<f64>,
    parameters: E::Parameters,
    inputs: E::Inputs,
    /// Set by fmi2SetRealInputDerivatives, each input's reset by its next fmi2SetReal.
    derivatives: E::InputDerivatives,
}

impl<E: Model> Default for Core<E> {
    fn default() -> Self {
        Self {
            phase: Phase::Instantiated,
            start_time: 0.0,
            stop_time: None,
            parameters: E::Parameters::default(),
            inputs: E::Inputs::default(),
            derivatives: E::InputDerivatives::default(),
        }
    }
}

impl<E: Model> Core<E> {
    /// The serialized FMU state.
    pub fn serialize(&self) -> Outcome<Vec<u8>> {
        state_bytes::encode(self, &state_bytes::Envelope::of::<E>()).map_err(Refusal::error)
    }

    /// What every state this FMU makes satisfies, so what a restored one must: finite times and
    /// variables (the setters take only finite values), and past initialization, parameters that
    /// passed fmi2ExitInitializationMode and a simulation with a finite time and outputs.
    fn check(&self) -> Result<(), String> {
        if !self.start_time.is_finite() || self.stop_time.is_some_and(|s| !(s >= self.start_time && s.is_finite())) {
            return Err(format!("start time {} s or stop time {:?} s is invalid", self.start_time, self.stop_time));
        }
        let no_outputs = E::Outputs::default();
        for (vr, v) in E::DESCRIPTION.variables.iter().enumerate() {
            if v.kind == Kind::Real && v.causality != Causality::Output {
                let x = (E::DESCRIPTION.get_real)(vr as u32, &self.parameters, &self.inputs, &no_outputs);
                if x.is_some_and(|x| !x.is_finite()) {
                    return Err(format!("{} = {x:?} is not finite", v.name));
                }
            }
        }
        match &self.phase {
            Phase::StepComplete(sim) | Phase::Terminated(sim) => {
                E::validate(&self.parameters).and_then(|()| E::check(sim)).map_err(|e| e.0)
            }
            Phase::Instantiated | Phase::InitializationMode => Ok(()),
        }
    }
}

/// A value the host sets: one of FMI's variable types.
pub enum Value<'a> {
    Real(f64),
    Integer(i32),
    String(&'a str),
}

impl Value<'_> {
    fn kind(&self) -> Kind {
        match self {
            Value::Real(_) => Kind::Real,
            Value::Integer(_) => Kind::Integer,
            Value::String(_) => Kind::String,
        }
    }
}

pub struct Instance<E: Model> {
    pub logger: Logger,
    /// Set by a model failure (Error) or a caught panic (Fatal); overrides the phase.
    failure: Option<Mode>,
    core: Core<E>,
    /// The FMU's `resources/` directory, where bare file names of parameters are looked up.
    resources: Option<PathBuf>,
}

/// Relative tolerance on the communication point: hosts accumulate t += h in floating point.
const TIME_TOLERANCE: f64 = 1e-9;

impl<E: Model> Instance<E> {
    pub fn new(logger: Logger, resources: Option<PathBuf>) -> Self {
        Self { logger, failure: None, core: Core::default(), resources }
    }

    /// The parameters with bare file names turned into their paths in the resources.
    fn resolved_parameters(&self) -> E::Parameters {
        E::resolve(&self.core.parameters, self.resources.as_deref())
    }

    pub fn mode(&self) -> Mode {
        self.failure.unwrap_or(match self.core.phase {
            Phase::Instantiated => Instantiated,
            Phase::InitializationMode => InitializationMode,
            Phase::StepComplete(_) => StepComplete,
            Phase::Terminated(_) => Terminated,
        })
    }

    /// After a caught panic: the instance can only be freed.
    pub fn set_fatal(&mut self) {
        self.failure = Some(Fatal);
    }

    pub fn setup_experiment(&mut self, start: f64, stop: Option<f64>) -> Outcome {
        if !start.is_finite() {
            return Err(Refusal::error(format!("startTime = {start} is not finite")));
        }
        if let Some(stop) = stop.filter(|s| !(s.is_finite() && *s >= start)) {
            return Err(Refusal::error(format!("stopTime = {stop} must be finite and ≥ startTime = {start}")));
        }
        self.core.start_time = start;
        self.core.stop_time = stop;
        Ok(())
    }

    pub fn enter_initialization_mode(&mut self) -> Outcome {
        self.core.phase = Phase::InitializationMode;
        Ok(())
    }

    /// Builds the simulation from the parameters: bad parameters are a failure naming the parameter.
    pub fn exit_initialization_mode(&mut self) -> Outcome {
        let sim = E::start(&self.resolved_parameters(), &self.core.inputs, self.core.start_time).map_err(|e| self.fail(e))?;
        self.core.phase = Phase::StepComplete(sim);
        Ok(())
    }

    pub fn terminate(&mut self) -> Outcome {
        if let Phase::StepComplete(sim) = std::mem::replace(&mut self.core.phase, Phase::Instantiated) {
            self.core.phase = Phase::Terminated(sim);
        }
        Ok(())
    }

    /// Back to the state after fmi2Instantiate (debug-logging settings are kept).
    pub fn reset(&mut self) -> Outcome {
        self.core = Core::default();
        self.failure = None;
        Ok(())
    }

    /// Checks every (value reference, value) pair before changing anything: all or nothing.
    pub fn set(&mut self, values: &[(u32, Value)]) -> Outcome {
        for (vr, value) in values {
            self.check_settable(*vr, value)?;
        }
        let (p, i) = (&mut self.core.parameters, &mut self.core.inputs);
        for (vr, value) in values {
            let missing = || Refusal::error(format!("value reference {vr} has no field")); // excluded above
                                                                                           // A new value of an input ends the polynomial its derivatives described (FMI 2.0 §4.2.1).
            if let Some(d) = E::DESCRIPTION.variable(*vr).and_then(|v| E::input_derivatives(&mut self.core.derivatives, v.name)) {
                *d = [0.0; 2];
            }
            let d = &E::DESCRIPTION;
            match value {
                Value::Real(x) => *(d.real_mut)(*vr, p, i).ok_or_else(missing)? = *x,
                Value::Integer(x) => *(d.integer_mut)(*vr, p, i).ok_or_else(missing)? = *x,
                Value::String(s) => *(d.string_mut)(*vr, p, i).ok_or_else(missing)? = (*s).to_string(),
            }
        }
        Ok(())
    }

    /// fmi2SetRealInputDerivatives: the `order`-th time derivative (1 or 2) of each Real input `vr`,
    /// checked all before any is set. The inputs follow these polynomials over the next steps until
    /// their next fmi2SetReal.
    pub fn set_input_derivatives(&mut self, vrs: &[u32], orders: &[i32], values: &[f64]) -> Outcome {
        for ((&vr, &order), &value) in vrs.iter().zip(orders).zip(values) {
            let v = typed_variable::<E>(vr, Kind::Real)?;
            if v.causality != Causality::Input {
                return Err(Refusal::error(format!("{} (value reference {vr}) is not an input: it has no input derivatives", v.name)));
            }
            if !(1..=E::MAX_INPUT_DERIVATIVE_ORDER).contains(&order) {
                return Err(Refusal::error(format!(
                    "derivative order {order} of {} refused: orders 1..={} are supported",
                    v.name,
                    E::MAX_INPUT_DERIVATIVE_ORDER
                )));
            }
            if !value.is_finite() {
                return Err(Refusal::error(format!("derivative {order} of {} = {value} refused: values must be finite", v.name)));
            }
        }
        for ((&vr, &order), &value) in vrs.iter().zip(orders).zip(values) {
            let name = E::DESCRIPTION.variable(vr).map_or("", |v| v.name);
            let d = E::input_derivatives(&mut self.core.derivatives, name)
                .ok_or_else(|| Refusal::error(format!("{name} has no input derivatives")))?;
            d[order as usize - 1] = value;
        }
        Ok(())
    }

    fn check_settable(&self, vr: u32, value: &Value) -> Outcome {
        let v = typed_variable::<E>(vr, value.kind())?;
        match v.causality {
            Causality::Output => return Err(Refusal::error(format!("{} (value reference {vr}) is an output: it cannot be set", v.name))),
            Causality::Parameter if !matches!(self.mode(), Instantiated | InitializationMode) => {
                return Err(Refusal::error(format!(
                    "{} is a fixed parameter: set it before fmi2ExitInitializationMode (state is {})",
                    v.name,
                    self.mode()
                )))
            }
            _ => {}
        }
        match value {
            Value::Real(x) if !x.is_finite() => Err(Refusal::error(format!("{} = {x} refused: values must be finite", v.name))),
            _ => Ok(()),
        }
    }

    /// Reads variables of one kind. In initialization mode the outputs are the initial ones of a
    /// simulation built from the current parameters. `independent`: a value reference beyond the table
    /// that `read` answers (FMI 3.0's time).
    pub fn get<T>(
        &self,
        vrs: &[u32],
        kind: Kind,
        read: impl for<'a> Fn(u32, &'a E::Parameters, &'a E::Inputs, &'a E::Outputs) -> Option<T>,
        out: &mut [T],
        independent: Option<u32>,
    ) -> Outcome {
        for &vr in vrs.iter().filter(|&&vr| Some(vr) != independent) {
            typed_variable::<E>(vr, kind)?;
        }
        let preview;
        let no_outputs;
        let outputs = match &self.core.phase {
            Phase::StepComplete(sim) | Phase::Terminated(sim) => E::outputs(sim),
            _ if vrs.iter().any(|&vr| is_output::<E>(vr)) => {
                preview = E::preview(&self.resolved_parameters(), &self.core.inputs, self.core.start_time)
                    .map_err(|e| Refusal::error(format!("cannot compute the initial outputs: {e}")))?;
                E::outputs(&preview)
            }
            _ => {
                no_outputs = E::Outputs::default();
                &no_outputs
            }
        };
        let (p, i) = (&self.core.parameters, &self.core.inputs);
        // Into the host's array directly: a host reads outputs every step, and collecting a list
        // first would allocate at every call.
        for (&vr, value) in vrs.iter().zip(out) {
            *value = read(vr, p, i, outputs).ok_or_else(|| Refusal::error(format!("value reference {vr} has no field")))?;
        }
        Ok(())
    }

    /// fmi2GetRealOutputDerivatives: the `order`-th time derivative of each Real output now, up to the
    /// model's MAX_OUTPUT_DERIVATIVE_ORDER.
    pub fn output_derivatives(&self, vrs: &[u32], orders: &[i32], out: &mut [f64]) -> Outcome {
        for (&vr, &order) in vrs.iter().zip(orders) {
            let v = typed_variable::<E>(vr, Kind::Real)?;
            if v.causality != Causality::Output {
                return Err(Refusal::error(format!("{} (value reference {vr}) is not an output: it has no output derivatives", v.name)));
            }
            if !(1..=E::MAX_OUTPUT_DERIVATIVE_ORDER).contains(&order) {
                return Err(Refusal::error(format!(
                    "derivative order {order} of {} refused: maxOutputDerivativeOrder = {}",
                    v.name,
                    E::MAX_OUTPUT_DERIVATIVE_ORDER
                )));
            }
        }
        let (Phase::StepComplete(sim) | Phase::Terminated(sim)) = &self.core.phase else {
            return Err(Refusal::error("no simulation: output derivatives exist after fmi2ExitInitializationMode"));
        };
        for ((&vr, &order), value) in vrs.iter().zip(orders).zip(out) {
            *value = E::output_derivative(sim, vr, order)
                .ok_or_else(|| Refusal::error(format!("value reference {vr} has no derivative {order}")))?;
        }
        Ok(())
    }

    /// The getters and setters of a type no table has (fmi2GetBoolean, fmi3GetInt8, …): any value reference
    /// is refused (an empty list is fine).
    pub fn none_of_kind(&self, vrs: &[u32], kind: &str) -> Outcome {
        match vrs.first() {
            None => Ok(()),
            Some(&vr) => Err(match E::DESCRIPTION.variable(vr) {
                Some(v) => Refusal::error(format!("{} (value reference {vr}) is a {:?} variable, not {kind}", v.name, v.kind)),
                None => Refusal::error(format!("unknown value reference {vr}")),
            }),
        }
    }

    /// Advances from `t` (which must be the current time) to exactly `t + h` with the inputs held.
    pub fn do_step(&mut self, t: f64, h: f64) -> Outcome {
        let Phase::StepComplete(sim) = &mut self.core.phase else {
            return Err(Refusal::error("no simulation to step"));
        };
        let now = E::time(sim);
        if !(h.is_finite() && h > 0.0) {
            return Err(Refusal::error(format!("communicationStepSize = {h} must be finite and > 0")));
        }
        if !t.is_finite() || (t - now).abs() > TIME_TOLERANCE * now.abs().max(1.0) {
            return Err(Refusal::error(format!("currentCommunicationPoint = {t} s is not the FMU's current time {now} s")));
        }
        let t_end = t + h;
        if t_end <= now {
            return Err(Refusal::error(format!("step {h} s is too small to advance from {now} s")));
        }
        if let Some(stop) = self.core.stop_time.filter(|s| t_end > s + TIME_TOLERANCE * s.abs().max(1.0)) {
            return Err(Refusal::error(format!("step to {t_end} s goes beyond stopTime = {stop} s")));
        }
        match E::step(sim, &self.core.inputs, &self.core.derivatives, t_end) {
            Ok(()) => {
                E::log_step(sim, &self.logger);
                Ok(())
            }
            Err(e) => Err(self.fail(e)),
        }
    }

    /// The time of the simulation (start time before initialization).
    pub fn time(&self) -> f64 {
        match &self.core.phase {
            Phase::StepComplete(sim) | Phase::Terminated(sim) => E::time(sim),
            _ => self.core.start_time,
        }
    }

    pub fn state(&self) -> Core<E> {
        self.core.clone()
    }

    /// Restores a saved state (and cuts the files the simulation writes back to it); leaves the error state.
    pub fn set_state(&mut self, core: &Core<E>) -> Outcome {
        if let Phase::StepComplete(sim) | Phase::Terminated(sim) = &core.phase {
            // Restoring cuts the state's log file: only this instance's own log may be cut, so
            // foreign or crafted state bytes cannot truncate an arbitrary file.
            if let Some(why) = E::foreign_files(sim, &self.core.parameters) {
                return Err(Refusal::error(format!("{why}: refused")));
            }
            E::rewind_files(sim).map_err(|e| Refusal::error(format!("cannot restore the logs: {e}")))?;
        }
        self.core = core.clone();
        self.failure = None;
        Ok(())
    }

    pub fn deserialize(&self, bytes: &[u8]) -> Outcome<Core<E>> {
        let core: Core<E> = state_bytes::decode(bytes, &state_bytes::Envelope::of::<E>())
            .map_err(|e| Refusal::error(format!("refused state bytes: {e}")))?;
        core.check().map_err(|e| Refusal::error(format!("refused state bytes: {e}")))?;
        Ok(core)
    }

    fn fail(&mut self, e: super::Error) -> Refusal {
        self.failure = Some(Error);
        Refusal::error(e.0)
    }
}

fn is_output<E: Model>(vr: u32) -> bool {
    E::DESCRIPTION.variable(vr).is_some_and(|v| v.causality == Causality::Output)
}

/// The variable `vr`, refused when unknown or not of `kind`.
fn typed_variable<E: Model>(vr: u32, kind: Kind) -> Outcome<&'static Variable> {
    let v = E::DESCRIPTION.variable(vr).ok_or_else(|| Refusal::error(format!("unknown value reference {vr}")))?;
    if v.kind != kind {
        return Err(Refusal::error(format!("{} (value reference {vr}) is a {:?} variable, not {kind:?}", v.name, v.kind)));
    }
    Ok(v)
}
