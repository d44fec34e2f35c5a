//! Craig–Bampton basis of the ANCF rod with isotropic fixed-interface modes.
//!
//! ```text
//! e ≈ V p,   V = [ I   0  ]   (boundary rows)
//!                [ Ψ   Φ_m ]  (interior rows)
//! Ψ = −K_ii⁻¹ K_ib            static constraint modes
//! (K_ii − ω² M_ii) φ = 0       fixed-interface normal modes, mass-normalised, m lowest kept
//! M̄ = Vᵀ M V (constant),   Q̄(p, ṗ) = Vᵀ Q(V p, V ṗ),   K̄_T = Vᵀ K_T(V p) V
//! ```
//! K and M are the rod's scalar reference matrices ⊗ I₂ (bending stiffness EI ∫ s''s''ᵀ and the
//! consistent mass), so every mode shape enters in both Cartesian directions and the reduced space
//! does not depend on the rod's orientation (docs/model.md §2). With global ordering the whole basis is
//! V = v ⊗ I₂ for a scalar basis v of size 2(n+1) × (b + m), b boundary coordinates per direction.
//!
//! Two interfaces ([`Boundary`]):
//! - **positions and slopes** of both end nodes (Sun et al. 2015): b = 4, p = [r₀, r₀,ₓ, r_n, r_n,ₓ,
//!   η₁, …, η_m] (each a 2-vector). Ψ interpolates the ends by the cubic Hermite field; the
//!   fixed-interface modes are clamped–clamped. The end slopes carry the rod's axial strain at the
//!   ends with almost no mass: the reduced rod keeps frequencies near the full model's highest
//!   (measured ω_max ≈ 1.6e6 rad/s for 8 elements, 4 modes).
//! - **pins**: the two joint positions only: b = 2, p = [r₀, r_n, η₁, …, η_m]. Ψ is the linear
//!   interpolation between the pins (rigid motion and uniform stretch, exactly); end slopes and
//!   interior nodes are spanned by the pinned–pinned modes, whose profiles sin(kπx/L) are both the
//!   bending modes (transverse direction) and the fixed–fixed axial modes (axial direction), so
//!   the first axial modes are in the basis and the highest frequency is that of the last kept one.
//!
//! `nModes` counts fixed-interface mode shapes in both cases; the pin interface has 4 coordinates
//! fewer for the same count, and `nModes` = 0 is a straight, extensible rod.
//!
//! # References
//! - R. R. Craig, M. C. C. Bampton (1968), Coupling of substructures for dynamic analyses, AIAA J. 6,
//!   1313–1319.
//! - Sun et al. (2015), Mech. Mach. Theory 85, eqs. (2)–(3) (read as q ≈ V p).
//! - docs/model.md §2 and §7 (mode count, isotropic pairs; positions-only interface "also valid because
//!   both joints are pins").

use faer::linalg::matmul::matmul;
use faer::reborrow::{Reborrow, ReborrowMut};
use faer::{Accum, Mat, MatMut, MatRef, Par, Side, linalg::solvers::Solve};

use super::modes::generalized_eigen;
use crate::ancf::Rod;
use crate::ancf::rod::kron_identity;
use crate::error::ModelError;

/// The coordinates of the rod that stay physical in the reduction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Boundary {
    /// Positions and slopes of both end nodes (Sun et al. 2015); clamped–clamped interior modes.
    PositionsAndSlopes,
    /// The two pin positions; pinned–pinned interior modes span the end slopes too.
    Pins,
}

impl Boundary {
    /// Scalar boundary coordinates (per direction) of a rod of `n_elements`: indices into
    /// [r₀, r₀,ₓ, r₁, r₁,ₓ, …, r_n, r_n,ₓ].
    fn scalar_indices(self, n_elements: usize) -> Vec<usize> {
        let last = 2 * n_elements;
        match self {
            Self::PositionsAndSlopes => vec![0, 1, last, last + 1],
            Self::Pins => vec![0, last],
        }
    }
}

/// Checks `rod.nModes` ≤ [`max_modes`]; the error states the rule and the element count.
pub fn check_mode_count(
    n_elements: usize,
    n_modes: usize,
    boundary: Boundary,
) -> Result<(), ModelError> {
    let max = max_modes(n_elements, boundary);
    if n_modes <= max {
        return Ok(());
    }
    let rule = match boundary {
        Boundary::PositionsAndSlopes => "2 (rod.nElements - 1)",
        Boundary::Pins => "2 rod.nElements",
    };
    Err(ModelError::invalid(
        "rod.nModes",
        n_modes as f64,
        format!("[0, {max}] (at most {rule} = {max} with rod.nElements = {n_elements})"),
    ))
}

/// A Craig–Bampton reduction of a [`Rod`] with `n_modes` fixed-interface mode shapes.
#[derive(Clone, Debug)]
pub struct CraigBampton {
    boundary: Boundary,
    n_boundary: usize,
    n_modes: usize,
    scalar_basis: Mat<f64>,
    /// The scalar basis v, row-major, for the hot-path products.
    scalar_rows: Vec<f64>,
    basis: Mat<f64>,
    mass: Mat<f64>,
    mode_frequencies: Vec<f64>,
}

