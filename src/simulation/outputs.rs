//! The outputs a system engineer plots, computed from a state.

use super::cycle::Extreme;
use super::peaks::PeakHold;
use crate::error::ModelError;
use crate::joint::{JointRole, film_thickness};
use crate::mechanism::layout::CRANK_ANGLE;
use crate::mechanism::{Conditions, SliderCrank};

/// Everything a system engineer plots, at the current time (SI units).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Outputs {
    /// Time \[s\].
    pub time: f64,
    /// Crank angle θ \[rad\].
    pub crank_angle: f64,
    /// Crank speed θ̇ \[rad/s\].
    pub crank_speed: f64,
    /// Crank angular acceleration θ̈ \[rad/s²\].
    pub crank_acceleration: f64,
    /// Torque applied by the drive to the crank, CCW positive \[N m\].
    pub crank_torque: f64,
    /// Slider abscissa x_s \[m\].
    pub slider_position: f64,
    /// Slider velocity \[m/s\].
    pub slider_velocity: f64,
    /// Slider acceleration \[m/s²\].
    pub slider_acceleration: f64,
    /// The total external force on the slider along the guide: the input and the load table at
    /// the crank angle \[N\].
    pub slider_applied_force: f64,
    /// Joint force on the journal, x \[N\].
    pub joint_force_x: f64,
    /// Joint force on the journal, y \[N\].
    pub joint_force_y: f64,
    /// Magnitude of the joint force \[N\].
    pub joint_force: f64,
    /// Eccentricity e = journal centre − bearing centre, x \[m\].
    pub eccentricity_x: f64,
    /// Eccentricity, y \[m\].
    pub eccentricity_y: f64,
    /// Rate of the eccentricity ė, x \[m/s\].
    pub eccentricity_rate_x: f64,
    /// Rate of the eccentricity, y \[m/s\].
    pub eccentricity_rate_y: f64,
    /// Penetration max(|e| − c, 0) \[m\].
    pub penetration: f64,
    /// Whether journal and bearing touch.
    pub in_contact: bool,
    /// The crank pin's eccentricity e = crank pin centre − rod eye centre, x \[m\] (0 for the
    /// ideal crank pin).
    pub crank_pin_eccentricity_x: f64,
    /// The crank pin's eccentricity, y \[m\].
    pub crank_pin_eccentricity_y: f64,
    /// The crank pin's penetration max(|e| − c, 0) \[m\].
    pub crank_pin_penetration: f64,
    /// Whether the crank pin touches the rod's eye.
    pub crank_pin_in_contact: bool,
    /// The main bearing's eccentricity e = crank pivot centre − bearing centre, x \[m\] (0 for
    /// the ideal main bearing).
    pub main_bearing_eccentricity_x: f64,
    /// The main bearing's eccentricity, y \[m\].
    pub main_bearing_eccentricity_y: f64,
    /// The main bearing's penetration max(|e| − c, 0) \[m\].
    pub main_bearing_penetration: f64,
    /// Whether the crank's pivot touches the main bearing.
    pub main_bearing_in_contact: bool,
    /// Rod mid-span deflection relative to the chord, left positive \[m\].
    pub midspan_deflection: f64,
    /// Rod strain (deformation) energy \[J\].
    pub deformation_energy: f64,
    /// Kinetic energy of crank, rod and slider \[J\].
    pub kinetic_energy: f64,
    /// Work done by the drive since the start \[J\].
    pub drive_work: f64,
    /// Energy dissipated in the joint since the start \[J\].
    pub dissipated_energy: f64,
    /// Elastic energy stored in the contact, K δ^2.5 / 2.5 \[J\].
    pub contact_energy: f64,
    /// Gravitational potential energy (zero at y = 0) \[J\].
    pub gravity_energy: f64,
    /// Work done by the external slider force since the start \[J\].
    pub slider_work: f64,
    /// Energy dissipated by the rod's material damping since the start \[J\].
    pub material_damping: f64,
    /// Constraint drift ‖Φ‖.
    pub constraint_drift: f64,
    /// Largest |joint force| over the last communication interval \[N\] ([`super::PeakHold`]).
    pub joint_force_peak: f64,
    /// Largest |slider acceleration| over the last communication interval \[m/s²\].
    pub slider_acceleration_peak: f64,
    /// Largest rod deformation energy over the last communication interval \[J\].
    pub deformation_energy_peak: f64,
    /// Force of the crank on the rod at the crank pin, x \[N\].
    pub crank_pin_force_x: f64,
    /// Force of the crank on the rod at the crank pin, y \[N\].
    pub crank_pin_force_y: f64,
    /// Magnitude of the crank-pin force \[N\].
    pub crank_pin_force: f64,
    /// Largest crank-pin force over the last communication interval \[N\].
    pub crank_pin_force_peak: f64,
    /// Force of the ground on the crank at the main bearing, x \[N\].
    pub main_bearing_force_x: f64,
    /// Force of the ground on the crank at the main bearing, y \[N\].
    pub main_bearing_force_y: f64,
    /// Magnitude of the main-bearing force \[N\].
    pub main_bearing_force: f64,
    /// Largest main-bearing force over the last communication interval \[N\].
    pub main_bearing_force_peak: f64,
    /// Normal force of the guide on the slider, along y \[N\].
    pub guide_force: f64,
    /// Largest |guide force| over the last communication interval \[N\].
    pub guide_force_peak: f64,
    /// Largest normal stress magnitude over the rod \[Pa\].
    pub rod_stress: f64,
    /// Largest rod stress over the last communication interval \[Pa\].
    pub rod_stress_peak: f64,
    /// The most tensile fibre stress over the rod, max (N/A + |M| c/I) \[Pa\] (signed).
    pub rod_stress_max: f64,
    /// The most compressive fibre stress over the rod, min (N/A − |M| c/I) \[Pa\] (signed).
    pub rod_stress_min: f64,
    /// The largest `rod_stress_max` over the last communication interval \[Pa\].
    pub rod_stress_max_peak: f64,
    /// The smallest `rod_stress_min` over the last communication interval \[Pa\].
    pub rod_stress_min_peak: f64,
    /// Where the largest stress magnitude lies, a fraction of the rod's length from the crank
    /// pin.
    pub rod_stress_location: f64,
    /// The rod's axial force at mid-span, tension positive \[N\].
    pub rod_axial_force_midspan: f64,
    /// The rod's bending moment at mid-span, positive where it turns left \[N m\].
    pub rod_bending_moment_midspan: f64,
    /// The rod's axial force at the crank pin, tension positive \[N\].
    pub rod_axial_force_crank_pin: f64,
    /// The rod's axial force at the slider pin, tension positive \[N\].
    pub rod_axial_force_slider_pin: f64,
    /// Contact onsets in the last communication interval.
    pub contact_onsets: u64,
    /// Contact onsets since the start.
    pub contact_onsets_total: u64,
    /// Contact onsets at the crank pin in the last communication interval.
    pub crank_pin_contact_onsets: u64,
    /// Contact onsets at the crank pin since the start.
    pub crank_pin_contact_onsets_total: u64,
    /// Contact onsets at the main bearing in the last communication interval.
    pub main_bearing_contact_onsets: u64,
    /// Contact onsets at the main bearing since the start.
    pub main_bearing_contact_onsets_total: u64,
    /// Warnings raised since the start ([`super::Engine::take_warnings`]).
    pub warnings: u64,
    /// Load cycles completed: the number of the cycle the cycle results describe (0 while the
    /// first is under way, whose results they show so far).
    pub cycle_number: u64,
    /// What a bearing designer reads at each joint, by [`JointRole`].
    pub bearings: [BearingOutputs; 3],
}

