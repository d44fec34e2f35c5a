//! Dry contact of a pin in a hole: Hertz force with hysteresis damping (Lankarani–Nikravesh by
//! default, or a law valid for any restitution) and Coulomb friction with Ambrósio's velocity
//! correction.
//!
//! ```text
//! F_N = K δ^1.5 [1 + χ(c_e) · δ̇/δ̇⁽⁻⁾]                                (δ > 0, clamped ≥ 0)
//! χ   = 3(1 − c_e²)/4       Lankarani–Nikravesh (1990), for c_e near 1
//!     = 8(1 − c_e)/(5 c_e)  Flores et al. (2011)
//!     = 3(1 − c_e)/(2 c_e)  Hu & Guo (2015)
//! K   = 4 / (3(σ_i + σ_j)) · (R_i R_j / (R_i − R_j))^½,   σ_k = (1 − ν_k²)/E_k
//! F_T = −μ c_d(|v_T|) F_N sgn(v_T),  c_d = 0 (|v_T| ≤ v₀), (|v_T| − v₀)/(v₁ − v₀), 1 (|v_T| ≥ v₁)
//! v_T = ė · t + R_j ω_j − R_b ω_b                       (R_b = R_j + c: slip at the contact point)
//! force on the journal f = −F_N n + F_T t,  moment about its centre R_j F_T
//! on the bearing −f,  moment about its centre −R_b F_T
//! ```
//!
//! # References
//! - Lankarani & Nikravesh (1990), J. Mech. Des. 112, 369–376 (hysteresis damping).
//! - J. Ambrósio (2003), Impact of rigid and flexible multibody systems, in Virtual Nonlinear
//!   Multibody Systems, Springer (friction correction c_d).
//! - Flores et al. (2008), book, ch. 4–5; docs/model.md §3.
//! - P. Flores, M. Machado, M. T. Silva, J. M. Martins (2011), On the continuous contact force
//!   models for soft materials in multibody dynamics, Multibody Syst. Dyn. 25, 357–375.
//! - S. Hu, X. Guo (2015), A dissipative contact force model for impact analysis in multibody
//!   dynamics, Multibody Syst. Dyn. 35, 131–151.
//!
//! Low impact speeds: δ̇⁽⁻⁾ is the normal speed at the onset of the contact event, floored at
//! [`MIN_IMPACT_VELOCITY`]. Below it the event is a continuous (resting or sliding) contact and
//! the damping term uses the floor, so the ratio δ̇/δ̇⁽⁻⁾ stays bounded; the normal force is never
//! tensile (clamped at 0 during separation, where δ̇ < 0 and low restitution make the bracket
//! negative).

use nalgebra::Vector2;

use super::kinematics::{JointForce, JointKinematics, MIN_IMPACT_VELOCITY};

/// Hertz-type stiffness K \[N/m^1.5\] of a journal of radius `r_journal` in a bearing of radius
/// `r_bearing`, both of Young's modulus `e` and Poisson ratio `nu`.
pub fn hertz_stiffness(r_bearing: f64, r_journal: f64, e: f64, nu: f64) -> f64 {
    let sigma = (1.0 - nu * nu) / e;
    4.0 / (3.0 * 2.0 * sigma) * (r_bearing * r_journal / (r_bearing - r_journal)).sqrt()
}

/// Hysteresis-damping law of the dry contact force F_N = K δ^1.5 (1 + χ δ̇/δ̇⁻)
/// ([`DryContact`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ContactLaw {
    /// Lankarani & Nikravesh (1990), χ = 3(1 − c_e²)/4: derived for restitution near 1 (the seed
    /// paper's law).
    LankaraniNikravesh,
    /// Flores, Machado, Silva & Martins (2011), χ = 8(1 − c_e)/(5 c_e): any restitution.
    Flores,
    /// Hu & Guo (2015), χ = 3(1 − c_e)/(2 c_e): any restitution.
    HuGuo,
}

/// Constants of the dry contact law.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DryContact {
    /// Hertz stiffness K \[N/m^1.5\].
    pub stiffness: f64,
    /// Radial clearance c \[m\].
    pub clearance: f64,
    /// Journal radius R_j \[m\].
    pub journal_radius: f64,
    /// Coefficient of restitution c_e.
    pub restitution: f64,
    /// Hysteresis-damping law.
    pub law: ContactLaw,
    /// Friction coefficient μ.
    pub friction: f64,
    /// Friction dead band v₀ \[m/s\].
    pub friction_v0: f64,
    /// Full-friction speed v₁ \[m/s\].
    pub friction_v1: f64,
}

