//! Banded Cholesky factor of the rod's constant mass matrix, solved in place without allocation.
//!
//! ```text
//! M = L Lᵀ,  L lower triangular with the bandwidth w of M (w = 7 for the assembled ANCF rod:
//! each element couples 8 consecutive coordinates; w = n − 1 for a dense reduced mass)
//! M x = b  ⇔  L y = b,  Lᵀ x = y          (≈ 2 n (w + 1) multiplications)
//! ```
//! The reduced and full masses are small (4 to 260 coordinates) and the solve runs at every
//! right-hand side, where a generic library call costs more in dispatch than the arithmetic
//! (BENCHMARKS.md, rod kernels).
//!
//! # References
//! - G. H. Golub, C. F. Van Loan (2013), Matrix Computations, 4th ed., §4.3.5 (band Cholesky).

use crate::error::Num;
use faer::MatRef;

use crate::error::ModelError;

/// Largest dense matrix stored as its inverse (the product uses a stack buffer of this size).
const DENSE_LIMIT: usize = 64;

/// L of M = L Lᵀ, row-major with the band only: row i holds L[i][i − w ..= i]; for a dense
/// matrix (w ≥ n/2) also M⁻¹, whose product costs n² instead of 2n(w + 1) with fewer branches.
#[derive(Clone, Debug)]
pub struct BandCholesky {
    n: usize,
    bandwidth: usize,
    /// Row i, entry k ↔ L[i][i + k − w] (k = w is the diagonal).
    rows: Vec<f64>,
    /// M⁻¹ row-major, when dense.
    inverse: Option<Vec<f64>>,
}

impl BandCholesky {
    /// Factorises a symmetric positive definite matrix; the bandwidth is read off its entries.
    pub fn new(m: MatRef<'_, f64>) -> Result<Self, ModelError> {
        let n = m.nrows();
        let bandwidth = (0..n)
            .flat_map(|i| (0..i).map(move |j| (i, j)))
            .filter(|&(i, j)| m[(i, j)] != 0.0)
            .map(|(i, j)| i - j)
            .max()
            .unwrap_or(0);
        let w = bandwidth;
        let mut rows = vec![0.0; n * (w + 1)];
        let at = |i: usize, j: usize| i * (w + 1) + (j + w - i);
        for i in 0..n {
            for j in i.saturating_sub(w)..=i {
                let mut sum = m[(i, j)];
                for k in i.saturating_sub(w).max(j.saturating_sub(w))..j {
                    sum -= rows[at(i, k)] * rows[at(j, k)];
                }
                if i == j {
                    if !(sum > 0.0 && sum.is_finite()) {
                        return Err(ModelError::Numerical(format!(
                            "rod mass matrix is not positive definite (pivot {i} is {})",
                            Num(sum)
                        )));
                    }
                    rows[at(i, i)] = sum.sqrt();
                } else {
                    rows[at(i, j)] = sum / rows[at(j, j)];
                }
            }
        }
        let mut chol = Self {
            n,
            bandwidth,
            rows,
            inverse: None,
        };
        if 2 * bandwidth >= n && n <= DENSE_LIMIT {
            let mut inverse = vec![0.0; n * n];
            for (j, column) in inverse.chunks_exact_mut(n).enumerate() {
                column[j] = 1.0;
                chol.solve_band(column);
            }
            // Columns of a symmetric inverse are its rows.
            chol.inverse = Some(inverse);
        }
        Ok(chol)
    }

    /// Solves M x = b in place.
    pub fn solve(&self, b: &mut [f64]) {
        match &self.inverse {
            Some(inverse) => {
                let n = self.n;
                let mut x = [0.0; DENSE_LIMIT];
                for (xi, row) in x.iter_mut().zip(inverse.chunks_exact(n)) {
                    *xi = row.iter().zip(b.iter()).map(|(a, v)| a * v).sum();
                }
                b.copy_from_slice(&x[..n]);
            }
            None => self.solve_band(b),
        }
    }

    /// Solves M x = b in place by the two banded triangular solves.
    fn solve_band(&self, b: &mut [f64]) {
        let (n, w) = (self.n, self.bandwidth);
        let row = |i: usize| &self.rows[i * (w + 1)..(i + 1) * (w + 1)];
        for i in 0..n {
            let r = row(i);
            let start = i.saturating_sub(w);
            let mut sum = b[i];
            for (j, l) in (start..i).zip(&r[start + w - i..w]) {
                sum -= l * b[j];
            }
            b[i] = sum / r[w];
        }
        for i in (0..n).rev() {
            b[i] /= row(i)[w];
            let bi = b[i];
            let start = i.saturating_sub(w);
            for (j, l) in (start..i).zip(&row(i)[start + w - i..w]) {
                b[j] -= l * bi;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use faer::Mat;

    use super::*;

    /// A tridiagonal and a dense SPD matrix: M x = b to round-off.
    #[test]
    fn solves_banded_and_dense_systems() {
        for dense in [false, true] {
            let n = 9;
            let m = Mat::from_fn(n, n, |i, j| {
                let d = i.abs_diff(j);
                if i == j {
                    4.0 + i as f64
                } else if d == 1 || dense {
                    1.0 / (1.0 + d as f64)
                } else {
                    0.0
                }
            });
            let chol = BandCholesky::new(m.as_ref()).unwrap();
            assert_eq!(chol.bandwidth, if dense { n - 1 } else { 1 });
            let x: Vec<f64> = (0..n).map(|i| crate::math::sin(i as f64) + 2.0).collect();
            let mut b: Vec<f64> = (0..n)
                .map(|i| (0..n).map(|j| m[(i, j)] * x[j]).sum())
                .collect();
            chol.solve(&mut b);
            for (a, e) in b.iter().zip(&x) {
                assert!((a - e).abs() < 1e-14 * 10.0, "{a} vs {e}");
            }
        }
        let indefinite = Mat::from_fn(2, 2, |i, j| if i == j { -1.0 } else { 0.0 });
        assert!(BandCholesky::new(indefinite.as_ref()).is_err());
    }
}
