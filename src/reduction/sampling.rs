//! Hyper-reduction of the Craig–Bampton rod's internal forces by energy-conserving sampling and
//! weighting (ECSW): a few of the mesh's quadrature points, with non-negative weights, stand for
//! all of them.
//!
//! ```text
//! U(p) = Σᵢ Uᵢ(p)          over every quadrature point i of the mesh (axial and bending)
//! Q̄(p) = Σᵢ ∇Uᵢ(p)         the reduced internal force, gᵢ(p) = ∇Uᵢ(p) = Vᵀ Qᵢ(V p)
//! Ũ(p) = Σ_{i∈S} ξᵢ Uᵢ(p),  Q̃(p) = ∇Ũ(p),   ξᵢ > 0 on a small set S
//! ```
//! The weights are those of the sparse non-negative least-squares fit Σᵢ ξᵢ gᵢ(p_k) ≈ Σᵢ gᵢ(p_k)
//! over training configurations p_k, to a relative residual [`TOLERANCE`], separately for the
//! axial and the bending points. Because the sampled force is the gradient of Ũ ≥ 0, the sampled
//! rod is conservative like the full one: its strain energy Ũ closes the energy account, and
//! strain-rate damping at the same points keeps dissipating (ξᵢ > 0).
//!
//! At a point, r' = Σⱼ aⱼ Pⱼ and r'' = Σⱼ bⱼ Pⱼ, where Pⱼ = (p₂ⱼ, p₂ⱼ₊₁) and a, b are the point's
//! shape derivatives s', s'' applied to the scalar basis rows of its element: the cost of an
//! evaluation is that of |S| points, whatever the number of elements the rod was reduced from.
//!
//! The strains ε and κ do not change under rigid motion and the point forces turn with the rod,
//! so configurations of the rod lying along x train every orientation. They are the straight rod
//! plus deformations along each reduced coordinate scaled to [`TRAINING_STRAIN`] (axial strain, or
//! outer-fibre bending strain), each alone with both signs and in random combinations.
//!
//! # References
//! - C. Farhat, T. Chapman, P. Avery (2015), Structure-preserving, stability, and accuracy
//!   properties of the energy-conserving sampling and weighting method for the hyper reduction of
//!   nonlinear finite element dynamic models, Int. J. Numer. Meth. Eng. 102, 1077–1110.
//! - docs/model.md §1.7.

use faer::Mat;
use nalgebra::Vector2;

use super::craig_bampton::CraigBampton;
use crate::ancf::Rod;
use crate::ancf::element::Curvature;
use crate::error::ModelError;
use crate::linalg::nnls::nnls;

/// Relative residual of the training forces that the sampled points reproduce.
pub const TOLERANCE: f64 = 1e-5;

/// Axial strain, and outer-fibre bending strain κ c, of the training deformations: about twice the
/// yield strain of a structural steel, beyond what an elastic rod reaches.
pub const TRAINING_STRAIN: f64 = 2e-3;

/// Quadrature points in reduced coordinates, each with its weight (stiffness × quadrature weight
/// × sampling weight) and its rows a (and b for bending) of `columns` entries.
#[derive(Clone, Debug, Default)]
struct Points {
    /// Entries per row (the reduced basis' columns).
    columns: usize,
    weights: Vec<f64>,
    slope: Vec<f64>,
    curvature: Vec<f64>,
}

/// Σⱼ rowⱼ Pⱼ.
#[inline]
fn field(row: &[f64], p: &[f64]) -> Vector2<f64> {
    let (mut x, mut y) = (0.0, 0.0);
    for (v, pj) in row.iter().zip(p.chunks_exact(2)) {
        x += v * pj[0];
        y += v * pj[1];
    }
    Vector2::new(x, y)
}

/// out_(2j..2j+2) += rowⱼ c.
#[inline]
fn add(row: &[f64], c: Vector2<f64>, out: &mut [f64]) {
    for (v, o) in row.iter().zip(out.chunks_exact_mut(2)) {
        o[0] += v * c.x;
        o[1] += v * c.y;
    }
}

impl Points {
    fn len(&self) -> usize {
        self.weights.len()
    }

