//! Craig–Bampton reduction of the ANCF rod, and [`RodModel`]: the rod in the coordinates the
//! equations of motion use (full nodal coordinates or reduced ones).
//!
//! # References
//! - R. R. Craig, M. C. C. Bampton (1968), AIAA J. 6, 1313–1319.
//! - Sun et al. (2015), Mech. Mach. Theory 85, 106–115, eqs. (1)–(3).

pub mod craig_bampton;
pub mod modes;
pub mod sampling;

use faer::{Mat, MatMut, MatRef};

use crate::linalg::band_cholesky::BandCholesky;

pub use craig_bampton::{Boundary, CraigBampton, check_mode_count, max_modes};
pub use modes::{Modes, generalized_eigen};
pub use sampling::SampledForces;

use nalgebra::Vector2;

use crate::ancf::RodLoad;
use crate::ancf::{NormalStresses, Rod, SectionResult};
use crate::error::ModelError;
use crate::math::same_bits;

/// How the reduced rod integrates its internal forces and strain energy.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quadrature {
    /// Every quadrature point of the mesh the rod was reduced from.
    Full,
    /// The few weighted points of energy-conserving sampling ([`sampling`]).
    Sampled,
}

/// What the rod's deformation gives a designer at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Deformation {
    /// Strain energy \[J\].
    pub energy: f64,
    /// The rod's normal stresses from the equilibrium of its parts ([`Rod::normal_stresses`]).
    pub stresses: NormalStresses,
    /// Unit tangents r,ₓ/|r,ₓ| at the crank-pin end and at the slider-pin end.
    pub tangents: [Vector2<f64>; 2],
}

/// An end of the rod: its first node, at the crank pin (pin A), or its last, at the slider pin
/// (pin B).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RodEnd {
    /// The crank pin's end, node 0.
    CrankPin = 0,
    /// The slider pin's end, node n.
    SliderPin = 1,
}

/// The rod in full ANCF coordinates or in Craig–Bampton coordinates p (e = V p), with the buffers
/// its force evaluation needs, so that evaluating forces never allocates.
///
/// In every case the first 2 coordinates are the crank-pin end r₀ and [`RodModel::end_node_offset`]
/// locates the slider-pin end r_n: joints are written directly in these coordinates. The end slopes
/// r₀,ₓ and r_n,ₓ (whose rotations are the pins' eyes') are coordinates of the full model and of the
/// positions-and-slopes interface, and linear combinations of p with the pin interface
/// ([`RodModel::end_slope`]).
#[derive(Clone, Debug)]
pub struct RodModel {
    rod: Rod,
    reduction: Option<CraigBampton>,
    /// The sampled internal forces, when the reduced rod uses [`Quadrature::Sampled`].
    sampled: Option<SampledForces>,
    mass: Mat<f64>,
    mass_factor: BandCholesky,
    /// Masses lumped at the crank-pin and the slider-pin ends (in `mass`) \[kg\].
    end_masses: [f64; 2],
    /// r_ₓ at each end ([`RodEnd`]) = Σ (w · (p₂ⱼ, p₂ⱼ₊₁)) over (j, w): the end slopes as
    /// combinations of coordinate pairs.
    end_slopes: [Vec<(usize, f64)>; 2],
    /// Nodal coordinates of the last model coordinates expanded.
    e: Expansion,
    e_dot: Vec<f64>,
    /// Nodal accelerations (section resultants).
    e_ddot: Vec<f64>,
    q: Vec<f64>,
    k_full: Mat<f64>,
    k_work: Mat<f64>,
    memo: ForceMemo,
}

/// The last internal force with its arguments. Most difference quotients of the integrator's
/// Jacobian (those in the velocities of an undamped rod, in the crank angle and the slider
/// position) leave the rod's coordinates unchanged: they reuse the force, bit for bit.
#[derive(Clone, Debug)]
struct ForceMemo {
    valid: bool,
    p: Vec<f64>,
    /// ṗ, when the force depends on it (a damped rod); empty otherwise.
    p_dot: Vec<f64>,
    force: Vec<f64>,
    power: f64,
}

impl ForceMemo {
    fn new(n: usize) -> Self {
        Self {
            valid: false,
            p: vec![0.0; n],
            p_dot: Vec::with_capacity(n),
            force: vec![0.0; n],
            power: 0.0,
        }
    }

