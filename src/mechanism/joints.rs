//! The mechanism's revolute joints: where each journal and bearing sit in the state, and where a
//! clearance joint's force acts (docs/model.md §3).
//!
//! ```text
//! joint        journal (ω_j)               bearing (ω_b)           e = r_journal − r_bearing
//! main bearing crank's pivot (θ̇)           ground (0)              r_G − a (cos θ, sin θ)
//! crank pin    crank pin r_P (θ̇)           rod's eye at A (ω_A)    r_O + d (cos θ, sin θ) − r_A
//! rod–slider   rod's pin at B (ω_B)         slider (0)              r_B − (x_s, e)
//! ```
//! ω_A, ω_B are the rod's rotations at its ends, r_O and d the crank's reference point and the
//! pin's distance from it (the fixed pivot, 0 and r_c; or the free crank's centre of mass r_G and
//! r_c − a, with a the pivot to centre-of-mass distance; e the guide's offset). The force F and
//! moment M_j act on the journal, −F and
//! M_b on the bearing: the crank receives F at its pin (crank pin) or at its pivot (main bearing)
//! and the moment M_j, and the rod −F at A with the moment M_b.

use nalgebra::Vector2;

use super::inputs::Conditions;
use super::layout::{CRANK_ANGLE, PIN_A, pair};
use super::slider_crank::SliderCrank;
use crate::joint::{
    BearingState, Contacts, FeedLocation, Joint, JointForce, JointKinematics, JointRates, JointRole,
};
use crate::math;
use crate::reduction::RodEnd;

/// The load of a clearance joint on the crank (the crank pin or the main bearing) in one
/// evaluation.
#[derive(Clone, Copy, Debug)]
pub(super) struct CrankLoad {
    /// Force on the crank, F \[N\].
    pub force: Vector2<f64>,
    /// Torque on the crank about its reference point r_O, (r − r_O) × F + M_j with r the
    /// journal's centre \[N m\].
    pub torque: f64,
    /// Power of the joint's forces on journal and bearing ([`JointKinematics::power`]) \[W\].
    pub power: f64,
    /// Elastic energy stored in the contact \[J\].
    pub potential: f64,
    /// The joint's friction power and oil flow, where its heat balance reads them.
    pub heat: Option<JointRates>,
}

impl SliderCrank {
    /// The law of the joint `role`.
    pub fn joint(&self, role: JointRole) -> &Joint {
        &self.joints[role as usize]
    }

    /// Whether the joint `role` has a clearance (dry or lubricated).
    pub fn has_clearance(&self, role: JointRole) -> bool {
        !matches!(self.joint(role), Joint::Ideal)
    }

    /// Whether any joint is lubricated (has an oil film).
    pub fn has_film(&self) -> bool {
        self.joints
            .iter()
            .any(|joint| matches!(joint, Joint::Lubricated(_)))
    }

    /// The crank's reference point r_O and its velocity: the fixed pivot (at rest at the origin)
    /// or the free crank's centre of mass.
    pub(super) fn crank_reference(&self, y: &[f64]) -> Option<(Vector2<f64>, Vector2<f64>)> {
        let l = self.layout;
        l.crank_centre()
            .map(|g| (pair(y, g), pair(y, l.rate_of(g))))
    }

