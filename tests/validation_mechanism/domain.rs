//! Domain exits are reported once per cause, the start from rest, and failing steps name their likely causes.

use super::*;

/// Validity warnings over 2 ms in steps of 0.1 ms (until a step fails).
fn warnings_over_2_ms(sim: Simulation) -> Vec<String> {
    let inputs = *sim.inputs();
    warnings_over_2_ms_with(sim, &inputs)
}

/// [`warnings_over_2_ms`] with the inputs `inputs`.
fn warnings_over_2_ms_with(mut sim: Simulation, inputs: &InputSignal) -> Vec<String> {
    let mut warnings = Vec::new();
    for i in 1..=20 {
        if sim.advance_with(inputs, 1e-4 * f64::from(i)).is_err() {
            break;
        }
        warnings.extend(sim.take_warnings());
    }
    println!("{warnings:?}");
    warnings
}

/// Validity monitors: the documented extreme parameter sets leave the model's domain with
/// a warning naming the value and the limit, once per cause; the benchmarks stay silent.
#[test]
fn leaving_the_domain_is_reported_once_per_cause() {
    let quiet = [
        Parameters::default(),
        Parameters::benchmark_a(),
        Parameters::benchmark_c(),
        Parameters::benchmark_d(),
    ];
    for p in quiet {
        let mut sim = Simulation::new(p).unwrap();
        sim.advance_to(REVOLUTION).unwrap();
        // (benchmark C's bearing is outside the short-bearing range: a parameter warning, not a
        // domain exit)
        let warnings = sim.take_warnings();
        assert!(
            warnings.iter().all(|w| !w.contains("left its domain")),
            "{warnings:?}"
        );
    }
    let mut stiff_drive = Parameters {
        drive_mode: DriveMode::Torque,
        ..Parameters::default()
    };
    stiff_drive.crank_initial_speed = Some(0.0);
    let cases = [
        (
            "joint penetration",
            Parameters {
                joint: JointParameters {
                    journal_radius: 1e-4,
                    ..Parameters::default().joint
                },
                ..Parameters::default()
            },
        ),
        (
            "slider position",
            Parameters {
                crank_initial_speed: Some(1e4),
                ..Parameters::default()
            },
        ),
    ];
    for (cause, p) in cases {
        let warnings = warnings_over_2_ms(Simulation::new(p).unwrap());
        assert_eq!(
            warnings.iter().filter(|w| w.contains(cause)).count(),
            1,
            "{cause}: {warnings:?}"
        );
    }
    // A speed drive at the declared limit (1e4 rad/s) is within the drive's range.
    let at_limit = warnings_over_2_ms(
        Simulation::new(Parameters {
            crank_initial_speed: Some(1e4),
            ..Parameters::default()
        })
        .unwrap(),
    );
    assert!(!at_limit.iter().any(|w| w.contains("crank speed")));
    let sim = Simulation::new(stiff_drive).unwrap();
    let mut inputs = *sim.inputs();
    inputs.value.drive_torque = 1e6;
    let warnings = warnings_over_2_ms_with(sim, &inputs);
    assert!(
        warnings.iter().any(|w| w.contains("crank speed")),
        "{warnings:?}"
    );
}

/// A start from rest (crank.initialSpeed = 0) equilibrates: the straight rod is already in
/// equilibrium and the Newton residual starts at its round-off floor (regression: this failed
/// with "Newton did not converge").
#[test]
fn start_from_rest_is_equilibrated() {
    for drive_mode in [DriveMode::Speed, DriveMode::Torque] {
        for rod_formulation in [RodFormulation::CraigBampton, RodFormulation::Ancf] {
            let p = Parameters {
                drive_mode,
                rod_formulation,
                crank_initial_speed: Some(0.0),
                ..Parameters::default()
            };
            let mut sim = Simulation::new(p).unwrap();
            assert!(sim.outputs().unwrap().deformation_energy < 1e-15);
            sim.advance_to(1e-3).unwrap();
        }
    }
}

