//! The gradient-deficient planar ANCF beam element with Gerstmayr–Irschik strain measures.
//!
//! ```text
//! ε = |r'| − 1                       axial strain
//! κ = (r' × r'') / |r'|²             material curvature
//! U = ½ ∫₀ˡ (EA ε² + EI κ²) dx        strain energy,   Q_e = ∂U/∂e
//! Q_e = ∫₀ˡ (EA ε ε_eᵀ + EI κ κ_eᵀ) dx
//! K_T = ∫₀ˡ EA (ε_eᵀε_e + ε ε_ee) + EI (κ_eᵀκ_e + κ κ_ee) dx
//! ```
//! with ε_e = r'ᵀS'/|r'|, ε_ee = S'ᵀ(I − t tᵀ)S'/|r'| (t = r'/|r'|), and for κ = f/g, f = r' × r'',
//! g = r'·r': κ_e = f_e/g − f g_e/g², κ_ee = f_ee/g − (f_e g_eᵀ + g_e f_eᵀ)/g² − f g_ee/g² + 2f g_e g_eᵀ/g³.
//!
//! Quadrature: 5 Gauss points for the axial term (order 9: ε² of a stretched straight element is a
//! degree-8 polynomial in the Berzeri–Shabana limit and smooth here) and 3 for bending (order 5:
//! κ² of a cubic is of degree ≤ 4 when |r'| is constant), as Exudyn's default `A9-B5` rule.
//!
//! Optional strain-rate (stiffness-proportional) damping with coefficient β \[s\]:
//! N_d = β EA ε̇, M_d = β EI κ̇, Q_d = ∫ (N_d ε_eᵀ + M_d κ_eᵀ) dx. It vanishes under rigid motion.
//! Its dissipated power is ėᵀQ_d = ∫ β (EA ε̇² + EI κ̇²) dx ≥ 0 (ε̇ = ε_e ė, κ̇ = κ_e ė), summed at
//! the same Gauss points, so that it equals ėᵀQ_d of the discrete force exactly.
//!
//! # References
//! - Gerstmayr & Irschik (2008), J. Sound Vib. 318, 461; docs/model.md §1.2–1.4.
//! - Exudyn `CObjectANCFCable2D.cpp` (strain variations, quadrature orders).

use nalgebra::{Matrix2, Matrix4, SMatrix, SVector, Vector2, Vector4};

use super::shape::{shape, shape_x, shape_xx};
use crate::quadrature::{GAUSS_3, GAUSS_5};

/// Element coordinate vector e = [r₁, r₁,ₓ, r₂, r₂,ₓ].
pub type ElementVector = SVector<f64, 8>;
/// 8 × 8 element matrix.
pub type ElementMatrix = SMatrix<f64, 8, 8>;

/// Cross-section properties of the beam.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Section {
    /// Axial stiffness EA \[N\].
    pub ea: f64,
    /// Bending stiffness EI \[N m²\].
    pub ei: f64,
    /// Mass per unit length ρA \[kg/m\].
    pub rho_a: f64,
    /// Strain-rate damping coefficient β \[s\] (0: undamped).
    pub damping: f64,
}

/// Shape-function derivatives and scaled weight at one Gauss point.
#[derive(Clone, Copy, Debug)]
struct GaussPoint {
    s_x: Vector4<f64>,
    s_xx: Vector4<f64>,
    weight: f64,
}

/// One planar ANCF element of reference length `l`, with its quadrature points precomputed.
#[derive(Clone, Copy, Debug)]
pub struct Element {
    section: Section,
    l: f64,
    axial: [GaussPoint; 5],
    bending: [GaussPoint; 3],
}

/// Axial strain and its first variation at a point.
struct Axial {
    eps: f64,
    eps_e: ElementVector,
    t: Vector2<f64>,
    norm: f64,
}

/// Curvature and the pieces of its variations at a point.
struct Bending {
    kappa: f64,
    kappa_e: ElementVector,
    f: f64,
    g: f64,
    f_e: ElementVector,
    g_e: ElementVector,
}

/// The curvature κ = f/g (f = r' × r'', g = r'·r') at a point and its variation
/// κ_e = f_e/g − f g_e/g² written as κ_e = s' ⊗ a + s'' ⊗ b for the point's shape derivatives
/// s', s'' (of an element, or rows of a reduced basis), with a = (r''_y, −r''_x)/g − 2f r'/g² and
/// b = (−r'_y, r'_x)/g.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Curvature {
    pub a: Vector2<f64>,
    pub b: Vector2<f64>,
    pub f: f64,
    pub g: f64,
}

