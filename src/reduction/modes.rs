//! Symmetric generalized eigenproblem K φ = ω² M φ (M symmetric positive definite).
//!
//! ```text
//! M = L Lᵀ,   C = L⁻¹ K L⁻ᵀ = U Λ Uᵀ,   Φ = L⁻ᵀ U   ⇒   Φᵀ M Φ = I,  Φᵀ K Φ = Λ
//! ```
//!
//! # References
//! - G. H. Golub, C. F. Van Loan (2013), Matrix Computations, 4th ed., §8.7.2.

use faer::linalg::triangular_solve::{
    solve_lower_triangular_in_place, solve_upper_triangular_in_place,
};
use faer::{Mat, MatRef, Par, Side};

use crate::error::ModelError;

/// Mass-normalised eigenpairs, eigenvalues ω² ascending.
#[derive(Clone, Debug)]
pub struct Modes {
    /// Eigenvalues ω² \[rad²/s²\], nondecreasing.
    pub eigenvalues: Vec<f64>,
    /// Mass-normalised mode shapes, one per column.
    pub shapes: Mat<f64>,
}

impl Modes {
    /// Natural frequencies ω = √max(λ, 0) \[rad/s\].
    pub fn angular_frequencies(&self) -> Vec<f64> {
        self.eigenvalues.iter().map(|l| l.max(0.0).sqrt()).collect()
    }
}

/// Solves K φ = λ M φ for symmetric `k` and symmetric positive definite `m`.
pub fn generalized_eigen(k: MatRef<'_, f64>, m: MatRef<'_, f64>) -> Result<Modes, ModelError> {
    let n = k.nrows();
    if n == 0 {
        // No coordinates, no modes (faer's eigensolver does not accept an empty matrix).
        return Ok(Modes {
            eigenvalues: Vec::new(),
            shapes: Mat::zeros(0, 0),
        });
    }
    let llt = m.llt(Side::Lower).map_err(|e| {
        ModelError::Numerical(format!(
            "mass matrix ({n}×{n}) is not positive definite: {e:?}"
        ))
    })?;
    let l = llt.L();
    // X = L⁻¹ K, then C = L⁻¹ Xᵀ = L⁻¹ K L⁻ᵀ.
    let mut x = k.to_owned();
    solve_lower_triangular_in_place(l, x.as_mut(), Par::Seq);
    let mut c = x.transpose().to_owned();
    solve_lower_triangular_in_place(l, c.as_mut(), Par::Seq);
    let c = Mat::from_fn(n, n, |i, j| 0.5 * (c[(i, j)] + c[(j, i)]));
    let evd = c
        .self_adjoint_eigen(Side::Lower)
        .map_err(|e| ModelError::Numerical(format!("eigensolver failed ({n}×{n}): {e:?}")))?;
    let mut shapes = evd.U().to_owned();
    solve_upper_triangular_in_place(l.transpose(), shapes.as_mut(), Par::Seq);
    let s = evd.S().column_vector();
    Ok(Modes {
        eigenvalues: (0..n).map(|i| s[i]).collect(),
        shapes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A system without coordinates has no modes (a pinned–pinned rod reduced to its pins).
    #[test]
    fn empty_system_has_no_modes() {
        let empty = Mat::<f64>::zeros(0, 0);
        let modes = generalized_eigen(empty.as_ref(), empty.as_ref()).unwrap();
        assert!(modes.eigenvalues.is_empty());
        assert_eq!(modes.shapes.nrows(), 0);
    }

    /// Two masses, three springs: ω² = k/m and 3k/m; shapes mass-normalised.
    #[test]
    fn two_degree_of_freedom_chain() {
        let (kk, mm) = (1000.0, 2.0);
        let k = Mat::from_fn(2, 2, |i, j| if i == j { 2.0 * kk } else { -kk });
        let m = Mat::from_fn(2, 2, |i, j| if i == j { mm } else { 0.0 });
        let modes = generalized_eigen(k.as_ref(), m.as_ref()).unwrap();
        assert!((modes.eigenvalues[0] - kk / mm).abs() < 1e-12 * kk);
        assert!((modes.eigenvalues[1] - 3.0 * kk / mm).abs() < 1e-12 * kk);
        let phi = &modes.shapes;
        let gram = phi.transpose() * &m * phi;
        for i in 0..2 {
            for j in 0..2 {
                let expected = if i == j { 1.0 } else { 0.0 };
                assert!((gram[(i, j)] - expected).abs() < 1e-14);
            }
        }
    }

    #[test]
    fn indefinite_mass_is_an_error() {
        let k = Mat::<f64>::identity(2, 2);
        let m = Mat::from_fn(2, 2, |i, j| if i == j { -1.0 } else { 0.0 });
        assert!(matches!(
            generalized_eigen(k.as_ref(), m.as_ref()),
            Err(ModelError::Numerical(_))
        ));
    }
}
