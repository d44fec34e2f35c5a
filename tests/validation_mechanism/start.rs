//! Starts that do not pollute the peaks: the crank at the prescribed speed, and journals settled
//! against their loads instead of crossing the clearance, at every joint.

use super::*;
use flexible_slider_crank::Inputs;
use flexible_slider_crank::params::JournalStart;

/// A small compressor (crank 20 mm, rod 80 mm, 1500 rpm) with a constant gas force of 880 N on
/// the slider, worn at the joints `worn` (0.1 mm clearance, 5 mm journal, dry) whose journals start
/// at `journal_start`, the others ideal.
fn compressor(worn: &[JointRole], journal_start: JournalStart) -> (Parameters, Inputs) {
    let speed = 1500.0 * std::f64::consts::TAU / 60.0;
    let mut p = Parameters {
        crank_length: 0.02,
        ..Parameters::default()
    };
    p.rod.length = 0.08;
    for role in JointRole::ALL {
        let joint = p.joint_mut(role);
        *joint = JointParameters {
            model: if worn.contains(&role) {
                JointModel::Dry
            } else {
                JointModel::Ideal
            },
            initial_state: journal_start,
            clearance: 1e-4,
            journal_radius: 5e-3,
            ..Parameters::default().joint
        };
    }
    let inputs = Inputs {
        drive_speed: speed,
        slider_force: -880.0,
        ..Inputs::default()
    };
    (p, inputs)
}

/// The load output of the joint `role` in `o`: its force and its peak over the last interval.
fn joint_load(o: &Outputs, role: JointRole) -> (Vector2, f64) {
    match role {
        JointRole::MainBearing => (
            [o.main_bearing_force_x, o.main_bearing_force_y],
            o.main_bearing_force_peak,
        ),
        JointRole::CrankPin => (
            [o.crank_pin_force_x, o.crank_pin_force_y],
            o.crank_pin_force_peak,
        ),
        JointRole::RodSlider => ([o.joint_force_x, o.joint_force_y], o.joint_force_peak),
    }
}

/// A force's components.
type Vector2 = [f64; 2];

/// Largest force peak at the joint `role` over (0, 5 ms] and over (40, 80] ms (the second
/// revolution).
fn start_and_steady_peaks(p: Parameters, inputs: Inputs, role: JointRole) -> (f64, f64) {
    let mut sim = Simulation::with_inputs(p, inputs).unwrap();
    let (mut start, mut steady) = (0.0f64, 0.0f64);
    for i in 1..=800 {
        let t = f64::from(i) * 1e-4;
        sim.advance_to(t).unwrap();
        let peak = joint_load(&sim.outputs().unwrap(), role).1;
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
/// largest force peak of the first 5 ms at the worn joint is at most 1.5× the largest of the
/// second revolution, for the rigid and the 4-mode rod, and for each joint worn alone, where the
/// centred journal's start-up impact is more than 4× it.
#[test]
fn a_settled_journal_starts_without_an_impact() {
    for role in JointRole::ALL {
        for rod_formulation in [RodFormulation::Rigid, RodFormulation::CraigBampton] {
            let ratio = |journal_start| {
                let (p, inputs) = compressor(&[role], journal_start);
                let p = Parameters {
                    rod_formulation,
                    ..p
                };
                let (start, steady) = start_and_steady_peaks(p, inputs, role);
                println!(
                    "{} worn, {rod_formulation:?} rod, {journal_start:?} journal: first 5 ms \
                     {start:.0} N, 40-80 ms {steady:.0} N, ratio {:.2}",
                    role.prefix(),
                    start / steady
                );
                start / steady
            };
            let context = format!("{}, {rod_formulation:?}", role.prefix());
            assert!(ratio(JournalStart::Settled) <= 1.5, "{context}");
            assert!(ratio(JournalStart::Centred) > 4.0, "{context}");
        }
    }
}

/// The settled journals at t = 0: in contact, carrying the ideal joint's reaction (each worn
/// joint's force equals the one the ideal mechanism gives the same start within 1 %), at rest in
/// the bearing; each joint worn alone, and all three together.
#[test]
fn a_settled_journal_carries_the_ideal_joints_reaction() {
    use JointRole::{CrankPin, MainBearing, RodSlider};
    for worn in [
        &[MainBearing][..],
        &[CrankPin],
        &[RodSlider],
        &JointRole::ALL,
    ] {
        for rod_formulation in [RodFormulation::Rigid, RodFormulation::CraigBampton] {
            let (p, inputs) = compressor(worn, JournalStart::Settled);
            let p = Parameters {
                rod_formulation,
                ..p
            };
            let ideal = p.with_ideal_joints();
            let o = Simulation::with_inputs(p, inputs)
                .unwrap()
                .outputs()
                .unwrap();
            let reference = Simulation::with_inputs(ideal, inputs)
                .unwrap()
                .outputs()
                .unwrap();
            for &role in worn {
                let context = format!("{worn:?} worn, {rod_formulation:?}, at {role:?}");
                let ((force, _), (expected, _)) =
                    (joint_load(&o, role), joint_load(&reference, role));
                let (in_contact, penetration) = match role {
                    MainBearing => (o.main_bearing_in_contact, o.main_bearing_penetration),
                    CrankPin => (o.crank_pin_in_contact, o.crank_pin_penetration),
                    RodSlider => (o.in_contact, o.penetration),
                };
                assert!(in_contact && penetration > 0.0, "{context}");
                let difference = math::hypot(force[0] - expected[0], force[1] - expected[1]);
                let magnitude = math::hypot(expected[0], expected[1]);
                println!("{context}: {force:?} N vs the ideal joint's {expected:?} N");
                assert!(difference < 1e-2 * magnitude, "{context}");
            }
            if worn.contains(&RodSlider) {
                let rate = math::hypot(o.eccentricity_rate_x, o.eccentricity_rate_y);
                assert!(rate < 1e-9, "{rod_formulation:?}: ė = {rate} m/s");
            }
        }
    }
}

/// Setting only the prescribed speed starts the crank at it: no jump at the first step (crank
/// speed at the first communication point within 0.1 % of drive.speed) and no warning; with
/// crank.initialSpeed set to another value the crank jumps at the first step with the inputs
/// passed, and the run warns.
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
            crank_initial_speed: Some(300.0),
            ..Parameters::default()
        },
        inputs,
    )
    .unwrap();
    jump.advance_with(&InputSignal::held(inputs), 1e-4).unwrap();
    let o = jump.outputs().unwrap();
    assert_eq!(o.warnings, 1);
    assert!(
        (o.crank_speed - drive_speed).abs() < 1e-3 * drive_speed,
        "{}",
        o.crank_speed
    );
}