impl DryContact {
    /// Penetration δ = |e| − c (negative: gap).
    pub fn penetration(&self, k: &JointKinematics) -> f64 {
        k.e.norm() - self.clearance
    }

    /// Hysteresis factor χ of the contact law.
    pub fn hysteresis_factor(&self) -> f64 {
        let e = self.restitution;
        match self.law {
            ContactLaw::LankaraniNikravesh => 0.75 * (1.0 - e * e),
            ContactLaw::Flores => 1.6 * (1.0 - e) / e,
            ContactLaw::HuGuo => 1.5 * (1.0 - e) / e,
        }
    }

    /// Normal force for penetration `delta` > 0, rate `delta_dot` and impact velocity
    /// `impact_velocity` (floored at [`MIN_IMPACT_VELOCITY`]); 0 without penetration, never
    /// negative.
    pub fn normal_force(&self, delta: f64, delta_dot: f64, impact_velocity: f64) -> f64 {
        if delta <= 0.0 {
            return 0.0;
        }
        let chi = self.hysteresis_factor();
        let damping = 1.0 + chi * delta_dot / impact_velocity.max(MIN_IMPACT_VELOCITY);
        (self.stiffness * delta * delta.sqrt() * damping).max(0.0)
    }

    /// Dynamic correction c_d(|v_T|) of the friction coefficient.
    pub fn friction_factor(&self, v_t: f64) -> f64 {
        let v = v_t.abs();
        if v <= self.friction_v0 {
            0.0
        } else if v >= self.friction_v1 {
            1.0
        } else {
            (v - self.friction_v0) / (self.friction_v1 - self.friction_v0)
        }
    }

