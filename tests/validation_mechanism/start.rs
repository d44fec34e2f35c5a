//! Starts that do not pollute the peaks: the crank at the prescribed speed, and a journal settled
//! against its load instead of crossing the clearance.

use super::*;
use flexible_slider_crank::Inputs;
use flexible_slider_crank::params::JournalStart;

/// A small compressor (crank 20 mm, rod 80 mm, 0.1 mm clearance, 5 mm pin, 1500 rpm) with a
/// constant gas force of 880 N on the slider.
fn compressor(
    rod_formulation: RodFormulation,
    journal_start: JournalStart,
) -> (Parameters, Inputs) {
    let speed = 1500.0 * std::f64::consts::TAU / 60.0;
    let mut p = Parameters {
        joint: JointParameters {
            initial_state: journal_start,
            clearance: 1e-4,
            journal_radius: 5e-3,
            ..Parameters::default().joint
        },
        rod_formulation,
        crank_length: 0.02,
        ..Parameters::default()
    };
    p.rod.length = 0.08;
    let inputs = Inputs {
        drive_speed: speed,
        drive_torque: 0.0,
        slider_force: -880.0,
    };
    (p, inputs)
}

/// Largest joint.forcePeak over (0, 5 ms] and over (40, 80] ms (the second revolution).
fn start_and_steady_peaks(p: Parameters, inputs: Inputs) -> (f64, f64) {
    let mut sim = Simulation::with_inputs(p, inputs).unwrap();
    let (mut start, mut steady) = (0.0f64, 0.0f64);
    for i in 1..=800 {
        let t = f64::from(i) * 1e-4;
        sim.advance_to(t).unwrap();
        let peak = sim.outputs().unwrap().joint_force_peak;
        if i <= 50 {
            start = start.max(peak);
        }
        if i > 400 {
            steady = steady.max(peak);
        }
    }
    (start, steady)
}

/// The compressor with its journal settled against the gas force shows no start-up impact: the
/// largest joint.forcePeak of the first 5 ms is at most 1.5× the largest of the second
/// revolution, for the rigid and the 4-mode rod, where the centred journal's start-up impact is
/// more than 5× it.
#[test]
fn a_settled_journal_starts_without_an_impact() {
    for rod_formulation in [RodFormulation::Rigid, RodFormulation::CraigBampton] {
        let ratio = |journal_start| {
            let (p, inputs) = compressor(rod_formulation, journal_start);
            let (start, steady) = start_and_steady_peaks(p, inputs);
            println!(
                "{rod_formulation:?} rod, {journal_start:?} journal: first 5 ms {start:.0} N, \
                 40-80 ms {steady:.0} N, ratio {:.2}",
                start / steady
            );
            start / steady
        };
        assert!(ratio(JournalStart::Settled) <= 1.5, "{rod_formulation:?}");
        assert!(ratio(JournalStart::Centred) > 5.0, "{rod_formulation:?}");
    }
}

/// The settled journal at t = 0: in contact, carrying the ideal joint's reaction (the joint force
/// equals the one the ideal joint gives the same start within 1 %), at rest in the bearing.
#[test]
fn a_settled_journal_carries_the_ideal_joints_reaction() {
    for rod_formulation in [RodFormulation::Rigid, RodFormulation::CraigBampton] {
        let (p, inputs) = compressor(rod_formulation, JournalStart::Settled);
        let ideal = Parameters {
            joint: JointParameters {
                model: JointModel::Ideal,
                ..p.clone().joint
            },
            ..p.clone()
        };
        let mut settled = Simulation::with_inputs(p, inputs).unwrap();
        let o = settled.outputs().unwrap();
        let reference = Simulation::with_inputs(ideal, inputs)
            .unwrap()
            .outputs()
            .unwrap();
        assert!(o.in_contact && o.penetration > 0.0, "{rod_formulation:?}");
        let difference = ((o.joint_force_x - reference.joint_force_x).powi(2)
            + (o.joint_force_y - reference.joint_force_y).powi(2))
        .sqrt();
        assert!(
            difference < 1e-2 * reference.joint_force,
            "{rod_formulation:?}: {} N vs the ideal joint's {} N",
            o.joint_force,
            reference.joint_force
        );
        let rate = math::hypot(o.eccentricity_rate_x, o.eccentricity_rate_y);
        assert!(rate < 1e-9, "{rod_formulation:?}: ė = {rate} m/s");
    }
}

/// Setting only the prescribed speed starts the crank at it: no jump at the first step (crank
/// speed at the first communication point within 0.1 % of drive.speed) and no warning; with
/// crank.initialSpeed set to another value the crank jumps and the run warns.
#[test]
fn the_crank_starts_at_the_prescribed_speed() {
    let drive_speed = 157.0;
    let inputs = Inputs {
        drive_speed,
        ..Inputs::default()
    };
    let mut sim = Simulation::with_inputs(Parameters::default(), inputs).unwrap();
    sim.advance_to(1e-4).unwrap();
    let o = sim.outputs().unwrap();
    assert!(
        (o.crank_speed - drive_speed).abs() < 1e-3 * drive_speed,
        "{}",
        o.crank_speed
    );
    assert_eq!(o.warnings, 0);
    let mut jump = Simulation::with_inputs(
        Parameters {
            crank_initial_speed: 300.0,
            ..Parameters::default()
        },
        inputs,
    )
    .unwrap();
    jump.advance_to(1e-4).unwrap();
    assert_eq!(jump.outputs().unwrap().warnings, 1);
}
