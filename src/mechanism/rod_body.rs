//! The connecting rod as a body of the mechanism: rigid, full ANCF, or Craig–Bampton reduced.
//!
//! In every formulation the first two coordinates are the crank-pin end A, and
//! [`RodBody::end_offset`] locates the slider-pin end B, so joints are written the same way.
//!
//! - Rigid: natural coordinates p = [r_A, r_B] of a uniform bar, constant mass
//!   M = m [1/3 1/6; 1/6 1/3] ⊗ I₂ (inertia m l²/12 about the centre), with the length constraint
//!   ½(|r_B − r_A|² − l²) = 0 added by the mechanism.
//! - ANCF / Craig–Bampton: [`RodModel`].
//!
//! The end masses m_A, m_B (the eyes) add m_A I₂ and m_B I₂ to M at the pins' coordinates, and
//! their weights m g to the gravity load there.
//!
//! # References
//! - J. García de Jalón, E. Bayo (1994), Kinematic and Dynamic Simulation of Multibody Systems,
//!   Springer, ch. 3 (natural coordinates).

use faer::{Mat, MatRef};
use nalgebra::Vector2;

use crate::ancf::Rod;
use crate::error::ModelError;
use crate::params::{Parameters, RodFormulation};
use crate::reduction::{RodEnd, RodModel};

/// The connecting rod in the mechanism's coordinates.
#[derive(Clone, Debug)]
pub enum RodBody {
    /// Rigid uniform bar in natural coordinates [r_A, r_B].
    Rigid {
        /// The bar's mass \[kg\].
        mass: f64,
        /// The masses at its pins, A and B \[kg\].
        end_masses: [f64; 2],
        /// Length \[m\].
        length: f64,
        /// Constant 4 × 4 mass matrix.
        mass_matrix: Mat<f64>,
    },
    /// Flexible ANCF rod, full or reduced.
    Flexible(Box<RodModel>),
}

fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

impl RodBody {
    /// The rod described by the parameters (validated beforehand).
    pub fn from_parameters(p: &Parameters) -> Result<Self, ModelError> {
        match p.rod_formulation {
            RodFormulation::Rigid => {
                let mass = p.rod.mass();
                let end_masses = p.rod.end_masses();
                let mass_matrix = Mat::from_fn(4, 4, |i, j| {
                    if i % 2 != j % 2 {
                        0.0
                    } else if i / 2 == j / 2 {
                        mass / 3.0 + end_masses[i / 2]
                    } else {
                        mass / 6.0
                    }
                });
                Ok(Self::Rigid {
                    mass,
                    end_masses,
                    length: p.rod.length,
                    mass_matrix,
                })
            }
            RodFormulation::Ancf => Ok(Self::Flexible(Box::new(
                RodModel::full(Rod::new(p.rod, p.n_elements)?)?
                    .with_end_masses(p.rod.end_masses())?,
            ))),
            RodFormulation::CraigBampton => Ok(Self::Flexible(Box::new(
                RodModel::craig_bampton(
                    Rod::new(p.rod, p.n_elements)?,
                    p.n_modes,
                    p.boundary,
                    p.quadrature,
                )?
                .with_end_masses(p.rod.end_masses())?,
            ))),
        }
    }

    /// Number of coordinates.
    pub fn n_coordinates(&self) -> usize {
        match self {
            Self::Rigid { .. } => 4,
            Self::Flexible(model) => model.n_coordinates(),
        }
    }

    /// Offset of r_B (the slider-pin end) in the rod coordinates.
    pub fn end_offset(&self) -> usize {
        match self {
            Self::Rigid { .. } => 2,
            Self::Flexible(model) => model.end_node_offset(),
        }
    }

