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
use super::elastic::{self, Elastic, Relaxation};
use super::fill::{self, partial, Fill};
use super::reynolds::{Carried, Cavitation, Film, Grid, Reynolds};
use super::shear::{self, arm, closed_weight, RowTerms, Shear, Wetted};
use super::supply::{self, Liner};
use super::{CavitationCondition, FilmLinear, PressureMap, SideMap, SkirtDesign, SkirtLoads, SkirtMotion};
use crate::models::ModelError;
use nalgebra::{Matrix2, Matrix4x3, RowVector3, Vector2, Vector3};
use std::cell::{RefCell, RefMut};

/// Per side: column terms (cos θ, ovality·sin²θ) at the node columns, the x faces, and the closed grid
/// (edges included, for the asperities, the smallest film and the plots).
#[derive(Clone, Debug)]
struct Side {
    nodes: Vec<(f64, f64)>,
    faces: Vec<(f64, f64)>,
    closed: Vec<(f64, f64)>,
    angles: Vec<f64>,
    /// The closed columns where some row's film can be least (`lower_envelope`).
    envelope: Vec<(f64, f64)>,
}

/// Per axial row: (u, radius r(u) = d/2 − drop(u)) at the node rows, z faces and closed grid.
#[derive(Clone, Debug)]
struct Rows {
    nodes: Vec<(f64, f64)>,
    faces: Vec<(f64, f64)>,
    closed: Vec<(f64, f64)>,
}

/// How far (as a fraction of the thinnest film) an evaluation's pose may lie from its film solve's
/// for the solve's Couette shear sums to serve it to first order (`Shear::sums_at`): the carried
/// solves of a run move at most `step_film::CARRY_MOVE` (1 %) plus half a step, where the sums err
/// by ≈ 1e-4 of themselves; farther away (tests, plots) they are walked at the pose.
const SHEAR_REACH: f64 = 0.02;

/// Sliding speed, m/s, below which boundary friction is `μ_b W V / BOUNDARY_SLIP` rather than
/// `μ_b W sign V`: a skirt held still on its asperities by friction creeps at most this fast (the
/// slope is made implicit by the crank train, so its size costs no step), and an engine's reversal
/// crosses the band in `2·BOUNDARY_SLIP/|ÿ|`, 0.3 µs at the default engine's TDC at 1200 rpm.
pub const BOUNDARY_SLIP: f64 = 1e-4;

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
    /// A limited supply's map of the liner; none when flooded.
    liner: Option<Liner>,
    /// An elastic skirt's compliance; none when rigid.
    elastic: Option<Elastic>,
    /// The workspace, lent to each evaluation: every entry is written before it is read, so an
    /// evaluation's result does not depend on the one before.
    scratch: Workspace,
}

/// A skirt's workspace, made at its first use. A clone starts without one: the model is cloned at
/// every communication step to be put back if the step fails, and a copy of the solver's band
/// matrices would be most of that clone. The clone's first solves start cold, which changes their
/// active-set steps, not their result (the discrete problem's unique solution).
#[derive(Debug, Default)]
struct Workspace(RefCell<Option<Box<Scratch>>>);