    /// The stored power if the arguments equal the stored ones bit for bit (force copied to `out`).
    fn recall(&self, p: &[f64], p_dot: &[f64], out: &mut [f64]) -> Option<f64> {
        let hit = self.valid
            && same_bits(&self.p, p)
            && (self.p_dot.is_empty() || same_bits(&self.p_dot, p_dot));
        hit.then(|| {
            out.copy_from_slice(&self.force);
            self.power
        })
    }

    fn store(&mut self, p: &[f64], p_dot: Option<&[f64]>, force: &[f64], power: f64) {
        self.p.copy_from_slice(p);
        self.p_dot.clear();
        self.p_dot.extend_from_slice(p_dot.unwrap_or_default());
        self.force.copy_from_slice(force);
        self.power = power;
        self.valid = true;
    }
}

impl RodModel {
    /// The full (unreduced) rod.
    pub fn full(rod: Rod) -> Result<Self, ModelError> {
        let mass = rod.mass_matrix();
        Self::build(rod, None, mass)
    }

    /// The rod reduced by Craig–Bampton with `n_modes` mode shapes and the given interface, its
    /// internal forces integrated by `quadrature`.
    pub fn craig_bampton(
        rod: Rod,
        n_modes: usize,
        boundary: Boundary,
        quadrature: Quadrature,
    ) -> Result<Self, ModelError> {
        let cb = CraigBampton::new(&rod, n_modes, boundary)?;
        let mass = cb.mass_matrix().to_owned();
        let sampled = match quadrature {
            Quadrature::Full => None,
            Quadrature::Sampled => Some(SampledForces::new(&rod, &cb)?),
        };
        let mut model = Self::build(rod, Some(cb), mass)?;
        model.sampled = sampled;
        Ok(model)
    }

    fn build(
        rod: Rod,
        reduction: Option<CraigBampton>,
        mass: Mat<f64>,
    ) -> Result<Self, ModelError> {
        let mass_factor = BandCholesky::new(mass.as_ref())?;
        let n_full = rod.n_coordinates();
        let n = mass.nrows();
        // The slopes r₀,ₓ and r_n,ₓ are the pairs 1 and 2n + 1 of the full model's coordinates.
        let end_slopes = [1, 2 * rod.n_elements() + 1].map(|slope_row| match &reduction {
            Some(cb) => cb
                .scalar_row(slope_row)
                .enumerate()
                .filter(|(_, w)| *w != 0.0)
                .collect(),
            None => vec![(slope_row, 1.0)],
        });
        Ok(Self {
            end_slopes,
            reduction,
            sampled: None,
            mass_factor,
            mass,
            end_masses: [0.0; 2],
            e: Expansion::new(n, n_full),
            e_dot: vec![0.0; n_full],
            e_ddot: vec![0.0; n_full],
            q: vec![0.0; n_full],
            k_full: Mat::zeros(n_full, n_full),
            k_work: Mat::zeros(n_full, n),
            memo: ForceMemo::new(n),
            rod,
        })
    }

    /// The model with the masses `end_masses` lumped at its end nodes' positions (the pins): added
    /// to the mass matrix's diagonal there, where the coordinates are physical in every model
    /// (the reduced rod's boundary block; its fixed-interface modes do not change), and the
    /// factor renewed. Without end masses the model is returned as it is.
    pub fn with_end_masses(mut self, end_masses: [f64; 2]) -> Result<Self, ModelError> {
        if end_masses == [0.0; 2] {
            return Ok(self);
        }
        let b = self.end_node_offset();
        for (pin, mass) in [0, b].into_iter().zip(end_masses) {
            for d in 0..2 {
                self.mass[(pin + d, pin + d)] += mass;
            }
        }
        self.mass_factor = BandCholesky::new(self.mass.as_ref())?;
        self.end_masses = end_masses;
        Ok(self)
    }

    /// The underlying ANCF rod.
    pub fn rod(&self) -> &Rod {
        &self.rod
    }

    /// The Craig–Bampton reduction, if any.
    pub fn reduction(&self) -> Option<&CraigBampton> {
        self.reduction.as_ref()
    }

