//! The error scales of the mechanism's states: the length and speed in which the integrators
//! measure every coordinate's error.

use super::SliderCrank;
use super::layout::CRANK_ANGLE;
use crate::integrator::ErrorScales;
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

impl SliderCrank {
    /// Error weights of each state component ([`ErrorScales`]): the integrators compare its
    /// local error with `rtol · sᵢ` for coordinates and velocities (absolute only: positions and
    /// velocities have no natural origin) and with `rtol · (sᵢ + |yᵢ|)` for the work integrals.
    ///
    /// Every state is measured by the displacement (or velocity) it causes in the mechanism, in
    /// units of the joint's length scale ℓ (see `position_scale`) and of the speed V = ω₀ ℓ
    /// (ω₀ = |crank.initialSpeed|, at least 1 rad/s):
    /// ```text
    /// θ, θ_d          ℓ / r_c               θ̇            V / r_c
    /// rod coordinate  ℓ / d_j               its rate     V / d_j
    /// x_s             ℓ                     ẋ_s          V
    /// works           ½ m (ω₀ r_c)² ℓ / r_c,   m = I_O/r_c² + m_rod + m_slider
    /// ```
    /// with d_j the largest displacement along the rod per unit of coordinate j (1 for positions,
    /// ≈ (4/27) l_e for ANCF slopes, the mode shape's largest value for modal amplitudes). A
    /// coordinate whose unit moves the rod little gets a proportionally larger scale, so the
    /// error control asks the same physical accuracy of every coordinate.
    pub fn error_scales(&self) -> ErrorScales {
        let l = self.layout;
        let length = self.position_scale;
        let speed = self.reference_speed * length;
        let pin_speed = self.reference_speed * self.crank_length;
        let mass =
            self.crank_inertia / self.crank_length.powi(2) + self.rod_mass + self.slider_mass;
        let mut scales = vec![0.0; l.n_states()];
        scales[CRANK_ANGLE] = length / self.crank_length;
        scales[l.crank_speed()] = speed / self.crank_length;
        for (j, d) in self.rod.displacement_scales().into_iter().enumerate() {
            scales[l.rod_coordinate(j)] = length / d;
            scales[l.rod_rate(j)] = speed / d;
        }
        scales[l.slider()] = length;
        scales[l.slider_velocity()] = speed;
        scales[l.drive_angle()] = scales[CRANK_ANGLE];
        for s in &mut scales[l.integrals()] {
            *s = 0.5 * mass * pin_speed * pin_speed * length / self.crank_length;
        }
        let relative = (0..scales.len())
            .map(|i| if l.integrals().contains(&i) { 1.0 } else { 0.0 })
            .collect();
        ErrorScales {
            absolute: scales,
            relative,
        }
    }
}
