//! The lubricated skirt (`skirt_model = 2`) on the crank train: the film and asperity loads of
//! [`crate::models::skirt`] as generalized forces on φ = (φ1, φ2, φ3), their damping made linearly
//! implicit through the inertia matrix (`documentation/design/lubricated_skirt.md` gives the reasoning and the
//! measurements).
//!
//! The skirt sees the pin's lateral position `x = −l1 sin φ1 − l2 sin φ2`, the tilt φ3 and the pin's
//! axial velocity `ẏ = −l1 sin φ1 φ̇1 − l2 sin φ2 φ̇2`. With `G = ∂(x, φ3)/∂φ`, rows
//! `(−l1 cos φ1, −l2 cos φ2, 0)` and `(0, 0, 1)`, and `g = ∂y/∂φ = (−l1 sin φ1, −l2 sin φ2, 0)`, the
//! loads (lateral force F, moment M, axial force F_a and its moment M_a) act as
//! `Q = Gᵀ (F, M + M_a) + g F_a`: through the rod angle on the crank, so that the prescribed drive
//! supplies the skirt's friction and a free crank is slowed by it.
//!
//! Stiffness: `D = −∂(F, M)/∂(ẋ, φ̇3)` makes the lateral and tilt motion relax over m/|D| ≈ 1e-8 s.
//! The film acts instead as `Q − τ Gᵀ D (G φ̈ + Ġ φ̇)`, its force at the rates (ẋ, φ̇3) a time τ
//! later to first order (`Ġ φ̇`, the rod's swing, is most of ẍ's terms: leaving it out pushes the
//! piston into the film): the evaluation returns `M + τ Gᵀ D G` and `f + Q − τ Gᵀ D Ġ φ̇`. A mode
//! `m v̇ = −c v` then relaxes at
//! `λ = −c/(m + τ c) ≥ −1/τ`, inside RK4's stability region for steps up to τ whatever the film;
//! with D → 0 the dry equations come back exactly. Boundary friction on the asperities, linear in
//! the sliding speed V across a narrow band (`skirt::BOUNDARY_SLIP`), is made implicit the same way
//! along `g` (slope c): a skirt that stops on its asperities is held by a friction that would
//! otherwise flip with V at every step. The books (`System::powers`, `books`) keep apart what the
//! loads at the instant's rates take from the motion, `−Q·φ̇` (the film's and boundary friction's
//! dissipation, and the asperities' stored energy's rise), and what the implicit term takes,
//! `τ (G φ̇)ᵀ D (G φ̈ + Ġ φ̇)`, with at a projection onto held corners (a jump Δφ̇) the impulse
//! `−τ Gᵀ D G Δφ̇`'s share: with v = G φ̇ the rise of `½ τ vᵀ D v` less `½ τ vᵀ Ḋ v`, no loss but
//! the relaxation's own work (D renewed at each film solve, so no function of the state either);
//! each wall's push, its side's share of the lateral force with its share of the implicit term (and
//! of the impulse at a projection), as two further channels: the film's and asperities' impulse on
//! the liner. An impact acts through the linkage's inertia alone (`Evaluation::mass`): the film,
//! a finite force, takes no impulse in it.
//!
//! Cost: the film is solved at most once per RK4 step (`Lubrication::begin_step`, from
//! `System::begin_step`), its pressure's loads linear in the rates within the step
//! (`Skirt::loads_with`), and carried on to the next steps while the piston moves little
//! (`step_film`).

use super::books::SkirtRates;
use super::linkage::LinkAngles;
use super::step_bounds::{CLEAR_ERROR_FACTOR, CLEAR_GAP};
use super::step_film::{key, Solved, StepFilm};
use crate::models::numerics::LastValue;
use crate::models::skirt::{
    read_matrix, CavitationCondition, Compliance, Fill, FilmLinear, OilSupply, PressureMap, Roughness, Skirt, SkirtDesign, SkirtLoads,
    SkirtMotion, SkirtProfile,
};
use crate::models::ModelError;
use nalgebra::{Matrix2x3, Matrix3, SVector, Vector2, Vector3, Vector4};
use serde::{Deserialize, Serialize};
use std::cell::RefCell;

