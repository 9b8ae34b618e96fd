//! One finite-volume Reynolds solver for every film here: the skirt's two sides and the journal
//! bearings of the tests, on a rectangle with p = 0 on its edges.
//!
//! The incompressible, isoviscous Reynolds equation in the frame where the film thickness h(x, z, t)
//! is defined, `∇·(h³/(12μ) ∇p) = ∂h/∂t + ∇·(u h)`, u the mean of the two surfaces' velocities (uniform),
//! is integrated over the cell of each interior node of a uniform grid (nodes at `(i+1)·dx`, `(j+1)·dz`,
//! the edges at 0 and `lx`, `lz` carrying p = 0): face fluxes `h³/(12μ)·Δp/Δ` with h³ taken at the
//! face midpoint, the wedge term as the difference of `u·h` across the cell, the squeeze term `ḣ·ΔA` at
//! the node. The result is `A p = b` with A a symmetric M-matrix (second-order accurate; the grid tests
//! measure the order).
//!
//! Cavitation is the Reynolds (Swift–Stieber) condition: p ≥ 0 everywhere, the Reynolds equation where
//! p > 0, and no outflow into the cavitated zone, i.e. the linear complementarity problem
//! `p ≥ 0, w = A p − b ≥ 0, pᵢ wᵢ = 0`. It is the obstacle problem of an M-matrix, solved by the
//! primal–dual active-set method (Hintermüller, Ito & Kunisch, SIAM J. Optim. 13 (2003) 865–888), which
//! for an M-matrix ends in finitely many steps at the exact solution of the discrete problem, from any
//! starting set (a solve starts from its workspace's last set); the last step is a direct (band
//! Cholesky) solve on the converged set, so the result depends on the set alone, and the same
//! factorisation gives the damping (`gᵀA⁻¹g = |L⁻¹g|²`, forward substitutions only). A step
//! refactorises only from the first band row its set changes touch.
//!
//! The mass-conserving (JFO) condition (`Cavitation::MassConserving`) solves the same LCP on the nodes
//! whose film is full, the fill fraction θ ∈ [0, 1] of the others given (`skirt/fill.rs`): a partly filled
//! node has p = 0, and the wedge carries `u·h·θ` across each face with θ of the node upwind of it
//! (`Film::add_wedge` with a [`Carried`] fill; the supply beyond an edge is full). The LCP's complement
//! `w` is then the rate at which a full node starts to empty, and the flow balance of a partly filled node
//! gives its `∂(θh)/∂t` (`fill::rate`), so θ is carried between solves as state. Why this form and not
//! Elrod–Adams' universal variable is in `documentation/design/lubricated_skirt.md`.
//!
//! The Reynolds condition places the rupture boundary where the film's pressure gradient vanishes, which
//! is exact for rupture, but it does not conserve mass through the cavitated zone, so it cannot place a
//! reformation boundary (where the film refills) from the oil the cavitated zone carries: a film that
//! ruptured while separating refills at once. In exchange its problem is a convex LCP with a unique
//! solution at every motion and no history.

use super::band::Band;

/// A uniform grid of interior nodes on `[0, lx] × [0, lz]`, p = 0 on the edges; `long` drops the axial
/// direction (an infinitely long film: nz = 1, results per unit axial length).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Grid {
    pub nx: usize,
    pub nz: usize,
    pub lx: f64,
    pub lz: f64,
    pub long: bool,
}

impl Grid {
    pub(crate) fn new(nx: usize, nz: usize, lx: f64, lz: f64) -> Self {
        Self { nx, nz, lx, lz, long: false }
    }

    /// An infinitely long film along z: results per metre of axial length.
    #[cfg(test)]
    pub(crate) fn long(nx: usize, lx: f64) -> Self {
        Self { nx, nz: 1, lx, lz: 1.0, long: true }
    }

    pub(crate) fn len(&self) -> usize {
        self.nx * self.nz
    }

    pub(crate) fn dx(&self) -> f64 {
        self.lx / (self.nx + 1) as f64
    }

    /// The axial spacing, 1 m for a long film (its cells are a metre long).
    pub(crate) fn dz(&self) -> f64 {
        if self.long {
            1.0
        } else {
            self.lz / (self.nz + 1) as f64
        }
    }

    pub(crate) fn x(&self, i: usize) -> f64 {
        (i + 1) as f64 * self.dx()
    }