/// Largest mode count for a rod of `n_elements`: the number of interior scalar coordinates,
/// 2(n − 1) with the positions-and-slopes interface, 2n with the pin interface.
pub fn max_modes(n_elements: usize, boundary: Boundary) -> usize {
    2 * (n_elements + 1) - boundary.scalar_indices(n_elements).len()
}

impl CraigBampton {
    /// Builds the basis for `rod` with the given interface, keeping `n_modes` ∈ [0, max] mode
    /// shapes (0 = Guyan).
    pub fn new(rod: &Rod, n_modes: usize, boundary: Boundary) -> Result<Self, ModelError> {
        let n = rod.n_elements();
        check_mode_count(n, n_modes, boundary)?;
        let k = rod.scalar_bending_stiffness();
        let m = rod.scalar_mass_matrix();
        let n_scalar = 2 * (n + 1);
        let boundary_rows = boundary.scalar_indices(n);
        let interior: Vec<usize> = (0..n_scalar)
            .filter(|i| !boundary_rows.contains(i))
            .collect();
        let (n_b, n_i) = (boundary_rows.len(), interior.len());
        let k_ii = Mat::from_fn(n_i, n_i, |i, j| k[(interior[i], interior[j])]);
        let m_ii = Mat::from_fn(n_i, n_i, |i, j| m[(interior[i], interior[j])]);
        let k_ib = Mat::from_fn(n_i, n_b, |i, j| -k[(interior[i], boundary_rows[j])]);

        let mut scalar_basis = Mat::zeros(n_scalar, n_b + n_modes);
        for (j, &b) in boundary_rows.iter().enumerate() {
            scalar_basis[(b, j)] = 1.0;
        }
        let mut mode_frequencies = Vec::new();
        if n_i > 0 {
            let llt = k_ii.llt(Side::Lower).map_err(|e| {
                ModelError::Numerical(format!(
                    "interior stiffness is not positive definite: {e:?}"
                ))
            })?;
            let psi = llt.solve(&k_ib);
            let modes = generalized_eigen(k_ii.as_ref(), m_ii.as_ref())?;
            for (i, &row) in interior.iter().enumerate() {
                for j in 0..n_b {
                    scalar_basis[(row, j)] = psi[(i, j)];
                }
                for j in 0..n_modes {
                    scalar_basis[(row, n_b + j)] = modes.shapes[(i, j)];
                }
            }
            mode_frequencies = modes.angular_frequencies()[..n_modes].to_vec();
        }
        let scalar_mass = scalar_basis.transpose() * &m * &scalar_basis;
        Ok(Self {
            boundary,
            n_boundary: n_b,
            n_modes,
            basis: kron_identity(&scalar_basis),
            scalar_rows: (0..scalar_basis.nrows())
                .flat_map(|i| (0..scalar_basis.ncols()).map(move |j| (i, j)))
                .map(|(i, j)| scalar_basis[(i, j)])
                .collect(),
            mass: kron_identity(&scalar_mass),
            scalar_basis,
            mode_frequencies,
        })
    }

    /// The interface.
    pub fn boundary(&self) -> Boundary {
        self.boundary
    }

    /// Offset of the slider-end position r_n in p.
    pub fn end_node_offset(&self) -> usize {
        self.n_boundary
    }

