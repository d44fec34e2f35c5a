//! A revolute joint of the mechanism (the main bearing, the crank pin, the rod–slider joint):
//! ideal, dry clearance, or lubricated.
//!
//! Kinematics (docs/model.md §3, Sun et al. 2015 eqs. 4–5): the eccentricity e = r_journal − r_bearing,
//! n = e/|e|, t = ẑ × n, penetration δ = |e| − c. The joint returns the force on the journal
//! (the bearing gets its opposite) and the moment on the journal about its centre.
//!
//! # References
//! - H. M. Lankarani, P. E. Nikravesh (1990), J. Mech. Des. 112, 369–376.
//! - P. Flores, J. Ambrósio, J. C. P. Claro, H. M. Lankarani (2008), Kinematics and Dynamics of
//!   Multibody Systems with Imperfect Joints, Springer.

pub mod asperity;
pub mod bearing;
pub mod contact;
pub mod feed;
pub mod finite_film;
pub mod kinematics;
pub mod oil;
pub mod parameters;
pub mod reynolds;
pub mod role;
pub mod short_film;
pub mod thermal;

pub use asperity::{Asperity, AsperityState};
pub use bearing::{Film, JournalBearing};
pub use contact::{ContactGeometry, ContactLaw, DryContact, Elastic, LineContact, hertz_stiffness};
pub use feed::{Feed, FeedLocation, FeedModel};
pub use kinematics::{
    ContactState, Contacts, JointForce, JointKinematics, JointRates, MIN_IMPACT_VELOCITY,
    normal_rate_error,
};
pub use oil::{Oil, OilParameters};
pub use parameters::{
    FilmModel, JointModel, JointParameters, JournalStart, ThermalModel, ThermalStart,
};
pub use role::{JointField, JointRole};
pub use thermal::HeatBalance;

use nalgebra::Vector2;

use crate::error::ModelError;

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

impl Joint {
    /// The joint of the parameters `p` (validated beforehand: a finite film's L/D in its
    /// table's range).
    pub fn new(p: &JointParameters) -> Result<Self, ModelError> {
        let dry = DryContact {
            elastic: p.elastic(),
            clearance: p.clearance,
            journal_radius: p.journal_radius,
            restitution: p.restitution,
            law: p.contact_law,
            friction: p.friction,
            friction_v0: p.friction_v0,
            friction_v1: p.friction_v1,
        };
        Ok(match p.model {
            JointModel::Ideal => Self::Ideal,
            JointModel::Dry => Self::Dry(dry),
            JointModel::Lubricated => Self::Lubricated(Self::bearing(p, dry)?),
        })
    }

    /// The lubricated joint of the parameters `p` with the dry contact `dry`: its film over the
    /// lands its feed leaves ([`Feed::lands`]).
    fn bearing(p: &JointParameters, dry: DryContact) -> Result<JournalBearing, ModelError> {
        let feed = Feed::new(
            p.feed,
            p.feed_location,
            p.feed_position,
            (p.feed_diameter, p.feed_groove_length * p.bearing_length),
            (p.bearing_length, p.journal_radius),
        );
        let (lands, length) = Feed::lands(feed.as_ref(), p.bearing_length);
        Ok(JournalBearing {
            viscosity: p.viscosity,
            length,
            lands,
            feed: feed.map(Box::new),
            switch_eccentricity: p.switch_eccentricity,
            heat_balance: None,
            asperity: (p.roughness > 0.0).then(|| {
                asperity::Asperity::new(
                    p.roughness,
                    p.asperity_density_product,
                    p.asperity_roughness_ratio,
                    (p.youngs_modulus, p.poisson_ratio),
                    p.boundary_friction,
                    lands * length,
                )
            }),
            film: match p.film_model {
                FilmModel::Short => Film::Short,
                FilmModel::Finite => Film::Finite(finite_film::FiniteFilm::new(
                    length / (2.0 * p.journal_radius),
                )?),
            },
            dry,
        })
    }

    /// The joint of the parameters `p` with the oil `oil`, which its heat balance uses
    /// (`p.thermal_model`; an isoviscous or dry joint does not).
    pub fn with_oil(p: &JointParameters, oil: &OilParameters) -> Result<Self, ModelError> {
        let mut joint = Self::new(p)?;
        if let (Self::Lubricated(bearing), ThermalModel::HeatBalance) =
            (&mut joint, p.thermal_model)
        {
            bearing.heat_balance = Some(HeatBalance {
                oil: oil.oil(),
                capacity: p.heat_capacity,
                conductance: p.heat_transfer_coefficient,
            });
        }
        Ok(joint)
    }

