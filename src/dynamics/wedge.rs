//! The forces of a contact problem whose rows are dependent but agree: a body wedged across a
//! channel at rest, sticking at two diagonal points, has four rows (two normal, two tangential) on
//! a three-degree-of-freedom linkage. The motion then fixes the forces only up to a set
//! that balances itself: the wedge's squeeze, both normal forces with the friction couple that
//! holds them. Without a solution for the stick, only the pair slipping opposite ways at the edges
//! of their cones would be consistent, a slip the motion reverses at once.
//!
//! The forces taken: the least-norm solution, moved along the one-dimensional null space to the
//! set whose smallest margin (each closed constraint's normal force, each stick's distance to the
//! edges of its cone) is largest, which keeps every stick as far inside its cone as the others.
//! Where the margins grow without bound along it (a wedge that locks: μ above the body's length
//! over the channel's width), the admissible set nearest the least-norm one, the least squeeze. Solved by
//! Gaussian elimination with full pivoting: arithmetic only, so that every platform gets the same
//! bits (a decomposition through `hypot` would call the system's libm). Heap matrices: the rows may
//! outnumber the degrees of freedom, and this runs only while a wedge holds.

use super::complementarity::{COMPLEMENTARITY_TOL, DEPENDENT_PIVOT};
use nalgebra::{DMatrix, DVector};

/// The last but one pivot, relative to the first, below which a wedge is not held: a second
/// dependence (a wedge at a dead centre of a linkage, where the rank changes along the motion),
/// left to the other modes, for held the stick would lose its solution within a step.
const WELL_POSED: f64 = 1e-6;

/// One linear margin `c · x ≥ 0` over the unknowns: `(unknown, coefficient)` pairs.
pub(crate) type Margin = [(usize, f64); 2];

/// The unknowns `x` of `a x = rhs` (square, more rows than degrees of freedom: one dependent)
/// chosen as the module says, over the `margins`; `None` when a second row is dependent or the rows
/// disagree beyond round-off.
pub(crate) fn wedged(a: DMatrix<f64>, rhs: DVector<f64>, margins: &[Margin]) -> Option<DVector<f64>> {
    let (x0, n) = solutions(&a, &rhs)?;
    if (&a * &x0 - &rhs).amax() > COMPLEMENTARITY_TOL * (rhs.amax() + a.amax() * x0.amax()) {
        return None;
    }
    let value = |x: &DVector<f64>, m: &Margin| m.iter().map(|&(k, c)| c * x[k]).sum::<f64>();
    // Each margin along x0 + t n: a + b t.
    let lines: Vec<(f64, f64)> = margins.iter().map(|m| (value(&x0, m), value(&n, m))).collect();
    let flat = 1e-12 * lines.iter().fold(0.0_f64, |s, l| s.max(l.1.abs()));
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    for &(a, b) in lines.iter().filter(|l| l.1.abs() > flat) {
        if b > 0.0 {
            lo = lo.max(-a / b);
        } else {
            hi = hi.min(-a / b);
        }
    }
    let smallest = |t: f64| lines.iter().fold(f64::INFINITY, |s, &(a, b)| s.min(a + b * t));
    let t = if lo > hi {
        0.0
    } else if lo.is_finite() && hi.is_finite() {
        // The largest smallest margin of lines: at an end or where two of them cross.
        let crossings = lines
            .iter()
            .enumerate()
            .flat_map(|(j, &(a, b))| lines[j + 1..].iter().filter(move |l| l.1 != b).map(move |&(a2, b2)| (a2 - a) / (b - b2)));
        [lo, hi]
            .into_iter()
            .chain(crossings.filter(|&t| t > lo && t < hi))
            .fold(lo, |best, t| if smallest(t) > smallest(best) { t } else { best })
    } else {
        0.0_f64.clamp(lo, hi)
    };
    Some(x0 + n * t)
}