    /// The sampled internal forces, if the reduced rod uses them.
    pub fn sampled(&self) -> Option<&SampledForces> {
        self.sampled.as_ref()
    }

    /// Number of coordinates of the model.
    pub fn n_coordinates(&self) -> usize {
        self.mass.nrows()
    }

    /// Offset of the last node's position r_n in the model's coordinate vector.
    pub fn end_node_offset(&self) -> usize {
        match &self.reduction {
            Some(cb) => cb.end_node_offset(),
            None => self.rod.last_node_offset(),
        }
    }

    /// Slope r_ₓ at the rod's end `end` for the coordinates `p` (or its rate, applied to ṗ: the
    /// map is linear).
    pub fn end_slope(&self, end: RodEnd, p: &[f64]) -> Vector2<f64> {
        self.end_slopes[end as usize]
            .iter()
            .fold(Vector2::zeros(), |acc, &(j, w)| {
                acc + w * Vector2::new(p[2 * j], p[2 * j + 1])
            })
    }

    /// Adds the generalised force of a force `g` acting on the slope r_ₓ at the end `end`:
    /// (∂r_ₓ/∂p)ᵀ g.
    pub fn add_end_slope_force(&self, end: RodEnd, g: Vector2<f64>, out: &mut [f64]) {
        for &(j, w) in &self.end_slopes[end as usize] {
            out[2 * j] += w * g.x;
            out[2 * j + 1] += w * g.y;
        }
    }

