//! Unit tests of the mechanism: its held errors, and the clearance joint load against the right-hand side.

use super::*;
use crate::params::{JointModel, JointParameters, RodFormulation};

/// The dry journal's normal velocity is held to rtol · V / w on its own, with
/// w = `solver.impactErrorWeight`: its scale falls as 1/w, w = 0 leaves it to the RMS, and the
/// lubricated and ideal joints hold nothing.
#[test]
fn the_impact_error_weight_sets_the_held_journal_velocity() {
    let held = |joint_model, impact_error_weight| {
        let p = Parameters {
            joint: JointParameters {
                model: joint_model,
                ..Parameters::default().joint
            },
            impact_error_weight,
            ..Parameters::default()
        };
        SliderCrank::new(&p)
            .expect("valid parameters")
            .error_scales()
            .held
    };
    let (strict, loose) = (held(JointModel::Dry, 4.0), held(JointModel::Dry, 1.0));
    assert_eq!((strict.len(), loose.len()), (1, 1));
    assert!(strict[0] > 0.0);
    assert_eq!(4.0 * strict[0], loose[0]);
    assert!(held(JointModel::Dry, 0.0).is_empty());
    for joint_model in [JointModel::Lubricated, JointModel::Ideal] {
        assert!(held(joint_model, 4.0).is_empty());
    }
}

/// The held error is that of the journal's velocity relative to the slider along the
/// eccentricity's direction, its magnitude when the journal is centred.
#[test]
fn the_held_error_is_the_journals_normal_velocity_error() {
    let m = SliderCrank::new(&Parameters::default()).expect("default parameters build");
    let l = m.layout();
    let mut y = m.initial_state(0.3, 400.0);
    // e = (3, 4) µm: direction (0.6, 0.8); ė error (1 − 0.5, 2) = (0.5, 2).
    y[l.slider()] = y[l.pin_b()] - 3e-6;
    y[l.pin_b() + 1] = 4e-6;
    let mut err = vec![0.0; y.len()];
    err[l.rate_of(l.pin_b())] = 1.0;
    err[l.rate_of(l.pin_b()) + 1] = 2.0;
    err[l.slider_velocity()] = 0.5;
    let mut out = [0.0];
    m.journal_held_errors(&y, &err, &mut out);
    assert!(
        (out[0] - (0.6 * 0.5 + 0.8 * 2.0)).abs() < 1e-12,
        "{}",
        out[0]
    );
    y[l.slider()] = y[l.pin_b()];
    y[l.pin_b() + 1] = 0.0;
    m.journal_held_errors(&y, &err, &mut out);
    assert!(
        (out[0] - (0.25f64 + 4.0).sqrt()).abs() < 1e-12,
        "{}",
        out[0]
    );
}

/// The crank joints' held errors are the errors of their journals' normal velocities: for a
/// small error δ in θ, θ̇, ṙ_A and ṙ_G they equal |n · (ė(y + δ) − ė(y))| (the free crank,
/// both crank joints dry and off centre).
#[test]
fn the_crank_joints_held_errors_are_their_normal_velocity_errors() {
    let worn = JointParameters {
        model: JointModel::Dry,
        ..JointParameters::benchmark()
    };
    let p = Parameters {
        crank_pin: worn,
        main_bearing: worn,
        ..Parameters::default()
    };
    let m = SliderCrank::new(&p).expect("worn crank joints build");
    let l = m.layout();
    let g = l.crank_centre().expect("a free crank");
    let mut y = m.initial_state(0.3, 400.0);
    y[g] += 3e-6;
    y[g + 1] -= 4e-6;
    y[PIN_A] += 2e-6;
    let mut err = vec![0.0; y.len()];
    err[CRANK_ANGLE] = 1e-7;
    err[l.crank_speed()] = 2e-3;
    for (at, e) in [
        (l.rate_of(PIN_A), [1e-4, -2e-4]),
        (l.rate_of(g), [3e-4, 1e-4]),
    ] {
        err[at..at + 2].copy_from_slice(&e);
    }
    let mut out = [0.0; 3];
    m.journal_held_errors(&y, &err, &mut out);
    let shifted: Vec<f64> = y.iter().zip(&err).map(|(a, b)| a + b).collect();
    for (held, role) in out
        .iter()
        .zip([JointRole::MainBearing, JointRole::CrankPin])
    {
        let kin = m.joint_kinematics(role, &y);
        let change = m.joint_kinematics(role, &shifted).e_dot - kin.e_dot;
        let expected = kin.normal().dot(&change).abs();
        assert!(expected > 1e-6, "{role:?}: {expected}");
        assert!(
            (held - expected).abs() < 1e-6 * expected,
            "{role:?}: {held} vs {expected}"
        );
    }
}

/// The joint load from the kinematics alone equals the full right-hand side's, for every
/// clearance joint and rod, in contact (inside and at the start of an event) and with a
/// slider force; the ideal joint has none.
#[test]
fn clearance_joint_load_equals_the_right_hand_side() {
    for joint_model in [JointModel::Dry, JointModel::Lubricated, JointModel::Ideal] {
        for rod_formulation in [RodFormulation::Rigid, RodFormulation::CraigBampton] {
            let p = Parameters {
                joint: JointParameters {
                    model: joint_model,
                    ..Parameters::default().joint
                },
                rod_formulation,
                ..Parameters::default()
            };
            let mut m = SliderCrank::new(&p).expect("default parameters build");
            let inputs = Inputs {
                slider_force: -150.0,
                ..Inputs::at_start(&p)
            };
            let mut y = m.initial_state(0.3, 400.0);
            let l = m.layout();
            // Journal 20 µm into the wall, moving into it.
            y[l.slider()] -= p.joint.clearance + 2e-5;
            y[l.slider_velocity()] -= 0.5;
            let mut dy = vec![0.0; y.len()];
            let mut in_contact = crate::joint::Contacts::default();
            in_contact[JointRole::RodSlider] = crate::joint::ContactState {
                in_contact: true,
                impact_velocity: 0.8,
            };
            for contacts in [crate::joint::Contacts::default(), in_contact] {
                let c = Conditions::held(inputs, &contacts);
                let load = m.clearance_joint_load(&y, &c);
                let ev = *m.evaluate(&y, &c, &mut dy).expect("regular configuration");
                match load {
                    None => assert_eq!(joint_model, JointModel::Ideal),
                    Some((force, acceleration)) => {
                        assert!(force.norm() > 100.0, "{joint_model:?}: {force} N");
                        assert_eq!(force, ev.joint_force);
                        assert_eq!(acceleration, ev.slider_acceleration);
                    }
                }
            }
        }
    }
}