/// A joint as its designer reads it (SI units): all zeros for an ideal joint, which has no
/// clearance.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BearingOutputs {
    /// The eccentricity ratio ε = |e|/c (the actual one: above 1 in metal contact).
    pub eccentricity_ratio: f64,
    /// The minimum gap c (1 − ε), 0 in metal contact \[m\].
    pub film_thickness: f64,
    /// Its smallest value over the last communication interval \[m\] ([`super::PeakHold`]).
    pub film_thickness_min: f64,
    /// Its smallest value since the start \[m\].
    pub film_thickness_min_since_start: f64,
    /// The largest film pressure (at mid-length) over the last communication interval \[Pa\].
    pub film_pressure_peak: f64,
    /// The largest film pressure since the start \[Pa\].
    pub film_pressure_peak_since_start: f64,
    /// The friction moment on the journal (dry friction, film shear) \[N m\].
    pub friction_torque: f64,
    /// The rate at which the joint's friction dissipates energy, ≥ 0 \[W\].
    pub friction_power: f64,
    /// The rate at which the dry contact's hysteresis damping dissipates energy, ≥ 0 \[W\]:
    /// with [`BearingOutputs::friction_power`], the rate of [`BearingOutputs::energy_dissipated`].
    pub hysteresis_power: f64,
    /// The energy the joint has dissipated since the start \[J\].
    pub energy_dissipated: f64,
    /// The oil flow through the bearing: out of both ends of the pressurised film, and the
    /// feed's \[m³/s\].
    pub oil_flow: f64,
    /// The flow the supply pressure drives from the feed \[m³/s\].
    pub feed_flow: f64,
    /// The smallest film thickness over the last complete load cycle \[m\]
    /// ([`super::CycleHold`]).
    pub film_thickness_min_cycle: f64,
    /// The crank angle within the cycle where it occurred \[deg\].
    pub film_thickness_min_cycle_angle: f64,
    /// The largest film pressure over the last complete load cycle \[Pa\].
    pub film_pressure_peak_cycle: f64,
    /// The crank angle within the cycle where it occurred \[deg\].
    pub film_pressure_peak_cycle_angle: f64,
    /// The largest force over the last complete load cycle \[N\].
    pub force_peak_cycle: f64,
    /// The crank angle within the cycle where it occurred \[deg\].
    pub force_peak_cycle_angle: f64,
    /// The mean friction power over the last complete load cycle \[W\].
    pub friction_power_mean_cycle: f64,
    /// The mean oil flow over the last complete load cycle \[m³/s\].
    pub oil_flow_mean_cycle: f64,
    /// The asperities' normal force \[N\].
    pub asperity_force: f64,
    /// The largest asperity pressure \[Pa\].
    pub asperity_pressure_peak: f64,
    /// The asperities' boundary friction power \[W\].
    pub asperity_friction_power: f64,
    /// The film ratio h_min/σ (0 for smooth surfaces and in metal contact).
    pub film_ratio: f64,
    /// The largest asperity force over the last complete load cycle \[N\].
    pub asperity_force_peak_cycle: f64,
    /// The fraction of the last complete load cycle's duration in dry contact.
    pub metal_contact_fraction_cycle: f64,
    /// The effective film temperature, 0 without a heat balance \[K\].
    pub film_temperature: f64,
    /// The oil's viscosity in the film, 0 without a film \[Pa s\].
    pub viscosity_effective: f64,
    /// The heat the oil flow carries away, 0 without a heat balance \[W\].
    pub heat_flow: f64,
    /// The largest film temperature over the last complete load cycle \[K\].
    pub film_temperature_max_cycle: f64,
}