    fn rows(&self, k: usize) -> (&[f64], &[f64]) {
        let c = self.columns;
        let curvature = if self.curvature.is_empty() {
            &[][..]
        } else {
            &self.curvature[k * c..(k + 1) * c]
        };
        (&self.slope[k * c..(k + 1) * c], curvature)
    }

    /// Point k's axial force w (ε + β ε̇) ε_pᵀ added to `out`; returns its damping power w β ε̇².
    fn add_axial(&self, k: usize, p: &[f64], rate: Option<(&[f64], f64)>, out: &mut [f64]) -> f64 {
        let (a, _) = self.rows(k);
        let w = self.weights[k];
        let r_x = field(a, p);
        let norm = r_x.norm();
        let t = r_x / norm;
        let mut n = w * (norm - 1.0);
        let mut power = 0.0;
        if let Some((p_dot, beta)) = rate {
            let eps_dot = t.dot(&field(a, p_dot));
            n += w * beta * eps_dot;
            power = w * beta * eps_dot * eps_dot;
        }
        add(a, n * t, out);
        power
    }

    /// Point k's bending force w (κ + β κ̇) κ_pᵀ added to `out`; returns its damping power
    /// w β κ̇².
    fn add_bending(
        &self,
        k: usize,
        p: &[f64],
        rate: Option<(&[f64], f64)>,
        out: &mut [f64],
    ) -> f64 {
        let (a, b) = self.rows(k);
        let w = self.weights[k];
        let c = Curvature::at(field(a, p), field(b, p));
        let mut m = w * c.f / c.g;
        let mut power = 0.0;
        if let Some((p_dot, beta)) = rate {
            let kappa_dot = c.a.dot(&field(a, p_dot)) + c.b.dot(&field(b, p_dot));
            m += w * beta * kappa_dot;
            power = w * beta * kappa_dot * kappa_dot;
        }
        add(a, m * c.a, out);
        add(b, m * c.b, out);
        power
    }

    fn axial_energy(&self, k: usize, p: &[f64]) -> f64 {
        let eps = field(self.rows(k).0, p).norm() - 1.0;
        0.5 * self.weights[k] * eps * eps
    }

    fn bending_energy(&self, k: usize, p: &[f64]) -> f64 {
        let (a, b) = self.rows(k);
        let c = Curvature::at(field(a, p), field(b, p));
        let kappa = c.f / c.g;
        0.5 * self.weights[k] * kappa * kappa
    }

    /// The points whose sampling weight ξ is positive, with their weights multiplied by ξ.
    fn sampled(&self, xi: &[f64]) -> Self {
        let mut out = Self {
            columns: self.columns,
            ..Self::default()
        };
        for (k, &x) in xi.iter().enumerate().filter(|(_, x)| **x > 0.0) {
            let (a, b) = self.rows(k);
            out.weights.push(x * self.weights[k]);
            out.slope.extend_from_slice(a);
            out.curvature.extend_from_slice(b);
        }
        out
    }
}

/// The rows s'·v (and s''·v) of every axial and bending quadrature point of the mesh.
fn mesh_points(rod: &Rod, cb: &CraigBampton) -> (Points, Points) {
    let element = rod.element();
    let section = element.section();
    let rows: Vec<Vec<f64>> = (0..2 * (rod.n_elements() + 1))
        .map(|i| cb.scalar_row(i).collect())
        .collect();
    let columns = rows[0].len();
    let row = |e: usize, s: &nalgebra::Vector4<f64>| -> Vec<f64> {
        (0..columns)
            .map(|j| (0..4).map(|k| s[k] * rows[2 * e + k][j]).sum())
            .collect()
    };
    let empty = Points {
        columns,
        ..Points::default()
    };
    let (mut axial, mut bending) = (empty.clone(), empty);
    for e in 0..rod.n_elements() {
        for (s_x, w) in element.axial_points() {
            axial.weights.push(section.ea * w);
            axial.slope.extend(row(e, &s_x));
        }
        for (s_x, s_xx, w) in element.bending_points() {
            bending.weights.push(section.ei * w);
            bending.slope.extend(row(e, &s_x));
            bending.curvature.extend(row(e, &s_xx));
        }
    }
    (axial, bending)
}

