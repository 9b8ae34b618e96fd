//! The interface the FMU drives a mechanism through, and the events it reports.

use super::skirt::PressureMap;
use super::{InputPolynomial, ModelError};
use crate::dynamics::EventKind;
use serde::{Deserialize, Serialize};

/// One four-stroke engine cycle of crank angle, rad; firing top dead centre at 0 mod 4π.
pub const CYCLE: f64 = 4.0 * std::f64::consts::PI;

/// What happened at an event, in the impact log's words (`impact`, `slide`, `release`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum EngineEventKind {
    /// A corner strikes the liner.
    Impact,
    /// A corner stays on the liner after an impact and slides along it.
    Slide,
    /// A corner leaves the liner.
    Release,
    /// With liner friction: a corner in contact comes to rest along the liner and sticks.
    Stick,
    /// With liner friction: a corner in contact starts to slip, from sticking or reversing.
    Slip,
}

impl From<EventKind> for EngineEventKind {
    /// The core's event kind under its impact-log name.
    fn from(kind: EventKind) -> Self {
        match kind {
            EventKind::Impact => Self::Impact,
            EventKind::Slide => Self::Slide,
            EventKind::Release => Self::Release,
            EventKind::Stick => Self::Stick,
            EventKind::Slip => Self::Slip,
        }
    }
}

/// One row of the impact log (ARCHITECTURE.md §4), in SI units.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct EngineEvent {
    /// s.
    pub time: f64,
    /// rad, in [0, 4π).
    pub crank_angle: f64,
    /// The engine cycle the event lies in: whole cycles (4π) of the accumulated crank angle.
    pub cycle: i64,
    /// What happened.
    pub kind: EngineEventKind,
    /// 1..4: 1, 2 on the −D/2 (anti-thrust) wall, 3, 4 on the +D/2 (major-thrust) wall.
    pub corner: u8,
    /// m/s, normal approach speed −ḣ⁻ (≥ 0 for an impact).
    pub normal_velocity_before: f64,
    /// m/s, ḣ⁺.
    pub normal_velocity_after: f64,
    /// J, kinetic energy dissipated by this event.
    pub energy_lost: f64,
    /// J, the part of `energy_lost` liner friction dissipated (0 without friction).
    pub friction_energy: f64,
    /// m, pin position along the cylinder axis.
    pub position: f64,
    /// J, the piston's kinetic energy of lateral motion and tilt just before the event (the
    /// `lateral_kinetic_energy` output's).
    pub lateral_kinetic_energy: f64,
}

/// The inputs over a step, each a polynomial in time from the step's start: the host's values and
/// derivatives there, built once per step by the façade.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepInputs {
    /// rad/s.
    pub crank_speed: InputPolynomial,
    /// Pa, gauge.
    pub gas_pressure: InputPolynomial,
    /// N·m.
    pub load_torque: InputPolynomial,
}

/// A model variant as the FMU drives it: advanced with held or interpolated inputs.
pub trait EngineModel: Sized + Clone {
    /// Advances to exactly `t_end`, the inputs following their polynomials from the current time, appending
    /// every event to `events`; a model that cannot follow a derivative refuses it. On error the model may be
    /// left anywhere: the caller restores its own copy.
    fn advance_interpolated(&mut self, inputs: &StepInputs, t_end: f64, events: &mut Vec<EngineEvent>) -> Result<(), ModelError>;

    /// Before the first step, the state that step would start from with `inputs` (whose outputs are
    /// then the initial ones); the first step rebuilds it from its own inputs.
    fn prepare(&mut self, _inputs: &StepInputs) -> Result<(), ModelError> {
        Ok(())
    }

    /// The lubricated skirt's pressure and film fields now, where the model has one.
    fn pressure_map(&self) -> Option<PressureMap> {
        None
    }

    /// Advances to `t_end` as [`Self::advance_interpolated`] would where that only reads the state
    /// there from a step already taken (no events): all or nothing, and a point the caller then
    /// refuses is undone by [`Self::serve_again`] at the time before it, with no copy. None, with
    /// nothing done, where it is not such a point.
    fn serve(&mut self, _inputs: &StepInputs, _t_end: f64) -> Option<Result<(), ModelError>> {
        None
    }

    /// Reads the state at `t` again from the step already taken, after a point that
    /// [`Self::serve`] gave beyond `t`: the model is then exactly as it was at `t`.
    fn serve_again(&mut self, t: f64) -> Result<(), ModelError> {
        Err(ModelError(format!("no step taken past t = {t} s to read the state from")))
    }
}
