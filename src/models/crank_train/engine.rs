//! The engine the crank turns (`Engine`: linkage, gas, restitution, friction, the optional film) and the
//! crank train as a `System` for the core in its two crank modes.
//!
//! - [`PrescribedCrank`]: φ1(t) = φ1_ref + ∫ω is given, q = (φ2, φ3), with ω(t) the `crank_speed` input
//!   (held, or a polynomial in t when the host gives its derivatives). Rows 2–3 of the linkage equations
//!   with φ̇1 = ω and φ̈1 = ω̇ (the crank's inertia coupling moved to the right-hand side); the gaps become
//!   rheonomic: `∂h/∂t = (∂h/∂φ1) ω` and d gains `(∂h/∂φ1) ω̇` beside the ω² terms. The crank row then
//!   yields the drive torque.
//! - [`FreeCrank`]: q = (φ1, φ2, φ3) under gas force, load torque and damping (A&K eq 55).

use super::books::{self, SkirtRates};
use super::linkage::{Bodies, LinkAngles, Linkage, Loads};
use super::lubrication::{self, predicted, Lubrication};
use super::step_bounds::MAX_STEP_ANGLE;
use crate::dynamics::{Change, Evaluation, Powers, StepBounds, System, Tangents, Terms};
use crate::models::gas::GasPressure;
use crate::models::numerics::{trig, LastValue};
use crate::models::{InputPolynomial, ModelError};
use nalgebra::{Matrix2, Matrix3, Matrix4x2, Vector2, Vector3, Vector4};
use serde::{Deserialize, Serialize};

/// What drives the links apart from the crank motion: linkage, pressure, restitution.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Engine {
    /// The links' geometry, masses and the liner's corners.
    pub linkage: Linkage,
    /// Private: `PrescribedCrank` caches the curve's values, so only a held pressure may change.
    pressure: GasPressure,
    /// Crown area π d²/4, m².
    pub crown_area: f64,
    /// Newton's restitution coefficient e of the corners' impacts on the liner.
    pub restitution: f64,
    /// Coulomb friction coefficient μ of the corners on the liner.
    pub friction: f64,
    /// The lubricated skirt (`skirt_model = 2`); none: the dry corners alone. Boxed: the engine is
    /// copied with the model before every step a host may have undone, and the dry one carries no
    /// room for the film.
    pub lubrication: Option<Box<Lubrication>>,
}

/// What an [`Engine`] is built from, SI.
#[derive(Clone, Debug)]
pub(crate) struct EngineDesign {
    /// The links and the corners.
    pub(crate) linkage: Bodies,
    /// Where the gas pressure comes from (a held input starts at the input's default).
    pub(crate) pressure: GasPressure,
    /// d, m: the crown's diameter.
    pub(crate) piston_diameter: f64,
    /// e.
    pub(crate) restitution: f64,
    /// μ.
    pub(crate) friction: f64,
    /// The lubricated skirt; none: the dry corners alone.
    pub(crate) skirt: Option<lubrication::Design>,
}

/// The gas's power on the crown and the joint damping's dissipation rate at one state, W
/// (`Linkage::gas_and_damping_power`).
type Applied = (f64, f64);

/// What an evaluation needs of the crank angle alone.
#[derive(Clone, Copy, Debug)]
struct Crank {
    sin: f64,
    cos: f64,
    /// The gauge pressure of the curve or trace at this angle; 0 with a held pressure.
    curve: f64,
}

impl Engine {
    /// The engine of a validated design; a skirt the film cannot be solved on is refused.
    pub(crate) fn new(design: EngineDesign) -> Result<Self, ModelError> {
        let d = design.piston_diameter;
        Ok(Self {
            linkage: design.linkage.into(),
            pressure: design.pressure,
            crown_area: 0.25 * std::f64::consts::PI * d * d,
            restitution: design.restitution,
            friction: design.friction,
            lubrication: design.skirt.map(Lubrication::try_from).transpose()?.map(Box::new),
        })
    }

