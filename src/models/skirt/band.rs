//! Cholesky factorisation of a symmetric positive definite band matrix, row by row (up-looking), within
//! each row's envelope.

/// A symmetric matrix of half bandwidth `b` (entries `(i, j)` with `|i − j| ≤ b`), stored by rows as
/// its lower band, and factorised in place into `L Lᵀ`.
#[derive(Clone, Debug)]
pub(crate) struct Band {
    n: usize,
    b: usize,
    /// Row i holds columns i − b ..= i at `i·(b + 1) + (j + b − i)` (those left of column 0 stay 0).
    data: Vec<f64>,
    /// 1 / L_ii after [`Band::factor_from`].
    inverse_diagonal: Vec<f64>,
    /// The first column of row i's envelope (its first non-zero entry) after [`Band::factor_from`].
    start: Vec<usize>,
}

impl Band {
    pub(crate) fn new(n: usize, b: usize) -> Self {
        Self { n, b, data: vec![0.0; n * (b + 1)], inverse_diagonal: vec![0.0; n], start: (0..n).collect() }
    }

    /// Row i's `b + 1` entries, columns i − b ..= i (the diagonal last), to be written in full.
    #[inline]
    pub(crate) fn row_mut(&mut self, i: usize) -> &mut [f64] {
        let w = self.b + 1;
        &mut self.data[i * w..i * w + w]
    }

    /// Where column j of row i lies in `data`: `at(i) + j`.
    #[inline]
    fn at(&self, i: usize) -> usize {
        i * self.b + self.b
    }

    /// Factorises into `L Lᵀ`; false if a pivot is not positive (the matrix is not positive definite).
    /// Up-looking: row i of L is `L_ij = (a_ij − Σₖ L_ik L_jk) / L_jj` for j < i, then
    /// `L_ii = √(a_ii − Σₖ L_ik²)`, each sum a [`dot`] over the columns k < j where both rows' envelopes
    /// (from their first non-zero entry on; L has no fill outside the envelope of A) overlap. Rows
    /// marked in `identity` must hold the identity (1 on the diagonal, 0 elsewhere): their rows of L
    /// are the identity's and their columns of L stay 0, so they and their columns are skipped.
    ///
    /// Only rows `first..` are factorised: row i of L depends on rows ..= i of the matrix alone, so
    /// when the matrix changed from row `first` on since a factorisation, rows `..first` of that
    /// factorisation stand, and the rows from `first` on take exactly the operations of a full
    /// factorisation: the result is the full factorisation's bit for bit.
    pub(crate) fn factor_from(&mut self, identity: &[bool], first: usize) -> bool {
        let (b, w) = (self.b, self.b + 1);
        for i in first..self.n {
            if identity[i] {
                self.inverse_diagonal[i] = 1.0;
                self.start[i] = i;
                continue;
            }
            // Row i (offset m holds column i − b + m) against the rows above it, all factorised.
            let (done, rest) = self.data.split_at_mut(i * w);
            let row = &mut rest[..w];
            let lowest = b.saturating_sub(i);
            let start = (lowest..b).find(|&m| row[m] != 0.0).unwrap_or(b);
            self.start[i] = i + start - b;
            for m in start..b {
                let j = i + m - b;
                if identity[j] {
                    continue;
                }
                // Row j holds column i − b + t at offset t + b − m.
                let from = start.max((self.start[j] + b).saturating_sub(i));
                let other = &done[j * w + b - m..j * w + b];
                let s = dot(&row[from..m], &other[from..m]);
                row[m] = (row[m] - s) * self.inverse_diagonal[j];
            }
            let s = row[b] - dot(&row[start..b], &row[start..b]);
            if s.is_nan() || s <= 0.0 {
                return false;
            }
            let d = s.sqrt();
            row[b] = d;
            self.inverse_diagonal[i] = 1.0 / d;
        }
        true
    }

