//! The impact statistics outputs, computed from the event rows: running totals, the last step's
//! figures and the per-cycle metrics. Kept apart from the model's outputs so a model writing its
//! `Outputs` cannot disturb them.

use crate::fmus::piston_slap::Outputs;
use crate::models::numerics::floor_to_i64;
use crate::models::{EngineEvent, EngineEventKind, CYCLE};
use serde::{Deserialize, Serialize};

#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ImpactStatistics {
    impact_velocity: f64,
    impact_count: i32,
    impacts_in_step: i32,
    max_impact_velocity_in_step: f64,
    impact_energy_in_step: f64,
    impact_energy_total: f64,
    last_impact_corner: i32,
    last_impact_crank_angle: f64,
    slap_threshold: f64,
    /// The wall of the last landing (impact or slide start): −1 anti-thrust, 1 major thrust, 0 none yet.
    wall: i8,
    /// The engine cycle in progress: its index (whole cycles of the crank angle) and its figures.
    cycle: i64,
    open: CycleMetrics,
    /// The figures of the last completed cycle and how many cycles have completed.
    completed: CycleMetrics,
    cycle_count: i32,
    friction: FrictionCycle,
}

/// The piston–liner friction work per cycle (`cycle_skirt_fmep`): the work at the last point, and
/// at the start of the cycle in progress where the run has seen it, the work at a cycle boundary
/// taken linearly in crank angle between the points around it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
struct FrictionCycle {
    /// Displaced volume π d²/4 · 2 l1, m³.
    volume: f64,
    /// rad (accumulated) and J at the last point.
    angle: f64,
    work: f64,
    /// J at the start of the cycle in progress.
    start: Option<f64>,
    /// Pa, of the last completed cycle.
    fmep: f64,
}

impl FrictionCycle {
    fn record(&mut self, angle: f64, work: f64) {
        let (from, to) = (cycle_of(self.angle), cycle_of(angle));
        // Only the last two boundaries matter; a step past more has no cycle start to go by.
        if to > from + 2 {
            self.start = None;
        }
        for c in (from + 1).max(to - 1)..=to {
            let boundary = c as f64 * CYCLE;
            let at = self.work + (work - self.work) * (boundary - self.angle) / (angle - self.angle);
            if let Some(start) = self.start {
                self.fmep = (at - start) / self.volume;
            }
            self.start = Some(at);
        }
        (self.angle, self.work) = (angle, work);
    }
}

/// What one engine cycle's impacts amount to: all of them, and the slaps among them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
struct CycleMetrics {
    impacts: i32,
    impact_energy: f64,
    max_impact_energy_antithrust: f64,
    max_impact_energy_thrust: f64,
    /// Per wall, [anti-thrust, major thrust]: slaps, their energy, the largest.
    slaps: [i32; 2],
    slap_energy: [f64; 2],
    max_slap_energy: [f64; 2],
}

/// The wall a corner touches: −1 for corners 1, 2 (−D/2, anti-thrust), 1 for 3, 4 (+D/2, major thrust).
fn wall_of(corner: u8) -> i8 {
    if corner <= 2 {
        -1
    } else {
        1
    }
}

impl CycleMetrics {
    /// Takes in one impact; `slap` when it lands the piston on the other wall faster than the threshold.
    fn add(&mut self, e: &EngineEvent, slap: bool) {
        let energy = normal_energy(e);
        self.impacts = self.impacts.saturating_add(1);
        self.impact_energy += energy;
        let side = if e.corner <= 2 { &mut self.max_impact_energy_antithrust } else { &mut self.max_impact_energy_thrust };
        *side = side.max(energy);
        if slap {
            let w = usize::from(e.corner > 2);
            self.slaps[w] = self.slaps[w].saturating_add(1);
            self.slap_energy[w] += energy;
            self.max_slap_energy[w] = self.max_slap_energy[w].max(energy);
        }
    }
}

/// J, what an event's normal (restitution) impulse dissipated: its loss less the tangential
/// (friction) part, which `friction_energy_total` counts. The impact outputs count only this, so
/// that impact and friction energy partition the dissipation.
pub fn normal_energy(e: &EngineEvent) -> f64 {
    e.energy_lost - e.friction_energy
}

