//! The length scale of the mechanism's error control: the length at which the joint's force law
//! changes, in which the integrators measure every coordinate's error
//! ([`super::SliderCrank::error_scales`]).

use crate::params::{JointModel, Parameters, RodFormulation};

/// The length ℓ at which the joint's force law changes (the error scales' unit of length):
/// 1 % of the crank length at most, and
/// - dry joint: the clearance c (contact starts when the journal crosses it);
/// - lubricated joint: the film thickness at the switch, c (1 − ε_b) (the film force grows as
///   (1 − ε)^−5/2 towards it);
/// - ideal joint on a flexible rod: the rod's axial deformation under the inertial load,
///   F L / EA with F = (m_rod + m_slider) ω₀² r_c (the joint force is the rod's axial force),
///   per element (L/n) for the full rod, whose coordinates resolve each element's stretch.
pub(super) fn position_scale(p: &Parameters) -> f64 {
    let base = 0.01 * p.crank_length;
    match (p.joint_model, p.rod_formulation) {
        (JointModel::Dry, _) => p.clearance.min(base),
        (JointModel::Lubricated, _) => p.clearance.min(base) * (1.0 - p.switch_eccentricity),
        (JointModel::Ideal, RodFormulation::Rigid) => base,
        (JointModel::Ideal, rod) => {
            let speed = p.crank_initial_speed.abs().max(1.0);
            let load = (p.rod.mass() + p.slider_mass) * speed * speed * p.crank_length;
            // The full rod's coordinates resolve each element's stretch, the reduced rod's the
            // stretch between the pins.
            let length = match rod {
                RodFormulation::Ancf => p.rod.length / p.n_elements as f64,
                _ => p.rod.length,
            };
            base.min(load * length / (p.rod.youngs_modulus * p.rod.area))
        }
    }
}
