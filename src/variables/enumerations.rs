//! The enumeration types of the FMU's switches, and each type's index, named.

use fmi_core::table::Enumeration;

/// Index of the `RodFormulation` type in [`ENUMERATIONS`].
pub const ROD_FORMULATION: usize = 0;
/// Index of the `JointModel` type in [`ENUMERATIONS`].
pub const JOINT_MODEL: usize = 1;
/// Index of the `DriveMode` type in [`ENUMERATIONS`].
pub const DRIVE_MODE: usize = 2;
/// Index of the `RodBoundary` type in [`ENUMERATIONS`].
pub const ROD_BOUNDARY: usize = 3;
/// Index of the `RodInitialState` type in [`ENUMERATIONS`].
pub const ROD_INITIAL_STATE: usize = 4;
/// Index of the `IntegrationMethod` type in [`ENUMERATIONS`].
pub const INTEGRATION_METHOD: usize = 5;
/// Index of the `ContactLaw` type in [`ENUMERATIONS`].
pub const CONTACT_LAW: usize = 6;
/// Index of the `JournalStart` type in [`ENUMERATIONS`].
pub const JOURNAL_START: usize = 7;
/// Index of the `RodQuadrature` type in [`ENUMERATIONS`].
pub const ROD_QUADRATURE: usize = 8;
/// Index of the `ContactGeometry` type in [`ENUMERATIONS`].
pub const CONTACT_GEOMETRY: usize = 9;
/// Index of the `FilmModel` type in [`ENUMERATIONS`].
pub const FILM_MODEL: usize = 10;
/// Index of the `ThermalModel` type in [`ENUMERATIONS`].
pub const THERMAL_MODEL: usize = 11;
/// Index of the `ThermalStart` type in [`ENUMERATIONS`].
pub const THERMAL_START: usize = 12;
/// Index of the `Feed` type in [`ENUMERATIONS`].
pub const FEED: usize = 13;
/// Index of the `FeedLocation` type in [`ENUMERATIONS`].
pub const FEED_LOCATION: usize = 14;