    /// Whether taking `pressure` would change nothing: it is the held input already, or the
    /// pressure comes from the built-in curve or a trace.
    pub fn holds(&self, pressure: &InputPolynomial) -> bool {
        self.pressure.holds(pressure)
    }

    /// Takes the `gas_pressure` input over the next step, if the pressure comes from it.
    pub fn hold_pressure(&mut self, pressure: InputPolynomial) {
        self.pressure.hold(pressure);
    }

    /// Gas force toward the crank at time t and crank angle φ1, N.
    pub fn gas_force(&self, t: f64, crank_angle: f64) -> f64 {
        self.gas_force_at(t, &self.crank(crank_angle))
    }

    /// Gauge gas pressure on the crown at time t and crank angle φ1, Pa: the input, the curve or the trace.
    pub fn pressure(&self, t: f64, crank_angle: f64) -> f64 {
        self.pressure_at(t, &self.crank(crank_angle))
    }

    #[inline(always)]
    fn pressure_at(&self, t: f64, crank: &Crank) -> f64 {
        self.pressure.at(t, crank.curve)
    }

    #[inline(always)]
    fn gas_force_at(&self, t: f64, crank: &Crank) -> f64 {
        self.pressure_at(t, crank) * self.crown_area
    }

    /// Inlined, with the cache's lookup (`PrescribedCrank::crank`, `LastValue::get_or`), into
    /// the evaluations: called out of line, a cache hit would cost a call at every stage.
    #[inline(always)]
    fn crank(&self, angle: f64) -> Crank {
        let (sin, cos) = trig::sin_cos(angle);
        Crank { sin, cos, curve: self.pressure.of_angle(angle, sin, cos) }
    }

    /// The linkage's evaluation at (t, φ, φ̇) with the gas force at t and the crank angle of `crank`
    /// and the load torque `load_torque`, and the gas's and the damping's power there.
    #[inline(always)]
    fn evaluate(&self, t: f64, phi: &Vector3<f64>, phid: &Vector3<f64>, load_torque: f64, crank: Crank) -> (Evaluation<3, 4>, Applied) {
        self.evaluate_with(t, (phi, &LinkAngles::with_crank((crank.sin, crank.cos), phi)), phid, load_torque, crank)
    }

    /// [`Self::evaluate`] with the angles' sines and cosines `trig` (of φ) at hand.
    #[inline(always)]
    fn evaluate_with(
        &self,
        t: f64,
        (phi, trig): (&Vector3<f64>, &LinkAngles),
        phid: &Vector3<f64>,
        load_torque: f64,
        crank: Crank,
    ) -> (Evaluation<3, 4>, Applied) {
        let loads = Loads { gas_force: self.gas_force_at(t, &crank), load_torque };
        let mut ev = self.linkage.evaluate_with(trig, phid, loads);
        ev.implicit = self.lubrication.as_ref().map(|l| l.apply((phi, trig), phid, &mut ev.force));
        (ev, self.linkage.gas_and_damping_power(trig, phid, loads.gas_force))
    }

    /// The inertia `M + K` and f of [`Self::evaluate`] alone, and the gas's and the damping's power.
    #[inline(always)]
    fn inertia_and_force(
        &self,
        t: f64,
        phi: &Vector3<f64>,
        phid: &Vector3<f64>,
        load_torque: f64,
        crank: Crank,
    ) -> (Matrix3<f64>, Vector3<f64>, Applied) {
        let (trig, loads) = self.trig_and_loads(t, phi, load_torque, &crank);
        let (mut mass, mut force) = self.linkage.inertia_and_force_with(&trig, phid, loads);
        if let Some(lubrication) = &self.lubrication {
            mass += lubrication.apply((phi, &trig), phid, &mut force);
        }
        (mass, force, self.linkage.gas_and_damping_power(&trig, phid, loads.gas_force))
    }

