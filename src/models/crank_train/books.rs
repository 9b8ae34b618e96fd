//! The rates the crank train reports to the core (`System::powers`), which the core integrates
//! along the motion into the totals of the energy books: the film's channels (the core's absorbed
//! channel first), then the drive's, the gas's and the joint damping's power.

use crate::dynamics::Powers;
use nalgebra::Vector4;

/// All the lubricated skirt takes from the motion (film, asperities, their friction), W.
pub const FILM: usize = 0;
/// The skirt's axial friction, a share of [`FILM`], W.
pub const SKIRT_FRICTION: usize = 1;
/// The lateral push of the film and asperities on [anti-thrust, thrust] wall, N.
pub const WALL_PUSH: [usize; 2] = [2, 3];
/// The power of the crank's drive (prescribed crank) or of its load torque (free crank), W.
pub const DRIVE: usize = 4;
/// The power of the gas on the crown, W.
pub const GAS: usize = 5;
/// The joint damping's dissipation rate, ≥ 0, W.
pub const DAMPING: usize = 6;

/// The channels of the film's rates `film` ([`FILM`] to [`WALL_PUSH`]) and of the drive's, the
/// gas's and the damping's power.
#[inline(always)]
pub fn powers(film: &Vector4<f64>, drive: f64, gas: f64, damping: f64) -> Powers {
    let mut p = Powers::zeros();
    p.fixed_rows_mut::<4>(FILM).copy_from(film);
    [p[DRIVE], p[GAS], p[DAMPING]] = [drive, gas, damping];
    p
}
