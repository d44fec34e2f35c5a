//! Lubricated journal bearing: infinitely short bearing (Ocvirk; Pinkus–Sternlicht), π-film with the
//! film mirrored for negative wedge speed, and dry contact taking over near metal contact.
//!
//! ```text
//! ε = |e|/c,  ε̇ = e·ė/(|e| c),  γ̇ = (e × ė)/|e|²,  w = ω_J + ω_B − 2γ̇   (ω_B = 0: slider)
//! K_h = μ R L³ / (2c²)
//! F_r = −K_h [2ε²|w|/(1−ε²)² + π(1+2ε²) ε̇/(1−ε²)^{5/2}]
//! F_t = sgn(w) K_h [π ε |w| / (2(1−ε²)^{3/2}) + 4 ε ε̇/(1−ε²)²]
//! force on the journal F = F_r n + F_t t   (through the journal centre: no moment)
//! ```
//! Hand-over (MODEL.md §4, continuous rule): for ε ≥ ε_b the film force is evaluated with ε
//! clamped to ε_b (actual ε̇ and w), and the dry contact force of [`DryContact`] is added whenever
//! δ = |e| − c > 0. Both pieces are continuous, so the total force is continuous in e.
//!
//! # References
//! - P. Flores, J. Ambrósio, J. C. P. Claro, H. M. Lankarani, C. S. Koshy (2006), A study on
//!   dynamics of mechanical systems including joints with clearance and lubrication, Mech. Mach.
//!   Theory 41, 247–261.
//! - O. Pinkus, B. Sternlicht (1961), Theory of Hydrodynamic Lubrication, McGraw-Hill.
//! - MODEL.md §4 (sign convention verified against direct integration).

use nalgebra::Vector2;

use super::{DryContact, JointForce, JointKinematics};

/// Constants of the lubricated joint.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JournalBearing {
    /// Dynamic viscosity μ \[Pa s\].
    pub viscosity: f64,
    /// Bearing length L \[m\].
    pub length: f64,
    /// Eccentricity ratio ε_b above which the film model is clamped and dry contact may act.
    pub switch_eccentricity: f64,
    /// Dry contact law (clearance, journal radius, friction, stiffness).
    pub dry: DryContact,
}

impl JournalBearing {
    /// Film coefficient K_h = μ R L³ / (2c²) \[N s\].
    pub fn film_coefficient(&self) -> f64 {
        let c = self.dry.clearance;
        self.viscosity * self.dry.journal_radius * self.length.powi(3) / (2.0 * c * c)
    }

    /// Film force on the journal (π-film, mirrored for w < 0), ε clamped to ε_b.
    pub fn film_force(&self, k: &JointKinematics) -> Vector2<f64> {
        let c = self.dry.clearance;
        let e_norm = k.e.norm();
        if e_norm <= 1e-12 * c {
            // Centred journal: direction undefined, and every term carries ε or a direction.
            return Vector2::zeros();
        }
        let n = k.e / e_norm;
        let t = Vector2::new(-n.y, n.x);
        let eps = (e_norm / c).min(self.switch_eccentricity);
        let eps_dot = k.e.dot(&k.e_dot) / (e_norm * c);
        let gamma_dot = (k.e.x * k.e_dot.y - k.e.y * k.e_dot.x) / (e_norm * e_norm);
        let w = k.omega_journal - 2.0 * gamma_dot;
        let s = 1.0 - eps * eps;
        let pi = std::f64::consts::PI;
        let kh = self.film_coefficient();
        let f_r = -kh
            * (2.0 * eps * eps * w.abs() / (s * s)
                + pi * (1.0 + 2.0 * eps * eps) * eps_dot / s.powf(2.5));
        let f_t = w.signum()
            * kh
            * (pi * eps * w.abs() / (2.0 * s.powf(1.5)) + 4.0 * eps * eps_dot / (s * s));
        f_r * n + f_t * t
    }

    /// Film force plus dry contact when the journal touches the bearing.
    pub fn force(&self, k: &JointKinematics, impact_velocity: f64) -> JointForce {
        let dry = self.dry.force(k, impact_velocity);
        JointForce {
            force: self.film_force(k) + dry.force,
            ..dry
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::joint::hertz_stiffness;

    fn bearing() -> JournalBearing {
        JournalBearing {
            viscosity: 0.4,
            length: 0.04,
            switch_eccentricity: 0.95,
            dry: DryContact {
                stiffness: hertz_stiffness(0.010, 0.0095, 207e9, 0.3),
                clearance: 0.5e-3,
                journal_radius: 0.0095,
                restitution: 0.9,
                friction: 0.0,
                friction_v0: 1e-4,
                friction_v1: 1e-3,
            },
        }
    }

    /// MODEL.md §5(b): K_h = 0.486 N s for the benchmark C bearing.
    #[test]
    fn film_coefficient_of_benchmark_c() {
        assert!((bearing().film_coefficient() - 0.486).abs() < 0.001);
    }

    /// Steady load (ε̇ = 0, γ̇ = 0): the attitude angle satisfies tan φ = π√(1−ε²)/(4ε) and the
    /// radial force pushes the journal back to the centre.
    #[test]
    fn steady_attitude_angle() {
        let b = bearing();
        let eps: f64 = 0.6;
        let k = JointKinematics {
            e: Vector2::new(eps * b.dry.clearance, 0.0),
            e_dot: Vector2::zeros(),
            omega_journal: 100.0,
        };
        let f = b.film_force(&k);
        assert!(f.x < 0.0);
        let tan_phi = f.y.abs() / f.x.abs();
        let expected = std::f64::consts::PI * (1.0 - eps * eps).sqrt() / (4.0 * eps);
        assert!((tan_phi - expected).abs() < 1e-12 * expected);
    }

    /// Squeeze film resists approach to the wall (ε̇ > 0 ⇒ outward motion pushed back).
    #[test]
    fn squeeze_film_resists_approach() {
        let b = bearing();
        let k = JointKinematics {
            e: Vector2::new(0.0, 0.5 * b.dry.clearance),
            e_dot: Vector2::new(0.0, 0.1),
            omega_journal: 0.0,
        };
        assert!(b.film_force(&k).y < 0.0);
    }

    /// The force is continuous across the switch ratio ε_b and across metal contact (δ = 0).
    #[test]
    fn hand_over_is_continuous() {
        let b = bearing();
        let c = b.dry.clearance;
        let at = |r: f64| JointKinematics {
            e: Vector2::new(r * c, 0.0),
            e_dot: Vector2::new(0.02, 0.01),
            omega_journal: 50.0,
        };
        for r in [b.switch_eccentricity, 1.0] {
            let below = b.force(&at(r * (1.0 - 1e-9)), 0.1).force;
            let above = b.force(&at(r * (1.0 + 1e-9)), 0.1).force;
            assert!(
                (below - above).norm() <= 1e-6 * below.norm(),
                "jump at ε = {r}: {below:?} vs {above:?}"
            );
        }
    }
}
