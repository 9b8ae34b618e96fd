//! Variant 1: the piston – connecting rod – crankshaft system of Awrejcewicz & Kudra on the core,
//! as the FMU drives it (prescribed crank speed, or a free crank under a load torque).

use super::books::{DAMPING, DRIVE, GAS};
use super::drive::Drive;
use super::engine::{Engine, FreeCrank, PrescribedCrank};
use super::kinematics::SliderCrank;
use super::linkage::LinkAngles;
use super::step_bounds::{LOCAL_ERROR, MAX_STEP};
use crate::dynamics::{DynamicsError, StepCounts, Stepper, StepperOptions};
use crate::models::skirt::PressureMap;
use crate::models::{check, EngineEvent, EngineModel, InputPolynomial, ModelError, Outputs, StepInputs};
use nalgebra::{Vector2, Vector3, Vector4};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// The crank train in one of its two crank modes.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct CrankTrain {
    pub(super) drive: Drive,
    pub(super) geometry: SliderCrank,
    start: StartOffset,
    /// The initial state is rebuilt with the first step's crank speed (ARCHITECTURE.md §4: nominal kinematics).
    started: bool,
    options: StepperOptions,
    /// Work the prescribed drive has done through impulses since the start, J (`EnergyBalance`).
    pub(super) impulse_work: f64,
    /// Whole cycles (4π) taken off the crank angle (`keep_angle_within_a_cycle`).
    cycles: f64,
    /// Energy the friction impulses of impacts have dissipated since the start, J.
    impact_friction_energy: f64,
    /// The impacts' impulse on the piston since the start per wall [anti-thrust (K1, K2), major
    /// thrust (K3, K4)], N·s.
    impact_impulse: [f64; 2],
    /// The asperities' elastic energy where the stepper's totals start, J (`skirt_outputs`).
    pub(super) asperity_energy_start: f64,
    /// The diametral clearance at running temperature, m (`RunningGeometry`).
    running_clearance: f64,
}

/// What a [`CrankTrain`] is built from: a validated design at running temperature.
#[derive(Clone, Debug)]
pub struct CrankTrainDesign {
    /// The engine the crank turns.
    pub engine: Engine,
    /// The slider crank's lengths and pin offset.
    pub geometry: SliderCrank,
    /// How the start departs from the nominal slider-crank state.
    pub start: StartOffset,
    /// φ1 at the start time, rad.
    pub crank_angle: f64,
    /// A free crank under a load torque (else the crank turns at the prescribed speed).
    pub free_crank: bool,
    /// The crank speed, rad/s, and load torque, N·m, the inputs hold until the first step.
    pub inputs: (f64, f64),
    /// The diametral clearance at running temperature, m.
    pub running_clearance: f64,
}

/// How the start departs from the nominal (zero-clearance) slider-crank state: the pin's lateral
/// displacement from its centred position x = pin_offset, the piston's tilt, and their rates.
#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
pub struct StartOffset {
    /// m.
    pub lateral: f64,
    /// m/s.
    pub lateral_velocity: f64,
    /// rad.
    pub tilt: f64,
    /// rad/s.
    pub tilt_rate: f64,
}

impl StartOffset {
    /// (φ2, φ3) and their rates at crank angle φ1 turning at ω: the pin at x = a + x₀ (l2 sin φ2 =
    /// −(a + x₀ + l1 sin φ1)) moving at ẋ₀ (−l2 cos φ2 φ̇2 = ẋ₀ + l1 cos φ1 ω), the tilt as given.
    fn state(&self, geometry: &SliderCrank, crank_angle: f64, speed: f64) -> Result<(Vector2<f64>, Vector2<f64>), ModelError> {
        let shifted = SliderCrank { pin_offset: geometry.pin_offset + self.lateral, ..*geometry };
        let sine = -(shifted.pin_offset + shifted.crank_radius * libm::sin(crank_angle)) / shifted.rod_length;
        check(sine.abs() < 1.0, || format!("piston_lateral_start ({} m) puts the pin out of the rod's reach", self.lateral))?;
        let s = shifted.at(crank_angle);
        let rod_rate = s.rod_rate * speed - self.lateral_velocity / (shifted.rod_length * libm::cos(s.rod_angle));
        Ok((Vector2::new(s.rod_angle, self.tilt), Vector2::new(rod_rate, self.tilt_rate)))
    }
}

