//! The mechanism's revolute joints by role, and the FMU names of each one's parameters.

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
            concat!($prefix, ".filmModel"),
            concat!($prefix, ".feedDiameter"),
            concat!($prefix, ".feedGrooveLength"),
        ]
    };
}

/// The fields of a joint's parameters (`JointParameters`), for [`JointRole::parameter`].
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
    FilmModel,
    FeedDiameter,
    FeedGrooveLength,
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
        const NAMES: [[&str; 17]; 3] = [names!("mainBearing"), names!("crankPin"), names!("joint")];
        NAMES[self as usize][field as usize]
    }
}