    pub(crate) fn z(&self, j: usize) -> f64 {
        if self.long {
            0.0
        } else {
            (j + 1) as f64 * self.dz()
        }
    }

    /// Unknown index of node (i, j): the shorter direction runs fastest, for the narrowest band.
    #[inline]
    pub(crate) fn index(&self, i: usize, j: usize) -> usize {
        if self.nx <= self.nz {
            j * self.nx + i
        } else {
            i * self.nz + j
        }
    }

    /// Half bandwidth of A in [`Grid::index`] order.
    fn band(&self) -> usize {
        self.nx.min(self.nz)
    }
}

/// Terms of a separable film thickness at the nodes and at the faces (see [`Film::fill`]).
pub(crate) type Terms<'a> = (&'a [(f64, f64)], &'a [(f64, f64)]);

/// A film thickness sampled where the discretisation needs it: nodes, x faces (`(nx+1)·nz`, face i
/// lies left of node i) and z faces (`nx·(nz+1)`).
#[derive(Clone, Debug)]
pub(crate) struct Film {
    pub node: Vec<f64>,
    pub face_x: Vec<f64>,
    pub face_z: Vec<f64>,
}

impl Film {
    pub(crate) fn new(grid: &Grid) -> Self {
        Self { node: vec![0.0; grid.len()], face_x: vec![0.0; (grid.nx + 1) * grid.nz], face_z: vec![0.0; grid.nx * (grid.nz + 1)] }
    }

    /// Fills a film of the separable form `h = max(a_j + b_j·c_i + d_i, floor)` from its row terms
    /// (a, b) at the node rows and the z-face rows (j = 0 ..= nz, face j below node j) and its column
    /// terms (c, d) at the node columns and the x-face columns (i = 0 ..= nx, face i left of node i).
    pub(crate) fn fill(&mut self, grid: &Grid, rows: Terms, columns: Terms, floor: f64) {
        let nx = grid.nx;
        let h = |(a, b): (f64, f64), (c, d): (f64, f64)| (a + b * c + d).max(floor);
        for (j, &row) in rows.0.iter().enumerate() {
            for (i, &column) in columns.0.iter().enumerate() {
                self.node[j * nx + i] = h(row, column);
            }
            for (i, &column) in columns.1.iter().enumerate() {
                self.face_x[j * (nx + 1) + i] = h(row, column);
            }
        }
        if !grid.long {
            for (j, &row) in rows.1.iter().enumerate() {
                for (i, &column) in columns.0.iter().enumerate() {
                    self.face_z[j * nx + i] = h(row, column);
                }
            }
        }
    }

    /// Deflects the film by `deflection` (m, away from the liner) given on the closed grid (the nodes
    /// and the edges, row-major by axial line; empty: none): the nodes take their points', each face
    /// the mean of the two points either side of it; the film kept at least `floor`.
    pub(crate) fn deform(&mut self, grid: &Grid, deflection: &[f64], floor: f64) {
        if deflection.is_empty() {
            return;
        }
        let (nx, nz) = (grid.nx, grid.nz);
        let at = |i: usize, j: usize| deflection[j * (nx + 2) + i];
        let bend = |h: &mut f64, d: f64| *h = (*h + d).max(floor);
        for j in 0..nz {
            for i in 0..nx {
                bend(&mut self.node[j * nx + i], at(i + 1, j + 1));
            }
            for i in 0..=nx {
                bend(&mut self.face_x[j * (nx + 1) + i], 0.5 * (at(i, j + 1) + at(i + 1, j + 1)));
            }
        }
        for j in 0..=nz {
            for i in 0..nx {
                bend(&mut self.face_z[j * nx + i], 0.5 * (at(i + 1, j) + at(i + 1, j + 1)));
            }
        }
    }