/// The core's error in the crank train's words: a violated constraint is a corner in the liner.
fn dynamics_error(e: DynamicsError) -> ModelError {
    match e {
        DynamicsError::Penetration { time, constraint, gap } => {
            ModelError(format!("crank train: at t = {time} s: corner K{} is {:e} m inside the liner", constraint + 1, -gap))
        }
        e => ModelError(format!("crank train: {e}")),
    }
}

/// A per-corner quantity summed per wall: [K1 + K2 (anti-thrust), K3 + K4 (major thrust)].
pub(super) fn by_wall(x: &Vector4<f64>) -> [f64; 2] {
    [x[0] + x[1], x[2] + x[3]]
}

impl CrankTrain {
    /// Builds `design` at `start_time` with the FMU's integrator options (`MAX_STEP`, `LOCAL_ERROR`).
    pub fn of(design: CrankTrainDesign, start_time: f64) -> Result<Self, ModelError> {
        Self::with_options(
            design,
            start_time,
            StepperOptions { step: MAX_STEP, local_error: Some(LOCAL_ERROR), ..StepperOptions::default() },
        )
    }

    /// Builds `design` with explicit integrator options (the FMU uses `MAX_STEP`, `LOCAL_ERROR` and the
    /// core's tolerances).
    pub fn with_options(design: CrankTrainDesign, start_time: f64, options: StepperOptions) -> Result<Self, ModelError> {
        check(start_time.is_finite(), || format!("start time ({start_time} s) must be finite"))?;
        let CrankTrainDesign { engine, geometry, start, crank_angle: angle, free_crank, inputs: (speed, load), running_clearance } = design;
        let (q, _) = start.state(&geometry, angle, 0.0)?;
        let gaps = engine.linkage.gaps(&Vector3::new(angle, q[0], q[1]));
        if let Some(i) = (0..4).find(|&i| gaps[i] < -options.gap_tolerance) {
            return Err(ModelError(format!(
                "piston_lateral_start ({} m) and piston_tilt_start ({} rad) put corner K{} {:e} m outside the bore",
                start.lateral,
                start.tilt,
                i + 1,
                -gaps[i]
            )));
        }
        let drive = if free_crank {
            let system = FreeCrank { engine, load_torque: InputPolynomial::held(load) };
            Drive::Free(Self::free(system, &geometry, &start, angle, start_time, speed, &options)?)
        } else {
            Drive::Prescribed(Self::prescribed(engine, &geometry, &start, angle, start_time, speed, &options)?)
        };
        let mut model = Self {
            drive,
            geometry,
            start,
            started: false,
            options,
            impulse_work: 0.0,
            cycles: 0.0,
            impact_friction_energy: 0.0,
            impact_impulse: [0.0; 2],
            asperity_energy_start: 0.0,
            running_clearance,
        };
        model.asperity_energy_start = model.asperity_energy();
        Ok(model)
    }

    fn prescribed(
        engine: Engine,
        geometry: &SliderCrank,
        start: &StartOffset,
        angle: f64,
        time: f64,
        speed: f64,
        options: &StepperOptions,
    ) -> Result<Stepper<PrescribedCrank, 2, 4>, ModelError> {
        let (q, qd) = start.state(geometry, angle, speed)?;
        Stepper::new(PrescribedCrank::new(engine, angle, time, speed), time, q, qd, options.clone()).map_err(dynamics_error)
    }

    fn free(
        system: FreeCrank,
        geometry: &SliderCrank,
        start: &StartOffset,
        angle: f64,
        time: f64,
        speed: f64,
        options: &StepperOptions,
    ) -> Result<Stepper<FreeCrank, 3, 4>, ModelError> {
        let (q, qd) = start.state(geometry, angle, speed)?;
        let (q, qd) = (Vector3::new(angle, q[0], q[1]), Vector3::new(speed, qd[0], qd[1]));
        Stepper::new(system, time, q, qd, options.clone()).map_err(dynamics_error)
    }