    /// Constant mass matrix (full M or reduced Vᵀ M V).
    pub fn mass_matrix(&self) -> MatRef<'_, f64> {
        self.mass.as_ref()
    }

    /// Solves M x = b in place with the stored banded Cholesky factor (no allocation).
    pub fn solve_mass(&self, b: &mut [f64]) {
        self.mass_factor.solve(b);
    }

    /// Nodal ANCF coordinates e of the model coordinates `p` (e = V p, or p itself).
    pub fn nodal_coordinates<'a>(&'a mut self, p: &'a [f64]) -> &'a [f64] {
        self.e.of(self.reduction.as_ref(), p)
    }

    /// Internal (elastic + damping) force in model coordinates, written to `out`; returns the
    /// power the damping dissipates, ṗᵀQ_d = ėᵀQ_d (the projection preserves power) \[W\].
    pub fn internal_force(&mut self, p: &[f64], p_dot: &[f64], out: &mut [f64]) -> f64 {
        if let Some(power) = self.memo.recall(p, p_dot, out) {
            return power;
        }
        let damped = self.rod.element().section().damping != 0.0;
        let power = match (&self.reduction, &self.sampled) {
            (_, Some(sampled)) => sampled.internal_force(p, p_dot, out),
            (Some(cb), None) => {
                let e = self.e.of(Some(cb), p);
                let power = if damped {
                    cb.expand(p_dot, &mut self.e_dot);
                    self.rod.internal_force(e, &self.e_dot, &mut self.q)
                } else {
                    self.rod.elastic_force(e, &mut self.q);
                    0.0
                };
                cb.project(&self.q, out);
                power
            }
            (None, None) => self.rod.internal_force(p, p_dot, out),
        };
        self.memo.store(p, damped.then_some(p_dot), out, power);
        power
    }

    /// Tangent stiffness ∂Q_e/∂p in model coordinates of the mesh's full quadrature, written to
    /// `out`.
    pub fn tangent_stiffness(&mut self, p: &[f64], out: MatMut<'_, f64>) {
        match &self.reduction {
            Some(cb) => {
                let e = self.e.of(Some(cb), p);
                self.rod.tangent_stiffness(e, self.k_full.as_mut());
                cb.project_matrix(self.k_full.as_ref(), self.k_work.as_mut(), out);
            }
            None => self.rod.tangent_stiffness(p, out),
        }
    }

    /// Strain energy U(V p) \[J\] (the sampled Ũ(p) of a sampled rod).
    pub fn strain_energy(&mut self, p: &[f64]) -> f64 {
        if let Some(sampled) = &self.sampled {
            return sampled.strain_energy(p);
        }
        let e = self.e.of(self.reduction.as_ref(), p);
        self.rod.strain_energy(e)
    }

    /// The rod's strain energy, normal stresses and end tangents at `p` with accelerations
    /// `p_ddot` under `load`, from one expansion to nodal coordinates.
    pub fn deformation(&mut self, p: &[f64], p_ddot: &[f64], load: &RodLoad) -> Deformation {
        let e = self.e.of(self.reduction.as_ref(), p);
        let e_ddot = nodal(self.reduction.as_ref(), &mut self.e_ddot, p_ddot);
        let last = self.rod.last_node_offset();
        let unit = |at: usize| Vector2::new(e[at], e[at + 1]).normalize();
        Deformation {
            energy: match &self.sampled {
                Some(sampled) => sampled.strain_energy(p),
                None => self.rod.strain_energy(e),
            },
            stresses: self.rod.normal_stresses(e, e_ddot, load),
            tangents: [unit(2), unit(last + 2)],
        }
    }

    /// Mid-span deflection: displacement of the point at arc length L/2 perpendicular to the chord
    /// from node 0 to the last node, positive to the left of the chord direction \[m\].
    pub fn midspan_deflection(&mut self, p: &[f64]) -> f64 {
        let e = self.e.of(self.reduction.as_ref(), p);
        self.rod.deflection(e, 0.5)
    }

    /// The rod's `result` at `out.len()` evenly spaced sections from its first node to its last
    /// ([`crate::ancf::section_place`]) at `p` with accelerations `p_ddot` under `load`.
    pub fn sections(
        &mut self,
        p: &[f64],
        p_ddot: &[f64],
        load: &RodLoad,
        result: SectionResult,
        out: &mut [f64],
    ) {
        let e = self.e.of(self.reduction.as_ref(), p);
        let e_ddot = nodal(self.reduction.as_ref(), &mut self.e_ddot, p_ddot);
        self.rod.sections(e, e_ddot, load, result, out);
    }

    /// For each model coordinate, the largest displacement along the rod \[m\] per unit of it:
    /// max over nodes of |∂r_k/∂p_j| and (4/27) l_e |∂r_k,ₓ/∂p_j| (the largest value of the cubic
    /// slope shape function l_e(ξ − 2ξ² + ξ³), l_e the element length). Positions give 1.
    pub fn displacement_scales(&self) -> Vec<f64> {
        let slope_length = 4.0 / 27.0 * self.rod.element().length();
        let n_full = self.rod.n_coordinates();
        (0..self.n_coordinates())
            .map(|j| {
                (0..n_full)
                    .map(|i| {
                        let weight = if (i / 2) % 2 == 0 { 1.0 } else { slope_length };
                        let v = match &self.reduction {
                            Some(cb) => cb.basis()[(i, j)],
                            None => f64::from(u8::from(i == j)),
                        };
                        weight * v.abs()
                    })
                    .fold(0.0, f64::max)
            })
            .collect()
    }

    /// Generalised force Vᵀ q of a force `q` on the nodal coordinates, written to `out`.
    pub fn project_force(&self, q: &[f64], out: &mut [f64]) {
        match &self.reduction {
            Some(cb) => cb.project(q, out),
            None => out.copy_from_slice(q),
        }
    }

    /// Model coordinates of nodal coordinates `e`: the M-orthogonal projection
    /// p = (Vᵀ M V)⁻¹ Vᵀ M e, exact when e lies in the reduced space (e.g. any straight rod), M
    /// the beam's mass with the end masses at its end nodes' positions.
    pub fn model_coordinates(&self, e: &[f64]) -> Vec<f64> {
        let Some(cb) = &self.reduction else {
            return e.to_vec();
        };
        let me = self.rod.mass_matrix() * MatRef::from_column_major_slice(e, e.len(), 1);
        let mut p = vec![0.0; self.n_coordinates()];
        let mut me: Vec<f64> = (0..e.len()).map(|i| me[(i, 0)]).collect();
        let last = self.rod.last_node_offset();
        for (node, mass) in [0, last].into_iter().zip(self.end_masses) {
            for d in 0..2 {
                me[node + d] += mass * e[node + d];
            }
        }
        cb.project(&me, &mut p);
        self.solve_mass(&mut p);
        p
    }
}