    /// Adds the wedge term of a uniform mean surface velocity (u_x, u_z) to `b` (node order j·nx + i):
    /// `−[u_x (h_e − h_w) dz + u_z (h_n − h_s) dx]`, each face's h times the fill upwind of it where
    /// `carried` gives one.
    pub(crate) fn add_wedge(&self, grid: &Grid, (ux, uz): (f64, f64), carried: Option<&Carried>, b: &mut [f64]) {
        let (dx, dz, nx, nz) = (grid.dx(), grid.dz(), grid.nx, grid.nz);
        for j in 0..nz {
            for i in 0..nx {
                let (west, east) = (self.face_x[j * (nx + 1) + i], self.face_x[j * (nx + 1) + i + 1]);
                let (south, north) = if grid.long { (0.0, 0.0) } else { (self.face_z[j * nx + i], self.face_z[(j + 1) * nx + i]) };
                let s = match carried {
                    None => {
                        let mut s = ux * (east - west) * dz;
                        if !grid.long {
                            s += uz * (north - south) * dx;
                        }
                        s
                    }
                    Some(c) => {
                        let [w, e, s, n] = c.upwind(grid, i, j);
                        ux * (east * e - west * w) * dz + uz * (north * n - south * s) * dx
                    }
                };
                b[j * nx + i] -= s;
            }
        }
    }
}

impl Film {
    /// The flow node `k` (node order) passes per unit of its own fill through its downstream faces
    /// under the mean surface velocity (u_x, u_z), m³/s: `|u_x| h dz + |u_z| h dx` at those faces.
    pub(crate) fn carried_out(&self, grid: &Grid, (ux, uz): (f64, f64), k: usize) -> f64 {
        let (nx, (i, j)) = (grid.nx, (k % grid.nx, k / grid.nx));
        let x = self.face_x[j * (nx + 1) + i + usize::from(ux >= 0.0)];
        let z = if grid.long { 0.0 } else { self.face_z[(j + usize::from(uz >= 0.0)) * nx + i] };
        ux.abs() * x * grid.dz() + uz.abs() * z * grid.dx()
    }
}

/// A fill fraction carried by the wedge's flow: per node (node order j·nx + i), θ ∈ [0, 1], and the
/// flow's direction along x and z (true: toward +x, +z). Beyond the edges the supply is `inlet`'s:
/// along x per row, along z per column, the fill the oil arriving across the upstream edge has (a
/// limited supply, `skirt/supply.rs`); full (θ = 1, flooded) where none is given.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Carried<'a> {
    pub fill: &'a [f64],
    pub forward: (bool, bool),
    pub inlet: (Option<&'a [f64]>, Option<&'a [f64]>),
}

impl Carried<'_> {
    /// The fill each face of node (i, j) carries, [west, east, south, north]: its upwind node's, or
    /// beyond an edge the supply's.
    fn upwind(&self, grid: &Grid, i: usize, j: usize) -> [f64; 4] {
        let (nx, nz) = (grid.nx, grid.nz);
        let at = |i: Option<usize>, j: Option<usize>| match (i, j) {
            (Some(i), Some(j)) if i < nx && j < nz => self.fill[j * nx + i],
            (Some(i), _) if i < nx => self.inlet.1.map_or(1.0, |inlet| inlet[i]),
            (_, Some(j)) if j < nz => self.inlet.0.map_or(1.0, |inlet| inlet[j]),
            _ => 1.0,
        };
        let (here, (x, z)) = (at(Some(i), Some(j)), self.forward);
        let (west, east) = if x { (at(i.checked_sub(1), Some(j)), here) } else { (here, at(Some(i + 1), Some(j))) };
        let (south, north) = if z { (at(Some(i), j.checked_sub(1)), here) } else { (here, at(Some(i), Some(j + 1))) };
        [west, east, south, north]
    }

    /// The flows out of the rectangle across its edges after a solve, m³/s (negative: inflow), by edge
    /// face: [`EdgeFlows`]'s order. Each is the wedge's `u·h·θ` across the face, θ upwind of it, plus
    /// the Poiseuille flow `h³/(12μ) p` over the half cell to the edge's p = 0, the same face fluxes the
    /// solve and `fill::rate` take, so that the content of the film changes by their sum alone.
    pub(crate) fn edge_flows(&self, reynolds: &Reynolds, film: &Film, viscosity: f64, (ux, uz): (f64, f64)) -> EdgeFlows {
        let g = &reynolds.grid;
        let (nx, nz, dx, dz) = (g.nx, g.nz, g.dx(), g.dz());
        let p = |i: usize, j: usize| reynolds.pressure[j * nx + i];
        let conductance = |h: f64, across: f64, along: f64| h * h * h / (12.0 * viscosity) * across / along;
        let mut flows = EdgeFlows::default();
        for j in 0..nz {
            let (west, east) = (film.face_x[j * (nx + 1)], film.face_x[j * (nx + 1) + nx]);
            let (w, e) = (self.upwind(g, 0, j)[0], self.upwind(g, nx - 1, j)[1]);
            flows.west.push(-ux * west * w * dz + conductance(west, dz, dx) * p(0, j));
            flows.east.push(ux * east * e * dz + conductance(east, dz, dx) * p(nx - 1, j));
        }
        if !g.long {
            for i in 0..nx {
                let (south, north) = (film.face_z[i], film.face_z[nz * nx + i]);
                let (s, n) = (self.upwind(g, i, 0)[2], self.upwind(g, i, nz - 1)[3]);
                flows.south.push(-uz * south * s * dx + conductance(south, dx, dz) * p(i, 0));
                flows.north.push(uz * north * n * dx + conductance(north, dx, dz) * p(i, nz - 1));
            }
        }
        flows
    }
}

