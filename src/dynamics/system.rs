//! What the core integrates: the system's interface and the terms it evaluates.

use nalgebra::{SMatrix, SVector};

/// Rates a system reports along the motion (`System::powers`) and their integrals, which the core
/// keeps with every step's own weights and carries across events alike, in up to eight channels the
/// system names (W and J, or N and N·s for a force it reports). `[0]` holds the power the implicit
/// part of its force (`Evaluation::implicit`) takes from the motion, to which the core adds the share
/// contacts held with that part projected take over (`implicit/`).
pub type Powers = SVector<f64, 8>;

/// Everything one RK4 stage, one impact or one sliding solve needs, evaluated at `(t, q, q̇)`.
///
/// Conventions (A&K eqs 1, 2, 16, 18): `ḣ = J q̇ + ∂h/∂t` and `ḧ = J q̈ + d`, with `J = ∂h/∂q`.
/// With `h` a distance in metres and `(M + K) q̈ = f + Jᵀ λ`, the multiplier `λ` is the normal contact force.
#[derive(Clone, Debug, PartialEq)]
pub struct Evaluation<const N: usize, const M: usize> {
    /// `M(q,t)`: symmetric, positive definite inertia matrix.
    pub mass: SMatrix<f64, N, N>,
    /// `K`: the implicit part of a stiff force. A damper `−D q̇` applied as `−D (q̇ + τ q̈)`, its
    /// rates a time τ ahead, has `K = τ D` here and the rest in `f`: the motion between events
    /// takes `M + K` ([`Self::inertia`]), stable at steps up to τ however large D; an impact, in
    /// which the finite force takes no impulse, takes `M` (`implicit/`). None: no such force.
    pub implicit: Option<SMatrix<f64, N, N>>,
    /// `f(q,q̇,t)`: gyroscopic, damping, potential and exciting forces.
    pub force: SVector<f64, N>,
    /// `h(q,t)`: normal distance to each obstacle, ≥ 0 where admissible.
    pub gap: SVector<f64, M>,
    /// `J = ∂h/∂q`.
    pub gap_jacobian: SMatrix<f64, M, N>,
    /// `∂h/∂t`: non-zero for rheonomic (moving) constraints.
    pub gap_time_rate: SVector<f64, M>,
    /// `d = q̇ᵀ ∂²h/∂q² q̇ + 2 ∂²h/∂t∂q q̇ + ∂²h/∂t²` (eq 18).
    pub gap_bias: SVector<f64, M>,
}

/// The tangential kinematics of the constraints at `(t, q, q̇)` (planar contact: one tangent per
/// constraint, along which its friction acts): the slip velocity `γ = J_T q̇ + ∂γ/∂t` and
/// `γ̇ = J_T q̈ + d_T`. The tangential force `λ_T` enters the equations as `J_Tᵀ λ_T`.
#[derive(Clone, Debug, PartialEq)]
pub struct Tangents<const N: usize, const M: usize> {
    /// `J_T`.
    pub jacobian: SMatrix<f64, M, N>,
    /// `∂γ/∂t`: the slip of the constraint's surface (a moving belt, a prescribed drive).
    pub time_rate: SVector<f64, M>,
    /// `d_T = γ̇ − J_T q̈`.
    pub bias: SVector<f64, M>,
}

impl<const N: usize, const M: usize> Evaluation<N, M> {
    /// The inertia of the motion between events, `M + K`.
    #[inline(always)]
    pub fn inertia(&self) -> SMatrix<f64, N, N> {
        self.implicit.map_or(self.mass, |k| self.mass + k)
    }
}

impl<const N: usize, const M: usize> Tangents<N, M> {
    /// `γ = J_T q̇ + ∂γ/∂t`.
    pub fn slip(&self, qd: &SVector<f64, N>) -> SVector<f64, M> {
        self.jacobian * qd + self.time_rate
    }
}

/// The uses of [`System::evaluate_terms`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Terms {
    /// A communication point read from a step ahead (the state the stepper then shows): all the terms, where a
    /// system whose outputs need more of the same may keep them.
    Point,
    /// A projection onto the held constraints: only the terms the configuration sets are read (`mass`,
    /// `implicit`, `gap`, `gap_jacobian`, `gap_time_rate`), and a system may leave `force` and `gap_bias` zero.
    Configuration,
}

/// What bounds an RK4 step from one state (`System::step_bounds`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepBounds {
    /// The largest step the motion allows, s (the stepper takes the smaller of this and
    /// `StepperOptions::step`). A system whose motion the error control cannot see (a prescribed
    /// motion, being no coordinate; a coordinate the held constraints leave alone moving at a speed
    /// RK4 follows exactly while the held ones drift) bounds it here so that the steps and their dense
    /// output follow that motion.
    pub largest: f64,
    /// The factor on the options' local-error bound (`StepperOptions::local_error`): a system whose
    /// gaps are far from closing, its motion carried by forces the gaps do not measure, may loosen it.
    pub error_scale: f64,
}

impl Default for StepBounds {
    /// No bound of the system's own: infinite, the options' error bound.
    fn default() -> Self {
        Self { largest: f64::INFINITY, error_scale: 1.0 }
    }
}

/// Where [`System::powers`] is asked.
#[derive(Clone, Copy, Debug)]
pub enum Change<'a, const N: usize, const M: usize> {
    /// Along the motion.
    Rates {
        /// `q̇`.
        v: &'a SVector<f64, N>,
        /// `q̈`.
        acc: &'a SVector<f64, N>,
        /// The held constraints' normal and tangential forces `(λ, λ_T)`.
        forces: (&'a SVector<f64, M>, &'a SVector<f64, M>),
    },
    /// A velocity jump.
    Jump {
        /// `q̇⁻`.
        before: &'a SVector<f64, N>,
        /// `q̇⁺`.
        after: &'a SVector<f64, N>,
    },
}