    /// Row of the scalar basis v for scalar nodal coordinate `i`: r_i (per direction) = Σⱼ vᵢⱼ pⱼ.
    pub fn scalar_row(&self, i: usize) -> impl Iterator<Item = f64> + '_ {
        (0..self.scalar_basis.ncols()).map(move |j| self.scalar_basis[(i, j)])
    }

    /// The reduced coordinates of the straight, unstressed rod of length `length` from the origin
    /// along x: the interface of its end nodes (positions, and unit slopes), no modal amplitude.
    pub fn straight_coordinates(&self, length: f64) -> Vec<f64> {
        let ends: &[f64] = match self.boundary {
            Boundary::Pins => &[0.0, 0.0, length, 0.0],
            Boundary::PositionsAndSlopes => &[0.0, 0.0, 1.0, 0.0, length, 0.0, 1.0, 0.0],
        };
        let mut p = ends.to_vec();
        p.resize(self.n_coordinates(), 0.0);
        p
    }

    /// Number of kept mode shapes m.
    pub fn n_modes(&self) -> usize {
        self.n_modes
    }

    /// Number of reduced coordinates 2(b + m): 8 + 2m (positions and slopes) or 4 + 2m (pins).
    pub fn n_coordinates(&self) -> usize {
        2 * (self.n_boundary + self.n_modes)
    }

    /// Fixed-interface natural frequencies ω \[rad/s\] of the kept mode shapes.
    pub fn mode_frequencies(&self) -> &[f64] {
        &self.mode_frequencies
    }

    /// Full basis V (4(n+1) × 2(b + m)).
    pub fn basis(&self) -> MatRef<'_, f64> {
        self.basis.as_ref()
    }

    /// Constant reduced mass M̄ = Vᵀ M V.
    pub fn mass_matrix(&self) -> MatRef<'_, f64> {
        self.mass.as_ref()
    }

    /// Nodal coordinates e = V p, written to `e`: e₂ᵢ₊d = Σⱼ vᵢⱼ p₂ⱼ₊d (V = v ⊗ I₂).
    pub fn expand(&self, p: &[f64], e: &mut [f64]) {
        let cols = self.scalar_basis.ncols();
        for (row, out) in self
            .scalar_rows
            .chunks_exact(cols)
            .zip(e.chunks_exact_mut(2))
        {
            let (mut x, mut y) = (0.0, 0.0);
            for (v, pj) in row.iter().zip(p.chunks_exact(2)) {
                x += v * pj[0];
                y += v * pj[1];
            }
            out[0] = x;
            out[1] = y;
        }
    }

    /// Generalised force in reduced coordinates Vᵀ q, written to `out`:
    /// out₂ⱼ₊d = Σᵢ vᵢⱼ q₂ᵢ₊d.
    pub fn project(&self, q: &[f64], out: &mut [f64]) {
        let cols = self.scalar_basis.ncols();
        out.fill(0.0);
        for (row, qi) in self.scalar_rows.chunks_exact(cols).zip(q.chunks_exact(2)) {
            for (v, o) in row.iter().zip(out.chunks_exact_mut(2)) {
                o[0] += v * qi[0];
                o[1] += v * qi[1];
            }
        }
    }

    /// Reduced matrix Vᵀ A V of a full square matrix `a`, written to `out`; `work` is 4(n+1) × 2(b + m).
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
        let err = CraigBampton::new(&rod, 7, Boundary::PositionsAndSlopes).unwrap_err();
        assert_eq!(
            err.to_string(),
            "rod.nModes = 7 is outside the allowed range [0, 6] (at most 2 (rod.nElements - 1) = 6 \
             with rod.nElements = 4)"
        );
        assert!(CraigBampton::new(&rod, 6, Boundary::PositionsAndSlopes).is_ok());
        let err = CraigBampton::new(&rod, 9, Boundary::Pins).unwrap_err();
        assert!(
            err.to_string()
                .contains("[0, 8] (at most 2 rod.nElements = 8"),
            "{err}"
        );
        assert!(CraigBampton::new(&rod, 8, Boundary::Pins).is_ok());
        let single = Rod::new(RodProperties::benchmark_b(), 1).unwrap();
        let guyan = CraigBampton::new(&single, 0, Boundary::PositionsAndSlopes).unwrap();
        assert_eq!(guyan.n_coordinates(), 8);
        assert!(CraigBampton::new(&single, 1, Boundary::PositionsAndSlopes).is_err());
        let pins = CraigBampton::new(&single, 2, Boundary::Pins).unwrap();
        assert_eq!(pins.n_coordinates(), 8);
    }

    /// With the pin interface the static modes are the linear interpolation between the pins and
    /// the fixed-interface modes are the pinned–pinned ones: every kept mode vanishes at both
    /// pins, and the first frequency is close to Euler–Bernoulli's π² √(EI/ρAL⁴) (8 elements:
    /// discretisation error ≈ 1e-5, bound 1e-4).
    #[test]
    fn pin_interface_is_linear_plus_pinned_modes() {
        let props = RodProperties::benchmark_b();
        let rod = Rod::new(props, 8).unwrap();
        let cb = CraigBampton::new(&rod, 3, Boundary::Pins).unwrap();
        let n_scalar = 18;
        for i in 0..=8 {
            let xi = i as f64 / 8.0;
            let row: Vec<f64> = cb.scalar_row(2 * i).collect();
            assert!((row[0] - (1.0 - xi)).abs() < 1e-12 && (row[1] - xi).abs() < 1e-12);
            let slope: Vec<f64> = cb.scalar_row(2 * i + 1).collect();
            assert!((slope[0] + 1.0 / props.length).abs() < 1e-9);
            assert!((slope[1] - 1.0 / props.length).abs() < 1e-9);
        }
        for j in 2..5 {
            assert!(cb.scalar_basis[(0, j)].abs() < 1e-15);
            assert!(cb.scalar_basis[(n_scalar - 2, j)].abs() < 1e-15);
        }
        let ei = props.youngs_modulus * props.second_moment_of_area;
        let rho_a = props.density * props.area;
        let exact = std::f64::consts::PI.powi(2) * (ei / (rho_a * props.length.powi(4))).sqrt();
        let w1 = cb.mode_frequencies()[0];
        assert!((w1 - exact).abs() < 1e-4 * exact, "{w1} vs {exact}");
    }
}
