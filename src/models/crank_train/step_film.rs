//! The film an RK4 step of the lubricated skirt takes (`Lubrication::begin_step`): solved at the
//! step's middle, or the last solve carried on.
//!
//! For a fixed position and cavitation set the film's loads are `−Γ r`, linear in the rates
//! r = (ẋ, φ̇3, V) (`FilmLinear`); the set depends on the rates' direction alone (the discrete
//! Reynolds problem with `b = Σ r_c b_c` scaled by a positive factor keeps its solution's set). A
//! solve is carried on to a step whose middle lies within [`CARRY_MOVE`] of the thinnest film from it
//! (lateral move plus the skirt's longest arm times the tilt: a bound on how much any node's film
//! changed) and whose rates differ from its rates by at most [`CARRY_RATES`] of their size in the
//! film's own dissipation norm (`Γ`'s upper 3 × 3). `Γ` is then moved to the step's middle along the
//! secant of the last two solves when both have the same cavitation set, so that the error left is
//! second order in the move (the position's first-order change taken out); otherwise it is held.
//! Near the liner (a corner or the thinnest film within `CLEAR_GAP`), where the corners' events
//! are, every step is solved. With mass-conserving cavitation a solve is carried only while no node's
//! fill would have moved by more than [`CARRY_FILL`] since it, and the next solve takes the fill
//! moved on from the latest solve to its own time, with a limited supply the liner's oil exchanged
//! with the film's edges over the pin's path (`Skirt::fill_after`).

use super::step_bounds::CLEAR_GAP;
use crate::models::skirt::{Fill, FilmLinear, PressureMap, Skirt, SkirtMotion};
use nalgebra::{Vector2, Vector3};

/// How far the piston's middle of a step may lie from the last solve's position for that solve to be
/// carried on, as a fraction of the thinnest film there. The default engine (`skirt_study -- RPM 3`):
/// 0.01 solves at one RK4 step in 4.1 (1200 rpm) and 3.9 (3000 rpm), every figure of the study within
/// 0.26 % of a solve per step.
pub const CARRY_MOVE: f64 = 0.01;
/// How much the rates may have changed, relative to their size in the film's dissipation norm: the
/// cavitation set follows the rates' direction, which a change this small keeps (the default engine's
/// thinnest film at 1200 rpm within 0.26 % of a solve per step).
pub const CARRY_RATES: f64 = 0.1;
/// With mass-conserving cavitation, how far any node's fill fraction may have moved at its solve's
/// rate since the latest solve for that solve to be carried on: its oil content then changes by about
/// as little as the film thickness may under [`CARRY_MOVE`].
pub const CARRY_FILL: f64 = 0.01;
/// The secant reaches at most this many times its own length beyond the latest solve: a slope from
/// two solves far closer together than the move ahead (a rejected step's solve next to the latest)
/// is not trusted that far.
const SECANT_REACH: f64 = 16.0;

/// A film solve, its time (s) and the thinnest film at its motion, m; with a limited supply, the oil
/// the film has taken since the first solve beyond what the liner's cells held, m³ (`Skirt::fill_after`);
/// an elastic skirt's deflection the solve started from (the solve before's; empty: undeflected).
#[derive(Clone, Debug)]
pub(super) struct Solved {
    pub linear: FilmLinear,
    pub time: f64,
    thinnest: f64,
    pub lacked: f64,
    pub start: [Vec<f64>; 2],
}

impl Solved {
    /// The film solved at `motion` at `time`, with mass-conserving cavitation at the fill fraction
    /// `fill` (flooded where none), an elastic skirt's deflection relaxed from `start`.
    pub fn at(skirt: &Skirt, motion: &SkirtMotion, time: f64, fill: Option<&Fill>, start: &[Vec<f64>; 2]) -> Self {
        let linear = skirt.linearise_deflected(motion, fill, start);
        let [thrust, antithrust] = skirt.loads_with(&linear, motion).min_film;
        Self { linear, time, thinnest: thrust.min(antithrust), lacked: 0.0, start: start.clone() }
    }

    /// The film solved at `motion` at `time` after this one, the pin at axial position `axial` (m):
    /// the fill moved on to `time`.
    pub fn next(&self, skirt: &Skirt, motion: &SkirtMotion, time: f64, axial: f64) -> Self {
        let (fill, lacked) = skirt.fill_after(&self.linear, time - self.time, (motion, axial));
        Self { lacked: self.lacked + lacked, ..Self::at(skirt, motion, time, Some(&fill), &self.linear.deflection) }
    }