    /// Forward substitution `L y = r` in place after [`Band::factor_from`], for `R` right-hand sides at
    /// once (column c of every row is one of them): each column takes exactly the operations a lone one
    /// would, the columns interleaved so that their dependency chains overlap. Identity rows keep their
    /// entries (rows of L with nothing left of the diagonal).
    pub(crate) fn forward<const R: usize>(&self, identity: &[bool], r: &mut [[f64; R]]) {
        for i in 0..self.n {
            if identity[i] {
                continue;
            }
            let (row, start) = (self.at(i), self.start[i]);
            // The right-hand sides are independent chains: a plain sum in order.
            let s = self.data[row + start..row + i].iter().zip(&r[start..i]).fold([0.0; R], |s, (&l, y)| s.add_product(l, *y));
            for (x, s) in r[i].iter_mut().zip(s) {
                *x = (*x - s) * self.inverse_diagonal[i];
            }
        }
    }

    /// Back substitution `Lᵀ x = y` in place: after [`Band::forward`] it solves `L Lᵀ x = r`.
    pub(crate) fn backward(&self, identity: &[bool], r: &mut [f64]) {
        for i in (0..self.n).rev() {
            if identity[i] {
                continue;
            }
            let s = r[i] * self.inverse_diagonal[i];
            r[i] = s;
            let (row, start) = (self.at(i), self.start[i]);
            for (x, &l) in r[start..i].iter_mut().zip(&self.data[row + start..row + i]) {
                *x -= l * s;
            }
        }
    }
}

/// What [`dot`] sums: one number, or one per right-hand side.
trait Lanes: Copy {
    const ZERO: Self;
    /// `self + a·b`, per column.
    fn add_product(self, a: f64, b: Self) -> Self;
    /// `self + other`, per column.
    fn plus(self, other: Self) -> Self;
}

impl Lanes for f64 {
    const ZERO: Self = 0.0;
    #[inline(always)]
    fn add_product(self, a: f64, b: Self) -> Self {
        self + a * b
    }
    #[inline(always)]
    fn plus(self, other: Self) -> Self {
        self + other
    }
}

impl<const R: usize> Lanes for [f64; R] {
    const ZERO: Self = [0.0; R];
    #[inline(always)]
    fn add_product(mut self, a: f64, b: Self) -> Self {
        for (x, b) in self.iter_mut().zip(b) {
            *x += a * b;
        }
        self
    }
    #[inline(always)]
    fn plus(mut self, other: Self) -> Self {
        for (x, o) in self.iter_mut().zip(other) {
            *x += o;
        }
        self
    }
}

/// Σ aₖ bₖ (per column, for several right-hand sides) in four interleaved partial sums (a fixed order, so every platform gets the same bits, and
/// one the compiler can keep in vector registers), and the last `len mod 4` terms in order, over
/// chunks of four (no bounds checks in the loop).
#[inline]
fn dot<T: Lanes>(a: &[f64], b: &[T]) -> T {
    let n = a.len().min(b.len());
    let (a, b) = (a[..n].chunks_exact(4), b[..n].chunks_exact(4));
    let mut tail = T::ZERO;
    for (&x, &y) in a.remainder().iter().zip(b.remainder()) {
        tail = tail.add_product(x, y);
    }
    let mut acc = [T::ZERO; 4];
    for (x, y) in a.zip(b) {
        for t in 0..4 {
            acc[t] = acc[t].add_product(x[t], y[t]);
        }
    }
    acc[0].plus(acc[1]).plus(acc[2].plus(acc[3])).plus(tail)
}

#[cfg(test)]
mod tests {
    use super::Band;

    /// Adds `v` to entry (i, j), j ≤ i ≤ j + b.
    fn add(a: &mut Band, i: usize, j: usize, v: f64) {
        let b = a.b;
        a.row_mut(i)[j + b - i] += v;
    }