    /// Constant mass matrix.
    pub fn mass_matrix(&self) -> MatRef<'_, f64> {
        match self {
            Self::Rigid { mass_matrix, .. } => mass_matrix.as_ref(),
            Self::Flexible(model) => model.mass_matrix(),
        }
    }

    /// Solves M x = b in place.
    pub fn solve_mass(&self, b: &mut [f64]) {
        match self {
            Self::Rigid {
                mass, end_masses, ..
            } if *end_masses == [0.0; 2] => {
                // M⁻¹ = (2/m) [2 −1; −1 2] ⊗ I₂.
                let c = 2.0 / mass;
                for d in 0..2 {
                    let (a, bb) = (b[d], b[2 + d]);
                    b[d] = c * (2.0 * a - bb);
                    b[2 + d] = c * (2.0 * bb - a);
                }
            }
            Self::Rigid {
                mass, end_masses, ..
            } => {
                // [m/3 + m_A, m/6; m/6, m/3 + m_B]⁻¹ ⊗ I₂.
                let (p, q, r) = (
                    mass / 3.0 + end_masses[0],
                    mass / 6.0,
                    mass / 3.0 + end_masses[1],
                );
                let det = p * r - q * q;
                for d in 0..2 {
                    let (a, bb) = (b[d], b[2 + d]);
                    b[d] = (r * a - q * bb) / det;
                    b[2 + d] = (p * bb - q * a) / det;
                }
            }
            Self::Flexible(model) => model.solve_mass(b),
        }
    }

    /// Internal (elastic + damping) force, written to `out` (zero for the rigid rod); returns the
    /// power the material damping dissipates \[W\].
    pub fn internal_force(&mut self, p: &[f64], p_dot: &[f64], out: &mut [f64]) -> f64 {
        match self {
            Self::Rigid { .. } => {
                out.fill(0.0);
                0.0
            }
            Self::Flexible(model) => model.internal_force(p, p_dot, out),
        }
    }

    /// Constant gravity load for the acceleration `g`.
    pub fn gravity_force(&self, g: Vector2<f64>) -> Vec<f64> {
        match self {
            Self::Rigid {
                mass, end_masses, ..
            } => {
                let half = 0.5 * mass;
                let [a, b] = end_masses.map(|m| half + m);
                vec![a * g.x, a * g.y, b * g.x, b * g.y]
            }
            Self::Flexible(model) => {
                let q = model.rod().gravity_force(g);
                let mut out = vec![0.0; model.n_coordinates()];
                model.project_force(&q, &mut out);
                let b = model.end_node_offset();
                for (pin, m) in [0, b]
                    .into_iter()
                    .zip(model.rod().properties().end_masses())
                {
                    out[pin] += m * g.x;
                    out[pin + 1] += m * g.y;
                }
                out
            }
        }
    }

    /// Largest displacement along the rod \[m\] per unit of each coordinate (1 for the rigid rod's
    /// pin positions; see [`RodModel::displacement_scales`]).
    pub fn displacement_scales(&self) -> Vec<f64> {
        match self {
            Self::Rigid { .. } => vec![1.0; 4],
            Self::Flexible(model) => model.displacement_scales(),
        }
    }

    /// Strain energy \[J\] (0 for the rigid rod).
    pub fn strain_energy(&mut self, p: &[f64]) -> f64 {
        match self {
            Self::Rigid { .. } => 0.0,
            Self::Flexible(model) => model.strain_energy(p),
        }
    }

    /// Direction whose rotation is the rod's at the end `end`: the end slope r_x of the ANCF rod,
    /// or the chord r_B − r_A of the rigid rod. It is linear in the coordinates, so applied to ṗ
    /// it gives the rate.
    pub fn end_direction(&self, end: RodEnd, v: &[f64]) -> Vector2<f64> {
        match self {
            Self::Rigid { .. } => Vector2::new(v[2] - v[0], v[3] - v[1]),
            Self::Flexible(model) => model.end_slope(end, v),
        }
    }

    /// Angular velocity of the rod at the end `end`, ω = (d × ḋ)/|d|² (docs/model.md §1.1).
    pub fn end_angular_velocity(&self, end: RodEnd, p: &[f64], p_dot: &[f64]) -> f64 {
        let d = self.end_direction(end, p);
        cross(d, self.end_direction(end, p_dot)) / d.norm_squared()
    }

    /// Adds the generalised force of a moment `m` acting at the end `end`: m (∂φ/∂p)ᵀ with
    /// ∂φ/∂d = ẑ × d / |d|² (docs/model.md §1.6).
    pub fn add_end_moment(&self, end: RodEnd, p: &[f64], m: f64, out: &mut [f64]) {
        let d = self.end_direction(end, p);
        let g = m / d.norm_squared() * Vector2::new(-d.y, d.x);
        match self {
            Self::Rigid { .. } => {
                out[2] += g.x;
                out[3] += g.y;
                out[0] -= g.x;
                out[1] -= g.y;
            }
            Self::Flexible(model) => model.add_end_slope_force(end, g, out),
        }
    }

    /// Mid-span deflection: displacement of the point at arc length l/2 perpendicular to the chord
    /// A → B, positive to the left of the chord direction (docs/model.md §7). 0 for the rigid rod.
    pub fn midspan_deflection(&mut self, p: &[f64]) -> f64 {
        match self {
            Self::Rigid { .. } => 0.0,
            Self::Flexible(model) => model.midspan_deflection(p),
        }
    }

    /// Model coordinates of the straight, uniformly stretched rod from `a` to `b`: r(x) = a +
    /// (x/L)(b − a), r_x = (b − a)/L (the natural coordinates [a, b] of the rigid rod). The map is
    /// linear, so applied to end velocities or accelerations it gives the straight rod's rates.
    pub fn straight(&self, a: Vector2<f64>, b: Vector2<f64>) -> Vec<f64> {
        match self {
            Self::Rigid { .. } => vec![a.x, a.y, b.x, b.y],
            Self::Flexible(model) => {
                let rod = model.rod();
                let n = rod.n_elements();
                let slope = (b - a) / rod.properties().length;
                let e: Vec<f64> = (0..=n)
                    .flat_map(|k| {
                        let r = a + (k as f64 / n as f64) * (b - a);
                        [r.x, r.y, slope.x, slope.y]
                    })
                    .collect();
                model.model_coordinates(&e)
            }
        }
    }

    /// Rigid-rod length l, if rigid (the mechanism adds the length constraint).
    pub fn rigid_length(&self) -> Option<f64> {
        match self {
            Self::Rigid { length, .. } => Some(*length),
            Self::Flexible(_) => None,
        }
    }
}
