//! The implicit part of a stiff force (`Evaluation::implicit`), in one place: a damper `−D q̇`
//! applied as `−D (q̇ + τ q̈)`, its `K = τ D` beside the inertia `M`.
//!
//! - Between events the motion takes `M + K` (`Evaluation::inertia`): a mode `m v̇ = −c v` relaxes at
//!   `−c/(m + τ c) ≥ −1/τ`, inside RK4's stability region at steps up to τ however large c.
//! - An impact takes `M` alone ([`for_impact`]): the force is finite and takes no impulse in an
//!   instant. (Through `M + K`, Newton's law would dissipate in that metric, not in the kinetic
//!   energy's: where D turns between impacts each impact could feed the motion.)
//! - A held motion whose contact problem has no solution through `M + K` is held with `K` projected
//!   off the held normals ([`Projected`], below).
//! - The system books the work of `−K q̈` with its other rates (`System::powers`); the core adds the
//!   share projected contacts take over from it ([`Projected::taken`], [`Projected::by_jump`]).
//!
//! The projection. Through `M + K` the contact problem is the implicit term's, not the motion's: where
//! `K` ≫ `M` along the held normals, `W_NN = J (M + K)⁻¹ Jᵀ` shrinks with `K` while friction's coupling
//! `W_NT` keeps its share, and the slipping contact problem can have no non-negative solution at
//! a friction far below the critical one (Painlevé's paradox made by a numerical
//! device). Along a held normal the rate is the constraint's, so the damper is not stiff there:
//! the implicit term is needed only in the motions the held contacts leave free. With `P` the
//! `M`-orthogonal projector onto `ker J_H` and `a_p = −M⁻¹ J_Hᵀ W⁻¹ d_H` the acceleration the held
//! gaps impose (every held `q̈` is `a_p + P q̈`), the held motion takes
//!
//! `(M + Pᵀ K P) q̈ = f − Pᵀ K a_p + J_Hᵀ λ + J_Tᵀ λ_T`:
//!
//! the implicit force `−Pᵀ K q̈` instead of `−K q̈`, the difference `(I − Pᵀ) K q̈` (along `J_Hᵀ`)
//! taken by the contact force. Since `P M⁻¹ J_Hᵀ = 0`, `(M + Pᵀ K P)⁻¹ J_Hᵀ = M⁻¹ J_Hᵀ`: the held
//! rows' `W_NN` and `W_NT` are those of `M` alone, whose friction a well-posed system keeps below its
//! critical coefficient. Without friction the motion is the one through `M + K`; only the normal
//! force leaves out the implicit term's normal share.
//!
//! `projection.rs` holds the projection and the impact's evaluation; `held.rs` the stepper's decisions where an
//! implicit part acts: the laws' fallback to the projection, the jumps onto held contacts and their books, the
//! held step's totals on its path, the search's reading of the path's middle.

mod held;
mod projection;

pub(super) use held::{on_path_totals, stages_off_path};
pub(super) use projection::{for_impact, Projected};
