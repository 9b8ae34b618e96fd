//! The elastic skirt: its compliance on the film grid, built once, and the relaxation that solves the
//! film and the deflection its pressure causes together.
//!
//! A side's deflection δ (away from the liner, on the closed grid: the nodes and the edges, where the
//! asperities, the shear and the thinnest film are read) is `C f`, f the film's and the asperities'
//! pressure at the nodes times a cell's area; the film is `h = h_rigid + δ`. Both sides alike, each its
//! own panel: the two skirt sides meet only at the stiff pin bosses.

use super::reynolds::Grid;
use super::shell::{Cells, Points, ShellPanel, POISSON};
use super::{Compliance, SkirtDesign};
use crate::models::ModelError;
use std::sync::Arc;

/// A side's compliance from its nodes' loads to its closed grid's deflection, m/N.
#[derive(Clone, Debug)]
pub(super) struct Elastic {
    /// Column-major (loaded node, closed point): a node's column contiguous, so that the unloaded
    /// (cavitated) nodes are skipped.
    columns: Arc<[f64]>,
    closed: usize,
}

/// Series terms per cell width each way: the patch loads' coefficients fall as 1/(m n) and the
/// shell's response as the wavenumber⁻⁴, so the deflection at the nodes converges well within this.
const MODES_PER_CELL: usize = 8;

/// The relaxation's end: the largest change of any point's deflection at most this share of the
/// side's thinnest film.
const TOLERANCE: f64 = 1e-3;

/// Relaxation steps at most; the last iterate is taken beyond (`Relaxation::converged` false).
pub(super) const MOST_STEPS: usize = 60;

impl Elastic {
    /// The compliance `design` asks for on `grid`; none for a rigid skirt.
    pub(super) fn new(design: &SkirtDesign, grid: &Grid) -> Option<Self> {
        let (nx, nz) = (grid.nx, grid.nz);
        let closed = (nx + 2) * (nz + 2);
        let by_point = match &design.compliance {
            Compliance::Rigid => return None,
            Compliance::Shell { thickness, modulus } => {
                let around = std::f64::consts::PI * design.radius_bore;
                let panel = ShellPanel {
                    axial: design.length,
                    around,
                    radius: design.radius_piston - 0.5 * thickness,
                    thickness: *thickness,
                    modulus: *modulus,
                    poisson: POISSON,
                };
                // The side's arc centred between the pin bosses.
                let offset = 0.5 * (around - grid.lx);
                let (dx, dz) = (grid.dx(), grid.dz());
                let axial: Vec<f64> = (0..nz + 2).map(|j| j as f64 * dz).collect();
                let round: Vec<f64> = (0..nx + 2).map(|i| offset + i as f64 * dx).collect();
                let points = Points { axial: &axial, around: &round };
                let cells = Cells { axial: &axial[1..=nz], around: &round[1..=nx], width: (dz, dx) };
                let modes = (MODES_PER_CELL * (nz + 1), MODES_PER_CELL * (around / dx).ceil() as usize);
                panel.compliance(&points, &cells, modes)
            }
            // A node's row serves the edge points next to it.
            Compliance::Matrix(matrix) => (0..nz + 2)
                .flat_map(|j| (0..nx + 2).map(move |i| (j.clamp(1, nz) - 1) * nx + i.clamp(1, nx) - 1))
                .flat_map(|row| matrix[row * nx * nz..(row + 1) * nx * nz].iter().copied())
                .collect(),
        };
        let nodes = nx * nz;
        let columns = (0..nodes).flat_map(|l| (0..closed).map(move |k| (k, l))).map(|(k, l)| by_point[k * nodes + l]).collect();
        Some(Self { columns, closed })
    }

    /// The closed grid's deflection under the nodes' loads `loads`, N, into `out`, m.
    pub(super) fn deflect(&self, loads: &[f64], out: &mut [f64]) {
        out.fill(0.0);
        for (column, &f) in self.columns.chunks_exact(self.closed).zip(loads).filter(|(_, &f)| f != 0.0) {
            for (o, &c) in out.iter_mut().zip(column) {
                *o += c * f;
            }
        }
    }
}

