//! What every joint law works with: the journal's kinematics in the bearing, the force it returns,
//! and the contact event's memory (docs/model.md §3, Sun et al. 2015 eqs. 4–5).

use nalgebra::Vector2;

/// Smallest impact velocity used in the Lankarani–Nikravesh damping term \[m/s\] (docs/model.md §7).
pub const MIN_IMPACT_VELOCITY: f64 = 1e-4;

/// Relative kinematics of the journal in the bearing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointKinematics {
    /// Eccentricity e = journal centre − bearing centre \[m\].
    pub e: Vector2<f64>,
    /// Its rate ė \[m/s\].
    pub e_dot: Vector2<f64>,
    /// Absolute angular velocity of the journal (CCW +) \[rad/s\]; the bearing does not rotate.
    pub omega_journal: f64,
}

impl JointKinematics {
    /// Unit normal n = e/|e| (x axis when e = 0).
    pub fn normal(&self) -> Vector2<f64> {
        let norm = self.e.norm();
        if norm > 0.0 {
            self.e / norm
        } else {
            Vector2::x()
        }
    }

    /// Normal relative velocity δ̇ = ė · n.
    pub fn normal_velocity(&self) -> f64 {
        self.e_dot.dot(&self.normal())
    }
}

/// The error of a journal's normal velocity δ̇ = n · ė for an error `rate_error` of its
/// eccentricity rate, n the direction of the eccentricity `e` (the magnitude of the error when the
/// journal is centred).
pub fn normal_rate_error((px, py): (f64, f64), (ex, ey): (f64, f64)) -> f64 {
    let length = (px * px + py * py).sqrt();
    if length > 0.0 {
        (px * ex + py * ey).abs() / length
    } else {
        (ex * ex + ey * ey).sqrt()
    }
}

/// Force of the joint on the journal.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct JointForce {
    /// Force on the journal \[N\] (the bearing receives −force).
    pub force: Vector2<f64>,
    /// Moment on the journal about its centre \[N m\] (friction only).
    pub moment: f64,
    /// Elastic energy stored in the contact, K δ^2.5 / 2.5 \[J\].
    pub potential: f64,
}

/// Discrete contact state, updated at accepted steps only.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactState {
    /// Whether the journal touched the bearing at the end of the last accepted step.
    pub in_contact: bool,
    /// Normal velocity δ̇⁽⁻⁾ at the onset of the current contact event \[m/s\].
    pub impact_velocity: f64,
}
