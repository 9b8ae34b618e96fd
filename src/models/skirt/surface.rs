//! The skirt: both sides' grids built once from the design, and the film solved per motion.
//!
//! Each side is unwrapped onto `x = R·(θ − θ_c + arc/2) ∈ [0, R·arc]` (R the bore radius, θ_c = 0 on
//! the thrust side, π on the anti-thrust side) by `u ∈ [0, length]` down from the skirt's top edge, at
//! `z = pin_from_top − u` above the pin. The film thickness (see [`SkirtDesign`]) is separable,
//! `h = a(u) + b(u)·cos θ + ovality·sin²θ` with `a = R − r(u)·cos φ3`, `b = −(x − z sin φ3 − a_pin cos φ3)`,
//! so each evaluation fills it by multiply-adds from tables built here. In the piston's frame the liner
//! slides at −V along the axis, i.e. +V along u: the mean surface velocity is (0, V/2).
//!
//! The Reynolds film takes `max(h, σ/10)`: a film collapsed onto the asperities keeps a finite (stiff)
//! squeeze resistance and the asperity law, with the true h, carries the load.

use super::asperity::Asperity;
use super::reynolds::{Cavitation, Film, Grid, Reynolds};
use super::{PressureMap, SideMap, SkirtDesign, SkirtLoads, SkirtMotion};
use crate::models::ModelError;
use nalgebra::Matrix2;
use std::cell::RefCell;

/// Per side: column terms (cos θ, ovality·sin²θ) at the node columns, the x faces, and the closed grid
/// (edges included, for the asperities, the smallest film and the plots).
#[derive(Clone, Debug)]
struct Side {
    nodes: Vec<(f64, f64)>,
    faces: Vec<(f64, f64)>,
    closed: Vec<(f64, f64)>,
    angles: Vec<f64>,
}

/// Per axial row: (u, radius r(u) = d/2 − drop(u)) at the node rows, z faces and closed grid.
#[derive(Clone, Debug)]
struct Rows {
    nodes: Vec<(f64, f64)>,
    faces: Vec<(f64, f64)>,
    closed: Vec<(f64, f64)>,
}

/// A skirt ready to evaluate: the design checked and its grids and tables built.
///
/// [`Skirt::loads`] gives the discrete problem's unique solution at the motion: each side's
/// active-set iteration starts from that side's last cavitation set (a warm start: successive
/// motions of a run differ little, so the set is mostly right and one factorisation confirms it)
/// and ends with a direct solve on the converged set, so the result depends on that set alone and
/// is what a fresh skirt gives, bit for bit unless a node lies on the cavitation boundary to
/// round-off (then within 1e-12 of the loads' scale; the tests measure both). A motion with a
/// non-finite entry gives non-finite loads.
#[derive(Clone, Debug)]
pub struct Skirt {
    design: SkirtDesign,
    grid: Grid,
    sides: [Side; 2],
    rows: Rows,
    asperity: Asperity,
    floor: f64,
    /// The workspace, lent to each evaluation: every entry is written before it is read, so an
    /// evaluation's result does not depend on the one before.
    scratch: RefCell<Scratch>,
}

/// A row's terms at one motion: (a, b) of h = a + b cos θ + ov(θ), (α, β) of ∂h/∂φ3 = α + β cos θ,
/// the height z above the pin and the skirt radius r there.
type RowTerms = ((f64, f64), (f64, f64), f64, f64);

/// The per-evaluation workspace.
#[derive(Clone, Debug)]
struct Scratch {
    /// Per side: each solve starts its active-set iteration from the side's last cavitation set.
    reynolds: [Reynolds; 2],
    film: Film,
    rhs: Vec<f64>,
    rate_x: Vec<f64>,
    rate_tilt: Vec<f64>,
    /// [`RowTerms`] at the node rows and on the closed grid; (a, b) at the node rows and the z faces.
    node_rows: Vec<RowTerms>,
    closed_rows: Vec<RowTerms>,
    film_rows: Vec<(f64, f64)>,
    face_rows: Vec<(f64, f64)>,
}

impl Scratch {
    fn new(grid: &Grid) -> Self {
        let n = grid.len();
        let reynolds = [Reynolds::new(grid.clone()), Reynolds::new(grid.clone())];
        Self {
            reynolds,
            film: Film::new(grid),
            rhs: vec![0.0; n],
            rate_x: vec![0.0; n],
            rate_tilt: vec![0.0; n],
            node_rows: Vec::with_capacity(grid.nz),
            closed_rows: Vec::with_capacity(grid.nz + 2),
            film_rows: Vec::with_capacity(grid.nz),
            face_rows: Vec::with_capacity(grid.nz + 1),
        }
    }
}

