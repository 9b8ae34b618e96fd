//! Small systems with closed-form behaviour, shared by the integration tests (`tests/core/`) and the
//! benchmark (`benches/core.rs`, which includes this file by path like every shared piece of `tests/common/`).
// Each includer uses some of them.
#![allow(dead_code)]

use nalgebra::{Matrix1, Matrix2, Matrix3, RowVector2, SMatrix, SVector, Vector1, Vector2, Vector3};
use pistonslap::dynamics::{Change, Evaluation, Powers, StepBounds, System, Tangents};
use serde::{Deserialize, Serialize};
use std::cell::Cell;

/// Any system, counting how often the core evaluates it (the cost measure of the integrator).
#[derive(Clone)]
pub struct Counted<S> {
    /// The system evaluated.
    pub inner: S,
    /// `evaluate` calls so far.
    pub evaluations: Cell<u64>,
}

impl<S> Counted<S> {
    /// `inner`, with no evaluation counted yet.
    pub fn new(inner: S) -> Self {
        Self { inner, evaluations: Cell::new(0) }
    }
}

impl<S: System<N, M>, const N: usize, const M: usize> System<N, M> for Counted<S> {
    fn evaluate(&self, t: f64, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> Evaluation<N, M> {
        self.evaluations.set(self.evaluations.get() + 1);
        self.inner.evaluate(t, q, qd)
    }
    fn restitution(&self) -> f64 {
        self.inner.restitution()
    }
    fn friction(&self, i: usize) -> f64 {
        self.inner.friction(i)
    }
    fn tangents(&self, t: f64, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> Tangents<N, M> {
        self.inner.tangents(t, q, qd)
    }
}

/// Prescribed motion `y_f(t)` of the surface a [`Ball`] hits (a rheonomic constraint).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Floor {
    /// `y_f = 0`.
    Fixed,
    /// `y_f = velocity · t`.
    Moving {
        /// m/s.
        velocity: f64,
    },
    /// `y_f = amplitude · sin(ω t)`.
    Oscillating {
        /// m.
        amplitude: f64,
        /// ω, rad/s.
        angular_frequency: f64,
    },
}

impl Floor {
    /// `(y_f, ẏ_f, ÿ_f)` at `t`.
    pub fn motion(&self, t: f64) -> (f64, f64, f64) {
        match *self {
            Floor::Fixed => (0.0, 0.0, 0.0),
            Floor::Moving { velocity } => (velocity * t, velocity, 0.0),
            Floor::Oscillating { amplitude: a, angular_frequency: w } => {
                let (s, c) = libm::sincos(w * t);
                (a * s, a * w * c, -a * w * w * s)
            }
        }
    }
}

/// A point mass on a line above a floor, under gravity: `q = y`, `h = y − y_f(t)`, `λ` = the
/// floor's normal force. With `gravity = 0` it is a ball against a moving wall.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Ball {
    /// kg.
    pub mass: f64,
    /// m/s², downward.
    pub gravity: f64,
    /// Newton's coefficient `e` at the floor.
    pub restitution: f64,
    /// The floor's motion.
    pub floor: Floor,
}

impl System<1, 1> for Ball {
    fn evaluate(&self, t: f64, q: &Vector1<f64>, _qd: &Vector1<f64>) -> Evaluation<1, 1> {
        let (yf, vf, af) = self.floor.motion(t);
        Evaluation {
            mass: Matrix1::new(self.mass),
            implicit: None,
            force: Vector1::new(-self.mass * self.gravity),
            gap: Vector1::new(q[0] - yf),
            gap_jacobian: Matrix1::new(1.0),
            gap_time_rate: Vector1::new(-vf),
            gap_bias: Vector1::new(-af),
        }
    }
    fn restitution(&self) -> f64 {
        self.restitution
    }
}

/// The first three channels of [`Powers`], the rest zero.
fn channels(first: [f64; 3]) -> Powers {
    Powers::from_fn(|i, _| first.get(i).copied().unwrap_or(0.0))
}

/// A [`Ball`] with a viscous damper to the ground, `−c ẏ`, made linearly implicit over the time
/// `relaxation` τ as a stiff film is: `K = τ c` and `f = −m g − c ẏ`, so that the damper acts
/// as `−c (ẏ + τ ÿ)` and its mode relaxes over ≈ τ whatever c. The damper's work, through `ÿ` and
/// at the projections onto a resting contact, is absorbed (`System::powers`); an impact acts
/// through m alone (`Evaluation::mass`: the damper is a finite force). Steps are bounded by τ.
/// With c = 0 it is the `Ball`, bit for bit.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct DampedBall {
    /// The ball, floor and restitution.
    pub ball: Ball,
    /// c, N·s/m.
    pub damping: f64,
    /// τ, s.
    pub relaxation: f64,
}

