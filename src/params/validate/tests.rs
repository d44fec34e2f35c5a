//! Unit tests of the parameter validation.

use super::*;
use crate::ancf::RodProperties;

/// The short-bearing film is flagged outside L/D <= 0.5 (benchmark C: L/D = 2.1), only for
/// the lubricated joint.
#[test]
fn long_bearings_are_flagged() {
    let c = Parameters::benchmark_c();
    let warnings = c.warnings();
    assert_eq!(warnings.len(), 1);
    assert!(warnings[0].contains("2.105") && warnings[0].contains("L/D <= 0.5"));
    let short = Parameters {
        joint: JointParameters {
            bearing_length: 0.009,
            ..c.joint
        },
        ..c
    };
    assert!(short.warnings().is_empty());
    assert!(Parameters::default().warnings().is_empty());
}

/// Every joint takes every joint model.
#[test]
fn every_joint_can_be_worn() {
    for model in [JointModel::Dry, JointModel::Lubricated] {
        let worn = JointParameters {
            model,
            ..JointParameters::benchmark()
        };
        for p in [
            Parameters {
                main_bearing: worn,
                ..Parameters::default()
            },
            Parameters {
                crank_pin: worn,
                ..Parameters::default()
            },
        ] {
            p.validate().unwrap();
        }
    }
}

/// Material damping is accepted up to a critically damped first bending mode (β ω₁ = 2,
/// ω₁ = 15 270 rad/s for benchmark B's rod) and only for a flexible rod; the message names
/// the limit for this rod. A very thin rod is limited by its first axial mode instead.
#[test]
fn overdamped_rods_are_rejected() {
    let omega = Parameters::default().rod.first_bending_frequency();
    assert!((omega - 15_270.0).abs() < 10.0, "{omega}");
    let with = |beta: f64, rod_formulation| Parameters {
        rod: RodProperties {
            stiffness_damping: beta,
            ..RodProperties::benchmark_b()
        },
        rod_formulation,
        ..Parameters::default()
    };
    with(0.99 * 2.0 / omega, RodFormulation::CraigBampton)
        .validate()
        .unwrap();
    with(1.0, RodFormulation::Rigid).validate().unwrap();
    for rod in [RodFormulation::CraigBampton, RodFormulation::Ancf] {
        let message = with(1.01 * 2.0 / omega, rod)
            .validate()
            .unwrap_err()
            .to_string();
        assert!(
            message.contains("rod.stiffnessDamping")
                && message.contains(&format!("[0, {}] s", Num(2.0 / omega))),
            "{message}"
        );
    }
}

/// A flexible rod must be slender (L/r ≥ 10); the rigid rod need not be.
#[test]
fn thick_rods_are_rejected() {
    let p = Parameters::default();
    let r = (p.rod.second_moment_of_area / p.rod.area).sqrt();
    assert!((p.rod.length / r - 27.8).abs() < 0.05);
    let with = |i: f64, rod_formulation| Parameters {
        rod: RodProperties {
            second_moment_of_area: i,
            ..RodProperties::benchmark_b()
        },
        rod_formulation,
        ..Parameters::default()
    };
    let limit = p.rod.area * (p.rod.length / 10.0).powi(2);
    with(0.99 * limit, RodFormulation::Ancf).validate().unwrap();
    with(1.01 * limit, RodFormulation::Rigid)
        .validate()
        .unwrap();
    let message = with(1.01 * limit, RodFormulation::CraigBampton)
        .validate()
        .unwrap_err()
        .to_string();
    assert!(
        message.contains("rod.secondMomentOfArea") && message.contains("at least 10"),
        "{message}"
    );
    let thin = RodProperties {
        second_moment_of_area: 1.5e-17,
        ..RodProperties::benchmark_b()
    };
    let axial_limit = 2.0 * Parameters::MAX_AXIAL_DAMPING_RATIO / thin.first_axial_frequency();
    assert!(axial_limit < 2.0 / thin.first_bending_frequency());
    for (beta, accepted) in [(0.99 * axial_limit, true), (1.01 * axial_limit, false)] {
        let p = Parameters {
            rod: RodProperties {
                stiffness_damping: beta,
                ..thin
            },
            ..Parameters::default()
        };
        assert_eq!(p.validate().is_ok(), accepted, "β = {beta} s");
    }
}

/// The library rejects just beyond every declared bound with an error naming the parameter:
/// the variable table is the one statement of each range.
#[test]
fn declared_ranges_are_the_library_ranges() {
    use crate::params::{set_integer_parameter, set_real_parameter};
    let beyond = |v: &crate::variables::Variable, value: f64| {
        let mut p = Parameters::default();
        let set = match v.kind {
            Kind::Real { .. } => set_real_parameter(&mut p, v.vr, value),
            _ => set_integer_parameter(&mut p, v.vr, value as i32),
        };
        if !set {
            // A negative count has no field value to hold it.
            assert!(value < 0.0, "{} = {value} not stored", v.name);
            return;
        }
        match p.validate() {
            Err(ModelError::InvalidParameter { name, .. }) => assert_eq!(name, v.name),
            other => panic!("{} = {value}: expected an error, got {other:?}", v.name),
        }
    };
    for v in VARIABLES
        .iter()
        .filter(|v| v.causality == Causality::Parameter)
    {
        match v.kind {
            Kind::Real { min, max, .. } => {
                beyond(v, min.next_down());
                beyond(v, max.next_up());
                beyond(v, f64::NAN);
            }
            Kind::Integer { min, max, .. } => {
                if min > i32::MIN {
                    beyond(v, f64::from(min - 1));
                }
                if max < i32::MAX {
                    beyond(v, f64::from(max + 1));
                }
            }
            Kind::Enumeration { .. } | Kind::Boolean | Kind::String { .. } => {}
        }
    }
    let elements = VARIABLES.iter().find(|v| v.name == "rod.nElements");
    assert!(matches!(
        elements.map(|v| v.kind),
        Some(Kind::Integer { max, .. }) if max as usize == crate::ancf::rod::MAX_ELEMENTS
    ));
}

