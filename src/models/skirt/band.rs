//! Cholesky factorisation of a symmetric positive definite band matrix, column by column (right-looking).

/// A symmetric matrix of half bandwidth `b` (entries `(i, j)` with `|i − j| ≤ b`), stored by rows as
/// its lower band, and factorised in place into `L Lᵀ`.
#[derive(Clone, Debug)]
pub(crate) struct Band {
    n: usize,
    b: usize,
    /// Row i holds columns i − b ..= i at `i·(b + 1) + (j + b − i)`.
    data: Vec<f64>,
    /// 1 / L_ii after [`Band::factor_from`].
    inverse_diagonal: Vec<f64>,
    /// Column k of L below the diagonal while column k updates the rows below it.
    column: Vec<f64>,
}

impl Band {
    pub(crate) fn new(n: usize, b: usize) -> Self {
        Self { n, b, data: vec![0.0; n * (b + 1)], inverse_diagonal: vec![0.0; n], column: vec![0.0; b] }
    }

    /// Clears every entry of rows `first..`.
    pub(crate) fn clear_from(&mut self, first: usize) {
        self.data[first * (self.b + 1)..].fill(0.0);
    }

    /// Adds `v` to entry (i, j), j ≤ i ≤ j + b.
    #[inline]
    pub(crate) fn add(&mut self, i: usize, j: usize, v: f64) {
        self.data[i * (self.b + 1) + j + self.b - i] += v;
    }

    /// Factorises into `L Lᵀ`; false if a pivot is not positive (the matrix is not positive definite).
    /// Right-looking: once column k of L is known, it updates the rows below it,
    /// `a_ij −= L_ik·L_jk` for k < j ≤ i ≤ k + b (contiguous runs of a row, no chain of dependent
    /// sums), so every entry takes its updates one by one in the order of k. Rows marked in
    /// `identity` must hold the identity (1 on the diagonal, 0 elsewhere): their work is skipped
    /// (their rows of L are the identity's, and their columns of L below them stay 0).
    ///
    /// Only rows `first..` are factorised: row i of L depends on rows ..= i of the matrix alone, so
    /// when the matrix changed from row `first` on since a factorisation, rows `..first` of that
    /// factorisation stand; the columns `first − b .. first` then update the rows from `first` on
    /// as they would in a full factorisation, in the same order, and the result is the full
    /// factorisation's bit for bit.
    pub(crate) fn factor_from(&mut self, identity: &[bool], first: usize) -> bool {
        let (n, b, w) = (self.n, self.b, self.b + 1);
        for k in first.saturating_sub(b)..n {
            if identity[k] {
                self.inverse_diagonal[k] = 1.0;
                continue;
            }
            if k >= first {
                let s = self.data[k * w + b];
                if s.is_nan() || s <= 0.0 {
                    return false;
                }
                let d = s.sqrt();
                self.data[k * w + b] = d;
                self.inverse_diagonal[k] = 1.0 / d;
            }
            let inverse = self.inverse_diagonal[k];
            let below = b.min(n - 1 - k);
            // Row i = k + 1 + m holds column k at i·w + b − 1 − m; rows above `first` hold L already.
            for m in 0..below {
                let (i, at) = (k + 1 + m, (k + 1 + m) * w + b - 1 - m);
                if i >= first {
                    self.data[at] *= inverse;
                }
                self.column[m] = self.data[at];
            }
            for m in 0..below {
                let i = k + 1 + m;
                if i < first || identity[i] {
                    continue;
                }
                let l = self.column[m];
                // Columns k + 1 ..= i of row i.
                let row = &mut self.data[i * w + b - m..i * w + w];
                for (x, &c) in row.iter_mut().zip(&self.column[..=m]) {
                    *x -= l * c;
                }
            }
        }
        true
    }

    /// Forward substitution `L y = r` in place after [`Band::factor_from`], for `R` right-hand sides at
    /// once (column c of every row is one of them): each column takes exactly the operations a lone one
    /// would, the columns interleaved so that their dependency chains overlap.
    pub(crate) fn forward<const R: usize>(&self, r: &mut [[f64; R]]) {
        let (n, b, w) = (self.n, self.b, self.b + 1);
        for i in 0..n {
            let (row, first) = (i * w + b - i, i.saturating_sub(b));
            let s = dot(&self.data[row + first..row + i], &r[first..i]);
            for (x, s) in r[i].iter_mut().zip(s) {
                *x = (*x - s) * self.inverse_diagonal[i];
            }
        }
    }

