//! The rod–slider joint: ideal, dry clearance, or lubricated.
//!
//! Kinematics (docs/model.md §3, Sun et al. 2015 eqs. 4–5): the eccentricity e = r_journal − r_bearing,
//! n = e/|e|, t = ẑ × n, penetration δ = |e| − c. The joint returns the force on the journal
//! (the bearing gets its opposite) and the moment on the journal about its centre.
//!
//! # References
//! - H. M. Lankarani, P. E. Nikravesh (1990), J. Mech. Des. 112, 369–376.
//! - P. Flores, J. Ambrósio, J. C. P. Claro, H. M. Lankarani (2008), Kinematics and Dynamics of
//!   Multibody Systems with Imperfect Joints, Springer.

pub mod bearing;
pub mod contact;
pub mod kinematics;

pub use bearing::JournalBearing;
pub use contact::{DryContact, hertz_stiffness};
pub use kinematics::{ContactState, JointForce, JointKinematics, MIN_IMPACT_VELOCITY};

use nalgebra::Vector2;

use crate::params::{JointModel, Parameters};

/// The joint model with its constants.
#[derive(Clone, Debug, PartialEq)]
pub enum Joint {
    /// Ideal revolute joint: a constraint, no force law.
    Ideal,
    /// Dry clearance joint.
    Dry(DryContact),
    /// Lubricated journal bearing with dry contact near metal contact.
    Lubricated(JournalBearing),
}

/// Hertz-type stiffness K \[N/m^1.5\] of the parameters' journal in their bearing
/// ([`hertz_stiffness`]), the FMU's calculated parameter joint.contactStiffness.
pub fn contact_stiffness(p: &Parameters) -> f64 {
    hertz_stiffness(
        p.bearing_radius(),
        p.journal_radius,
        p.joint_youngs_modulus,
        p.joint_poisson_ratio,
    )
}

impl Joint {
    /// The joint described by the parameters (validated beforehand).
    pub fn from_parameters(p: &Parameters) -> Self {
        let dry = DryContact {
            stiffness: contact_stiffness(p),
            clearance: p.clearance,
            journal_radius: p.journal_radius,
            restitution: p.restitution,
            law: p.contact_law,
            friction: p.friction,
            friction_v0: p.friction_v0,
            friction_v1: p.friction_v1,
        };
        match p.joint_model {
            JointModel::Ideal => Self::Ideal,
            JointModel::Dry => Self::Dry(dry),
            JointModel::Lubricated => Self::Lubricated(JournalBearing {
                viscosity: p.viscosity,
                length: p.bearing_length,
                switch_eccentricity: p.switch_eccentricity,
                dry,
            }),
        }
    }

    /// The dry-contact law, if the joint has one.
    pub fn dry_contact(&self) -> Option<&DryContact> {
        match self {
            Self::Ideal => None,
            Self::Dry(dry) => Some(dry),
            Self::Lubricated(bearing) => Some(&bearing.dry),
        }
    }

    /// The eccentricity at which the journal, at rest in the bearing (ė = 0) and turning at
    /// `omega_journal`, receives the force `force` from the joint: its quasi-static equilibrium
    /// against a steady load (the settled start, docs/model.md §10).
    ///
    /// Dry and frictionless in closed form, e = −(c + δ) F/|F| with K δ^1.5 = |F|; with friction
    /// or a film, Newton's method on F(e) = F from that point (a 2 × 2 difference Jacobian, steps
    /// halved until the residual falls). The ideal joint and a zero force give the centre.
    pub fn eccentricity_carrying(&self, force: Vector2<f64>, omega_journal: f64) -> Vector2<f64> {
        let Some(dry) = self.dry_contact() else {
            return Vector2::zeros();
        };
        let magnitude = force.norm();
        if magnitude == 0.0 {
            return Vector2::zeros();
        }
        let depth = crate::math::powf(magnitude / dry.stiffness, 2.0 / 3.0);
        let mut e = -(dry.clearance + depth) / magnitude * force;
        let residual = |e: Vector2<f64>| {
            let kinematics = JointKinematics {
                e,
                e_dot: Vector2::zeros(),
                omega_journal,
            };
            self.force(&kinematics, MIN_IMPACT_VELOCITY).force - force
        };
        let mut r = residual(e);
        for _ in 0..50 {
            if r.norm() <= 1e-10 * magnitude {
                break;
            }
            let h = 1e-7 * (dry.clearance + e.norm());
            let jacobian = nalgebra::Matrix2::from_columns(&[
                (residual(e + Vector2::new(h, 0.0)) - r) / h,
                (residual(e + Vector2::new(0.0, h)) - r) / h,
            ]);
            let Some(step) = jacobian.lu().solve(&(-r)) else {
                break;
            };
            let mut scale = 1.0;
            loop {
                let trial = e + scale * step;
                let r_trial = residual(trial);
                if r_trial.norm() < r.norm() {
                    (e, r) = (trial, r_trial);
                    break;
                }
                scale *= 0.5;
                if scale < 1e-6 {
                    return e;
                }
            }
        }
        e
    }

    /// Force on the journal; `impact_velocity` is δ̇⁽⁻⁾ of the current contact event.
    pub fn force(&self, k: &JointKinematics, impact_velocity: f64) -> JointForce {
        match self {
            Self::Ideal => JointForce::default(),
            Self::Dry(dry) => dry.force(k, impact_velocity),
            Self::Lubricated(bearing) => bearing.force(k, impact_velocity),
        }
    }
}
