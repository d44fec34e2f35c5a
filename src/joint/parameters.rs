//! The parameters of one revolute joint — the rod–slider joint, the crank pin or the main bearing —
//! from which [`super::Joint`] is built: its model, geometry, material, friction and lubricant, and
//! where its journal starts.

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

/// Hysteresis-damping law of the dry contact force F_N = K δ^1.5 (1 + χ δ̇/δ̇⁻)
/// ([`crate::joint::DryContact`]).
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

/// Where a clearance joint's journal starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JournalStart {
    /// Centred in the bearing (the benchmarks' start): it crosses the clearance and impacts.
    Centred,
    /// In quasi-static equilibrium with the ideal joint's initial reaction, at rest relative to
    /// the bearing ([`crate::mechanism::SliderCrank::settle_journal`]): no start-up impact.
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
    /// Where the journal starts.
    pub initial_state: JournalStart,
}

impl JointParameters {
    /// The benchmarks' rod–slider joint (docs/model.md §5): a dry clearance of 0.5 mm between a
    /// 9.5 mm steel journal and a 10 mm bearing, restitution 0.9 with the Lankarani–Nikravesh law,
    /// no friction (friction band 1e-4 … 1e-3 m/s), the benchmark C lubricant and bearing, the
    /// journal centred.
    pub fn benchmark() -> Self {
        Self {
            model: JointModel::Dry,
            clearance: 0.5e-3,
            journal_radius: 9.5e-3,
            youngs_modulus: 207e9,
            poisson_ratio: 0.3,
            restitution: 0.9,
            contact_law: ContactLaw::LankaraniNikravesh,
            friction: 0.0,
            friction_v0: 1e-4,
            friction_v1: 1e-3,
            viscosity: 0.4,
            bearing_length: 0.04,
            switch_eccentricity: 0.95,
            initial_state: JournalStart::Centred,
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

    /// Bearing (hole) radius R_i = R_j + c \[m\].
    pub fn bearing_radius(&self) -> f64 {
        self.journal_radius + self.clearance
    }

    /// Hertz-type stiffness K \[N/m^1.5\] of the journal in its bearing
    /// ([`super::hertz_stiffness`]).
    pub fn contact_stiffness(&self) -> f64 {
        super::hertz_stiffness(
            self.bearing_radius(),
            self.journal_radius,
            self.youngs_modulus,
            self.poisson_ratio,
        )
    }
}

/// Which revolute joint of the mechanism.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JointRole {
    /// The main bearing: the crank's pivot (journal) in the ground (bearing).
    MainBearing,
    /// The crank pin: the crank's pin (journal) in the rod's eye (bearing), the big end.
    CrankPin,
    /// The rod–slider joint: the rod's pin (journal) in the slider (bearing), the small end.
    RodSlider,
}

/// The FMU names of a joint's parameters, `<prefix>.<field>`, in the order of
/// [`JointRole::parameter`]'s fields.
macro_rules! names {
    ($prefix:literal) => {
        [
            concat!($prefix, ".model"),
            concat!($prefix, ".clearance"),
            concat!($prefix, ".journalRadius"),
            concat!($prefix, ".youngsModulus"),
            concat!($prefix, ".poissonRatio"),
            concat!($prefix, ".restitution"),
            concat!($prefix, ".contactLaw"),
            concat!($prefix, ".friction"),
            concat!($prefix, ".frictionV0"),
            concat!($prefix, ".frictionV1"),
            concat!($prefix, ".viscosity"),
            concat!($prefix, ".bearingLength"),
            concat!($prefix, ".switchEccentricity"),
            concat!($prefix, ".initialState"),
        ]
    };
}

/// The fields of [`JointParameters`], for [`JointRole::parameter`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum JointField {
    Model,
    Clearance,
    JournalRadius,
    YoungsModulus,
    PoissonRatio,
    Restitution,
    ContactLaw,
    Friction,
    FrictionV0,
    FrictionV1,
    Viscosity,
    BearingLength,
    SwitchEccentricity,
    InitialState,
}

impl JointRole {
    /// Every joint, from the ground to the slider.
    pub const ALL: [Self; 3] = [Self::MainBearing, Self::CrankPin, Self::RodSlider];

    /// The prefix of the joint's FMU variables: `mainBearing`, `crankPin`, `joint`.
    pub fn prefix(self) -> &'static str {
        match self {
            Self::MainBearing => "mainBearing",
            Self::CrankPin => "crankPin",
            Self::RodSlider => "joint",
        }
    }

    /// The FMU name of one of the joint's parameters, e.g. `crankPin.clearance`.
    pub fn parameter(self, field: JointField) -> &'static str {
        const NAMES: [[&str; 14]; 3] = [names!("mainBearing"), names!("crankPin"), names!("joint")];
        NAMES[self as usize][field as usize]
    }
}