/// RK4 steps per relaxation time τ: the fast mode then sees λh ≥ −1/2, where the books of its
/// transients close to ≈ 2e-3 of their energy (`tests/core/absorbing.rs`).
pub const STEPS_PER_RELAXATION: f64 = 2.0;

/// Where in an RK4 step the film is solved, as a fraction of the step ([`predicted`]): half a step
/// in, the film's position errs to second order over the stages (at the start, first order: the
/// default engine's peak side force then moved 0.60 % from the per-stage solve, against 0.31 %).
pub const SOLVE_AT: f64 = 0.5;

/// The skirt on the linkage: its film solver, the crank and rod lengths that place it, and τ.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(try_from = "Saved", into = "Saved")]
pub struct Lubrication {
    design: Design,
    skirt: Skirt,
    /// The film of the current RK4 step ([`Lubrication::begin_step`]), whose loads every
    /// evaluation takes until the next step begins; none before the first: each motion solved.
    frozen: RefCell<Option<StepFilm>>,
    /// The loads at the last motion and film evaluated: an RK4 stage's absorbed power reads its evaluation's.
    last: LastValue<SkirtLoads, 10>,
}

/// What a lubricated skirt is saved as: its design and the motions of the current step's film, with
/// the solves' times and fill fractions (solved again on restoring: the same films, the discrete
/// problem's unique solutions).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
struct Saved {
    design: Design,
    film: Option<SavedFilm>,
}

/// A [`StepFilm`]'s solves: the one before the latest, the latest; and the current step's middle
/// and its time.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
struct SavedFilm {
    previous: Option<SavedSolve>,
    latest: SavedSolve,
    current: [f64; 5],
    current_time: f64,
}

/// A solve's motion, time and the fill fraction it took (both sides; empty under the Reynolds
/// condition); with a limited supply the liner's oil, the pin's axial position it was exchanged up to
/// and the oil the liner lacked so far (`Solved::lacked`); an elastic skirt's deflection it started from.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
struct SavedSolve {
    motion: [f64; 5],
    time: f64,
    fill: [Vec<f64>; 2],
    liner: [Vec<f64>; 2],
    axial: f64,
    lacked: f64,
    start: [Vec<f64>; 2],
}

impl From<&Solved> for SavedSolve {
    fn from(solved: &Solved) -> Self {
        let fill = &solved.linear.fill;
        Self {
            motion: key(&solved.linear.at),
            time: solved.time,
            fill: fill.sides.clone(),
            liner: fill.liner.clone(),
            axial: fill.axial,
            lacked: solved.lacked,
            start: solved.start.clone(),
        }
    }
}

/// What a lubricated skirt is built from (and saved as), SI.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct Design {
    /// (l1, l2).
    pub(crate) links: [f64; 2],
    /// τ, s.
    pub(crate) relaxation: f64,
    /// D/2, d/2, s, h, a.
    pub(crate) geometry: [f64; 5],
    pub(crate) viscosity: f64,
    pub(crate) arc: f64,
    pub(crate) profile: String,
    pub(crate) ovality: f64,
    /// σ, η, β, E'.
    pub(crate) roughness: [f64; 4],
    pub(crate) boundary_friction: f64,
    pub(crate) grid: (usize, usize),
    /// `cavitation`: 1 Reynolds, 2 mass-conserving.
    pub(crate) cavitation: i32,
    /// `oil_supply`: 1 fully flooded, 2 limited to the oil on the liner, starting at `liner_oil_film`, m.
    pub(crate) oil_supply: i32,
    pub(crate) liner_oil_film: f64,
    /// `skirt_compliance`: 0 rigid, 1 the built-in shell of `wall` (thickness, m; Young's modulus,
    /// Pa), 2 the matrix in `compliance_file`.
    pub(crate) compliance: i32,
    pub(crate) wall: [f64; 2],
    pub(crate) compliance_file: String,
}

impl PartialEq for Lubrication {
    fn eq(&self, other: &Self) -> bool {
        self.design == other.design
    }
}

impl From<Lubrication> for Saved {
    fn from(lubrication: Lubrication) -> Self {
        let film = lubrication.frozen.borrow().as_ref().map(|f| SavedFilm {
            previous: f.previous.as_ref().map(SavedSolve::from),
            latest: SavedSolve::from(&f.latest),
            current: key(&f.current.at),
            current_time: f.current_time,
        });
        Self { design: lubrication.design, film }
    }
}

