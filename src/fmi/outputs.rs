//! The Real and the count outputs of the FMU by value reference: the lists that map each output
//! row of the variable table to its field of [`Outputs`].

use crate::simulation::Outputs;
use crate::variables::Vr;

/// The value of a Real output, None for other variables.
pub fn real_output(o: &Outputs, vr: Vr) -> Option<f64> {
    Some(match vr {
        Vr::CrankAngle => o.crank_angle,
        Vr::CrankSpeed => o.crank_speed,
        Vr::CrankTorque => o.crank_torque,
        Vr::SliderPosition => o.slider_position,
        Vr::SliderVelocity => o.slider_velocity,
        Vr::SliderAcceleration => o.slider_acceleration,
        Vr::JointForce => o.joint_force,
        Vr::JointForceX => o.joint_force_x,
        Vr::JointForceY => o.joint_force_y,
        Vr::JointEccentricityX => o.eccentricity_x,
        Vr::JointEccentricityY => o.eccentricity_y,
        Vr::JointPenetration => o.penetration,
        Vr::CrankPinEccentricityX => o.crank_pin_eccentricity_x,
        Vr::CrankPinEccentricityY => o.crank_pin_eccentricity_y,
        Vr::CrankPinPenetration => o.crank_pin_penetration,
        Vr::MainBearingEccentricityX => o.main_bearing_eccentricity_x,
        Vr::MainBearingEccentricityY => o.main_bearing_eccentricity_y,
        Vr::MainBearingPenetration => o.main_bearing_penetration,
        Vr::RodMidspanDeflection => o.midspan_deflection,
        Vr::RodDeformationEnergy => o.deformation_energy,
        Vr::EnergyKinetic => o.kinetic_energy,
        Vr::EnergyDriveWork => o.drive_work,
        Vr::EnergyDissipated => o.dissipated_energy,
        Vr::JointForcePeak => o.joint_force_peak,
        Vr::EnergyContact => o.contact_energy,
        Vr::EnergyGravity => o.gravity_energy,
        Vr::EnergySliderWork => o.slider_work,
        Vr::EnergyMaterialDamping => o.material_damping,
        Vr::SliderAccelerationPeak => o.slider_acceleration_peak,
        Vr::RodDeformationEnergyPeak => o.deformation_energy_peak,
        Vr::CrankPinForce => o.crank_pin_force,
        Vr::CrankPinForceX => o.crank_pin_force_x,
        Vr::CrankPinForceY => o.crank_pin_force_y,
        Vr::CrankPinForcePeak => o.crank_pin_force_peak,
        Vr::MainBearingForce => o.main_bearing_force,
        Vr::MainBearingForceX => o.main_bearing_force_x,
        Vr::MainBearingForceY => o.main_bearing_force_y,
        Vr::MainBearingForcePeak => o.main_bearing_force_peak,
        Vr::GuideForce => o.guide_force,
        Vr::GuideForcePeak => o.guide_force_peak,
        Vr::RodStress => o.rod_stress,
        Vr::RodStressPeak => o.rod_stress_peak,
        Vr::RodAxialForceCrankPin => o.rod_axial_force_crank_pin,
        Vr::RodAxialForceSliderPin => o.rod_axial_force_slider_pin,
        _ => return None,
    })
}

/// The value of a count output (an Integer computed from the outputs), None for other variables.
pub fn count_output(o: &Outputs, vr: Vr) -> Option<u64> {
    Some(match vr {
        Vr::JointContactOnsets => o.contact_onsets,
        Vr::JointContactOnsetsTotal => o.contact_onsets_total,
        Vr::CrankPinContactOnsets => o.crank_pin_contact_onsets,
        Vr::CrankPinContactOnsetsTotal => o.crank_pin_contact_onsets_total,
        Vr::MainBearingContactOnsets => o.main_bearing_contact_onsets,
        Vr::MainBearingContactOnsetsTotal => o.main_bearing_contact_onsets_total,
        Vr::SolverWarnings => o.warnings,
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::variables::{Causality, Kind, VARIABLES};

    /// Exactly the Real outputs of the table have a value, and exactly the Integer outputs other
    /// than the integrator's statistics (read from the simulation) a count.
    #[test]
    fn every_real_and_count_output_and_nothing_else_has_a_value() {
        let o = Outputs::default();
        for v in VARIABLES {
            let output = v.causality == Causality::Output;
            let real = output && matches!(v.kind, Kind::Real { .. });
            let statistic = matches!(v.vr, Vr::SolverSteps | Vr::SolverEvaluations);
            let count = output && matches!(v.kind, Kind::Integer { .. }) && !statistic;
            assert_eq!(real_output(&o, v.vr).is_some(), real, "{}", v.name);
            assert_eq!(count_output(&o, v.vr).is_some(), count, "{}", v.name);
        }
    }
}