/// Whole engine cycles (4π) in an accumulated crank angle: the index of the cycle it lies in.
pub fn cycle_of(crank_angle: f64) -> i64 {
    floor_to_i64(crank_angle / CYCLE)
}

impl ImpactStatistics {
    /// No impacts yet; the first cycle is the one `crank_angle` (rad, accumulated) lies in, and
    /// counts for the friction work per displaced volume `volume` (m³) if it starts there.
    pub fn starting_at(crank_angle: f64, slap_threshold: f64, volume: f64) -> Self {
        let start = (crank_angle.rem_euclid(CYCLE) == 0.0).then_some(0.0);
        let friction = FrictionCycle { volume, angle: crank_angle, start, ..FrictionCycle::default() };
        Self { cycle: cycle_of(crank_angle), slap_threshold, friction, ..Self::default() }
    }

    /// Takes in the events of one step, after which the crank angle is `crank_angle` (rad,
    /// accumulated). Only impacts count: slides and releases dissipate nothing in the outputs'
    /// definition ("energy dissipated by impacts"); a slide start is a landing, though, so the next
    /// impact on the same wall is no slap. A slap is an impact landing the piston on the other wall
    /// than the last landing's (a side change; the first landing is none), faster than
    /// `slap_threshold`. A cycle is complete once an event or the step's end lies in a later one;
    /// cycles without impacts complete with zero figures. `friction_work`: the piston–liner friction
    /// work since the start then, J.
    pub fn record_step(&mut self, events: &[EngineEvent], crank_angle: f64, friction_work: f64) {
        self.friction.record(crank_angle, friction_work);
        self.impacts_in_step = 0;
        self.max_impact_velocity_in_step = 0.0;
        self.impact_energy_in_step = 0.0;
        for e in events.iter().filter(|e| matches!(e.kind, EngineEventKind::Impact | EngineEventKind::Slide)) {
            let (previous, wall) = (self.wall, wall_of(e.corner));
            self.wall = wall;
            if e.kind == EngineEventKind::Slide {
                continue;
            }
            self.advance_to_cycle(e.cycle);
            self.open.add(e, previous == -wall && e.normal_velocity_before > self.slap_threshold);
            self.impacts_in_step = self.impacts_in_step.saturating_add(1);
            self.max_impact_velocity_in_step = self.max_impact_velocity_in_step.max(e.normal_velocity_before);
            self.impact_energy_in_step += normal_energy(e);
            self.impact_velocity = e.normal_velocity_before;
            self.last_impact_corner = i32::from(e.corner);
            self.last_impact_crank_angle = e.crank_angle;
        }
        self.advance_to_cycle(cycle_of(crank_angle));
        self.impact_count = self.impact_count.saturating_add(self.impacts_in_step);
        self.impact_energy_total += self.impact_energy_in_step;
    }

    /// Completes the cycles before `cycle`.
    fn advance_to_cycle(&mut self, cycle: i64) {
        if cycle <= self.cycle {
            return;
        }
        let finished = std::mem::take(&mut self.open);
        // Cycles skipped without an event had no impacts.
        self.completed = if cycle == self.cycle + 1 { finished } else { CycleMetrics::default() };
        let passed = i32::try_from(cycle - self.cycle).unwrap_or(i32::MAX);
        self.cycle_count = self.cycle_count.saturating_add(passed);
        self.cycle = cycle;
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
        out.cycle_count = self.cycle_count;
        out.cycle_skirt_fmep = self.friction.fmep;
        let c = &self.completed;
        out.cycle_slap_events = c.slaps[0].saturating_add(c.slaps[1]);
        out.cycle_impacts = c.impacts;
        out.cycle_impact_energy = c.impact_energy;
        out.cycle_max_impact_energy_antithrust = c.max_impact_energy_antithrust;
        out.cycle_max_impact_energy_thrust = c.max_impact_energy_thrust;
        [out.cycle_slaps_antithrust, out.cycle_slaps_thrust] = c.slaps;
        [out.cycle_slap_energy_antithrust, out.cycle_slap_energy_thrust] = c.slap_energy;
        [out.cycle_max_slap_energy_antithrust, out.cycle_max_slap_energy_thrust] = c.max_slap_energy;
    }
}