impl System<1, 1> for DampedBall {
    fn evaluate(&self, t: f64, q: &Vector1<f64>, qd: &Vector1<f64>) -> Evaluation<1, 1> {
        let mut ev = self.ball.evaluate(t, q, qd);
        ev.implicit = Some(Matrix1::new(self.relaxation * self.damping));
        ev.force[0] -= self.damping * qd[0];
        ev
    }
    fn step_bounds(&self, _t: f64, _qd: &Vector1<f64>, _gaps: &Vector1<f64>) -> StepBounds {
        StepBounds { largest: self.relaxation, ..StepBounds::default() }
    }
    const POWERS: bool = true;
    /// Along the motion, all of it in both power channels and the damper's force on the ball,
    /// `−c (ẏ + τ ÿ)`, in the third; at a jump, the implicit impulse's work and the impulse.
    fn powers(&self, _t: f64, _q: &Vector1<f64>, change: Change<'_, 1, 1>) -> Powers {
        match change {
            Change::Rates { v, acc, .. } => {
                let force = -self.damping * (v[0] + self.relaxation * acc[0]);
                channels([-force * v[0], -force * v[0], force])
            }
            Change::Jump { before, after } => {
                let impulse = -self.relaxation * self.damping * (after[0] - before[0]);
                let work = -impulse * 0.5 * (after[0] + before[0]);
                channels([work, work, impulse])
            }
        }
    }
    fn restitution(&self) -> f64 {
        self.ball.restitution
    }
}

/// A uniform planar rod (mass `m`, length `L`) above a horizontal floor at height `y_f(t)` under
/// gravity, `q = (x, y, θ)` of its centre; constraint `i` keeps end `i` above the floor:
/// `h₀ = y − y_f − (L/2) sin θ`, `h₁ = y − y_f + (L/2) sin θ`. The ends couple translation and
/// rotation. With Coulomb friction μ on the floor, end `i` slips at `γᵢ = ẋ ± (L/2) sin θ θ̇`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Rod {
    /// kg.
    pub mass: f64,
    /// m.
    pub length: f64,
    /// m/s², downward.
    pub gravity: f64,
    /// Newton's coefficient `e` at both ends.
    pub restitution: f64,
    /// Coulomb's μ at both ends (0: frictionless).
    pub friction: f64,
    /// The floor's motion.
    pub floor: Floor,
}

impl Rod {
    /// Central moment of inertia `m L² / 12`.
    pub fn inertia(&self) -> f64 {
        self.mass * self.length * self.length / 12.0
    }
}

impl System<3, 2> for Rod {
    fn evaluate(&self, t: f64, q: &Vector3<f64>, qd: &Vector3<f64>) -> Evaluation<3, 2> {
        let half = 0.5 * self.length;
        let (s, c) = libm::sincos(q[2]);
        let spin = half * s * qd[2] * qd[2];
        let (yf, vf, af) = self.floor.motion(t);
        let (centre, rise) = (q[1] - yf, half * s);
        Evaluation {
            mass: Matrix3::from_diagonal(&Vector3::new(self.mass, self.mass, self.inertia())),
            implicit: None,
            force: Vector3::new(0.0, -self.mass * self.gravity, 0.0),
            gap: Vector2::new(centre - rise, centre + rise),
            gap_jacobian: SMatrix::<f64, 2, 3>::new(0.0, 1.0, -half * c, 0.0, 1.0, half * c),
            gap_time_rate: Vector2::new(-vf, -vf),
            gap_bias: Vector2::new(spin - af, -spin - af),
        }
    }
    fn restitution(&self) -> f64 {
        self.restitution
    }
    fn friction(&self, _: usize) -> f64 {
        self.friction
    }
    fn tangents(&self, _t: f64, q: &Vector3<f64>, qd: &Vector3<f64>) -> Tangents<3, 2> {
        let half = 0.5 * self.length;
        let (s, c) = libm::sincos(q[2]);
        let spin = half * c * qd[2] * qd[2];
        Tangents {
            jacobian: SMatrix::<f64, 2, 3>::new(1.0, 0.0, half * s, 1.0, 0.0, -half * s),
            time_rate: Vector2::zeros(),
            bias: Vector2::new(spin, -spin),
        }
    }
}

/// A point mass in the plane inside a wedge of two walls through the origin,
/// `hᵢ = nᵢ · q ≥ 0` with unit inward normals `nᵢ`, under a constant force field `g`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Wedge {
    /// kg.
    pub mass: f64,
    /// The force field per unit mass `g`, m/s².
    pub gravity: Vector2<f64>,
    /// The walls' unit inward normals `nᵢ`.
    pub normals: [Vector2<f64>; 2],
    /// Newton's coefficient `e` at both walls.
    pub restitution: f64,
}