impl Clone for Workspace {
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl Workspace {
    /// The workspace for `grid`, made if there is none yet.
    fn lend(&self, grid: &Grid) -> RefMut<'_, Scratch> {
        RefMut::map(self.0.borrow_mut(), |s| &mut **s.get_or_insert_with(|| Box::new(Scratch::new(grid))))
    }
}

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
    /// A limited supply's inlet fill per column (`supply::inlet_fill`).
    inlet: Vec<f64>,
    /// An elastic skirt's nodal loads, N, and the deflection they cause on the closed grid, m.
    loads: Vec<f64>,
    target: Vec<f64>,
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
            inlet: Vec::with_capacity(grid.nx),
            loads: vec![0.0; n],
            target: vec![0.0; (grid.nx + 2) * (grid.nz + 2)],
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
            let closed: Vec<_> = (0..nc + 2).map(|i| column(i as f64 * dx).1).collect();
            Side {
                nodes: (0..nc).map(|i| column(grid.x(i)).1).collect(),
                faces: (0..=nc).map(|i| column((i as f64 + 0.5) * dx).1).collect(),
                envelope: lower_envelope(&closed),
                closed,
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
        let scratch = Workspace::default();
        let liner = Liner::new(&design, &grid);
        let elastic = Elastic::new(&design, &grid);
        Ok(Self { sides: [side(0.0), side(std::f64::consts::PI)], rows, asperity, floor, liner, elastic, grid, design, scratch })
    }

    /// The skirt's longest distance from the pin, m (axially, plus the pin's offset): a tilt change δφ3
    /// moves no node's film by more than this times δφ3 (to first order in the tilt, which the
    /// clearance keeps at a few mrad).
    pub fn arm(&self) -> f64 {
        let d = &self.design;
        d.pin_from_top.abs().max((d.length - d.pin_from_top).abs()) + d.pin_offset.abs()
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

    /// Solves the film at `motion`: its cavitation set and the pressure's loads per unit rate; with
    /// mass-conserving cavitation, of a flooded film ([`Skirt::linearise_filled`]).
    pub fn linearise(&self, motion: &SkirtMotion) -> FilmLinear {
        self.linearise_filled(motion, None)
    }

    /// [`Skirt::linearise`] with mass-conserving cavitation at the fill fraction `fill` (flooded where
    /// none), giving also the fill's rate and decay at `motion`'s rates and the oil the film holds;
    /// with a limited supply whose liner `fill` holds ([`Skirt::starting_fill`]), the leading edge fed
    /// by the liner's oil ahead of it and the film's edge flows (`skirt/supply.rs`). Under the Reynolds
    /// condition `fill` is not read.
    pub fn linearise_filled(&self, motion: &SkirtMotion, fill: Option<&Fill>) -> FilmLinear {
        self.linearise_deflected(motion, fill, &Default::default())
    }

    /// [`Skirt::linearise_filled`], an elastic skirt's deflection relaxed from `start` (per side, on
    /// the closed grid, as [`FilmLinear::deflection`]; empty: undeflected): a nearby solve's deflection
    /// saves most of the relaxation. A rigid skirt does not read it.
    pub fn linearise_deflected(&self, motion: &SkirtMotion, fill: Option<&Fill>, start: &[Vec<f64>; 2]) -> FilmLinear {
        let mut workspace = self.scratch.lend(&self.grid);
        let s = &mut *workspace;
        let mut linear = FilmLinear { at: *motion, ..FilmLinear::default() };
        if self.design.cavitation == CavitationCondition::MassConserving {
            linear.fill = fill.cloned().unwrap_or_else(|| Fill::flooded(self.grid.len()));
            linear.fill_rate = Fill::flooded(self.grid.len());
            linear.fill_decay = Fill::flooded(self.grid.len());
        }
        let forward = motion.sliding_speed >= 0.0;
        for (side, start) in start.iter().enumerate() {
            let carried = linear.fill.sides[side].as_slice();
            let carried = (!carried.is_empty()).then_some(carried);
            if let (Some(liner), false) = (&self.liner, linear.fill.liner[side].is_empty()) {
                liner.ahead(&linear.fill.liner[side], linear.fill.axial, forward, &mut linear.supply[side]);
            }
            let supplied = Some(linear.supply[side].as_slice()).filter(|l| !l.is_empty());
            let cavitation = if carried.is_some() { Cavitation::MassConserving } else { Cavitation::Reynolds };
            linear.factorisations[side] = match &self.elastic {
                Some(elastic) => {
                    let oil = (carried, supplied);
                    let (steps, deflection) = self.solve_elastic(s, (elastic, start), side, motion, cavitation, oil);
                    linear.deflection[side] = deflection;
                    steps
                }
                None => self.solve_side(s, side, motion, cavitation, (carried, supplied), &[]),
            };
            linear.peak_pressure = s.reynolds[side].pressure.iter().fold(linear.peak_pressure, |m, &p| m.max(p));
            if let Some(theta) = carried {
                let area = self.grid.dx() * self.grid.dz();
                linear.content += theta.iter().zip(&s.film.node).map(|(t, h)| t * h).sum::<f64>() * area;
                let squeeze = |k: usize| -(s.rate_x[k] * motion.lateral_rate + s.rate_tilt[k] * motion.tilt_rate) / area;
                linear.gaps[side] = s.film.node.iter().enumerate().map(|(k, &h)| (h, squeeze(k))).collect();
                if supplied.is_some() {
                    let carried = Carried { fill: theta, forward: (true, forward), inlet: (None, Some(&s.inlet)) };
                    let velocity = (0.0, 0.5 * motion.sliding_speed);
                    linear.edges[side] = carried.edge_flows(&s.reynolds[side], &s.film, self.design.viscosity, velocity);
                }
                let solve = fill::Solve {
                    reynolds: &s.reynolds[side],
                    film: &s.film,
                    grid: &self.grid,
                    fill: theta,
                    rhs: &s.rhs,
                    velocity: (0.0, 0.5 * motion.sliding_speed),
                    squeeze: |k| -(s.rate_x[k] * motion.lateral_rate + s.rate_tilt[k] * motion.tilt_rate),
                    area,
                };
                fill::rate(&solve, (&mut linear.fill_rate.sides[side], &mut linear.fill_decay.sides[side]));
            }
            let reynolds = &s.reynolds[side];
            linear.gram += Matrix4x3::from_fn(|a, c| reynolds.gram[a][c]);
            linear.lateral_by_side.set_row(side, &RowVector3::from_fn(|_, c| reynolds.gram[0][c]));
            linear.moment_by_side.set_row(side, &RowVector3::from_fn(|_, c| reynolds.gram[1][c]));
            linear.free[side].clone_from(&reynolds.free);
        }
        let pose = self.pose(motion);
        s.closed_rows.clear();
        s.closed_rows.extend(self.rows.closed.iter().map(&pose));
        let (tilt, forward) = ((libm::sin(motion.tilt), libm::cos(motion.tilt)), motion.sliding_speed >= 0.0);
        linear.shear = Shear { at: Vector2::new(motion.lateral, motion.tilt), forward, ..Shear::default() };
        for side in 0..2 {
            let wetted = (&linear.free[side][..], &linear.fill.sides[side][..], &linear.supply[side][..]);
            let (sums, gradient) = self.shear_walk::<true>(&s.closed_rows, side, (wetted, &linear.deflection[side]), forward, tilt);
            linear.shear.sums += sums;
            linear.shear.gradient += gradient;
        }
        linear
    }

    /// With a limited supply, the oil a run starts with, the pin at axial position `axial` (m) and the
    /// skirt at `motion`: the liner's uniform film on both sides' maps, and in the film at each node
    /// what that film fills of the gap, `min(1, l/h)`; none when flooded (a flooded film at rest).
    pub fn starting_fill(&self, motion: &SkirtMotion, axial: f64) -> Option<Fill> {
        let liner = self.liner.as_ref()?;
        let film = liner.starting_film();
        let sides = self.node_films(motion, &Default::default()).map(|h| h.iter().map(|h| (film / h).min(1.0)).collect());
        Some(Fill { sides, liner: [liner.start(), liner.start()], axial })
    }

    /// Both sides' film at the nodes at `motion`'s pose deflected by `deflection` (per side, on the
    /// closed grid; empty: rigid), m (the Reynolds film's, at least its floor).
    fn node_films(&self, motion: &SkirtMotion, deflection: &[Vec<f64>; 2]) -> [Vec<f64>; 2] {
        let mut workspace = self.scratch.lend(&self.grid);
        let s = &mut *workspace;
        let pose = self.pose(motion);
        [0, 1].map(|side| {
            s.film_rows.clear();
            s.film_rows.extend(self.rows.nodes.iter().map(|r| pose(r).0));
            s.face_rows.clear();
            s.face_rows.extend(self.rows.faces.iter().map(|r| pose(r).0));
            s.film.fill(&self.grid, (&s.film_rows, &s.face_rows), (&self.sides[side].nodes, &self.sides[side].faces), self.floor);
            s.film.deform(&self.grid, &deflection[side], self.floor);
            s.film.node.clone()
        })
    }

    /// The fill `dt` (s) after the solve `linear` with the skirt then at `motion` and the pin at axial
    /// position `axial` (m), each node's oil kept to its solve's flows (`fill::advanced_conserving`);
    /// with a limited supply, the film's edge flows at the solve exchanged with the liner over the
    /// pin's path since the fill's own position (`supply::Liner::exchange`), and what a node holds
    /// beyond its flows taken from the liner under it (or, negative, left there): the oil on the liner
    /// and in the film is then constant but for the oil the film took beyond what the liner's cells
    /// held, which this also returns, m³. Under the Reynolds condition, no fill.
    pub fn fill_after(&self, linear: &FilmLinear, dt: f64, (motion, axial): (&SkirtMotion, f64)) -> (Fill, f64) {
        if linear.fill.sides[0].is_empty() {
            return (Fill::default(), 0.0);
        }
        let (area, nx) = (self.grid.dx() * self.grid.dz(), self.grid.nx);
        let mut fill = Fill { liner: linear.fill.liner.clone(), axial: linear.fill.axial, ..Fill::default() };
        let mut lacked = 0.0;
        for (side, after) in self.node_films(motion, &linear.deflection).iter().enumerate() {
            let (before, rates): (Vec<f64>, Vec<f64>) = linear.gaps[side].iter().copied().unzip();
            let (theta, rate) = (&linear.fill.sides[side], &linear.fill_rate.sides[side]);
            let (kept, held) = fill::advanced_conserving(theta, rate, dt, (&before, &rates, after));
            fill.sides[side] = kept;
            let (Some(liner), map) = (&self.liner, &mut fill.liner[side]) else { continue };
            if map.is_empty() {
                continue;
            }
            lacked += liner.exchange(map, &linear.edges[side], (linear.fill.axial, axial), dt);
            for (k, &held) in held.iter().enumerate().filter(|(_, &h)| h != 0.0) {
                lacked += liner.leave(map, (k % nx, k / nx), axial, -held * area);
            }
            fill.axial = axial;
        }
        (fill, lacked)
    }

    /// With a limited supply, the oil `fill`'s liner holds, m³, and the area its maps cover, m² (both
    /// sides); (0, 0) when flooded.
    pub fn liner_oil(&self, fill: &Fill) -> (f64, f64) {
        match &self.liner {
            Some(liner) => {
                fill.liner.iter().filter(|m| !m.is_empty()).fold((0.0, 0.0), |(v, a), m| (v + liner.volume(m), a + liner.area()))
            }
            None => (0.0, 0.0),
        }
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
    /// (minus the axial moment's weights). With a `fill` (mass-conserving), the wedge carries it upwind
    /// of each face along the sliding and its partly filled nodes are held at p = 0; with a `supply`
    /// (the liner's oil ahead of the leading edge per column), the oil crossing that edge fills
    /// `supply::inlet_fill` of the gap (into `s.inlet`), full otherwise. The skirt deflected by
    /// `deflection` (on the closed grid; empty: rigid). Returns the active-set steps.
    fn solve_side(
        &self,
        s: &mut Scratch,
        side_index: usize,
        m: &SkirtMotion,
        cavitation: Cavitation,
        (fill, supply): (Option<&[f64]>, Option<&[f64]>),
        deflection: &[f64],
    ) -> usize {
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
        s.film.deform(&self.grid, deflection, self.floor);
        s.wedge.fill(0.0);
        let forward = m.sliding_speed >= 0.0;
        if let Some(liner) = supply {
            let edge = if forward { 0 } else { self.grid.nz * nx };
            supply::inlet_fill(liner, s.film.face_z[edge..edge + nx].iter().copied(), &mut s.inlet);
        }
        let inlet = supply.map(|_| s.inlet.as_slice());
        let carried = fill.map(|fill| Carried { fill, forward: (true, forward), inlet: (None, inlet) });
        s.film.add_wedge(&self.grid, (0.0, 0.5), carried.as_ref(), &mut s.wedge);
        if let Some(fill) = fill {
            s.reynolds[side_index].pin(fill.iter().map(|&t| partial(t)));
        }
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

    /// One side's film and deflection solved together at `m` (`skirt/elastic.rs`): from `start` (empty:
    /// the rigid skirt), the deflection relaxed toward the compliance's response to the film's and the
    /// asperities' pressure at the nodes until it moves by less than its tolerance, each step a
    /// [`Skirt::solve_side`] on the deflected skirt (its cavitation set the last step's); the last
    /// solve is the deflection's. Returns the active-set steps of all solves and the deflection.
    fn solve_elastic(
        &self,
        s: &mut Scratch,
        (elastic, start): (&Elastic, &[f64]),
        side: usize,
        m: &SkirtMotion,
        cavitation: Cavitation,
        oil: (Option<&[f64]>, Option<&[f64]>),
    ) -> (usize, Vec<f64>) {
        let area = self.grid.dx() * self.grid.dz();
        let mut deflection = if start.is_empty() { vec![0.0; s.target.len()] } else { start.to_vec() };
        let mut relaxation = Relaxation::new();
        let mut steps = 0;
        for _ in 0..elastic::MOST_STEPS {
            steps += self.solve_side(s, side, m, cavitation, oil, &deflection);
            for ((f, &p), &h) in s.loads.iter_mut().zip(&s.reynolds[side].pressure).zip(&s.film.node) {
                *f = (p + self.asperity.pressure(h)) * area;
            }
            elastic.deflect(&s.loads, &mut s.target);
            let thinnest = s.film.node.iter().fold(f64::INFINITY, |a, &h| a.min(h));
            if relaxation.step(&mut deflection, &s.target, elastic::tolerance(thinnest)) {
                break;
            }
        }
        (steps, deflection)
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
            wall_moment: -linear.moment_by_side * rates,
            factorisations: linear.factorisations,
            ..SkirtLoads::default()
        };
        let mut workspace = self.scratch.lend(&self.grid);
        let s = &mut *workspace;
        let (s3, c3) = (libm::sin(m.tilt), libm::cos(m.tilt));
        let pose = self.pose(m);
        s.closed_rows.clear();
        s.closed_rows.extend(self.rows.closed.iter().map(&pose));
        let (nx, nz) = (self.grid.nx, self.grid.nz);
        let area = self.grid.dx() * self.grid.dz();
        let v = m.sliding_speed;
        // Boundary friction's direction, linear across |V| < BOUNDARY_SLIP (its slope returned as
        // `boundary_damping`): the sign of V, were it Coulomb's, flips at every step of a skirt that
        // stops on its asperities.
        let (slip, within) = ((v / BOUNDARY_SLIP).clamp(-1.0, 1.0), v.abs() < BOUNDARY_SLIP);
        let smallest: [f64; 2] = std::array::from_fn(|side| match &linear.deflection[side][..] {
            [] => thinnest(&s.closed_rows, &self.sides[side].envelope),
            deflection => thinnest_deflected(&s.closed_rows, &self.sides[side].closed, deflection),
        });
        // The Couette shear: the solve's sums to first order in the pose where they serve, walked here otherwise.
        let at = Vector2::new(m.lateral, m.tilt);
        let reach = SHEAR_REACH * smallest[0].min(smallest[1]);
        let shear = if map.is_none() && linear.shear.serves(v, at, self.arm(), reach) {
            linear.shear.sums_at(at)
        } else {
            (0..2)
                .map(|side| {
                    // The supply feeds the solve's leading edge.
                    let supply = if (v >= 0.0) == linear.shear.forward { &linear.supply[side][..] } else { &[] };
                    let wetted = (&linear.free[side][..], &linear.fill.sides[side][..], supply);
                    self.shear_walk::<false>(&s.closed_rows, side, (wetted, &linear.deflection[side]), v >= 0.0, (s3, c3)).0
                })
                .sum()
        };
        out.friction_force -= d.viscosity * v * shear[0];
        out.friction_moment -= d.viscosity * v * shear[1];
        out.shear_power = d.viscosity * v * v * shear[0];
        for (side_index, side) in self.sides.iter().enumerate() {
            // A load at cos θ = c pushes the piston by −c along x: the thrust wall's push is +c times it.
            let toward_wall = [1.0, -1.0][side_index];
            let mut pushed = 0.0;
            let mut side_map = map.as_ref().map(|_| SideMap {
                angle: side.angles.clone(),
                position: self.rows.closed.iter().map(|r| r.0).collect(),
                ..SideMap::default()
            });
            if side_map.is_some() {
                s.reynolds[side_index].free.clone_from(&linear.free[side_index]);
                let held = SkirtMotion { lateral: linear.at.lateral, tilt: linear.at.tilt, ..*m };
                let carried = Some(linear.fill.sides[side_index].as_slice()).filter(|f| !f.is_empty());
                let supplied = Some(linear.supply[side_index].as_slice()).filter(|l| !l.is_empty());
                self.solve_side(s, side_index, &held, Cavitation::Held, (carried, supplied), &linear.deflection[side_index]);
            }
            // Asperities on the closed grid (trapezoid weights), with the true film thickness down to
            // the film's floor σ/10, below which the corners carry the collapsed film (the asperities'
            // load is then the floor's, not the steep Greenwood–Tripp tail of a surface through the
            // liner, which an RK4 stage off the held corners' manifold reads by nanometres); a side whose
            // thinnest film is beyond their reach has none.
            let pressure = &s.reynolds[side_index].pressure;
            let rows = if side_map.is_some() || self.asperity.touches(smallest[side_index]) { &s.closed_rows[..] } else { &[] };
            let deflection = &linear.deflection[side_index];
            for (jj, &((a, b), (alpha, beta), z, r)) in rows.iter().enumerate() {
                for (ii, &(c, ov)) in side.closed.iter().enumerate() {
                    let rigid = a + b * c + ov;
                    let h = if deflection.is_empty() { rigid } else { rigid + deflection[jj * (nx + 2) + ii] };
                    let read = h.max(self.floor);
                    let pa = self.asperity.pressure(read);
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
                    out.asperity_energy += (self.asperity.energy(read) + pa * (read - h)) * weight;
                    out.lateral_force += load * -c;
                    pushed += load * c;
                    out.moment += load * (alpha + beta * c);
                    out.wall_moment[side_index] += load * (alpha + beta * c);
                    let axial = -d.boundary_friction * load * slip;
                    out.friction_force += axial;
                    out.friction_moment += axial * arm(z, r, c, (s3, c3), d.pin_offset);
                    out.asperity_friction_power -= axial * v;
                    if within {
                        out.boundary_damping += d.boundary_friction * load / BOUNDARY_SLIP;
                    }
                }
            }
            out.min_film[side_index] = smallest[side_index];
            out.wall_push[side_index] += toward_wall * pushed;
            if let (Some(mm), Some(sm)) = (map.as_deref_mut(), side_map) {
                mm.sides[side_index] = sm;
            }
        }
        out.lateral_force += out.film_force;
        out
    }

    /// One side's Couette shear sums (and with `GRADIENT` their gradient) at the pose of `rows`, its
    /// film set, fill and supply `wetted` and its deflection (`shear::walk`).
    fn shear_walk<const GRADIENT: bool>(
        &self,
        rows: &[RowTerms],
        side: usize,
        (wetted, deflection): (Wetted, &[f64]),
        forward: bool,
        tilt: (f64, f64),
    ) -> (Vector2<f64>, Matrix2<f64>) {
        let area = self.grid.dx() * self.grid.dz();
        let columns = (&self.sides[side].closed[..], deflection);
        shear::walk::<GRADIENT>(rows, columns, wetted, forward, self.floor, tilt, self.design.pin_offset, area)
    }
}

/// The smallest film over the closed grid at the pose of `rows`: on each row `a + b c + ov` is least
/// at a column of the lower envelope of the lines `b ↦ b c + ov`, `envelope`.
fn thinnest(rows: &[RowTerms], envelope: &[(f64, f64)]) -> f64 {
    rows.iter().flat_map(|&((a, b), ..)| envelope.iter().map(move |&(c, ov)| a + b * c + ov)).fold(f64::INFINITY, f64::min)
}

/// The smallest film over the closed grid at the pose of `rows`, `columns` the closed columns'
/// (c, ov), the skirt deflected by `deflection` (closed grid, row-major).
fn thinnest_deflected(rows: &[RowTerms], columns: &[(f64, f64)], deflection: &[f64]) -> f64 {
    let films = rows.iter().flat_map(|&((a, b), ..)| columns.iter().map(move |&(c, ov)| a + b * c + ov));
    films.zip(deflection).fold(f64::INFINITY, |m, (h, d)| m.min(h + d))
}

/// The columns `(c, ov)` on the lower envelope of the lines `b ↦ b c + ov`: the lower convex hull of
/// the points (c, ov) (monotone chain), the only columns where some row's film can be least.
fn lower_envelope(columns: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut points = columns.to_vec();
    points.sort_by(|p, q| p.0.total_cmp(&q.0).then(p.1.total_cmp(&q.1)));
    points.dedup_by(|q, p| q.0 == p.0);
    let mut hull: Vec<(f64, f64)> = Vec::with_capacity(points.len());
    for p in points {
        while let [.., o, a] = hull[..] {
            // Drop `a` unless o → a → p turns left (a lies strictly below the chord o–p).
            if (a.0 - o.0) * (p.1 - o.1) - (a.1 - o.1) * (p.0 - o.0) > 0.0 {
                break;
            }
            hull.pop();
        }
        hull.push(p);
    }
    hull
}
