//! Energies of a mechanism state, and their balance against the work integrals in the state.

use faer::MatRef;

use super::layout::CRANK_ANGLE;
use super::slider_crank::SliderCrank;
use crate::joint::{Contacts, JointRole};
use crate::math;

/// Energies of a state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Energies {
    /// Kinetic energy ½ q̇ᵀ M q̇ \[J\].
    pub kinetic: f64,
    /// Rod strain energy \[J\].
    pub strain: f64,
    /// Elastic energy stored in the contacts \[J\].
    pub contact: f64,
    /// Elastic energy the contacts stored at the start (journals settled against their
    /// bearings start with some) \[J\].
    pub contact_at_start: f64,
    /// Gravitational potential energy (zero at y = 0) \[J\].
    pub gravity: f64,
    /// Work done by the drive \[J\].
    pub drive_work: f64,
    /// Work done by the joint forces (contact, friction, film) \[J\].
    pub joint_work: f64,
    /// The work done by each joint's forces and the elastic energy stored in its contact, by
    /// [`JointRole`] (zeros for an ideal joint) \[J\].
    pub joints: [JointEnergy; 3],
    /// Work done by the external slider force \[J\].
    pub external_work: f64,
    /// Energy dissipated by the rod's material (strain-rate) damping \[J\].
    pub material_damping: f64,
}

/// The work of one joint's forces and its contact's stored energy.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct JointEnergy {
    /// Work done by the joint's forces on journal and bearing \[J\].
    pub work: f64,
    /// Elastic energy stored in its contact \[J\].
    pub contact: f64,
    /// Elastic energy stored in its contact at the start \[J\].
    pub contact_at_start: f64,
}

impl JointEnergy {
    /// Energy the joint has dissipated since the start: −W − (V_c − V_c(0)), the work of its
    /// forces less the change of its contact's stored energy (≥ 0 up to integration error; 0 at
    /// the start, also for a journal settled against its bearing).
    pub fn dissipated(&self) -> f64 {
        -self.work - (self.contact - self.contact_at_start)
    }
}

impl Energies {
    /// Energy lost in the joints since the start: −W_joint − (V_c − V_c(0)) (≥ 0 up to
    /// integration error), the sum of the joints' [`JointEnergy::dissipated`].
    pub fn dissipated(&self) -> f64 {
        -self.joint_work - (self.contact - self.contact_at_start)
    }

    /// Balance T + U + V_g + D_material − W_drive − W_external − W_joint, constant in exact
    /// arithmetic (the joint work includes the work of the elastic contact force, so V_c does not
    /// appear).
    pub fn balance(&self) -> f64 {
        self.kinetic + self.strain + self.gravity + self.material_damping
            - self.drive_work
            - self.external_work
            - self.joint_work
    }
}

impl SliderCrank {
    /// Deformation (strain) energy of the rod in state `y` \[J\] (docs/model.md §1.4; 0 for the
    /// rigid rod).
    pub fn strain_energy(&mut self, y: &[f64]) -> f64 {
        self.rod.strain_energy(&y[self.layout.rod()])
    }

    pub(super) fn kinetic_energy(&self, y: &[f64]) -> f64 {
        let l = self.layout;
        let p_dot = &y[l.rod_rates()];
        let m: MatRef<'_, f64> = self.rod.mass_matrix();
        let rod: f64 = (0..p_dot.len())
            .map(|i| p_dot[i] * (0..p_dot.len()).map(|j| m[(i, j)] * p_dot[j]).sum::<f64>())
            .sum();
        let (crank, slider) = (y[l.crank_speed()], y[l.slider_velocity()]);
        let kinetic =
            0.5 * (self.crank.inertia * crank * crank + rod + self.slider.mass * slider * slider);
        match self.crank_reference(y) {
            Some((_, v_g)) => kinetic + 0.5 * self.crank.mass * v_g.norm_squared(),
            None => kinetic,
        }
    }

    /// Gravitational potential −m g·r of the crank (centre of mass r_G, at a (cos θ, sin θ) on the
    /// fixed pivot) and of the slider (at (x_s, e)) \[J\]; the rod's is −Q_gᵀp (its gravity load
    /// is constant).
    fn gravity_potential(&self, y: &[f64]) -> f64 {
        if self.gravity == nalgebra::Vector2::zeros() {
            return 0.0;
        }
        let crank = match self.crank_reference(y) {
            Some((r_g, _)) => -self.crank.mass * self.gravity.dot(&r_g),
            None => {
                let (sin, cos) = math::sin_cos(y[CRANK_ANGLE]);
                -self.crank.mass
                    * self.crank.centre_ratio
                    * self.crank.length
                    * (self.gravity.x * cos + self.gravity.y * sin)
            }
        };
        crank
            - self.slider.mass * self.gravity.x * y[self.layout.slider()]
            - self.slider.mass * self.gravity.y * self.slider.offset
    }

    /// Energies of a state with the contact states `contacts` (evaluates the joint forces for the
    /// stored contact energy).
    pub fn energies(&mut self, y: &[f64], contacts: &Contacts) -> Energies {
        let strain = self.rod.strain_energy(&y[self.layout.rod()]);
        self.energies_with_strain(y, contacts, strain)
    }

    /// [`SliderCrank::energies`] with the rod's strain energy at `y` already known, `strain`
    /// (as [`SliderCrank::loads`] gives it).
    pub fn energies_with_strain(
        &mut self,
        y: &[f64],
        contacts: &Contacts,
        strain: f64,
    ) -> Energies {
        let l = self.layout;
        let p = &y[l.rod()];
        let rod_gravity: f64 = self
            .rod_data
            .gravity
            .iter()
            .zip(p)
            .map(|(g, x)| g * x)
            .sum();
        let joints = JointRole::ALL.map(|role| match self.joint_work[role as usize] {
            Some(i) => JointEnergy {
                work: y[i],
                contact: self.joint_force(role, y, contacts).0.potential,
                contact_at_start: self.contact_at_start[role as usize],
            },
            None => JointEnergy::default(),
        });
        Energies {
            kinetic: self.kinetic_energy(y),
            strain,
            contact: self.contact_potential(y, contacts),
            contact_at_start: self.contact_at_start.iter().sum(),
            gravity: self.gravity_potential(y) - rod_gravity,
            drive_work: y[l.drive_work()],
            joint_work: y[l.joint_works()].iter().sum(),
            joints,
            external_work: y[l.external_work()],
            material_damping: y.get(l.material_damping()).copied().unwrap_or(0.0),
        }
    }
}
