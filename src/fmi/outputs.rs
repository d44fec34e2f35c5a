//! The Real and the count outputs of the FMU by value reference: the lists that map each output
//! row of the variable table to its field of [`Outputs`].

use fmi_export::FmuError;
use fmi_export::model::{Context, Var};

use crate::simulation::{
    BearingOutputs, Engine, Input, Inputs, Outputs, SectionResult, section_place,
};
use crate::variables::{SectionArray, VARIABLES, Vr};

/// The rod.section array `array` (its index in [`SectionArray::ALL`]) at `value.len()` sections
/// along a rod of reference length `rod_length` \[m\]; the results other than the positions
/// come from the current state of the `engine` at the point and with the inputs of `cx`.
pub fn section_array<'a>(
    array: usize,
    value: &mut [f64],
    rod_length: f64,
    cx: &Context<Inputs>,
    engine: impl FnOnce() -> Result<&'a mut Engine, FmuError>,
) -> Result<(), FmuError> {
    let result = match SectionArray::ALL.get(array) {
        Some(SectionArray::Position) => {
            let n = value.len();
            for (k, v) in value.iter_mut().enumerate() {
                *v = section_place(k, n) * rod_length;
            }
            return Ok(());
        }
        Some(SectionArray::Deflection) => SectionResult::Deflection,
        Some(SectionArray::AxialForce) => SectionResult::AxialForce,
        Some(SectionArray::BendingMoment) => SectionResult::BendingMoment,
        None => return Err(FmuError::Invalid(format!("no array {array}"))),
    };
    Ok(engine()?.rod_sections(cx.time, cx.inputs.reading(), result, value)?)
}

/// Relative size of the input steps of [`sensitivity`].
const INPUT_STEP: f64 = 1e-3;

/// Each peak-hold output of a signed value with the output whose largest (or smallest) value it
/// holds.
const SIGNED_PEAKS: &[(Vr, Vr)] = &[
    (Vr::RodStressMaxPeak, Vr::RodStressMax),
    (Vr::RodStressMinPeak, Vr::RodStressMin),
];

/// Each peak-hold output with the output whose largest |value| it holds.
const PEAKS: &[(Vr, Vr)] = &[
    (Vr::JointForcePeak, Vr::JointForce),
    (Vr::SliderAccelerationPeak, Vr::SliderAcceleration),
    (Vr::RodDeformationEnergyPeak, Vr::RodDeformationEnergy),
    (Vr::CrankPinForcePeak, Vr::CrankPinForce),
    (Vr::MainBearingForcePeak, Vr::MainBearingForce),
    (Vr::GuideForcePeak, Vr::GuideForce),
    (Vr::RodStressPeak, Vr::RodStress),
];

/// ∂y/∂u: the derivatives of the Real outputs `unknowns` with respect to `input` (now at `u`
/// among the master's inputs, `cx`) at the current state, by central differences of the outputs
/// with the input moved by ±h = ±10⁻³ max(1, |u|) and the state held. At a given state the accelerations, torques,
/// constraint forces and their components are affine in the inputs (the equations of motion and
/// the drive constraint are linear in the applied torque, the slider force and the speed
/// drive's velocity error), so their differences are exact up to round-off; a force magnitude
/// |F| has a relative error of order (h ∂F/∂u / |F|)². A peak-hold output max(held, |y|) has the
/// derivative of |y| while the current value sets it and 0 while the held one does (its own
/// differences would average both sides of a kink within ±h); a signed peak-hold (the largest or
/// smallest value) likewise, with the value's derivative itself.
pub fn sensitivity(
    engine: &mut Engine,
    cx: &Context<Inputs>,
    input: Input,
    unknowns: &[Var<Vr>],
    column: &mut [f64],
) -> Result<(), FmuError> {
    let (t, inputs) = (cx.time, cx.inputs.reading());
    let h = INPUT_STEP * inputs.value.get(input).abs().max(1.0);
    let now = engine.outputs(t, inputs)?;
    let plus = engine.outputs_with_input_moved(t, inputs, input, h)?;
    let minus = engine.outputs_with_input_moved(t, inputs, input, -h)?;
    let derivative = |vr: Vr| -> Option<f64> {
        Some((real_output(&plus, vr)? - real_output(&minus, vr)?) / (2.0 * h))
    };
    for (v, c) in unknowns.iter().zip(column.iter_mut()) {
        let held = PEAKS.iter().find(|(peak, _)| *peak == v.vr);
        let signed = SIGNED_PEAKS.iter().find(|(peak, _)| *peak == v.vr);
        let d = match (held, signed) {
            (_, Some(&(peak, value))) => real_output(&now, value).and_then(|y| {
                let set_now = real_output(&now, peak)? == y;
                Some(if set_now { derivative(value)? } else { 0.0 })
            }),
            (Some(&(peak, value)), None) => real_output(&now, value).and_then(|y| {
                let set_now = real_output(&now, peak)? == y.abs();
                // d|y| = sign(y) dy, the mean of both sides (0) at y = 0.
                let sign = if y == 0.0 { 0.0 } else { y.signum() };
                Some(if set_now {
                    sign * derivative(value)?
                } else {
                    0.0
                })
            }),
            (None, None) => derivative(v.vr),
        };
        *c = d.ok_or_else(|| FmuError::Invalid(format!("{} is not a Real output", v.name)))?;
    }
    Ok(())
}