/// The nodal coordinates e = V p of the model coordinates last expanded, with those
/// coordinates: the validity check at a communication point, the equations of motion there and
/// in the peak-hold's samples, and the loads read with them ask for the same expansion, and a
/// Jacobian's difference quotients in a damped rod's velocities keep the positions.
#[derive(Clone, Debug)]
struct Expansion {
    p: Vec<f64>,
    e: Vec<f64>,
    valid: bool,
}

impl Expansion {
    fn new(n: usize, n_full: usize) -> Self {
        Self {
            p: vec![0.0; n],
            e: vec![0.0; n_full],
            valid: false,
        }
    }

    /// The nodal coordinates of `p`: expanded by the reduction unless the stored ones are of
    /// these coordinates bit for bit, or `p` itself for the full rod.
    fn of<'a>(&'a mut self, reduction: Option<&CraigBampton>, p: &'a [f64]) -> &'a [f64] {
        let Some(cb) = reduction else {
            return p;
        };
        if !(self.valid && same_bits(&self.p, p)) {
            cb.expand(p, &mut self.e);
            self.p.copy_from_slice(p);
            self.valid = true;
        }
        &self.e
    }
}

/// The nodal coordinates of the model coordinates `p`: expanded into `buffer` by the
/// reduction, or `p` itself for the full rod.
fn nodal<'a>(reduction: Option<&CraigBampton>, buffer: &'a mut [f64], p: &'a [f64]) -> &'a [f64] {
    match reduction {
        Some(cb) => {
            cb.expand(p, buffer);
            buffer
        }
        None => p,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ancf::RodProperties;
    use crate::math;

    /// What a reduced, damped rod gives at some coordinates is the same, bit for bit, whatever
    /// coordinates it expanded before: two deformed states read in turn, through every method
    /// that expands positions, against a model that reads each state afresh.
    #[test]
    fn a_reading_is_of_its_own_coordinates() {
        let props = RodProperties {
            stiffness_damping: 1e-5,
            ..RodProperties::benchmark_b()
        };
        let model = || {
            let rod = Rod::new(props, 4).unwrap();
            RodModel::craig_bampton(rod, 4, Boundary::PositionsAndSlopes, Quadrature::Full).unwrap()
        };
        let straight = model().model_coordinates(
            &model()
                .rod()
                .straight_configuration(Vector2::new(0.03, -0.01), 0.7),
        );
        let states: Vec<(Vec<f64>, Vec<f64>)> = [1.0, -2.0]
            .iter()
            .map(|&s| {
                let p = straight
                    .iter()
                    .enumerate()
                    .map(|(i, x)| x + s * 1e-4 * math::sin(i as f64 + 1.0))
                    .collect();
                let p_dot = (0..straight.len())
                    .map(|i| s * math::cos(i as f64))
                    .collect();
                (p, p_dot)
            })
            .collect();
        let load = RodLoad {
            start_force: Vector2::new(120.0, -40.0),
            start_moment: 0.0,
            gravity: Vector2::new(0.0, -9.81),
        };
        let n = straight.len();
        let read = |m: &mut RodModel, (p, p_dot): &(Vec<f64>, Vec<f64>)| {
            let mut force = vec![0.0; n];
            let power = m.internal_force(p, p_dot, &mut force);
            let deformation = m.deformation(p, p_dot, &load);
            let mut stiffness = Mat::zeros(n, n);
            m.tangent_stiffness(p, stiffness.as_mut());
            let stiffness: Vec<u64> = (0..n * n)
                .map(|k| stiffness[(k % n, k / n)].to_bits())
                .collect();
            let energy = m.strain_energy(p);
            let midspan = m.midspan_deflection(p);
            let mut sections = vec![0.0; 5];
            m.sections(p, p_dot, &load, SectionResult::AxialForce, &mut sections);
            let nodal = m.nodal_coordinates(p).to_vec();
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            (
                bits(&force),
                power.to_bits(),
                format!("{deformation:?}"),
                stiffness,
                [energy, midspan].map(f64::to_bits),
                bits(&sections),
                bits(&nodal),
            )
        };
        let mut in_turn = model();
        for state in [&states[0], &states[1], &states[0], &states[1]] {
            assert_eq!(read(&mut in_turn, state), read(&mut model(), state));
        }
    }
}
