//! The parameters of one revolute joint — the rod–slider joint, the crank pin or the main bearing —
//! from which the joint's law (`Joint`) is built: its model, geometry, material, friction and lubricant, and
//! where its journal starts.

use super::contact::{ContactGeometry, ContactLaw, Elastic, LineContact, hertz_stiffness};
use super::feed::{FeedLocation, FeedModel};

/// Model of a revolute joint.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JointModel {
    /// Ideal revolute joint (constraint).
    Ideal,
    /// Dry clearance joint: Lankarani–Nikravesh contact with Coulomb–Ambrósio friction.
    Dry,
    /// Lubricated journal bearing (short-bearing film), dry contact near metal contact.
    Lubricated,
}

/// The oil film of a lubricated joint.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FilmModel {
    /// Ocvirk's infinitely short bearing: the benchmarks' film (Flores et al.), the limit
    /// L/D → 0, carrying up to twice the finite bearing's load at L/D 0.5–1.
    Short,
    /// The finite bearing: the Reynolds equation over the bearing's length with the Reynolds
    /// cavitation condition, tabulated ([`crate::joint::finite_film`]), L/D up to 4.
    Finite,
}

/// How a lubricated joint's oil gets its viscosity.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ThermalModel {
    /// The joint's `viscosity`, constant.
    Isoviscous,
    /// The oil's viscosity law at the film's effective temperature, a state of its own heat
    /// balance ([`crate::joint::thermal`]).
    HeatBalance,
}

/// Where a heat balance's film temperature starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ThermalStart {
    /// At the oil's supply temperature: the bearing warms up from cold oil.
    Supply,
    /// In the steady heat balance of the start's load and speed: the bearing at its operating
    /// temperature.
    Settled,
}

/// Where a clearance joint's journal starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JournalStart {
    /// Centred in the bearing (the benchmarks' start): it crosses the clearance and impacts.
    Centred,
    /// In quasi-static equilibrium with the ideal joint's initial reaction, at rest relative to
    /// the bearing ([`crate::mechanism::SliderCrank::settle_journals`]): no start-up impact.
    Settled,
}

/// The parameters of one revolute joint (SI units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointParameters {
    /// Joint model.
    pub model: JointModel,
    /// Radial clearance c = R_bearing − R_journal \[m\].
    pub clearance: f64,
    /// Journal (pin) radius R_j \[m\].
    pub journal_radius: f64,
    /// Young's modulus of journal and bearing \[Pa\].
    pub youngs_modulus: f64,
    /// Poisson ratio of journal and bearing.
    pub poisson_ratio: f64,
    /// Coefficient of restitution c_e ∈ (0, 1].
    pub restitution: f64,
    /// Hysteresis-damping law of the dry contact.
    pub contact_law: ContactLaw,
    /// Geometry of the dry contact: point (Hertz) or cylinder (Johnson's line contact).
    pub contact_geometry: ContactGeometry,
    /// Coulomb friction coefficient μ.
    pub friction: f64,
    /// Tangential speed below which friction vanishes v₀ \[m/s\].
    pub friction_v0: f64,
    /// Tangential speed above which friction is fully developed v₁ \[m/s\].
    pub friction_v1: f64,
    /// Lubricant dynamic viscosity \[Pa s\].
    pub viscosity: f64,
    /// Bearing length L \[m\].
    pub bearing_length: f64,
    /// Eccentricity ratio above which dry contact takes over, ε_b ∈ (0, 1).
    pub switch_eccentricity: f64,
    /// The oil film's model.
    pub film_model: FilmModel,
    /// Combined RMS roughness σ of journal and bearing, 0 for smooth surfaces \[m\]
    /// ([`super::asperity`]).
    pub roughness: f64,
    /// Boundary friction coefficient μ_b of the asperity contact.
    pub boundary_friction: f64,
    /// σβη: the product of roughness, asperity summit radius and summit density.
    pub asperity_density_product: f64,
    /// σ/β: the roughness over the asperity summit radius.
    pub asperity_roughness_ratio: f64,
    /// How a lubricated joint's oil gets its viscosity.
    pub thermal_model: ThermalModel,
    /// Where the heat balance's film temperature starts.
    pub thermal_start: ThermalStart,
    /// The heat capacity that follows the film's temperature \[J/K\].
    pub heat_capacity: f64,
    /// The conductance from the film to the housing, at the supply temperature \[W/K\].
    pub heat_transfer_coefficient: f64,
    /// Where the journal starts.
    pub initial_state: JournalStart,
    /// The oil feed ([`super::feed`]).
    pub feed: FeedModel,
    /// The body the feed sits in.
    pub feed_location: FeedLocation,
    /// The feed's angle from its body's axis \[rad\].
    pub feed_position: f64,
    /// A hole's diameter or a groove's width \[m\].
    pub feed_diameter: f64,
    /// An axial groove's length over the bearing's length.
    pub feed_groove_length: f64,
}

