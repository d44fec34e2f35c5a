//! Craig–Bampton basis of the ANCF rod with isotropic fixed-interface modes.
//!
//! ```text
//! e ≈ V p,   V = [ I   0  ]   (boundary rows: both end nodes, 8 coordinates)
//!                [ Ψ   Φ_m ]  (interior rows)
//! Ψ = −K_ii⁻¹ K_ib            static constraint modes
//! (K_ii − ω² M_ii) φ = 0       fixed-interface normal modes, mass-normalised, m lowest kept
//! M̄ = Vᵀ M V (constant),   Q̄(p, ṗ) = Vᵀ Q(V p, V ṗ),   K̄_T = Vᵀ K_T(V p) V
//! ```
//! K and M are the rod's scalar reference matrices ⊗ I₂ (bending stiffness EI ∫ s''s''ᵀ and the
//! consistent mass), so every mode shape enters in both Cartesian directions and the reduced space
//! does not depend on the rod's orientation (MODEL.md §2). With global ordering the whole basis is
//! V = v ⊗ I₂ for a scalar basis v of size 2(n+1) × (4 + m): reduced coordinates are
//! p = [r₀, r₀,ₓ, r_n, r_n,ₓ, η₁ₓ, η₁ᵧ, …, η_mₓ, η_mᵧ].
//!
//! # References
//! - R. R. Craig, M. C. C. Bampton (1968), Coupling of substructures for dynamic analyses, AIAA J. 6,
//!   1313–1319.
//! - Sun et al. (2015), Mech. Mach. Theory 85, eqs. (2)–(3) (read as q ≈ V p).
//! - MODEL.md §2 and §10 (mode count, isotropic pairs).

use faer::linalg::matmul::matmul;
use faer::reborrow::{Reborrow, ReborrowMut};
use faer::{Accum, Mat, MatMut, MatRef, Par, Side, linalg::solvers::Solve};

use super::modes::generalized_eigen;
use crate::ancf::Rod;
use crate::ancf::rod::kron_identity;
use crate::error::ModelError;

/// A Craig–Bampton reduction of a [`Rod`] with `n_modes` fixed-interface mode shapes.
#[derive(Clone, Debug)]
pub struct CraigBampton {
    n_modes: usize,
    scalar_basis: Mat<f64>,
    basis: Mat<f64>,
    mass: Mat<f64>,
    mode_frequencies: Vec<f64>,
}

/// Largest mode count for a rod of `n_elements`: 2(n − 1), the interior scalar coordinates.
pub fn max_modes(n_elements: usize) -> usize {
    2 * n_elements.saturating_sub(1)
}

impl CraigBampton {
    /// Builds the basis for `rod` keeping `n_modes` ∈ [0, 2(n − 1)] mode shapes (0 = Guyan).
    pub fn new(rod: &Rod, n_modes: usize) -> Result<Self, ModelError> {
        let n = rod.n_elements();
        let max = max_modes(n);
        if n_modes > max {
            return Err(ModelError::invalid(
                "rod.nModes",
                n_modes as f64,
                format!("[0, {max}] (= 2 (rod.nElements - 1) with rod.nElements = {n})"),
            ));
        }
        let k = rod.scalar_bending_stiffness();
        let m = rod.scalar_mass_matrix();
        let n_scalar = 2 * (n + 1);
        let boundary = [0, 1, n_scalar - 2, n_scalar - 1];
        let n_interior = n_scalar - 4;
        // Interior scalar coordinates are 2..2n, contiguous.
        let interior = |i: usize| i + 2;
        let k_ii = Mat::from_fn(n_interior, n_interior, |i, j| k[(interior(i), interior(j))]);
        let m_ii = Mat::from_fn(n_interior, n_interior, |i, j| m[(interior(i), interior(j))]);
        let k_ib = Mat::from_fn(n_interior, 4, |i, j| -k[(interior(i), boundary[j])]);

        let mut scalar_basis = Mat::zeros(n_scalar, 4 + n_modes);
        for (j, &b) in boundary.iter().enumerate() {
            scalar_basis[(b, j)] = 1.0;
        }
        let mut mode_frequencies = Vec::new();
        if n_interior > 0 {
            let llt = k_ii.llt(Side::Lower).map_err(|e| {
                ModelError::Numerical(format!(
                    "interior stiffness is not positive definite: {e:?}"
                ))
            })?;
            let psi = llt.solve(&k_ib);
            let modes = generalized_eigen(k_ii.as_ref(), m_ii.as_ref())?;
            for i in 0..n_interior {
                for j in 0..4 {
                    scalar_basis[(interior(i), j)] = psi[(i, j)];
                }
                for j in 0..n_modes {
                    scalar_basis[(interior(i), 4 + j)] = modes.shapes[(i, j)];
                }
            }
            mode_frequencies = modes.angular_frequencies()[..n_modes].to_vec();
        }
        let scalar_mass = scalar_basis.transpose() * &m * &scalar_basis;
        Ok(Self {
            n_modes,
            basis: kron_identity(&scalar_basis),
            mass: kron_identity(&scalar_mass),
            scalar_basis,
            mode_frequencies,
        })
    }

