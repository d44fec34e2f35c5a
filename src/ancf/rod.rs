//! The rod: n equal planar ANCF elements in a row, assembled.
//!
//! Global coordinates are node by node, e = [r₀, r₀,ₓ, r₁, r₁,ₓ, …, r_n, r_n,ₓ] ∈ ℝ^{4(n+1)}, so element j
//! owns the contiguous slice 4j .. 4j + 8 and assembly is a sum of overlapping blocks.
//! The boundary coordinates (the Craig–Bampton interface) are the two end nodes, 0..4 and 4n..4n+4.
//!
//! Vectors are plain slices (`&[f64]`), matrices faer `Mat`, so the per-step force evaluation
//! allocates nothing.
//!
//! # References
//! - docs/model.md §1; A. A. Shabana (2005), Dynamics of Multibody Systems, ch. 7.

use faer::{Mat, MatMut};
use nalgebra::Vector2;

use super::element::{Element, ElementVector, Section};
use crate::error::{ModelError, require_non_negative, require_positive};
use crate::math;

/// Largest number of elements a rod may have.
pub const MAX_ELEMENTS: usize = 64;

/// Material and geometry of the rod (SI units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RodProperties {
    /// Reference length L \[m\].
    pub length: f64,
    /// Young's modulus E \[Pa\].
    pub youngs_modulus: f64,
    /// Density ρ \[kg/m³\].
    pub density: f64,
    /// Cross-section area A \[m²\].
    pub area: f64,
    /// Second moment of area I \[m⁴\].
    pub second_moment_of_area: f64,
    /// Outer-fibre distance c: the largest distance of the section from its neutral axis (h/2
    /// for a rectangle of height h) \[m\].
    pub outer_fibre_distance: f64,
    /// Strain-rate (stiffness-proportional) damping coefficient β \[s\]; 0 = undamped.
    pub stiffness_damping: f64,
    /// The damping ratio ζ₁ of the first pinned–pinned bending mode, which sets β = 2ζ₁/ω₁ when
    /// it is not 0 ([`RodProperties::damping`]; at most one of the two is set).
    pub damping_ratio: f64,
    /// Mass lumped at the crank-pin centre (the rod's big eye, its bush and bolts) \[kg\]: part
    /// of the rod's inertia and weight, not of its beam (the ANCF element carries ρ A only; the
    /// mechanism adds it at the pin).
    pub crank_end_mass: f64,
    /// Mass lumped at the slider-pin centre (the small eye) \[kg\].
    pub slider_end_mass: f64,
}

impl RodProperties {
    /// The steel rod of benchmark B (docs/model.md §5(b)): L = 0.12 m, E = 207 GPa, ρ = 7800 kg/m³,
    /// A = 2.2436e-4 m² (mass 0.21 kg), I = 4.195e-9 m⁴ (a 14.98 mm square: c = 7.49 mm), undamped.
    pub fn benchmark_b() -> Self {
        Self {
            length: 0.12,
            youngs_modulus: 207e9,
            density: 7800.0,
            area: 0.21 / (7800.0 * 0.12),
            second_moment_of_area: 4.195e-9,
            outer_fibre_distance: 7.4893e-3,
            stiffness_damping: 0.0,
            damping_ratio: 0.0,
            crank_end_mass: 0.0,
            slider_end_mass: 0.0,
        }
    }

    /// Checks every property; the error names the FMU parameter.
    pub fn validate(&self) -> Result<(), ModelError> {
        require_positive("rod.length", self.length)?;
        require_positive("rod.youngsModulus", self.youngs_modulus)?;
        require_positive("rod.density", self.density)?;
        require_positive("rod.area", self.area)?;
        require_positive("rod.secondMomentOfArea", self.second_moment_of_area)?;
        require_positive("rod.outerFibreDistance", self.outer_fibre_distance)?;
        require_non_negative("rod.stiffnessDamping", self.stiffness_damping)?;
        require_non_negative("rod.dampingRatio", self.damping_ratio)?;
        require_non_negative("rod.crankEndMass", self.crank_end_mass)?;
        require_non_negative("rod.sliderEndMass", self.slider_end_mass)?;
        Ok(())
    }

    /// The beam's mass ρ A L \[kg\] (without the end masses).
    pub fn mass(&self) -> f64 {
        self.density * self.area * self.length
    }

    /// The rod's whole mass: the beam's and the end masses \[kg\].
    pub fn total_mass(&self) -> f64 {
        self.mass() + self.crank_end_mass + self.slider_end_mass
    }

    /// The end masses at the crank pin and at the slider pin \[kg\].
    pub fn end_masses(&self) -> [f64; 2] {
        [self.crank_end_mass, self.slider_end_mass]
    }

