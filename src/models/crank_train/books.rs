//! The rates the crank train reports to the core (`System::powers`), which the core integrates
//! along the motion into the totals of the energy books: the film's channels (the core's implicit
//! channel first), then the drive's, the gas's and the joint damping's power.

use crate::dynamics::Powers;
use nalgebra::SVector;

/// The work rate the lubricated skirt's implicit term `−τ Gᵀ D (G φ̈ + Ġ φ̇)` (with the boundary
/// friction's) takes from the motion, W: the core's channel (`dynamics::Powers`). No dissipation:
/// while D holds it is the rise of `½ τ vᵀ D v` (v the lateral and tilt rates), and as D grows under
/// a moving skirt it gives `½ τ vᵀ Ḋ v` back.
pub const IMPLICIT: usize = 0;
/// What the film, the asperities and their friction take from the motion at the rates of the
/// instant, W (the asperities' share less their stored energy's rise is the film's dissipation).
pub const FILM: usize = 1;
/// The skirt's axial friction, a share of [`FILM`], W.
pub const SKIRT_FRICTION: usize = 2;
/// The lateral push of the film and asperities on [anti-thrust, thrust] wall, N.
pub const WALL_PUSH: [usize; 2] = [3, 4];
/// The power of the crank's drive (prescribed crank) or of its load torque (free crank), W.
pub const DRIVE: usize = 5;
/// The power of the gas on the crown, W.
pub const GAS: usize = 6;
/// The joint damping's dissipation rate, ≥ 0, W.
pub const DAMPING: usize = 7;

/// The skirt's rates in the order of the channels [`IMPLICIT`] to [`WALL_PUSH`].
pub type SkirtRates = SVector<f64, 5>;

/// The channels of the skirt's rates `skirt` and of the drive's, the gas's and the damping's power.
#[inline(always)]
pub fn powers(skirt: &SkirtRates, drive: f64, gas: f64, damping: f64) -> Powers {
    let mut p = Powers::zeros();
    p.fixed_rows_mut::<5>(IMPLICIT).copy_from(skirt);
    [p[DRIVE], p[GAS], p[DAMPING]] = [drive, gas, damping];
    p
}