    /// An RK4 step begins: the lubricated skirt prepares its film at the time and state (t, φ, φ̇)
    /// predicted into it, with the corners' gaps there (`Lubrication::begin_step`); at the step's `start`
    /// where the prediction puts a corner through the liner, which the step's event search will
    /// stop at: there the film would sit on its floor, stiffer than the linkage by up to ≈ 1e16, and
    /// the inertia matrix with its implicit term would not be positive definite to round-off.
    fn begin_step(&self, predicted: (f64, Vector3<f64>, Vector3<f64>), start: (f64, Vector3<f64>, Vector3<f64>)) {
        if let Some(lubrication) = &self.lubrication {
            let gaps = self.linkage.gaps(&predicted.1);
            let ((t, phi, phid), gaps) = if gaps.min() >= 0.0 { (predicted, gaps) } else { (start, self.linkage.gaps(&start.1)) };
            lubrication.begin_step(t, &phi, &phid, &gaps);
        }
    }

    /// The bounds of a step from corner gaps `gaps` turning the crank at `speed`, rad/s: at most
    /// [`MAX_STEP_ANGLE`] of the crank, and the lubricated skirt's (`Lubrication::largest_step`,
    /// `Lubrication::error_scale`).
    fn step_bounds(&self, speed: f64, gaps: &Vector4<f64>) -> StepBounds {
        let crank = MAX_STEP_ANGLE / speed.abs();
        match &self.lubrication {
            Some(l) => StepBounds { largest: crank.min(l.largest_step()), error_scale: l.error_scale(gaps) },
            None => StepBounds { largest: crank, error_scale: 1.0 },
        }
    }

    /// The rates the crank train reports at (φ, φ̇, φ̈) (`books`), the drive's power `drive` and the
    /// gas's and the damping's `applied` given: with the lubricated skirt's
    /// (`Lubrication::absorbed_power`).
    #[inline(always)]
    fn powers(
        &self,
        (phi, crank): (&Vector3<f64>, &Crank),
        phid: &Vector3<f64>,
        phidd: &Vector3<f64>,
        drive: f64,
        (gas, damping): Applied,
    ) -> Powers {
        let film = self
            .lubrication
            .as_ref()
            .map_or(SkirtRates::zeros(), |l| l.absorbed_power((phi, &LinkAngles::with_crank((crank.sin, crank.cos), phi)), phid, phidd));
        books::powers(&film, drive, gas, damping)
    }

    /// What the lubricated skirt takes from a velocity jump at φ, J (`Lubrication::jump_books`).
    fn jump(&self, phi: &Vector3<f64>, trig: &LinkAngles, before: &Vector3<f64>, after: &Vector3<f64>) -> Powers {
        let film = self.lubrication.as_ref().map_or(SkirtRates::zeros(), |l| l.jump_books((phi, trig), before, after));
        books::powers(&film, 0.0, 0.0, 0.0)
    }

    #[inline(always)]
    fn trig_and_loads(&self, t: f64, phi: &Vector3<f64>, load_torque: f64, crank: &Crank) -> (LinkAngles, Loads) {
        (LinkAngles::with_crank((crank.sin, crank.cos), phi), Loads { gas_force: self.gas_force_at(t, crank), load_torque })
    }
}

/// Rod and piston with the crank turning at the speed of the `crank_speed` input.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PrescribedCrank {
    /// The engine the crank turns.
    pub engine: Engine,
    /// φ1 at the speed's reference time.
    angle_ref: f64,
    speed: InputPolynomial,
    /// The crank's terms at the last crank angle evaluated (RK4's paired stages share it).
    #[serde(skip)]
    last_crank: LastValue<Crank>,
    /// The crank row at the state last evaluated, for its drive torque.
    #[serde(skip)]
    row: LastValue<CrankRow, 7>,
    /// The link angles' sines and cosines at the configuration whose terms were last taken alone
    /// (`Terms::Configuration`, which judges a communication point): for the point's evaluation
    /// and outputs there.
    #[serde(skip)]
    angles: LastValue<LinkAngles, 3>,
}