#[test]
fn defaults_are_valid_and_benchmark_b() {
    let p = Parameters::default();
    p.validate().unwrap();
    assert!((p.rod.mass() - 0.21).abs() < 1e-12);
    assert!((p.joint.bearing_radius() - 0.010).abs() < 1e-15);
}

/// Every listed bad value is rejected with an error naming the parameter.
#[test]
fn bad_values_name_the_parameter() {
    let base = Parameters::default();
    let cases: Vec<(&str, Parameters)> = vec![
        (
            "slider.forceTablePeriod",
            Parameters {
                slider_force_table_period: 540,
                ..base.clone()
            },
        ),
        (
            "rod.length",
            Parameters {
                rod: RodProperties {
                    length: 0.04,
                    ..base.rod
                },
                ..base.clone()
            },
        ),
        (
            "joint.clearance",
            Parameters {
                joint: JointParameters {
                    clearance: 0.0,
                    ..base.clone().joint
                },
                ..base.clone()
            },
        ),
        (
            "joint.clearance",
            Parameters {
                joint: JointParameters {
                    clearance: f64::NAN,
                    ..base.clone().joint
                },
                ..base.clone()
            },
        ),
        (
            "joint.restitution",
            Parameters {
                joint: JointParameters {
                    restitution: 0.0,
                    ..base.clone().joint
                },
                ..base.clone()
            },
        ),
        (
            "joint.restitution",
            Parameters {
                joint: JointParameters {
                    restitution: 1.2,
                    ..base.clone().joint
                },
                ..base.clone()
            },
        ),
        (
            "joint.switchEccentricity",
            Parameters {
                joint: JointParameters {
                    switch_eccentricity: 1.0,
                    ..base.clone().joint
                },
                ..base.clone()
            },
        ),
        (
            "joint.frictionV1",
            Parameters {
                joint: JointParameters {
                    friction_v1: 1e-5,
                    ..base.clone().joint
                },
                ..base.clone()
            },
        ),
        (
            "joint.friction",
            Parameters {
                joint: JointParameters {
                    friction: -0.1,
                    ..base.clone().joint
                },
                ..base.clone()
            },
        ),
        (
            "slider.mass",
            Parameters {
                slider_mass: f64::INFINITY,
                ..base.clone()
            },
        ),
        (
            "crank.length",
            Parameters {
                crank_length: -0.05,
                ..base.clone()
            },
        ),
        (
            "rod.nModes",
            Parameters {
                n_modes: 17,
                ..base.clone()
            },
        ),
        (
            "rod.nModes",
            Parameters {
                n_modes: MAX_SAMPLED_MODES + 1,
                quadrature: Quadrature::Sampled,
                ..base.clone()
            },
        ),
        (
            "rod.nElements",
            Parameters {
                n_elements: 0,
                ..base.clone()
            },
        ),
        (
            "solver.relativeTolerance",
            Parameters {
                relative_tolerance: 0.0,
                ..base.clone()
            },
        ),
        (
            "solver.relativeTolerance",
            Parameters {
                method: Method::DormandPrince,
                relative_tolerance: 1e-2,
                ..base.clone()
            },
        ),
        (
            "solver.relativeTolerance",
            Parameters {
                method: Method::GeneralizedAlpha,
                relative_tolerance: 5e-2,
                ..base.clone()
            },
        ),
        (
            "solver.spectralRadius",
            Parameters {
                spectral_radius: 1.5,
                ..base.clone()
            },
        ),
    ];
    for (name, p) in cases {
        match p.validate() {
            Err(ModelError::InvalidParameter { name: n, .. }) => assert_eq!(n, name),
            other => panic!("{name}: expected an error, got {other:?}"),
        }
    }
    let ok = Parameters {
        joint: JointParameters {
            restitution: 1.0,
            model: JointModel::Ideal,
            clearance: 0.0,
            ..base.joint
        },
        ..base
    };
    ok.validate().unwrap();
}

/// A feed wider than half the bearing's length, or an axial groove that reaches the bearing's
/// ends, is refused naming the parameter, its value and the allowed range; an unfed or dry joint
/// is not checked.
#[test]
fn feeds_that_do_not_fit_are_refused() {
    let fed = |feed, feed_diameter, feed_groove_length| Parameters {
        crank_pin: JointParameters {
            model: JointModel::Lubricated,
            bearing_length: 0.016,
            feed,
            feed_diameter,
            feed_groove_length,
            ..JointParameters::benchmark()
        },
        ..Parameters::default()
    };
    fed(FeedModel::Hole, 8e-3, 0.8).validate().unwrap();
    fed(FeedModel::AxialGroove, 3e-3, 0.8).validate().unwrap();
    fed(FeedModel::None, 0.1, 0.8).validate().unwrap();
    let message = fed(FeedModel::CircumferentialGroove, 9e-3, 0.8)
        .validate()
        .unwrap_err()
        .to_string();
    assert!(
        message.contains("crankPin.feedDiameter")
            && message.contains("0.009")
            && message.contains("(0, 0.008]"),
        "{message}"
    );
    let message = fed(FeedModel::AxialGroove, 4e-3, 0.9)
        .validate()
        .unwrap_err()
        .to_string();
    assert!(
        message.contains("crankPin.feedGrooveLength") && message.contains("0.825"),
        "{message}"
    );
}
