//! A clearance at the crank pin (the big end): its limits, its energy account, and an independent
//! formulation of the rigid mechanism.

use super::*;

/// The crank pin worn, every other joint ideal.
fn crank_pin_worn(base: Parameters, model: JointModel, clearance: f64) -> Parameters {
    Parameters {
        joint: JointParameters {
            model: JointModel::Ideal,
            ..base.joint
        },
        crank_pin: JointParameters {
            model,
            clearance,
            ..JointParameters::benchmark()
        },
        ..base
    }
}

/// Clearance → 0 at the crank pin alone (rigid rod, dry, 5000 rpm): the slider acceleration
/// approaches the ideal mechanism's, the RMS error over the second revolution falling at least
/// 100× from c = 1e-4 to 1e-6 m.
#[test]
fn vanishing_crank_pin_clearance_approaches_the_ideal_joint() {
    let base = Parameters {
        rod_formulation: RodFormulation::Rigid,
        ..Parameters::default()
    };
    let (_, ideal) = run(
        crank_pin_worn(base.clone(), JointModel::Ideal, 0.5e-3),
        2.0 * REVOLUTION,
        400,
    );
    let errors: Vec<f64> = [1e-4, 1e-5, 1e-6]
        .iter()
        .map(|&c| {
            let (_, rows) = run(
                crank_pin_worn(base.clone(), JointModel::Dry, c),
                2.0 * REVOLUTION,
                400,
            );
            let sum: f64 = rows[200..]
                .iter()
                .zip(&ideal[200..])
                .map(|(a, b)| (a.slider_acceleration - b.slider_acceleration).powi(2))
                .sum();
            (sum / 201.0).sqrt()
        })
        .collect();
    println!(
        "crank pin: RMS slider-acceleration error vs ideal for c = 1e-4, 1e-5, 1e-6 m: \
         {errors:.3?} m/s²"
    );
    assert!(errors[0] > errors[1] && errors[1] > errors[2], "{errors:?}");
    assert!(errors[0] > 100.0 * errors[2], "{errors:?}");
}

/// The energy account from the outputs closes with the crank pin worn, and its residual over one
/// revolution falls at least 100× from rtol 1e-4 to 1e-8: the crank pin alone dry (without and with
/// friction, whose moments act on the crank and on the turning rod eye) and lubricated, and both
/// pins dry and both lubricated (rigid rod and 4 modes).
#[test]
fn energy_balance_converges_with_a_worn_crank_pin() {
    for rod_formulation in [RodFormulation::Rigid, RodFormulation::CraigBampton] {
        for (name, model, slider_pin, friction) in [
            ("crank pin dry", JointModel::Dry, JointModel::Ideal, 0.0),
            (
                "crank pin dry, μ = 0.2",
                JointModel::Dry,
                JointModel::Ideal,
                0.2,
            ),
            (
                "crank pin lubricated",
                JointModel::Lubricated,
                JointModel::Ideal,
                0.0,
            ),
            ("both pins dry", JointModel::Dry, JointModel::Dry, 0.0),
            (
                "both pins lubricated",
                JointModel::Lubricated,
                JointModel::Lubricated,
                0.0,
            ),
        ] {
            let residual = |relative_tolerance| {
                let mut p = crank_pin_worn(
                    Parameters {
                        rod_formulation,
                        relative_tolerance,
                        ..Parameters::default()
                    },
                    model,
                    0.5e-3,
                );
                p.joint.model = slider_pin;
                p.crank_pin.friction = friction;
                let (_, rows) = run(p, REVOLUTION, 100);
                super::balance::output_balance_residual(&rows)
            };
            let (loose, tight) = (residual(1e-4), residual(1e-8));
            println!(
                "{rod_formulation:?}, {name}: energy residual {loose:.1e} (rtol 1e-4), \
                 {tight:.1e} (rtol 1e-8)"
            );
            assert!(loose > 100.0 * tight, "{rod_formulation:?}, {name}");
        }
    }
}