/// A deterministic uniform generator on [−1, 1] (xorshift64*).
struct Uniform(u64);

impl Uniform {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let bits = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11;
        2.0 * (bits as f64 / (1u64 << 53) as f64) - 1.0
    }
}

/// The deformations that train the sampling: (index into p, amplitude) for each reduced
/// coordinate that strains the rod, its x component scaled to an axial strain and its y component
/// to an outer-fibre bending strain of [`TRAINING_STRAIN`] at the most strained point of a rod
/// lying along x.
fn training_directions(axial: &Points, bending: &Points, outer_fibre: f64) -> Vec<(usize, f64)> {
    let largest = |points: &Points, curvature: bool, j: usize| {
        (0..points.len())
            .map(|k| {
                let (a, b) = points.rows(k);
                if curvature { b[j] } else { a[j] }.abs()
            })
            .fold(0.0, f64::max)
    };
    // A coordinate that strains the rod a million times less than the most straining one only
    // moves it rigidly (in exact arithmetic, not at all).
    let mut directions = Vec::new();
    for (component, points, strain) in [
        (0, axial, TRAINING_STRAIN),
        (1, bending, TRAINING_STRAIN / outer_fibre),
    ] {
        let sensitivities: Vec<f64> = (0..points.columns)
            .map(|j| largest(points, component == 1, j))
            .collect();
        let threshold = 1e-6 * sensitivities.iter().copied().fold(0.0, f64::max);
        for (j, sensitivity) in sensitivities.into_iter().enumerate() {
            if sensitivity > threshold {
                directions.push((2 * j + component, strain / sensitivity));
            }
        }
    }
    directions
}

/// Training configurations: the straight rod `reference` plus each of `directions` alone, with
/// both signs, and as many random combinations of all of them (scaled by 1/√count).
fn training_configurations(reference: &[f64], directions: &[(usize, f64)]) -> Vec<Vec<f64>> {
    let mut configurations = Vec::new();
    for &(index, amplitude) in directions {
        for sign in [-1.0, 1.0] {
            let mut p = reference.to_vec();
            p[index] += sign * amplitude;
            configurations.push(p);
        }
    }
    let mut uniform = Uniform(0x9e37_79b9_7f4a_7c15);
    let spread = 1.0 / (directions.len() as f64).sqrt();
    for _ in 0..2 * directions.len() {
        let mut p = reference.to_vec();
        for &(index, amplitude) in directions {
            p[index] += spread * amplitude * uniform.next();
        }
        configurations.push(p);
    }
    configurations
}

/// The sampling weights ξ ≥ 0 of `points` (see the module docs), fitted on `configurations`.
fn sampling_weights(
    points: &Points,
    configurations: &[Vec<f64>],
    add_force: impl Fn(&Points, usize, &[f64], &mut [f64]),
) -> Result<Vec<f64>, ModelError> {
    let n = configurations[0].len();
    let mut g = Mat::zeros(configurations.len() * n, points.len());
    let mut force = vec![0.0; n];
    for (c, p) in configurations.iter().enumerate() {
        for k in 0..points.len() {
            force.fill(0.0);
            add_force(points, k, p, &mut force);
            for (i, f) in force.iter().enumerate() {
                g[(c * n + i, k)] = *f;
            }
        }
    }
    let b: Vec<f64> = (0..g.nrows())
        .map(|i| (0..g.ncols()).map(|k| g[(i, k)]).sum())
        .collect();
    // Columns scaled to unit norm, so that the points enter by their shape, not their size.
    let scales: Vec<f64> = (0..g.ncols())
        .map(|k| {
            (0..g.nrows())
                .map(|i| g[(i, k)] * g[(i, k)])
                .sum::<f64>()
                .sqrt()
        })
        .collect();
    let scaled = Mat::from_fn(g.nrows(), g.ncols(), |i, k| {
        if scales[k] > 0.0 {
            g[(i, k)] / scales[k]
        } else {
            0.0
        }
    });
    let (y, reached) = nnls(scaled.as_ref(), &b, TOLERANCE);
    if reached > TOLERANCE {
        return Err(ModelError::Numerical(format!(
            "the sampled rod reproduces its training forces only to {reached:.2e} (asked {TOLERANCE:.0e})"
        )));
    }
    Ok(y.iter()
        .zip(&scales)
        .map(|(y, s)| if *s > 0.0 { y / s } else { 0.0 })
        .collect())
}