impl TryFrom<Saved> for Lubrication {
    type Error = ModelError;

    fn try_from(saved: Saved) -> Result<Self, ModelError> {
        let lubrication = Self::try_from(saved.design)?;
        if let Some(film) = saved.film {
            let solve = |s: &SavedSolve| {
                let fill = Fill { sides: s.fill.clone(), liner: s.liner.clone(), axial: s.axial };
                let fill = Some(&fill).filter(|f| !f.sides[0].is_empty());
                let mut solved = Solved::at(&lubrication.skirt, &motion(&s.motion), s.time, fill, &s.start);
                solved.lacked = s.lacked;
                solved
            };
            let previous = film.previous.as_ref().map(solve);
            let mut step = StepFilm::solved(solve(&film.latest), previous);
            // A current film other than the latest solve was carried there.
            step.carry_to(&motion(&film.current), film.current_time, lubrication.skirt.arm(), true);
            *lubrication.frozen.borrow_mut() = Some(step);
        }
        Ok(lubrication)
    }
}

impl TryFrom<Design> for Lubrication {
    type Error = ModelError;

    fn try_from(design: Design) -> Result<Self, ModelError> {
        let [radius_bore, radius_piston, length, pin_from_top, pin_offset] = design.geometry;
        let [sigma, density, radius, modulus] = design.roughness;
        let film = SkirtDesign {
            profile: design.profile.parse::<SkirtProfile>()?,
            ovality: design.ovality,
            roughness: Roughness { sigma, density, radius, modulus },
            boundary_friction: design.boundary_friction,
            grid: design.grid,
            cavitation: CavitationCondition::try_from(design.cavitation)?,
            supply: supply(&design)?,
            compliance: compliance(&design)?,
            ..SkirtDesign::new(radius_bore, radius_piston, length, pin_from_top, pin_offset, design.arc, design.viscosity)
        };
        let skirt = Skirt::new(film)?;
        Ok(Self { design, skirt, frozen: RefCell::new(None), last: LastValue::default() })
    }
}

/// The supply `oil_supply` names, placed along the pin's travel (l2 − l1 to l2 + l1 from the crank centre).
fn supply(design: &Design) -> Result<OilSupply, ModelError> {
    let [l1, l2] = design.links;
    match design.oil_supply {
        1 => Ok(OilSupply::Flooded),
        2 => Ok(OilSupply::Limited { liner_film: design.liner_oil_film, travel: (l2 - l1, l2 + l1) }),
        n => Err(ModelError(format!("oil_supply = {n} must be 1 (fully flooded) or 2 (limited to the oil on the liner)"))),
    }
}

/// The compliance `skirt_compliance` names.
fn compliance(design: &Design) -> Result<Compliance, ModelError> {
    match design.compliance {
        0 => Ok(Compliance::Rigid),
        1 => Ok(Compliance::Shell { thickness: design.wall[0], modulus: design.wall[1] }),
        2 => read_matrix(&design.compliance_file),
        n => Err(ModelError(format!("skirt_compliance = {n} must be 0 (rigid), 1 (the built-in shell) or 2 (a matrix from a file)"))),
    }
}

/// The skirt's motion and how it moves with φ.
struct Kinematics {
    motion: SkirtMotion,
    /// The pin's axial position `y = l1 cos φ1 + l2 cos φ2` from the crank centre, m.
    axial_position: f64,
    /// `G = ∂(x, φ3)/∂φ`.
    lateral: Matrix2x3<f64>,
    /// `g = ∂y/∂φ`.
    axial: Vector3<f64>,
    /// `Ġ φ̇`: (ẍ, φ̈3) = G φ̈ + Ġ φ̇.
    bias: Vector2<f64>,
    /// `ġ·φ̇`: ÿ = g·φ̈ + ġ·φ̇.
    axial_bias: f64,
}

impl Lubrication {
    /// The largest RK4 step, s: τ / [`STEPS_PER_RELAXATION`].
    pub fn largest_step(&self) -> f64 {
        self.design.relaxation / STEPS_PER_RELAXATION
    }

