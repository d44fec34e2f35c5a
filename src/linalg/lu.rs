//! Dense LU factorisation with partial pivoting for the small Newton matrices of the implicit
//! integrator, in preallocated storage (no allocation after construction).
//!
//! ```text
//! P A = L U,   A x = b  ⇔  L y = P b,  U x = y
//! ```
//! The matrices are those of the mechanism's coordinates (14 to 40 for the reduced and 8-element
//! rods), where a generic library call costs more in dispatch than the arithmetic (BENCHMARKS.md).
//!
//! # References
//! - G. H. Golub, C. F. Van Loan (2013), Matrix Computations, 4th ed., §3.4 (Algorithm 3.4.1).

use crate::error::ModelError;
use crate::error::Num;

/// An n × n matrix factorised in place (column-major), with its row permutation.
#[derive(Clone, Debug)]
pub struct Lu {
    n: usize,
    /// L (unit lower, below the diagonal) and U (on and above it), column-major.
    factors: Vec<f64>,
    pivots: Vec<usize>,
}

impl Lu {
    /// Storage for an n × n factorisation.
    pub fn new(n: usize) -> Self {
        Self {
            n,
            factors: vec![0.0; n * n],
            pivots: vec![0; n],
        }
    }

    /// The column-major matrix to factorise: fill it, then call [`Lu::factorize`].
    pub fn matrix_mut(&mut self) -> &mut [f64] {
        &mut self.factors
    }

    /// Factorises the matrix in place; fails on an exactly singular or non-finite pivot.
    pub fn factorize(&mut self) -> Result<(), ModelError> {
        let n = self.n;
        let a = &mut self.factors;
        for k in 0..n {
            let (mut p, mut best) = (k, a[k * n + k].abs());
            for i in k + 1..n {
                let v = a[k * n + i].abs();
                if v > best {
                    (p, best) = (i, v);
                }
            }
            if !(best > 0.0 && best.is_finite()) {
                return Err(ModelError::Numerical(format!(
                    "singular Newton matrix (pivot {k} of {n} is {})",
                    Num(best)
                )));
            }
            self.pivots[k] = p;
            if p != k {
                for j in 0..n {
                    a.swap(j * n + k, j * n + p);
                }
            }
            let inv = 1.0 / a[k * n + k];
            for i in k + 1..n {
                a[k * n + i] *= inv;
            }
            for j in k + 1..n {
                let u = a[j * n + k];
                if u != 0.0 {
                    for i in k + 1..n {
                        a[j * n + i] -= a[k * n + i] * u;
                    }
                }
            }
        }
        Ok(())
    }

    /// Solves A x = b in place.
    pub fn solve(&self, b: &mut [f64]) {
        let n = self.n;
        for (k, &p) in self.pivots.iter().enumerate() {
            b.swap(k, p);
        }
        for (k, column) in self.factors.chunks_exact(n).enumerate() {
            let bk = b[k];
            if bk != 0.0 {
                for (bi, l) in b[k + 1..].iter_mut().zip(&column[k + 1..]) {
                    *bi -= l * bk;
                }
            }
        }
        for (k, column) in self.factors.chunks_exact(n).enumerate().rev() {
            b[k] /= column[k];
            let bk = b[k];
            for (bi, u) in b[..k].iter_mut().zip(&column[..k]) {
                *bi -= u * bk;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A random non-symmetric system that needs pivoting (zero leading entry): A x = b to
    /// round-off (cond(A) ≈ 1e2, so 1e-13 relative).
    #[test]
    fn solves_a_system_that_needs_pivoting() {
        let n = 7;
        let mut lu = Lu::new(n);
        let mut seed = 12345u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let a: Vec<f64> = (0..n * n)
            .map(|k| if k == 0 { 0.0 } else { next() } + if k % (n + 1) == 0 { 2.0 } else { 0.0 })
            .collect();
        let a = {
            let mut a = a;
            a[0] = 0.0;
            a
        };
        let x: Vec<f64> = (0..n).map(|i| 1.0 + i as f64).collect();
        let mut b: Vec<f64> = (0..n)
            .map(|i| (0..n).map(|j| a[j * n + i] * x[j]).sum())
            .collect();
        lu.matrix_mut().copy_from_slice(&a);
        lu.factorize().unwrap();
        lu.solve(&mut b);
        for (xi, bi) in x.iter().zip(&b) {
            assert!((xi - bi).abs() < 1e-13 * 7.0, "{xi} vs {bi}");
        }
    }

    #[test]
    fn singular_matrix_is_an_error() {
        let mut lu = Lu::new(2);
        lu.matrix_mut().copy_from_slice(&[1.0, 2.0, 2.0, 4.0]);
        assert!(lu.factorize().is_err());
    }
}
