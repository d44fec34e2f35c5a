//! The energy outputs close the balance, and the balance converges with the tolerance.

use super::*;

/// Largest |balance(t) − balance(0)| of the outputs over a run, relative to the largest kinetic
/// energy.
pub(crate) fn output_balance_residual(rows: &[Outputs]) -> f64 {
    let kinetic = rows.iter().fold(0.0f64, |m, o| m.max(o.kinetic_energy));
    let start = rows[0].energy_balance();
    rows.iter()
        .fold(0.0f64, |m, o| m.max((o.energy_balance() - start).abs()))
        / kinetic
}

/// Energy account: from the outputs alone the balance closes with the dry joint and
/// oblique gravity (40° from −y: the slider's weight works along the guide too; before
/// energy.contact was an output, it was off by 2.6e-3 of the kinetic energy on benchmark B).
#[test]
fn energy_outputs_close_the_balance() {
    let p = Parameters {
        gravity: 9.81,
        gravity_angle: f64::to_radians(40.0),
        relative_tolerance: 1e-8,
        ..Parameters::default()
    };
    let (_, rows) = run(p, REVOLUTION, 200);
    let kinetic = rows.iter().fold(0.0f64, |m, o| m.max(o.kinetic_energy));
    let contact = rows.iter().fold(0.0f64, |m, o| m.max(o.contact_energy));
    let residual = output_balance_residual(&rows);
    println!(
        "outputs' energy balance over one revolution: residual {residual:.1e} of the kinetic \
         energy (largest contact energy {contact:.3} J)"
    );
    assert!(contact > 1e-3 * kinetic);
    assert!(residual < 1e-6, "{residual:e}");
}

/// The outputs' energy-balance residual over one revolution falls at least
/// 100× from rtol 1e-4 to 1e-8 on benchmarks A, B (4 modes and full), C, with the torque drive
/// and a slider force, with friction 0.1, with three worn joints (two films with their shear), with
/// gravity 9.81 and with material damping 1e-5 s
/// (the work integrals are states under the same error control as the motion).
#[test]
fn energy_balance_converges_with_the_tolerance() {
    let cases = [
        ("A", Parameters::benchmark_a(), 0.0, 0.0),
        ("B, 4 modes", Parameters::default(), 0.0, 0.0),
        ("B, full rod", Parameters::benchmark_b(), 0.0, 0.0),
        ("C", Parameters::benchmark_c(), 0.0, 0.0),
        (
            "torque drive 20 N m, slider force -500 N",
            Parameters {
                drive_mode: DriveMode::Torque,
                ..Parameters::default()
            },
            20.0,
            -500.0,
        ),
        (
            "friction 0.1",
            Parameters {
                joint: JointParameters {
                    friction: 0.1,
                    ..Parameters::default().joint
                },
                ..Parameters::default()
            },
            0.0,
            0.0,
        ),
        (
            "gravity 9.81",
            Parameters {
                gravity: 9.81,
                ..Parameters::default()
            },
            0.0,
            0.0,
        ),
        (
            "lubricated crank pin and main bearing (film shear), dry friction 0.1",
            Parameters {
                crank_pin: JointParameters {
                    model: JointModel::Lubricated,
                    clearance: 5e-5,
                    bearing_length: 9e-3,
                    viscosity: 0.04,
                    ..JointParameters::benchmark()
                },
                main_bearing: JointParameters {
                    model: JointModel::Lubricated,
                    clearance: 5e-5,
                    bearing_length: 9e-3,
                    viscosity: 0.04,
                    ..JointParameters::benchmark()
                },
                joint: JointParameters {
                    friction: 0.1,
                    ..JointParameters::benchmark()
                },
                ..Parameters::default()
            },
            0.0,
            0.0,
        ),
        (
            "material damping 1e-5 s",
            Parameters {
                rod: RodProperties {
                    stiffness_damping: 1e-5,
                    ..RodProperties::benchmark_b()
                },
                ..Parameters::default()
            },
            0.0,
            0.0,
        ),
    ];
    for (name, p, torque, slider_force) in cases {
        let residual = |rtol: f64| {
            let mut sim = Simulation::new(Parameters {
                relative_tolerance: rtol,
                ..p.clone()
            })
            .unwrap();
            let mut inputs = *sim.inputs();
            inputs.value.drive_torque = torque;
            inputs.value.slider_force = slider_force;
            let mut rows = vec![sim.outputs_seeing(&inputs).unwrap()];
            for i in 1..=60 {
                sim.advance_with(&inputs, REVOLUTION * f64::from(i) / 60.0)
                    .unwrap();
                rows.push(sim.outputs().unwrap());
            }
            let last = rows[rows.len() - 1];
            (output_balance_residual(&rows), last)
        };
        let (coarse, _) = residual(1e-4);
        let (fine, last) = residual(1e-8);
        println!(
            "{name}: residual {coarse:.2e} at rtol 1e-4, {fine:.2e} at 1e-8 ({:.0}×); \
             dissipated {:.3e} J, material damping {:.3e} J, slider work {:.3e} J",
            coarse / fine,
            last.dissipated_energy,
            last.material_damping,
            last.slider_work
        );
        assert!(fine * 100.0 <= coarse, "{name}: {coarse:e} → {fine:e}");
    }
}