impl Curvature {
    /// The curvature terms of the slope `r_x` = r' and its derivative `r_xx` = r''.
    #[inline]
    pub fn at(r_x: Vector2<f64>, r_xx: Vector2<f64>) -> Self {
        let f = cross(r_x, r_xx);
        let g = r_x.norm_squared();
        Self {
            a: Vector2::new(r_xx.y, -r_xx.x) / g - (2.0 * f / (g * g)) * r_x,
            b: Vector2::new(-r_x.y, r_x.x) / g,
            f,
            g,
        }
    }
}

/// [sₖ v_d] for k = 0..4, d = 0..2, in element coordinate order.
fn kron(s: &Vector4<f64>, v: Vector2<f64>) -> ElementVector {
    ElementVector::from_fn(|i, _| s[i / 2] * v[i % 2])
}

/// a ⊗ b: out[(2k + d, 2j + c)] = a[(k, j)] b[(d, c)].
fn kron_mat(a: &Matrix4<f64>, b: &Matrix2<f64>) -> ElementMatrix {
    ElementMatrix::from_fn(|i, j| a[(i / 2, j / 2)] * b[(i % 2, j % 2)])
}

/// Σₖ sₖ r_k, the field value of a derivative with shape values `s`.
fn field(s: &Vector4<f64>, e: &ElementVector) -> Vector2<f64> {
    (0..4).fold(Vector2::zeros(), |acc, k| {
        acc + s[k] * Vector2::new(e[2 * k], e[2 * k + 1])
    })
}

fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

impl Element {
    /// An element of length `l` \[m\] with the given section.
    pub fn new(section: Section, l: f64) -> Self {
        let point = |(xi, weight): (f64, f64)| GaussPoint {
            s_x: shape_x(xi, l),
            s_xx: shape_xx(xi, l),
            weight,
        };
        Self {
            section,
            l,
            axial: std::array::from_fn(|i| point(GAUSS_5.unit_node(i, l))),
            bending: std::array::from_fn(|i| point(GAUSS_3.unit_node(i, l))),
        }
    }

