//! The bounds of the crank train's adaptive RK4 steps: their size, the crank angle they span, and the
//! local error they keep.

use std::f64::consts::PI;

/// The adaptive RK4 step's largest size, s (7.2° of crank angle at 1200 rpm), and its bound on
/// the local error of each step on the corner gaps, m. Event times and velocities do not depend
/// on the step (events are located by root finding); the step follows the motion: near 1e-3 s
/// where the piston lies flat on a wall (fully constrained, no error to control), ≈ 1e-4 s in
/// flight. Over ten cycles of the default case against a 2.5 µs fixed-step reference (958
/// impacts faster than 0.1 mm/s, `tools/step_study.rs`): impact times agree to 4.6e-9 s and
/// speeds to 2.3e-4 relative, as a fixed 1e-4 s step does (4.5e-9 s, 2.8e-4) with 2.3×
/// as many RK4 steps; 1e-10 m gives 3.0e-8 s and 8.7e-4.
pub const MAX_STEP: f64 = 1e-3;
/// The crank angle one step of the prescribed crank may span, rad (7.2°: `MAX_STEP` at 1200 rpm, so
/// that slower cranks keep `MAX_STEP`); see `PrescribedCrank::step_bounds`.
pub const MAX_STEP_ANGLE: f64 = 2.0 * PI / 50.0;
/// The bound on the local error of each step on the corner gaps, m (see `MAX_STEP`).
pub const LOCAL_ERROR: f64 = 1e-11;
/// Corner gap, m, beyond which (at every corner) the film alone carries the piston: a step's local
/// error may then be [`CLEAR_ERROR_FACTOR`] times the corners' bound, and a step may carry the last
/// film solve on (`step_film`). The corners' bound would hold the film's stiff mode to steps well
/// under the τ/2 its stability allows; loosened, the film's figures stay within the grid's and τ's
/// errors (`documentation/design/lubricated_skirt.md`, "The steps' error bound away from the liner").
/// Near the liner, where the corners' events are, the corners' bound stands.
pub const CLEAR_GAP: f64 = 10e-6;
/// See [`CLEAR_GAP`].
pub const CLEAR_ERROR_FACTOR: f64 = 10.0;
