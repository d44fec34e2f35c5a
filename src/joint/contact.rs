//! Dry contact of a pin in a hole: an elastic law — Hertz's point contact, or Johnson's line
//! contact of a pin with its length — with hysteresis damping (Lankarani–Nikravesh by default, or
//! a law valid for any restitution) and Coulomb friction with Ambrósio's velocity correction.
//!
//! ```text
//! F_N = F_e(δ) [1 + χ(c_e) · δ̇/δ̇⁽⁻⁾]                                 (δ > 0, clamped ≥ 0)
//! F_e = K δ^1.5                                                   point (Hertz)
//! δ   = (F_e/(π L E*)) (ln(4π L ΔR E*/F_e) − 1)                   cylinder (Johnson), ΔR = c
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
//! The hysteresis factors hold for any elastic law F_e: integrating m δ̇ dδ̇ = −F_e (1 + χ δ̇/δ̇⁻) dδ
//! over compression and restitution gives ∫ x/(1 + χx) dx = 0 over x ∈ (−c_e, 1), whatever F_e
//! (the elastic work cancels), so the restitution each law was fitted for is that of the point
//! and the line contact alike (tested below).
//!
//! The line contact ([`LineContact`]): two cylinders of radii R_j and R_b = R_j + c in internal
//! contact along the bearing length L, E* the plane-strain modulus 1/E* = (1 − ν²)/E + (1 − ν²)/E.
//! The approach of the axes under the load F is Johnson's for two cylinders pressed along their
//! length (Johnson 1985, pp. 99–104), with the relative radius R_j R_b/c of the conformal pair, as the
//! clearance-joint literature uses it (Pereira, Ramalho & Ambrósio 2011). It holds while the
//! contact half-width b = √(4 F R_j R_b/(π L E* c)) stays small against the radius; F_e(δ) is its
//! inverse, by Newton's method (4 to 6 iterations), up to δ_lim = 8 e⁻³ c ≈ 0.40 c, where its
//! stiffness has fallen to π L E*, and the tangent line beyond (the law's own δ(F) turns back at
//! 0.54 c). Against the point law it sinks a long pin much less: 2.6 µm against 7.7 µm for 4.4 kN
//! on an 18 mm long, 6 mm steel pin in a 20 µm clearance.
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
//! - K. L. Johnson (1985), Contact Mechanics, Cambridge University Press, pp. 99–104 (the approach of
//!   two cylinders in line contact).
//! - C. M. Pereira, A. L. Ramalho, J. A. Ambrósio (2011), A critical overview of internal and
//!   external cylinder contact force models, Nonlinear Dyn. 63, 681–697.
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

/// The geometry of the dry contact, which sets its elastic law F_e(δ) ([`Elastic`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ContactGeometry {
    /// Hertz's point contact, F_e = K δ^1.5 (the seed paper's law).
    Point,
    /// Johnson's line contact of the pin along the bearing length ([`LineContact`]).
    Cylinder,
}

/// The elastic part F_e(δ) of the dry contact force and its stored energy.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Elastic {
    /// Hertz's point contact F_e = K δ^1.5, with K \[N/m^1.5\] ([`hertz_stiffness`]).
    Point(f64),
    /// Johnson's line contact.
    Cylinder(LineContact),
}

impl Elastic {
    /// The elastic force F_e at the penetration δ > 0 \[N\].
    pub fn force(&self, delta: f64) -> f64 {
        match self {
            Self::Point(k) => k * delta * delta.sqrt(),
            Self::Cylinder(line) => line.force(delta),
        }
    }

    /// The energy stored at the penetration δ > 0, ∫₀^δ F_e \[J\].
    pub fn energy(&self, delta: f64) -> f64 {
        match self {
            Self::Point(k) => k * delta * delta * delta.sqrt() / 2.5,
            Self::Cylinder(line) => line.energy(delta),
        }
    }

    /// The penetration at which the elastic force is `force` ≥ 0 (the inverse of
    /// [`Elastic::force`]) \[m\].
    pub fn penetration(&self, force: f64) -> f64 {
        match self {
            Self::Point(k) => crate::math::powf(force / k, 2.0 / 3.0),
            Self::Cylinder(line) => line.penetration(force),
        }
    }
}