    /// Restarts from the initial state with the first step's crank speed (both modes): the free
    /// crank's initial speed is the `crank_speed` input as the first step starts.
    fn start(&mut self, speed: f64) -> Result<(), ModelError> {
        let (geometry, start) = (&self.geometry, &self.start);
        self.drive = match &self.drive {
            Drive::Prescribed(s) => {
                let sys = s.system();
                let (angle, time) = (sys.crank_angle(s.time()), s.time());
                Drive::Prescribed(Self::prescribed(sys.engine.clone(), geometry, start, angle, time, speed, &self.options)?)
            }
            Drive::Free(s) => {
                Drive::Free(Self::free(s.system().clone(), geometry, start, s.position()[0], s.time(), speed, &self.options)?)
            }
        };
        self.started = true;
        self.asperity_energy_start = self.asperity_energy();
        Ok(())
    }

    /// Full coordinates φ = (φ1, φ2, φ3) and rates now.
    pub fn state(&self) -> (Vector3<f64>, Vector3<f64>) {
        let (mut phi, phid) = self.state_within_cycle();
        phi[0] += 4.0 * PI * self.cycles;
        (phi, phid)
    }

    /// [`Self::state`] with the crank angle less the whole cycles taken off it.
    pub(super) fn state_within_cycle(&self) -> (Vector3<f64>, Vector3<f64>) {
        self.drive.stepper().angles()
    }

    /// Keeps the crank angle within its first cycle, the whole cycles counted apart: left to
    /// grow, φ1 would carry the round-off of its size (≈ 1e-11 rad at 10³ s of engine time,
    /// 5e-13 m on the gaps), noise near the event tolerance that makes a corner leaving the liner
    /// look as if it penetrated, and that ended a 10⁴-cycle free-crank run in the event budget.
    /// The prescribed crank's angle is a function of time (restarted), the free crank's a
    /// coordinate (shifted: the model has period 4π in it).
    fn keep_angle_within_a_cycle(&mut self) -> Result<(), ModelError> {
        let (angle, cycles) = self.angle_past_cycles();
        if cycles == 0.0 {
            return Ok(());
        }
        self.drive.stepper_mut().take_cycles(angle, cycles).map_err(dynamics_error)?;
        self.cycles += cycles;
        Ok(())
    }

    /// The crank angle less the whole cycles taken off it, and the whole cycles it is past its first.
    fn angle_past_cycles(&self) -> (f64, f64) {
        let angle = self.state().0[0] - 4.0 * PI * self.cycles;
        (angle, (angle / (4.0 * PI)).floor())
    }

    /// Corner gaps h_i, m.
    pub fn gaps(&self) -> Vector4<f64> {
        self.engine().linkage.gaps(&self.state().0)
    }

    /// Contact forces λ_i, N, and whether each corner is in persistent contact.
    pub fn contacts(&self) -> (Vector4<f64>, [bool; 4]) {
        self.drive.stepper().contacts()
    }

    /// Friction forces on the corners along +y, N; the power friction dissipates now, W; and the
    /// energy it has dissipated since the start, J (sliding and impacts).
    pub fn friction(&self) -> (Vector4<f64>, f64, f64) {
        let (forces, (power, sliding)) = self.drive.stepper().friction();
        (forces, power, sliding + self.impact_friction_energy)
    }

    /// The integrator's work so far (see `StepCounts`).
    pub fn step_counts(&self) -> StepCounts {
        self.drive.stepper().counts()
    }

    /// s, the time reached.
    pub fn time(&self) -> f64 {
        self.drive.stepper().time()
    }

    pub(super) fn engine(&self) -> &Engine {
        self.drive.stepper().engine()
    }

    fn engine_mut(&mut self) -> Result<&mut Engine, ModelError> {
        self.drive.stepper_mut().engine_mut().map_err(dynamics_error)
    }
}

impl EngineModel for CrankTrain {
    fn prepare(&mut self, inputs: &StepInputs) -> Result<(), ModelError> {
        if !self.started && inputs.crank_speed.value.is_finite() {
            self.start(inputs.crank_speed.value)?;
            self.started = false;
        }
        Ok(())
    }