/// The crank row of the full equations at one state, the drive torque's terms: `M_1·`, `f_1` and,
/// from a full evaluation, the gaps' crank column `∂h/∂φ1`; and the gas's and the damping's power
/// there, the other terms of the powers the crank reports.
#[derive(Clone, Copy, Debug)]
struct CrankRow {
    mass: Vector3<f64>,
    force: f64,
    gaps: Option<Vector4<f64>>,
    applied: Applied,
}

impl CrankRow {
    #[inline(always)]
    fn of((full, applied): &(Evaluation<3, 4>, Applied)) -> Self {
        Self { gaps: Some(full.gap_jacobian.column(0).into_owned()), ..Self::of_inertia(&(full.inertia(), full.force, *applied)) }
    }

    #[inline(always)]
    fn of_inertia((mass, force, applied): &(Matrix3<f64>, Vector3<f64>, Applied)) -> Self {
        Self { mass: mass.row(0).transpose(), force: force[0], gaps: None, applied: *applied }
    }
}

impl PrescribedCrank {
    /// The crank at `crank_angle` at `time`, turning at `speed` held.
    pub fn new(engine: Engine, crank_angle: f64, time: f64, speed: f64) -> Self {
        let speed = InputPolynomial { time, ..InputPolynomial::held(speed) };
        Self {
            engine,
            angle_ref: crank_angle,
            speed,
            last_crank: LastValue::default(),
            row: LastValue::default(),
            angles: LastValue::default(),
        }
    }

    /// φ1(t): the speed integrated exactly.
    pub fn crank_angle(&self, t: f64) -> f64 {
        self.angle_ref + self.speed.integral(t)
    }

    /// ω(t).
    pub fn speed(&self, t: f64) -> f64 {
        self.speed.at(t)
    }

    /// ω̇(t).
    pub fn acceleration(&self, t: f64) -> f64 {
        self.speed.rate(t)
    }

    /// Follows `speed` (about its own time) from then on, keeping the crank angle continuous. A held
    /// speed equal to the one held keeps the reference point, so results do not depend on how often
    /// a host repeats an unchanged input.
    pub fn hold_speed(&mut self, speed: InputPolynomial) {
        if !self.holds_speed(&speed) {
            self.angle_ref = self.crank_angle(speed.time);
            self.speed = speed;
        }
    }

    /// Whether taking `speed` would change nothing.
    pub fn holds_speed(&self, speed: &InputPolynomial) -> bool {
        speed.same_as(&self.speed)
    }

    /// The same crank with the crank angle `angle` at time `t` (a whole number of cycles away from
    /// its own), the speed's reference moved to `t`.
    pub fn rebased(&self, t: f64, angle: f64) -> Self {
        let (last_crank, row, angles) = (LastValue::default(), LastValue::default(), LastValue::default());
        Self { engine: self.engine.clone(), angle_ref: angle, speed: self.speed.from(t), last_crank, row, angles }
    }

    /// The crank terms at `angle`, from the cache when it is the last angle evaluated (inlined:
    /// see `Engine::crank`).
    #[inline(always)]
    fn crank(&self, angle: f64) -> Crank {
        self.last_crank.get_or([angle], || self.engine.crank(angle))
    }

    /// Gauge gas pressure on the crown at time t and crank angle φ1 within the cycle, Pa: the
    /// engine's, from the cache when it is the angle last evaluated (the end of the last step).
    pub fn pressure(&self, t: f64, angle: f64) -> f64 {
        self.engine.pressure_at(t, &self.crank(angle))
    }

    /// Full coordinates and velocities at `(t, q, q̇)`.
    pub fn full_state(&self, t: f64, q: &Vector2<f64>, qd: &Vector2<f64>) -> (Vector3<f64>, Vector3<f64>) {
        (Vector3::new(self.crank_angle(t), q[0], q[1]), Vector3::new(self.speed.at(t), qd[0], qd[1]))
    }