    /// The factor on the corners' local-error bound (`LOCAL_ERROR`) of a step starting at corner gaps
    /// `gaps`: `CLEAR_ERROR_FACTOR` while every corner is more than `CLEAR_GAP` off the liner, 1
    /// otherwise.
    pub fn error_scale(&self, gaps: &Vector4<f64>) -> f64 {
        if gaps.min() > CLEAR_GAP {
            CLEAR_ERROR_FACTOR
        } else {
            1.0
        }
    }

    /// At (φ, φ̇), `trig` the angles' sines and cosines.
    fn kinematics(&self, (phi, trig): (&Vector3<f64>, &LinkAngles), phid: &Vector3<f64>) -> Kinematics {
        let ([s1, s2, _], [c1, c2, _]) = (trig.sin, trig.cos);
        let [l1, l2] = self.design.links;
        let lateral = Matrix2x3::new(-l1 * c1, -l2 * c2, 0.0, 0.0, 0.0, 1.0);
        let axial = Vector3::new(-l1 * s1, -l2 * s2, 0.0);
        let rates = lateral * phid;
        let motion = SkirtMotion {
            lateral: -l1 * s1 - l2 * s2,
            tilt: phi[2],
            lateral_rate: rates[0],
            tilt_rate: rates[1],
            sliding_speed: axial.dot(phid),
        };
        let bias = Vector2::new(l1 * s1 * phid[0] * phid[0] + l2 * s2 * phid[1] * phid[1], 0.0);
        let axial_bias = -l1 * c1 * phid[0] * phid[0] - l2 * c2 * phid[1] * phid[1];
        Kinematics { motion, axial_position: l1 * c1 + l2 * c2, lateral, axial, bias, axial_bias }
    }

    /// Prepares the film for an RK4 step at (t, φ, φ̇), the time and state [`predicted`] [`SOLVE_AT`]
    /// into it, where the corners' gaps are `gaps`: while every corner is more than `CLEAR_GAP` off
    /// the liner, the last solve carried on where `StepFilm::carry_to` allows; otherwise solved there
    /// (near the liner, where the corners' events are, each step has its own solve), with
    /// mass-conserving cavitation at the latest solve's fill moved on to t (`Solved::next`; a limited
    /// supply's first solve takes `Skirt::starting_fill`). Until the next
    /// step begins, every evaluation takes the film's loads linear in its own rates from it
    /// (`Skirt::loads_with`). A step taken again from the same start and length (an event's search)
    /// takes the same film.
    pub fn begin_step(&self, t: f64, phi: &Vector3<f64>, phid: &Vector3<f64>, gaps: &Vector4<f64>) {
        let Kinematics { motion, axial_position, .. } = self.kinematics((phi, &LinkAngles::new(phi)), phid);
        let mut frozen = self.frozen.borrow_mut();
        let clear = gaps.min() > CLEAR_GAP;
        if !frozen.as_mut().is_some_and(|f| f.carry_to(&motion, t, self.skirt.arm(), clear)) {
            let previous = frozen.take().map(|f| f.latest);
            let solved = match &previous {
                Some(p) => p.next(&self.skirt, &motion, t, axial_position),
                None => {
                    Solved::at(&self.skirt, &motion, t, self.skirt.starting_fill(&motion, axial_position).as_ref(), &Default::default())
                }
            };
            *frozen = Some(StepFilm::solved(solved, previous));
        }
    }

    /// The film's loads at `motion` from the current step's film (solved at `motion` before the first).
    fn loads(&self, motion: &SkirtMotion) -> SkirtLoads {
        let frozen = self.frozen.borrow();
        let [x, y, z, u, v] = key(motion);
        let [a, b, c, d, e] = frozen.as_ref().map_or(key(motion), |f| key(&f.current.at));
        self.last.get_or([x, y, z, u, v, a, b, c, d, e], || match frozen.as_ref() {
            Some(f) => self.skirt.loads_with(&f.current, motion),
            None => self.skirt.loads(motion),
        })
    }

