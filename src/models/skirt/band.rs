//! Cholesky factorisation of a symmetric positive definite band matrix, row by row.

/// A symmetric matrix of half bandwidth `b` (entries `(i, j)` with `|i − j| ≤ b`), stored by rows as
/// its lower band, and factorised in place into `L Lᵀ`.
#[derive(Clone, Debug)]
pub(crate) struct Band {
    n: usize,
    b: usize,
    /// Row i holds columns i − b ..= i at `i·(b + 1) + (j + b − i)`.
    data: Vec<f64>,
    /// 1 / L_ii after [`Band::factor`].
    inverse_diagonal: Vec<f64>,
}

impl Band {
    pub(crate) fn new(n: usize, b: usize) -> Self {
        Self { n, b, data: vec![0.0; n * (b + 1)], inverse_diagonal: vec![0.0; n] }
    }

    /// Clears every entry.
    pub(crate) fn clear(&mut self) {
        self.data.fill(0.0);
    }

    /// Adds `v` to entry (i, j), j ≤ i ≤ j + b.
    #[inline]
    pub(crate) fn add(&mut self, i: usize, j: usize, v: f64) {
        self.data[i * (self.b + 1) + j + self.b - i] += v;
    }

    /// Factorises into `L Lᵀ`; false if a pivot is not positive (the matrix is not positive definite).
    pub(crate) fn factor(&mut self) -> bool {
        let (n, b, w) = (self.n, self.b, self.b + 1);
        for i in 0..n {
            let first = i.saturating_sub(b);
            for j in first..=i {
                let start = first.max(j.saturating_sub(b));
                let (row_i, row_j) = (i * w + b - i, j * w + b - j);
                let mut s = self.data[row_i + j];
                for k in start..j {
                    s -= self.data[row_i + k] * self.data[row_j + k];
                }
                if j < i {
                    self.data[row_i + j] = s * self.inverse_diagonal[j];
                } else {
                    if s.is_nan() || s <= 0.0 {
                        return false;
                    }
                    let d = s.sqrt();
                    self.data[row_i + i] = d;
                    self.inverse_diagonal[i] = 1.0 / d;
                }
            }
        }
        true
    }

    /// Solves `L Lᵀ x = r` in place after [`Band::factor`].
    pub(crate) fn solve(&self, r: &mut [f64]) {
        let (n, b, w) = (self.n, self.b, self.b + 1);
        for i in 0..n {
            let (row, first) = (i * w + b - i, i.saturating_sub(b));
            let s = r[i] - self.data[row + first..row + i].iter().zip(&r[first..i]).fold(0.0, |acc, (l, x)| acc + l * x);
            r[i] = s * self.inverse_diagonal[i];
        }
        for i in (0..n).rev() {
            let s = r[i] * self.inverse_diagonal[i];
            r[i] = s;
            let (row, first) = (i * w + b - i, i.saturating_sub(b));
            for (x, l) in r[first..i].iter_mut().zip(&self.data[row + first..row + i]) {
                *x -= l * s;
            }
        }
    }
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
        assert!(a.factor());
        let mut r = vec![1.0; n];
        a.solve(&mut r);
        for (i, x) in r.iter().enumerate() {
            let k = (i + 1) as f64;
            assert!((x - k * (n as f64 + 1.0 - k) / 2.0).abs() < 1e-12, "{i}: {x}");
        }
    }
}
