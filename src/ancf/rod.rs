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

/// Weights of the four Gauss-point values of two neighbouring elements (at a, b, 1 + a, 1 + b
/// element lengths from the patch's start, a, b = (1 ∓ 1/√3)/2) in the value of their
/// least-squares quadratic at the patch's start (a pin): the first row of (VᵀV)⁻¹Vᵀ for the
/// points' Vandermonde matrix V (checked by a unit test), and at the first element's mid-point and
/// at the node between the elements. The patch's end and its second element's mid-point take the
/// mirrored weights.
const PATCH_AT_END: [f64; 4] = [
    1.418_856_620_135_745_3,
    -0.168_856_620_135_744,
    -0.485_843_918_243_526,
    0.235_843_918_243_524_58,
];
/// See [`PATCH_AT_END`].
const PATCH_AT_HALF: [f64; 4] = [
    0.473_584_391_824_351,
    0.401_415_608_175_649,
    0.242_921_959_121_758_43,
    -0.117_921_959_121_758_76,
];
/// See [`PATCH_AT_END`].
const PATCH_AT_NODE: [f64; 4] = [
    -0.038_675_134_594_817_306,
    0.538_675_134_594_817,
    0.538_675_134_594_817_2,
    -0.038_675_134_594_816_97,
];

/// A one-element rod's linear field through its two Gauss-point values (given twice, as
/// [g₁, g₂, g₁, g₂]) at ξ = 0, 1/2 and 1.
const SINGLE_ELEMENT: [[f64; 4]; 3] = {
    let (a, b) = GAUSS_POINTS;
    let (w, v) = (0.5 * b / (b - a), -0.5 * a / (b - a));
    [[w, v, w, v], [0.25; 4], [v, w, v, w]]
};

/// The places (element fractions) of an element's two Gauss points, (1 ∓ 1/√3)/2, at which the
/// patch weights above read the strains.
const GAUSS_POINTS: (f64, f64) = (0.211_324_865_405_187_1, 0.788_675_134_594_812_9);

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

/// The extremes of ε ± c |κ| over the samples of a rod, and where the largest magnitude lies.
#[derive(Clone, Copy, Debug)]
struct Field {
    largest: f64,
    max: f64,
    min: f64,
    location: f64,
}

impl Default for Field {
    fn default() -> Self {
        Self {
            largest: 0.0,
            max: f64::NEG_INFINITY,
            min: f64::INFINITY,
            location: 0.0,
        }
    }
}

impl Field {
    /// Takes in the strains (ε, κ) at `place` along the rod, for the outer-fibre distance `c`.
    fn add(&mut self, place: f64, (eps, kappa): (f64, f64), c: f64) {
        let bending = c * kappa.abs();
        let magnitude = eps.abs() + bending;
        if magnitude > self.largest {
            self.largest = magnitude;
            self.location = place;
        }
        self.max = self.max.max(eps + bending);
        self.min = self.min.min(eps - bending);
    }
}

/// An assembled ANCF rod of `n` equal elements.
#[derive(Clone, Debug)]
pub struct Rod {
    properties: RodProperties,
    n_elements: usize,
    element: Element,
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

    /// The rod's normal stresses ([`NormalStresses`]): over the rod, σ = N/A ± |M| c/I =
    /// E (ε ± c |κ|) (Euler–Bernoulli, c the outer-fibre distance), its largest magnitude
    /// |N|/A + |M| c/I and where it lies, its most tensile and most compressive values, and the
    /// axial force and bending moment at mid-span (N = EA ε, M = EI κ: tension and a left-turning
    /// curvature positive).
    ///
    /// N and M are taken at the elements' Gauss points, where they are superconvergent
    /// ([`Element::strain_at_stress_points`]), and recovered at the nodes and the element
    /// mid-points from the least-squares quadratic through the four Gauss-point values of two
    /// neighbouring elements (superconvergent patch recovery; O. C. Zienkiewicz, J. Z. Zhu (1992),
    /// Int. J. Numer. Meth. Eng. 33, 1331–1364). The recovery is exact for a quadratic moment (a
    /// beam under a uniform load), so the largest moment is found wherever it lies: at a node, in
    /// an element, at a pin. A one-element rod uses its own linear field.
    pub fn normal_stresses(&self, e: &[f64]) -> NormalStresses {
        let n = self.n_elements;
        let p = &self.properties;
        let c = p.outer_fibre_distance;
        // (ε, κ) at the Gauss points, in order along the rod (no allocation: at most 64 elements).
        let mut points = [(0.0, 0.0); 2 * MAX_ELEMENTS];
        for j in 0..n {
            let [a, b] = self
                .element
                .strain_at_stress_points(&Self::element_coordinates(e, j));
            points[2 * j] = a;
            points[2 * j + 1] = b;
        }
        let points = &points[..2 * n];
        let combine = |weights: &[f64; 4], values: &[(f64, f64)]| {
            weights
                .iter()
                .zip(values)
                .fold((0.0, 0.0), |(eps, kappa), (w, v)| {
                    (eps + w * v.0, kappa + w * v.1)
                })
        };
        // Every sample: its place along the rod (a fraction of its length) and (ε, κ) there.
        let mut field = Field::default();
        let (a, b) = GAUSS_POINTS;
        let element = 1.0 / n as f64;
        for (k, &point) in points.iter().enumerate() {
            let offset = if k % 2 == 0 { a } else { b };
            field.add(((k / 2) as f64 + offset) * element, point, c);
        }
        let mirrored = |w: &[f64; 4]| [w[3], w[2], w[1], w[0]];
        let midspan = if n == 1 {
            let doubled = [points[0], points[1], points[0], points[1]];
            for (weights, place) in SINGLE_ELEMENT.iter().zip([0.0, 0.5, 1.0]) {
                field.add(place, combine(weights, &doubled), c);
            }
            combine(&SINGLE_ELEMENT[1], &doubled)
        } else if n % 2 == 0 {
            combine(&PATCH_AT_NODE, &points[n - 2..n + 2])
        } else {
            combine(&PATCH_AT_HALF, &points[n - 1..n + 3])
        };
        // Patch j: elements j and j + 1, its points at a, b, 1 + a, 1 + b element lengths.
        for j in 0..n.saturating_sub(1) {
            let patch = &points[2 * j..2 * j + 4];
            field.add((j + 1) as f64 * element, combine(&PATCH_AT_NODE, patch), c);
            field.add(
                (j as f64 + 0.5) * element,
                combine(&PATCH_AT_HALF, patch),
                c,
            );
            if j == 0 {
                field.add(0.0, combine(&PATCH_AT_END, patch), c);
            }
            if j + 2 == n {
                let half = combine(&mirrored(&PATCH_AT_HALF), patch);
                field.add((j as f64 + 1.5) * element, half, c);
                field.add(1.0, combine(&mirrored(&PATCH_AT_END), patch), c);
            }
        }
        let modulus = p.youngs_modulus;
        NormalStresses {
            largest: modulus * field.largest,
            max: modulus * field.max,
            min: modulus * field.min,
            location: field.location,
            midspan_axial_force: modulus * p.area * midspan.0,
            midspan_moment: modulus * p.second_moment_of_area * midspan.1,
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

pub mod sections;

#[cfg(test)]
mod tests;