    /// The strain-rate damping coefficient β the rod is integrated with \[s\]: 2ζ₁/ω₁ when the
    /// damping ratio ζ₁ of its first pinned–pinned bending mode (ω₁,
    /// [`RodProperties::first_bending_frequency`]) is given, else `stiffness_damping`. Being
    /// stiffness-proportional, it damps every mode k at ζ_k = β ω_k / 2 = ζ₁ ω_k/ω₁: the rod's
    /// higher bending modes (ω_k ≈ k² ω₁ pinned–pinned) and its axial modes more.
    pub fn damping(&self) -> f64 {
        if self.damping_ratio > 0.0 {
            2.0 * self.damping_ratio / self.first_bending_frequency()
        } else {
            self.stiffness_damping
        }
    }

    /// First axial frequency of the rod held at both ends, ω = (π/L) √(E/ρ) \[rad/s\].
    pub fn first_axial_frequency(&self) -> f64 {
        std::f64::consts::PI / self.length * (self.youngs_modulus / self.density).sqrt()
    }

    /// First bending frequency of the rod pinned at both ends (Euler–Bernoulli),
    /// ω₁ = (π/L)² √(EI/ρA) \[rad/s\].
    pub fn first_bending_frequency(&self) -> f64 {
        (std::f64::consts::PI / self.length).powi(2)
            * (self.youngs_modulus * self.second_moment_of_area / (self.density * self.area)).sqrt()
    }
}

/// The normal stresses of a rod in one state ([`Rod::normal_stresses`]; SI units).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NormalStresses {
    /// The largest magnitude over the rod, |N|/A + |M| c/I \[Pa\].
    pub largest: f64,
    /// The most tensile fibre's stress, max (N/A + |M| c/I) \[Pa\].
    pub max: f64,
    /// The most compressive fibre's stress, min (N/A − |M| c/I) \[Pa\].
    pub min: f64,
    /// Where the largest magnitude lies, a fraction of the rod's length from the crank pin.
    pub location: f64,
    /// The axial force at mid-span, tension positive \[N\].
    pub midspan_axial_force: f64,
    /// The bending moment at mid-span, positive where the rod turns left (counter-clockwise
    /// curvature) \[N m\].
    pub midspan_moment: f64,
}

/// An assembled ANCF rod of `n` equal elements.
#[derive(Clone, Debug)]
pub struct Rod {
    properties: RodProperties,
    n_elements: usize,
    element: Element,
    /// The element's quarter pieces for the stress scan ([`Rod::normal_stresses`]).
    quarters: crate::ancf::quarters::Quarters,
}

impl Rod {
    /// A rod of `n_elements` ∈ [1, [`MAX_ELEMENTS`]] equal elements.
    pub fn new(properties: RodProperties, n_elements: usize) -> Result<Self, ModelError> {
        properties.validate()?;
        if !(1..=MAX_ELEMENTS).contains(&n_elements) {
            return Err(ModelError::invalid(
                "rod.nElements",
                n_elements as f64,
                format!("[1, {MAX_ELEMENTS}]"),
            ));
        }
        let p = &properties;
        let section = Section {
            ea: p.youngs_modulus * p.area,
            ei: p.youngs_modulus * p.second_moment_of_area,
            rho_a: p.density * p.area,
            damping: p.damping(),
        };
        let element = Element::new(section, p.length / n_elements as f64);
        Ok(Self {
            properties,
            n_elements,
            element,
            quarters: crate::ancf::quarters::Quarters::new(element.length()),
        })
    }

    /// Material and geometry.
    pub fn properties(&self) -> &RodProperties {
        &self.properties
    }

    /// The (common) element.
    pub fn element(&self) -> &Element {
        &self.element
    }

    /// Number of elements n.
    pub fn n_elements(&self) -> usize {
        self.n_elements
    }

    /// Number of nodal coordinates 4(n + 1).
    pub fn n_coordinates(&self) -> usize {
        4 * (self.n_elements + 1)
    }

    /// Offset of the last node's coordinates (4n).
    pub fn last_node_offset(&self) -> usize {
        4 * self.n_elements
    }

    /// Coordinates of a straight, unstressed rod starting at `origin` with unit direction at `angle`
    /// \[rad\]: node k at origin + xₖ t, slope t.
    pub fn straight_configuration(&self, origin: Vector2<f64>, angle: f64) -> Vec<f64> {
        let t = Vector2::new(math::cos(angle), math::sin(angle));
        let l = self.element.length();
        (0..=self.n_elements)
            .flat_map(|k| {
                let r = origin + (k as f64 * l) * t;
                [r.x, r.y, t.x, t.y]
            })
            .collect()
    }

    fn element_coordinates(e: &[f64], j: usize) -> ElementVector {
        ElementVector::from_column_slice(&e[4 * j..4 * j + 8])
    }

