//! The contact decision at an event: the impact law (the generalized Newton law, A&K eqs 4–11
//! generalized per ARCHITECTURE.md §6.4, or with friction Glocker's Newton–Coulomb law) and its energy
//! balance (eqs 8–9), and the laws of persistent contact (the sliding law, or with friction the
//! Coulomb law) with their tie rule. Each reduces to a complementarity problem
//! (`complementarity.rs`, `coulomb.rs`); `settle.rs` applies them in turn.

use super::complementarity::{contains, members, select, solve_lcp, solve_on, tie_margin, ties, Contacts, Frame, Mode, Set};
use super::coulomb::{Choice, Tangential};
use super::system::friction_of;
use super::{DynamicsError, Evaluation, System};
use nalgebra::SVector;

/// How far ahead, in nominal steps, the laws of persistent contact look to decide a tie
/// (`sliding_law`): far enough that the trend outweighs round-off, near enough that it is the
/// trend at the instant.
const TIE_PROBE: f64 = 1e-4;

/// The state `(t, q, q̇)` and the evaluation there that the laws of persistent contact reach
/// `steps` nominal steps after the current one, with `Contacts` held (one RK4 step, the caller's).
pub(super) type Probe<'a, const N: usize, const M: usize> =
    &'a dyn Fn(Contacts, f64) -> Result<(f64, SVector<f64, N>, SVector<f64, N>, Evaluation<N, M>), DynamicsError>;

/// The tolerances the laws of persistent contact decide with.
#[derive(Clone, Copy)]
pub(super) struct Tolerances {
    /// ε_ḣ: a slip slower than this is at tangential rest.
    pub velocity: f64,
    /// ε_λ: a force below this is unloaded, whatever the scale of the problem.
    pub multiplier: f64,
}

/// What an impact does: the normal and tangential impulses, the velocity and `ḣ` after, and the
/// energy each constraint's impulses dissipate.
pub(super) struct Jump<const N: usize, const M: usize> {
    pub normal: SVector<f64, M>,
    pub tangent: SVector<f64, M>,
    pub v: SVector<f64, N>,
    pub hd: SVector<f64, M>,
    pub lost: SVector<f64, M>,
    /// The part of `lost` the tangential impulses dissipate.
    pub friction_lost: SVector<f64, M>,
}

/// Impulses `Λ` of an impact over the closed set `C`: with one coefficient `e`
/// for them all, `Λ ≥ 0`, `ξ = ġ⁺ + e ġ⁻ ≥ 0`, `Λᵢ ξᵢ = 0`, with `ġ⁺ = ġ⁻ + W Λ`.
///
/// The one `e` makes the law dissipative however the constraints couple (Glocker 2013, energetic
/// consistency of Newton-type impact laws): `Λᵀξ = 0` gives `Λᵀ(ġ⁻ + ġ⁺) = −(1 − e)/(1 + e) ΛᵀWΛ
/// ≤ 0`. A coefficient per constraint is not (a held or resting one pushed by another's impulse,
/// taken with `e = 0`, would return `Λ ġ⁻/2` of energy). With one closed constraint this is
/// exactly eq 11: `Λ = −(1 + e) ḣ⁻ / W`, the percussion `M⁻¹∇h Λ` along the gradient in the metric
/// of `M` (eq 5 keeps the M-weighted tangential velocity, so the Euclidean one jumps with inertia
/// coupling) and `ḣ⁺ = −e ḣ⁻` with `ḣ` including `∂h/∂t` (eq 7).
/// `None` is the paper's "multiple impact exception": no impulse set satisfies the law.
fn newton_impulses<const N: usize, const M: usize>(
    frame: &Frame<N, M>,
    hd_minus: &SVector<f64, M>,
    restitution: f64,
    closed: Set,
) -> Option<SVector<f64, M>> {
    let mut b = SVector::<f64, M>::zeros();
    for i in members::<M>(closed) {
        b[i] = (1.0 + restitution) * hd_minus[i];
    }
    let scale = members::<M>(closed).fold(0.0_f64, |s, i| s.max(hd_minus[i].abs()));
    solve_lcp(&frame.w, &b, closed, scale).map(|(impulse, _)| impulse)
}