impl Skirt {
    /// Checks the design and builds the grids, or refuses it naming the field and reason.
    pub fn new(design: SkirtDesign) -> Result<Self, ModelError> {
        design.validate()?;
        let (nc, na) = design.grid;
        let grid = Grid::new(nc, na, design.radius_bore * design.arc, design.length);
        let (dx, dz) = (grid.dx(), grid.dz());
        let side = |centre: f64| {
            let column = |x: f64| {
                let theta = centre - 0.5 * design.arc + x / design.radius_bore;
                let (s, c) = (libm::sin(theta), libm::cos(theta));
                (theta, (c, design.ovality * s * s))
            };
            Side {
                nodes: (0..nc).map(|i| column(grid.x(i)).1).collect(),
                faces: (0..=nc).map(|i| column((i as f64 + 0.5) * dx).1).collect(),
                closed: (0..nc + 2).map(|i| column(i as f64 * dx).1).collect(),
                angles: (0..nc + 2).map(|i| column(i as f64 * dx).0).collect(),
            }
        };
        let row = |u: f64| (u, design.radius_piston - design.profile.drop(u, design.length));
        let rows = Rows {
            nodes: (0..na).map(|j| row(grid.z(j))).collect(),
            faces: (0..=na).map(|j| row((j as f64 + 0.5) * dz)).collect(),
            closed: (0..na + 2).map(|j| row(j as f64 * dz)).collect(),
        };
        let asperity = Asperity::new(&design.roughness);
        let floor = 0.1 * design.roughness.sigma;
        let scratch = RefCell::new(Scratch::new(&grid));
        Ok(Self { sides: [side(0.0), side(std::f64::consts::PI)], rows, asperity, floor, grid, design, scratch })
    }

    /// The design this skirt was built from.
    pub fn design(&self) -> &SkirtDesign {
        &self.design
    }

    /// Film and asperity loads, their damping, friction and dissipation at `motion`.
    pub fn loads(&self, motion: &SkirtMotion) -> SkirtLoads {
        self.evaluate(motion, None)
    }

    /// The pressure and film fields of both sides at `motion`, for plots.
    pub fn pressure_map(&self, motion: &SkirtMotion) -> PressureMap {
        let mut map = PressureMap::default();
        self.evaluate(motion, Some(&mut map));
        map
    }

