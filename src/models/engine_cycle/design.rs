//! The engine cycle's design and what it implies: the relations of its values, the heat-transfer speed and the
//! slider-crank volume.

use crate::models::error::ModelError;
use serde::{Deserialize, Serialize};
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

/// The engine cycle's design: the cylinder, the gas model, the walls, the manifolds' pressures and the charge,
/// the combustion, the exhaust valve timing and the prescribed speed. Its fields are checked against each other
/// by [`CycleDesign::validate`]; their ranges are the caller's to check.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CycleDesign {
    /// M: cylinder bore B.
    pub bore: f64,
    /// M: stroke S, twice the crank radius.
    pub stroke: f64,
    /// M: connecting-rod length l, > S/2.
    pub rod_length: f64,
    /// Compression ratio ε = (V_c + V_d)/V_c, > 1.
    pub compression_ratio: f64,
    /// 1 = constant `polytropic_exponent`, 2 = temperature-dependent heat capacities of air and burned gas.
    pub gas_properties: i32,
    /// Polytropic exponent n of compression and expansion with `gas_properties` 1, > 1.
    pub polytropic_exponent: f64,
    /// Wall heat transfer over the closed cycle ([`super::Correlation`]'s code: 0 none, 1 Woschni, 2 Hohenberg).
    pub heat_transfer: i32,
    /// K: wall temperature of head, piston crown and liner.
    pub wall_temperature: f64,
    /// Pa: absolute pressure of the intake stroke and at intake valve closing.
    pub intake_pressure: f64,
    /// K: charge temperature at intake valve closing.
    pub intake_temperature: f64,
    /// Mass fraction of burned gas in the charge at intake valve closing.
    pub residual_gas_fraction: f64,
    /// Pa: absolute pressure of the exhaust stroke.
    pub exhaust_pressure: f64,
    /// Pa: absolute crankcase pressure, under the piston.
    pub crankcase_pressure: f64,
    /// J: heat released by combustion per cycle (0: motored).
    pub heat_release: f64,
    /// J/kg: lower heating value of the fuel.
    pub fuel_heating_value: f64,
    /// Y of the fuel CH_y: the burned gas and the stoichiometric fuel/air ratio.
    pub fuel_hydrogen_carbon_ratio: f64,
    /// Rad: start of combustion relative to firing top dead centre (Wiebe ϑ_s), > −π.
    pub burn_start: f64,
    /// Rad: combustion duration (Wiebe Δϑ).
    pub burn_duration: f64,
    /// Wiebe efficiency factor a.
    pub wiebe_efficiency: f64,
    /// Wiebe form factor m.
    pub wiebe_form: i32,
    /// Rad: exhaust valve opening after firing top dead centre, < π.
    pub exhaust_valve_opening: f64,
    /// Rad/s: crank speed at the start time.
    pub speed_start: f64,
    /// Rad/s: crank speed at the end of the ramp.
    pub speed_end: f64,
    /// S: duration of the linear speed ramp (0: constant `speed_start`).
    pub ramp_time: f64,
    /// Rad: crank angle at the start time.
    pub crank_angle_start: f64,
}

impl CycleDesign {
    /// The relations of values each within its range: exponents above 1, the exhaust valve and the burn within the
    /// cycle, a rod longer than the crank radius, and a running engine where heat transfer is on; the message names
    /// the value. The limits that depend on the charge (fuel, peak pressure and temperature) are checked by the cycle.
    pub fn validate(&self) -> Result<(), ModelError> {
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

    /// The slider-crank volume at crank angle `theta` (Heywood eq 2.6; the number not checked).
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