    /// The film's generalized force `Q − τ Gᵀ D Ġ φ̇ − τ c g ġ·φ̇` at (φ, φ̇), added to the linkage's
    /// `f`, and its implicit inertia `K = τ Gᵀ D G + τ c g gᵀ` (`Evaluation::implicit`); c the boundary
    /// friction's slope in the sliding speed (`SkirtLoads::boundary_damping`), made implicit as D is.
    #[inline(always)]
    pub fn apply(&self, at: (&Vector3<f64>, &LinkAngles), phid: &Vector3<f64>, force: &mut Vector3<f64>) -> Matrix3<f64> {
        let k = self.kinematics(at, phid);
        let loads = self.loads(&k.motion);
        let tau = self.design.relaxation;
        let (damping, boundary) = (loads.damping * tau, loads.boundary_damping * tau);
        *force += generalized(&k, &loads) - k.lateral.transpose() * (damping * k.bias) - k.axial * (boundary * k.axial_bias);
        k.lateral.transpose() * damping * k.lateral + k.axial * k.axial.transpose() * boundary
    }

    /// Both sides' film and asperity pressure and film thickness at (φ, φ̇), for plots.
    pub fn pressure_map(&self, at: (&Vector3<f64>, &LinkAngles), phid: &Vector3<f64>) -> PressureMap {
        let motion = self.kinematics(at, phid).motion;
        match self.frozen.borrow().as_ref() {
            Some(f) => f.pressure_map(&self.skirt, &motion),
            None => self.skirt.pressure_map(&self.skirt.linearise(&motion), &motion),
        }
    }

    /// The wetted share of the skirt's film area at time `t` (`Fill::wetted`): the latest solve's
    /// fill moved on to `t`; 1 before the first solve.
    pub fn wetted_fraction(&self, t: f64) -> f64 {
        self.frozen.borrow().as_ref().map_or(1.0, |f| f.latest.linear.fill_after(t - f.latest.time).wetted())
    }

    /// With a limited supply, the oil at the latest solve (none before the first): on the liner and in
    /// the film, m³, what the liner's cells lacked of what the film took since the start, m³, and the
    /// area the liner's maps cover, m².
    pub fn oil(&self) -> Option<Oil> {
        let frozen = self.frozen.borrow();
        let latest = &frozen.as_ref()?.latest;
        let (liner, area) = self.skirt.liner_oil(&latest.linear.fill);
        (area > 0.0).then_some(Oil { liner, film: latest.linear.content, lacked: latest.lacked, area })
    }

    /// The largest film pressure, Pa, and the skirt's largest deflection away from the liner, m, at
    /// the latest film solve (with none yet, of a solve at (φ, φ̇)).
    pub fn film_peaks(&self, at: (&Vector3<f64>, &LinkAngles), phid: &Vector3<f64>) -> (f64, f64) {
        let peaks = |linear: &FilmLinear| {
            let deflection = linear.deflection.iter().flatten().fold(0.0_f64, |m, &d| m.max(d));
            (linear.peak_pressure, deflection)
        };
        match self.frozen.borrow().as_ref() {
            Some(f) => peaks(&f.latest.linear),
            None => peaks(&self.skirt.linearise(&self.kinematics(at, phid).motion)),
        }
    }

    /// The loads at (φ, φ̇), for the outputs.
    pub fn loads_at(&self, at: (&Vector3<f64>, &LinkAngles), phid: &Vector3<f64>) -> SkirtLoads {
        self.loads(&self.kinematics(at, phid).motion)
    }

    /// The skirt's rates at (φ, φ̇, φ̈) (`books::SkirtRates`): what its implicit term takes,
    /// `τ (G φ̇)ᵀ D (G φ̈ + Ġ φ̇) + τ c ẏ ÿ`, W (the relaxation's work, no dissipation); what
    /// its loads at the instant's rates take, `−Q·φ̇`, W, and their axial friction's share,
    /// `−(F_a ẏ + M_a φ̇3)`; and the anti-thrust and the thrust wall's push as the motion takes it, N:
    /// each wall's share of the lateral force with the implicit term,
    /// `P + τ ∂P/∂(ẋ, φ̇3) (G φ̈ + Ġ φ̇)` (`SkirtLoads::wall_push`, whose rates' rows differ by D's first row).
    pub fn absorbed_power(&self, at: (&Vector3<f64>, &LinkAngles), phid: &Vector3<f64>, phidd: &Vector3<f64>) -> SkirtRates {
        let k = self.kinematics(at, phid);
        let loads = self.loads(&k.motion);
        let tau = self.design.relaxation;
        let acceleration = k.lateral * phidd + k.bias;
        let implicit = (k.lateral * phid).dot(&(loads.damping * acceleration)) * tau;
        let boundary = tau * loads.boundary_damping * k.motion.sliding_speed * (k.axial.dot(phidd) + k.axial_bias);
        let [thrust, antithrust] = (loads.wall_push + loads.wall_push_rates * acceleration * tau).into();
        let film = -generalized(&k, &loads).dot(phid);
        SkirtRates::new(implicit + boundary, film, -friction_power(&k, &loads), antithrust, thrust)
    }