impl Wedge {
    fn jacobian(&self) -> Matrix2<f64> {
        Matrix2::from_rows(&[self.normals[0].transpose(), self.normals[1].transpose()])
    }
}

impl System<2, 2> for Wedge {
    fn evaluate(&self, _t: f64, q: &Vector2<f64>, _qd: &Vector2<f64>) -> Evaluation<2, 2> {
        Evaluation {
            mass: Matrix2::identity() * self.mass,
            implicit: None,
            force: self.gravity * self.mass,
            gap: self.jacobian() * q,
            gap_jacobian: self.jacobian(),
            gap_time_rate: Vector2::zeros(),
            gap_bias: Vector2::zeros(),
        }
    }
    fn restitution(&self) -> f64 {
        self.restitution
    }
}

/// A double pendulum of point masses `m₁`, `m₂` on massless rods `l₁`, `l₂`, angles `θ₁`, `θ₂`
/// from the downward vertical, whose tip may not pass the wall `x = −wall`:
/// `h = l₁ sin θ₁ + l₂ sin θ₂ + wall ≥ 0`. Its inertia matrix couples the two angles.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct DoublePendulum {
    /// `m₁`, `m₂`, kg.
    pub masses: [f64; 2],
    /// `l₁`, `l₂`, m.
    pub lengths: [f64; 2],
    /// m/s², downward.
    pub gravity: f64,
    /// The wall's distance from the pivot, m (far beyond `l₁ + l₂`: no wall in reach).
    pub wall: f64,
    /// Newton's coefficient `e` at the wall.
    pub restitution: f64,
}

impl DoublePendulum {
    /// The inertia matrix `M(θ₁, θ₂)`.
    pub fn mass_matrix(&self, q: &Vector2<f64>) -> Matrix2<f64> {
        let ([m1, m2], [l1, l2]) = (self.masses, self.lengths);
        let coupling = m2 * l1 * l2 * libm::cos(q[0] - q[1]);
        Matrix2::new((m1 + m2) * l1 * l1, coupling, coupling, m2 * l2 * l2)
    }

    /// Total mechanical energy `T + V`.
    pub fn energy(&self, q: &Vector2<f64>, qd: &Vector2<f64>) -> f64 {
        let ([m1, m2], [l1, l2]) = (self.masses, self.lengths);
        let potential = -(m1 + m2) * self.gravity * l1 * libm::cos(q[0]) - m2 * self.gravity * l2 * libm::cos(q[1]);
        0.5 * qd.dot(&(self.mass_matrix(q) * qd)) + potential
    }
}

impl System<2, 1> for DoublePendulum {
    fn evaluate(&self, _t: f64, q: &Vector2<f64>, qd: &Vector2<f64>) -> Evaluation<2, 1> {
        let ([m1, m2], [l1, l2], g) = (self.masses, self.lengths, self.gravity);
        let (s1, c1) = libm::sincos(q[0]);
        let (s2, c2) = libm::sincos(q[1]);
        let cross = m2 * l1 * l2 * libm::sin(q[0] - q[1]);
        Evaluation {
            mass: self.mass_matrix(q),
            implicit: None,
            force: Vector2::new(-cross * qd[1] * qd[1] - (m1 + m2) * g * l1 * s1, cross * qd[0] * qd[0] - m2 * g * l2 * s2),
            gap: Vector1::new(l1 * s1 + l2 * s2 + self.wall),
            gap_jacobian: RowVector2::new(l1 * c1, l2 * c2),
            gap_time_rate: Vector1::zeros(),
            gap_bias: Vector1::new(-l1 * s1 * qd[0] * qd[0] - l2 * s2 * qd[1] * qd[1]),
        }
    }
    fn restitution(&self) -> f64 {
        self.restitution
    }
}

/// A plank resting with both ends on a floor, lifted at its centre by `F = m g + lift_rate · t`
/// and turned by `τ = torque_rate · max(t, 0)`: `q = (y, θ)`, the centre's height and the tilt;
/// `h = y ∓ a sin θ` for the left and right ends (a = half-length). Both contact forces are
/// `(m g − F)/2 = −lift_rate · t / 2` while it rests, so they reach zero together at `t = 0`, the
/// instant the torque starts: a tie that only the motion after it decides.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Plank {
    /// kg.
    pub mass: f64,
    /// About the centre, kg·m².
    pub inertia: f64,
    /// `a`, m.
    pub half_length: f64,
    /// m/s², downward.
    pub gravity: f64,
    /// N/s.
    pub lift_rate: f64,
    /// N·m/s.
    pub torque_rate: f64,
}

