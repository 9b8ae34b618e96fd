//! The engine cycle's design from EngineCycle's parameters, in one place.

use super::contract::Parameters;
use crate::models::{CycleDesign, ModelError};

/// The design of `p`, each value within its table range (modelDescription/engine_cycle.xml) and the design's
/// relations checked ([`CycleDesign::validate`]).
pub fn design(p: &Parameters) -> Result<CycleDesign, ModelError> {
    p.check_ranges()?;
    let design = CycleDesign {
        bore: p.bore,
        stroke: p.stroke,
        rod_length: p.rod_length,
        compression_ratio: p.compression_ratio,
        gas_properties: p.gas_properties,
        polytropic_exponent: p.polytropic_exponent,
        heat_transfer: p.heat_transfer,
        wall_temperature: p.wall_temperature,
        intake_pressure: p.intake_pressure,
        intake_temperature: p.intake_temperature,
        residual_gas_fraction: p.residual_gas_fraction,
        exhaust_pressure: p.exhaust_pressure,
        crankcase_pressure: p.crankcase_pressure,
        heat_release: p.heat_release,
        fuel_heating_value: p.fuel_heating_value,
        fuel_hydrogen_carbon_ratio: p.fuel_hydrogen_carbon_ratio,
        burn_start: p.burn_start,
        burn_duration: p.burn_duration,
        wiebe_efficiency: p.wiebe_efficiency,
        wiebe_form: p.wiebe_form,
        exhaust_valve_opening: p.exhaust_valve_opening,
        speed_start: p.speed_start,
        speed_end: p.speed_end,
        ramp_time: p.ramp_time,
        crank_angle_start: p.crank_angle_start,
    };
    design.validate()?;
    Ok(design)
}