    /// What the implicit film impulse `−τ (Gᵀ D G + c g gᵀ) Δφ̇` of a projection `before → after` at
    /// φ takes, J: the negative of its work on the mean velocity (D and c at the velocity before), in
    /// the relaxation's channel; and each wall's share of its lateral impulse,
    /// `τ ∂P/∂(ẋ, φ̇3) G Δφ̇`, N·s (anti-thrust, thrust). The loads at the instant's rates take no impulse.
    pub fn jump_books(&self, at: (&Vector3<f64>, &LinkAngles), before: &Vector3<f64>, after: &Vector3<f64>) -> SkirtRates {
        let k = self.kinematics(at, before);
        let loads = self.loads(&k.motion);
        let (jump, tau) = (k.lateral * (after - before), self.design.relaxation);
        let mean = (before + after) * 0.5;
        let [thrust, antithrust] = (loads.wall_push_rates * jump * tau).into();
        let boundary = tau * loads.boundary_damping * k.axial.dot(&mean) * k.axial.dot(&(after - before));
        let implicit = (k.lateral * mean).dot(&(loads.damping * tau * jump)) + boundary;
        SkirtRates::new(implicit, 0.0, 0.0, antithrust, thrust)
    }

    /// The axial friction's power at (φ, φ̇), W (≥ 0 where it opposes the sliding).
    pub fn friction_power(&self, at: (&Vector3<f64>, &LinkAngles), phid: &Vector3<f64>) -> f64 {
        let k = self.kinematics(at, phid);
        -friction_power(&k, &self.loads(&k.motion))
    }
}

/// A limited supply's oil ([`Lubrication::oil`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Oil {
    /// On both sides' liner maps, m³.
    pub liner: f64,
    /// In the film, m³.
    pub film: f64,
    /// What the liner's cells lacked of what the film took since the start, m³.
    pub lacked: f64,
    /// The area the liner's maps cover, m².
    pub area: f64,
}

/// The time `SOLVE_AT·dt` into an RK4 step of `dt` from (q, q̇, q̈) and the state there to second
/// order, `(q + q̇ s + q̈ s²/2, q̇ + q̈ s)`: the rates too, since the skirt's lateral rate is the small
/// difference of the crank's and the rod's terms (`G(φ) φ̇`), which a position moved without its
/// rates would spoil by ≈ l1 ω² s, several times the rate itself.
pub fn predicted<const N: usize>(
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
    dt: f64,
) -> (f64, SVector<f64, N>, SVector<f64, N>) {
    let s = SOLVE_AT * dt;
    (s, q + qd * s + qdd * (0.5 * s * s), qd + qdd * s)
}

/// The motion of five numbers (`key`'s inverse).
fn motion(&[lateral, tilt, lateral_rate, tilt_rate, sliding_speed]: &[f64; 5]) -> SkirtMotion {
    SkirtMotion { lateral, tilt, lateral_rate, tilt_rate, sliding_speed }
}

/// `Q = Gᵀ (F, M + M_a) + g F_a`.
fn generalized(k: &Kinematics, loads: &SkirtLoads) -> Vector3<f64> {
    k.lateral.transpose() * Vector2::new(loads.lateral_force, loads.moment + loads.friction_moment) + k.axial * loads.friction_force
}

/// The axial force's work rate on the skirt, `F_a ẏ + M_a φ̇3`, W.
fn friction_power(k: &Kinematics, loads: &SkirtLoads) -> f64 {
    loads.friction_force * k.motion.sliding_speed + loads.friction_moment * k.motion.tilt_rate
}
