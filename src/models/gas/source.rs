//! Where the crank train's gas pressure comes from (`pressure_source`): the host's `gas_pressure` input (1),
//! the built-in four-stroke curve (2) or a measured trace (3), all gauge (cylinder minus crankcase), Pa.

use super::{FourStrokePressure, PressureTrace};
use crate::models::InputPolynomial;
use serde::{Deserialize, Serialize};

/// The pressure on the crown, of crank angle (curve, trace) or of time (the held input).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum GasPressure {
    /// The built-in four-stroke curve of crank angle.
    BuiltIn(FourStrokePressure),
    /// A measured trace of crank angle.
    Trace(PressureTrace),
    /// The host's `gas_pressure` input, Pa, over a step.
    Held(InputPolynomial),
}

impl GasPressure {
    /// Whether taking `pressure` would change nothing: it is the held input already, or the
    /// pressure comes from the built-in curve or a trace.
    pub fn holds(&self, pressure: &InputPolynomial) -> bool {
        !matches!(self, Self::Held(p) if !p.same_as(pressure))
    }

    /// Takes the `gas_pressure` input over the next step, if the pressure comes from it.
    pub fn hold(&mut self, pressure: InputPolynomial) {
        if let Self::Held(p) = self {
            *p = pressure;
        }
    }

    /// The part of the pressure that is a function of crank angle (`sin`, `cos` its sine and
    /// cosine), Pa; 0 for the held input.
    #[inline(always)]
    pub fn of_angle(&self, angle: f64, sin: f64, cos: f64) -> f64 {
        match self {
            Self::BuiltIn(curve) => curve.gauge_at(angle, sin, cos),
            Self::Trace(trace) => trace.gauge(angle),
            Self::Held(_) => 0.0,
        }
    }

    /// The pressure at time `t` where [`Self::of_angle`] gave `of_angle`, Pa.
    #[inline(always)]
    pub fn at(&self, t: f64, of_angle: f64) -> f64 {
        match self {
            Self::BuiltIn(_) | Self::Trace(_) => of_angle,
            Self::Held(p) => p.at(t),
        }
    }
}