    /// Journal–bearing kinematics of the joint `role` in state `y`, with the oil's viscosity at
    /// its film temperature where it has a heat balance.
    pub fn joint_kinematics(&self, role: JointRole, y: &[f64]) -> JointKinematics {
        let l = self.layout;
        let (p, p_dot) = (&y[l.rod()], &y[l.rod_rates()]);
        let (theta, omega) = (y[CRANK_ANGLE], y[l.crank_speed()]);
        let viscosity = self.film_viscosity(role, y);
        match role {
            JointRole::MainBearing => {
                let (e, e_dot) = match self.crank_reference(y) {
                    Some((r_g, v_g)) => {
                        let (sin, cos) = math::sin_cos(theta);
                        let a = self.crank.centre;
                        (
                            r_g - a * Vector2::new(cos, sin),
                            v_g + a * omega * Vector2::new(sin, -cos),
                        )
                    }
                    None => (Vector2::zeros(), Vector2::zeros()),
                };
                JointKinematics {
                    e,
                    e_dot,
                    omega_journal: omega,
                    omega_bearing: 0.0,
                    viscosity,
                }
            }
            JointRole::CrankPin => {
                let (sin, cos) = math::sin_cos(theta);
                let d = self.crank.arm;
                let mut e = d * Vector2::new(cos, sin) - pair(y, PIN_A);
                let mut e_dot = d * omega * Vector2::new(-sin, cos) - pair(y, l.rate_of(PIN_A));
                if let Some((r_o, v_o)) = self.crank_reference(y) {
                    e += r_o;
                    e_dot += v_o;
                }
                JointKinematics {
                    e,
                    e_dot,
                    omega_journal: omega,
                    omega_bearing: self.rod.end_angular_velocity(RodEnd::CrankPin, p, p_dot),
                    viscosity,
                }
            }
            JointRole::RodSlider => {
                let (b, b_rate) = (l.pin_b(), l.rate_of(l.pin_b()));
                JointKinematics {
                    e: Vector2::new(y[b] - y[l.slider()], y[b + 1] - self.slider.offset),
                    e_dot: Vector2::new(y[b_rate] - y[l.slider_velocity()], y[b_rate + 1]),
                    omega_journal: self.rod.end_angular_velocity(RodEnd::SliderPin, p, p_dot),
                    omega_bearing: 0.0,
                    viscosity,
                }
            }
        }
    }

    /// The force of the joint `role` in state `y` with the contact states `contacts`, with its
    /// kinematics.
    pub fn joint_force(
        &self,
        role: JointRole,
        y: &[f64],
        contacts: &Contacts,
    ) -> (JointForce, JointKinematics) {
        let kin = self.joint_kinematics(role, y);
        let impact_velocity = self.impact_velocity(role, &kin, contacts);
        (self.joint(role).force(&kin, impact_velocity), kin)
    }

    /// [`SliderCrank::joint_force`] under the conditions `c` with, where the joint has a heat
    /// balance, its friction power and oil flow (the film's, from the same evaluation of it, and
    /// the feed's) — what its film temperature's rate reads.
    #[inline]
    pub(super) fn joint_force_with_heat(
        &self,
        role: JointRole,
        y: &[f64],
        c: &Conditions,
    ) -> (JointForce, JointKinematics, Option<JointRates>) {
        let kin = self.joint_kinematics(role, y);
        let impact_velocity = self.impact_velocity(role, &kin, c.contacts);
        match self.joint(role) {
            Joint::Lubricated(bearing) if bearing.heat_balance.is_some() => {
                let (force, mut rates) = bearing.force_and_rates(&kin, impact_velocity);
                rates.oil_flow += self.feed_flow(role, y, &kin, c.inputs.oil_supply_pressure);
                (force, kin, Some(rates))
            }
            joint => (joint.force(&kin, impact_velocity), kin, None),
        }
    }

    /// The crank pin's clearance-joint force in state `y` applied to the rod (−F at its end A and
    /// the bearing moment M_b on its eye, added to the rod's generalised forces `rod_force`), with
    /// the crank's share returned; `None` for the ideal crank pin (a constraint).
    pub(super) fn apply_crank_pin(
        &self,
        y: &[f64],
        c: &Conditions,
        rod_force: &mut [f64],
    ) -> Option<CrankLoad> {
        if !self.has_clearance(JointRole::CrankPin) {
            return None;
        }
        let (f, kin, heat) = self.joint_force_with_heat(JointRole::CrankPin, y, c);
        rod_force[0] -= f.force.x;
        rod_force[1] -= f.force.y;
        let p = &y[self.layout.rod()];
        self.rod
            .add_end_moment(RodEnd::CrankPin, p, f.bearing_moment, rod_force);
        Some(self.crank_load(y, self.crank.arm, (&f, &kin, heat)))
    }

    /// The main bearing's clearance-joint load on the free crank in state `y`; `None` for the ideal
    /// main bearing (the fixed pivot).
    pub(super) fn main_bearing_load(&self, y: &[f64], c: &Conditions) -> Option<CrankLoad> {
        if !self.active.free_crank {
            return None;
        }
        let (f, kin, heat) = self.joint_force_with_heat(JointRole::MainBearing, y, c);
        Some(self.crank_load(y, -self.crank.centre, (&f, &kin, heat)))
    }

