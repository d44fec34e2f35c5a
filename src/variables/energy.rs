//! The energy account: every term of the mechanism's energy balance.

use super::vr::{Variable, Vr};

/// The energy account's rows.
pub(super) const VARIABLES: &[Variable] = &[
    Variable::output(
        Vr::EnergyKinetic,
        "energy.kinetic",
        "J",
        "Kinetic energy of crank, rod and slider",
    ),
    Variable::output(
        Vr::EnergyDriveWork,
        "energy.driveWork",
        "J",
        "Work done by the drive",
    ),
    Variable::output(
        Vr::EnergyDissipated,
        "energy.dissipated",
        "J",
        "Energy dissipated in the joints: the sum of joint, crankPin and mainBearing.energyDissipated",
    ),
    Variable::output(
        Vr::EnergyContact,
        "energy.contact",
        "J",
        "Elastic energy stored in the joints' contacts (K penetration^2.5 / 2.5 for the point contact; the integral of the line contact's force)",
    ),
    Variable::output(
        Vr::EnergyGravity,
        "energy.gravity",
        "J",
        "Gravitational potential energy of crank, rod and slider (zero at y = 0)",
    ),
    Variable::output(
        Vr::EnergySliderWork,
        "energy.sliderWork",
        "J",
        "Work done on the slider by its external force, slider.appliedForce (the input slider.force and slider.forceTable)",
    ),
    Variable::output(
        Vr::EnergyMaterialDamping,
        "energy.materialDamping",
        "J",
        "Energy dissipated in the rod by its material damping (rod.dampingRatio or rod.stiffnessDamping)",
    ),
];
