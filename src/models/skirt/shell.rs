//! The built-in skirt's compliance: a thin, shallow cylindrical panel simply supported on its four
//! edges, under radial pressure, in Donnell's theory.
//!
//! With x along the cylinder's axis, y round it, w the radial deflection along the load q, a panel of
//! radius R, wall t, modulus E and Poisson's ratio ν obeys Donnell's equation
//! `D ∇⁸w + (E t / R²) ∂⁴w/∂x⁴ = ∇⁴q`, `D = E t³ / (12 (1 − ν²))` (Timoshenko & Woinowsky-Krieger,
//! Theory of Plates and Shells, 2nd ed., §124; Ventsel & Krauthammer, Thin Plates and Shells, §17.2).
//! Simply supported edges (w, the bending moment, the in-plane normal force and the tangential
//! displacement zero: a shear diaphragm) make the double sine series exact (Navier's solution): a load
//! `q = Σ q_mn sin αx sin βy`, `α = mπ/a`, `β = nπ/b`, deflects the panel by
//! `w_mn = q_mn (α² + β²)² / (D (α² + β²)⁴ + (E t / R²) α⁴)`. A force F spread uniformly over the
//! cell `[x₁, x₂] × [y₁, y₂]` has
//! `q_mn = 4F / (a b Δx Δy) · (cos αx₁ − cos αx₂)/α · (cos βy₁ − cos βy₂)/β`.
//! With R → ∞ this is the simply supported plate (Navier), with b → ∞ and q independent of y the
//! axisymmetric cylinder on its elastic foundation (`D w'''' + (E t / R²) w = q`); the tests check
//! both against their closed forms.

/// Poisson's ratio of the skirt: an aluminium–silicon piston alloy.
pub const POISSON: f64 = 0.33;

/// A simply supported shallow cylindrical panel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShellPanel {
    /// Length along the axis a, m.
    pub axial: f64,
    /// Arc length round the axis b, m.
    pub around: f64,
    /// Radius of the mid-surface R, m (infinite: a flat plate).
    pub radius: f64,
    /// Wall thickness t, m.
    pub thickness: f64,
    /// Young's modulus E, Pa.
    pub modulus: f64,
    /// Poisson's ratio ν, –.
    pub poisson: f64,
}

/// Points on a tensor grid of the panel: their axial positions x and positions round y, m; a point
/// k lies at (x[k / y.len()], y[k % y.len()]).
pub struct Points<'a> {
    pub axial: &'a [f64],
    pub around: &'a [f64],
}

/// Cells of a uniform tensor grid of the panel, each loaded by a force spread uniformly over it: their
/// centres and their widths (axial, round), m; cell l centred at (x[l / y.len()], y[l % y.len()]).
pub struct Cells<'a> {
    pub axial: &'a [f64],
    pub around: &'a [f64],
    pub width: (f64, f64),
}

impl ShellPanel {
    /// The flexural rigidity D, N·m.
    pub fn rigidity(&self) -> f64 {
        self.modulus * self.thickness.powi(3) / (12.0 * (1.0 - self.poisson * self.poisson))
    }

    /// The deflection of `points` per unit force on `cells`, m/N, row-major (point, cell), from the
    /// series' first `modes` (axial, round) terms: by the panel's separable form, a sum over the axial
    /// modes of products of per-mode tables, `Σ_m X_m(x_k) S_m(x_l) G_m(y_k, y_l)` with
    /// `G_m = Σ_n w_mn Y_n(y_k) T_n(y_l)`.
    pub fn compliance(&self, points: &Points, cells: &Cells, modes: (usize, usize)) -> Vec<f64> {
        let (a, b) = (self.axial, self.around);
        let (d, membrane) = (self.rigidity(), self.modulus * self.thickness / (self.radius * self.radius));
        let wavenumber = |m: usize, length: f64| (m + 1) as f64 * std::f64::consts::PI / length;
        // A mode's value at the points and its mean over each cell's width.
        let at = |k: f64, xs: &[f64]| xs.iter().map(|&x| libm::sin(k * x)).collect::<Vec<_>>();
        let mean = |k: f64, xs: &[f64], width: f64| {
            xs.iter().map(|&x| (libm::cos(k * (x - 0.5 * width)) - libm::cos(k * (x + 0.5 * width))) / (k * width)).collect::<Vec<_>>()
        };
        let round: Vec<_> = (0..modes.1).map(|n| wavenumber(n, b)).collect();
        let point_round: Vec<_> = round.iter().map(|&k| at(k, points.around)).collect();
        let cell_round: Vec<_> = round.iter().map(|&k| mean(k, cells.around, cells.width.1)).collect();
        let (py, cy) = (points.around.len(), cells.around.len());
        let (px, cx) = (points.axial.len(), cells.axial.len());
        let mut out = vec![0.0; px * py * cx * cy];
        let mut g = vec![0.0; py * cy];
        for m in 0..modes.0 {
            let alpha = wavenumber(m, a);
            let (alpha2, alpha4) = (alpha * alpha, alpha.powi(4));
            g.fill(0.0);
            for (n, &beta) in round.iter().enumerate() {
                let k2 = alpha2 + beta * beta;
                let w = 4.0 / (a * b) * k2 * k2 / (d * k2.powi(4) + membrane * alpha4);
                for (gk, &yk) in g.chunks_exact_mut(cy).zip(&point_round[n]) {
                    for (gl, &tl) in gk.iter_mut().zip(&cell_round[n]) {
                        *gl += w * yk * tl;
                    }
                }
            }
            let (point_axial, cell_axial) = (at(alpha, points.axial), mean(alpha, cells.axial, cells.width.0));
            for (xi, &xk) in point_axial.iter().enumerate() {
                for (yi, gk) in g.chunks_exact(cy).enumerate() {
                    let row = &mut out[(xi * py + yi) * cx * cy..][..cx * cy];
                    for (xl, &sl) in cell_axial.iter().enumerate() {
                        let scale = xk * sl;
                        for (o, &gl) in row[xl * cy..(xl + 1) * cy].iter_mut().zip(gk) {
                            *o += scale * gl;
                        }
                    }
                }
            }
        }
        out
    }
}
