//! What the engine cycle's parameters imply: their relations beyond the table's ranges, the heat-transfer speed and
//! the slider-crank volume.

use super::EngineCycleParameters;
use crate::models::error::ModelError;
use std::f64::consts::PI;

/// rad/s: below this the correlations, fitted on running engines, are not applied.
pub const SLOWEST_HEAT_TRANSFER_SPEED: f64 = 10.0 * PI;

/// Cylinder volume V and its first two derivatives with respect to the crank angle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Volume {
    /// m³.
    pub v: f64,
    /// m³/rad.
    pub dv: f64,
    /// m³/rad².
    pub d2v: f64,
}

impl EngineCycleParameters {
    /// Every value finite and within its table range (modelDescription/engine_cycle.xml), a rod longer
    /// than the crank radius, and a running engine where heat transfer is on; the message names the parameter.
    /// The limits that depend on the charge (fuel, peak pressure and temperature) are checked by the cycle.
    pub fn validate(&self) -> Result<(), ModelError> {
        self.check_ranges()?;
        for (name, value) in [("compression_ratio", self.compression_ratio), ("polytropic_exponent", self.polytropic_exponent)] {
            if value <= 1.0 {
                return Err(ModelError(format!("{name} = {value} is out of range: must be > 1")));
            }
        }
        if self.burn_start <= -PI {
            return Err(ModelError(format!("burn_start = {} rad is out of range: must be > −π", self.burn_start)));
        }
        if self.exhaust_valve_opening >= PI {
            return Err(ModelError(format!("exhaust_valve_opening = {} rad is out of range: must be < π", self.exhaust_valve_opening)));
        }
        if self.rod_length <= 0.5 * self.stroke {
            return Err(ModelError(format!(
                "rod_length = {} m is out of range: must be > stroke/2 = {} m",
                self.rod_length,
                0.5 * self.stroke
            )));
        }
        if self.heat_transfer != 0 && self.cycle_speed() < SLOWEST_HEAT_TRANSFER_SPEED {
            return Err(ModelError(format!(
                "heat_transfer = {} needs a running engine: the cycle's speed (speed_end after a ramp, else speed_start) \
                 {} rad/s is below {SLOWEST_HEAT_TRANSFER_SPEED:.2} rad/s (300 rpm)",
                self.heat_transfer,
                self.cycle_speed()
            )));
        }
        Ok(())
    }

    /// rad/s, the speed the closed cycle's heat transfer is computed at: `speed_end` after a ramp, else
    /// `speed_start` (per crank angle the wall heat scales with ω^−0.2 for Woschni).
    pub fn cycle_speed(&self) -> f64 {
        if self.ramp_time > 0.0 {
            self.speed_end
        } else {
            self.speed_start
        }
    }

    /// m², piston crown area A = π B²/4.
    pub fn area(&self) -> f64 {
        0.25 * PI * self.bore * self.bore
    }

    /// m³, displaced volume V_d = A S.
    pub fn displacement(&self) -> f64 {
        self.area() * self.stroke
    }

    /// The slider-crank volume at crank angle `theta` (Heywood eq 2.6).
    pub fn volume(&self, theta: f64) -> Volume {
        let (r, l, area) = (0.5 * self.stroke, self.rod_length, self.area());
        let (sin, cos) = libm::sincos(theta);
        let root = (l * l - r * r * sin * sin).sqrt();
        let s = r + l - r * cos - root;
        let ds = r * sin + r * r * sin * cos / root;
        let d2s = r * cos + r * r * ((cos * cos - sin * sin) / root + r * r * sin * sin * cos * cos / root.powi(3));
        let clearance = self.displacement() / (self.compression_ratio - 1.0);
        Volume { v: clearance + area * s, dv: area * ds, d2v: area * d2s }
    }
}