/// The value of a Real output, None for other variables.
pub fn real_output(o: &Outputs, vr: Vr) -> Option<f64> {
    Some(match vr {
        Vr::CrankAngle => o.crank_angle,
        Vr::CrankSpeed => o.crank_speed,
        Vr::CrankTorque => o.crank_torque,
        Vr::SliderPosition => o.slider_position,
        Vr::SliderVelocity => o.slider_velocity,
        Vr::SliderAcceleration => o.slider_acceleration,
        Vr::SliderAppliedForce => o.slider_applied_force,
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
        Vr::RodStressMax => o.rod_stress_max,
        Vr::RodStressMin => o.rod_stress_min,
        Vr::RodStressMaxPeak => o.rod_stress_max_peak,
        Vr::RodStressMinPeak => o.rod_stress_min_peak,
        Vr::RodStressLocation => o.rod_stress_location,
        Vr::RodAxialForceMidspan => o.rod_axial_force_midspan,
        Vr::RodBendingMomentMidspan => o.rod_bending_moment_midspan,
        _ => return bearing_output(o, vr),
    })
}

/// Each joint's bearing-design outputs, by [`JointRole`], in the order of
/// [`bearing_values`].
const BEARING_OUTPUTS: [[Vr; 29]; 3] = [
    [
        Vr::MainBearingEccentricityRatio,
        Vr::MainBearingFilmThickness,
        Vr::MainBearingFilmThicknessMin,
        Vr::MainBearingFilmThicknessMinSinceStart,
        Vr::MainBearingFilmPressurePeak,
        Vr::MainBearingFilmPressurePeakSinceStart,
        Vr::MainBearingFrictionTorque,
        Vr::MainBearingFrictionPower,
        Vr::MainBearingEnergyDissipated,
        Vr::MainBearingOilFlow,
        Vr::MainBearingFilmThicknessMinCycle,
        Vr::MainBearingFilmThicknessMinCycleAngle,
        Vr::MainBearingFilmPressurePeakCycle,
        Vr::MainBearingFilmPressurePeakCycleAngle,
        Vr::MainBearingForcePeakCycle,
        Vr::MainBearingForcePeakCycleAngle,
        Vr::MainBearingFrictionPowerMeanCycle,
        Vr::MainBearingOilFlowMeanCycle,
        Vr::MainBearingAsperityForce,
        Vr::MainBearingAsperityPressurePeak,
        Vr::MainBearingAsperityFrictionPower,
        Vr::MainBearingFilmRatio,
        Vr::MainBearingAsperityForcePeakCycle,
        Vr::MainBearingMetalContactFractionCycle,
        Vr::MainBearingFilmTemperature,
        Vr::MainBearingViscosityEffective,
        Vr::MainBearingHeatFlow,
        Vr::MainBearingFilmTemperatureMaxCycle,
        Vr::MainBearingFeedFlow,
    ],
    [
        Vr::CrankPinEccentricityRatio,
        Vr::CrankPinFilmThickness,
        Vr::CrankPinFilmThicknessMin,
        Vr::CrankPinFilmThicknessMinSinceStart,
        Vr::CrankPinFilmPressurePeak,
        Vr::CrankPinFilmPressurePeakSinceStart,
        Vr::CrankPinFrictionTorque,
        Vr::CrankPinFrictionPower,
        Vr::CrankPinEnergyDissipated,
        Vr::CrankPinOilFlow,
        Vr::CrankPinFilmThicknessMinCycle,
        Vr::CrankPinFilmThicknessMinCycleAngle,
        Vr::CrankPinFilmPressurePeakCycle,
        Vr::CrankPinFilmPressurePeakCycleAngle,
        Vr::CrankPinForcePeakCycle,
        Vr::CrankPinForcePeakCycleAngle,
        Vr::CrankPinFrictionPowerMeanCycle,
        Vr::CrankPinOilFlowMeanCycle,
        Vr::CrankPinAsperityForce,
        Vr::CrankPinAsperityPressurePeak,
        Vr::CrankPinAsperityFrictionPower,
        Vr::CrankPinFilmRatio,
        Vr::CrankPinAsperityForcePeakCycle,
        Vr::CrankPinMetalContactFractionCycle,
        Vr::CrankPinFilmTemperature,
        Vr::CrankPinViscosityEffective,
        Vr::CrankPinHeatFlow,
        Vr::CrankPinFilmTemperatureMaxCycle,
        Vr::CrankPinFeedFlow,
    ],
    [
        Vr::JointEccentricityRatio,
        Vr::JointFilmThickness,
        Vr::JointFilmThicknessMin,
        Vr::JointFilmThicknessMinSinceStart,
        Vr::JointFilmPressurePeak,
        Vr::JointFilmPressurePeakSinceStart,
        Vr::JointFrictionTorque,
        Vr::JointFrictionPower,
        Vr::JointEnergyDissipated,
        Vr::JointOilFlow,
        Vr::JointFilmThicknessMinCycle,
        Vr::JointFilmThicknessMinCycleAngle,
        Vr::JointFilmPressurePeakCycle,
        Vr::JointFilmPressurePeakCycleAngle,
        Vr::JointForcePeakCycle,
        Vr::JointForcePeakCycleAngle,
        Vr::JointFrictionPowerMeanCycle,
        Vr::JointOilFlowMeanCycle,
        Vr::JointAsperityForce,
        Vr::JointAsperityPressurePeak,
        Vr::JointAsperityFrictionPower,
        Vr::JointFilmRatio,
        Vr::JointAsperityForcePeakCycle,
        Vr::JointMetalContactFractionCycle,
        Vr::JointFilmTemperature,
        Vr::JointViscosityEffective,
        Vr::JointHeatFlow,
        Vr::JointFilmTemperatureMaxCycle,
        Vr::JointFeedFlow,
    ],
];

