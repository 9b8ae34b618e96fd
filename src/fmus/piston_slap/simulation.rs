//! The facade the FMI layer drives: a validated model, its time, its outputs (including the impact
//! statistics computed from the event rows) and the impact log. No FFI and no FMI words: the FMI
//! layer maps its calls and errors onto this.

mod csv_log;
mod impact_log;
mod landings;
mod model_variant;
mod skirt_map;
mod statistics;

pub use impact_log::ImpactLog;
pub use model_variant::ModelVariant;

use super::{mechanisms, Mechanism};
use crate::fmus::piston_slap::{InputDerivatives, Inputs, Outputs, Parameters};
use crate::models::{EngineEvent, ModelError, StepInputs};
use landings::{Landing, LandingLog, Landings};
use serde::{Deserialize, Serialize};
use skirt_map::SkirtMap;
use statistics::ImpactStatistics;

/// A running simulation of engine model `E` (the FMU runs [`ModelVariant`]).
///
/// Clone + Serialize + Deserialize: it is the whole simulation state an FMU state saves, including
/// the impact statistics, the events of the last step and the log cursor.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Simulation<E = ModelVariant> {
    model: E,
    time: f64,
    outputs: Outputs,
    statistics: ImpactStatistics,
    landings: Landings,
    step_events: Vec<EngineEvent>,
    log: Option<ImpactLog>,
    landing_log: Option<LandingLog>,
    map: Option<SkirtMap>,
    /// The event list of the step before last, lent to the next step (see [`Self::step`]).
    #[serde(skip)]
    spare_events: Scratch<Vec<EngineEvent>>,
    /// The landings a step ended, lent from step to step.
    #[serde(skip)]
    ended: Scratch<Vec<Landing>>,
}

/// A buffer lent from step to step so that a step allocates nothing: not state, so not saved,
/// not copied (a copy starts empty) and equal in every comparison.
#[derive(Debug, Default)]
struct Scratch<T: Default>(T);

