//! Contact events: the discrete contact state, the onset control of the integrator's steps
//! (no contact starts deep inside the wall; the impact velocity is latched at the located onset),
//! and the mechanism as the integrators' first-order system ([`Driven`]: the mechanism with its
//! inputs as functions of time and its contact states).

use super::inputs::{Conditions, InputSignal};
use super::slider_crank::SliderCrank;
use crate::error::ModelError;
use crate::integrator::{MechanicalSystem, OdeSystem};
use crate::joint::{ContactState, Contacts, JointKinematics, JointRole, MIN_IMPACT_VELOCITY};

/// Largest penetration accepted at the first step of a contact event \[m\]: 1e-3 of the Hertz
/// maximum penetration of a 0.1 kg, 1 m/s impact (≈ 20 µm, docs/model.md §6), so that the impact
/// velocity is located accurately and the integrator never starts a contact deep inside.
pub const CONTACT_ONSET_PENETRATION: f64 = 2e-8;

impl SliderCrank {
    /// δ̇⁽⁻⁾ of the joint `role` in the contact states `contacts`: latched in a contact event,
    /// the normal velocity otherwise.
    pub(super) fn impact_velocity(
        &self,
        role: JointRole,
        k: &JointKinematics,
        contacts: &Contacts,
    ) -> f64 {
        let contact = contacts[role];
        if contact.in_contact {
            contact.impact_velocity
        } else {
            k.normal_velocity().max(MIN_IMPACT_VELOCITY)
        }
    }

    /// Penetration δ = |e| − c of the joint `role` in a state (−∞ for an ideal joint).
    pub fn penetration(&self, role: JointRole, y: &[f64]) -> f64 {
        match self.joint(role).dry_contact() {
            Some(dry) => dry.penetration(&self.joint_kinematics(role, y)),
            None => f64::NEG_INFINITY,
        }
    }

    /// Normal velocity δ̇ of the joint `role` in a state.
    fn normal_velocity(&self, role: JointRole, y: &[f64]) -> f64 {
        self.joint_kinematics(role, y).normal_velocity()
    }

    /// The clearance joints, from the ground to the slider.
    fn clearance_joints(&self) -> impl Iterator<Item = JointRole> + '_ {
        JointRole::ALL
            .into_iter()
            .filter(|&role| self.has_clearance(role))
    }
}

/// The mechanism driven by its inputs as functions of time, as the integrators step it: a
/// short-lived view that borrows the mechanism, the inputs and the contact states, evaluates at
/// each evaluation's time with the inputs there, and latches the contact states at each accepted
/// step.
pub struct Driven<'a> {
    /// The mechanism.
    pub mechanism: &'a mut SliderCrank,
    /// Its inputs.
    pub signal: &'a InputSignal,
    /// The joints' contact states.
    pub contacts: &'a mut Contacts,
}

impl OdeSystem for Driven<'_> {
    /// The derivative at (t, y) with the inputs at t, or the singular configuration that has none
    /// (a locked mechanism: the integrator retries the step shorter and names it if it cannot
    /// pass).
    fn rhs(&mut self, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), ModelError> {
        let c = Conditions::at(self.signal, t, self.contacts);
        self.mechanism.derivative(y, &c, dy)
    }

    fn check_step(&mut self, _t0: f64, y0: &[f64], _t1: f64, y1: &[f64]) -> Option<f64> {
        self.mechanism.onset_limit(y0, y1)
    }

    fn accept_step(&mut self, _t0: f64, y0: &[f64], _t1: f64, y1: &[f64]) -> Option<f64> {
        self.mechanism.latch_contacts(y0, y1, self.contacts)
    }
}

impl MechanicalSystem for Driven<'_> {
    fn n_coordinates(&self) -> usize {
        self.mechanism.n_coordinates()
    }

    fn held_errors(&self, y: &[f64], err: &[f64], out: &mut [f64]) {
        self.mechanism.journal_held_errors(y, err, out);
    }
}

impl SliderCrank {
    /// Rejects a step from `y0` to `y1` that starts a contact deeper than
    /// [`CONTACT_ONSET_PENETRATION`] at any joint: the fraction of the step to retry with, towards
    /// the earliest crossing (linear estimate of the crossing time).
    pub fn onset_limit(&self, y0: &[f64], y1: &[f64]) -> Option<f64> {
        self.clearance_joints()
            .filter_map(|role| {
                let (d0, d1) = (self.penetration(role, y0), self.penetration(role, y1));
                (d0 <= 0.0 && d1 > CONTACT_ONSET_PENETRATION).then(|| {
                    let crossing = -d0 / (d1 - d0);
                    (crossing + 0.5 * CONTACT_ONSET_PENETRATION / (d1 - d0)).clamp(0.01, 0.9)
                })
            })
            .reduce(f64::min)
    }