    /// Whether a step with its middle at `motion` at `time` may take this solve, `arm` the skirt's
    /// longest distance from the pin, m.
    fn carries_to(&self, motion: &SkirtMotion, time: f64, arm: f64) -> bool {
        let at = &self.linear.at;
        let moved = (motion.lateral - at.lateral).abs() + arm * (motion.tilt - at.tilt).abs();
        let dissipation = self.linear.gram.fixed_view::<3, 3>(0, 0).into_owned();
        let (solved, change) = (rates(at), rates(motion) - rates(at));
        let norm = |r: &Vector3<f64>| r.dot(&(dissipation * r));
        let filled = self.linear.fill_rate.sides.iter().flatten().fold(0.0_f64, |m, r| m.max(r.abs())) * (time - self.time).abs();
        self.thinnest > CLEAR_GAP
            && moved <= CARRY_MOVE * self.thinnest
            && norm(&change) <= CARRY_RATES * CARRY_RATES * norm(&solved)
            && filled <= CARRY_FILL
    }
}

/// The film of the current step and the solves it comes from.
#[derive(Clone, Debug)]
pub(super) struct StepFilm {
    /// What the step takes: the latest solve's cavitation set with `Γ` moved to its `at`, the
    /// step's middle (the latest solve itself where it was solved).
    pub current: FilmLinear,
    /// The time of `current`'s `at`, s.
    pub current_time: f64,
    pub latest: Solved,
    pub previous: Option<Solved>,
    /// How far along the secant `current`'s `Γ` lies beyond the latest solve, in secants (0: held).
    reach: f64,
}

impl StepFilm {
    /// The film of a step solved at its middle, `previous` the solve before.
    pub fn solved(latest: Solved, previous: Option<Solved>) -> Self {
        Self { current: latest.linear.clone(), current_time: latest.time, latest, previous, reach: 0.0 }
    }

    /// Prepares a step whose middle is at `motion` at `time`: true if the current film serves (the
    /// same middle, a step taken again) or, `carry` allowing, the latest solve is carried to it; false
    /// if the step needs a solve of its own.
    pub fn carry_to(&mut self, motion: &SkirtMotion, time: f64, arm: f64, carry: bool) -> bool {
        if key(&self.current.at).map(f64::to_bits) == key(motion).map(f64::to_bits) {
            return true;
        }
        if !carry || !self.latest.carries_to(motion, time, arm) {
            return false;
        }
        let b = &self.latest.linear;
        self.reach = 0.0;
        if let Some(a) = self.previous.as_ref().map(|p| &p.linear).filter(|a| a.free == b.free) {
            let pose = |m: &SkirtMotion| Vector2::new(m.lateral, arm * m.tilt);
            let (secant, ahead) = (pose(&b.at) - pose(&a.at), pose(motion) - pose(&b.at));
            let reach = ahead.dot(&secant) / secant.norm_squared();
            if reach.abs() <= SECANT_REACH && dissipates(&(b.gram + (b.gram - a.gram) * reach)) {
                self.reach = reach;
            }
        }
        self.current.gram = self.along_secant(b.gram, |p| p.linear.gram);
        self.current.lateral_by_side = self.along_secant(b.lateral_by_side, |p| p.linear.lateral_by_side);
        self.current.moment_by_side = self.along_secant(b.moment_by_side, |p| p.linear.moment_by_side);
        self.current.at = *motion;
        self.current_time = time;
        true
    }

    /// `x` of the latest solve moved along the secant to `current` (`of` reads it from a solve).
    fn along_secant<T>(&self, latest: T, of: impl Fn(&Solved) -> T) -> T
    where
        T: Copy + std::ops::Add<Output = T> + std::ops::Sub<Output = T> + std::ops::Mul<f64, Output = T>,
    {
        match self.previous.as_ref().filter(|_| self.reach != 0.0) {
            Some(previous) => latest + (latest - of(previous)) * self.reach,
            None => latest,
        }
    }

    /// Both sides' fields at `motion` for plots, the pressure the one whose loads are `current`'s:
    /// the solves' pressures at `motion`'s rates (on their own cavitation set) moved along the
    /// secant as `Γ` was. Where that extrapolation dips below zero (a node near the set's edge) it
    /// is drawn as zero.
    pub fn pressure_map(&self, skirt: &Skirt, motion: &SkirtMotion) -> PressureMap {
        let mut map = skirt.pressure_map(&self.latest.linear, motion);
        if let Some(previous) = self.previous.as_ref().filter(|_| self.reach != 0.0) {
            let before = skirt.pressure_map(&previous.linear, motion);
            for (side, old) in map.sides.iter_mut().zip(&before.sides) {
                for (p, a) in side.pressure.iter_mut().zip(&old.pressure) {
                    *p = self.along_secant(*p, |_| *a).max(0.0);
                }
            }
        }
        map
    }
}