    /// The axial quadrature points: s'(ξ) and the weight scaled to the element's length.
    pub(crate) fn axial_points(&self) -> impl Iterator<Item = (Vector4<f64>, f64)> + '_ {
        self.axial.iter().map(|p| (p.s_x, p.weight))
    }

    /// The bending quadrature points: s'(ξ), s''(ξ) and the weight scaled to the element's length.
    pub(crate) fn bending_points(
        &self,
    ) -> impl Iterator<Item = (Vector4<f64>, Vector4<f64>, f64)> + '_ {
        self.bending.iter().map(|p| (p.s_x, p.s_xx, p.weight))
    }

    /// Reference length l \[m\].
    pub fn length(&self) -> f64 {
        self.l
    }

    /// Cross-section properties.
    pub fn section(&self) -> &Section {
        &self.section
    }

    /// Scalar consistent mass m = ρA ∫ s sᵀ dx (closed form, docs/model.md §1.2); M_e = m ⊗ I₂.
    pub fn scalar_mass_matrix(&self) -> Matrix4<f64> {
        let l = self.l;
        let c = self.section.rho_a * l;
        c * Matrix4::new(
            13.0 / 35.0,
            11.0 * l / 210.0,
            9.0 / 70.0,
            -13.0 * l / 420.0,
            11.0 * l / 210.0,
            l * l / 105.0,
            13.0 * l / 420.0,
            -l * l / 140.0,
            9.0 / 70.0,
            13.0 * l / 420.0,
            13.0 / 35.0,
            -11.0 * l / 210.0,
            -13.0 * l / 420.0,
            -l * l / 140.0,
            -11.0 * l / 210.0,
            l * l / 105.0,
        )
    }

    /// Constant element mass matrix M_e = m ⊗ I₂ (ANCF: no centrifugal or Coriolis terms).
    pub fn mass_matrix(&self) -> ElementMatrix {
        kron_mat(&self.scalar_mass_matrix(), &Matrix2::identity())
    }

    /// Scalar bending stiffness k = EI ∫ s'' s''ᵀ dx = EI/l³ [12 6l −12 6l; …] (docs/model.md §2: the stiffness of the straight rod).
    ///
    /// This is the stiffness of the unstressed straight element in each Cartesian direction; it is
    /// isotropic, which is what makes the Craig–Bampton subspace independent of the rod's orientation.
    pub fn scalar_bending_stiffness(&self) -> Matrix4<f64> {
        let l = self.l;
        let c = self.section.ei / (l * l * l);
        c * Matrix4::new(
            12.0,
            6.0 * l,
            -12.0,
            6.0 * l,
            6.0 * l,
            4.0 * l * l,
            -6.0 * l,
            2.0 * l * l,
            -12.0,
            -6.0 * l,
            12.0,
            -6.0 * l,
            6.0 * l,
            2.0 * l * l,
            -6.0 * l,
            4.0 * l * l,
        )
    }

    /// Gravity load Q_g = ρA ∫ Sᵀ g dx = ρA l [g/2, l g/12, g/2, −l g/12] (docs/model.md §1.3).
    pub fn gravity_force(&self, g: Vector2<f64>) -> ElementVector {
        let c = self.section.rho_a * self.l;
        kron(
            &Vector4::new(0.5, self.l / 12.0, 0.5, -self.l / 12.0),
            g * c,
        )
    }

    /// Axial strain ε = |r'| − 1 at a Gauss point (the energy alone, without derivatives).
    fn strain_at(p: &GaussPoint, e: &ElementVector) -> f64 {
        field(&p.s_x, e).norm() - 1.0
    }

    /// Curvature κ = (r' × r'')/|r'|² at a Gauss point (the energy alone, without derivatives).
    fn curvature_at(p: &GaussPoint, e: &ElementVector) -> f64 {
        let r_x = field(&p.s_x, e);
        cross(r_x, field(&p.s_xx, e)) / r_x.norm_squared()
    }

    fn axial_at(p: &GaussPoint, e: &ElementVector) -> Axial {
        let r_x = field(&p.s_x, e);
        let norm = r_x.norm();
        let t = r_x / norm;
        Axial {
            eps: norm - 1.0,
            eps_e: kron(&p.s_x, t),
            t,
            norm,
        }
    }

    fn bending_at(p: &GaussPoint, e: &ElementVector) -> Bending {
        let r_x = field(&p.s_x, e);
        let r_xx = field(&p.s_xx, e);
        let f = cross(r_x, r_xx);
        let g = r_x.norm_squared();
        let f_e = kron(&p.s_x, Vector2::new(r_xx.y, -r_xx.x))
            + kron(&p.s_xx, Vector2::new(-r_x.y, r_x.x));
        let g_e = 2.0 * kron(&p.s_x, r_x);
        let kappa_e = f_e / g - (f / (g * g)) * g_e;
        Bending {
            kappa: f / g,
            kappa_e,
            f,
            g,
            f_e,
            g_e,
        }
    }

    /// Generalised force of the stress resultants at the Gauss points:
    /// Q = Σ w [N ε_eᵀ + M κ_eᵀ], with N = EA(ε + β ε̇) and M = EI(κ + β κ̇) (β = 0: elastic).
    ///
    /// Written per node k as Q_k = Σ w [N s'_k t + M (s'_k a + s''_k b)], since ε_e = s' ⊗ t and
    /// κ_e = f_e/g − f g_e/g² = s' ⊗ a + s'' ⊗ b with a = (r''_y, −r''_x)/g − 2f r'/g² and
    /// b = (−r'_y, r'_x)/g: the kron form of the module docs without building 8-vectors (this is
    /// the hot path of every flexible model). Also returns the damping power
    /// Σ w β (EA ε̇² + EI κ̇²) (0 without `e_dot`).
    fn resultant_force(
        &self,
        e: &ElementVector,
        e_dot: Option<&ElementVector>,
    ) -> (ElementVector, f64) {
        let Section {
            ea, ei, damping, ..
        } = self.section;
        let mut q = [Vector2::zeros(); 4];
        let mut power = 0.0;
        // The pointwise kinematics first, for all points: the square roots and divisions are
        // independent and overlap instead of stalling each point's accumulation.
        let norms: [f64; 5] = std::array::from_fn(|i| field(&self.axial[i].s_x, e).norm());
        let tangents: [Vector2<f64>; 5] =
            std::array::from_fn(|i| field(&self.axial[i].s_x, e) / norms[i]);
        for ((p, t), norm) in self.axial.iter().zip(tangents).zip(norms) {
            let mut n = ea * (norm - 1.0);
            if let Some(e_dot) = e_dot {
                let eps_dot = t.dot(&field(&p.s_x, e_dot));
                n += ea * damping * eps_dot;
                power += p.weight * ea * damping * eps_dot * eps_dot;
            }
            let c = p.weight * n;
            for (k, qk) in q.iter_mut().enumerate() {
                *qk += (c * p.s_x[k]) * t;
            }
        }
        let curvature: [_; 3] = std::array::from_fn(|i| {
            let p = &self.bending[i];
            let c = Curvature::at(field(&p.s_x, e), field(&p.s_xx, e));
            (c.a, c.b, ei * c.f / c.g)
        });
        for (p, (a, b, mut m)) in self.bending.iter().zip(curvature) {
            if let Some(e_dot) = e_dot {
                let kappa_dot = a.dot(&field(&p.s_x, e_dot)) + b.dot(&field(&p.s_xx, e_dot));
                m += ei * damping * kappa_dot;
                power += p.weight * ei * damping * kappa_dot * kappa_dot;
            }
            let c = p.weight * m;
            for (k, qk) in q.iter_mut().enumerate() {
                *qk += c * (p.s_x[k] * a + p.s_xx[k] * b);
            }
        }
        (ElementVector::from_fn(|i, _| q[i / 2][i % 2]), power)
    }

    /// Elastic force Q_e(e) = ∂U/∂e.
    pub fn elastic_force(&self, e: &ElementVector) -> ElementVector {
        self.resultant_force(e, None).0
    }

    /// Internal force: elastic force plus strain-rate damping β(EA ε̇ ε_eᵀ + EI κ̇ κ_eᵀ), and
    /// the power the damping dissipates, ėᵀQ_d = ∫ β (EA ε̇² + EI κ̇²) dx \[W\].
    pub fn internal_force(&self, e: &ElementVector, e_dot: &ElementVector) -> (ElementVector, f64) {
        if self.section.damping == 0.0 {
            return (self.elastic_force(e), 0.0);
        }
        self.resultant_force(e, Some(e_dot))
    }

    /// Tangent stiffness K_T = ∂Q_e/∂e (analytic, symmetric).
    pub fn tangent_stiffness(&self, e: &ElementVector) -> ElementMatrix {
        let Section { ea, ei, .. } = self.section;
        let mut k = ElementMatrix::zeros();
        for p in &self.axial {
            let a = Self::axial_at(p, e);
            let projector = Matrix2::identity() - a.t * a.t.transpose();
            let eps_ee = kron_mat(&(p.s_x * p.s_x.transpose()), &projector) / a.norm;
            k += (p.weight * ea) * (a.eps_e * a.eps_e.transpose() + a.eps * eps_ee);
        }
        let rotation = Matrix2::new(0.0, 1.0, -1.0, 0.0);
        for p in &self.bending {
            let b = Self::bending_at(p, e);
            let a_kj = p.s_x * p.s_xx.transpose() - p.s_xx * p.s_x.transpose();
            let f_ee = kron_mat(&a_kj, &rotation);
            let g_ee = 2.0 * kron_mat(&(p.s_x * p.s_x.transpose()), &Matrix2::identity());
            let (f, g) = (b.f, b.g);
            let fg = b.f_e * b.g_e.transpose();
            let kappa_ee = f_ee / g - (fg + fg.transpose()) / (g * g) - (f / (g * g)) * g_ee
                + (2.0 * f / (g * g * g)) * (b.g_e * b.g_e.transpose());
            k += (p.weight * ei) * (b.kappa_e * b.kappa_e.transpose() + b.kappa * kappa_ee);
        }
        k
    }

    /// Strain energy U = ½ ∫ (EA ε² + EI κ²) dx.
    pub fn strain_energy(&self, e: &ElementVector) -> f64 {
        let Section { ea, ei, .. } = self.section;
        let axial: f64 = self
            .axial
            .iter()
            .map(|p| p.weight * ea * Self::strain_at(p, e).powi(2))
            .sum();
        let bending: f64 = self
            .bending
            .iter()
            .map(|p| p.weight * ei * Self::curvature_at(p, e).powi(2))
            .sum();
        0.5 * (axial + bending)
    }

    /// Position r(x) = S(x) e at arc length `x` ∈ [0, l] on the reference.
    pub fn position(&self, e: &ElementVector, x: f64) -> Vector2<f64> {
        field(&shape(x / self.l, self.l), e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quadrature::GAUSS_4;

    fn element() -> Element {
        Element::new(
            Section {
                ea: 4.6e7,
                ei: 868.0,
                rho_a: 1.75,
                damping: 0.0,
            },
            0.03,
        )
    }

    /// The closed-form mass equals ρA ∫ S Sᵀ dx by 4-point Gauss (exact for degree 6).
    #[test]
    fn closed_form_mass_equals_quadrature() {
        let el = element();
        let l = el.length();
        let mut m = Matrix4::zeros();
        for (xi, w) in GAUSS_4.on_unit_interval(l) {
            let s = shape(xi, l);
            m += w * 1.75 * s * s.transpose();
        }
        assert!((m - el.scalar_mass_matrix()).norm() < 1e-15 * m.norm().max(1.0) * 10.0);
    }

    /// Closed-form bending stiffness equals EI ∫ s'' s''ᵀ (3-point Gauss is exact for degree 2).
    #[test]
    fn closed_form_bending_stiffness_equals_quadrature() {
        let el = element();
        let l = el.length();
        let mut k = Matrix4::zeros();
        for (xi, w) in GAUSS_3.on_unit_interval(l) {
            let s = shape_xx(xi, l);
            k += w * 868.0 * s * s.transpose();
        }
        let k_ref = el.scalar_bending_stiffness();
        assert!((k - k_ref).norm() < 1e-12 * k_ref.norm());
    }

    /// The gravity load equals ρA ∫ Sᵀ g (4-point Gauss, exact for cubic S).
    #[test]
    fn gravity_equals_quadrature() {
        let el = element();
        let g = Vector2::new(0.3, -9.81);
        let mut q = ElementVector::zeros();
        for (xi, w) in GAUSS_4.on_unit_interval(el.length()) {
            q += kron(&shape(xi, el.length()), w * 1.75 * g);
        }
        assert!((q - el.gravity_force(g)).norm() < 1e-15);
    }

    /// Linear-in-e straight stretch: tangent of the unstressed element is symmetric and the
    /// energy of a uniform 1 % stretch is ½ EA ε² l.
    #[test]
    fn uniform_stretch_energy() {
        let el = element();
        let l = el.length();
        let s = 1.01;
        let e = ElementVector::from_column_slice(&[0.0, 0.0, s, 0.0, s * l, 0.0, s, 0.0]);
        let u = el.strain_energy(&e);
        let expected = 0.5 * 4.6e7 * 0.01f64.powi(2) * l;
        assert!((u - expected).abs() < 1e-12 * expected);
        let k = el.tangent_stiffness(&e);
        assert!((k - k.transpose()).norm() < 1e-10 * k.norm());
    }

    /// The returned damping power is ėᵀQ_d with Q_d = internal − elastic force, positive; a
    /// rigid-body velocity (translation + rotation) dissipates nothing.
    #[test]
    fn damping_power_is_the_damping_force_times_the_rate() {
        let el = Element::new(
            Section {
                damping: 1e-3,
                ..element().section
            },
            0.03,
        );
        let l = el.length();
        let e = ElementVector::from_column_slice(&[0.0, 0.0, 1.01, 0.02, l, 1e-3, 0.99, -0.03]);
        let e_dot = ElementVector::from_column_slice(&[0.1, -0.2, 0.5, 0.3, 0.2, 0.1, -0.4, 0.6]);
        let (q, power) = el.internal_force(&e, &e_dot);
        let expected = e_dot.dot(&(q - el.elastic_force(&e)));
        assert!(power > 0.0);
        assert!(
            (power - expected).abs() < 1e-12 * expected.abs(),
            "{power} vs {expected}"
        );
        // Rigid rotation at rate w about the first node plus a translation: ṙ = v + w k × r.
        let (v, w) = (Vector2::new(0.3, -0.7), 2.0);
        let rigid = ElementVector::from_fn(|i, _| {
            let (node, component) = (i / 2, i % 2);
            let r = Vector2::new(e[2 * node], e[2 * node + 1]);
            let rotated = w * Vector2::new(-r.y, r.x);
            if node % 2 == 0 {
                v[component] + rotated[component]
            } else {
                rotated[component]
            }
        });
        let (_, rigid_power) = el.internal_force(&e, &rigid);
        assert!(rigid_power.abs() < 1e-12 * power, "{rigid_power}");
    }
}
