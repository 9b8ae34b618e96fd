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
use super::{FilmLinear, PressureMap, SideMap, SkirtDesign, SkirtLoads, SkirtMotion};
use crate::models::ModelError;
use nalgebra::{Matrix2, Matrix4x3, RowVector3, Vector3};
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
    wedge: Vec<f64>,
    arm_wedge: Vec<f64>,
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
            wedge: vec![0.0; n],
            arm_wedge: vec![0.0; n],
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
        self.loads_with(&self.linearise(motion), motion)
    }

    /// The loads at `motion` with the film's pressure of `linear`: the film at `linear`'s position
    /// and cavitation set, linear in `motion`'s rates; the Couette shear (over `linear`'s film set),
    /// the asperities and the thinnest film at `motion`'s position. At `linear`'s own motion, the
    /// loads of [`Skirt::loads`].
    pub fn loads_with(&self, linear: &FilmLinear, motion: &SkirtMotion) -> SkirtLoads {
        self.evaluate(linear, motion, None)
    }

    /// The pressure and film fields of both sides at `motion` with `linear` as in
    /// [`Skirt::loads_with`], for plots: the pressure `linear`'s at `motion`'s rates (so that it sums
    /// to the loads), the film and asperity fields at `motion`'s position.
    pub fn pressure_map(&self, linear: &FilmLinear, motion: &SkirtMotion) -> PressureMap {
        let mut map = PressureMap::default();
        self.evaluate(linear, motion, Some(&mut map));
        map
    }

    /// Solves the film at `motion`: its cavitation set and the pressure's loads per unit rate.
    pub fn linearise(&self, motion: &SkirtMotion) -> FilmLinear {
        let s = &mut *self.scratch.borrow_mut();
        let mut linear = FilmLinear { at: *motion, ..FilmLinear::default() };
        for side in 0..2 {
            linear.factorisations[side] = self.solve_side(s, side, motion, Cavitation::Reynolds);
            let reynolds = &s.reynolds[side];
            linear.gram += Matrix4x3::from_fn(|a, c| reynolds.gram[a][c]);
            linear.lateral_by_side.set_row(side, &RowVector3::from_fn(|_, c| reynolds.gram[0][c]));
            linear.free[side].clone_from(&reynolds.free);
        }
        linear
    }

    /// The row terms of the pose (lateral position, tilt) of `m` at rows (u, r).
    fn pose(&self, m: &SkirtMotion) -> impl Fn(&(f64, f64)) -> RowTerms + '_ {
        let d = &self.design;
        let (s3, c3) = (libm::sin(m.tilt), libm::cos(m.tilt));
        let (lateral, a_pin) = (m.lateral, d.pin_offset);
        move |&(u, r): &(f64, f64)| {
            let z = d.pin_from_top - u;
            ((d.radius_bore - r * c3, -(lateral - z * s3 - a_pin * c3)), (r * s3, z * c3 - a_pin * s3), z, r)
        }
    }

    /// One side's Reynolds solve at `m`: the film at its pose, `b = −ḣ ΔA + wedge` at its rates, and
    /// the extra right-hand sides ∂b/∂ẋ = cos θ ΔA, ∂b/∂φ̇3 = −(α + β cos θ) ΔA, ∂b/∂V (the wedge per
    /// unit speed, −½ ∂h/∂u ΔA: minus the axial push's weights) and that times the axial force's arm
    /// (minus the axial moment's weights). Returns the active-set steps.
    fn solve_side(&self, s: &mut Scratch, side_index: usize, m: &SkirtMotion, cavitation: Cavitation) -> usize {
        let pose = self.pose(m);
        s.node_rows.clear();
        s.node_rows.extend(self.rows.nodes.iter().map(&pose));
        s.film_rows.clear();
        s.film_rows.extend(s.node_rows.iter().map(|t| t.0));
        s.face_rows.clear();
        s.face_rows.extend(self.rows.faces.iter().map(|r| pose(r).0));
        let side = &self.sides[side_index];
        let (nx, area) = (self.grid.nx, self.grid.dx() * self.grid.dz());
        s.film.fill(&self.grid, (&s.film_rows, &s.face_rows), (&side.nodes, &side.faces), self.floor);
        s.wedge.fill(0.0);
        s.film.add_wedge(&self.grid, (0.0, 0.5), &mut s.wedge);
        let (s3, c3) = (libm::sin(m.tilt), libm::cos(m.tilt));
        for (j, &(_, (alpha, beta), z, r)) in s.node_rows.iter().enumerate() {
            for (i, &(c, _)) in side.nodes.iter().enumerate() {
                let k = j * nx + i;
                s.rate_x[k] = c * area;
                s.rate_tilt[k] = -(alpha + beta * c) * area;
                s.arm_wedge[k] = s.wedge[k] * arm(z, r, c, (s3, c3), self.design.pin_offset);
                s.rhs[k] = s.rate_x[k] * m.lateral_rate + s.rate_tilt[k] * m.tilt_rate + s.wedge[k] * m.sliding_speed;
            }
        }
        s.reynolds[side_index].solve(&s.film, self.design.viscosity, &s.rhs, cavitation, &[&s.rate_x, &s.rate_tilt, &s.wedge, &s.arm_wedge])
    }

    fn evaluate(&self, linear: &FilmLinear, m: &SkirtMotion, mut map: Option<&mut PressureMap>) -> SkirtLoads {
        let d = &self.design;
        let rates = Vector3::new(m.lateral_rate, m.tilt_rate, m.sliding_speed);
        // The pressure's loads g_aᵀ p with g_a = −(the a-th extra right-hand side), p = A⁻¹ Σ r_c b_c.
        let film = -linear.gram * rates;
        let squeeze = linear.gram.fixed_rows::<3>(0);
        // Each wall's push is its side's pressure's lateral force, negated on the thrust side (−x).
        let walls = Matrix2::new(1.0, 0.0, 0.0, -1.0) * linear.lateral_by_side;
        let mut out = SkirtLoads {
            film_force: film[0],
            moment: film[1],
            friction_force: film[2],
            friction_moment: film[3],
            damping: linear.gram.fixed_view::<2, 2>(0, 0).into_owned(),
            squeeze_power: rates.dot(&(squeeze * rates)),
            wall_push: walls * rates,
            wall_push_rates: walls.fixed_columns::<2>(0).into_owned(),
            factorisations: linear.factorisations,
            ..SkirtLoads::default()
        };
        let s = &mut *self.scratch.borrow_mut();
        let (s3, c3) = (libm::sin(m.tilt), libm::cos(m.tilt));
        let pose = self.pose(m);
        s.closed_rows.clear();
        s.closed_rows.extend(self.rows.closed.iter().map(&pose));
        let (nx, nz) = (self.grid.nx, self.grid.nz);
        let area = self.grid.dx() * self.grid.dz();
        let (mu, v) = (d.viscosity, m.sliding_speed);
        let sign_v = if v > 0.0 {
            1.0
        } else if v < 0.0 {
            -1.0
        } else {
            0.0
        };
        for (side_index, side) in self.sides.iter().enumerate() {
            let free = &linear.free[side_index];
            // A load at cos θ = c pushes the piston by −c along x: the thrust wall's push is +c times it.
            let toward_wall = [1.0, -1.0][side_index];
            let mut pushed = 0.0;
            let mut side_map = map.as_ref().map(|_| SideMap {
                angle: side.angles.clone(),
                position: self.rows.closed.iter().map(|r| r.0).collect(),
                ..SideMap::default()
            });
            if side_map.is_some() {
                s.reynolds[side_index].free.clone_from(free);
                let held = SkirtMotion { lateral: linear.at.lateral, tilt: linear.at.tilt, ..*m };
                self.solve_side(s, side_index, &held, Cavitation::Held);
            }
            // Oil fills a cavitated point as far as the film carried into it along the liner's motion
            // (+u for V > 0) allows: at a Reynolds rupture the pressure flow vanishes, so the Couette
            // flux V·h_r/2 goes on as streamers filling h_r/h of a thicker gap. The upstream edge is
            // flooded. Couette shear acts on the filled part, on the closed grid (trapezoid weights).
            for (ii, &(c, ov)) in side.closed.iter().enumerate() {
                let mut carried = f64::INFINITY;
                // The column's Σ w·fill/h and Σ w·fill/h·arm, scaled by −μV and its weight after.
                let (mut force, mut moment) = (0.0, 0.0);
                for step in 0..nz + 2 {
                    let jj = if v >= 0.0 { step } else { nz + 1 - step };
                    let ((a, b), _, z, r) = s.closed_rows[jj];
                    let h = (a + b * c + ov).max(self.floor);
                    let inside = ii > 0 && ii <= nx && jj > 0 && jj <= nz;
                    // The film's content `fill·h` is min(carried, h), and `fill/h` is `carried/h²`:
                    // the chain from node to node is a min, one division off it.
                    carried = if step == 0 || (inside && free[(jj - 1) * nx + ii - 1]) { h } else { carried.min(h) };
                    let unit = carried / (h * h) * closed_weight(jj, nz);
                    force += unit;
                    moment += unit * arm(z, r, c, (s3, c3), d.pin_offset);
                }
                let scale = -mu * v * closed_weight(ii, nx) * area;
                out.shear_power -= scale * force * v;
                out.friction_force += scale * force;
                out.friction_moment += scale * moment;
            }
            // Asperities on the closed grid (trapezoid weights), with the true film thickness; a side
            // whose thinnest film is beyond their reach has none.
            let film_at = |&((a, b), ..): &RowTerms, &(c, ov): &(f64, f64)| a + b * c + ov;
            let mut smallest =
                s.closed_rows.iter().flat_map(|row| side.closed.iter().map(move |col| film_at(row, col))).fold(f64::INFINITY, f64::min);
            let pressure = &s.reynolds[side_index].pressure;
            let rows = if side_map.is_some() || self.asperity.touches(smallest) { &s.closed_rows[..] } else { &[] };
            for (jj, &((a, b), (alpha, beta), z, r)) in rows.iter().enumerate() {
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
                    pushed += load * c;
                    out.moment += load * (alpha + beta * c);
                    let axial = -d.boundary_friction * load * sign_v;
                    out.friction_force += axial;
                    out.friction_moment += axial * arm(z, r, c, (s3, c3), d.pin_offset);
                    out.asperity_friction_power += d.boundary_friction * load * v.abs();
                }
            }
            out.min_film[side_index] = smallest;
            out.wall_push[side_index] += toward_wall * pushed;
            if let (Some(mm), Some(sm)) = (map.as_deref_mut(), side_map) {
                mm.sides[side_index] = sm;
            }
        }
        out.lateral_force += out.film_force;
        out
    }
}

/// The arm about the pin of an axial force on the skirt surface at height z, radius r and cos θ = c,
/// conjugate to φ3 (`(sin φ3, cos φ3)` the tilt's), m.
fn arm(z: f64, r: f64, c: f64, (s3, c3): (f64, f64), pin_offset: f64) -> f64 {
    -z * s3 + (r * c - pin_offset) * c3
}

/// Trapezoid weight of closed-grid line `k` of `n` interior lines: ½ on the two edges.
fn closed_weight(k: usize, n: usize) -> f64 {
    if k == 0 || k == n + 1 {
        0.5
    } else {
        1.0
    }
}