    #[test]
    fn solves_a_tridiagonal_system_exactly() {
        // −x_{i−1} + 2 x_i − x_{i+1} = r with x = i(n+1−i)/2 … the discrete Poisson solution: r = 1.
        let n = 9;
        let mut a = Band::new(n, 1);
        for i in 0..n {
            add(&mut a, i, i, 2.0);
            if i > 0 {
                add(&mut a, i, i - 1, -1.0);
            }
        }
        assert!(a.factor_from(&[false; 9], 0));
        let mut r = vec![[1.0]; n];
        a.forward(&[false; 9], &mut r);
        let mut r: Vec<f64> = r.iter().map(|[x]| *x).collect();
        a.backward(&[false; 9], &mut r);
        for (i, x) in r.iter().enumerate() {
            let k = (i + 1) as f64;
            assert!((x - k * (n as f64 + 1.0 - k) / 2.0).abs() < 1e-12, "{i}: {x}");
        }
    }

    /// A band matrix of half band 4 on 30 unknowns, diagonally dominant (so positive definite), entries
    /// from a fixed pseudo-random sequence, rows in `identity` the identity's, every fifth row's
    /// envelope shorter than the band; `shift` changes rows from 12 on.
    fn matrix(identity: &[bool], shift: f64) -> Band {
        let (n, b) = (identity.len(), 4);
        let mut a = Band::new(n, b);
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        for i in 0..n {
            let change = if i >= 12 { shift } else { 0.0 };
            if identity[i] {
                add(&mut a, i, i, 1.0);
                continue;
            }
            add(&mut a, i, i, 2.0 * b as f64 + 1.0 + change);
            for (j, &cavitated) in identity.iter().enumerate().take(i).skip(i.saturating_sub(b)) {
                let v = next();
                // Every fifth row's envelope starts two columns left of its diagonal.
                if !cavitated && (i % 5 != 0 || j + 2 >= i) {
                    add(&mut a, i, j, v + change);
                }
            }
        }
        a
    }

    #[test]
    fn a_partial_refactorisation_is_the_full_one_bit_for_bit_and_solves_the_system() {
        let identity: Vec<bool> = (0..30).map(|i| i % 7 == 3).collect();
        let mut partial = matrix(&identity, 0.0);
        assert!(partial.factor_from(&identity, 0));
        // Rows 12.. change: assembled again, refactorised from row 12.
        let changed = matrix(&identity, 0.25);
        partial.data[12 * 5..].copy_from_slice(&changed.data[12 * 5..]);
        assert!(partial.factor_from(&identity, 12));
        let mut full = changed.clone();
        assert!(full.factor_from(&identity, 0));
        assert_eq!(partial.data.iter().map(|x| x.to_bits()).collect::<Vec<_>>(), full.data.iter().map(|x| x.to_bits()).collect::<Vec<_>>());
        // And L Lᵀ x = r solves A x = r: the residual against the unfactorised matrix, to round-off.
        let r: Vec<f64> = (0..30).map(|i| if identity[i] { 0.0 } else { 1.0 + 0.1 * i as f64 }).collect();
        let mut y: Vec<[f64; 1]> = r.iter().map(|&x| [x]).collect();
        full.forward(&identity, &mut y);
        let mut x: Vec<f64> = y.iter().map(|[v]| *v).collect();
        full.backward(&identity, &mut x);
        let entry = |i: usize, j: usize| {
            if i.abs_diff(j) > 4 {
                0.0
            } else {
                let (i, j) = (i.max(j), i.min(j));
                changed.data[i * 5 + j + 4 - i]
            }
        };
        for (i, &ri) in r.iter().enumerate() {
            let ax: f64 = x.iter().enumerate().map(|(j, xj)| entry(i, j) * xj).sum();
            assert!((ax - ri).abs() < 1e-13 * (1.0 + ri.abs()), "row {i}: {ax} against {ri}");
        }
    }
}