    /// The load on the crank of the joint force `f` whose journal lies at `arm` from the crank's
    /// reference point along the crank, with the joint's power from its kinematics `kin`.
    fn crank_load(
        &self,
        y: &[f64],
        arm: f64,
        (f, kin, heat): (&JointForce, &JointKinematics, Option<JointRates>),
    ) -> CrankLoad {
        let (sin, cos) = math::sin_cos(y[CRANK_ANGLE]);
        let arm = arm * Vector2::new(cos, sin);
        CrankLoad {
            force: f.force,
            torque: arm.x * f.force.y - arm.y * f.force.x + f.moment,
            power: kin.power(f),
            potential: f.potential,
            heat,
        }
    }

    /// What a bearing designer reads off the joint `role` in state `y` with the contact states
    /// `contacts` ([`crate::joint::Joint::bearing_state`]), the oil supplied at the pressure
    /// `supply_pressure` \[Pa\]: its oil flow the film's side flow and the feed's.
    pub fn bearing_state(
        &self,
        role: JointRole,
        y: &[f64],
        contacts: &Contacts,
        supply_pressure: f64,
    ) -> BearingState {
        let kin = self.joint_kinematics(role, y);
        let impact_velocity = self.impact_velocity(role, &kin, contacts);
        let mut state = self.joint(role).bearing_state(&kin, impact_velocity);
        state.feed_flow = self.feed_flow(role, y, &kin, supply_pressure);
        state.oil_flow += state.feed_flow;
        state
    }

    /// The pressure-fed flow of the joint `role`'s feed in state `y` of kinematics `kin` for the
    /// supply pressure `pressure` \[m³/s\] ([`crate::joint::Feed::flow`]); 0 without a feed.
    fn feed_flow(&self, role: JointRole, y: &[f64], kin: &JointKinematics, pressure: f64) -> f64 {
        match self.joint(role) {
            Joint::Lubricated(bearing) if bearing.feed.is_some() => {
                bearing.feed_flow(kin, self.feed_axis(role, y), pressure)
            }
            _ => 0.0,
        }
    }

    /// The unit axis of the body the joint `role`'s feed sits in, in state `y`: its journal's or
    /// its bearing's (x̂ without a feed).
    pub(super) fn feed_axis(&self, role: JointRole, y: &[f64]) -> Vector2<f64> {
        match self.joint(role).feed().map(|feed| feed.location) {
            Some(FeedLocation::Journal) => self.journal_axis(role, y),
            Some(FeedLocation::Shell) => self.bearing_axis(role, y),
            None => Vector2::x(),
        }
    }

    /// The unit axis of the joint `role`'s journal body in state `y`: the crank's from its pivot
    /// to its pin, the rod's tangent at its pin.
    fn journal_axis(&self, role: JointRole, y: &[f64]) -> Vector2<f64> {
        match role {
            JointRole::MainBearing | JointRole::CrankPin => {
                let (sin, cos) = math::sin_cos(y[CRANK_ANGLE]);
                Vector2::new(cos, sin)
            }
            JointRole::RodSlider => self.rod_axis(RodEnd::SliderPin, y),
        }
    }

    /// The unit axis of the joint `role`'s bearing body in state `y`: the ground's and the
    /// slider's x axis, the rod's tangent at its eye.
    fn bearing_axis(&self, role: JointRole, y: &[f64]) -> Vector2<f64> {
        match role {
            JointRole::MainBearing | JointRole::RodSlider => Vector2::x(),
            JointRole::CrankPin => self.rod_axis(RodEnd::CrankPin, y),
        }
    }

    /// The rod's unit tangent at its end `end` in state `y`.
    fn rod_axis(&self, end: RodEnd, y: &[f64]) -> Vector2<f64> {
        self.rod
            .end_direction(end, &y[self.layout.rod()])
            .normalize()
    }