/// Whether `gram`'s upper 3 × 3, the film's dissipation as a quadratic form in the rates, is positive
/// semidefinite as every solve's is (to 1e-6 of its largest eigenvalue: one direction dissipates next
/// to nothing, and the default engine's secants leave it at −1e-11 of the largest). A secant that
/// moves it off, the pose ahead far along a slope that changes fast, would make the film give energy
/// to the motion: at a τ above the largest accepted, a film carried along such secants drives a whirl
/// until the inertia matrix with the implicit term is not positive definite.
fn dissipates(gram: &nalgebra::Matrix4x3<f64>) -> bool {
    let form = gram.fixed_view::<3, 3>(0, 0);
    let eigenvalues = nalgebra::SymmetricEigen::new((form + form.transpose()) * 0.5).eigenvalues;
    eigenvalues.min() >= -1e-6 * eigenvalues.max()
}

/// The rates (ẋ, φ̇3, V) of a motion.
fn rates(m: &SkirtMotion) -> Vector3<f64> {
    Vector3::new(m.lateral_rate, m.tilt_rate, m.sliding_speed)
}

/// A motion's five numbers.
pub(super) fn key(m: &SkirtMotion) -> [f64; 5] {
    [m.lateral, m.tilt, m.lateral_rate, m.tilt_rate, m.sliding_speed]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fmus::piston_slap::Parameters;
    use crate::models::skirt::{SkirtDesign, SkirtProfile};

    /// The default engine's skirt (12 × 18 grid) and its longest arm from the pin, m.
    fn default_skirt() -> (Skirt, f64) {
        let p = Parameters::default();
        let mut d = SkirtDesign::new(
            0.5 * p.bore,
            0.5 * p.piston_diameter,
            p.skirt_length,
            p.pin_height,
            p.pin_offset,
            p.skirt_arc,
            p.oil_viscosity,
        );
        d.profile = p.skirt_profile.parse::<SkirtProfile>().expect("the default profile");
        let skirt = Skirt::new(d).expect("the default skirt");
        let arm = skirt.arm();
        (skirt, arm)
    }

    #[test]
    fn a_carried_film_is_the_fresh_solve_to_second_order_in_the_move() {
        // The piston pressed toward the thrust wall and closing on it while it slides (mid-stroke):
        // solves at two poses a move δ apart, carried on a move δ beyond the latest (every node's
        // film changed by at most δ), against a fresh solve there. Held, the loads err to first order
        // in δ/h (the film's h⁻³: measured 1.26 δ/h); along the secant, to second order (×4 per
        // doubling of δ: measured 3.99), 2e-4 of the loads at the bound δ = CARRY_MOVE·h.
        let (skirt, arm) = default_skirt();
        let errors = |delta: f64| {
            let pose = |k: f64| SkirtMotion {
                lateral: 20e-6 + k * delta / 2.0,
                tilt: 1e-4 + k * delta / (2.0 * arm),
                lateral_rate: 4e-3,
                tilt_rate: 0.05,
                sliding_speed: 6.0,
            };
            let (a, b, at) = (
                Solved::at(&skirt, &pose(0.0), 0.0, None, &Default::default()),
                Solved::at(&skirt, &pose(1.0), 0.0, None, &Default::default()),
                pose(2.0),
            );
            assert_eq!(a.linear.free, b.linear.free, "one cavitation set along the path");
            let thinnest = b.thinnest;
            let fresh = -skirt.linearise(&at).gram * rates(&at);
            let error = |previous: Option<Solved>| {
                let mut film = StepFilm::solved(b.clone(), previous);
                assert!(film.carry_to(&at, 0.0, arm, true) == (delta <= CARRY_MOVE * thinnest), "δ {delta}: carried iff within the bound");
                film.latest.thinnest = f64::INFINITY;
                assert!(film.carry_to(&at, 0.0, arm, true));
                (-film.current.gram * rates(&at) - fresh).amax() / fresh.amax()
            };
            (delta / thinnest, error(None), error(Some(a)))
        };
        let (relative, held, secant) = errors(0.1e-6);
        let (_, held_half, secant_half) = errors(0.05e-6);
        assert!(relative < CARRY_MOVE && held > relative && held < 2.0 * relative, "held: {held:e} at δ/h {relative}");
        assert!((held / held_half - 2.0).abs() < 0.1, "held, first order: {held:e}, {held_half:e}");
        assert!((secant / secant_half - 4.0).abs() < 0.4 && secant < 5e-4, "secant, second order: {secant:e}, {secant_half:e}");
    }
}