    /// The film's heat balance, if the joint has one.
    pub fn heat_balance(&self) -> Option<&HeatBalance> {
        match self {
            Self::Lubricated(bearing) => bearing.heat_balance.as_ref(),
            _ => None,
        }
    }

    /// The oil feed, if the joint has one.
    pub fn feed(&self) -> Option<&Feed> {
        match self {
            Self::Lubricated(bearing) => bearing.feed.as_deref(),
            _ => None,
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

    /// The eccentricity at which the journal, at rest in the bearing (ė = 0), journal and bearing
    /// turning at `omega_journal` and `omega_bearing`, the oil of viscosity `viscosity` (where the
    /// joint's heat balance sets it), receives the force `force` from the joint: its quasi-static equilibrium
    /// against a steady load (the settled start, docs/model.md §8).
    ///
    /// Dry and frictionless in closed form, e = −(c + δ) F/|F| with F_e(δ) = |F|; with friction
    /// or a film, Newton's method on F(e) = F in polar coordinates e = ρ (cos φ, sin φ) from that
    /// point (friction and film turn the force against e, so the angle is the natural unknown),
    /// with a difference Jacobian and steps halved until the residual falls. The ideal joint and
    /// a zero force give the centre.
    pub fn eccentricity_carrying(
        &self,
        force: Vector2<f64>,
        (omega_journal, omega_bearing): (f64, f64),
        viscosity: Option<f64>,
    ) -> Vector2<f64> {
        let Some(dry) = self.dry_contact() else {
            return Vector2::zeros();
        };
        let magnitude = force.norm();
        if magnitude == 0.0 {
            return Vector2::zeros();
        }
        let eccentricity = |(rho, phi): (f64, f64)| {
            let (sin, cos) = crate::math::sin_cos(phi);
            rho * Vector2::new(cos, sin)
        };
        let residual = |x: (f64, f64)| {
            let kinematics = JointKinematics {
                e: eccentricity(x),
                e_dot: Vector2::zeros(),
                omega_journal,
                omega_bearing,
                viscosity,
            };
            self.force(&kinematics, MIN_IMPACT_VELOCITY).force - force
        };
        let depth = dry.elastic.penetration(magnitude);
        let (h_rho, h_phi) = (1e-7 * depth.max(1e-3 * dry.clearance), 1e-7);
        let newton = |mut x: (f64, f64)| {
            let mut r = residual(x);
            for _ in 0..50 {
                if r.norm() <= 1e-10 * magnitude {
                    break;
                }
                let jacobian = nalgebra::Matrix2::from_columns(&[
                    (residual((x.0 + h_rho, x.1)) - r) / h_rho,
                    (residual((x.0, x.1 + h_phi)) - r) / h_phi,
                ]);
                let Some(step) = jacobian.lu().solve(&(-r)) else {
                    break;
                };
                let mut scale = 1.0;
                loop {
                    let trial = (x.0 + scale * step.x, x.1 + scale * step.y);
                    let r_trial = residual(trial);
                    if r_trial.norm() < r.norm() {
                        (x, r) = (trial, r_trial);
                        break;
                    }
                    scale *= 0.5;
                    if scale < 1e-6 {
                        return (x, r.norm());
                    }
                }
            }
            (x, r.norm())
        };
        let angle = crate::math::atan2(-force.y, -force.x);
        // From the wall (dry contact), and for a film from inside its range too: between the
        // switch eccentricity and the wall the clamped film does not change with ρ.
        let mut best = newton((dry.clearance + depth, angle));
        if let Self::Lubricated(bearing) = self {
            let inside = newton((0.5 * bearing.switch_eccentricity * dry.clearance, angle));
            if inside.1 < best.1 {
                best = inside;
            }
        }
        eccentricity(best.0)
    }

    /// The film temperature of the steady heat balance of a journal carrying `force` at rest in
    /// the bearing, journal and bearing turning at `omegas`, the oil supplied at the temperature
    /// `supply` and the pressure `pressure`, the body the feed sits in along `feed_axis`: where
    /// the friction power at its settled eccentricity ([`Joint::eccentricity_carrying`] at that
    /// temperature) equals the heat the oil flow (the film's and the feed's) and the housing take,
    /// P(T) = 2 ρ c_p Q(T) (T − T_s) + k (T − T_s) ([`thermal`]). `supply` itself for a joint
    /// without heat balance; None where no temperature up to 1000 K above the supply carries the
    /// friction power away (no oil flow and no housing to take it).
    ///
    /// By bisection on the surplus P − Φ, ≥ 0 at T_s and falling with T (the viscosity and with
    /// it the friction falls, the heat taken rises), to 1e-9 K.
    pub fn settled_temperature(
        &self,
        force: Vector2<f64>,
        omegas: (f64, f64),
        (supply, pressure): (f64, f64),
        feed_axis: Vector2<f64>,
    ) -> Option<f64> {
        let (Self::Lubricated(bearing), Some(balance)) = (self, self.heat_balance()) else {
            return Some(supply);
        };
        let surplus = |t: f64| {
            let k = JointKinematics {
                e: self.eccentricity_carrying(force, omegas, Some(balance.oil.viscosity(t))),
                e_dot: Vector2::zeros(),
                omega_journal: omegas.0,
                omega_bearing: omegas.1,
                viscosity: Some(balance.oil.viscosity(t)),
            };
            let rates = self.rates(&k, MIN_IMPACT_VELOCITY);
            let flow = rates.oil_flow + bearing.feed_flow(&k, feed_axis, pressure);
            rates.friction_power
                - balance.heat_to_oil(flow, t, supply)
                - balance.heat_to_housing(t, supply)
        };
        let (mut low, mut high) = (supply, supply + 1.0);
        while surplus(high) > 0.0 {
            (low, high) = (high, supply + 2.0 * (high - supply));
            if high > supply + 1000.0 {
                return None;
            }
        }
        while high - low > 1e-9 {
            let mid = 0.5 * (low + high);
            if surplus(mid) > 0.0 {
                low = mid;
            } else {
                high = mid;
            }
        }
        Some(0.5 * (low + high))
    }

    /// Force on the journal; `impact_velocity` is δ̇⁽⁻⁾ of the current contact event.
    pub fn force(&self, k: &JointKinematics, impact_velocity: f64) -> JointForce {
        match self {
            Self::Ideal => JointForce::default(),
            Self::Dry(dry) => dry.force(k, impact_velocity),
            Self::Lubricated(bearing) => bearing.force(k, impact_velocity),
        }
    }

    /// What a bearing designer reads off the joint in a state ([`BearingState`]); all zeros for
    /// the ideal joint, which has no clearance.
    pub fn bearing_state(&self, k: &JointKinematics, impact_velocity: f64) -> BearingState {
        let Some(dry) = self.dry_contact() else {
            return BearingState::default();
        };
        let c = dry.clearance;
        let eccentricity_ratio = k.e.norm() / c;
        let (force, rates, film_pressure, asperity, viscosity) = match self {
            Self::Lubricated(bearing) => {
                let (force, rates) = bearing.force_and_rates(k, impact_velocity);
                let asperity = bearing.asperity_force(k).1;
                let pressure = bearing.peak_pressure(k);
                (force, rates, pressure, asperity, bearing.viscosity_at(k))
            }
            _ => (
                self.force(k, impact_velocity),
                self.rates(k, impact_velocity),
                0.0,
                AsperityState::default(),
                0.0,
            ),
        };
        let film_thickness = film_thickness(c, eccentricity_ratio);
        let film_ratio = match self {
            Self::Lubricated(JournalBearing {
                asperity: Some(a), ..
            }) => film_thickness / a.roughness,
            _ => 0.0,
        };
        BearingState {
            eccentricity_ratio,
            film_thickness,
            film_pressure,
            friction_torque: force.moment,
            friction_power: rates.friction_power,
            hysteresis_power: dry.hysteresis_power(k, impact_velocity),
            oil_flow: rates.oil_flow,
            feed_flow: 0.0,
            asperity_force: rates.asperity_force,
            asperity_pressure_peak: asperity.pressure_peak,
            asperity_friction_power: asperity.friction_power,
            film_ratio,
            viscosity,
        }
    }

    /// Whether the joint dissipates by friction or carries a film: what has a friction power
    /// or an oil flow to integrate (not the ideal joint, nor a dry joint without friction).
    pub fn has_friction_or_film(&self) -> bool {
        match self {
            Self::Ideal => false,
            Self::Dry(dry) => dry.friction != 0.0,
            Self::Lubricated(_) => true,
        }
    }

    /// The joint's friction power, oil flow and asperity force in a state (what
    /// [`Joint::bearing_state`] gives of them, without the force and the pressure peak).
    pub fn rates(&self, k: &JointKinematics, impact_velocity: f64) -> JointRates {
        match self {
            Self::Ideal => JointRates::default(),
            Self::Dry(dry) => JointRates {
                friction_power: dry.friction_power(k, impact_velocity),
                ..JointRates::default()
            },
            Self::Lubricated(bearing) => bearing.force_and_rates(k, impact_velocity).1,
        }
    }
}

/// The minimum gap c (1 − ε) between journal and bearing at the eccentricity ratio ε, 0 in
/// metal contact (ε ≥ 1) \[m\].
pub fn film_thickness(clearance: f64, eccentricity_ratio: f64) -> f64 {
    (clearance * (1.0 - eccentricity_ratio)).max(0.0)
}

/// A joint as its designer reads it in one state (SI units).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BearingState {
    /// The eccentricity ratio ε = |e|/c (the actual one, not the film model's clamped value).
    pub eccentricity_ratio: f64,
    /// The minimum gap c (1 − ε), 0 in metal contact \[m\] ([`film_thickness`]).
    pub film_thickness: f64,
    /// The largest film pressure, at mid-length; 0 without a film \[Pa\]
    /// ([`JournalBearing::peak_pressure`]).
    pub film_pressure: f64,
    /// The friction moment on the journal about its centre: dry friction and film shear \[N m\].
    pub friction_torque: f64,
    /// The rate at which the joint's friction dissipates energy, ≥ 0: the film's viscous loss
    /// ([`JournalBearing::film_loss`]) and dry friction's −F_T v_T \[W\].
    pub friction_power: f64,
    /// The rate at which the dry contact's hysteresis damping dissipates energy, ≥ 0 \[W\]
    /// ([`DryContact::hysteresis_power`]).
    pub hysteresis_power: f64,
    /// The oil flow through the bearing: out of both ends of the pressurised film
    /// ([`JournalBearing::side_flow`]) and, where the mechanism adds it, the feed's
    /// (`feed_flow`); 0 without a film \[m³/s\].
    pub oil_flow: f64,
    /// The flow the supply pressure drives from the feed, 0 without one \[m³/s\]
    /// ([`JournalBearing::feed_flow`]): the mechanism sets it, with the bodies' axes and the
    /// supply pressure.
    pub feed_flow: f64,
    /// The normal force the rough surfaces' asperities carry, 0 for smooth surfaces \[N\]
    /// ([`asperity`]).
    pub asperity_force: f64,
    /// The largest asperity pressure, at the thinnest film \[Pa\].
    pub asperity_pressure_peak: f64,
    /// The asperities' boundary friction power (part of `friction_power`) \[W\].
    pub asperity_friction_power: f64,
    /// The film ratio h_min/σ, 0 for smooth surfaces and in metal contact.
    pub film_ratio: f64,
    /// The oil's viscosity in the film, 0 without a film \[Pa s\]
    /// ([`JournalBearing::viscosity_at`]).
    pub viscosity: f64,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The settled eccentricity carries the given force, at rest in the bearing: dry without
    /// friction (on the line of the force, beyond the clearance), dry with friction and
    /// lubricated (the film carries part or all of it), for loads from 10 N to 10 kN in several
    /// directions; the ideal joint and no load give the centre.
    #[test]
    fn the_settled_eccentricity_carries_the_load() {
        let p = JointParameters::benchmark();
        let omega = -120.0;
        for (name, joint) in [
            ("dry", Joint::new(&p).unwrap()),
            (
                "dry, friction 0.2",
                Joint::new(&JointParameters { friction: 0.2, ..p }).unwrap(),
            ),
            (
                "lubricated",
                Joint::new(&JointParameters {
                    model: JointModel::Lubricated,
                    ..p
                })
                .unwrap(),
            ),
        ] {
            for magnitude in [10.0, 1e3, 1e4] {
                for angle in [0.0, 2.0, 4.5] {
                    let (sin, cos) = crate::math::sin_cos(angle);
                    let force = magnitude * Vector2::new(cos, sin);
                    let e = joint.eccentricity_carrying(force, (omega, 0.0), None);
                    let kinematics = JointKinematics {
                        e,
                        e_dot: Vector2::zeros(),
                        omega_journal: omega,
                        omega_bearing: 0.0,
                        viscosity: None,
                    };
                    let carried = joint.force(&kinematics, MIN_IMPACT_VELOCITY).force;
                    assert!(
                        (carried - force).norm() < 1e-8 * magnitude,
                        "{name}, {magnitude} N at {angle} rad: carries {carried:?}"
                    );
                    if name == "dry" {
                        assert!(e.norm() > p.clearance);
                        assert!(e.dot(&force) < 0.0);
                    }
                }
            }
        }
        let joint = Joint::new(&p).unwrap();
        assert_eq!(
            joint.eccentricity_carrying(Vector2::zeros(), (omega, 0.0), None),
            Vector2::zeros()
        );
        assert_eq!(
            Joint::Ideal.eccentricity_carrying(Vector2::new(5.0, 1.0), (omega, 0.0), None),
            Vector2::zeros()
        );
    }
}