/// A joint's bearing-design outputs in the order of a row of [`BEARING_OUTPUTS`].
fn bearing_values(b: &BearingOutputs) -> [f64; 29] {
    [
        b.eccentricity_ratio,
        b.film_thickness,
        b.film_thickness_min,
        b.film_thickness_min_since_start,
        b.film_pressure_peak,
        b.film_pressure_peak_since_start,
        b.friction_torque,
        b.friction_power,
        b.energy_dissipated,
        b.oil_flow,
        b.film_thickness_min_cycle,
        b.film_thickness_min_cycle_angle,
        b.film_pressure_peak_cycle,
        b.film_pressure_peak_cycle_angle,
        b.force_peak_cycle,
        b.force_peak_cycle_angle,
        b.friction_power_mean_cycle,
        b.oil_flow_mean_cycle,
        b.asperity_force,
        b.asperity_pressure_peak,
        b.asperity_friction_power,
        b.film_ratio,
        b.asperity_force_peak_cycle,
        b.metal_contact_fraction_cycle,
        b.film_temperature,
        b.viscosity_effective,
        b.heat_flow,
        b.film_temperature_max_cycle,
        b.feed_flow,
    ]
}

/// Where each variable's value sits in [`BEARING_OUTPUTS`], by value reference: its joint's row
/// and its place in the row, None for the other variables.
const BEARING_PLACES: [Option<(usize, usize)>; VARIABLES.len()] = {
    let mut places = [None; VARIABLES.len()];
    let mut joint = 0;
    while joint < BEARING_OUTPUTS.len() {
        let mut k = 0;
        while k < BEARING_OUTPUTS[joint].len() {
            places[BEARING_OUTPUTS[joint][k] as usize] = Some((joint, k));
            k += 1;
        }
        joint += 1;
    }
    places
};

/// The value of a joint's bearing-design output, None for other variables.
fn bearing_output(o: &Outputs, vr: Vr) -> Option<f64> {
    let (joint, k) = BEARING_PLACES[vr as usize]?;
    Some(bearing_values(&o.bearings[joint])[k])
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
        Vr::CycleNumber => o.cycle_number,
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
