//! What goes into and comes out of a skirt evaluation.

use super::reynolds::EdgeFlows;
use super::{Fill, Shear};
use nalgebra::{Matrix2, Matrix2x3, Matrix4x3, Vector2};

/// The skirt's motion relative to the liner, in the crank train's coordinates.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SkirtMotion {
    /// Lateral position x of the pin O3, m: +x toward the major-thrust wall, 0 centred in the bore.
    pub lateral: f64,
    /// Tilt φ3 of the piston axis, rad, the linkage's sign (e(φ3) = (−sin φ3, cos φ3)).
    pub tilt: f64,
    /// ẋ of the pin, m/s.
    pub lateral_rate: f64,
    /// φ̇3, rad/s.
    pub tilt_rate: f64,
    /// Axial velocity of the piston along the cylinder axis, m/s, + away from the crank (the linkage's y).
    pub sliding_speed: f64,
}

/// What the film and the asperities do to the piston at one motion, and their linearisation in the rates.
///
/// Forces are generalized forces on the piston conjugate to the pin's lateral position x and the tilt φ3
/// (virtual work `Σ p·δh` over the skirt): the pressure `p` pushes the surfaces apart.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SkirtLoads {
    /// Lateral force on the piston along +x, N: film and asperities, both sides.
    pub lateral_force: f64,
    /// Moment on the piston about the pin, N·m, conjugate to φ3 (film and asperities, both sides).
    pub moment: f64,
    /// −∂(lateral_force, moment)/∂(lateral_rate, tilt_rate) at fixed position and sliding speed, in
    /// (N·s/m, N·s, N·m·s/m, N·m·s): exact for the solved cavitation set (`gᵀA⁻¹g` from the same
    /// factorisation, g the loads' weights per node), symmetric.
    pub damping: Matrix2<f64>,
    /// Axial force on the piston, N, + away from the crank: the film's shear on the skirt, the axial
    /// component of its pressure on the profiled skirt, and boundary friction on the asperity load.
    pub friction_force: f64,
    /// Moment about the pin, N·m, conjugate to φ3, of the axial `friction_force` acting at the skirt surface.
    pub friction_moment: f64,
    /// Net hydrodynamic lateral force along +x, N (both sides).
    pub film_force: f64,
    /// Total asperity load, N, both sides (≥ 0).
    pub asperity_force: f64,
    /// The elastic energy the asperities store, J, both sides (≥ 0): the loads' potential, the work
    /// the asperity load would do as the skirt leaves the liner (`Asperity::energy`; below the film's
    /// floor the load is the floor's, so the energy grows linearly there).
    pub asperity_energy: f64,
    /// Couette dissipation of the film, W (≥ 0): `∫ μ V² / h` over the wetted skirt.
    pub shear_power: f64,
    /// Poiseuille dissipation of the film, W (≥ 0): `∫ h³/(12μ) |∇p|²`, which equals the power the
    /// pressure takes from the lateral and tilt motion (squeeze) plus the sliding's wedge work on it.
    /// `shear_power + squeeze_power` is the power the film takes from the piston's motion.
    pub squeeze_power: f64,
    /// Power of boundary friction on the asperity load, W (≥ 0).
    pub asperity_friction_power: f64,
    /// `−∂friction_force/∂sliding_speed` of the boundary friction, N·s/m: `μ_b W / BOUNDARY_SLIP`
    /// while |V| < `BOUNDARY_SLIP` (the friction linear in V there), 0 beyond.
    pub boundary_damping: f64,
    /// Smallest film thickness per side, m: [thrust (+x), anti-thrust (−x)].
    pub min_film: [f64; 2],
    /// Each wall's lateral push on the piston, N, [thrust, anti-thrust]: film and asperities on that
    /// side, the thrust wall's along −x and the anti-thrust wall's along +x, so that
    /// `lateral_force = wall_push[1] − wall_push[0]` (≥ 0 where the side's pressure is).
    pub wall_push: Vector2<f64>,
    /// `∂wall_push/∂(lateral_rate, tilt_rate)` at fixed position and sliding speed, rows by wall
    /// (the film's; the asperities' load depends on the position alone): the walls' shares of
    /// `damping`, whose first row is `wall_push_rates` row 0 − row 1.
    pub wall_push_rates: Matrix2<f64>,
    /// Each side's moment on the piston about the pin, N·m, conjugate to φ3, [thrust, anti-thrust]:
    /// film and asperities on that side, `moment`'s shares (a push P at a height z above the pin
    /// gives P z on the thrust side, −P z on the anti-thrust side).
    pub wall_moment: Vector2<f64>,
    /// Band Cholesky factorisations per side (active-set steps): the evaluation's cost.
    pub factorisations: [usize; 2],
}

