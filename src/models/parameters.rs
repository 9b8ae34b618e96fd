//! The FMU's variable contract (`../shared/DESIGN.md` §4) as plain Rust values, in SI units.
//! Field names are the FMI variable names: the value-reference dispatch generated from
//! `modelDescription/` addresses these fields by name.

use serde::{Deserialize, Serialize};
use std::fmt;

/// A refused parameter set or a failed step, with a message naming the cause.
#[derive(Clone, Debug, PartialEq)]
pub struct ModelError(pub String);

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ModelError {}

/// Model parameters; defaults are Awrejcewicz & Kudra section 8 unless DESIGN.md says otherwise.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Parameters {
    pub model_variant: i32,
    pub crank_mode: i32,
    pub pressure_source: i32,
    pub roller_forcing: i32,
    pub peak_pressure: f64,
    pub crank_radius: f64,
    pub rod_length: f64,
    pub crank_com: f64,
    pub rod_com: f64,
    pub piston_com: f64,
    pub crank_mass: f64,
    pub rod_mass: f64,
    pub piston_mass: f64,
    pub crank_inertia: f64,
    pub rod_inertia: f64,
    pub piston_inertia: f64,
    pub piston_diameter: f64,
    pub skirt_length: f64,
    pub pin_height: f64,
    pub bore: f64,
    pub pin_offset: f64,
    pub restitution: f64,
    pub damping_main: f64,
    pub damping_crank_pin: f64,
    pub damping_piston_pin: f64,
    pub gravity: f64,
    pub crank_angle_start: f64,
    pub impact_log: String,
}

impl Default for Parameters {
    fn default() -> Self {
        Self {
            model_variant: 1,
            crank_mode: 1,
            pressure_source: 2,
            roller_forcing: 2,
            peak_pressure: 8e6,
            crank_radius: 0.04,
            rod_length: 0.15,
            crank_com: 0.0,
            rod_com: 0.12,
            piston_com: 0.01,
            crank_mass: 10.0,
            rod_mass: 1.0,
            piston_mass: 0.4,
            crank_inertia: 1.0,
            rod_inertia: 0.0075,
            piston_inertia: 0.001,
            piston_diameter: 0.08,
            skirt_length: 0.08,
            pin_height: 0.04,
            bore: 0.08008,
            pin_offset: 0.0,
            restitution: 0.5,
            damping_main: 0.0288,
            damping_crank_pin: 0.00576,
            damping_piston_pin: 0.00288,
            gravity: 9.81,
            crank_angle_start: 0.0,
            impact_log: String::new(),
        }
    }
}

/// Continuous inputs, held constant over a communication step.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Inputs {
    /// rad/s, used when `crank_mode = 1`.
    pub crank_speed: f64,
    /// Pa, cylinder minus crankcase pressure, used when `pressure_source = 1`.
    pub gas_pressure: f64,
    /// N·m, opposing rotation, used when `crank_mode = 2`.
    pub load_torque: f64,
}

impl Default for Inputs {
    fn default() -> Self {
        Self { crank_speed: 125.66, gas_pressure: 0.0, load_torque: 0.0 }
    }
}

/// Outputs (DESIGN.md §4). Impact statistics are filled by the caller from the event record;
/// the kinematic and force outputs by the model.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Outputs {
    pub impact_velocity: f64,
    pub impact_count: i32,
    pub impacts_in_step: i32,
    pub max_impact_velocity_in_step: f64,
    pub impact_energy_in_step: f64,
    pub impact_energy_total: f64,
    pub last_impact_corner: i32,
    pub last_impact_crank_angle: f64,
    pub piston_lateral: f64,
    pub piston_lateral_velocity: f64,
    pub piston_tilt: f64,
    pub piston_axial: f64,
    pub crank_angle: f64,
    pub rod_angle: f64,
    pub crank_torque: f64,
    pub contact_state_1: i32,
    pub contact_state_2: i32,
    pub contact_state_3: i32,
    pub contact_state_4: i32,
    pub contact_force_1: f64,
    pub contact_force_2: f64,
    pub contact_force_3: f64,
    pub contact_force_4: f64,
    pub side_force: f64,
}