/// A solution of `a x = rhs` whose last pivot (full pivoting) vanishes, of least norm, and the null
/// vector; `None` where the last but one pivot is small too.
fn solutions(a: &DMatrix<f64>, rhs: &DVector<f64>) -> Option<(DVector<f64>, DVector<f64>)> {
    let r = a.nrows();
    let (mut u, mut y, mut columns) = (a.clone(), rhs.clone(), (0..r).collect::<Vec<usize>>());
    let mut first = 0.0;
    for k in 0..r {
        let (mut p, mut q) = (k, k);
        for i in k..r {
            for j in k..r {
                if u[(i, j)].abs() > u[(p, q)].abs() {
                    (p, q) = (i, j);
                }
            }
        }
        u.swap_rows(k, p);
        y.swap_rows(k, p);
        u.swap_columns(k, q);
        columns.swap(k, q);
        let pivot = u[(k, k)].abs();
        if k == 0 {
            first = pivot;
        }
        // (A NaN pivot fails too.)
        let small = |fraction: f64| pivot.partial_cmp(&(fraction * first)) != Some(std::cmp::Ordering::Greater);
        if (k + 2 == r && small(WELL_POSED)) || (k + 1 == r && !small(DEPENDENT_PIVOT)) {
            return None;
        }
        for i in k + 1..r {
            let factor = u[(i, k)] / u[(k, k)];
            for j in k..r {
                u[(i, j)] -= factor * u[(k, j)];
            }
            y[i] -= factor * y[k];
        }
    }
    // Back substitution over the first r − 1 unknowns, the last (free) one put to `free`.
    let solve = |y: &DVector<f64>, free: f64| {
        let mut z = DVector::zeros(r);
        z[r - 1] = free;
        for k in (0..r - 1).rev() {
            z[k] = (y[k] - (k + 1..r).map(|j| u[(k, j)] * z[j]).sum::<f64>()) / u[(k, k)];
        }
        let mut x = DVector::zeros(r);
        for (k, &c) in columns.iter().enumerate() {
            x[c] = z[k];
        }
        x
    };
    let (particular, null) = (solve(&y, 0.0), solve(&DVector::zeros(r), 1.0));
    let least = &particular - &null * (particular.dot(&null) / null.dot(&null));
    Some((least, null))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two equal rows of a 2 × 2 system: x₀ + x₁ = 2 twice. The margins x₀ ≥ 0, x₁ ≥ 0 are largest
    /// together at (1, 1); with x₁ − x₀ ≥ 0 as well, all three are 2/3 at (2/3, 4/3); a margin that
    /// grows without bound one way (x₀ alone) keeps the least-squares solution; rows that disagree
    /// have none.
    #[test]
    fn the_squeeze_keeps_the_margins_even() {
        let a = DMatrix::from_row_slice(2, 2, &[1.0, 1.0, 1.0, 1.0]);
        let rhs = DVector::from_row_slice(&[2.0, 2.0]);
        let (first, second) = ([(0, 1.0), (0, 0.0)], [(1, 1.0), (1, 0.0)]);
        let x = wedged(a.clone(), rhs.clone(), &[first, second]).unwrap();
        assert!((x[0] - 1.0).abs() < 1e-12 && (x[1] - 1.0).abs() < 1e-12, "{x}");
        let x = wedged(a.clone(), rhs.clone(), &[first, second, [(1, 1.0), (0, -1.0)]]).unwrap();
        assert!((x[0] - 2.0 / 3.0).abs() < 1e-12 && (x[1] - 4.0 / 3.0).abs() < 1e-12, "{x}");
        let x = wedged(a.clone(), rhs.clone(), &[first]).unwrap();
        assert!((x[0] - 1.0).abs() < 1e-12 && (x[1] - 1.0).abs() < 1e-12, "{x}");
        let growing = [first];
        assert!(wedged(a, DVector::from_row_slice(&[2.0, 3.0]), &growing).is_none());
    }
}