/// The flows out of a film's rectangle after a solve, m³/s (negative: inflow), per face of each
/// edge: `west` (x = 0) and `east` (x = lx) per row, `south` (z = 0) and `north` (z = lz) per column
/// (empty for a long film).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct EdgeFlows {
    pub west: Vec<f64>,
    pub east: Vec<f64>,
    pub south: Vec<f64>,
    pub north: Vec<f64>,
}

impl EdgeFlows {
    /// The net outflow, m³/s.
    pub fn total(&self) -> f64 {
        [&self.west, &self.east, &self.south, &self.north].into_iter().flatten().sum()
    }
}

/// The LCP solver's workspace for one grid. The unknowns are in band order ([`Grid::index`]): lines of
/// `band` nodes along the shorter direction, so row − 1 is a node's neighbour along its line (none at
/// a line's start) and row − band its neighbour on the line before.
#[derive(Clone, Debug)]
pub(crate) struct Reynolds {
    pub grid: Grid,
    matrix: Band,
    /// Each node's band row (node order j·nx + i).
    order: Vec<usize>,
    /// Band order: the sum of a node's four face conductances `h³/(12μ)·(face length)/(node distance)`,
    /// and the conductances of its faces toward rows − 1 and − band (0 where there is none).
    diagonal: Vec<f64>,
    lower: Vec<[f64; 2]>,
    /// Band order: the pressure's right-hand side.
    rhs: Vec<f64>,
    /// Band order: up to [`EXTRA`] right-hand sides besides the pressure's, forward-substituted only.
    work: Vec<[f64; EXTRA]>,
    /// Band order: the pressure's right-hand side, forward- then back-substituted.
    back: Vec<[f64; 1]>,
    /// Cavitated rows in band order (identity rows of the reduced matrix).
    identity: Vec<bool>,
    /// Band order: nodes held at p = 0 by a partial fill ([`Cavitation::MassConserving`], [`Reynolds::pin`]).
    pinned: Vec<bool>,
    /// The last solve's pressures, Pa, node order j·nx + i.
    pub pressure: Vec<f64>,
    /// The last solve's film nodes (false: cavitated, p = 0), the next solve's starting set.
    pub free: Vec<bool>,
    /// The last solve's `rᵢᵀ A⁻¹ rⱼ` of its extra right-hand sides (0 beyond those given).
    pub gram: [[f64; EXTRA]; EXTRA],
}

/// Right-hand sides a solve takes besides the pressure's (the skirt's: its two squeeze rates, the
/// sliding speed's wedge and the axial friction moment's weights).
pub(crate) const EXTRA: usize = 4;

/// How a film may cavitate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Cavitation {
    /// Full Sommerfeld: negative pressures kept (the closed forms' reference, not physical oil).
    None,
    /// The Reynolds condition as the complementarity problem above.
    Reynolds,
    /// The film nodes held as `free` holds them (a set solved before): one direct solve, negative
    /// pressures kept.
    Held,
    /// Mass-conserving (JFO): the Reynolds condition's LCP on the nodes not pinned by a partial fill
    /// ([`Reynolds::pin`]), the pinned ones at p = 0.
    MassConserving,
}

impl Cavitation {
    /// Whether the solve is a complementarity problem (an active-set iteration).
    fn complementary(self) -> bool {
        matches!(self, Cavitation::Reynolds | Cavitation::MassConserving)
    }
}