    /// Latches the impact velocity in `contacts` at the located onset of each joint's contact
    /// event in the step accepted from `y0` to `y1` (linear interpolation of δ̇ to the crossing of
    /// δ = 0), and clears the contact flag at separation.
    ///
    /// Out of contact and approaching the wall (δ₁ < 0 < δ̇₁), the next step is limited to the
    /// linear estimate of the time at which δ reaches half the onset depth,
    /// (−δ₁ + δ_on/2)/δ̇₁ (the smallest over the joints): the step that starts the contact is
    /// aimed at the window 0 < δ ≤ δ_on that [`SliderCrank::onset_limit`] accepts, instead of
    /// overshooting it and being refused (event anticipation; without it the 4-mode rod of
    /// benchmark B refused about 370 steps per two revolutions, 3.3 attempts per onset).
    pub fn latch_contacts(&self, y0: &[f64], y1: &[f64], contacts: &mut Contacts) -> Option<f64> {
        let mut limit: Option<f64> = None;
        for role in JointRole::ALL {
            if !self.has_clearance(role) {
                continue;
            }
            let (d0, d1) = (self.penetration(role, y0), self.penetration(role, y1));
            if d1 > 0.0 && !contacts[role].in_contact {
                let s = if d0 < 0.0 { -d0 / (d1 - d0) } else { 0.0 };
                let (v0, v1) = (
                    self.normal_velocity(role, y0),
                    self.normal_velocity(role, y1),
                );
                contacts[role] = ContactState {
                    in_contact: true,
                    impact_velocity: (v0 + s * (v1 - v0)).max(MIN_IMPACT_VELOCITY),
                };
            } else if d1 <= 0.0 {
                contacts[role].in_contact = false;
            }
            if contacts[role].in_contact || !(d1 < 0.0 && d1.is_finite()) {
                continue;
            }
            let v1 = self.normal_velocity(role, y1);
            if v1 > 0.0 {
                let dt = (0.5 * CONTACT_ONSET_PENETRATION - d1) / v1;
                limit = Some(limit.map_or(dt, |l| l.min(dt)));
            }
        }
        limit
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::{JointModel, JointParameters, Parameters};

    /// Contact-onset anticipation: a step that ends 1 µm short of the wall and approaching it
    /// limits the next one to the time at which δ reaches half the onset depth; moving away, in
    /// contact, or with the ideal joint there is no limit.
    #[test]
    fn approaching_the_wall_limits_the_next_step() {
        let p = Parameters::default();
        let m = SliderCrank::new(&p).expect("default parameters build");
        let mut contacts = Contacts::default();
        let l = m.layout();
        let mut y = m.initial_state(0.3, 400.0);
        y[l.slider()] -= p.joint.clearance - 1e-6;
        let y0 = y.clone();
        let mut approaching = y.clone();
        approaching[l.slider_velocity()] -= 0.5;
        let rs = JointRole::RodSlider;
        let (d, v) = (
            m.penetration(rs, &approaching),
            m.normal_velocity(rs, &approaching),
        );
        assert!(d < 0.0 && d > -2e-6 && v > 0.4, "δ = {d}, δ̇ = {v}");
        let limit = m.latch_contacts(&y0, &approaching, &mut contacts);
        assert_eq!(limit, Some((0.5 * CONTACT_ONSET_PENETRATION - d) / v));
        assert!(!contacts[rs].in_contact);
        let mut leaving = y.clone();
        leaving[l.slider_velocity()] += 0.5;
        assert_eq!(m.latch_contacts(&y0, &leaving, &mut contacts), None);
        let mut inside = approaching.clone();
        inside[l.slider()] -= 2e-6;
        assert_eq!(m.latch_contacts(&y0, &inside, &mut contacts), None);
        assert!(contacts[rs].in_contact);
        let ideal = SliderCrank::new(&Parameters {
            joint: JointParameters {
                model: JointModel::Ideal,
                ..p.joint
            },
            ..p
        })
        .expect("ideal joint builds");
        let y = ideal.initial_state(0.3, 400.0);
        assert_eq!(ideal.latch_contacts(&y, &y, &mut contacts), None);
    }
}