/// Errors that name their cause: a lubricated joint with a 1 nm clearance is accepted
/// and gets an equilibrated start (the quasi-static Newton's finite differences use at least 1e-4
/// of the rod's length scale; regression: "singular Newton matrix" at instantiation), but its film
/// is too stiff to integrate within a work limit of 2 000 step attempts per interval (it takes
/// about 10 000, its shear clamping the pin's rotation to the slider): the interval fails with a
/// message naming the clearance and the joint model, and the simulation stays at its last
/// accepted step.
#[test]
fn a_failing_step_names_the_likely_parameters() {
    let p = Parameters {
        joint: JointParameters {
            model: JointModel::Lubricated,
            clearance: 1e-9,
            ..Parameters::default().joint
        },
        max_steps_per_interval: 2_000,
        ..Parameters::default()
    };
    let mut sim = Simulation::new(p).unwrap();
    assert!(sim.state().iter().all(|x| x.is_finite()));
    let message = (1..=40)
        .find_map(|i| sim.advance_to(1e-4 * f64::from(i)).err())
        .expect("the 1 nm film should not integrate")
        .to_string();
    println!("{message}");
    assert!(
        message.contains("joint.clearance = 1e-9 m with joint.model = lubricated"),
        "{message}"
    );
    assert!(sim.outputs().unwrap().slider_position.is_finite());
}

/// A rod too compliant for a quasi-static start (slenderness 16 000: I = 7.8e-14 m⁴ at the
/// default area) is refused with a message naming `rod.initialState` and the rod's stiffness,
/// and runs when started straight.
#[test]
fn a_failed_quasi_static_start_names_the_initial_state() {
    let mut p = Parameters {
        joint: JointParameters {
            contact_law: ContactLaw::Flores,
            ..Parameters::default().joint
        },
        crank_initial_angle: -77.332_090_043_934_3,
        ..Parameters::default()
    };
    p.rod.second_moment_of_area = 7.820_745_747_472_193e-14;
    let message = Simulation::new(p.clone())
        .expect_err("no quasi-static start for this rod")
        .to_string();
    println!("{message}");
    for name in [
        "rod.initialState = equilibrated",
        "rod.secondMomentOfArea = 7.820745747472193e-14",
        "rod.initialState = straight",
    ] {
        assert!(message.contains(name), "{message}");
    }
    p.initial_state = InitialState::Straight;
    let mut sim = Simulation::new(p).unwrap();
    sim.advance_to(1e-3).unwrap();
}

/// A lubricated joint that goes into dry metal contact warns, naming the joint, and every onset
/// counts in `solver.warnings`: the worn crank pin of 50 µm clearance, 9 mm long with a thin oil
/// (0.04 Pa s) starting centred knocks on its wall; the rod–slider joint's oil film of benchmark C
/// keeps its journal off the wall and stays silent.
#[test]
fn a_lubricated_joint_in_metal_contact_warns_naming_it() {
    let worn = Parameters {
        joint: JointParameters::ideal(),
        crank_pin: JointParameters {
            model: JointModel::Lubricated,
            clearance: 5e-5,
            bearing_length: 9e-3,
            viscosity: 0.04,
            ..JointParameters::benchmark()
        },
        ..Parameters::default()
    };
    let mut sim = Simulation::new(worn).unwrap();
    sim.advance_to(REVOLUTION).unwrap();
    let onsets = sim.outputs().unwrap().crank_pin_contact_onsets_total;
    let warnings = sim.take_warnings();
    println!("{onsets} onsets: {warnings:?}");
    let metal: Vec<_> = warnings
        .iter()
        .filter(|w| w.contains("dry metal contact"))
        .collect();
    assert!(onsets > 0);
    assert!(!metal.is_empty() && metal.iter().all(|w| w.contains("crankPin")));
    assert!(sim.outputs().unwrap().warnings >= onsets);
    let mut oiled = Simulation::new(Parameters::benchmark_c()).unwrap();
    oiled.advance_to(REVOLUTION).unwrap();
    assert_eq!(oiled.outputs().unwrap().contact_onsets_total, 0);
    assert!(
        oiled
            .take_warnings()
            .iter()
            .all(|w| !w.contains("dry metal contact"))
    );
}