impl<T: Default> Clone for Scratch<T> {
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl<T: Default> PartialEq for Scratch<T> {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl<E: Mechanism> Simulation<E> {
    /// Builds the model at `start_time` with its initial outputs; the model validates the parameters
    /// (`Mechanism::new`: the table's ranges, then its own checks, once). Touches no file: the impact log
    /// starts with [`Self::start`].
    pub fn new(params: &Parameters, start_time: f64) -> Result<Self, ModelError> {
        if !start_time.is_finite() {
            return Err(ModelError(format!("start time {start_time} is not finite")));
        }
        let model = E::new(params, start_time)?;
        let mut sim = Self {
            model,
            time: start_time,
            outputs: Outputs::default(),
            statistics: ImpactStatistics::starting_at(
                params.crank_angle_start,
                params.slap_threshold,
                std::f64::consts::PI * 0.5 * params.piston_diameter * params.piston_diameter * params.crank_radius,
            ),
            landings: Landings::default(),
            step_events: Vec::new(),
            log: None,
            landing_log: None,
            map: None,
            spare_events: Scratch::default(),
            ended: Scratch::default(),
        };
        Self::write_outputs(&sim.model, (&mut sim.statistics, &sim.landings), Some(&[]), &mut sim.outputs);
        sim.landings.seat(start_time, &sim.outputs);
        Ok(sim)
    }

    /// Before the first step: puts the model into the state the first step will start from with
    /// `inputs` (a free crank at its start speed `crank_speed`), so that the initial outputs
    /// (`kinetic_energy`, `crank_speed_actual`) describe it. A step rebuilds it from the inputs then.
    pub fn prepare(&mut self, inputs: &Inputs) -> Result<(), ModelError> {
        self.model.prepare(&mechanisms::held(inputs))?;
        Self::write_outputs(&self.model, (&mut self.statistics, &self.landings), None, &mut self.outputs);
        self.landings.seat(self.time, &self.outputs);
        Ok(())
    }

    /// Builds as [`Self::new`] and creates the impact log, the landing log and the skirt map when
    /// `impact_log`, `landing_log` and `skirt_map` name files: an unwritable path is an error here, not
    /// at the first impact, landing or pass.
    pub fn start(params: &Parameters, start_time: f64) -> Result<Self, ModelError> {
        let mut sim = Self::new(params, start_time)?;
        if !params.impact_log.is_empty() {
            sim.log = Some(ImpactLog::create(&params.impact_log)?);
        }
        if !params.landing_log.is_empty() {
            sim.landing_log = Some(LandingLog::create(&params.landing_log)?);
        }
        sim.map = SkirtMap::of(params)?;
        Ok(sim)
    }

    /// s, the time reached.
    pub fn time(&self) -> f64 {
        self.time
    }

    /// The outputs at `time()`.
    pub fn outputs(&self) -> &Outputs {
        &self.outputs
    }

    /// The events of the last step, in order.
    pub fn step_events(&self) -> &[EngineEvent] {
        &self.step_events
    }

    /// Advances to exactly `t_end` with `inputs` held. All or nothing: on error `self` is unchanged.
    pub fn step(&mut self, inputs: &Inputs, t_end: f64) -> Result<(), ModelError> {
        self.step_interpolated(inputs, &InputDerivatives::default(), t_end)
    }

    /// As [`Self::step`], the inputs following their values and `derivatives` (at the current time)
    /// as polynomials in time. The one place a step's inputs are checked: a value or derivative that is
    /// not finite is refused by name; the models take them as given.
    pub fn step_interpolated(&mut self, inputs: &Inputs, derivatives: &InputDerivatives, t_end: f64) -> Result<(), ModelError> {
        derivatives.check_finite(inputs)?;
        if !(t_end.is_finite() && t_end > self.time) {
            return Err(ModelError(format!("step end {t_end} s is not after the current time {} s", self.time)));
        }
        // The model advances in place, so that the event list inside it keeps its capacity from
        // step to step, and the step's events go into the list of the step before last: no
        // allocation. A copy taken first (allocation-free: between steps the model holds no
        // events) puts the model back if the step fails; a point the model serves from a step
        // already taken needs none: the model reads the point before it again. The statistics are
        // a few numbers, copied; the outputs are written again from the model and statistics.
        let inputs = derivatives.polynomials(inputs, self.time);
        let served = self.model.serve(&inputs, t_end);
        let before = served.is_none().then(|| self.model.clone());
        let mut events = std::mem::take(&mut self.spare_events.0);
        events.clear();
        let (statistics, landings) = (self.statistics, self.landings);
        let in_step = (self.outputs.liner_impulse_antithrust_in_step, self.outputs.liner_impulse_thrust_in_step);
        match self.try_step(served, &inputs, t_end, &mut events) {
            Ok(()) => {
                self.time = t_end;
                self.spare_events.0 = std::mem::replace(&mut self.step_events, events);
                Ok(())
            }
            Err(e) => {
                self.spare_events.0 = events;
                (self.statistics, self.landings) = (statistics, landings);
                match before {
                    Some(before) => self.model = before,
                    None => self.model.serve_again(self.time).map_err(|u| ModelError(format!("{e}; undoing the step failed: {u}")))?,
                }
                // The outputs are those of the model and the statistics: as they were again.
                Self::write_outputs(&self.model, (&mut self.statistics, &self.landings), None, &mut self.outputs);
                (self.outputs.liner_impulse_antithrust_in_step, self.outputs.liner_impulse_thrust_in_step) = in_step;
                Err(e)
            }
        }
    }

    /// The fallible part of [`Self::step`]: advances the model into `events` (unless it `served`
    /// the point already), takes them into the statistics, writes the outputs and, at a pass of its
    /// crank angle, the skirt map, and appends the events to the impact log once nothing else can
    /// fail. On error `step` puts the rest back.
    fn try_step(
        &mut self,
        served: Option<Result<(), ModelError>>,
        inputs: &StepInputs,
        t_end: f64,
        events: &mut Vec<EngineEvent>,
    ) -> Result<(), ModelError> {
        let failed = |what: &str, e: &dyn std::fmt::Display| ModelError(format!("step from t = {} s to {t_end} s {what}: {e}", self.time));
        let advanced = served.unwrap_or_else(|| self.model.advance_interpolated(inputs, t_end, events));
        advanced.map_err(|e| failed("failed", &e))?;
        let (before, crank_angle) = (self.outputs.liner_impulse_total, self.outputs.crank_angle);
        Self::write_outputs(&self.model, (&mut self.statistics, &self.landings), Some(events), &mut self.outputs);
        let ended = &mut self.ended.0;
        ended.clear();
        self.landings.record(events, t_end, &self.outputs, ended);
        self.landings.write(&mut self.outputs);
        // The liner's impulse during the step: the difference of its totals.
        let total = self.outputs.liner_impulse_total;
        [self.outputs.liner_impulse_antithrust_in_step, self.outputs.liner_impulse_thrust_in_step] =
            [total[0] - before[0], total[1] - before[1]];
        Self::valid(t_end, &self.outputs).map_err(|e| failed("refused", &e.0))?;
        // The film is solved once more only at a pass. Before the log: its rows are the last thing
        // a step writes.
        if let Some(map) = self.map.as_ref().filter(|map| map.passed(crank_angle, self.outputs.crank_angle)) {
            if let Some(fields) = self.model.pressure_map() {
                map.write(t_end, self.outputs.crank_angle, &fields)?;
            }
        }
        // Each log cuts its file back and keeps its cursor when it fails; the landing log is put back
        // where the impact log's failure fails the step after it.
        let mark = self.landing_log.as_ref().map(LandingLog::mark);
        if let Some(log) = &mut self.landing_log {
            log.append(&self.ended.0)?;
        }
        if let Some(log) = &mut self.log {
            if let Err(e) = log.append(events) {
                if let (Some(landing_log), Some(mark)) = (&mut self.landing_log, mark) {
                    landing_log.unwind(mark);
                }
                return Err(e);
            }
        }
        Ok(())
    }

    /// What every state must satisfy (a restored one included): a finite time, finite outputs and
    /// landings on the two walls.
    pub fn check(&self) -> Result<(), ModelError> {
        Self::valid(self.time, &self.outputs)?;
        self.landings.check()
    }

    fn valid(time: f64, outputs: &Outputs) -> Result<(), ModelError> {
        if !time.is_finite() {
            return Err(ModelError(format!("time {time} s is not finite")));
        }
        match outputs.first_non_finite() {
            Some((name, x)) => Err(ModelError(format!("{name} = {x} is not finite"))),
            None => Ok(()),
        }
    }

    /// A file this simulation writes that `params` do not name (a restored state may cut only the
    /// instance's own files), as the refusal says it; None when there is none.
    pub fn foreign_log(&self, params: &Parameters) -> Option<String> {
        let foreign = |path: Option<&str>, own: &str, name: &str| {
            path.filter(|p| *p != own).map(|p| format!("the state writes {name} {p:?}, not this instance's {name} {own:?}"))
        };
        foreign(self.log.as_ref().map(ImpactLog::path), &params.impact_log, "impact_log")
            .or_else(|| foreign(self.landing_log.as_ref().map(LandingLog::path), &params.landing_log, "landing_log"))
    }

    /// After a restore: cut the impact and landing logs back to this state's cursors.
    pub fn rewind_log(&self) -> Result<(), ModelError> {
        self.log.as_ref().map_or(Ok(()), ImpactLog::rewind)?;
        self.landing_log.as_ref().map_or(Ok(()), LandingLog::rewind)
    }

    /// Writes the outputs of `model` with the impact statistics `statistics`, which first take in the
    /// `events` of a step (none for a new simulation) ending at the model's crank angle, if given,
    /// and the landings' figures. Every output is written from the three: the outputs are a
    /// function of them (a step's landings are taken in from the model's outputs, then written again).
    fn write_outputs(
        model: &E,
        (statistics, landings): (&mut ImpactStatistics, &Landings),
        events: Option<&[EngineEvent]>,
        outputs: &mut Outputs,
    ) {
        model.write_outputs(outputs);
        // The engine's sign: what the crank train delivers to the drive or load.
        outputs.engine_torque = -outputs.crank_torque;
        if let Some(events) = events {
            statistics.record_step(events, outputs.crank_angle, outputs.liner_friction_work);
        }
        statistics.write(outputs);
        landings.write(outputs);
        outputs.dissipated_energy_total = outputs.impact_energy_total + outputs.friction_energy_total + outputs.film_energy_total;
    }
}

#[cfg(test)]
pub(crate) mod test_model;

#[cfg(test)]
mod tests;
