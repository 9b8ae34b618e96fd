//! The forces of a contact problem whose rows are dependent but agree: a piston wedged across the
//! bore at rest, sticking at two diagonal corners, has four rows (two normal, two tangential) on
//! the crank train's three degrees of freedom. The motion then fixes the forces only up to a set
//! that balances itself: the wedge's squeeze, both normal forces with the friction couple that
//! holds them. Without this, no stick of such a pair is solvable, and only the pair slipping
//! opposite ways at the edges of their cones remains, whose slip grows from round-off the wrong
//! way and is found reversed at once, again and again at one instant.
//!
//! The forces taken: the least-squares solution, moved along the one-dimensional null space to
//! the set whose smallest margin (each closed constraint's normal force, each stick's distance to
//! the edges of its cone) is largest, which keeps every stick as far inside its cone as the others.
//! Where the margins grow without bound along it (a wedge that locks: μ above the skirt length
//! over the diameter), the admissible set nearest the least-squares one, the least squeeze. Heap
//! matrices: the rows may outnumber the degrees of freedom, and this runs only while a wedge holds.

use super::complementarity::{COMPLEMENTARITY_TOL, DEPENDENT_PIVOT};
use nalgebra::{DMatrix, DVector};

/// One linear margin `c · x ≥ 0` over the unknowns: `(unknown, coefficient)` pairs.
pub(crate) type Margin = [(usize, f64); 2];

/// The unknowns `x` of `a x = rhs` (square, rank one short) chosen as the module says, over the
/// `margins`; `None` when the rank is lower or the rows disagree beyond round-off.
pub(crate) fn wedged(a: DMatrix<f64>, rhs: DVector<f64>, margins: &[Margin]) -> Option<DVector<f64>> {
    let scale = rhs.amax();
    let svd = a.clone().svd(true, true);
    let largest = svd.singular_values.max();
    let nulls: Vec<usize> = (0..svd.singular_values.len()).filter(|&k| svd.singular_values[k] <= DEPENDENT_PIVOT * largest).collect();
    let [null] = nulls[..] else { return None };
    let x0 = svd.solve(&rhs, DEPENDENT_PIVOT * largest).ok()?;
    if (&a * &x0 - &rhs).amax() > COMPLEMENTARITY_TOL * (scale + a.amax() * x0.amax()) {
        return None;
    }
    let n = svd.v_t?.row(null).transpose();
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