    /// Linkage evaluation in full coordinates, its crank row kept for the drive torque there.
    #[inline(always)]
    pub fn evaluate_full(&self, t: f64, q: &Vector2<f64>, qd: &Vector2<f64>) -> Evaluation<3, 4> {
        let (phi, phid, crank) = self.full_state_and_crank(t, q, qd);
        self.keep_row(t, (&phi, &phid, &crank), self.engine.evaluate(t, &phi, &phid, 0.0, crank))
    }

    /// The evaluation `full` at (t, φ, φ̇), its crank row kept for the drive torque there.
    #[inline(always)]
    fn keep_row(
        &self,
        t: f64,
        (phi, phid, crank): (&Vector3<f64>, &Vector3<f64>, &Crank),
        full: (Evaluation<3, 4>, Applied),
    ) -> Evaluation<3, 4> {
        self.row.set(self.row_key(t, phi, phid, crank), CrankRow::of(&full));
        full.0
    }

    /// The sines and cosines of the link angles φ, the crank's from `crank`: those the configuration's
    /// terms last took where φ is theirs.
    #[inline(always)]
    fn angles_of(&self, phi: &Vector3<f64>, crank: &Crank) -> LinkAngles {
        self.angles.get_or([phi[0], phi[1], phi[2]], || LinkAngles::with_crank((crank.sin, crank.cos), phi))
    }

    /// The sines and cosines of the link angles φ (`LinkAngles::new`), from the configuration's terms
    /// where they were last taken at φ.
    pub fn link_angles(&self, phi: &Vector3<f64>) -> LinkAngles {
        self.angles_of(phi, &self.crank(phi[0]))
    }

    /// φ, φ̇ and the crank's terms at `(t, q, q̇)`.
    #[inline(always)]
    fn full_state_and_crank(&self, t: f64, q: &Vector2<f64>, qd: &Vector2<f64>) -> (Vector3<f64>, Vector3<f64>, Crank) {
        let (phi, phid) = self.full_state(t, q, qd);
        let crank = self.crank(phi[0]);
        (phi, phid, crank)
    }

    /// What the crank row is a function of: φ, φ̇ and the gas force.
    #[inline(always)]
    fn row_key(&self, t: f64, phi: &Vector3<f64>, phid: &Vector3<f64>, crank: &Crank) -> [f64; 7] {
        [phi[0], phi[1], phi[2], phid[0], phid[1], phid[2], self.engine.gas_force_at(t, crank)]
    }

    /// Torque the drive applies to the crank: the crank row `M_1· φ̈ − f_1 − (Jᵀλ + J_Tᵀλ_T)_1` with
    /// φ̈1 = ω̇; `forces`: the corners' normal and friction forces.
    pub fn drive_torque(
        &self,
        t: f64,
        (q, qd, qdd): (&Vector2<f64>, &Vector2<f64>, &Vector2<f64>),
        forces: (&Vector4<f64>, &Vector4<f64>),
    ) -> f64 {
        let (phi, phid, crank) = self.full_state_and_crank(t, q, qd);
        self.torque_and_row(t, (&phi, &phid, &crank), qdd, forces).0
    }

    /// The drive torque at (t, φ, φ̇) (φ̈ = (ω̇, q̈)) and the crank row there: the evaluation at this
    /// state kept the row (a stage's or a point's), with the gaps' column where it was a full one.
    #[inline(always)]
    fn torque_and_row(
        &self,
        t: f64,
        (phi, phid, crank): (&Vector3<f64>, &Vector3<f64>, &Crank),
        qdd: &Vector2<f64>,
        forces: (&Vector4<f64>, &Vector4<f64>),
    ) -> (f64, CrankRow) {
        let (q, crank) = (Vector2::new(phi[1], phi[2]), *crank);
        let key = self.row_key(t, phi, phid, &crank);
        let full = || CrankRow::of(&self.engine.evaluate(t, phi, phid, 0.0, crank));
        let mut row = self.row.get_or(key, full);
        let normal = if *forces.0 == Vector4::zeros() {
            0.0
        } else {
            let gaps = row.gaps.unwrap_or_else(|| {
                row = full();
                self.row.set(key, row);
                row.gaps.unwrap_or_default()
            });
            gaps.dot(forces.0)
        };
        let driven = if self.speed.is_held() { 0.0 } else { row.mass[0] * self.acceleration(t) };
        let contact = normal + self.friction_reaction(t, &q, forces.1);
        (driven + row.mass[1] * qdd[0] + row.mass[2] * qdd[1] - row.force - contact, row)
    }