    fn advance_interpolated(&mut self, inputs: &StepInputs, t_end: f64, events: &mut Vec<EngineEvent>) -> Result<(), ModelError> {
        // The façade has checked them finite.
        let StepInputs { crank_speed: speed, gas_pressure: pressure, load_torque: load } = *inputs;
        if !self.started {
            self.start(speed.value)?;
        }
        // The system is touched only where an input changed: the core re-examines the contacts
        // after a change, and a communication point with the same inputs then costs nothing.
        if !self.engine().holds(&pressure) {
            self.engine_mut()?.hold_pressure(pressure);
        }
        self.keep_angle_within_a_cycle()?;
        let stepper = self.drive.stepper_mut();
        stepper.hold_drive(speed, load).map_err(dynamics_error)?;
        stepper.advance(t_end).map_err(dynamics_error)?;
        let (mut impulse_work, mut singular) = (self.impulse_work, None);
        let (mut friction_energy, mut impulses) = (0.0, Vector4::zeros());
        self.drive.stepper().each_event(self.cycles, &mut |e| {
            match e.drive_work {
                Some(work) => impulse_work += work,
                None => singular = singular.or(Some(e.row.time)),
            }
            friction_energy += e.row.friction_energy;
            impulses += e.impulses;
            events.push(e.row);
        });
        if let Some(time) = singular {
            return Err(ModelError(format!("crank train: at t = {time} s: the rod and piston inertia is singular")));
        }
        self.impulse_work = impulse_work;
        self.impact_friction_energy += friction_energy;
        let [anti, thrust] = by_wall(&impulses);
        self.impact_impulse = [self.impact_impulse[0] + anti, self.impact_impulse[1] + thrust];
        self.drive.stepper_mut().clear_events();
        Ok(())
    }

    /// With the inputs held as they are, no cycle to take off the crank angle and the step ahead
    /// past `t_end`, `advance_interpolated` would only have the stepper serve the point.
    fn serve(&mut self, inputs: &StepInputs, t_end: f64) -> Option<Result<(), ModelError>> {
        let StepInputs { crank_speed: speed, gas_pressure: pressure, load_torque: load } = inputs;
        if !(self.started && self.engine().holds(pressure) && self.angle_past_cycles().1 == 0.0) {
            return None;
        }
        let stepper = self.drive.stepper_mut();
        if !stepper.serves_with(speed, load, t_end) {
            return None;
        }
        Some(stepper.serve(t_end).map_err(dynamics_error))
    }

    fn serve_again(&mut self, t: f64) -> Result<(), ModelError> {
        self.drive.stepper_mut().serve(t).map_err(dynamics_error)
    }

    fn pressure_map(&self) -> Option<PressureMap> {
        self.skirt_pressure_map()
    }

