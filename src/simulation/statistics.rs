//! The impact statistics outputs (DESIGN.md §4), computed from the event rows. Kept apart from the
//! model's outputs so a model writing its `Outputs` cannot disturb them.

use crate::models::{EngineEvent, EngineEventKind, Outputs};
use serde::{Deserialize, Serialize};

#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ImpactStatistics {
    impact_velocity: f64,
    impact_count: i32,
    impacts_in_step: i32,
    max_impact_velocity_in_step: f64,
    impact_energy_in_step: f64,
    impact_energy_total: f64,
    last_impact_corner: i32,
    last_impact_crank_angle: f64,
}

impl ImpactStatistics {
    /// Takes in the events of one step. Only impacts count: slides and releases dissipate nothing
    /// in the outputs' definition ("energy dissipated by impacts").
    pub fn record_step(&mut self, events: &[EngineEvent]) {
        self.impacts_in_step = 0;
        self.max_impact_velocity_in_step = 0.0;
        self.impact_energy_in_step = 0.0;
        for e in events.iter().filter(|e| e.kind == EngineEventKind::Impact) {
            self.impacts_in_step = self.impacts_in_step.saturating_add(1);
            self.max_impact_velocity_in_step = self.max_impact_velocity_in_step.max(e.normal_velocity_before);
            self.impact_energy_in_step += e.energy_lost;
            self.impact_velocity = e.normal_velocity_before;
            self.last_impact_corner = i32::from(e.corner);
            self.last_impact_crank_angle = e.crank_angle;
        }
        self.impact_count = self.impact_count.saturating_add(self.impacts_in_step);
        self.impact_energy_total += self.impact_energy_in_step;
    }

    pub fn write(&self, out: &mut Outputs) {
        out.impact_velocity = self.impact_velocity;
        out.impact_count = self.impact_count;
        out.impacts_in_step = self.impacts_in_step;
        out.max_impact_velocity_in_step = self.max_impact_velocity_in_step;
        out.impact_energy_in_step = self.impact_energy_in_step;
        out.impact_energy_total = self.impact_energy_total;
        out.last_impact_corner = self.last_impact_corner;
        out.last_impact_crank_angle = self.last_impact_crank_angle;
    }
}