/// Johnson's line contact of a pin in a hole (module documentation): with x = F/(π L E*) and
/// a = 4c, the approach is δ = x (ln(a/x) − 1), so u = ln(a/x) solves u − ln(u − 1) = ln(a/δ)
/// and F = π L E* a e⁻ᵘ; the energy is ∫F dδ = π L E* x² (u/2 − 3/4). Valid for u ≥ 3 (δ up to
/// δ_lim = 2a e⁻³), continued by the tangent line F_lim + π L E* (δ − δ_lim) beyond.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineContact {
    /// π L E* \[N/m\].
    modulus: f64,
    /// a = 4c \[m\].
    reach: f64,
}

/// ln(a/x) at the end of the line contact's range: there dδ/dF = (u − 2)/(π L E*) has fallen to
/// 1/(π L E*).
const LINE_CONTACT_LIMIT: f64 = 3.0;

impl LineContact {
    /// The line contact of a bearing of length `length` and radial clearance `clearance`, journal
    /// and bearing of Young's modulus `e` and Poisson ratio `nu`.
    pub fn new(length: f64, clearance: f64, e: f64, nu: f64) -> Self {
        let plane_strain = e / (2.0 * (1.0 - nu * nu));
        Self {
            modulus: std::f64::consts::PI * length * plane_strain,
            reach: 4.0 * clearance,
        }
    }

    /// The end δ_lim = a e⁻³ (3 − 1) of the law's range, and the force there \[m, N\].
    pub fn limit(&self) -> (f64, f64) {
        let x = self.reach * crate::math::exp(-LINE_CONTACT_LIMIT);
        (x * (LINE_CONTACT_LIMIT - 1.0), self.modulus * x)
    }

    /// The approach δ under the force F ≥ 0 (Johnson's formula, continued linearly beyond the
    /// range) \[m\].
    pub fn penetration(&self, force: f64) -> f64 {
        let (delta_lim, force_lim) = self.limit();
        if force >= force_lim {
            return delta_lim + (force - force_lim) / self.modulus;
        }
        if force <= 0.0 {
            return 0.0;
        }
        let x = force / self.modulus;
        x * (crate::math::ln(self.reach / x) - 1.0)
    }

    /// u = ln(a/x) at the penetration 0 < δ < δ_lim, by Newton's method on the convex
    /// g(u) = u − ln(u − 1) − ln(a/δ), g' = (u − 2)/(u − 1) ≥ 1/2, from ln(a/δ) + ln(ln(a/δ) − 1).
    fn log_ratio(&self, delta: f64) -> f64 {
        let target = crate::math::ln(self.reach / delta);
        let mut u = (target + crate::math::ln(target - 1.0)).max(LINE_CONTACT_LIMIT);
        for _ in 0..LINE_CONTACT_ITERATIONS {
            let step = (u - crate::math::ln(u - 1.0) - target) * (u - 1.0) / (u - 2.0);
            u -= step;
            if step.abs() <= 1e-14 * u {
                break;
            }
        }
        u
    }

    /// The elastic force at the penetration δ > 0 \[N\].
    pub fn force(&self, delta: f64) -> f64 {
        let (delta_lim, force_lim) = self.limit();
        if delta >= delta_lim {
            return force_lim + self.modulus * (delta - delta_lim);
        }
        self.modulus * self.reach * crate::math::exp(-self.log_ratio(delta))
    }

    /// The energy stored at the penetration δ > 0 \[J\].
    pub fn energy(&self, delta: f64) -> f64 {
        let (delta_lim, force_lim) = self.limit();
        let inside = |u: f64| {
            let x = self.reach * crate::math::exp(-u);
            self.modulus * x * x * (0.5 * u - 0.75)
        };
        if delta >= delta_lim {
            let beyond = delta - delta_lim;
            return inside(LINE_CONTACT_LIMIT)
                + force_lim * beyond
                + 0.5 * self.modulus * beyond * beyond;
        }
        inside(self.log_ratio(delta))
    }
}

/// Newton iterations of the line contact's inverse (from 4 to 6 reach round-off).
const LINE_CONTACT_ITERATIONS: usize = 12;

/// Hysteresis-damping law of the dry contact force F_N = F_e(δ) (1 + χ δ̇/δ̇⁻)
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

