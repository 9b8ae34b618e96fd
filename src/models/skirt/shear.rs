//! The film's Couette shear on a side's closed grid, and its first-order change with the pose.
//!
//! The shear's axial force and moment are `−μV` times sums over the wetted skirt of `fill/h` (and that
//! times the arm about the pin), `fill·h` the film's content carried along the liner's motion. The
//! sums depend on the pose (lateral position, tilt) and on the direction of V alone, so a film solve
//! walks them once with their gradient in the pose ([`walk`]), and the evaluations of the steps it
//! serves take them to first order ([`Shear::sums_at`]): within the moves a solve serves (a few per
//! cent of the film, `step_film::CARRY_MOVE`), the error is second order, ≈ (move / film)².

use nalgebra::{Matrix2, Vector2};

/// A row's terms at one pose: (a, b) of h = a + b cos θ + ov(θ), (α, β) of ∂h/∂φ3 = α + β cos θ,
/// the height z above the pin and the skirt radius r there.
pub(super) type RowTerms = ((f64, f64), (f64, f64), f64, f64);

/// A side's wetting at a solve: its nodes' film set, fill and a limited supply's oil (see [`walk`]).
pub(super) type Wetted<'a> = (&'a [bool], &'a [f64], &'a [f64]);

/// Both sides' shear sums at a pose and their gradient there.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Shear {
    /// The pose walked at: (lateral position, m; tilt, rad).
    pub at: Vector2<f64>,
    /// Whether the oil was carried along +u (V ≥ 0): the walk's direction.
    pub forward: bool,
    /// `Σ w fill/h ΔA` (m) and `Σ w fill/h arm ΔA` (m²): times −μV the axial force and its moment.
    pub sums: Vector2<f64>,
    /// `∂sums/∂(lateral, tilt)`, rows by sum.
    pub gradient: Matrix2<f64>,
}

impl Shear {
    /// Whether a motion of sliding speed `v` at `pose` may take these sums to first order: V in the
    /// walk's direction (or 0) and the pose within `reach` (m) of the walk's, measured as a node's
    /// largest film change (lateral move plus `arm` times the tilt change).
    pub fn serves(&self, v: f64, pose: Vector2<f64>, arm: f64, reach: f64) -> bool {
        let moved = (pose[0] - self.at[0]).abs() + arm * (pose[1] - self.at[1]).abs();
        (v == 0.0 || (v > 0.0) == self.forward) && moved <= reach
    }

    /// The sums at `pose` to first order.
    pub fn sums_at(&self, pose: Vector2<f64>) -> Vector2<f64> {
        self.sums + self.gradient * (pose - self.at)
    }
}

/// A side's shear sums at the pose of `rows` (the closed grid's rows, [`RowTerms`]) and, with
/// `GRADIENT`, their gradient in (lateral, tilt): `columns` the closed columns' (cos θ, ovality
/// term) and the skirt's deflection on the closed grid (row-major; empty: rigid), held as the pose
/// moves, `free` the interior nodes' film set, `fill` their fill fraction (node order; empty under
/// the Reynolds condition) and `supply` a limited supply's oil ahead of the upstream edge per interior
/// column (empty: flooded), `forward` the oil's direction, `floor` the film the Reynolds solve takes at
/// least, `tilt` (sin φ3, cos φ3), `area` a cell's area.
///
/// Under the Reynolds condition oil fills a cavitated point as far as the film carried into it along
/// the liner's motion allows: at a rupture the pressure flow vanishes, so the Couette flux V·h_r/2 goes
/// on as streamers filling h_r/h of a thicker gap. The mass-conserving film knows its content at each
/// node, θ h (θ held at the solve's as the pose moves). The upstream edge is flooded, or with a
/// limited supply holds `min(l, h)` of the liner's oil l (the edge columns take their neighbours'). The shear acts on
/// the filled part, with the trapezoid weights of the closed grid.
#[allow(clippy::too_many_arguments)]
pub(super) fn walk<const GRADIENT: bool>(
    rows: &[RowTerms],
    (columns, deflection): (&[(f64, f64)], &[f64]),
    (free, fill, supply): Wetted,
    forward: bool,
    floor: f64,
    tilt: (f64, f64),
    pin_offset: f64,
    area: f64,
) -> (Vector2<f64>, Matrix2<f64>) {
    let (nx, nz) = (columns.len() - 2, rows.len() - 2);
    let (s3, c3) = tilt;
    let (mut sums, mut gradient) = (Vector2::zeros(), Matrix2::zeros());
    for (ii, &(c, ov)) in columns.iter().enumerate() {
        // The film's content `fill·h` is min(carried, h), and `fill/h` is `carried/h²`: the chain
        // from node to node is a min, one division off it. `d…` are gradients in (lateral, tilt).
        let (mut carried, mut d_carried) = (f64::INFINITY, [0.0; 2]);
        let (mut force, mut moment) = (0.0, 0.0);
        let (mut d_force, mut d_moment) = ([0.0; 2], [0.0; 2]);
        for step in 0..nz + 2 {
            let jj = if forward { step } else { nz + 1 - step };
            let ((a, b), (alpha, beta), z, r) = rows[jj];
            let rigid = a + b * c + ov;
            let raw = if deflection.is_empty() { rigid } else { rigid + deflection[jj * (nx + 2) + ii] };
            let h = raw.max(floor);
            let inside = ii > 0 && ii <= nx && jj > 0 && jj <= nz;
            let d_h = if GRADIENT && raw > floor { [-c, alpha + beta * c] } else { [0.0; 2] };
            let theta = if inside { fill.get((jj - 1) * nx + ii - 1) } else { None };
            if let Some(&theta) = theta {
                (carried, d_carried) = (theta * h, d_h.map(|d| theta * d));
            } else if let (0, Some(&oil)) = (step, supply.get(ii.clamp(1, nx) - 1)) {
                (carried, d_carried) = if oil < h { (oil, [0.0; 2]) } else { (h, d_h) };
            } else if step == 0 || (inside && free[(jj - 1) * nx + ii - 1]) || h < carried {
                (carried, d_carried) = (h, d_h);
            }
            let weight = closed_weight(jj, nz);
            let unit = carried / (h * h) * weight;
            let arm = arm(z, r, c, tilt, pin_offset);
            force += unit;
            moment += unit * arm;
            if GRADIENT {
                let d_arm = [0.0, -z * c3 - (r * c - pin_offset) * s3];
                for k in 0..2 {
                    let d_unit = (d_carried[k] - 2.0 * carried * d_h[k] / h) / (h * h) * weight;
                    d_force[k] += d_unit;
                    d_moment[k] += d_unit * arm + unit * d_arm[k];
                }
            }
        }
        let scale = closed_weight(ii, nx) * area;
        sums += Vector2::new(force, moment) * scale;
        if GRADIENT {
            gradient += Matrix2::new(d_force[0], d_force[1], d_moment[0], d_moment[1]) * scale;
        }
    }
    (sums, gradient)
}

/// The arm about the pin of an axial force on the skirt surface at height z, radius r and cos θ = c,
/// conjugate to φ3 (`(sin φ3, cos φ3)` the tilt's), m.
pub(super) fn arm(z: f64, r: f64, c: f64, (s3, c3): (f64, f64), pin_offset: f64) -> f64 {
    -z * s3 + (r * c - pin_offset) * c3
}

/// Trapezoid weight of closed-grid line `k` of `n` interior lines: ½ on the two edges.
pub(super) fn closed_weight(k: usize, n: usize) -> f64 {
    if k == 0 || k == n + 1 {
        0.5
    } else {
        1.0
    }
}