    /// The generalized forces `J_Tᵀ λ_T` of the friction forces `friction` in full coordinates (zero
    /// without friction, and then not computed).
    pub fn friction_reaction(&self, t: f64, q: &Vector2<f64>, friction: &Vector4<f64>) -> f64 {
        if *friction == Vector4::zeros() {
            return 0.0;
        }
        let (phi, phid) = self.full_state(t, q, &Vector2::zeros());
        self.engine.linkage.tangents(&phi, &phid).jacobian.column(0).dot(friction)
    }

    /// The reduced evaluation (coordinates φ2, φ3) of the full one at t.
    #[inline(always)]
    fn reduce(&self, t: f64, full: Evaluation<3, 4>) -> Evaluation<2, 4> {
        let force = self.reduced(t, &full.inertia(), &full.force).1;
        let crank_column = full.gap_jacobian.column(0);
        let gap_bias = if self.speed.is_held() { full.gap_bias } else { full.gap_bias + crank_column * self.acceleration(t) };
        Evaluation { force, gap_bias, ..self.reduce_configuration(t, &full) }
    }

    /// The terms of [`Self::reduce`] that the configuration and the crank's speed set (M, K, h, J,
    /// ∂h/∂t), with f and d zero.
    #[inline(always)]
    fn reduce_configuration(&self, t: f64, full: &Evaluation<3, 4>) -> Evaluation<2, 4> {
        Evaluation {
            mass: rod_and_piston(&full.mass),
            implicit: full.implicit.as_ref().map(rod_and_piston),
            force: Vector2::zeros(),
            gap: full.gap,
            gap_jacobian: Matrix4x2::from_columns(&[full.gap_jacobian.column(1), full.gap_jacobian.column(2)]),
            gap_time_rate: full.gap_jacobian.column(0) * self.speed.at(t),
            gap_bias: Vector4::zeros(),
        }
    }

    /// The rod and piston rows of the full inertia `M + K` and f at t, the crank's angular acceleration
    /// ω̇ moved into the force: `f_r − (M + K)_r1 ω̇` (nothing to move while the speed is held).
    #[inline(always)]
    fn reduced(&self, t: f64, inertia: &Matrix3<f64>, force: &Vector3<f64>) -> (Matrix2<f64>, Vector2<f64>) {
        let mut f = force.fixed_rows::<2>(1).into_owned();
        if !self.speed.is_held() {
            f -= inertia.fixed_view::<2, 1>(1, 0) * self.acceleration(t);
        }
        (rod_and_piston(inertia), f)
    }
}

impl System<2, 4> for PrescribedCrank {
    fn evaluate(&self, t: f64, q: &Vector2<f64>, qd: &Vector2<f64>) -> Evaluation<2, 4> {
        self.reduce(t, self.evaluate_full(t, q, qd))
    }

    /// A point with the sines and cosines of the configuration's terms taken there (`link_angles`); the dry
    /// linkage's configuration terms alone (`Linkage::configuration_with`), with the film the whole evaluation.
    fn evaluate_terms(&self, t: f64, q: &Vector2<f64>, qd: &Vector2<f64>, terms: Terms) -> Evaluation<2, 4> {
        match terms {
            Terms::Point => {
                let (phi, phid, crank) = self.full_state_and_crank(t, q, qd);
                let full = self.engine.evaluate_with(t, (&phi, &self.angles_of(&phi, &crank)), &phid, 0.0, crank);
                self.reduce(t, self.keep_row(t, (&phi, &phid, &crank), full))
            }
            Terms::Configuration if self.engine.lubrication.is_some() => self.evaluate(t, q, qd),
            Terms::Configuration => {
                let (phi, _, crank) = self.full_state_and_crank(t, q, qd);
                let (trig, linkage) = (self.angles_of(&phi, &crank), &self.engine.linkage);
                self.reduce_configuration(t, &linkage.configuration_with(&trig, linkage.inertia_with(&trig)))
            }
        }
    }

