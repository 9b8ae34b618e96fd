//! The generalized Newton impact law (A&K eqs 4–11, generalized per DESIGN.md §6.4) and its
//! energy balance (eqs 8–9).

use super::contact::{members, solve_lcp, Frame, Set};
use nalgebra::{SMatrix, SVector};

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

/// The kinetic energy each impulse removes, `−Λᵢ Jᵢ (q̇⁻ + q̇⁺) / 2`. The parts sum to
/// `T⁻ − T⁺` (eq 8) because `q̇⁺ − q̇⁻ = M⁻¹ Jᵀ Λ`; for one stationary constraint the part is
/// eq 9, `(1 − e²) (ḣ⁻)² / (2W)`. With a moving constraint it can be negative (the wall does work).
pub(crate) fn energy_lost<const N: usize, const M: usize>(
    jacobian: &SMatrix<f64, M, N>,
    impulse: &SVector<f64, M>,
    v_minus: &SVector<f64, N>,
    v_plus: &SVector<f64, N>,
) -> SVector<f64, M> {
    let mean_rate = jacobian * (v_minus + v_plus) * 0.5;
    -impulse.component_mul(&mean_rate)
}