impl Reynolds {
    pub(crate) fn new(grid: Grid) -> Self {
        let n = grid.len();
        let matrix = Band::new(n, grid.band());
        let order = (0..n).map(|k| grid.index(k % grid.nx, k / grid.nx)).collect();
        Self {
            grid,
            matrix,
            order,
            diagonal: vec![0.0; n],
            lower: vec![[0.0; 2]; n],
            rhs: vec![0.0; n],
            work: vec![[0.0; EXTRA]; n],
            back: vec![[0.0]; n],
            identity: vec![false; n],
            pinned: vec![false; n],
            pressure: vec![0.0; n],
            free: vec![true; n],
            gram: [[0.0; EXTRA]; EXTRA],
        }
    }

    /// Solves for the pressure (into `pressure`, node order j·nx + i) of `film` and right-hand side `b`,
    /// the set of film nodes into `free`, and for `extra` (at most [`EXTRA`] right-hand sides r, zero on
    /// cavitated nodes) the products `rᵢᵀ A⁻¹ rⱼ` of the reduced matrix A into `gram`: with A = L Lᵀ
    /// they are `(L⁻¹rᵢ)·(L⁻¹rⱼ)`, a forward substitution each, taken in the same pass over the factor
    /// as the pressure's on every active-set step (most evaluations take one). Returns the active-set
    /// steps taken.
    pub(crate) fn solve(&mut self, film: &Film, viscosity: f64, b: &[f64], cavitation: Cavitation, extra: &[&[f64]]) -> usize {
        assert!(extra.len() <= EXTRA, "at most {EXTRA} extra right-hand sides");
        self.conductances(film, viscosity);
        for (k, &row) in self.order.iter().enumerate() {
            self.rhs[row] = b[k];
            self.identity[row] = cavitation != Cavitation::None && !self.free[k] || self.held(row, cavitation);
        }
        let steps = self.active_set(extra, cavitation);
        for (k, &row) in self.order.iter().enumerate() {
            self.free[k] = !self.identity[row];
            // Negative pressures under the Reynolds condition are round-off below its tolerance.
            let [p] = self.back[row];
            self.pressure[k] = if cavitation.complementary() && p < 0.0 { 0.0 } else { p };
        }
        // Σ over the film rows (the cavitated ones' are 0) of the outer product, in row order.
        let mut gram = [[0.0; EXTRA]; EXTRA];
        for (y, _) in self.work.iter().zip(&self.identity).filter(|(_, &cavitated)| !cavitated) {
            for (a, row) in gram.iter_mut().enumerate() {
                for (c, g) in row.iter_mut().enumerate() {
                    *g += y[a] * y[c];
                }
            }
        }
        self.gram = gram;
        steps
    }

    /// The primal–dual active-set iteration from the set in `identity` (band order), the pressure into
    /// `back` (band order); the factorisation of the last set stays in `matrix`, and the extras,
    /// forward-substituted on it once the set holds, in `work` (a column's substitution takes the same
    /// operations alone or beside others, so the extras are those of a pass with the pressure's).
    fn active_set(&mut self, extra: &[&[f64]], cavitation: Cavitation) -> usize {
        let n = self.grid.len();
        let scale_b = self.rhs.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let mut steps = 0;
        // The first band row whose matrix row changed since the last factorisation (all at first).
        let mut first = 0;
        loop {
            steps += 1;
            self.assemble(first);
            if !self.matrix.factor_from(&self.identity, first) {
                // Only a non-finite film gets here (the callers keep h > 0): say so with NaN, never panic.
                self.back.fill([f64::NAN]);
                self.work.fill([f64::NAN; EXTRA]);
                return steps;
            }
            for ((p, &b), &cavitated) in self.back.iter_mut().zip(&self.rhs).zip(&self.identity) {
                *p = [if cavitated { 0.0 } else { b }];
            }
            self.matrix.forward(&self.identity, &mut self.back);
            self.matrix.backward(&self.identity, self.back.as_flattened_mut());
            if !cavitation.complementary() || steps > n {
                break;
            }
            // w = A p − b on the cavitated nodes; a node joins the film where w < 0 (oil would flow in),
            // leaves it where p < 0. Tolerances far below the solution's scale stop round-off cycling.
            // A node's change alters its own row and its higher-indexed neighbours' rows.
            let scale_p = self.back.iter().fold(0.0_f64, |m, [v]| m.max(v.abs()));
            first = n;
            for row in 0..n {
                if self.held(row, cavitation) {
                    continue;
                }
                let free = if self.identity[row] {
                    self.residual(row) - self.rhs[row] < -1e-12 * scale_b
                } else {
                    self.back[row][0] >= -1e-12 * scale_p
                };
                if free == self.identity[row] {
                    self.identity[row] = !free;
                    first = first.min(row);
                }
            }
            if first == n {
                break;
            }
        }
        for (k, &row) in self.order.iter().enumerate() {
            let column = &mut self.work[row];
            *column = [0.0; EXTRA];
            if !self.identity[row] {
                for (x, r) in column.iter_mut().zip(extra) {
                    *x = r[k];
                }
            }
        }
        self.matrix.forward(&self.identity, &mut self.work);
        steps
    }

