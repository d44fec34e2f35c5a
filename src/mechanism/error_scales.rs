//! The error scales of the mechanism's state: how the integrators measure each component's local
//! error, in units of the joint's length scale ([`super::scales::position_scale`]).

use super::layout::{CRANK_ANGLE, PIN_A};
use super::slider_crank::SliderCrank;
use crate::integrator::ErrorScales;
use crate::joint::{Joint, JointRole, normal_rate_error};

impl SliderCrank {
    /// Error weights of each state component ([`ErrorScales`]): the integrators compare its
    /// local error with `rtol · sᵢ` for coordinates and velocities (absolute only: positions and
    /// velocities have no natural origin) and with `rtol · (sᵢ + |yᵢ|)` for the work integrals.
    ///
    /// Every state is measured by the displacement (or velocity) it causes in the mechanism, in
    /// units of the joint's length scale ℓ (see `position_scale`) and of the speed V = ω₀ ℓ
    /// (ω₀ = |the crank's start speed|, at least 1 rad/s, [`crate::Parameters::start_speed`]):
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
    ///
    /// At each dry joint the journal's normal velocity in the bearing, δ̇ = n · ė with n = e/|e|
    /// (ė = ṙ_B − (ẋ_s, 0) at the rod–slider joint), is also held to `rtol · V / w` on its own, with
    /// w = `solver.impactErrorWeight` (max-norm; the implicit methods; not at w = 0): it decides
    /// when and how fast the journal meets the wall, hence every impact's onset and peak, yet the
    /// RMS over all 2n + 4 components lets it drift. (The tangential velocity is left to the RMS:
    /// with friction it is stiff while the journal sticks.)
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
        let held = self
            .held_joints()
            .map(|_| speed / self.impact_error_weight)
            .collect();
        ErrorScales {
            absolute: scales,
            relative,
            held,
        }
    }

    /// The dry joints whose journal's normal velocity is held (none at w = 0), from the ground to
    /// the slider: the order of [`ErrorScales::held`].
    fn held_joints(&self) -> impl Iterator<Item = JointRole> + '_ {
        JointRole::ALL.into_iter().filter(|&role| {
            self.impact_error_weight > 0.0 && matches!(self.joint(role), Joint::Dry(_))
        })
    }

    /// The local errors of the held quantities for the error estimate `err` of a step ending at
    /// `y` ([`crate::integrator::MechanicalSystem::held_errors`]): each dry journal's normal
    /// velocity in its bearing, δ̇ = n · ė, with n the direction of e at the step's end and the
    /// error of ė from those of the velocities it is made of (at the crank pin, ė = ṙ_P − ṙ_A with
    /// ṙ_P = r_c θ̇ (−sin θ, cos θ), whose error is r_c (−sin θ, cos θ) δθ̇ − r_c θ̇ (cos θ, sin θ) δθ).
    pub(super) fn journal_held_errors(&self, y: &[f64], err: &[f64], out: &mut [f64]) {
        let l = self.layout;
        for (role, out) in self.held_joints().zip(out) {
            *out = match role {
                JointRole::RodSlider => {
                    let (b, rate) = (l.pin_b(), l.rate_of(l.pin_b()));
                    normal_rate_error(
                        (y[b] - y[l.slider()], y[b + 1]),
                        (err[rate] - err[l.slider_velocity()], err[rate + 1]),
                    )
                }
                JointRole::CrankPin => {
                    let e = self.joint_kinematics(role, y).e;
                    let (sin, cos) = crate::math::sin_cos(y[CRANK_ANGLE]);
                    let r_c = self.crank_length;
                    let (d_angle, d_speed) = (err[CRANK_ANGLE], err[l.crank_speed()]);
                    let omega = y[l.crank_speed()];
                    let rate = l.rate_of(PIN_A);
                    normal_rate_error(
                        (e.x, e.y),
                        (
                            -r_c * sin * d_speed - r_c * omega * cos * d_angle - err[rate],
                            r_c * cos * d_speed - r_c * omega * sin * d_angle - err[rate + 1],
                        ),
                    )
                }
                JointRole::MainBearing => 0.0,
            };
        }
    }
}
