//! What every joint law works with: the journal's kinematics in the bearing, the force it returns,
//! and the contact event's memory (docs/model.md §3, Sun et al. 2015 eqs. 4–5).

use nalgebra::Vector2;

use super::role::JointRole;

/// Smallest impact velocity used in the hysteresis-damping term \[m/s\] (docs/model.md §3).
pub const MIN_IMPACT_VELOCITY: f64 = 1e-4;

/// Relative kinematics of the journal in the bearing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointKinematics {
    /// Eccentricity e = journal centre − bearing centre \[m\].
    pub e: Vector2<f64>,
    /// Its rate ė \[m/s\].
    pub e_dot: Vector2<f64>,
    /// Absolute angular velocity of the journal (CCW +) \[rad/s\].
    pub omega_journal: f64,
    /// Absolute angular velocity of the bearing (CCW +) \[rad/s\]: 0 for a bearing on the ground
    /// or on the slider, the rod's end rotation for the rod's eye.
    pub omega_bearing: f64,
    /// The oil's viscosity in this state where the joint's heat balance sets it (at its film
    /// temperature, a state) \[Pa s\]; None for the joint's own isoviscous oil.
    pub viscosity: Option<f64>,
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

    /// Power of the joint's force and moments `f` on the journal and the bearing,
    /// F · ė + M_j ω_j + M_b ω_b: the rate at which the joint stores (contact) or dissipates
    /// energy, with the opposite sign.
    pub fn power(&self, f: &JointForce) -> f64 {
        f.force.dot(&self.e_dot)
            + f.moment * self.omega_journal
            + f.bearing_moment * self.omega_bearing
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
    /// Moment on the journal about its centre \[N m\] (dry friction, film shear).
    pub moment: f64,
    /// Moment on the bearing about its centre \[N m\] (dry friction, film shear): the opposite friction
    /// force acts at the bearing's radius R_b = R_j + c, so it is −(R_b/R_j) times `moment`.
    pub bearing_moment: f64,
    /// Elastic energy stored in the contact, K δ^2.5 / 2.5 \[J\].
    pub potential: f64,
}

/// What the cycle results integrate or hold of a joint in one state (SI units).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct JointRates {
    /// The friction power \[W\] ([`super::BearingState::friction_power`]).
    pub friction_power: f64,
    /// The oil flow \[m³/s\] ([`super::BearingState::oil_flow`]).
    pub oil_flow: f64,
    /// The asperities' normal force \[N\] ([`super::BearingState::asperity_force`]).
    pub asperity_force: f64,
}

/// Discrete contact state, updated at accepted steps only.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactState {
    /// Whether the journal touched the bearing at the end of the last accepted step.
    pub in_contact: bool,
    /// Normal velocity δ̇⁽⁻⁾ at the onset of the current contact event \[m/s\].
    pub impact_velocity: f64,
}

impl ContactState {
    /// Out of contact, with the floor impact velocity.
    pub const APART: Self = Self {
        in_contact: false,
        impact_velocity: MIN_IMPACT_VELOCITY,
    };
}

/// The discrete contact states of a mechanism's joints, one per [`JointRole`] (those of ideal
/// joints stay [`ContactState::APART`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Contacts(pub [ContactState; 3]);

impl Contacts {
    /// Whether `other` holds the same states, bit for bit.
    pub fn same_bits(&self, other: &Contacts) -> bool {
        self.0.iter().zip(&other.0).all(|(a, b)| {
            a.in_contact == b.in_contact
                && a.impact_velocity.to_bits() == b.impact_velocity.to_bits()
        })
    }

    /// Whether any journal touches its bearing.
    pub fn any(&self) -> bool {
        self.0.iter().any(|c| c.in_contact)
    }
}

impl Default for Contacts {
    fn default() -> Self {
        Self([ContactState::APART; 3])
    }
}

impl std::ops::Index<JointRole> for Contacts {
    type Output = ContactState;
    fn index(&self, role: JointRole) -> &ContactState {
        &self.0[role as usize]
    }
}

impl std::ops::IndexMut<JointRole> for Contacts {
    fn index_mut(&mut self, role: JointRole) -> &mut ContactState {
        &mut self.0[role as usize]
    }
}