/// The forces of a contact in one state.
#[derive(Clone, Copy, Debug)]
struct Contact {
    /// Penetration δ > 0 \[m\].
    delta: f64,
    /// Normal n = e/|e| and tangent t = ẑ × n.
    n: Vector2<f64>,
    t: Vector2<f64>,
    /// Normal force F_N ≥ 0 and friction force F_T along t \[N\].
    f_n: f64,
    f_t: f64,
    /// Slip speed v_T at the contact point \[m/s\].
    v_t: f64,
}

/// Constants of the dry contact law.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DryContact {
    /// The elastic law F_e(δ).
    pub elastic: Elastic,
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
        (self.elastic.force(delta) * damping).max(0.0)
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

    /// The slip speed v_T = ė · t + R_j ω_j − R_b ω_b at the contact point on the line of `t`
    /// \[m/s\].
    pub fn slip_speed(&self, k: &JointKinematics, t: &Vector2<f64>) -> f64 {
        let bearing_radius = self.journal_radius + self.clearance;
        k.e_dot.dot(t) + self.journal_radius * k.omega_journal - bearing_radius * k.omega_bearing
    }

    /// The contact's normal and friction forces, `None` without penetration.
    fn contact(&self, k: &JointKinematics, impact_velocity: f64) -> Option<Contact> {
        let delta = self.penetration(k);
        if delta <= 0.0 {
            return None;
        }
        let n = k.normal();
        let t = Vector2::new(-n.y, n.x);
        let f_n = self.normal_force(delta, k.e_dot.dot(&n), impact_velocity);
        let v_t = self.slip_speed(k, &t);
        let f_t = -self.friction * self.friction_factor(v_t) * f_n * v_t.signum();
        Some(Contact {
            delta,
            n,
            t,
            f_n,
            f_t,
            v_t,
        })
    }

    /// Contact force and friction moment on the journal.
    pub fn force(&self, k: &JointKinematics, impact_velocity: f64) -> JointForce {
        let Some(Contact {
            delta,
            n,
            t,
            f_n,
            f_t,
            ..
        }) = self.contact(k, impact_velocity)
        else {
            return JointForce::default();
        };
        let bearing_radius = self.journal_radius + self.clearance;
        JointForce {
            force: -f_n * n + f_t * t,
            moment: self.journal_radius * f_t,
            bearing_moment: -bearing_radius * f_t,
            potential: self.elastic.energy(delta),
        }
    }

    /// The rate at which friction dissipates energy, −F_T v_T ≥ 0 \[W\] (0 out of contact).
    pub fn friction_power(&self, k: &JointKinematics, impact_velocity: f64) -> f64 {
        self.contact(k, impact_velocity)
            .map_or(0.0, |c| -c.f_t * c.v_t)
    }

    /// The rate at which the hysteresis damping of the normal force dissipates energy,
    /// (F_N − F_e(δ)) δ̇ ≥ 0 \[W\] (0 out of contact), F_e the elastic force of
    /// [`DryContact::normal_force`]: F_e χ δ̇²/v₀, or −F_e δ̇ where the force is cut at zero as
    /// the journal leaves the wall. The normal force does the work −F_N δ̇ on the journal, of which
    /// −F_e δ̇ is stored in the contact (its potential V(δ)); with [`DryContact::friction_power`]
    /// this is everything the contact loses.
    pub fn hysteresis_power(&self, k: &JointKinematics, impact_velocity: f64) -> f64 {
        self.contact(k, impact_velocity).map_or(0.0, |c| {
            (c.f_n - self.elastic.force(c.delta)) * k.e_dot.dot(&c.n)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Restitution reached by an isolated central impact of a mass m at speed v₀ on the bearing
    /// wall, m δ̈ = −F_N(δ, δ̇, v₀), integrated with classical Runge–Kutta at 1/20 000 of the
    /// contact duration: the exit speed over v₀ once δ is back to 0.
    fn effective_restitution(contact: &DryContact, mass: f64, v0: f64) -> f64 {
        // The elastic impact's deepest penetration, where the law has stored ½ m v₀² (by
        // bisection), and its duration, about 3 δ_max/v₀ (2.94 for Hertz, π for a linear spring).
        let kinetic = 0.5 * mass * v0 * v0;
        let (mut low, mut high) = (0.0, contact.clearance);
        for _ in 0..100 {
            let mid = 0.5 * (low + high);
            if contact.elastic.energy(mid) < kinetic {
                low = mid;
            } else {
                high = mid;
            }
        }
        let duration = 3.2 * high / v0;
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
    /// more than 10 %. The force is never tensile on the way out. The line contact of a 40 mm
    /// pin, four times softer than the point contact at this impact, reaches the same restitution
    /// (within 1e-3: the hysteresis factors do not depend on the elastic law).
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
                let line = DryContact {
                    elastic: Elastic::Cylinder(LineContact::new(0.04, 0.5e-3, 207e9, 0.3)),
                    ..c
                };
                let e_line = effective_restitution(&line, 0.21, 1.0);
                assert!(
                    (e_line - e).abs() < 1e-3,
                    "{law:?}, c_e = {restitution}: line {e_line} vs point {e}"
                );
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
            elastic: Elastic::Point(hertz_stiffness(0.010, 0.0095, 207e9, 0.3)),
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
        let k = hertz_stiffness(0.010, 0.0095, 207e9, 0.3);
        assert!((k - 6.61e10).abs() < 0.005e10, "K = {k:e}");
    }

    /// Johnson's line contact against its closed form δ(F) = (F/(π L E*)) (ln(4π L c E*/F) − 1),
    /// E* = E/(2(1 − ν²)): a 6 mm steel pin 18 mm long in a 20 µm clearance sinks 2.57 µm under
    /// 4.4 kN (the point contact: 7.75 µm). The law inverts its closed form to 1e-12 from 1 N to
    /// beyond its range, its energy's derivative is its force (central differences), and force
    /// and stiffness are continuous where the tangent line takes over.
    #[test]
    fn line_contact_follows_johnson() {
        let (length, clearance, e, nu) = (0.018, 20e-6, 207e9, 0.3);
        let line = LineContact::new(length, clearance, e, nu);
        let modulus = e / (2.0 * (1.0 - nu * nu));
        let johnson = |f: f64| {
            let x = f / (std::f64::consts::PI * length * modulus);
            x * (crate::math::ln(4.0 * clearance / x) - 1.0)
        };
        let delta = johnson(4.4e3);
        assert!((delta - 2.57e-6).abs() < 0.01e-6, "{delta:e}");
        let point = hertz_stiffness(6.02e-3, 6e-3, e, nu);
        let hertz = Elastic::Point(point).penetration(4.4e3);
        assert!((hertz - 7.75e-6).abs() < 0.01e-6, "{hertz:e}");
        let (delta_lim, force_lim) = line.limit();
        assert!((delta_lim / clearance - 8.0 * crate::math::exp(-3.0)).abs() < 1e-12);
        for f in [1.0, 100.0, 4.4e3, 0.5 * force_lim, 0.999 * force_lim] {
            let d = johnson(f);
            assert!((line.penetration(f) - d).abs() <= 1e-12 * d, "{f} N");
            assert!(
                (line.force(d) - f).abs() <= 1e-12 * f,
                "{f} N: {}",
                line.force(d)
            );
        }
        for d in [1e-7, 1e-6, 5e-6, 0.99 * delta_lim, 1.2 * delta_lim] {
            let h = 1e-6 * d;
            let slope = (line.energy(d + h) - line.energy(d - h)) / (2.0 * h);
            assert!(
                (slope - line.force(d)).abs() < 1e-6 * line.force(d),
                "{d:e}"
            );
        }
        let below = |d: f64| line.force(delta_lim * (1.0 - d));
        let above = |d: f64| line.force(delta_lim * (1.0 + d));
        assert!((below(1e-12) - above(1e-12)).abs() < 1e-6 * force_lim);
        let stiffness = |f: &dyn Fn(f64) -> f64| (f(1e-6) - f(2e-6)) / (1e-6 * delta_lim);
        let (inside, beyond) = (stiffness(&below), -stiffness(&above));
        assert!(
            (inside - beyond).abs() < 1e-3 * beyond,
            "{inside} vs {beyond}"
        );
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
            viscosity: None,
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
            viscosity: None,
        };
        let f = c.force(&k, 1.0);
        let f_n = c.normal_force(1e-6, 0.0, 1.0);
        assert!((f.force.y + c.friction * f_n).abs() < 1e-9 * f_n);
        assert!((f.moment - c.journal_radius * f.force.y).abs() < 1e-15);
    }
}
