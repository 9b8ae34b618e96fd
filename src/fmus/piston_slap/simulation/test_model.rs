//! Test-only engine model with closed-form answers, to test the facade and the FMI layer before and
//! independently of the physics: a shuttle moving laterally at constant speed between the liner walls
//! x = ±c, c = (bore − piston_diameter)/2, with Newton restitution `restitution` at each wall.
//! It starts at x = 0 with ẋ = `SHUTTLE_SPEED`; crank angle = crank_angle_start + ∫ crank_speed dt.
//! A negative `gas_pressure` makes `advance` fail, `load_torque` = 42 makes it panic (to test error
//! handling). Input derivatives are ignored (the inputs are held). Never shipped.

use super::super::Mechanism;
use crate::fmus::piston_slap::{Outputs, Parameters};
use crate::models::{EngineEvent, EngineEventKind, EngineModel, ModelError, StepInputs};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

pub const SHUTTLE_SPEED: f64 = 0.01;

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Shuttle {
    time: f64,
    x: f64,
    v: f64,
    crank_angle: f64,
    half_clearance: f64,
    restitution: f64,
    mass: f64,
}

impl Mechanism for Shuttle {
    fn new(params: &Parameters, start_time: f64) -> Result<Self, ModelError> {
        params.validate()?;
        Ok(Self {
            time: start_time,
            x: 0.0,
            v: SHUTTLE_SPEED,
            crank_angle: params.crank_angle_start,
            half_clearance: (params.bore - params.piston_diameter) / 2.0,
            restitution: params.restitution,
            mass: params.piston_mass,
        })
    }

    fn write_outputs(&self, out: &mut Outputs) {
        // Overwrite everything, as a model may: the facade must keep its statistics regardless.
        *out = Outputs {
            piston_lateral: self.x,
            piston_lateral_velocity: self.v,
            crank_angle: self.crank_angle,
            lateral_kinetic_energy: 0.5 * self.mass * self.v * self.v,
            ..Outputs::default()
        };
    }
}

impl EngineModel for Shuttle {
    fn advance_interpolated(&mut self, inputs: &StepInputs, t_end: f64, events: &mut Vec<EngineEvent>) -> Result<(), ModelError> {
        assert!(inputs.load_torque.value != 42.0, "shuttle: load_torque = 42 panics (to test panic containment)");
        if inputs.gas_pressure.value < 0.0 {
            // Move first so that a caller that does not restore its copy would be caught.
            self.time = t_end;
            return Err(ModelError("shuttle: negative gas_pressure".into()));
        }
        while self.time < t_end {
            let wall = self.half_clearance * self.v.signum();
            let to_wall = if self.v == 0.0 { f64::INFINITY } else { (wall - self.x) / self.v };
            let dt = to_wall.min(t_end - self.time);
            self.time += dt;
            self.crank_angle += inputs.crank_speed.value * dt;
            if dt < to_wall {
                self.x += self.v * dt;
                continue;
            }
            self.x = wall;
            let before = self.v;
            self.v = -self.restitution * before;
            events.push(EngineEvent {
                time: self.time,
                crank_angle: self.crank_angle.rem_euclid(4.0 * PI),
                cycle: (self.crank_angle / (4.0 * PI)).floor() as i64,
                kind: EngineEventKind::Impact,
                corner: if wall > 0.0 { 3 } else { 1 },
                normal_velocity_before: before.abs(),
                normal_velocity_after: self.v.abs(),
                energy_lost: 0.5 * self.mass * (before * before - self.v * self.v),
                friction_energy: 0.0,
                position: 0.0,
                lateral_kinetic_energy: 0.5 * self.mass * before * before,
            });
        }
        self.time = t_end;
        Ok(())
    }
}