/// The energy figures at the default tolerance over 0.5 s (about 42 revolutions at 5000 rpm), the
/// 4-mode rod, one joint worn at a time (rod–slider joint, crank pin, main bearing): with the short
/// and the finite film, energy.driveWork and energy.dissipated within 0.5 % of a run at rtol 1e-4
/// and the outputs' account within 0.5 % of the drive work at every communication point (1e-4 s).
/// With a dry joint, whose impacts after the first are chaotic (a converged run follows another
/// sequence), the account alone (a dry main bearing is integrated at rtol 1e-3 at most).
#[test]
fn energy_figures_are_right_at_the_default_tolerance() {
    const DURATION: f64 = 0.5;
    let worn = |role: JointRole, model: JointModel, film_model: FilmModel| {
        let joint = JointParameters {
            model,
            film_model,
            ..JointParameters::benchmark()
        };
        let mut p = Parameters {
            joint: JointParameters::ideal(),
            ..Parameters::default()
        };
        *match role {
            JointRole::RodSlider => &mut p.joint,
            JointRole::CrankPin => &mut p.crank_pin,
            JointRole::MainBearing => &mut p.main_bearing,
        } = joint;
        p
    };
    let account = |p: Parameters| {
        let (_, rows) = run(p, DURATION, (DURATION / 1e-4).round() as usize);
        let start = rows[0].energy_balance();
        let last = rows[rows.len() - 1];
        let residual = rows
            .iter()
            .fold(0.0f64, |m, o| m.max((o.energy_balance() - start).abs()));
        (last, residual / last.drive_work.abs())
    };
    let roles = [
        JointRole::RodSlider,
        JointRole::CrankPin,
        JointRole::MainBearing,
    ];
    let cases: Vec<(String, Parameters)> = roles
        .iter()
        .flat_map(|&role| {
            [FilmModel::Short, FilmModel::Finite].map(|film| {
                (
                    format!("{role:?}, {film:?} film"),
                    worn(role, JointModel::Lubricated, film),
                )
            })
        })
        .collect();
    for (name, p) in cases {
        let (default, residual) = account(p.clone());
        let (converged, _) = account(Parameters {
            relative_tolerance: 1e-4,
            ..p
        });
        let off = |a: f64, b: f64| (a - b) / b.abs();
        let drive = off(default.drive_work, converged.drive_work);
        let dissipated = off(default.dissipated_energy, converged.dissipated_energy);
        println!(
            "{name}: drive work {:.3} J ({:+.3} %), dissipated {:.3} J ({:+.3} %), account \
             {:.3} % of the drive work",
            default.drive_work,
            100.0 * drive,
            default.dissipated_energy,
            100.0 * dissipated,
            100.0 * residual
        );
        assert!(drive.abs() < 5e-3, "{name}: drive work off by {drive:e}");
        assert!(
            dissipated.abs() < 5e-3,
            "{name}: dissipated energy off by {dissipated:e}"
        );
        assert!(residual < 5e-3, "{name}: account off by {residual:e}");
    }
    for role in roles {
        let (_, residual) = account(worn(role, JointModel::Dry, FilmModel::Finite));
        println!(
            "{role:?}, dry: account {:.3} % of the drive work",
            100.0 * residual
        );
        assert!(
            residual < 5e-3,
            "{role:?}, dry: account off by {residual:e}"
        );
    }
}