    fn write_outputs(&self, out: &mut Outputs) {
        // The sines and cosines once, of the angle within the cycle (what the stepper holds).
        let (phi, phid) = self.state_within_cycle();
        let trig = LinkAngles::new(&phi);
        let linkage = &self.engine().linkage;
        let (pin, gaps) = linkage.pin_and_gaps(&trig);
        let (forces, in_contact) = self.contacts();
        let (friction, friction_power, friction_energy) = self.friction();
        out.piston_lateral = pin.x;
        // ẋ_O3 = −l1 cos φ1 φ̇1 − l2 cos φ2 φ̇2.
        out.piston_lateral_velocity =
            -self.geometry.crank_radius * trig.cos[0] * phid[0] - self.geometry.rod_length * trig.cos[1] * phid[1];
        out.piston_tilt = phi[2];
        out.piston_tilt_rate = phid[2];
        out.lateral_kinetic_energy = linkage.lateral_kinetic_energy(&trig, &phid);
        // The piston axis at a corner pair's height is midway between the two corners, whose gaps
        // from their walls are D/2 + x (K1, K2) and D/2 − x (K3, K4).
        out.skirt_top_lateral = 0.5 * (gaps[0] - gaps[2]);
        out.skirt_bottom_lateral = 0.5 * (gaps[1] - gaps[3]);
        let stepper = self.drive.stepper();
        out.gas_pressure_acting = stepper.gas_pressure(phi[0]);
        out.piston_axial = pin.y;
        out.crank_angle = phi[0] + 4.0 * PI * self.cycles;
        out.rod_angle = phi[1];
        out.crank_torque = stepper.crank_torque(&forces, &friction);
        [out.contact_state_1, out.contact_state_2, out.contact_state_3, out.contact_state_4] = in_contact.map(i32::from);
        [out.contact_force_1, out.contact_force_2, out.contact_force_3, out.contact_force_4] = [forces[0], forces[1], forces[2], forces[3]];
        out.crank_speed_actual = stepper.crank_speed(phid[0]);
        (out.kinetic_energy, out.potential_energy) = linkage.energy_with(&trig, &phi, &phid);
        let contact = self.contact_impulse();
        out.liner_impulse_total = std::array::from_fn(|w| contact[w] + self.impact_impulse[w]);
        [out.friction_force_1, out.friction_force_2, out.friction_force_3, out.friction_force_4] = friction.into();
        (out.friction_power, out.friction_energy_total) = (friction_power, friction_energy);
        let books = stepper.energies();
        out.drive_work_total = books[DRIVE] + self.impulse_work;
        (out.gas_work_total, out.damping_energy_total) = (books[GAS], books[DAMPING]);
        out.running_clearance = self.running_clearance;
        self.write_skirt((&phi, &trig, &phid), &gaps, &forces, out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fmus::piston_slap::mechanisms::design_space::validate;
    use crate::fmus::piston_slap::mechanisms::RunningGeometry;
    use crate::fmus::piston_slap::Mechanism;
    use crate::models::{Inputs, Parameters};

    /// Outputs after each of `n` steps of `h` seconds with `inputs` held.
    fn run(params: &Parameters, inputs: &Inputs, h: f64, n: usize) -> Vec<Outputs> {
        let mut model = CrankTrain::new(params, 0.0).unwrap();
        let mut events = Vec::new();
        (1..=n)
            .map(|k| {
                model.advance(inputs, k as f64 * h, &mut events).unwrap();
                let mut out = Outputs::default();
                model.write_outputs(&mut out);
                out
            })
            .collect()
    }

    #[test]
    fn gas_pressure_acting_is_the_input_or_the_curve() {
        let held = Parameters { pressure_source: 1, ..Parameters::default() };
        let inputs = Inputs { gas_pressure: 2.5e6, ..Inputs::default() };
        assert!(run(&held, &inputs, 1e-3, 20).iter().all(|out| out.gas_pressure_acting == 2.5e6));
        // The built-in curve over one cycle sampled every 0.36°: its maximum is peak_pressure (reached
        // near 11° after firing TDC, so the samples come within 0.1 %), and it is zero in the exhaust
        // and intake strokes, BDC to BDC.
        let p = Parameters::default();
        let cycle = run(&p, &Inputs::default(), 5e-5, 2000);
        let peak = cycle.iter().map(|out| out.gas_pressure_acting).fold(0.0, f64::max);
        assert!(peak <= p.peak_pressure && peak > 0.999 * p.peak_pressure, "{peak}");
        let gas_exchange = cycle.iter().filter(|out| (PI + 1e-9..3.0 * PI - 1e-9).contains(&out.crank_angle));
        assert!(gas_exchange.clone().count() > 900 && gas_exchange.clone().all(|out| out.gas_pressure_acting == 0.0));
    }

    #[test]
    fn the_shipped_full_load_trace_is_the_built_in_curve_plus_one_bar() {
        // resources/full_load.csv samples the built-in curve (default geometry, 8 MPa) every 0.5° in
        // absolute bar; less the default crankcase pressure it is the curve again, up to the
        // interpolation error between samples (measured 265 Pa at most, near the peak).
        let trace = Parameters { pressure_source: 3, pressure_trace: "resources/full_load.csv".into(), ..Parameters::default() };
        let (from_trace, from_curve) =
            (run(&trace, &Inputs::default(), 5e-5, 2000), run(&Parameters::default(), &Inputs::default(), 5e-5, 2000));
        for (a, b) in from_trace.iter().zip(&from_curve) {
            assert_eq!(a.crank_angle, b.crank_angle);
            assert!(
                (a.gas_pressure_acting - b.gas_pressure_acting).abs() < 1e-4 * 8e6,
                "{} {}",
                a.gas_pressure_acting,
                b.gas_pressure_acting
            );
        }
        let missing = Parameters { pressure_trace: "resources/none.csv".into(), ..trace };
        let message = CrankTrain::new(&missing, 0.0).unwrap_err().0;
        assert!(message.starts_with("pressure_trace \"resources/none.csv\": cannot be read"), "{message}");
    }

    /// The piston axis at the corners' heights z = h and h − s lies at x_pin − z sin φ3 (pin on the
    /// axis): the two differ by −s sin φ3 and straddle the pin (h = s/2); a corner in contact puts its
    /// end of the axis at (D − d cos φ3)/2 from the centre.
    #[test]
    fn skirt_positions_follow_the_pin_and_the_tilt() {
        let p = Parameters::default();
        let mut contacts = 0;
        for out in run(&p, &Inputs::default(), 1e-4, 1000) {
            let (top, bottom, tilt) = (out.skirt_top_lateral, out.skirt_bottom_lateral, out.piston_tilt);
            assert!((top - bottom + p.skirt_length * libm::sin(tilt)).abs() < 1e-15, "{out:?}");
            assert!((0.5 * (top + bottom) - out.piston_lateral).abs() < 1e-15, "{out:?}");
            let wall = 0.5 * (p.bore - p.piston_diameter * libm::cos(tilt));
            let ends =
                [(out.contact_state_1, -top), (out.contact_state_2, -bottom), (out.contact_state_3, top), (out.contact_state_4, bottom)];
            for (state, toward_wall) in ends.into_iter().filter(|(state, _)| *state == 1) {
                assert!((toward_wall - wall).abs() < 1e-9, "{state}: {out:?}");
                contacts += 1;
            }
        }
        assert!(contacts > 100, "the default cycle slides on both walls: {contacts}");
    }

    /// Both skirt models run with the diameters at their running temperatures: a design at 100 °C skirt and
    /// 110 °C liner runs as the design at the reference temperature with those hot diameters, bit for bit,
    /// and `running_clearance` is the hand calculation of `RunningGeometry`'s test (24.8792 µm).
    #[test]
    fn a_hot_design_runs_as_the_design_of_its_hot_diameters() {
        for skirt_model in [1, 2] {
            let hot = Parameters { skirt_model, piston_temperature: 373.15, liner_temperature: 383.15, ..Parameters::default() };
            let geometry = RunningGeometry::of(&hot);
            let cold = Parameters {
                bore: geometry.bore,
                piston_diameter: geometry.piston_diameter,
                ..Parameters { skirt_model, ..Parameters::default() }
            };
            let (a, b) = (run(&hot, &Inputs::default(), 1e-3, 30), run(&cold, &Inputs::default(), 1e-3, 30));
            assert_eq!(a, b, "skirt_model {skirt_model}");
            assert!(a.iter().all(|out| (out.running_clearance - 24.8792e-6).abs() < 1e-15), "{}", a[0].running_clearance);
        }
        let defaults = run(&Parameters::default(), &Inputs::default(), 1e-3, 1);
        assert_eq!(defaults[0].running_clearance, 0.08008 - 0.08);
        let seized = Parameters { piston_temperature: 413.15, liner_temperature: 383.15, ..Parameters::default() };
        let message = CrankTrain::new(&seized, 0.0).unwrap_err().0;
        assert!(message.starts_with("running clearance -4.23208") && message.contains("≤ 0"), "{message}");
    }

    #[test]
    fn refuses_parameters_naming_them() {
        let cases: [(Parameters, &str); 17] = [
            // The generic ranges.
            (Parameters { bore: 0.079, ..Parameters::default() }, "bore = 0.079 m must exceed piston_diameter = 0.08 m"),
            (Parameters { restitution: 1.2, ..Parameters::default() }, "restitution"),
            (Parameters { rod_mass: 0.0, ..Parameters::default() }, "rod_mass"),
            (Parameters { crank_mode: 3, ..Parameters::default() }, "crank_mode"),
            (Parameters { damping_main: f64::NAN, ..Parameters::default() }, "damping_main"),
            // The crank train's own.
            (Parameters { skirt_length: 0.0, ..Parameters::default() }, "skirt_length (0 m) must be positive"),
            (Parameters { bore: 0.2, ..Parameters::default() }, "piston diagonal"),
            (Parameters { pin_offset: -0.041, ..Parameters::default() }, "pin_offset (-0.041 m) must be smaller"),
            (Parameters { rod_length: 0.05, pin_offset: 0.02, ..Parameters::default() }, "rod_length (0.05 m) must be at least 1.5 ×"),
            // The declared space: rod ratio, clearance, masses and inertias.
            (Parameters { rod_length: 0.0899, pin_offset: 0.02, ..Parameters::default() }, "rod_length (0.0899 m) must be at least"),
            (
                Parameters { bore: 0.08 + 1.9e-6, ..Parameters::default() },
                "bore (0.0800019 m) must exceed piston_diameter (0.08 m) by 2 × 0.000001 m",
            ),
            (Parameters { piston_mass: 0.0099, ..Parameters::default() }, "crank_mass (10 kg) and piston_mass (0.0099 kg)"),
            (Parameters { rod_inertia: 1e-9, ..Parameters::default() }, "rod_inertia (0.000000001 kg·m²) gives the rod"),
            (
                Parameters { restitution: 1.0, friction: 0.1, ..Parameters::default() },
                "restitution = 1 with friction (0.1) on a prescribed crank",
            ),
            (
                Parameters { piston_mass: 0.02, piston_inertia: 5e-5, ..Parameters::default() },
                "piston_mass (0.02 kg) must lie within [40, 15000] kg/m³",
            ),
            (Parameters { piston_mass: 8.0, ..Parameters::default() }, "piston_mass (8 kg) must lie within [40, 15000] kg/m³"),
            // A 1 kg rod 0.15 m long: √(J/m) = 0.151 m, just beyond its length.
            (Parameters { rod_inertia: 0.0228, ..Parameters::default() }, "outside [0.05, 1] × rod_length (0.15 m)"),
        ];
        for (params, expected) in cases {
            let message = validate(&params).unwrap_err().0;
            assert!(message.contains(expected), "{message}");
        }
        assert!(validate(&Parameters::default()).is_ok());
        // Exactly at the bounds: accepted.
        let edges = Parameters {
            rod_length: 0.06,
            rod_inertia: 0.003,
            bore: 0.08 + 2e-6,
            crank_mass: 400.0,
            piston_mass: 0.4,
            ..Parameters::default()
        };
        assert!(validate(&edges).is_ok(), "{:?}", validate(&edges));
        // Perfectly elastic with friction: on a free crank, whose energy is bounded.
        assert!(validate(&Parameters { restitution: 1.0, friction: 0.1, crank_mode: 2, ..Parameters::default() }).is_ok());
    }

    /// The critical friction coefficient is a property of the design: 0.998 for the defaults (the
    /// piston against a wall at top dead centre; centred, it is above the XML's maximum 1), 0.70
    /// with a 6 cm skirt in either crank mode; above it the start is refused, naming it.
    #[test]
    fn friction_above_the_critical_coefficient_is_refused_at_the_start() {
        for mode in [1, 2] {
            let defaults = |friction| CrankTrain::new(&Parameters { crank_mode: mode, friction, ..Parameters::default() }, 0.0);
            assert!(defaults(0.997).is_ok());
            let message = defaults(0.999).unwrap_err().0;
            assert!(message.contains("critical coefficient 0.998"), "{message}");
            let p = |friction| Parameters { crank_mode: mode, friction, skirt_length: 0.06, ..Parameters::default() };
            assert!(CrankTrain::new(&p(0.70), 0.0).is_ok());
            let message = CrankTrain::new(&p(0.71), 0.0).unwrap_err().0;
            assert!(message.contains("friction (0.71) exceeds this design's critical coefficient 0.70"), "{message}");
        }
    }
}