/// The energy each impulse dissipates, `−Λᵢ (ḣ⁻ᵢ + ḣ⁺ᵢ) / 2` with `ḣ = J q̇ + ∂h/∂t`: the work
/// of the contact force on the relative normal motion (eqs 8–9). For one constraint it is
/// `(1 − e²) (ḣ⁻)² / (2W) ≥ 0`. With fixed constraints the parts sum to `T⁻ − T⁺`; with moving
/// ones (a prescribed motion of a surface) `T⁺ − T⁻` also holds the work `−Λᵢ ∂hᵢ/∂t` the
/// constraint's drive does through the impulse, which is not dissipated (and can exceed it).
pub(super) fn energy_lost<const M: usize>(
    impulse: &SVector<f64, M>,
    hd_minus: &SVector<f64, M>,
    hd_plus: &SVector<f64, M>,
) -> SVector<f64, M> {
    -impulse.component_mul(&(hd_minus + hd_plus)) * 0.5
}

/// The impact over `closed` at `(t, q, q̇)`: the generalized Newton law, or where the system has
/// friction the Newton–Coulomb law (`coulomb.rs`), with the system's one `e` for every member.
pub(super) fn impact<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    (t, q, v): (f64, &SVector<f64, N>, &SVector<f64, N>),
    ev: &Evaluation<N, M>,
    frame: &Frame<N, M>,
    closed: Set,
) -> Result<Jump<N, M>, DynamicsError> {
    let refused = DynamicsError::MultipleImpact { time: t, constraints: closed };
    let e = sys.restitution();
    let hd = ev.gap_jacobian * v + ev.gap_time_rate;
    let Some(mu) = friction_of(sys) else {
        let impulse = newton_impulses(frame, &hd, e, closed).ok_or(refused)?;
        let hd_plus = hd + frame.w * impulse;
        let lost = energy_lost(&impulse, &hd, &hd_plus);
        return Ok(Jump {
            normal: impulse,
            tangent: SVector::zeros(),
            v: v + frame.minv_jt * impulse,
            hd: hd_plus,
            lost,
            friction_lost: SVector::zeros(),
        });
    };
    let tangents = sys.tangents(t, q, v);
    let (coulomb, _) = Tangential::at(ev, &tangents, mu).ok_or(DynamicsError::SingularMass { time: t })?;
    let slip = tangents.slip(v);
    // ξ = γ⁺ + e γ⁻ in both directions, for every member.
    let b = (hd * (1.0 + e), slip * (1.0 + e));
    let choices = std::array::from_fn(|i| if contains(closed, i) { Choice::AtRest } else { Choice::Open });
    let scale = members::<M>(closed).fold(0.0_f64, |s, i| s.max(hd[i].abs()).max(slip[i].abs()));
    let (_, mut jump) = coulomb.enumerate(&choices, (&b.0, &b.1), scale).ok_or(refused)?;
    // A normal impulse below zero is the solve's round-off, within its tolerance: none, and no
    // friction with it (else it returns energy, −1e-13 J against 1e-8 m/s approaches).
    for i in members::<M>(closed) {
        if jump.normal[i] < 0.0 {
            (jump.normal[i], jump.tangent[i]) = (0.0, 0.0);
        }
    }
    let v_plus = coulomb.motion(v, &jump);
    let hd_plus = ev.gap_jacobian * v_plus + ev.gap_time_rate;
    let lost = energy_lost(&jump.normal, &hd, &hd_plus) + energy_lost(&jump.tangent, &slip, &tangents.slip(&v_plus));
    // Friction's share: −Λ_T ξ_T / (1 + e) = μ Λ_N |ξ_T| / (1 + e) ≥ 0. With the normal share
    // (1 − e)/(2(1 + e)) ΛᵀGΛ ≥ 0 (G the Delassus operator of both directions) it makes up the
    // whole loss, as in `newton_impulses`; the work of Λ_T on the mean slip, −Λ_T (γ⁻ + γ⁺)/2,
    // can be negative where the impulses couple the normal and tangential motion. Taken as the
    // magnitude |Λ_T ξ_T|: a sticking constraint's ξ_T is zero up to round-off, whose sign would
    // otherwise make its share, and the friction books with it, −1e-19 J.
    let xi = tangents.slip(&v_plus) + slip * e;
    let friction_lost = SVector::<f64, M>::from_fn(|i, _| (jump.tangent[i] * xi[i]).abs() / (1.0 + e));
    Ok(Jump { normal: jump.normal, tangent: jump.tangent, v: v_plus, hd: hd_plus, lost, friction_lost })
}