/// The sampled internal forces of a Craig–Bampton rod (see the module docs).
#[derive(Clone, Debug)]
pub struct SampledForces {
    axial: Points,
    bending: Points,
    /// Strain-rate damping coefficient β \[s\] (0: undamped).
    damping: f64,
}

impl SampledForces {
    /// Samples the quadrature points of `rod` reduced by `cb`.
    pub fn new(rod: &Rod, cb: &CraigBampton) -> Result<Self, ModelError> {
        let (axial, bending) = mesh_points(rod, cb);
        let reference = cb.straight_coordinates(rod.properties().length);
        let outer_fibre = rod.properties().outer_fibre_distance;
        let directions = training_directions(&axial, &bending, outer_fibre);
        let configurations = training_configurations(&reference, &directions);
        let xi_axial = sampling_weights(&axial, &configurations, |s, k, p, out| {
            s.add_axial(k, p, None, out);
        })?;
        let xi_bending = sampling_weights(&bending, &configurations, |s, k, p, out| {
            s.add_bending(k, p, None, out);
        })?;
        Ok(Self {
            axial: axial.sampled(&xi_axial),
            bending: bending.sampled(&xi_bending),
            damping: rod.element().section().damping,
        })
    }

    /// Number of sampled points (axial, bending).
    pub fn n_points(&self) -> (usize, usize) {
        (self.axial.len(), self.bending.len())
    }

    /// Sampled internal force Q̃(p, ṗ) written to `out` (ṗ only for a damped rod); returns the
    /// damping power \[W\].
    pub fn internal_force(&self, p: &[f64], p_dot: &[f64], out: &mut [f64]) -> f64 {
        out.fill(0.0);
        let rate = (self.damping != 0.0).then_some((p_dot, self.damping));
        let mut power = 0.0;
        for k in 0..self.axial.len() {
            power += self.axial.add_axial(k, p, rate, out);
        }
        for k in 0..self.bending.len() {
            power += self.bending.add_bending(k, p, rate, out);
        }
        power
    }