/// The film solved at one motion (`Skirt::linearise`): for that position and cavitation set the
/// pressure is linear in the right-hand side, i.e. in the rates r = (ẋ, φ̇3, V) (squeeze and
/// wedge), and so are its loads, `(F, M, F_a, M_a) = −gram · r` exactly.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FilmLinear {
    /// The motion solved at.
    pub at: SkirtMotion,
    /// `gᵀ A⁻¹ b_c` summed over both sides: rows g the pressure's weights in (F, M, F_a, M_a) (minus
    /// the extra right-hand sides: ∂b/∂ẋ, ∂b/∂φ̇3, ∂b/∂V and the axial moment's), columns b_c the
    /// right-hand side per unit rate. Its upper-left 2 × 2 is the damping, its upper 3 × 3 the
    /// Poiseuille dissipation's quadratic form; symmetric there.
    pub gram: Matrix4x3<f64>,
    /// Each side's share of `gram`'s first row, [thrust, anti-thrust]: minus its pressure's lateral
    /// force per unit rate. The two rows sum to `gram`'s first.
    pub lateral_by_side: Matrix2x3<f64>,
    /// Each side's share of `gram`'s second row, [thrust, anti-thrust]: minus its pressure's moment
    /// about the pin per unit rate. The two rows sum to `gram`'s second.
    pub moment_by_side: Matrix2x3<f64>,
    /// Per side, the film nodes (node order; false: cavitated).
    pub free: [Vec<bool>; 2],
    /// Both sides' Couette shear sums at the solve's pose and their gradient there.
    pub shear: Shear,
    /// Band Cholesky factorisations per side.
    pub factorisations: [usize; 2],
    /// Mass-conserving cavitation: the fill fraction the solve took; empty under the Reynolds condition.
    pub fill: Fill,
    /// The fill's rate at the solve's rates, 1/s (`skirt/fill.rs`); empty under the Reynolds condition.
    pub fill_rate: Fill,
    /// The fill's decay, 1/s: each node's own outflow per unit fill over its oil volume (`skirt/fill.rs`).
    pub fill_decay: Fill,
    /// A limited supply: per side, the oil on the liner just ahead of the leading edge per column, m
    /// (`supply::Liner::ahead`); empty when flooded.
    pub supply: [Vec<f64>; 2],
    /// A limited supply: per side, the flows out of the film's edges at the solve's rates, m³/s.
    pub edges: [EdgeFlows; 2],
    /// Mass-conserving cavitation: per side, each node's film h at the solve and its rate ḣ at the
    /// solve's rates, m and m/s (node order); empty under the Reynolds condition.
    pub gaps: [Vec<(f64, f64)>; 2],
    /// Mass-conserving cavitation: the oil the film holds at the solve, `Σ θ h ΔA` over both sides'
    /// nodes, m³.
    pub content: f64,
    /// An elastic skirt: per side, its deflection away from the liner at the solve on the closed grid
    /// (nodes and edges, row-major by axial line: `(nz + 2)` rows of `(nx + 2)`), m, held by the
    /// evaluations this solve serves; empty for a rigid skirt.
    pub deflection: [Vec<f64>; 2],
    /// The largest film pressure of the solve at its own rates, both sides, Pa.
    pub peak_pressure: f64,
}

impl FilmLinear {
    /// The fill `dt` (s) after this solve ([`Fill::advanced`]); empty under the Reynolds condition.
    pub fn fill_after(&self, dt: f64) -> Fill {
        self.fill.advanced((&self.fill_rate, &self.fill_decay), dt)
    }
}

/// One side's pressure field on its grid, for plots.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SideMap {
    /// Circumferential node angles θ from +x, rad.
    pub angle: Vec<f64>,
    /// Axial node positions from the skirt's top edge, m (0 at the top, the skirt length at the bottom).
    pub position: Vec<f64>,
    /// Film pressure per node, Pa, row-major by axial position: `pressure[j * angle.len() + i]`.
    pub pressure: Vec<f64>,
    /// Asperity pressure per node, Pa, same layout.
    pub asperity_pressure: Vec<f64>,
    /// Film thickness per node, m, same layout.
    pub film: Vec<f64>,
}

/// Both sides' fields: [thrust (+x), anti-thrust (−x)].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PressureMap {
    /// Thrust, anti-thrust.
    pub sides: [SideMap; 2],
}