    /// Back substitution `Lᵀ x = y` in place: after [`Band::forward`] it solves `L Lᵀ x = r`.
    pub(crate) fn backward(&self, r: &mut [f64]) {
        let (n, b, w) = (self.n, self.b, self.b + 1);
        for i in (0..n).rev() {
            let s = r[i] * self.inverse_diagonal[i];
            r[i] = s;
            let (row, first) = (i * w + b - i, i.saturating_sub(b));
            for (x, &l) in r[first..i].iter_mut().zip(&self.data[row + first..row + i]) {
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
/// one the compiler can keep in vector registers), then the last `len mod 4` terms in order. Indexed
/// over slices cut to one length, so the short sums of a narrow band pay no iterator set-up.
#[inline]
fn dot<T: Lanes>(a: &[f64], b: &[T]) -> T {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    let whole = n & !3;
    let mut acc = [T::ZERO; 4];
    let mut k = 0;
    while k < whole {
        acc[0] = acc[0].add_product(a[k], b[k]);
        acc[1] = acc[1].add_product(a[k + 1], b[k + 1]);
        acc[2] = acc[2].add_product(a[k + 2], b[k + 2]);
        acc[3] = acc[3].add_product(a[k + 3], b[k + 3]);
        k += 4;
    }
    let mut tail = T::ZERO;
    for k in whole..n {
        tail = tail.add_product(a[k], b[k]);
    }
    acc[0].plus(acc[1]).plus(acc[2].plus(acc[3])).plus(tail)
}

#[cfg(test)]
mod tests {
    use super::Band;

    #[test]
    fn solves_a_tridiagonal_system_exactly() {
        // −x_{i−1} + 2 x_i − x_{i+1} = r with x = i(n+1−i)/2 … the discrete Poisson solution: r = 1.
        let n = 9;
        let mut a = Band::new(n, 1);
        for i in 0..n {
            a.add(i, i, 2.0);
            if i > 0 {
                a.add(i, i - 1, -1.0);
            }
        }
        assert!(a.factor_from(&[false; 9], 0));
        let mut r = vec![[1.0]; n];
        a.forward(&mut r);
        let mut r: Vec<f64> = r.iter().map(|[x]| *x).collect();
        a.backward(&mut r);
        for (i, x) in r.iter().enumerate() {
            let k = (i + 1) as f64;
            assert!((x - k * (n as f64 + 1.0 - k) / 2.0).abs() < 1e-12, "{i}: {x}");
        }
    }

    /// A band matrix of half band 4 on 30 unknowns, diagonally dominant (so positive definite), entries
    /// from a fixed pseudo-random sequence, rows in `identity` the identity's; `shift` changes rows
    /// from 12 on.
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
                a.add(i, i, 1.0);
                continue;
            }
            a.add(i, i, 2.0 * b as f64 + 1.0 + change);
            for (j, &cavitated) in identity.iter().enumerate().take(i).skip(i.saturating_sub(b)) {
                let v = next();
                if !cavitated {
                    a.add(i, j, v + change);
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
        // Rows 12.. change: cleared, assembled again, refactorised from row 12.
        let changed = matrix(&identity, 0.25);
        partial.clear_from(12);
        partial.data[12 * 5..].copy_from_slice(&changed.data[12 * 5..]);
        assert!(partial.factor_from(&identity, 12));
        let mut full = changed.clone();
        assert!(full.factor_from(&identity, 0));
        assert_eq!(partial.data.iter().map(|x| x.to_bits()).collect::<Vec<_>>(), full.data.iter().map(|x| x.to_bits()).collect::<Vec<_>>());
        // And L Lᵀ x = r solves A x = r: the residual against the unfactorised matrix, to round-off.
        let r: Vec<f64> = (0..30).map(|i| if identity[i] { 0.0 } else { 1.0 + 0.1 * i as f64 }).collect();
        let mut y: Vec<[f64; 1]> = r.iter().map(|&x| [x]).collect();
        full.forward(&mut y);
        let mut x: Vec<f64> = y.iter().map(|[v]| *v).collect();
        full.backward(&mut x);
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