/// Reads `skirt_compliance_file`: N rows of N numbers (comma or blank separated), '#' lines and blank
/// lines skipped; the shape is checked against the grid by `SkirtDesign::validate`.
pub fn read_matrix(path: &str) -> Result<Compliance, ModelError> {
    let refuse = |what: String| ModelError(format!("skirt_compliance_file {path:?}: {what}"));
    let text = std::fs::read_to_string(path).map_err(|e| refuse(format!("cannot be read: {e}")))?;
    let mut values = Vec::new();
    let mut width = None;
    for (number, line) in text.lines().enumerate().filter(|(_, l)| !l.trim().is_empty() && !l.trim_start().starts_with('#')) {
        let row: Vec<f64> = line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|v| !v.is_empty())
            .map(|v| v.parse::<f64>().map_err(|_| refuse(format!("line {}: {v:?} is not a number", number + 1))))
            .collect::<Result<_, _>>()?;
        if *width.get_or_insert(row.len()) != row.len() {
            return Err(refuse(format!("line {} has {} numbers, the first row {}", number + 1, row.len(), width.unwrap_or(0))));
        }
        values.extend(row);
    }
    let columns = width.unwrap_or(0);
    if columns == 0 || values.len() != columns * columns {
        return Err(refuse(format!(
            "{} rows of {columns} numbers: the matrix must be square",
            values.len().checked_div(columns).unwrap_or(0)
        )));
    }
    Ok(Compliance::Matrix(values.into()))
}

/// Anderson's acceleration of the fixed point δ = C f(δ) (Anderson, J. ACM 12 (1965) 547–560; Walker
/// & Ni, SIAM J. Numer. Anal. 49 (2011) 1715–1735): the residual `r = C f(δ) − δ` and the iterates'
/// last [`MEMORY`] differences give the combination of them whose residual is least, and the step goes
/// [`MIXING`] of its residual beyond it. On a linear map this is GMRES on `I − J`, J the film's
/// response through the compliance, whose few large eigenvalues (the film's pressure ∝ h⁻³ where it
/// is thin, against a smooth compliance) a plain relaxation would need a step below their inverse for.
/// A residual grown [`RESTART`]-fold over the least so far (the cavitation set or the asperities'
/// contact changed) drops the history.
pub(super) struct Relaxation {
    iterates: Vec<Vec<f64>>,
    residuals: Vec<Vec<f64>>,
    least: f64,
}

/// Differences kept.
const MEMORY: usize = 6;
/// The share of the combined residual a step adds.
const MIXING: f64 = 0.3;
/// The growth of the residual over the least so far that drops the history.
const RESTART: f64 = 10.0;

impl Relaxation {
    pub(super) fn new() -> Self {
        Self { iterates: Vec::new(), residuals: Vec::new(), least: f64::INFINITY }
    }

    /// Moves `deflection` toward the fixed point, `target` its image C f, unless within `tolerance`
    /// (m) of it: true if it was (converged, `deflection` left as it is).
    pub(super) fn step(&mut self, deflection: &mut [f64], target: &[f64], tolerance: f64) -> bool {
        let residual: Vec<f64> = target.iter().zip(deflection.iter()).map(|(t, d)| t - d).collect();
        if residual.iter().all(|r| r.abs() <= tolerance) {
            return true;
        }
        let size = residual.iter().map(|r| r * r).sum::<f64>().sqrt();
        if size > RESTART * self.least {
            self.iterates.clear();
            self.residuals.clear();
        }
        self.least = self.least.min(size);
        self.iterates.push(deflection.to_vec());
        self.residuals.push(residual);
        if self.iterates.len() > MEMORY + 1 {
            self.iterates.remove(0);
            self.residuals.remove(0);
        }
        let m = self.residuals.len() - 1;
        let last = &self.residuals[m];
        // γ minimising |r_m − ΔR γ|, ΔR's columns the residuals' successive differences.
        let differences =
            |v: &[Vec<f64>]| -> Vec<Vec<f64>> { v.windows(2).map(|w| w[1].iter().zip(&w[0]).map(|(a, b)| a - b).collect()).collect() };
        let (dr, dx) = (differences(&self.residuals), differences(&self.iterates));
        let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
        let normal = nalgebra::DMatrix::from_fn(m, m, |i, j| dot(&dr[i], &dr[j]));
        let scale = normal.diagonal().max().max(f64::MIN_POSITIVE);
        let normal = normal + nalgebra::DMatrix::identity(m, m) * (1e-12 * scale);
        let rhs = nalgebra::DVector::from_fn(m, |i, _| dot(&dr[i], last));
        let gamma = normal.cholesky().map_or_else(|| nalgebra::DVector::zeros(m), |c| c.solve(&rhs));
        for (k, d) in deflection.iter_mut().enumerate() {
            let mut x = self.iterates[m][k] + MIXING * last[k];
            for (i, g) in gamma.iter().enumerate() {
                x -= g * (dx[i][k] + MIXING * dr[i][k]);
            }
            *d = x;
        }
        false
    }
}

/// The tolerance of a side whose thinnest film is `film`, m.
pub(super) fn tolerance(film: f64) -> f64 {
    TOLERANCE * film
}
