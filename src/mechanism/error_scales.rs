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
    /// x_s, r_G        ℓ                     ẋ_s, ṙ_G     V
    /// works           ½ m (ω₀ r_c)² ℓ / r_c,   m = I_O/r_c² + m_rod + m_slider
    /// film temperature 1 K
    /// ```
    /// (r_G: the centre of mass of a crank free in a clearance main bearing; I_O the crank's
    /// inertia about its pivot.)
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
        let length = self.error_control.position_scale;
        let speed = self.error_control.reference_speed * length;
        let pin_speed = self.error_control.reference_speed * self.crank.length;
        let free_crank_inertia = if self.active.free_crank {
            self.crank.mass * self.crank.centre * self.crank.centre
        } else {
            0.0
        };
        let mass = (self.crank.inertia + free_crank_inertia) / self.crank.length.powi(2)
            + self.rod_data.mass
            + self.slider.mass;
        let mut scales = vec![0.0; l.n_states()];
        scales[CRANK_ANGLE] = length / self.crank.length;
        scales[l.crank_speed()] = speed / self.crank.length;
        for (j, d) in self.rod.displacement_scales().into_iter().enumerate() {
            scales[l.rod_coordinate(j)] = length / d;
            scales[l.rod_rate(j)] = speed / d;
        }
        scales[l.slider()] = length;
        scales[l.slider_velocity()] = speed;
        if let Some(g) = l.crank_centre() {
            let rate = l.rate_of(g);
            scales[g..g + 2].fill(length);
            scales[rate..rate + 2].fill(speed);
        }
        scales[l.drive_angle()] = scales[CRANK_ANGLE];
        // (the implicit methods leave the film temperatures, as every state after the drive angle,
        // to the steps the motion takes: their time constants are seconds)
        scales[l.temperatures()].fill(1.0);
        for s in &mut scales[l.integrals()] {
            *s = 0.5 * mass * pin_speed * pin_speed * length / self.crank.length;
        }
        let relative = (0..scales.len())
            .map(|i| if l.integrals().contains(&i) { 1.0 } else { 0.0 })
            .collect();
        let held = self
            .held_joints()
            .map(|_| speed / self.error_control.impact_error_weight)
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
            self.error_control.impact_error_weight > 0.0
                && matches!(self.joint(role), Joint::Dry(_))
        })
    }

    /// The local errors of the held quantities for the error estimate `err` of a step ending at
    /// `y` ([`crate::integrator::MechanicalSystem::held_errors`]): each dry journal's normal
    /// velocity in its bearing, δ̇ = n · ė, with n the direction of e at the step's end and the
    /// error of ė from those of the velocities it is made of: at the crank pin ė = ṙ_P − ṙ_A with
    /// ṙ_P = ṙ_O + d θ̇ (−sin θ, cos θ), whose error is δṙ_O + d (−sin θ, cos θ) δθ̇
    /// − d θ̇ (cos θ, sin θ) δθ; at the main bearing ė = ṙ_G + a θ̇ (sin θ, −cos θ), whose error is
    /// δṙ_G + a (sin θ, −cos θ) δθ̇ + a θ̇ (cos θ, sin θ) δθ.
    pub(super) fn journal_held_errors(&self, y: &[f64], err: &[f64], out: &mut [f64]) {
        let l = self.layout;
        for (role, out) in self.held_joints().zip(out) {
            *out = match role {
                JointRole::RodSlider => {
                    let (b, rate) = (l.pin_b(), l.rate_of(l.pin_b()));
                    normal_rate_error(
                        (y[b] - y[l.slider()], y[b + 1] - self.slider.offset),
                        (err[rate] - err[l.slider_velocity()], err[rate + 1]),
                    )
                }
                JointRole::CrankPin | JointRole::MainBearing => {
                    let e = self.joint_kinematics(role, y).e;
                    let (sin, cos) = crate::math::sin_cos(y[CRANK_ANGLE]);
                    let (d_angle, d_speed) = (err[CRANK_ANGLE], err[l.crank_speed()]);
                    let omega = y[l.crank_speed()];
                    let centre = l
                        .crank_centre()
                        .map_or((0.0, 0.0), |g| (err[l.rate_of(g)], err[l.rate_of(g) + 1]));
                    let (x, y) = if role == JointRole::CrankPin {
                        let (d, rate) = (self.crank.arm, l.rate_of(PIN_A));
                        (
                            -d * sin * d_speed - d * omega * cos * d_angle - err[rate],
                            d * cos * d_speed - d * omega * sin * d_angle - err[rate + 1],
                        )
                    } else {
                        let a = self.crank.centre;
                        (
                            a * sin * d_speed + a * omega * cos * d_angle,
                            -a * cos * d_speed + a * omega * sin * d_angle,
                        )
                    };
                    normal_rate_error((e.x, e.y), (x + centre.0, y + centre.1))
                }
            };
        }
    }
}