/// An `N`-degree-of-freedom Lagrangian system with `M` unilateral constraints, frictionless unless
/// it gives them Coulomb friction coefficients (`friction`) and tangents (`tangents`).
///
/// Inputs a host holds constant over a communication step live in the implementing type; the
/// stepper re-examines the contact state when they change (see `Stepper::system_mut`).
pub trait System<const N: usize, const M: usize> {
    /// Full evaluation at `(t, q, q̇)`; computes each trigonometric function once.
    fn evaluate(&self, t: f64, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> Evaluation<N, M>;

    /// `evaluate` for a use that reads only some of its terms (see [`Terms`]): a system may keep or leave
    /// out work there. The terms the use reads must equal `evaluate`'s.
    fn evaluate_terms(&self, t: f64, q: &SVector<f64, N>, qd: &SVector<f64, N>, _terms: Terms) -> Evaluation<N, M> {
        self.evaluate(t, q, qd)
    }

    /// The inertia of the motion `M + K` (`Evaluation::inertia`) and `f` alone: all an RK4 stage
    /// needs while no constraint is held. A system whose constraint terms cost work of their own
    /// overrides it; the result must equal `evaluate`'s.
    fn inertia_and_force(&self, t: f64, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> (SMatrix<f64, N, N>, SVector<f64, N>) {
        let ev = self.evaluate(t, q, qd);
        (ev.inertia(), ev.force)
    }

    /// Called at the start `(t, q, q̇)` of every RK4 step of length `dt`, before its stages, with
    /// the start's acceleration `q̈`: a system may prepare terms its stages share (solve a costly
    /// force law once per step), and returns whether it did: the start is then read again with
    /// them where constraints are held, so that the held forces there are the step's. What it
    /// prepares must be a function of these arguments (a step taken again from the same start is
    /// the same step). Nothing, the default.
    fn begin_step(&self, _t: f64, _state: (&SVector<f64, N>, &SVector<f64, N>, &SVector<f64, N>), _dt: f64) -> bool {
        false
    }

    /// Lengths `L_k` (m per unit of coordinate `k`) that turn a coordinate's error or speed into a
    /// displacement. With constraints held, the adaptive step bounds `|L_k δq_k|` on the motion left
    /// along them, which the gaps do not see (a coordinate turning while the held constraints leave
    /// the gaps at rest); the sliding law takes the system at rest where every `|L_k q̇_k|` is within
    /// the velocity tolerance. Zero, the default: not measured.
    fn coordinate_lengths(&self) -> SVector<f64, N> {
        SVector::zeros()
    }

    /// What bounds an RK4 step from `t` with velocities `q̇` and gaps `gaps`
    /// ([`StepBounds::default`] where nothing does beyond the options).
    fn step_bounds(&self, _t: f64, _qd: &SVector<f64, N>, _gaps: &SVector<f64, M>) -> StepBounds {
        StepBounds::default()
    }

    /// Whether the system reports [`Self::powers`] for the core to integrate. False, the default:
    /// no step evaluates them, and every total reads zero.
    const POWERS: bool = false;

    /// What the system books at `(t, q)` (asked only where [`Self::POWERS`]):
    /// - along the motion ([`Change::Rates`]), the rates of its own forces at `q̇` with the
    ///   acceleration `q̈` and the held constraints' normal and tangential forces `(λ, λ_T)` (zero in
    ///   flight), W or N, which the stepper integrates along each step with the step's own weights.
    ///   `q̈` is given because a force with an implicit part (`Evaluation::implicit`) acts, and does
    ///   work, through it; `(λ, λ_T)` because a drive acts through the contact forces too;
    /// - at a velocity jump `q̇⁻ → q̇⁺` onto held contacts ([`Change::Jump`]), what its forces take
    ///   there, J or N·s: a force with an implicit part takes an impulse at such a jump (the core
    ///   asks only where the evaluation has one; an impact acts through `M` alone and is not asked).
    fn powers(&self, _t: f64, _q: &SVector<f64, N>, _change: Change<'_, N, M>) -> Powers {
        Powers::zeros()
    }

    /// Newton's restitution coefficient `e ∈ [0, 1]`, one for every constraint: an impact's
    /// law is dissipative for any coupling of its constraints only with one `e`
    /// (`contact_laws::newton_impulses`).
    fn restitution(&self) -> f64;

    /// Coulomb friction coefficient `μ_i ≥ 0` of constraint `i`; zero, the default: frictionless
    /// (the core then takes its frictionless paths and never asks for `tangents`).
    fn friction(&self, _constraint: usize) -> f64 {
        0.0
    }

    /// The tangential kinematics at `(t, q, q̇)`; asked for only where some `friction(i) > 0`.
    fn tangents(&self, _t: f64, _q: &SVector<f64, N>, _qd: &SVector<f64, N>) -> Tangents<N, M> {
        Tangents { jacobian: SMatrix::zeros(), time_rate: SVector::zeros(), bias: SVector::zeros() }
    }
}

/// μ of each constraint, if any has friction: `None` keeps a frictionless system on the
/// frictionless paths, to the bit.
#[inline(always)]
pub(super) fn friction_of<S: System<N, M>, const N: usize, const M: usize>(sys: &S) -> Option<SVector<f64, M>> {
    let mu = SVector::<f64, M>::from_fn(|i, _| sys.friction(i));
    mu.iter().any(|&m| m != 0.0).then_some(mu)
}

/// `w` in the implicit part's channel `[0]` alone (the core's share of [`Powers`]).
#[inline(always)]
pub(super) fn implicit_share(w: f64) -> Powers {
    let mut p = Powers::zeros();
    p[0] = w;
    p
}