impl JointParameters {
    /// The benchmarks' rod–slider joint (docs/model.md §5): a dry clearance of 0.5 mm between a
    /// 9.5 mm steel journal and a 10 mm bearing, restitution 0.9 with the Lankarani–Nikravesh law,
    /// no friction (friction band 1e-4 … 1e-3 m/s), the benchmark C lubricant and bearing, the
    /// journal centred, the finite film when made lubricated (benchmark C names the short film).
    pub fn benchmark() -> Self {
        Self {
            model: JointModel::Dry,
            clearance: 0.5e-3,
            journal_radius: 9.5e-3,
            youngs_modulus: 207e9,
            poisson_ratio: 0.3,
            restitution: 0.9,
            contact_law: ContactLaw::LankaraniNikravesh,
            contact_geometry: ContactGeometry::Point,
            friction: 0.0,
            friction_v0: 1e-4,
            friction_v1: 1e-3,
            viscosity: 0.4,
            bearing_length: 0.04,
            switch_eccentricity: 0.95,
            film_model: FilmModel::Finite,
            roughness: 0.0,
            boundary_friction: 0.1,
            asperity_density_product: 0.04,
            asperity_roughness_ratio: 1e-3,
            thermal_model: ThermalModel::Isoviscous,
            thermal_start: ThermalStart::Settled,
            heat_capacity: 20.0,
            heat_transfer_coefficient: 0.0,
            initial_state: JournalStart::Centred,
            feed: FeedModel::None,
            feed_location: FeedLocation::Shell,
            feed_position: 0.0,
            feed_diameter: 4e-3,
            feed_groove_length: 0.8,
        }
    }

    /// An ideal joint with the benchmark's geometry and materials for when it is made a clearance
    /// joint.
    pub fn ideal() -> Self {
        Self {
            model: JointModel::Ideal,
            ..Self::benchmark()
        }
    }

    /// The bearing's length-to-diameter ratio L/D, D = 2 R_j.
    pub fn length_ratio(&self) -> f64 {
        self.bearing_length / (2.0 * self.journal_radius)
    }

    /// Bearing (hole) radius R_i = R_j + c \[m\].
    pub fn bearing_radius(&self) -> f64 {
        self.journal_radius + self.clearance
    }

    /// The elastic law of the dry contact for its geometry: Hertz's point contact with
    /// [`JointParameters::contact_stiffness`], or Johnson's line contact over the bearing length.
    pub fn elastic(&self) -> Elastic {
        match self.contact_geometry {
            ContactGeometry::Point => Elastic::Point(self.contact_stiffness()),
            ContactGeometry::Cylinder => Elastic::Cylinder(LineContact::new(
                self.bearing_length,
                self.clearance,
                self.youngs_modulus,
                self.poisson_ratio,
            )),
        }
    }

    /// Hertz-type stiffness K \[N/m^1.5\] of the journal in its bearing
    /// ([`hertz_stiffness`]), the point contact's.
    pub fn contact_stiffness(&self) -> f64 {
        hertz_stiffness(
            self.bearing_radius(),
            self.journal_radius,
            self.youngs_modulus,
            self.poisson_ratio,
        )
    }
}