/// The energy account closes with the asperities' boundary friction in it: a rough, lubricated
/// crank pin (finite film, 50 µm clearance, 9 mm long, 0.04 Pa s, 2 µm combined roughness,
/// boundary friction 0.12) whose film falls into mixed lubrication at every revolution, over 0.1 s
/// at the default tolerance: the outputs' account within 0.5 % of the drive work at every
/// communication point, the asperities carrying a load and their friction a part of the
/// dissipation (its energy, ∫ asperityFrictionPower dt, at least 1 % of energy.dissipated and
/// below it); and the account converges with the tolerance (100× from 1e-4 to 1e-8).
#[test]
fn energy_account_closes_with_asperity_friction() {
    const DURATION: f64 = 0.1;
    let p = Parameters {
        joint: JointParameters::ideal(),
        crank_pin: JointParameters {
            model: JointModel::Lubricated,
            film_model: FilmModel::Finite,
            clearance: 5e-5,
            bearing_length: 9e-3,
            viscosity: 0.04,
            roughness: 2e-6,
            boundary_friction: 0.12,
            ..JointParameters::benchmark()
        },
        ..Parameters::default()
    };
    let account = |p: Parameters| {
        let n = (DURATION / 1e-4).round() as usize;
        let (_, rows) = run(p, DURATION, n);
        let start = rows[0].energy_balance();
        let last = rows[n];
        let residual = rows
            .iter()
            .fold(0.0f64, |m, o| m.max((o.energy_balance() - start).abs()));
        (rows, residual / last.drive_work.abs())
    };
    let (rows, residual) = account(p.clone());
    let pin = |o: &Outputs| o.bearings[JointRole::CrankPin as usize];
    let asperity_energy: f64 = rows
        .windows(2)
        .map(|w| {
            0.5 * 1e-4 * (pin(&w[0]).asperity_friction_power + pin(&w[1]).asperity_friction_power)
        })
        .sum();
    let last = rows[rows.len() - 1];
    let largest = rows
        .iter()
        .map(|o| pin(o).asperity_force)
        .fold(0.0, f64::max);
    let thinnest = rows
        .iter()
        .map(|o| pin(o).film_ratio)
        .fold(f64::INFINITY, f64::min);
    println!(
        "account {:.3} % of the drive work {:.3} J; dissipated {:.4} J, of it asperity friction \
         {:.4} J; largest asperity force {largest:.1} N, smallest film ratio {thinnest:.2}",
        100.0 * residual,
        last.drive_work,
        last.dissipated_energy,
        asperity_energy
    );
    assert!(residual < 5e-3, "account off by {residual:e}");
    assert!(largest > 0.0);
    assert!(
        asperity_energy > 0.01 * last.dissipated_energy && asperity_energy < last.dissipated_energy,
        "asperity friction {asperity_energy} J of {} J dissipated",
        last.dissipated_energy
    );
    let tight = |rtol: f64| {
        account(Parameters {
            relative_tolerance: rtol,
            ..p.clone()
        })
        .1
    };
    let (coarse, fine) = (tight(1e-4), tight(1e-8));
    println!("account {coarse:.2e} at rtol 1e-4, {fine:.2e} at 1e-8");
    assert!(fine * 100.0 <= coarse, "{coarse:e} → {fine:e}");
}