    fn evaluate(&self, m: &SkirtMotion, mut map: Option<&mut PressureMap>) -> SkirtLoads {
        let d = &self.design;
        let (s3, c3) = (libm::sin(m.tilt), libm::cos(m.tilt));
        let a_pin = d.pin_offset;
        // Row terms of h = a + b cos θ + ov(θ), and of ∂h/∂φ3 = α + β cos θ (∂h/∂x = −cos θ), once per motion.
        let terms = |&(u, r): &(f64, f64)| {
            let z = d.pin_from_top - u;
            ((d.radius_bore - r * c3, -(m.lateral - z * s3 - a_pin * c3)), (r * s3, z * c3 - a_pin * s3), z, r)
        };
        let s = &mut *self.scratch.borrow_mut();
        let tabulate = |target: &mut Vec<RowTerms>, rows: &[(f64, f64)]| {
            target.clear();
            target.extend(rows.iter().map(terms));
        };
        tabulate(&mut s.node_rows, &self.rows.nodes);
        tabulate(&mut s.closed_rows, &self.rows.closed);
        s.film_rows.clear();
        s.film_rows.extend(s.node_rows.iter().map(|t| t.0));
        s.face_rows.clear();
        s.face_rows.extend(self.rows.faces.iter().map(|r| terms(r).0));
        let (nx, nz) = (self.grid.nx, self.grid.nz);
        let (dx, dz) = (self.grid.dx(), self.grid.dz());
        let area = dx * dz;
        let (mu, v) = (d.viscosity, m.sliding_speed);
        let sign_v = if v > 0.0 {
            1.0
        } else if v < 0.0 {
            -1.0
        } else {
            0.0
        };
        let mut out = SkirtLoads::default();
        let mut damping = Matrix2::zeros();
        for (side_index, side) in self.sides.iter().enumerate() {
            s.film.fill(&self.grid, (&s.film_rows, &s.face_rows), (&side.nodes, &side.faces), self.floor);
            // b = −ḣ ΔA + wedge; the rates' right-hand sides ∂b/∂ẋ = cos θ ΔA, ∂b/∂φ̇3 = −(α + β cos θ) ΔA.
            for (j, &(_, (alpha, beta), _, _)) in s.node_rows.iter().enumerate() {
                for (i, &(c, _)) in side.nodes.iter().enumerate() {
                    let k = j * nx + i;
                    let tilt = alpha + beta * c;
                    s.rhs[k] = -(-c * m.lateral_rate + tilt * m.tilt_rate) * area;
                    s.rate_x[k] = c * area;
                    s.rate_tilt[k] = -tilt * area;
                }
            }
            s.film.add_wedge(&self.grid, (0.0, 0.5 * v), &mut s.rhs);
            let reynolds = &mut s.reynolds[side_index];
            out.factorisations[side_index] = reynolds.solve(&s.film, mu, &s.rhs, Cavitation::Reynolds, &[&s.rate_x, &s.rate_tilt]);
            // D = −∂(F, M)/∂(ẋ, φ̇3) = gᵀ A⁻¹ g with g = ∂(F, M)/∂p = (∂h/∂x, ∂h/∂φ3) ΔA = −(the rates' right-hand sides).
            damping += Matrix2::from_fn(|a, c| reynolds.gram[a][c]);
            let (pressure, free) = (&reynolds.pressure, &reynolds.free);
            for (j, &(_, (alpha, beta), z, r)) in s.node_rows.iter().enumerate() {
                for (i, &(c, _)) in side.nodes.iter().enumerate() {
                    let k = j * nx + i;
                    let p = pressure[k];
                    let (dh_dx, dh_dtilt) = (-c, alpha + beta * c);
                    out.film_force += p * dh_dx * area;
                    out.moment += p * dh_dtilt * area;
                    out.squeeze_power += p * s.rhs[k];
                    // The pressure's net axial push on the profiled skirt along +y, ½ p ∂h/∂u (normal
                    // pressure on the slope plus the Poiseuille shear; its power is the wedge's work).
                    let axial = 0.5 * p * (s.film.face_z[(j + 1) * nx + i] - s.film.face_z[j * nx + i]) * dx;
                    out.friction_force += axial;
                    out.friction_moment += axial * (-z * s3 + (r * c - a_pin) * c3);
                }
            }
            // Oil fills a cavitated point as far as the film carried into it along the liner's motion
            // (+u for V > 0) allows: at a Reynolds rupture the pressure flow vanishes, so the Couette
            // flux V·h_r/2 goes on as streamers filling h_r/h of a thicker gap. The upstream edge is
            // flooded. Couette shear acts on the filled part, on the closed grid (trapezoid weights).
            for (ii, &(c, ov)) in side.closed.iter().enumerate() {
                let mut carried = f64::INFINITY;
                for step in 0..nz + 2 {
                    let jj = if v >= 0.0 { step } else { nz + 1 - step };
                    let ((a, b), _, z, r) = s.closed_rows[jj];
                    let h = (a + b * c + ov).max(self.floor);
                    let inside = ii > 0 && ii <= nx && jj > 0 && jj <= nz;
                    let fill = if step == 0 || (inside && free[(jj - 1) * nx + ii - 1]) { 1.0 } else { (carried / h).min(1.0) };
                    carried = fill * h;
                    let weight = closed_weight(ii, nx) * closed_weight(jj, nz) * area;
                    let axial = -fill * mu * v / h * weight;
                    out.shear_power -= axial * v;
                    out.friction_force += axial;
                    out.friction_moment += axial * (-z * s3 + (r * c - a_pin) * c3);
                }
            }
            // Asperities on the closed grid (trapezoid weights), with the true film thickness.
            let mut smallest = f64::INFINITY;
            let mut side_map = map.as_ref().map(|_| SideMap {
                angle: side.angles.clone(),
                position: self.rows.closed.iter().map(|r| r.0).collect(),
                ..SideMap::default()
            });
            for (jj, &((a, b), (alpha, beta), z, r)) in s.closed_rows.iter().enumerate() {
                for (ii, &(c, ov)) in side.closed.iter().enumerate() {
                    let h = a + b * c + ov;
                    smallest = smallest.min(h);
                    let pa = self.asperity.pressure(h);
                    if let Some(sm) = side_map.as_mut() {
                        let inside = ii > 0 && ii <= nx && jj > 0 && jj <= nz;
                        sm.pressure.push(if inside { pressure[(jj - 1) * nx + ii - 1] } else { 0.0 });
                        sm.asperity_pressure.push(pa);
                        sm.film.push(h);
                    }
                    if pa == 0.0 {
                        continue;
                    }
                    let weight = closed_weight(ii, nx) * closed_weight(jj, nz) * area;
                    let load = pa * weight;
                    out.asperity_force += load;
                    out.lateral_force += load * -c;
                    out.moment += load * (alpha + beta * c);
                    let axial = -d.boundary_friction * load * sign_v;
                    out.friction_force += axial;
                    out.friction_moment += axial * (-z * s3 + (r * c - a_pin) * c3);
                    out.asperity_friction_power += d.boundary_friction * load * v.abs();
                }
            }
            out.min_film[side_index] = smallest;
            if let (Some(mm), Some(sm)) = (map.as_deref_mut(), side_map) {
                mm.sides[side_index] = sm;
            }
        }
        out.lateral_force += out.film_force;
        out.damping = damping;
        out
    }
}

/// Trapezoid weight of closed-grid line `k` of `n` interior lines: ½ on the two edges.
fn closed_weight(k: usize, n: usize) -> f64 {
    if k == 0 || k == n + 1 {
        0.5
    } else {
        1.0
    }
}