    /// The eccentricity ratio ε = |e|/c and the film's peak pressure of each joint in state `y`,
    /// by [`JointRole`] (zeros for an ideal joint, a zero pressure without a film): what the
    /// film's peak-hold outputs follow between communication points.
    pub fn film_extremes(&self, y: &[f64]) -> [(f64, f64); 3] {
        JointRole::ALL.map(|role| match self.joint(role) {
            Joint::Ideal => (0.0, 0.0),
            Joint::Dry(dry) => (self.joint_kinematics(role, y).e.norm() / dry.clearance, 0.0),
            Joint::Lubricated(bearing) => {
                let kin = self.joint_kinematics(role, y);
                (
                    kin.e.norm() / bearing.dry.clearance,
                    bearing.peak_pressure(&kin),
                )
            }
        })
    }

    /// The oil's viscosity in the joint `role` in state `y` at its film temperature, where its
    /// heat balance sets it \[Pa s\].
    #[inline]
    fn film_viscosity(&self, role: JointRole, y: &[f64]) -> Option<f64> {
        let i = self.temperature[role as usize]?;
        let balance = self.joint(role).heat_balance()?;
        Some(balance.oil.viscosity(y[i]))
    }

    /// The film temperature of the joint `role` in state `y`, where it has a heat balance \[K\].
    pub fn film_temperature(&self, role: JointRole, y: &[f64]) -> Option<f64> {
        self.temperature[role as usize].map(|i| y[i])
    }

    /// Writes the rate of each film temperature in state `y` under the conditions `c` to `dy`:
    /// the heat balance's dT/dt = (P − Φ_oil − Φ_housing)/C with the joint's friction power and
    /// oil flow (the film's and the feed's) there, `heat` by [`JointRole`]
    /// ([`crate::joint::thermal`]).
    pub(super) fn film_temperature_rates(
        &self,
        y: &[f64],
        c: &Conditions,
        heat: [Option<JointRates>; 3],
        dy: &mut [f64],
    ) {
        for (role, index) in JointRole::ALL.into_iter().zip(self.temperature) {
            let (Some(i), Some(balance), Some(rates)) =
                (index, self.joint(role).heat_balance(), heat[role as usize])
            else {
                continue;
            };
            dy[i] = balance.rate(
                rates.friction_power,
                rates.oil_flow,
                y[i],
                c.inputs.oil_supply_temperature,
            );
        }
    }

    /// Each joint's friction power, oil flow (the film's and the feed's, the oil supplied at the
    /// pressure `supply_pressure`) and asperity force in state `y` with the contact states
    /// `contacts`, by [`JointRole`] ([`Joint::rates`]): what the cycle results' means integrate
    /// and their asperity peaks hold.
    pub fn joint_rates(
        &self,
        y: &[f64],
        contacts: &Contacts,
        supply_pressure: f64,
    ) -> [JointRates; 3] {
        JointRole::ALL.map(|role| {
            let joint = self.joint(role);
            if !joint.has_friction_or_film() {
                return JointRates::default();
            }
            let kin = self.joint_kinematics(role, y);
            let mut rates = joint.rates(&kin, self.impact_velocity(role, &kin, contacts));
            rates.oil_flow += self.feed_flow(role, y, &kin, supply_pressure);
            rates
        })
    }

    /// The elastic energy each joint's contact stores in state `y` with the contact states
    /// `contacts`, by [`JointRole`] (0 for an ideal joint) \[J\].
    pub fn contact_energies(&self, y: &[f64], contacts: &Contacts) -> [f64; 3] {
        JointRole::ALL.map(|role| {
            if self.has_clearance(role) {
                self.joint_force(role, y, contacts).0.potential
            } else {
                0.0
            }
        })
    }

    /// The elastic energy each joint's contact stored at the start, by [`JointRole`] \[J\]
    /// ([`super::JointEnergy::contact_at_start`]).
    pub fn contact_at_start(&self) -> [f64; 3] {
        self.contact_at_start
    }

    /// Sets the energies of [`SliderCrank::contact_at_start`]: those of the start state (a
    /// simulation's start, or a restored one's).
    pub fn set_contact_at_start(&mut self, energies: [f64; 3]) {
        self.contact_at_start = energies;
    }

    /// Elastic energy stored in the contacts of every clearance joint in state `y` with the
    /// contact states `contacts` \[J\].
    pub fn contact_potential(&self, y: &[f64], contacts: &Contacts) -> f64 {
        JointRole::ALL
            .into_iter()
            .filter(|&role| self.has_clearance(role))
            .map(|role| self.joint_force(role, y, contacts).0.potential)
            .sum()
    }
}
