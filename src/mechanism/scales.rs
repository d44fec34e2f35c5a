//! The mechanism's error control: its weights, and the length scale at which the joint's force law
//! changes, in which the integrators measure every coordinate's error
//! ([`super::SliderCrank::error_scales`]).

use super::inputs::Inputs;
use crate::params::{JointModel, Parameters, RodFormulation};

/// What the error control weighs the state by, fixed when the mechanism is built.
#[derive(Clone, Debug)]
pub(super) struct ErrorControl {
    /// Reference crank speed of the error scales (the initial speed, at least 1 rad/s).
    pub reference_speed: f64,
    /// Length scale ℓ of the error scales \[m\].
    pub position_scale: f64,
    /// Weight of a dry journal's normal velocity in the error control (0: not held).
    pub impact_error_weight: f64,
}

/// Round-off floor of the length scale, in units of ε_mach (r_c + l) / rtol: the error control
/// never asks for a position error below 100 units in the last place of the mechanism's
/// coordinates, which no step size can deliver (a 4-mode rod at rest under gravity, at
/// rtol 1e-8, otherwise shrank its steps to 5e-10 s and stalled).
const ROUND_OFF_FLOOR: f64 = 100.0 * f64::EPSILON;

/// The length ℓ at which a joint's force law changes (the error scales' unit of length):
/// 1 % of the crank length at most, and the smallest over the clearance joints of
/// - dry joint: the clearance c (contact starts when the journal crosses it);
/// - lubricated joint: the film thickness at the switch, c (1 − ε_b) (the film force grows as
///   (1 − ε)^−5/2 towards it);
///
/// or, with every joint ideal,
/// - the rigid rod: 1 % of the crank length;
/// - a flexible rod: the rod's axial deformation under its load, F L / EA with
///   F = (m_rod + m_slider) ω₀² r_c + |F_s| + |T|/r_c + (m_crank + m_rod + m_slider) |g|
///   (inertia, the start's slider force and drive torque, gravity: the joint force is the rod's
///   axial force), per element (L/n) for the full rod, whose coordinates resolve each element's
///   stretch;
///
/// and at least the round-off floor [`ROUND_OFF_FLOOR`] · (r_c + l) / rtol.
pub(super) fn position_scale(p: &Parameters, inputs: &Inputs) -> f64 {
    let floor = ROUND_OFF_FLOOR * (p.crank_length + p.rod.length) / p.integration_tolerance();
    joint_length(p, inputs).max(floor)
}

fn joint_length(p: &Parameters, inputs: &Inputs) -> f64 {
    let base = 0.01 * p.crank_length;
    let clearance_length = p
        .joints()
        .into_iter()
        .filter_map(|(_, joint)| match joint.model {
            JointModel::Dry => Some(joint.clearance.min(base)),
            JointModel::Lubricated => {
                Some(joint.clearance.min(base) * (1.0 - joint.switch_eccentricity))
            }
            JointModel::Ideal => None,
        })
        .reduce(f64::min);
    match (clearance_length, p.rod_formulation) {
        (Some(length), _) => length,
        (None, RodFormulation::Rigid) => base,
        (None, rod) => {
            let speed = p.start_speed(inputs.drive_speed).abs().max(1.0);
            let masses = p.rod.mass() + p.slider_mass;
            let load = masses * speed * speed * p.crank_length
                + inputs.slider_force.abs()
                + inputs.drive_torque.abs() / p.crank_length
                + (masses + p.crank_mass) * p.gravity.abs();
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