    /// Number of kept mode shapes m.
    pub fn n_modes(&self) -> usize {
        self.n_modes
    }

    /// Number of reduced coordinates 8 + 2m.
    pub fn n_coordinates(&self) -> usize {
        8 + 2 * self.n_modes
    }

    /// Fixed-interface natural frequencies ω \[rad/s\] of the kept mode shapes.
    pub fn mode_frequencies(&self) -> &[f64] {
        &self.mode_frequencies
    }

    /// Full basis V (4(n+1) × (8 + 2m)).
    pub fn basis(&self) -> MatRef<'_, f64> {
        self.basis.as_ref()
    }

    /// Constant reduced mass M̄ = Vᵀ M V.
    pub fn mass_matrix(&self) -> MatRef<'_, f64> {
        self.mass.as_ref()
    }

    /// Nodal coordinates e = V p, written to `e`.
    ///
    /// Computed as E = v P on the (·, 2) row-major views of e and p (V = v ⊗ I₂).
    pub fn expand(&self, p: &[f64], e: &mut [f64]) {
        let cols = self.scalar_basis.ncols();
        let rows = self.scalar_basis.nrows();
        matmul(
            MatMut::from_row_major_slice_mut(e, rows, 2),
            Accum::Replace,
            self.scalar_basis.as_ref(),
            MatRef::from_row_major_slice(p, cols, 2),
            1.0,
            Par::Seq,
        );
    }

    /// Generalised force in reduced coordinates Vᵀ q, written to `out`.
    pub fn project(&self, q: &[f64], out: &mut [f64]) {
        let cols = self.scalar_basis.ncols();
        let rows = self.scalar_basis.nrows();
        matmul(
            MatMut::from_row_major_slice_mut(out, cols, 2),
            Accum::Replace,
            self.scalar_basis.transpose(),
            MatRef::from_row_major_slice(q, rows, 2),
            1.0,
            Par::Seq,
        );
    }

    /// Reduced matrix Vᵀ A V of a full square matrix `a`, written to `out`; `work` is 4(n+1) × (8 + 2m).
    pub fn project_matrix(
        &self,
        a: MatRef<'_, f64>,
        mut work: MatMut<'_, f64>,
        out: MatMut<'_, f64>,
    ) {
        matmul(
            work.rb_mut(),
            Accum::Replace,
            a,
            self.basis.as_ref(),
            1.0,
            Par::Seq,
        );
        matmul(
            out,
            Accum::Replace,
            self.basis.transpose(),
            work.rb(),
            1.0,
            Par::Seq,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ancf::RodProperties;

    #[test]
    fn too_many_modes_is_an_error_naming_the_limit() {
        let rod = Rod::new(RodProperties::benchmark_b(), 4).unwrap();
        let err = CraigBampton::new(&rod, 7).unwrap_err();
        assert_eq!(
            err.to_string(),
            "rod.nModes = 7 is outside the allowed range [0, 6] (= 2 (rod.nElements - 1) with \
             rod.nElements = 4)"
        );
        assert!(CraigBampton::new(&rod, 6).is_ok());
        let single = Rod::new(RodProperties::benchmark_b(), 1).unwrap();
        let guyan = CraigBampton::new(&single, 0).unwrap();
        assert_eq!(guyan.n_coordinates(), 8);
        assert!(CraigBampton::new(&single, 1).is_err());
    }
}