/// The sliding law over `candidates` at `(t, q, q̇)`, with the tie rule: a candidate this
/// instant leaves undecided (zero force and zero gap acceleration together, as where a
/// contact opens, or where two contacts trade places as a body starts to pivot) takes the
/// law's answer `TIE_PROBE` nominal steps later along the motion (`probe`) with this instant's
/// support held. Every support consistent with the ties gives the same acceleration now, so the
/// motions differ at second order and any of them shows the first-order trend that decides.
/// A tie that persists there opens (the law's smallest support). With friction, the Coulomb law
/// (`coulomb_law`). Returns the contacts and q̈.
pub(super) fn sliding_law<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    tol: Tolerances,
    (t, q, v): (f64, &SVector<f64, N>, &SVector<f64, N>),
    (ev, frame): (&Evaluation<N, M>, &Frame<N, M>),
    candidates: Set,
    probe: Probe<N, M>,
) -> Result<(Contacts, SVector<f64, N>), DynamicsError> {
    if let Some(mu) = friction_of(sys) {
        return coulomb_law(sys, tol, (t, q, v), ev, mu, candidates, probe);
    }
    let eps = tol.multiplier;
    let unresolved = |time| DynamicsError::ContactUnresolved { time, constraints: candidates };
    let now = frame.sliding(ev, candidates, eps).ok_or(unresolved(t))?;
    let acc = |lambda: SVector<f64, M>| frame.free_acc + frame.minv_jt * lambda;
    if now.ties == 0 {
        return Ok((Contacts::frictionless(now.support), acc(now.lambda)));
    }
    let (_, _, _, ev_ahead) = probe(Contacts::frictionless(now.support), TIE_PROBE)?;
    let frame_ahead = Frame::new(&ev_ahead).ok_or(DynamicsError::SingularMass { time: t })?;
    let ahead = frame_ahead.sliding(&ev_ahead, candidates, eps).ok_or(unresolved(t))?;
    if ahead.support == now.support {
        return Ok((Contacts::frictionless(now.support), acc(now.lambda)));
    }
    let free = Frame::gap_acceleration(ev, &frame.free_acc);
    let lambda =
        solve_on(&frame.w, &-free, ahead.support).ok_or(DynamicsError::DependentContacts { time: t, constraints: ahead.support })?;
    Ok((Contacts::frictionless(ahead.support), acc(lambda.map(|x| x.max(0.0)))))
}

/// The velocity jump that puts `(t, q, q̇)` on the manifold of `contacts` where one sticks: `ḣ = 0`
/// on every held constraint and `γ = 0` on every sticking one, by impulses the modes allow (a
/// slipping constraint's normal impulse brings its friction along). A stick the law finds within
/// ε_ḣ of rest may still move the system: where the slip is a coordinate's speed times a lever
/// that vanishes (a dead centre of a linkage), a creeping coordinate held at γ̇ = 0 would have to
/// speed up as the lever shrinks. The tangential impulse stops that motion (an impact without
/// collision); what it dissipates is friction's. `None` without friction, without a stick, or
/// where the rows disagree (dependent): the normal projection alone is then left to the caller.
pub(super) fn stick_jump<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    tol: Tolerances,
    (t, q, v): (f64, &SVector<f64, N>, &SVector<f64, N>),
    ev: &Evaluation<N, M>,
    contacts: Contacts,
) -> Option<Jump<N, M>> {
    let mu = friction_of(sys)?;
    if contacts.stick & contacts.held == 0 {
        return None;
    }
    let tangents = sys.tangents(t, q, v);
    let (frame, _) = Tangential::at(ev, &tangents, mu)?;
    let lengths = sys.coordinate_lengths();
    let frame = frame.wedging((0..N).all(|k| (v[k] * lengths[k]).abs() <= tol.velocity));
    let (hd, slip) = (ev.gap_jacobian * v + ev.gap_time_rate, tangents.slip(v));
    let modes = std::array::from_fn(|i| contacts.mode(i));
    let jump = frame.solve(&modes, (&hd, &slip))?;
    let v_plus = frame.motion(v, &jump);
    let (hd_plus, slip_plus) = (ev.gap_jacobian * v_plus + ev.gap_time_rate, tangents.slip(&v_plus));
    // The loss, ½ΛᵀGΛ plus a slipping constraint's friction work (≥ 0: every row the jump zeroes
    // ends at ξ = 0), is what stopping the slip took, the normal rows being at rest within ε_ḣ
    // already: friction's, put on the first sticking constraint, since the works of the single
    // impulses −Λᵢ(uᵢ⁻ + uᵢ⁺)/2 need not each be ≥ 0.
    let total = (energy_lost(&jump.normal, &hd, &hd_plus) + energy_lost(&jump.tangent, &slip, &slip_plus)).sum();
    let first = (contacts.stick & contacts.held).trailing_zeros() as usize;
    let lost = SVector::<f64, M>::from_fn(|i, _| if i == first { total.max(0.0) } else { 0.0 });
    Some(Jump { normal: jump.normal, tangent: jump.tangent, v: v_plus, hd: hd_plus, lost, friction_lost: lost })
}