    /// Assembles element vectors: out = Σⱼ (element j's vector on its slice 4j .. 4j + 8).
    fn assemble(&self, out: &mut [f64], mut element_vector: impl FnMut(usize) -> ElementVector) {
        out.fill(0.0);
        for j in 0..self.n_elements {
            let q = element_vector(j);
            for (o, v) in out[4 * j..4 * j + 8].iter_mut().zip(q.iter()) {
                *o += v;
            }
        }
    }

    /// Internal force (elastic + strain-rate damping) Q(e, ė), written to `out`; returns the
    /// power the damping dissipates, ėᵀQ_d ≥ 0 \[W\].
    pub fn internal_force(&self, e: &[f64], e_dot: &[f64], out: &mut [f64]) -> f64 {
        let mut power = 0.0;
        self.assemble(out, |j| {
            let (q, p) = self.element.internal_force(
                &Self::element_coordinates(e, j),
                &Self::element_coordinates(e_dot, j),
            );
            power += p;
            q
        });
        power
    }

    /// Elastic force Q_e(e) = ∂U/∂e, written to `out`.
    pub fn elastic_force(&self, e: &[f64], out: &mut [f64]) {
        self.assemble(out, |j| {
            self.element.elastic_force(&Self::element_coordinates(e, j))
        });
    }

    /// Tangent stiffness ∂Q_e/∂e, written to the square matrix `out`.
    pub fn tangent_stiffness(&self, e: &[f64], mut out: MatMut<'_, f64>) {
        out.fill(0.0);
        for j in 0..self.n_elements {
            let k = self
                .element
                .tangent_stiffness(&Self::element_coordinates(e, j));
            for (a, b) in (0..8).flat_map(|a| (0..8).map(move |b| (a, b))) {
                out[(4 * j + a, 4 * j + b)] += k[(a, b)];
            }
        }
    }

    /// Strain energy U(e) = Σ element energies \[J\].
    pub fn strain_energy(&self, e: &[f64]) -> f64 {
        (0..self.n_elements)
            .map(|j| self.element.strain_energy(&Self::element_coordinates(e, j)))
            .sum()
    }

    /// Assembles a scalar (per Cartesian direction) element matrix into a 2(n+1) square matrix,
    /// scalar coordinates [r₀, r₀,ₓ, r₁, …] (the full matrix is this ⊗ I₂).
    fn assemble_scalar(&self, block: &nalgebra::Matrix4<f64>) -> Mat<f64> {
        let n = 2 * (self.n_elements + 1);
        let mut m = Mat::zeros(n, n);
        for j in 0..self.n_elements {
            for (a, b) in (0..4).flat_map(|a| (0..4).map(move |b| (a, b))) {
                m[(2 * j + a, 2 * j + b)] += block[(a, b)];
            }
        }
        m
    }

    /// Scalar mass matrix m (M = m ⊗ I₂).
    pub fn scalar_mass_matrix(&self) -> Mat<f64> {
        self.assemble_scalar(&self.element.scalar_mass_matrix())
    }

    /// Scalar bending stiffness k = EI ∫ s'' s''ᵀ (isotropic reference stiffness, K₀ = k ⊗ I₂).
    pub fn scalar_bending_stiffness(&self) -> Mat<f64> {
        self.assemble_scalar(&self.element.scalar_bending_stiffness())
    }

    /// Global constant mass matrix M = m ⊗ I₂.
    pub fn mass_matrix(&self) -> Mat<f64> {
        kron_identity(&self.scalar_mass_matrix())
    }

    /// Constant gravity load Q_g for acceleration `g` \[m/s²\].
    pub fn gravity_force(&self, g: Vector2<f64>) -> Vec<f64> {
        let mut out = vec![0.0; self.n_coordinates()];
        let q = self.element.gravity_force(g);
        self.assemble(&mut out, |_| q);
        out
    }

    /// Position of the material point at reference arc length `x` ∈ [0, L].
    pub fn position(&self, e: &[f64], x: f64) -> Vector2<f64> {
        let l = self.element.length();
        let j = ((x / l).floor() as usize).min(self.n_elements - 1);
        self.element
            .position(&Self::element_coordinates(e, j), x - j as f64 * l)
    }
}

/// a ⊗ I₂ in interleaved ordering: out[(2i + d, 2j + c)] = a[(i, j)] δ_dc.
pub fn kron_identity(a: &Mat<f64>) -> Mat<f64> {
    Mat::from_fn(2 * a.nrows(), 2 * a.ncols(), |i, j| {
        if i % 2 == j % 2 {
            a[(i / 2, j / 2)]
        } else {
            0.0
        }
    })
}

pub mod equilibrium;
pub mod sections;

#[cfg(test)]
mod tests;