/// Enumeration types.
pub const ENUMERATIONS: &[Enumeration] = &[
    Enumeration {
        name: "RodFormulation",
        items: &[
            ("rigid", "rigid uniform bar"),
            ("ancf", "full ANCF beam model"),
            ("craigBampton", "ANCF beam reduced by Craig-Bampton"),
        ],
    },
    Enumeration {
        name: "JointModel",
        items: &[
            ("ideal", "ideal revolute joint"),
            (
                "dry",
                "dry clearance joint (Hertz contact with the damping law of joint.contactLaw, Coulomb friction)",
            ),
            (
                "lubricated",
                "lubricated journal bearing (oil film of the joint's filmModel, dry contact near the wall)",
            ),
        ],
    },
    Enumeration {
        name: "DriveMode",
        items: &[
            ("speed", "crank speed prescribed"),
            ("torque", "crank torque prescribed"),
        ],
    },
    Enumeration {
        name: "RodBoundary",
        items: &[
            (
                "pins",
                "the two pin positions; pinned-pinned modes span the end slopes",
            ),
            (
                "positionsAndSlopes",
                "positions and slopes of both end nodes (Sun et al. 2015); clamped-clamped modes",
            ),
        ],
    },
    Enumeration {
        name: "RodInitialState",
        items: &[
            (
                "equilibrated",
                "deformed by the inertial loads of the initial motion (no start-up ringing)",
            ),
            ("straight", "straight and unstressed (the reference start)"),
        ],
    },
    Enumeration {
        name: "IntegrationMethod",
        items: &[
            (
                "implicit",
                "L-stable ESDIRK5(4) with Newton iterations: steps set by the motion, not by stiffness",
            ),
            (
                "explicit",
                "Dormand-Prince 5(4), the reference method: steps bound by the highest frequency",
            ),
            (
                "generalizedAlpha",
                "generalized-alpha (Chung-Hulbert), 2nd order, numerical dissipation set by solver.spectralRadius",
            ),
        ],
    },
    Enumeration {
        name: "ContactLaw",
        items: &[
            (
                "lankaraniNikravesh",
                "Lankarani-Nikravesh (1990) hysteresis damping, for restitution near 1",
            ),
            (
                "flores",
                "Flores et al. (2011) hysteresis damping, any restitution",
            ),
            (
                "huGuo",
                "Hu and Guo (2015) hysteresis damping, any restitution",
            ),
        ],
    },
    Enumeration {
        name: "JournalStart",
        items: &[
            (
                "centred",
                "centred in the bearing (the benchmarks' start): it crosses the clearance and impacts",
            ),
            (
                "settled",
                "in quasi-static equilibrium with the ideal joint's initial reaction, at rest in the bearing: no start-up impact",
            ),
        ],
    },
    Enumeration {
        name: "RodQuadrature",
        items: &[
            (
                "full",
                "every quadrature point of the mesh the rod was reduced from",
            ),
            (
                "sampled",
                "a few weighted points fitted at initialization (energy-conserving sampling and weighting): cost independent of rod.nElements",
            ),
        ],
    },
    Enumeration {
        name: "ContactGeometry",
        items: &[
            (
                "point",
                "Hertz point contact, K penetration^1.5 (the benchmarks' law)",
            ),
            (
                "cylinder",
                "Johnson's line contact of the pin along bearingLength: a long pin sinks much less",
            ),
        ],
    },
    Enumeration {
        name: "FilmModel",
        items: &[
            (
                "short",
                "Ocvirk's infinitely short bearing (the benchmarks' film): the limit L/D -> 0, which overestimates the load a bearing of L/D 0.3-1 carries",
            ),
            (
                "finite",
                "the finite bearing: Reynolds equation over the bearing length with the Reynolds cavitation condition (Raimondi and Boyd), tabulated for L/D up to 4",
            ),
        ],
    },
    Enumeration {
        name: "ThermalModel",
        items: &[
            ("isoviscous", "the joint's viscosity, constant"),
            (
                "heatBalance",
                "the oil's viscosity at the film's effective temperature, a state of the joint's heat balance (friction power in; the oil flow and the housing carry it out)",
            ),
        ],
    },
    Enumeration {
        name: "ThermalStart",
        items: &[
            (
                "supply",
                "the film starts at oil.supplyTemperature: the bearing warms up",
            ),
            (
                "settled",
                "the film starts in the steady heat balance of the start's load and speed: the bearing at its operating temperature",
            ),
        ],
    },
    Enumeration {
        name: "Feed",
        items: &[
            ("none", "no feed: the film's side flow alone"),
            (
                "hole",
                "a lubrication hole of feedDiameter at mid-length, at feedPosition",
            ),
            (
                "circumferentialGroove",
                "a groove of width feedDiameter all around at mid-length: two lands of (bearingLength - feedDiameter)/2 carry the film",
            ),
            (
                "axialGroove",
                "a groove feedDiameter wide and feedGrooveLength of the bearing long, centred on the length, at feedPosition",
            ),
        ],
    },
    Enumeration {
        name: "FeedLocation",
        items: &[
            (
                "shell",
                "in the bearing's shell: the feed stays with the bearing's body",
            ),
            (
                "journal",
                "in the journal (a drilling through the crankshaft): the feed turns with the journal",
            ),
        ],
    },
];

#[cfg(test)]
mod tests {
    use super::*;

    /// Each named index points to the type of its name.
    #[test]
    fn every_index_names_its_type() {
        let named = [
            (ROD_FORMULATION, "RodFormulation"),
            (JOINT_MODEL, "JointModel"),
            (DRIVE_MODE, "DriveMode"),
            (ROD_BOUNDARY, "RodBoundary"),
            (ROD_INITIAL_STATE, "RodInitialState"),
            (INTEGRATION_METHOD, "IntegrationMethod"),
            (CONTACT_LAW, "ContactLaw"),
            (JOURNAL_START, "JournalStart"),
            (ROD_QUADRATURE, "RodQuadrature"),
            (CONTACT_GEOMETRY, "ContactGeometry"),
            (FILM_MODEL, "FilmModel"),
            (THERMAL_MODEL, "ThermalModel"),
            (THERMAL_START, "ThermalStart"),
            (FEED, "Feed"),
            (FEED_LOCATION, "FeedLocation"),
        ];
        assert_eq!(named.len(), ENUMERATIONS.len());
        for (index, name) in named {
            assert_eq!(ENUMERATIONS[index].name, name);
        }
    }
}
