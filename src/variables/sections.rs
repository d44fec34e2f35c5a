//! The FMI 3 additions of the FMU: the rod's section results as arrays along it, their number a
//! structural parameter (FMI 2 has neither; its variables are the table's alone), and the
//! terminals a system editor connects: the crank's flange and the slider's.
//!
//! The sections are evenly spaced from the crank pin (k = 0) to the slider pin (k = N − 1), at
//! s_k = k L/(N − 1) along the rod's reference length L.

use fmi_core::interface::{ArrayVariable, Fmi3Interface, StructuralParameter, Terminal};
use fmi_core::table::Causality;

/// Value reference of `rod.nSections`, the first after the independent variable `time`'s.
pub const N_SECTIONS: u32 = 1_000_001;

/// The arrays, in the order of [`FMI3`]'s arrays.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SectionArray {
    /// `rod.section.position`.
    Position,
    /// `rod.section.deflection`.
    Deflection,
    /// `rod.section.axialForce`.
    AxialForce,
    /// `rod.section.bendingMoment`.
    BendingMoment,
}

impl SectionArray {
    /// All, in table order.
    pub const ALL: [Self; 4] = [
        Self::Position,
        Self::Deflection,
        Self::AxialForce,
        Self::BendingMoment,
    ];
}

/// The structural parameter that sizes the arrays.
pub const STRUCTURAL_PARAMETERS: &[StructuralParameter] = &[StructuralParameter {
    vr: N_SECTIONS,
    name: "rod.nSections",
    description: "Number of evenly spaced rod sections, crank pin to slider pin, at which the rod's section arrays (position, deflection, axial force, bending moment) are given; set in Configuration Mode",
    start: 11,
    min: 2,
    max: 1001,
}];

/// One output array along the rod.
const fn output(
    vr: u32,
    name: &'static str,
    unit: &'static str,
    description: &'static str,
) -> ArrayVariable {
    ArrayVariable {
        vr,
        name,
        description,
        causality: Causality::Output,
        unit,
        dimension: 0,
    }
}

/// The arrays, in [`SectionArray`] order.
pub const SECTION_ARRAYS: &[ArrayVariable] = &[
    ArrayVariable {
        vr: N_SECTIONS + 1,
        name: "rod.section.position",
        description: "Arc length of each section from the crank pin, along the rod's reference length",
        causality: Causality::CalculatedParameter,
        unit: "m",
        dimension: 0,
    },
    output(
        N_SECTIONS + 2,
        "rod.section.deflection",
        "m",
        "Deflection of each section from the chord between the rod's ends, left positive (0 for the rigid rod)",
    ),
    output(
        N_SECTIONS + 3,
        "rod.section.axialForce",
        "N",
        "Axial force at each section, tension positive",
    ),
    output(
        N_SECTIONS + 4,
        "rod.section.bendingMoment",
        "N.m",
        "Bending moment at each section, positive where the rod bends to its left (counter-clockwise curvature, looking along the rod from the crank pin)",
    ),
];

/// FMI 3 additions: with the master's consent a step returns early at the end of the internal
/// step in which a joint comes into contact, and with event mode that onset is an event (the
/// joints' inContact flags and onset counters change there); with intermediate update the
/// master reads the outputs after every internal step (and may end the step there); the rod's
/// section results are arrays.
pub const FMI3: Fmi3Interface = Fmi3Interface {
    might_return_early: true,
    has_event_mode: true,
    provides_intermediate_update: true,
    can_return_early_after_intermediate_update: true,
    structural_parameters: STRUCTURAL_PARAMETERS,
    arrays: SECTION_ARRAYS,
    terminals: &[
        Terminal {
            name: "crankFlange",
            kind: "rotationalFlange",
            description: "The crank as a shaft end: its angle and speed out, the drive torque in (drive.mode = torque); a motor's shaft terminal (w in, tau out) connects to it",
            members: &[
                ("phi", "crank.angle"),
                ("w", "crank.speed"),
                ("tau", "drive.torque"),
            ],
        },
        Terminal {
            name: "sliderFlange",
            kind: "translationalFlange",
            description: "The slider: its position and velocity out, the external force along the guide in",
            members: &[
                ("s", "slider.position"),
                ("v", "slider.velocity"),
                ("f", "slider.force"),
            ],
        },
    ],
    input_derivatives: true,
};