    /// Contact force and friction moment on the journal.
    pub fn force(&self, k: &JointKinematics, impact_velocity: f64) -> JointForce {
        let delta = self.penetration(k);
        if delta <= 0.0 {
            return JointForce::default();
        }
        let n = k.normal();
        let t = Vector2::new(-n.y, n.x);
        let f_n = self.normal_force(delta, k.e_dot.dot(&n), impact_velocity);
        let bearing_radius = self.journal_radius + self.clearance;
        let v_t = k.e_dot.dot(&t) + self.journal_radius * k.omega_journal
            - bearing_radius * k.omega_bearing;
        let f_t = -self.friction * self.friction_factor(v_t) * f_n * v_t.signum();
        JointForce {
            force: -f_n * n + f_t * t,
            moment: self.journal_radius * f_t,
            bearing_moment: -bearing_radius * f_t,
            potential: self.stiffness * delta * delta * delta.sqrt() / 2.5,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Restitution reached by an isolated central impact of a mass m at speed v₀ on the bearing
    /// wall, m δ̈ = −F_N(δ, δ̇, v₀), integrated with classical Runge–Kutta at 1/20 000 of the
    /// contact duration: the exit speed over v₀ once δ is back to 0.
    fn effective_restitution(contact: &DryContact, mass: f64, v0: f64) -> f64 {
        let k = contact.stiffness;
        // Hertz contact duration ≈ 2.94 (m²/(K² v₀))^(1/5) (elastic impact).
        let duration = 2.94 * crate::math::powf(mass * mass / (k * k * v0), 0.2);
        let h = duration / 20_000.0;
        let accel = |d: f64, v: f64| -contact.normal_force(d, v, v0) / mass;
        let (mut d, mut v) = (0.0f64, v0);
        for _ in 0..200_000 {
            let (k1d, k1v) = (v, accel(d, v));
            let (k2d, k2v) = (
                v + 0.5 * h * k1v,
                accel(d + 0.5 * h * k1d, v + 0.5 * h * k1v),
            );
            let (k3d, k3v) = (
                v + 0.5 * h * k2v,
                accel(d + 0.5 * h * k2d, v + 0.5 * h * k2v),
            );
            let (k4d, k4v) = (v + h * k3v, accel(d + h * k3d, v + h * k3v));
            d += h / 6.0 * (k1d + 2.0 * k2d + 2.0 * k3d + k4d);
            v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
            if d <= 0.0 && v < 0.0 {
                return -v / v0;
            }
        }
        panic!("the impact did not end");
    }

    /// The kinetic energy lost in an isolated impact, 1 − e_eff², is the
    /// 1 − c_e² the Flores and Hu–Guo laws are built for, within 10 %, for c_e = 0.3, 0.6, 0.9.
    /// Lankarani–Nikravesh, derived for c_e near 1, dissipates too little: measured −42 %, −33 %
    /// and −13 % of the predicted loss (e_eff = 0.684, 0.756, 0.913); asserted to stay short by
    /// more than 10 %. The force is never tensile on the way out.
    #[test]
    fn isolated_impact_loses_the_energy_each_law_predicts() {
        for law in [
            ContactLaw::LankaraniNikravesh,
            ContactLaw::Flores,
            ContactLaw::HuGuo,
        ] {
            for restitution in [0.3, 0.6, 0.9] {
                let c = DryContact {
                    law,
                    restitution,
                    ..contact()
                };
                let e = effective_restitution(&c, 0.21, 1.0);
                let (lost, predicted) = (1.0 - e * e, 1.0 - restitution * restitution);
                let error = (lost - predicted) / predicted;
                println!(
                    "{law:?}, c_e = {restitution}: e_eff = {e:.4}, energy lost {lost:.4} vs {predicted:.4} ({:+.1} %)",
                    100.0 * error
                );
                if law == ContactLaw::LankaraniNikravesh {
                    assert!(error < -0.1, "LN unexpectedly right at c_e = {restitution}");
                } else {
                    assert!(
                        error.abs() <= 0.1,
                        "{law:?} at c_e = {restitution}: {error}"
                    );
                }
                for v in [-1.0, -0.1, -1e-3] {
                    assert!(c.normal_force(1e-5, v, 1e-4) >= 0.0);
                }
            }
        }
    }

    fn contact() -> DryContact {
        DryContact {
            stiffness: hertz_stiffness(0.010, 0.0095, 207e9, 0.3),
            clearance: 0.5e-3,
            journal_radius: 0.0095,
            restitution: 0.9,
            law: ContactLaw::LankaraniNikravesh,
            friction: 0.01,
            friction_v0: 1e-4,
            friction_v1: 1e-3,
        }
    }

    /// docs/model.md §3: steel–steel, R_i = 10, R_j = 9.5 mm gives K = 6.61e10 N/m^1.5.
    #[test]
    fn hertz_stiffness_of_the_benchmark() {
        let k = contact().stiffness;
        assert!((k - 6.61e10).abs() < 0.005e10, "K = {k:e}");
    }

    /// No force without penetration; continuous (zero) at touch-down; grows as δ^1.5.
    #[test]
    fn force_is_zero_before_contact_and_continuous_at_touch_down() {
        let c = contact();
        let at = |gap: f64, rate: f64| JointKinematics {
            e: Vector2::new(0.0, c.clearance + gap),
            e_dot: Vector2::new(0.0, rate),
            omega_journal: 0.0,
            omega_bearing: 0.0,
        };
        assert_eq!(c.force(&at(-1e-6, 1.0), 1.0).force, Vector2::zeros());
        let tiny = c.force(&at(1e-15, 1.0), 1.0).force.norm();
        assert!(tiny < 1e-10, "force just after touch-down {tiny}");
        let f1 = c.normal_force(1e-6, 0.0, 1.0);
        let f2 = c.normal_force(4e-6, 0.0, 1.0);
        assert!((f2 / f1 - 8.0).abs() < 1e-12);
        // The force pushes the journal back towards the centre.
        assert!(c.force(&at(1e-6, 0.0), 1.0).force.y < 0.0);
    }

    /// Lankarani–Nikravesh: approaching (δ̇ > 0) adds damping force, separating removes it, and with
    /// c_e = 1 the law is purely elastic.
    #[test]
    fn hysteresis_damping() {
        let c = contact();
        let elastic = c.normal_force(1e-6, 0.0, 0.5);
        assert!(c.normal_force(1e-6, 0.5, 0.5) > elastic);
        assert!(c.normal_force(1e-6, -0.5, 0.5) < elastic);
        let conservative = DryContact {
            restitution: 1.0,
            ..c
        };
        assert_eq!(conservative.normal_force(1e-6, 0.5, 0.5), elastic);
    }

    /// Friction opposes the tangential slip, is zero in the dead band, full above v₁, and its
    /// moment is R_j F_T.
    #[test]
    fn friction_opposes_slip() {
        let c = contact();
        assert_eq!(c.friction_factor(5e-5), 0.0);
        assert_eq!(c.friction_factor(2e-3), 1.0);
        assert!((c.friction_factor(5.5e-4) - 0.5).abs() < 1e-12);
        let k = JointKinematics {
            e: Vector2::new(c.clearance + 1e-6, 0.0),
            e_dot: Vector2::new(0.0, 0.3),
            omega_journal: 0.0,
            omega_bearing: 0.0,
        };
        let f = c.force(&k, 1.0);
        let f_n = c.normal_force(1e-6, 0.0, 1.0);
        assert!((f.force.y + c.friction * f_n).abs() < 1e-9 * f_n);
        assert!((f.moment - c.journal_radius * f.force.y).abs() < 1e-15);
    }
}