    /// Sampled strain energy Ũ(p) \[J\].
    pub fn strain_energy(&self, p: &[f64]) -> f64 {
        let axial: f64 = (0..self.axial.len())
            .map(|k| self.axial.axial_energy(k, p))
            .sum();
        let bending: f64 = (0..self.bending.len())
            .map(|k| self.bending.bending_energy(k, p))
            .sum();
        axial + bending
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ancf::RodProperties;
    use crate::reduction::{Boundary, Quadrature, RodModel};

    fn models(n: usize, boundary: Boundary, damping: f64) -> (RodModel, RodModel) {
        let props = RodProperties {
            stiffness_damping: damping,
            ..RodProperties::benchmark_b()
        };
        let rod = || Rod::new(props, n).unwrap();
        let model = |q| RodModel::craig_bampton(rod(), 4, boundary, q).unwrap();
        (model(Quadrature::Full), model(Quadrature::Sampled))
    }

    /// Configurations of a rod turned by 0.7 rad and moved, deformed by random combinations of
    /// the training deformations each up to `size` times its amplitude (a generator that is not
    /// the training's).
    fn configurations(model: &RodModel, size: f64) -> Vec<Vec<f64>> {
        let (angle, origin) = (0.7, Vector2::new(0.03, -0.01));
        let turned = model.rod().straight_configuration(origin, angle);
        let reference = model.model_coordinates(&turned);
        let (axial, bending) = mesh_points(model.rod(), model.reduction().unwrap());
        let outer_fibre = model.rod().properties().outer_fibre_distance;
        let directions = training_directions(&axial, &bending, outer_fibre);
        let rotation = nalgebra::Rotation2::new(angle);
        let mut uniform = Uniform(0x0123_4567_89ab_cdef);
        (0..20)
            .map(|_| {
                let mut deformation = vec![0.0; reference.len()];
                for &(index, amplitude) in &directions {
                    deformation[index] = size * amplitude * uniform.next();
                }
                let mut p = reference.clone();
                for (pair, d) in p.chunks_exact_mut(2).zip(deformation.chunks_exact(2)) {
                    let turned = rotation * Vector2::new(d[0], d[1]);
                    pair[0] += turned.x;
                    pair[1] += turned.y;
                }
                p
            })
            .collect()
    }

    fn norm(v: &[f64]) -> f64 {
        v.iter().map(|x| x * x).sum::<f64>().sqrt()
    }

    /// Within the training strains, the sampled force of a turned and moved rod is the full
    /// quadrature's within 1e-4 (relative), for 8 and 32 elements and both interfaces, from fewer
    /// points than the mesh has, and far fewer for a fine mesh (32 elements: 256 points).
    #[test]
    fn sampled_forces_are_the_full_quadratures() {
        for (n, boundary) in [
            (8, Boundary::Pins),
            (32, Boundary::Pins),
            (8, Boundary::PositionsAndSlopes),
        ] {
            let (mut full, mut sampled) = models(n, boundary, 0.0);
            let (axial, bending) = sampled.sampled().unwrap().n_points();
            assert!(axial + bending < 8 * n, "{n}: {axial} + {bending} points");
            assert!(
                n < 32 || axial + bending <= 40,
                "{axial} + {bending} points"
            );
            let m = full.n_coordinates();
            for p in configurations(&full, 0.3) {
                let (mut a, mut b) = (vec![0.0; m], vec![0.0; m]);
                full.internal_force(&p, &p, &mut a);
                sampled.internal_force(&p, &p, &mut b);
                let error: Vec<f64> = a.iter().zip(&b).map(|(x, y)| x - y).collect();
                assert!(
                    norm(&error) < 1e-4 * norm(&a),
                    "{n} {boundary:?}: {:e}",
                    norm(&error) / norm(&a)
                );
                let (u_full, u_sampled) = (full.strain_energy(&p), sampled.strain_energy(&p));
                assert!(
                    (u_full - u_sampled).abs() < 1e-4 * u_full,
                    "{u_full} {u_sampled}"
                );
            }
        }
    }

    /// The sampled force is the gradient of the sampled energy (central differences), and the
    /// damping power is ṗᵀ(Q(p, ṗ) − Q(p, 0)) ≥ 0 and nothing for a rigid rotation: the sampled
    /// rod is conservative and dissipative like the full one.
    #[test]
    fn sampled_force_derives_from_the_sampled_energy() {
        let (full, mut sampled) = models(8, Boundary::Pins, 1e-4);
        let m = full.n_coordinates();
        let p = configurations(&full, 0.3).remove(0);
        let mut q = vec![0.0; m];
        let p_dot: Vec<f64> = (0..m).map(|i| 0.1 * (i as f64 - 5.0)).collect();
        let power = sampled.internal_force(&p, &p_dot, &mut q);
        let mut elastic = vec![0.0; m];
        let zero = vec![0.0; m];
        sampled.internal_force(&p, &zero, &mut elastic);
        let h = 1e-9;
        for i in 0..m {
            let energy = |s: f64, model: &mut RodModel| {
                let mut x = p.clone();
                x[i] += s * h;
                model.strain_energy(&x)
            };
            let derivative = (energy(1.0, &mut sampled) - energy(-1.0, &mut sampled)) / (2.0 * h);
            assert!(
                (derivative - elastic[i]).abs() < 1e-5 * norm(&elastic),
                "{i}: {derivative} vs {}",
                elastic[i]
            );
        }
        let damping: f64 = (0..m).map(|i| p_dot[i] * (q[i] - elastic[i])).sum();
        assert!(
            power > 0.0 && (power - damping).abs() < 1e-9 * power,
            "{power} {damping}"
        );
        // A rigid rotation about the origin at 3 rad/s: ṗ = ω k × p for every 2-vector of p.
        let spin: Vec<f64> = p
            .chunks_exact(2)
            .flat_map(|r| [-3.0 * r[1], 3.0 * r[0]])
            .collect();
        let rigid = sampled.internal_force(&p, &spin, &mut q);
        assert!(rigid.abs() < 1e-9 * power, "{rigid}");
    }
}
