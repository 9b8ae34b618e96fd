//! The two crank drives behind one interface. `CrankDrive` is what differs between a prescribed and a free
//! crank (their coordinates, drive input, torque and speed); `CrankStepper` is what the crank train asks of
//! its stepper, written once for a stepper of either drive. `Drive`, the serialized choice, lends its
//! stepper as a `dyn CrankStepper`: the one place the crank train looks at which drive it has.

use super::engine::{Engine, FreeCrank, PrescribedCrank};
use super::linkage::LinkAngles;
use crate::dynamics::{DynamicsError, Event, EventKind, Powers, StepCounts, Stepper, System};
use crate::models::{EngineEvent, InputPolynomial, CYCLE};
use nalgebra::{SVector, Vector3, Vector4};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// The crank train's stepper, of one drive or the other.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub(crate) enum Drive {
    /// The crank turns at the `crank_speed` input; the coordinates are the rod's and piston's angles.
    Prescribed(Stepper<PrescribedCrank, 2, 4>),
    /// The crank is a coordinate, loaded by the `load_torque` input.
    Free(Stepper<FreeCrank, 3, 4>),
}

impl Drive {
    /// The stepper, whichever drive.
    pub(crate) fn stepper(&self) -> &dyn CrankStepper {
        match self {
            Drive::Prescribed(s) => s,
            Drive::Free(s) => s,
        }
    }

    /// The stepper, whichever drive, to advance or change.
    pub(super) fn stepper_mut(&mut self) -> &mut dyn CrankStepper {
        match self {
            Drive::Prescribed(s) => s,
            Drive::Free(s) => s,
        }
    }
}

/// A core event of either drive as its impact-log row, with what the crank train books from it.
pub(crate) struct CrankEvent {
    /// The impact-log row.
    pub row: EngineEvent,
    /// N·s, the normal impulses per corner.
    pub impulses: Vector4<f64>,
    /// J, the work the drive did through the event's impulses (zero for a free crank, whose drive is a
    /// torque); `None` where the rod and piston inertia is singular.
    pub drive_work: Option<f64>,
}

