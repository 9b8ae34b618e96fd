//! What the core integrates: the system's interface and the terms it evaluates.

use nalgebra::{SMatrix, SVector};

/// Rates a system reports along the motion (`System::powers`) and their integrals, which the core
/// keeps with every step's own weights and carries across events alike, in up to eight channels the
/// system names (W and J, or N and N·s for a force it reports). One is the core's own: `[0]` holds
/// the power the system's force made linearly implicit through `M` takes from the motion
/// (`System::absorbs`), and the core adds to it the share projected contacts take over from that force.
pub type Powers = SVector<f64, 8>;

/// Everything one RK4 stage, one impact or one sliding solve needs, evaluated at `(t, q, q̇)`.
///
/// Conventions (A&K eqs 1, 2, 16, 18): `ḣ = J q̇ + ∂h/∂t` and `ḧ = J q̈ + d`, with `J = ∂h/∂q`.
/// With `h` a distance in metres and `M q̈ = f + Jᵀ λ`, the multiplier `λ` is the normal contact force.
#[derive(Clone, Debug, PartialEq)]
pub struct Evaluation<const N: usize, const M: usize> {
    /// `M(q,t)`: symmetric, positive definite inertia matrix.
    pub mass: SMatrix<f64, N, N>,
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

impl<const N: usize, const M: usize> Tangents<N, M> {
    /// `γ = J_T q̇ + ∂γ/∂t`.
    pub fn slip(&self, qd: &SVector<f64, N>) -> SVector<f64, M> {
        self.jacobian * qd + self.time_rate
    }
}

/// An `N`-degree-of-freedom Lagrangian system with `M` unilateral constraints, frictionless unless
/// it gives them Coulomb friction coefficients (`friction`) and tangents (`tangents`).
///
/// Inputs a host holds constant over a communication step live in the implementing type; the
/// stepper re-examines the contact state when they change (see `Stepper::system_mut`).
pub trait System<const N: usize, const M: usize> {
    /// Full evaluation at `(t, q, q̇)`; computes each trigonometric function once.
    fn evaluate(&self, t: f64, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> Evaluation<N, M>;

    /// `evaluate` at a communication point read from a step ahead (the state the stepper then
    /// shows): a system whose outputs need more of the same terms may keep them here. The result
    /// must equal `evaluate`'s.
    fn evaluate_point(&self, t: f64, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> Evaluation<N, M> {
        self.evaluate(t, q, qd)
    }

    /// `M` and `f` alone: all an RK4 stage needs while no constraint is held. A system whose
    /// constraint terms cost work of their own overrides it; the result must equal `evaluate`'s.
    fn inertia_and_force(&self, t: f64, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> (SMatrix<f64, N, N>, SVector<f64, N>) {
        let ev = self.evaluate(t, q, qd);
        (ev.mass, ev.force)
    }

    /// Called at the start `(t, q, q̇)` of every RK4 step of length `dt`, before its stages, with
    /// the start's acceleration `q̈`: a system may prepare terms its stages share (the lubricated
    /// skirt solves its film here, once per step). What it prepares must be a function of these
    /// arguments (a step taken again from the same start is the same step). Nothing, the default.
    fn begin_step(&self, _t: f64, _state: (&SVector<f64, N>, &SVector<f64, N>, &SVector<f64, N>), _dt: f64) {}

    /// Lengths `L_k` (m per unit of coordinate `k`) that turn an error of coordinate `k` into a
    /// displacement of the mechanism. With constraints held, the adaptive step bounds `|L_k δq_k|`
    /// on the motion left along them, which the gaps do not see (a crank turning while the piston
    /// slides flat on the liner). Zero, the default: not measured.
    fn coordinate_lengths(&self) -> SVector<f64, N> {
        SVector::zeros()
    }

    /// The largest RK4 step the motion allows at `t` with velocities `q̇`, s (the stepper takes the
    /// smaller of this and `StepperOptions::step`). A system whose motion the error control cannot
    /// see (a prescribed motion, being no coordinate; a coordinate the held constraints leave alone
    /// moving at a speed RK4 follows exactly while the held ones drift) bounds it here so that the
    /// steps and their dense output follow that motion. Infinite, the default: no bound of its own.
    fn largest_step(&self, _t: f64, _qd: &SVector<f64, N>) -> f64 {
        f64::INFINITY
    }

    /// The bound on the local error of a step starting where the gaps are `gaps`, m, given the
    /// options' bound `nominal` (`StepperOptions::local_error`): a system whose gaps are far from
    /// closing, its motion carried by forces the gaps do not measure, may loosen it. `nominal`, the
    /// default.
    fn local_error(&self, nominal: f64, _gaps: &SVector<f64, M>) -> f64 {
        nominal
    }

    /// Whether the system has a force made linearly implicit through `M` (a lubricating film's,
    /// see [`Self::powers`]), whose power [`Powers`]`[0]` holds. False, the default: the core takes
    /// its paths as without one.
    fn absorbs(&self) -> bool {
        false
    }

    /// Whether the system reports [`Self::powers`] for the core to integrate; an absorbing system
    /// must. False, the default: no step evaluates them, and every total reads zero.
    const POWERS: bool = false;

    /// The rates the system reports at `(t, q, q̇)` with the acceleration `q̈` and the held
    /// constraints' normal and tangential forces `(λ, λ_T)` (zero in flight): the power of its own
    /// forces (a drive's, say, which acts through the contact forces too), and, where it absorbs,
    /// `[0]`. `q̈` is given because a force made linearly implicit through `M` (a stiff damper `−D q̇`
    /// applied as `−D (q̇ + τ q̈)`, its `τ D` added to the inertia) does work, and acts, through it.
    /// The stepper integrates them along each step with the step's own weights; asked for only
    /// where [`Self::POWERS`].
    fn powers(
        &self,
        _t: f64,
        _state: (&SVector<f64, N>, &SVector<f64, N>, &SVector<f64, N>),
        _forces: (&SVector<f64, M>, &SVector<f64, M>),
    ) -> Powers {
        Powers::zeros()
    }

    /// The inertia an impact acts through at `(t, q, q̇)`, the evaluation there `ev`: `ev.mass`, the
    /// default. A system that adds to its inertia a force made linearly implicit (a stiff damper's
    /// `τ D`, see [`Self::powers`]) returns its inertia without it: that force is finite, so
    /// it takes no impulse in an instantaneous impact. (Through `M + τ D`, Newton's law dissipates
    /// in that metric, not in the kinetic energy's: where D turns between impacts, as on a piston
    /// rocking between two corners on a thin film, each impact can feed the motion.)
    fn impact_mass(&self, _t: f64, _q: &SVector<f64, N>, _qd: &SVector<f64, N>, ev: &Evaluation<N, M>) -> SMatrix<f64, N, N> {
        ev.mass
    }

    /// The work those forces take from a velocity jump `q̇⁻ → q̇⁺` at `(t, q)` through the
    /// evaluation's inertia (a projection onto held contacts; an impact acts through
    /// [`Self::impact_mass`] and is not asked), J, and the impulses of the reported forces, N·s: a
    /// force implicit in `q̈` takes an impulse at such a jump.
    /// Asked for only where [`Self::absorbs`].
    fn absorbed_by_jump(&self, _t: f64, _q: &SVector<f64, N>, _before: &SVector<f64, N>, _after: &SVector<f64, N>) -> Powers {
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

/// `w` in the absorbed channel `[0]` alone (the core's share of [`Powers`]).
#[inline(always)]
pub(super) fn absorbed(w: f64) -> Powers {
    let mut p = Powers::zeros();
    p[0] = w;
    p
}