    /// Keeps the crank row, without the gaps' column, for the drive torque of a free stage.
    fn inertia_and_force(&self, t: f64, q: &Vector2<f64>, qd: &Vector2<f64>) -> (Matrix2<f64>, Vector2<f64>) {
        let (phi, phid, crank) = self.full_state_and_crank(t, q, qd);
        let terms = self.engine.inertia_and_force(t, &phi, &phid, 0.0, crank);
        self.row.set(self.row_key(t, &phi, &phid, &crank), CrankRow::of_inertia(&terms));
        self.reduced(t, &terms.0, &terms.1)
    }

    fn begin_step(&self, t: f64, (q, qd, qdd): (&Vector2<f64>, &Vector2<f64>, &Vector2<f64>), dt: f64) -> bool {
        if self.engine.lubrication.is_some() {
            let (s, ahead, ahead_rates) = predicted(q, qd, qdd, dt);
            let ((phi, phid), (phi0, phid0)) = (self.full_state(t + s, &ahead, &ahead_rates), self.full_state(t, q, qd));
            self.engine.begin_step((t + s, phi, phid), (t, phi0, phid0));
        }
        self.engine.lubrication.is_some()
    }

    /// A step turns the crank by at most `MAX_STEP_ANGLE`. With two corners held the piston has no
    /// freedom left, the error control nothing to measure, and the step would grow to `MAX_STEP`
    /// whatever the speed: the quintic dense output of φ2 between such steps errs by ≈ (ω h)⁶, which
    /// put the corners of `piston_lateral` 3.6e-7 m outside the bore at 8000 rpm.
    fn step_bounds(&self, t: f64, _qd: &Vector2<f64>, gaps: &Vector4<f64>) -> StepBounds {
        self.engine.step_bounds(self.speed.at(t), gaps)
    }

    fn coordinate_lengths(&self) -> Vector2<f64> {
        let lengths = self.engine.linkage.lengths();
        Vector2::new(lengths[1], lengths[2])
    }

    const POWERS: bool = true;

    /// The drive's power is its torque (`drive_torque`) times ω; the row kept at this state gives
    /// the gas's and the damping's. The crank keeps its speed through a jump.
    fn powers(&self, t: f64, q: &Vector2<f64>, change: Change<'_, 2, 4>) -> Powers {
        match change {
            Change::Rates { v: qd, acc: qdd, forces } => {
                let (phi, phid, crank) = self.full_state_and_crank(t, q, qd);
                let (torque, row) = self.torque_and_row(t, (&phi, &phid, &crank), qdd, forces);
                let phidd = Vector3::new(self.acceleration(t), qdd[0], qdd[1]);
                self.engine.powers((&phi, &crank), &phid, &phidd, torque * phid[0], row.applied)
            }
            Change::Jump { before, after } => {
                let (phi, before, crank) = self.full_state_and_crank(t, q, before);
                let after = Vector3::new(before[0], after[0], after[1]);
                self.engine.jump(&phi, &LinkAngles::with_crank((crank.sin, crank.cos), &phi), &before, &after)
            }
        }
    }

    fn restitution(&self) -> f64 {
        self.engine.restitution
    }

    fn friction(&self, _constraint: usize) -> f64 {
        self.engine.friction
    }

