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
//! Why not mass-conserving JFO (Elrod–Adams): the Reynolds condition places the rupture boundary where
//! the film's pressure gradient vanishes, which is exact for rupture, but it does not conserve mass
//! through the cavitated zone, so it cannot place a reformation boundary (where the film refills) from the
//! upstream oil supply, nor follow a starved inlet. On a fully flooded skirt, with p = 0 on every edge
//! and ambient oil all round, the loads differ little (published comparisons on journal bearings differ
//! by a few per cent in load); what is lost is the film history under squeeze reversal (a film that
//! ruptured while separating refills at once here) and the oil-transport bookkeeping. In exchange the
//! problem stays a convex LCP with a unique solution, solved exactly, with a damping matrix exact for it.

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

    /// Node (i, j) of unknown index `row`: [`Grid::index`]'s inverse.
    #[inline]
    pub(crate) fn node(&self, row: usize) -> (usize, usize) {
        if self.nx <= self.nz {
            (row % self.nx, row / self.nx)
        } else {
            (row / self.nz, row % self.nz)
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

    /// Adds the wedge term of a uniform mean surface velocity (u_x, u_z) to `b` (node order j·nx + i):
    /// `−[u_x (h_e − h_w) dz + u_z (h_n − h_s) dx]`.
    pub(crate) fn add_wedge(&self, grid: &Grid, (ux, uz): (f64, f64), b: &mut [f64]) {
        let (dx, dz, nx) = (grid.dx(), grid.dz(), grid.nx);
        for j in 0..grid.nz {
            for i in 0..nx {
                let mut s = ux * (self.face_x[j * (nx + 1) + i + 1] - self.face_x[j * (nx + 1) + i]) * dz;
                if !grid.long {
                    s += uz * (self.face_z[(j + 1) * nx + i] - self.face_z[j * nx + i]) * dx;
                }
                b[j * nx + i] -= s;
            }
        }
    }
}

/// The LCP solver's workspace for one grid.
#[derive(Clone, Debug)]
pub(crate) struct Reynolds {
    pub grid: Grid,
    matrix: Band,
    /// Face conductances `h³/(12μ)·(face length)/(node distance)`, x then z faces, as in [`Film`].
    cx: Vec<f64>,
    cz: Vec<f64>,
    /// Band order: the pressure's right-hand side, then up to [`EXTRA`] others (forward-substituted only).
    work: Vec<[f64; 1 + EXTRA]>,
    /// Band order: the pressure's column of `work`, back-substituted on its own (contiguous).
    back: Vec<f64>,
    /// Cavitated rows in band order (identity rows of the reduced matrix).
    identity: Vec<bool>,
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
}

impl Reynolds {
    pub(crate) fn new(grid: Grid) -> Self {
        let n = grid.len();
        let matrix = Band::new(n, grid.band());
        let (cx, cz) = (vec![0.0; (grid.nx + 1) * grid.nz], vec![0.0; grid.nx * (grid.nz + 1)]);
        Self {
            grid,
            matrix,
            cx,
            cz,
            work: vec![[0.0; 1 + EXTRA]; n],
            back: vec![0.0; n],
            identity: vec![false; n],
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
        let (mut p, mut free) = (std::mem::take(&mut self.pressure), std::mem::take(&mut self.free));
        if cavitation == Cavitation::None {
            free.fill(true);
        }
        let steps = self.active_set((b, extra), cavitation, &mut p, &mut free);
        for (a, row) in self.gram.iter_mut().enumerate() {
            for (c, g) in row.iter_mut().enumerate() {
                *g = self.work.iter().map(|y| y[1 + a] * y[1 + c]).sum();
            }
        }
        (self.pressure, self.free) = (p, free);
        steps
    }

    /// The primal–dual active-set iteration from the set in `free`; the factorisation of the last set
    /// stays in `matrix`, the last step's forward-substituted extras in `work`.
    fn active_set(&mut self, (b, extra): (&[f64], &[&[f64]]), cavitation: Cavitation, p: &mut [f64], free: &mut [bool]) -> usize {
        let n = self.grid.len();
        let scale_b = b.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let mut steps = 0;
        // The first band row whose matrix row changed since the last factorisation (all at first).
        let mut first = 0;
        loop {
            steps += 1;
            self.assemble(free, first);
            if !self.matrix.factor_from(&self.identity, first) {
                // Only a non-finite film gets here (the callers keep h > 0): say so with NaN, never panic.
                p.fill(f64::NAN);
                self.work.fill([f64::NAN; 1 + EXTRA]);
                return steps;
            }
            let g = &self.grid;
            for j in 0..g.nz {
                for i in 0..g.nx {
                    let k = j * g.nx + i;
                    let mut column = [0.0; 1 + EXTRA];
                    if free[k] {
                        column[0] = b[k];
                        for (x, r) in column[1..].iter_mut().zip(extra) {
                            *x = r[k];
                        }
                    }
                    self.work[g.index(i, j)] = column;
                }
            }
            self.matrix.forward(&mut self.work);
            for (x, y) in self.back.iter_mut().zip(&self.work) {
                *x = y[0];
            }
            self.matrix.backward(&mut self.back);
            for j in 0..g.nz {
                for i in 0..g.nx {
                    p[j * g.nx + i] = self.back[g.index(i, j)];
                }
            }
            if cavitation != Cavitation::Reynolds || steps > n {
                break;
            }
            // w = A p − b on the cavitated nodes; a node joins the film where w < 0 (oil would flow in),
            // leaves it where p < 0. Tolerances far below the solution's scale stop round-off cycling.
            // A node's change alters its own row and its higher-indexed neighbours' rows.
            let scale_p = p.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            first = n;
            for k in 0..n {
                let now = if free[k] { p[k] >= -1e-12 * scale_p } else { self.residual(p, k) - b[k] < -1e-12 * scale_b };
                if now != free[k] {
                    free[k] = now;
                    first = first.min(self.grid.index(k % self.grid.nx, k / self.grid.nx));
                }
            }
            if first == n {
                break;
            }
        }
        if cavitation == Cavitation::Reynolds {
            // Round-off below the tolerance only.
            for v in p.iter_mut() {
                *v = v.max(0.0);
            }
        }
        steps
    }

    fn conductances(&mut self, film: &Film, viscosity: f64) {
        let g = &self.grid;
        let (dx, dz) = (g.dx(), g.dz());
        let k = |h: f64| h * h * h / (12.0 * viscosity);
        for (c, &h) in self.cx.iter_mut().zip(&film.face_x) {
            *c = k(h) * dz / dx;
        }
        if !g.long {
            for (c, &h) in self.cz.iter_mut().zip(&film.face_z) {
                *c = k(h) * dx / dz;
            }
        }
    }

    /// The reduced matrix, band rows `first..`: rows and columns of cavitated nodes replaced by the identity.
    fn assemble(&mut self, free: &[bool], first: usize) {
        let g = &self.grid;
        let (nx, nz) = (g.nx, g.nz);
        self.matrix.clear_from(first);
        for row in first..g.len() {
            let (i, j) = g.node(row);
            let k = j * nx + i;
            self.identity[row] = !free[k];
            if !free[k] {
                self.matrix.add(row, row, 1.0);
                continue;
            }
            let (west, east) = (self.cx[j * (nx + 1) + i], self.cx[j * (nx + 1) + i + 1]);
            let mut diagonal = west + east;
            if !g.long {
                diagonal += self.cz[j * nx + i] + self.cz[(j + 1) * nx + i];
            }
            self.matrix.add(row, row, diagonal);
            // Couplings to lower-indexed free neighbours (the band stores the lower triangle).
            let mut couple = |ni: usize, nj: usize, c: f64| {
                if free[nj * nx + ni] {
                    let col = g.index(ni, nj);
                    if col < row {
                        self.matrix.add(row, col, -c);
                    }
                }
            };
            if i > 0 {
                couple(i - 1, j, west);
            }
            if i + 1 < nx {
                couple(i + 1, j, east);
            }
            if !g.long {
                if j > 0 {
                    couple(i, j - 1, self.cz[j * nx + i]);
                }
                if j + 1 < nz {
                    couple(i, j + 1, self.cz[(j + 1) * nx + i]);
                }
            }
        }
    }

    /// (A p)_k of the full operator at node k (node order).
    fn residual(&self, p: &[f64], k: usize) -> f64 {
        let g = &self.grid;
        let nx = g.nx;
        let (i, j) = (k % nx, k / nx);
        let (west, east) = (self.cx[j * (nx + 1) + i], self.cx[j * (nx + 1) + i + 1]);
        let mut s = (west + east) * p[k];
        if i > 0 {
            s -= west * p[k - 1];
        }
        if i + 1 < nx {
            s -= east * p[k + 1];
        }
        if !g.long {
            let (south, north) = (self.cz[j * nx + i], self.cz[(j + 1) * nx + i]);
            s += (south + north) * p[k];
            if j > 0 {
                s -= south * p[k - nx];
            }
            if j + 1 < g.nz {
                s -= north * p[k + nx];
            }
        }
        s
    }
}
