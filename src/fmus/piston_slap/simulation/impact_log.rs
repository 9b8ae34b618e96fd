//! The `impact_log` CSV: one row per impact, slide start or release, in SI units, with the crank
//! angle in degrees as well (the last column, so readers of the older columns are unaffected). A first
//! line starting with `#` states the crank-angle conventions: `crank_angle` in rad in [0, 4π), and
//! `crank_angle_deg` as engine people read it, in [−360, 360), both from firing TDC. `energy_lost` is
//! what the normal (restitution) impulse dissipated, as `impact_energy_total` counts it;
//! `friction_energy_lost` the tangential (friction) impulse's share, which `friction_energy_total` counts.
//! The file keeps to the trajectory as every `CsvLog` does.

use super::csv_log::{CsvLog, Rows};
use super::statistics::normal_energy;
use crate::models::{EngineEvent, EngineEventKind};

/// The impact log's rows.
#[derive(Clone, Debug, PartialEq)]
pub struct Impacts;

impl Rows for Impacts {
    type Row = EngineEvent;
    const PARAMETER: &'static str = "impact_log";
    const HEADER: &'static str = "# crank_angle [rad] in [0, 4π) and crank_angle_deg [deg] in [-360, 360), both from firing TDC\n\
time,crank_angle,kind,corner,normal_velocity_before,normal_velocity_after,energy_lost,position,crank_angle_deg,friction_energy_lost\n";

    /// Floats in Rust's shortest round-trip form, so the file reproduces the values exactly.
    fn row(e: &EngineEvent) -> String {
        let kind = match e.kind {
            EngineEventKind::Impact => "impact",
            EngineEventKind::Slide => "slide",
            EngineEventKind::Release => "release",
            EngineEventKind::Stick => "stick",
            EngineEventKind::Slip => "slip",
        };
        format!(
            "{},{},{kind},{},{},{},{},{},{},{}\n",
            e.time,
            e.crank_angle,
            e.corner,
            e.normal_velocity_before,
            e.normal_velocity_after,
            normal_energy(e),
            e.position,
            degrees_from_firing_tdc(e.crank_angle),
            e.friction_energy
        )
    }
}

/// The open impact log.
pub type ImpactLog = CsvLog<Impacts>;

/// The crank angle `phase` ∈ [0, 4π) from firing TDC in degrees in [−360, 360): the cycle centred on firing TDC.
pub(super) fn degrees_from_firing_tdc(phase: f64) -> f64 {
    let degrees = phase.to_degrees();
    if degrees >= 360.0 {
        degrees - 720.0
    } else {
        degrees
    }
}