/// What a crank drive adds to its system for the crank train: the full link angles, the drive input,
/// the torque it puts on the crank.
pub(super) trait CrankDrive<const N: usize>: System<N, 4> + Sized {
    /// The engine the drive turns.
    fn engine(&self) -> &Engine;
    /// The same, to change.
    fn engine_mut(&mut self) -> &mut Engine;
    /// φ and φ̇ at `(t, q, q̇)`.
    fn angles(&self, t: f64, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> (Vector3<f64>, Vector3<f64>);
    /// Takes `cycles` whole cycles off the crank angle, `angle` now.
    fn take_cycles(stepper: &mut Stepper<Self, N, 4>, angle: f64, cycles: f64) -> Result<(), DynamicsError>;
    /// Whether the drive's input (crank speed, or load torque) already follows `speed` or `load`.
    fn holds(&self, speed: &InputPolynomial, load: &InputPolynomial) -> bool;
    /// Follows `speed` or `load` from now on.
    fn hold(&mut self, speed: InputPolynomial, load: InputPolynomial);
    /// J, the drive's work through the impulses of `event`.
    fn drive_work(&self, event: &Event<N, 4>) -> Option<f64>;
    /// Pa, the gauge gas pressure at time `t` and crank angle `angle`.
    fn gas_pressure(&self, t: f64, angle: f64) -> f64;
    /// The sines and cosines of the full link angles `phi`.
    fn link_angles(&self, phi: &Vector3<f64>) -> LinkAngles;
    /// N·m, the external torque on the crank now, the corners' contact and friction forces given.
    fn crank_torque(stepper: &Stepper<Self, N, 4>, forces: &Vector4<f64>, friction: &Vector4<f64>) -> f64;
    /// rad/s, the crank speed at time `t`, the crank's rate `rate` given.
    fn crank_speed(&self, t: f64, rate: f64) -> f64;
}

impl CrankDrive<2> for PrescribedCrank {
    fn engine(&self) -> &Engine {
        &self.engine
    }
    fn engine_mut(&mut self) -> &mut Engine {
        &mut self.engine
    }
    fn angles(&self, t: f64, q: &SVector<f64, 2>, qd: &SVector<f64, 2>) -> (Vector3<f64>, Vector3<f64>) {
        self.full_state(t, q, qd)
    }
    /// The crank angle is a function of time: the crank restarts its angle.
    fn take_cycles(stepper: &mut Stepper<Self, 2, 4>, angle: f64, cycles: f64) -> Result<(), DynamicsError> {
        let rebased = stepper.system().rebased(stepper.time(), angle - 4.0 * PI * cycles);
        *stepper.system_mut()? = rebased;
        Ok(())
    }
    fn holds(&self, speed: &InputPolynomial, _: &InputPolynomial) -> bool {
        self.holds_speed(speed)
    }
    fn hold(&mut self, speed: InputPolynomial, _: InputPolynomial) {
        self.hold_speed(speed);
    }
    fn drive_work(&self, e: &Event<2, 4>) -> Option<f64> {
        if e.impulses == Vector4::zeros() {
            return Some(0.0);
        }
        self.impulse_work((e.time, &e.q, &e.v), (&e.impulses, &e.friction_impulses), e.kind == EventKind::Impact)
    }
    fn gas_pressure(&self, t: f64, angle: f64) -> f64 {
        self.pressure(t, angle)
    }
    fn link_angles(&self, phi: &Vector3<f64>) -> LinkAngles {
        PrescribedCrank::link_angles(self, phi)
    }
    fn crank_torque(s: &Stepper<Self, 2, 4>, forces: &Vector4<f64>, friction: &Vector4<f64>) -> f64 {
        s.system().drive_torque(s.time(), (s.position(), s.velocity(), &s.acceleration()), (forces, friction))
    }
    fn crank_speed(&self, t: f64, _: f64) -> f64 {
        self.speed(t)
    }
}

impl CrankDrive<3> for FreeCrank {
    fn engine(&self) -> &Engine {
        &self.engine
    }
    fn engine_mut(&mut self) -> &mut Engine {
        &mut self.engine
    }
    fn angles(&self, _: f64, q: &Vector3<f64>, qd: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
        (*q, *qd)
    }
    /// The crank angle is a coordinate, and the model has period 4π in it: the stepper shifts it.
    fn take_cycles(stepper: &mut Stepper<Self, 3, 4>, _: f64, cycles: f64) -> Result<(), DynamicsError> {
        stepper.shift(0.0, &Vector3::new(-4.0 * PI * cycles, 0.0, 0.0))
    }
    fn holds(&self, _: &InputPolynomial, load: &InputPolynomial) -> bool {
        self.load_torque.same_as(load)
    }
    fn hold(&mut self, _: InputPolynomial, load: InputPolynomial) {
        self.load_torque = load;
    }
    fn drive_work(&self, _: &Event<3, 4>) -> Option<f64> {
        Some(0.0)
    }
    fn gas_pressure(&self, t: f64, angle: f64) -> f64 {
        self.engine.pressure(t, angle)
    }
    fn link_angles(&self, phi: &Vector3<f64>) -> LinkAngles {
        LinkAngles::new(phi)
    }
    /// The load, opposing rotation.
    fn crank_torque(s: &Stepper<Self, 3, 4>, _: &Vector4<f64>, _: &Vector4<f64>) -> f64 {
        -s.system().load_torque.at(s.time())
    }
    fn crank_speed(&self, _: f64, rate: f64) -> f64 {
        rate
    }
}

/// What the crank train asks of its stepper.
pub(crate) trait CrankStepper {
    /// s.
    fn time(&self) -> f64;
    /// The engine.
    fn engine(&self) -> &Engine;
    /// The engine, to change (the core re-examines the contacts then).
    fn engine_mut(&mut self) -> Result<&mut Engine, DynamicsError>;
    /// φ and φ̇ now, the crank angle as the stepper holds it.
    fn angles(&self) -> (Vector3<f64>, Vector3<f64>);
    /// Takes `cycles` whole cycles off the crank angle, `angle` now.
    fn take_cycles(&mut self, angle: f64, cycles: f64) -> Result<(), DynamicsError>;
    /// The contact forces λ_i, N, and whether each corner is in persistent contact.
    fn contacts(&self) -> (Vector4<f64>, [bool; 4]);
    /// The friction forces on the corners, N, and the core's friction dissipation (power, work).
    fn friction(&self) -> (Vector4<f64>, (f64, f64));
    /// N·s, the persistent contact forces' impulse per corner since the start.
    fn contact_impulses(&self) -> Vector4<f64>;
    /// The integrals since the start of the rates the crank train reports (`books`).
    fn energies(&self) -> Powers;
    /// The rates the crank train reports now (`books`); NaN where the state's motion no longer
    /// solves (it solved when the state was reached).
    fn rates(&self) -> Powers;
    /// The integrator's work so far.
    fn counts(&self) -> StepCounts;
    /// Follows the drive input `speed` or `load` unless it already does (a change makes the core
    /// re-examine the contacts).
    fn hold_drive(&mut self, speed: InputPolynomial, load: InputPolynomial) -> Result<(), DynamicsError>;
    /// Whether the drive input is `speed` or `load` and the step ahead already covers `t_end`.
    fn serves_with(&self, speed: &InputPolynomial, load: &InputPolynomial, t_end: f64) -> bool;
    /// Advances to `t_end`.
    fn advance(&mut self, t_end: f64) -> Result<(), DynamicsError>;
    /// Moves to `t` within the step taken.
    fn serve(&mut self, t: f64) -> Result<(), DynamicsError>;
    /// Each event since the last `clear_events`, in order, counting cycles from `cycles` whole
    /// cycles removed from the crank angle.
    fn each_event(&self, cycles: f64, each: &mut dyn FnMut(CrankEvent));
    /// Forgets the events.
    fn clear_events(&mut self);
    /// Pa, the gauge gas pressure now at crank angle `angle` within the cycle.
    fn gas_pressure(&self, angle: f64) -> f64;
    /// The sines and cosines of the full link angles `phi` (`LinkAngles::new`).
    fn link_angles(&self, phi: &Vector3<f64>) -> LinkAngles;
    /// N·m, the external torque on the crank now.
    fn crank_torque(&self, forces: &Vector4<f64>, friction: &Vector4<f64>) -> f64;
    /// rad/s, the crank speed now, φ̇1 being `rate`.
    fn crank_speed(&self, rate: f64) -> f64;
}

impl<S: CrankDrive<N>, const N: usize> CrankStepper for Stepper<S, N, 4> {
    fn time(&self) -> f64 {
        Stepper::time(self)
    }
    fn engine(&self) -> &Engine {
        self.system().engine()
    }
    fn engine_mut(&mut self) -> Result<&mut Engine, DynamicsError> {
        Ok(self.system_mut()?.engine_mut())
    }
    fn angles(&self) -> (Vector3<f64>, Vector3<f64>) {
        self.system().angles(Stepper::time(self), self.position(), self.velocity())
    }
    fn take_cycles(&mut self, angle: f64, cycles: f64) -> Result<(), DynamicsError> {
        S::take_cycles(self, angle, cycles)
    }
    fn contacts(&self) -> (Vector4<f64>, [bool; 4]) {
        (self.multipliers(), std::array::from_fn(|i| self.in_contact(i)))
    }
    fn friction(&self) -> (Vector4<f64>, (f64, f64)) {
        (self.friction_forces(), self.friction_dissipation())
    }
    fn contact_impulses(&self) -> Vector4<f64> {
        Stepper::contact_impulses(self)
    }
    fn energies(&self) -> Powers {
        Stepper::energies(self)
    }
    fn rates(&self) -> Powers {
        Stepper::rates(self).unwrap_or_else(|_| Powers::repeat(f64::NAN))
    }
    fn counts(&self) -> StepCounts {
        Stepper::counts(self)
    }
    fn hold_drive(&mut self, speed: InputPolynomial, load: InputPolynomial) -> Result<(), DynamicsError> {
        if !self.system().holds(&speed, &load) {
            self.system_mut()?.hold(speed, load);
        }
        Ok(())
    }
    fn serves_with(&self, speed: &InputPolynomial, load: &InputPolynomial, t_end: f64) -> bool {
        self.system().holds(speed, load) && self.serves(t_end)
    }
    fn advance(&mut self, t_end: f64) -> Result<(), DynamicsError> {
        Stepper::advance(self, t_end)
    }
    fn serve(&mut self, t: f64) -> Result<(), DynamicsError> {
        Stepper::serve(self, t)
    }
    fn each_event(&self, cycles: f64, each: &mut dyn FnMut(CrankEvent)) {
        let system = self.system();
        for e in self.events() {
            let (phi, phid) = system.angles(e.time, &e.q, &e.v);
            let linkage = &system.engine().linkage;
            let row = EngineEvent {
                time: e.time,
                crank_angle: phi[0].rem_euclid(CYCLE),
                cycle: (cycles + (phi[0] / CYCLE).floor()) as i64,
                kind: e.kind.into(),
                corner: e.constraint as u8 + 1,
                normal_velocity_before: -e.velocity_before,
                normal_velocity_after: e.velocity_after,
                energy_lost: e.energy_lost,
                friction_energy: e.friction_energy,
                position: linkage.pin(&phi).y,
                lateral_kinetic_energy: linkage.lateral_kinetic_energy(&LinkAngles::new(&phi), &phid),
            };
            each(CrankEvent { row, impulses: e.impulses, drive_work: system.drive_work(e) });
        }
    }
    fn clear_events(&mut self) {
        Stepper::clear_events(self);
    }
    fn gas_pressure(&self, angle: f64) -> f64 {
        self.system().gas_pressure(Stepper::time(self), angle)
    }
    fn link_angles(&self, phi: &Vector3<f64>) -> LinkAngles {
        self.system().link_angles(phi)
    }
    fn crank_torque(&self, forces: &Vector4<f64>, friction: &Vector4<f64>) -> f64 {
        S::crank_torque(self, forces, friction)
    }
    fn crank_speed(&self, rate: f64) -> f64 {
        self.system().crank_speed(Stepper::time(self), rate)
    }
}
