//! The generalized Newton impact law (A&K eqs 4–11, generalized per ARCHITECTURE.md §6.4) and its
//! energy balance (eqs 8–9).

use super::contact::{members, solve_lcp, Frame, Set};
use nalgebra::SVector;

/// Impulses `Λ` of an impact over the closed set `C`:
/// `Λ ≥ 0`, `ġ⁺ + e·min(ġ⁻, 0) ≥ 0`, `Λᵢ (ġ⁺ᵢ + eᵢ min(ġ⁻ᵢ, 0)) = 0`, with `ġ⁺ = ġ⁻ + W Λ`.
///
/// Closed constraints that are sliding or separating (`ġ⁻ ≥ 0`) only get an impulse if the others
/// would push them in, and then leave with `ġ⁺ ≥ 0`. With one closed constraint this is exactly
/// eq 11: `Λ = −(1 + e) ḣ⁻ / W`, the percussion `M⁻¹∇h Λ` along the gradient in the metric of `M`
/// (eq 5 keeps the M-weighted tangential velocity, so the Euclidean one jumps with inertia
/// coupling) and `ḣ⁺ = −e ḣ⁻` with `ḣ` including `∂h/∂t` (eq 7).
/// `None` is the paper's "multiple impact exception": no impulse set satisfies the law.
pub(crate) fn newton_impulses<const N: usize, const M: usize>(
    frame: &Frame<N, M>,
    hd_minus: &SVector<f64, M>,
    restitution: &SVector<f64, M>,
    closed: Set,
) -> Option<SVector<f64, M>> {
    let mut b = SVector::<f64, M>::zeros();
    for i in members::<M>(closed) {
        b[i] = hd_minus[i] + restitution[i] * hd_minus[i].min(0.0);
    }
    let scale = members::<M>(closed).fold(0.0_f64, |s, i| s.max(hd_minus[i].abs()));
    solve_lcp(&frame.w, &b, closed, scale).map(|(impulse, _)| impulse)
}

/// The energy each impulse dissipates, `−Λᵢ (ḣ⁻ᵢ + ḣ⁺ᵢ) / 2` with `ḣ = J q̇ + ∂h/∂t`: the work
/// of the contact force on the relative normal motion (eqs 8–9). For one constraint it is
/// `(1 − e²) (ḣ⁻)² / (2W) ≥ 0`. With fixed constraints the parts sum to `T⁻ − T⁺`; with moving
/// ones (a prescribed crank, the roller's walls) `T⁺ − T⁻` also holds the work `−Λᵢ ∂hᵢ/∂t` the
/// constraint's drive does through the impulse, which is not dissipated (and can exceed it).
pub(crate) fn energy_lost<const M: usize>(
    impulse: &SVector<f64, M>,
    hd_minus: &SVector<f64, M>,
    hd_plus: &SVector<f64, M>,
) -> SVector<f64, M> {
    -impulse.component_mul(&(hd_minus + hd_plus)) * 0.5
}