/// The sliding law with Coulomb friction (`coulomb.rs`): the modes of the candidates by
/// enumeration, a candidate slipping faster than ε_ḣ keeping its direction, one slower
/// sticking or starting to slip as its tangential row decides; ties in the normal direction
/// by the same rule as without friction.
fn coulomb_law<S: System<N, M>, const N: usize, const M: usize>(
    sys: &S,
    tol: Tolerances,
    (t, q, v): (f64, &SVector<f64, N>, &SVector<f64, N>),
    ev: &Evaluation<N, M>,
    mu: SVector<f64, M>,
    candidates: Set,
    probe: Probe<N, M>,
) -> Result<(Contacts, SVector<f64, N>), DynamicsError> {
    let at = |t: f64, q: &SVector<f64, N>, v: &SVector<f64, N>, ev: &Evaluation<N, M>| {
        let tangents = sys.tangents(t, q, v);
        let (frame, free) = Tangential::at(ev, &tangents, mu).ok_or(DynamicsError::SingularMass { time: t })?;
        let lengths = sys.coordinate_lengths();
        let frame = frame.wedging((0..N).all(|k| (v[k] * lengths[k]).abs() <= tol.velocity));
        let b = (Frame::gap_acceleration(ev, &free), tangents.jacobian * free + tangents.bias);
        let scale = members::<M>(candidates).fold(0.0_f64, |s, i| {
            s.max((ev.gap_jacobian.row(i) * free)[0].abs() + ev.gap_bias[i].abs())
                .max((tangents.jacobian.row(i) * free)[0].abs() + tangents.bias[i].abs())
        });
        Ok::<_, DynamicsError>((frame, free, b, scale, tangents.slip(v)))
    };
    let unresolved = DynamicsError::ContactUnresolved { time: t, constraints: candidates };
    let (frame, free, b, scale, slip) = at(t, q, v, ev)?;
    let choices = std::array::from_fn(|i| match (contains(candidates, i), slip[i]) {
        (false, _) => Choice::Open,
        (true, g) if g.abs() <= tol.velocity => Choice::AtRest,
        (true, g) => Choice::Slipping(g.signum()),
    });
    let (modes, now) = frame.enumerate(&choices, (&b.0, &b.1), scale).ok_or(unresolved.clone())?;
    let contacts = Contacts::of(&modes);
    let w = Frame::new(ev).ok_or(DynamicsError::SingularMass { time: t })?.w;
    // A stick at the edge of its cone is a tie too: the slip it may start has no acceleration
    // yet, and the event search, which locates the edge to within ε_λ, would find it crossed at
    // once and return here with nothing changed.
    let (edge, w_max) = tie_margin(&w, candidates, scale, tol.multiplier);
    let at_edge = select::<M>(|i| contains(contacts.stick, i) && mu[i] * now.normal[i] - now.tangent[i].abs() <= edge);
    // So is a slip the law starts from rest with no acceleration yet: the motion, not the sign
    // of a round-off γ̇, decides its way.
    let unstarted =
        select::<M>(|i| choices[i] == Choice::AtRest && matches!(modes[i], Mode::Slip(_)) && now.y_tangent[i].abs() <= edge * w_max);
    let tied = ties(&w, (&now.normal, &now.y_normal), (candidates, contacts.held), scale, tol.multiplier) | at_edge | unstarted;
    if tied == 0 {
        return Ok((contacts, frame.motion(&free, &now)));
    }
    let (t_ahead, q_ahead, v_ahead, ev_ahead) = probe(contacts, TIE_PROBE)?;
    let (frame_ahead, _, b_ahead, scale_ahead, _) = at(t_ahead, &q_ahead, &v_ahead, &ev_ahead)?;
    let (ahead, _) = frame_ahead.enumerate(&choices, (&b_ahead.0, &b_ahead.1), scale_ahead).ok_or(unresolved)?;
    if Contacts::of(&ahead) == contacts {
        return Ok((contacts, frame.motion(&free, &now)));
    }
    let dependent = DynamicsError::DependentContacts { time: t, constraints: Contacts::of(&ahead).held };
    let mut then = frame.solve(&ahead, (&b.0, &b.1)).ok_or(dependent)?;
    then.normal = then.normal.map(|x| x.max(0.0));
    for i in 0..M {
        if let Mode::Slip(s) = ahead[i] {
            then.tangent[i] = -mu[i] * s * then.normal[i];
        }
    }
    Ok((Contacts::of(&ahead), frame.motion(&free, &then)))
}