impl Outputs {
    /// The energy account from the outputs alone, energy.kinetic + rod.deformationEnergy +
    /// energy.contact + energy.gravity + energy.dissipated + energy.materialDamping −
    /// energy.driveWork − energy.sliderWork \[J\]: constant in exact arithmetic (docs/design.md,
    /// "Energy account").
    pub fn energy_balance(&self) -> f64 {
        self.kinetic_energy
            + self.deformation_energy
            + self.contact_energy
            + self.gravity_energy
            + self.dissipated_energy
            + self.material_damping
            - self.drive_work
            - self.slider_work
    }
}

/// The outputs of state `y` at `time` under the conditions `c` (one right-hand-side evaluation
/// into `scratch`, no allocation), with the peak-hold values of `peaks` and the `warnings` count.
pub(super) fn outputs(
    mechanism: &mut SliderCrank,
    c: &Conditions,
    (time, y): (f64, &[f64]),
    scratch: &mut [f64],
    peaks: &PeakHold,
    warnings: u64,
) -> Result<Outputs, ModelError> {
    let ev = *mechanism.evaluate(y, c, scratch)?;
    let loads = mechanism.loads(y, scratch, ev.joint_force, c.contacts);
    let l = mechanism.layout();
    let kin = mechanism.joint_kinematics(JointRole::RodSlider, y);
    let penetration = mechanism.penetration(JointRole::RodSlider, y);
    let clearance = |role| {
        let e = if mechanism.has_clearance(role) {
            mechanism.joint_kinematics(role, y).e
        } else {
            nalgebra::Vector2::zeros()
        };
        (e, mechanism.penetration(role, y))
    };
    let (crank_pin, crank_pin_penetration) = clearance(JointRole::CrankPin);
    let (main_bearing, main_bearing_penetration) = clearance(JointRole::MainBearing);
    let energies = mechanism.energies_with_strain(y, c.contacts, loads.deformation_energy);
    let forces = [
        loads.main_bearing.norm(),
        loads.crank_pin.norm(),
        ev.joint_force.norm(),
    ];
    let cycles = &peaks.cycles;
    let cycle = cycles.reported();
    // an extreme not yet seen (no step taken) is the value now
    let extreme = |e: Extreme, now: f64, angle: f64| match e.value.is_finite() {
        true => (e.value, cycles.within(e.angle).to_degrees()),
        false => (now, cycles.within(angle).to_degrees()),
    };
    let bearings = JointRole::ALL.map(|role| {
        let i = role as usize;
        let joint = &cycle.joints[i];
        let (force_peak_cycle, force_peak_cycle_angle) =
            extreme(joint.force, forces[i], y[CRANK_ANGLE]);
        let Some(clearance) = mechanism.joint(role).dry_contact().map(|dry| dry.clearance) else {
            return BearingOutputs {
                force_peak_cycle,
                force_peak_cycle_angle,
                ..BearingOutputs::default()
            };
        };
        let now = mechanism.bearing_state(role, y, c.contacts, c.inputs.oil_supply_pressure);
        let (film_temperature, heat_flow) = match (
            mechanism.film_temperature(role, y),
            mechanism.joint(role).heat_balance(),
        ) {
            (Some(t), Some(balance)) => (
                t,
                balance.heat_to_oil(now.oil_flow, t, c.inputs.oil_supply_temperature),
            ),
            _ => (0.0, 0.0),
        };
        let (interval, since_start) = (&peaks.interval, &peaks.since_start);
        let ratio = interval.eccentricity_ratio[i].max(now.eccentricity_ratio);
        let pressure = interval.film_pressure[i].max(now.film_pressure);
        let (ratio_cycle, film_thickness_min_cycle_angle) = extreme(
            joint.eccentricity_ratio,
            now.eccentricity_ratio,
            y[CRANK_ANGLE],
        );
        let (film_pressure_peak_cycle, film_pressure_peak_cycle_angle) =
            extreme(joint.film_pressure, now.film_pressure, y[CRANK_ANGLE]);
        BearingOutputs {
            eccentricity_ratio: now.eccentricity_ratio,
            film_thickness: now.film_thickness,
            film_thickness_min: film_thickness(clearance, ratio),
            film_thickness_min_since_start: film_thickness(
                clearance,
                since_start.eccentricity_ratio[i].max(ratio),
            ),
            film_pressure_peak: pressure,
            film_pressure_peak_since_start: since_start.film_pressure[i].max(pressure),
            friction_torque: now.friction_torque,
            friction_power: now.friction_power,
            hysteresis_power: now.hysteresis_power,
            energy_dissipated: energies.joints[i].dissipated(),
            oil_flow: now.oil_flow,
            feed_flow: now.feed_flow,
            film_thickness_min_cycle: film_thickness(clearance, ratio_cycle),
            film_thickness_min_cycle_angle,
            film_pressure_peak_cycle,
            film_pressure_peak_cycle_angle,
            force_peak_cycle,
            force_peak_cycle_angle,
            friction_power_mean_cycle: cycle.mean(joint.friction_energy),
            oil_flow_mean_cycle: cycle.mean(joint.oil_volume),
            asperity_force: now.asperity_force,
            asperity_pressure_peak: now.asperity_pressure_peak,
            asperity_friction_power: now.asperity_friction_power,
            film_ratio: now.film_ratio,
            asperity_force_peak_cycle: extreme(
                joint.asperity_force,
                now.asperity_force,
                y[CRANK_ANGLE],
            )
            .0,
            metal_contact_fraction_cycle: cycle.mean(joint.metal_contact_time),
            film_temperature,
            viscosity_effective: now.viscosity,
            heat_flow,
            film_temperature_max_cycle: extreme(
                joint.film_temperature,
                film_temperature,
                y[CRANK_ANGLE],
            )
            .0,
        }
    });
    Ok(Outputs {
        time,
        crank_angle: y[CRANK_ANGLE],
        crank_speed: y[l.crank_speed()],
        crank_acceleration: scratch[l.crank_speed()],
        crank_torque: ev.crank_torque,
        slider_position: y[l.slider()],
        slider_velocity: y[l.slider_velocity()],
        slider_acceleration: ev.slider_acceleration,
        slider_applied_force: mechanism.slider_force(&c.inputs, y[CRANK_ANGLE]),
        joint_force_x: ev.joint_force.x,
        joint_force_y: ev.joint_force.y,
        joint_force: ev.joint_force.norm(),
        eccentricity_x: kin.e.x,
        eccentricity_y: kin.e.y,
        eccentricity_rate_x: kin.e_dot.x,
        eccentricity_rate_y: kin.e_dot.y,
        penetration: penetration.max(0.0),
        in_contact: penetration > 0.0,
        crank_pin_eccentricity_x: crank_pin.x,
        crank_pin_eccentricity_y: crank_pin.y,
        crank_pin_penetration: crank_pin_penetration.max(0.0),
        crank_pin_in_contact: crank_pin_penetration > 0.0,
        main_bearing_eccentricity_x: main_bearing.x,
        main_bearing_eccentricity_y: main_bearing.y,
        main_bearing_penetration: main_bearing_penetration.max(0.0),
        main_bearing_in_contact: main_bearing_penetration > 0.0,
        midspan_deflection: mechanism.midspan_deflection(y),
        deformation_energy: energies.strain,
        kinetic_energy: energies.kinetic,
        drive_work: energies.drive_work,
        dissipated_energy: energies.dissipated(),
        contact_energy: energies.contact,
        gravity_energy: energies.gravity,
        slider_work: energies.external_work,
        material_damping: energies.material_damping,
        constraint_drift: ev.drift,
        joint_force_peak: peaks.interval.joint_force.max(ev.joint_force.norm()),
        slider_acceleration_peak: peaks
            .interval
            .slider_acceleration
            .max(ev.slider_acceleration.abs()),
        deformation_energy_peak: peaks.interval.deformation_energy.max(energies.strain),
        crank_pin_force_x: loads.crank_pin.x,
        crank_pin_force_y: loads.crank_pin.y,
        crank_pin_force: loads.crank_pin.norm(),
        crank_pin_force_peak: peaks.interval.crank_pin_force.max(loads.crank_pin.norm()),
        main_bearing_force_x: loads.main_bearing.x,
        main_bearing_force_y: loads.main_bearing.y,
        main_bearing_force: loads.main_bearing.norm(),
        main_bearing_force_peak: peaks
            .interval
            .main_bearing_force
            .max(loads.main_bearing.norm()),
        guide_force: loads.guide,
        guide_force_peak: peaks.interval.guide_force.max(loads.guide.abs()),
        rod_stress: loads.stress.largest,
        rod_stress_peak: peaks.interval.rod_stress.max(loads.stress.largest),
        rod_stress_max: loads.stress.max,
        rod_stress_min: loads.stress.min,
        rod_stress_max_peak: peaks.interval.rod_tension.max(loads.stress.max),
        rod_stress_min_peak: (-peaks.interval.rod_compression).min(loads.stress.min),
        rod_stress_location: loads.stress.location,
        rod_axial_force_midspan: loads.stress.midspan_axial_force,
        rod_bending_moment_midspan: loads.stress.midspan_moment,
        rod_axial_force_crank_pin: loads.axial[0],
        rod_axial_force_slider_pin: loads.axial[1],
        contact_onsets: peaks.interval.contact_onsets[JointRole::RodSlider as usize],
        contact_onsets_total: peaks.total_onsets[JointRole::RodSlider as usize],
        crank_pin_contact_onsets: peaks.interval.contact_onsets[JointRole::CrankPin as usize],
        crank_pin_contact_onsets_total: peaks.total_onsets[JointRole::CrankPin as usize],
        main_bearing_contact_onsets: peaks.interval.contact_onsets[JointRole::MainBearing as usize],
        main_bearing_contact_onsets_total: peaks.total_onsets[JointRole::MainBearing as usize],
        warnings,
        cycle_number: peaks.cycles.completed,
        bearings,
    })
}