impl System<2, 2> for Plank {
    fn evaluate(&self, t: f64, q: &Vector2<f64>, qd: &Vector2<f64>) -> Evaluation<2, 2> {
        let (s, c) = libm::sincos(q[1]);
        let a = self.half_length;
        Evaluation {
            mass: Matrix2::new(self.mass, 0.0, 0.0, self.inertia),
            implicit: None,
            force: Vector2::new(self.lift_rate * t, self.torque_rate * t.max(0.0)),
            gap: Vector2::new(q[0] - a * s, q[0] + a * s),
            gap_jacobian: Matrix2::new(1.0, -a * c, 1.0, a * c),
            gap_time_rate: Vector2::zeros(),
            gap_bias: Vector2::new(a * s * qd[1] * qd[1], -a * s * qd[1] * qd[1]),
        }
    }
    fn restitution(&self) -> f64 {
        0.5
    }
}

/// A block (a point mass) on a horizontal belt that moves at `belt` m/s along x, under gravity,
/// pushed along x by `push_rate · t`, with Coulomb friction μ on the belt: `q = (x, y)`, `h = y`,
/// slip `γ = ẋ − belt` (the belt's motion is the constraint's `∂γ/∂t`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Block {
    /// kg.
    pub mass: f64,
    /// m/s², downward.
    pub gravity: f64,
    /// Coulomb's μ on the belt.
    pub friction: f64,
    /// The belt's speed along x, m/s.
    pub belt: f64,
    /// N/s.
    pub push_rate: f64,
    /// Newton's coefficient `e` on the belt.
    pub restitution: f64,
}

impl System<2, 1> for Block {
    fn evaluate(&self, t: f64, q: &Vector2<f64>, _qd: &Vector2<f64>) -> Evaluation<2, 1> {
        Evaluation {
            mass: Matrix2::identity() * self.mass,
            implicit: None,
            force: Vector2::new(self.push_rate * t, -self.mass * self.gravity),
            gap: Vector1::new(q[1]),
            gap_jacobian: RowVector2::new(0.0, 1.0),
            gap_time_rate: Vector1::zeros(),
            gap_bias: Vector1::zeros(),
        }
    }
    fn restitution(&self) -> f64 {
        self.restitution
    }
    fn friction(&self, _: usize) -> f64 {
        self.friction
    }
    fn tangents(&self, _t: f64, _q: &Vector2<f64>, _qd: &Vector2<f64>) -> Tangents<2, 1> {
        Tangents { jacobian: RowVector2::new(1.0, 0.0), time_rate: Vector1::new(-self.belt), bias: Vector1::zeros() }
    }
}

/// A flywheel (angle φ, inertia `inertia`) driving a block on the floor through a lever: the block
/// sits at x = −L cos φ, so that it slips at `γ = L sin φ φ̇`, a lever that vanishes at the dead
/// centre φ = 0, as the piston's axial motion does at a dead centre of the crank. `q = (φ, y)`,
/// `h = y`; Coulomb friction μ on the floor. Kinetic energy `½ (I + m L² sin²φ) φ̇² + ½ m ẏ²`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Toggle {
    /// The flywheel's, kg·m².
    pub inertia: f64,
    /// The block's, kg.
    pub mass: f64,
    /// The lever L, m.
    pub lever: f64,
    /// m/s², downward.
    pub gravity: f64,
    /// Coulomb's μ on the floor.
    pub friction: f64,
}

impl Toggle {
    /// `I + m L² sin²φ`, kg·m²: the flywheel's inertia with the block's carried along.
    pub fn inertia_at(&self, phi: f64) -> f64 {
        self.inertia + self.mass * (self.lever * libm::sin(phi)).powi(2)
    }
}

impl System<2, 1> for Toggle {
    fn evaluate(&self, _t: f64, q: &Vector2<f64>, qd: &Vector2<f64>) -> Evaluation<2, 1> {
        let (s, c) = libm::sincos(q[0]);
        let (m, l) = (self.mass, self.lever);
        Evaluation {
            mass: Matrix2::new(self.inertia_at(q[0]), 0.0, 0.0, m),
            implicit: None,
            force: Vector2::new(-m * l * l * s * c * qd[0] * qd[0], -m * self.gravity),
            gap: Vector1::new(q[1]),
            gap_jacobian: RowVector2::new(0.0, 1.0),
            gap_time_rate: Vector1::zeros(),
            gap_bias: Vector1::zeros(),
        }
    }
    fn restitution(&self) -> f64 {
        0.0
    }
    fn friction(&self, _: usize) -> f64 {
        self.friction
    }
    fn tangents(&self, _t: f64, q: &Vector2<f64>, qd: &Vector2<f64>) -> Tangents<2, 1> {
        let (s, c) = libm::sincos(q[0]);
        Tangents {
            jacobian: RowVector2::new(self.lever * s, 0.0),
            time_rate: Vector1::zeros(),
            bias: Vector1::new(self.lever * c * qd[0] * qd[0]),
        }
    }
}