    /// The full tangents reduced like the gaps: the crank's column times ω is the slip the drive
    /// makes, and times ω̇ part of the bias.
    fn tangents(&self, t: f64, q: &Vector2<f64>, qd: &Vector2<f64>) -> Tangents<2, 4> {
        let (phi, phid) = self.full_state(t, q, qd);
        let full = self.engine.linkage.tangents(&phi, &phid);
        let crank_column = full.jacobian.column(0);
        Tangents {
            jacobian: Matrix4x2::from_columns(&[full.jacobian.column(1), full.jacobian.column(2)]),
            time_rate: crank_column * self.speed.at(t),
            bias: full.bias + crank_column * self.acceleration(t),
        }
    }
}

/// The rod and piston block of a full inertia: the crank's angle is given, not a coordinate.
#[inline(always)]
fn rod_and_piston(inertia: &Matrix3<f64>) -> Matrix2<f64> {
    inertia.fixed_view::<2, 2>(1, 1).into_owned()
}

/// Crank, rod and piston, the crank loaded by the `load_torque` input.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FreeCrank {
    /// The engine on the crank.
    pub engine: Engine,
    /// N·m, opposing rotation.
    pub load_torque: InputPolynomial,
}

impl System<3, 4> for FreeCrank {
    fn evaluate(&self, t: f64, q: &Vector3<f64>, qd: &Vector3<f64>) -> Evaluation<3, 4> {
        self.engine.evaluate(t, q, qd, self.load_torque.at(t), self.engine.crank(q[0])).0
    }

    fn inertia_and_force(&self, t: f64, q: &Vector3<f64>, qd: &Vector3<f64>) -> (Matrix3<f64>, Vector3<f64>) {
        let (mass, force, _) = self.engine.inertia_and_force(t, q, qd, self.load_torque.at(t), self.engine.crank(q[0]));
        (mass, force)
    }

    fn begin_step(&self, t: f64, (q, qd, qdd): (&Vector3<f64>, &Vector3<f64>, &Vector3<f64>), dt: f64) -> bool {
        if self.engine.lubrication.is_some() {
            let (s, phi, phid) = predicted(q, qd, qdd, dt);
            self.engine.begin_step((t + s, phi, phid), (t, *q, *qd));
        }
        self.engine.lubrication.is_some()
    }

    /// A step turns the crank by at most `MAX_STEP_ANGLE`, as the prescribed crank's does: with two
    /// corners held only the crank moves, at a speed RK4 follows whatever the step, so the error
    /// control sees nothing while the held gaps drift as (ω h)⁵ (micrometres at 0.36 rad steps).
    fn step_bounds(&self, _t: f64, qd: &Vector3<f64>, gaps: &Vector4<f64>) -> StepBounds {
        self.engine.step_bounds(qd[0], gaps)
    }

    fn coordinate_lengths(&self) -> Vector3<f64> {
        self.engine.linkage.lengths()
    }

    const POWERS: bool = true;

    /// The load torque's power stands in the drive's channel.
    fn powers(&self, t: f64, q: &Vector3<f64>, change: Change<'_, 3, 4>) -> Powers {
        match change {
            Change::Rates { v: qd, acc: qdd, .. } => {
                let crank = self.engine.crank(q[0]);
                let trig = LinkAngles::with_crank((crank.sin, crank.cos), q);
                let applied = self.engine.linkage.gas_and_damping_power(&trig, qd, self.engine.gas_force_at(t, &crank));
                self.engine.powers((q, &crank), qd, qdd, -self.load_torque.at(t) * qd[0], applied)
            }
            Change::Jump { before, after } => self.engine.jump(q, &LinkAngles::new(q), before, after),
        }
    }

    fn restitution(&self) -> f64 {
        self.engine.restitution
    }

    fn friction(&self, _constraint: usize) -> f64 {
        self.engine.friction
    }

    fn tangents(&self, _t: f64, q: &Vector3<f64>, qd: &Vector3<f64>) -> Tangents<3, 4> {
        self.engine.linkage.tangents(q, qd)
    }
}

#[cfg(test)]
#[path = "engine_tests.rs"]
mod tests;