    /// Holds the nodes where `partial` (node order) is true at p = 0 in the next
    /// [`Cavitation::MassConserving`] solves: the partly filled ones.
    pub(crate) fn pin(&mut self, partial: impl Iterator<Item = bool>) {
        for (&row, pinned) in self.order.iter().zip(partial) {
            self.pinned[row] = pinned;
        }
    }

    /// Whether band row `row` is held at p = 0 by a partial fill in a solve of `cavitation`.
    fn held(&self, row: usize, cavitation: Cavitation) -> bool {
        cavitation == Cavitation::MassConserving && self.pinned[row]
    }

    /// The last solve's net Poiseuille outflow of node `k` (node order), m³/s: `(A p)ₖ` of the full
    /// operator, the pressure taken unclipped as solved.
    pub(crate) fn outflow(&self, k: usize) -> f64 {
        self.residual(self.order[k])
    }

    /// The face conductances in band order (see [`Reynolds::diagonal`]).
    fn conductances(&mut self, film: &Film, viscosity: f64) {
        let g = &self.grid;
        let (nx, nz, dx, dz) = (g.nx, g.nz, g.dx(), g.dz());
        let k = |h: f64| h * h * h / (12.0 * viscosity);
        // The x faces left and right of node (i, j), and the z faces below and above it.
        let (x_scale, z_scale) = (dz / dx, if g.long { 0.0 } else { dx / dz });
        for j in 0..nz {
            let (x_faces, z_faces) = (&film.face_x[j * (nx + 1)..], &film.face_z[j * nx..]);
            let mut east = k(x_faces[0]) * x_scale;
            for i in 0..nx {
                let west = east;
                east = k(x_faces[i + 1]) * x_scale;
                let (south, north) = (k(z_faces[i]) * z_scale, k(z_faces[i + nx]) * z_scale);
                let row = g.index(i, j);
                self.diagonal[row] = west + east + south + north;
                // Along a line (row − 1) and to the line before (row − band).
                self.lower[row] = if nx <= nz {
                    [if i == 0 { 0.0 } else { west }, if j == 0 { 0.0 } else { south }]
                } else {
                    [if j == 0 { 0.0 } else { south }, if i == 0 { 0.0 } else { west }]
                };
            }
        }
    }

    /// The reduced matrix, band rows `first..`: rows and columns of cavitated nodes replaced by the identity.
    fn assemble(&mut self, first: usize) {
        let b = self.grid.band();
        for row in first..self.grid.len() {
            let entries = self.matrix.row_mut(row);
            entries.fill(0.0);
            if self.identity[row] {
                entries[b] = 1.0;
                continue;
            }
            entries[b] = self.diagonal[row];
            let [along, before] = self.lower[row];
            if along != 0.0 && !self.identity[row - 1] {
                entries[b - 1] -= along;
            }
            if before != 0.0 && !self.identity[row - b] {
                entries[0] -= before;
            }
        }
    }

    /// (A p)_row of the full operator at band row `row`, p the pressure in `back`.
    fn residual(&self, row: usize) -> f64 {
        let (n, b, p) = (self.grid.len(), self.grid.band(), self.back.as_flattened());
        let mut s = self.diagonal[row] * p[row];
        let [along, before] = self.lower[row];
        if along != 0.0 {
            s -= along * p[row - 1];
        }
        if before != 0.0 {
            s -= before * p[row - b];
        }
        if row + 1 < n {
            s -= self.lower[row + 1][0] * p[row + 1];
        }
        if row + b < n {
            s -= self.lower[row + b][1] * p[row + b];
        }
        s
    }
}
