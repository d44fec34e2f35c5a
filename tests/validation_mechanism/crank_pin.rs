//! Clearances at the crank pin (the big end) and at the main bearing (the crank's pivot): their
//! limits, their energy account, and an independent formulation of the rigid mechanism with a
//! worn crank pin.

use super::*;

/// The joint `role` worn (benchmark joint with `model` and `clearance`), every other joint ideal.
fn worn_at(role: JointRole, base: Parameters, model: JointModel, clearance: f64) -> Parameters {
    let mut p = Parameters {
        joint: JointParameters {
            model: JointModel::Ideal,
            ..base.joint
        },
        ..base
    };
    *p.joint_mut(role) = JointParameters {
        model,
        clearance,
        ..JointParameters::benchmark()
    };
    p
}

/// The crank pin worn, every other joint ideal.
fn crank_pin_worn(base: Parameters, model: JointModel, clearance: f64) -> Parameters {
    worn_at(JointRole::CrankPin, base, model, clearance)
}

/// Clearance → 0 at the crank pin alone and at the main bearing alone (rigid rod, dry, 5000 rpm):
/// the slider acceleration approaches the ideal mechanism's, the RMS error over the second
/// revolution falling at least 100× from c = 1e-4 to 1e-6 m.
#[test]
fn vanishing_crank_pin_and_main_bearing_clearances_approach_the_ideal_joint() {
    let base = Parameters {
        rod_formulation: RodFormulation::Rigid,
        ..Parameters::default()
    };
    let (_, ideal) = run(
        crank_pin_worn(base.clone(), JointModel::Ideal, 0.5e-3),
        2.0 * REVOLUTION,
        400,
    );
    for role in [JointRole::CrankPin, JointRole::MainBearing] {
        vanishing_clearance_approaches(role, &base, &ideal);
    }
}

fn vanishing_clearance_approaches(role: JointRole, base: &Parameters, ideal: &[Outputs]) {
    let errors: Vec<f64> = [1e-4, 1e-5, 1e-6]
        .iter()
        .map(|&c| {
            let (_, rows) = run(
                worn_at(role, base.clone(), JointModel::Dry, c),
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
        "{}: RMS slider-acceleration error vs ideal for c = 1e-4, 1e-5, 1e-6 m: \
         {errors:.3?} m/s²",
        role.prefix()
    );
    assert!(errors[0] > errors[1] && errors[1] > errors[2], "{errors:?}");
    assert!(errors[0] > 100.0 * errors[2], "{errors:?}");
}

/// The energy account from the outputs closes with the crank pin or the main bearing worn, and
/// its residual over one revolution falls at least 100× from rtol 1e-4 to 1e-8: each alone dry
/// (without and with friction, whose moments act on the crank and on the turning rod eye) and
/// lubricated, both pins dry and both lubricated, and all three joints dry (also under oblique
/// gravity, which loads the free crank's centre) and all three lubricated (rigid rod and 4 modes).
#[test]
fn energy_balance_converges_with_a_worn_crank_pin_and_main_bearing() {
    use JointModel::{Dry, Ideal, Lubricated};
    for rod_formulation in [RodFormulation::Rigid, RodFormulation::CraigBampton] {
        // (name, main bearing, crank pin, rod–slider joint, friction at the worn crank joint,
        // gravity)
        let cases = [
            ("crank pin dry", Ideal, Dry, Ideal, 0.0, 0.0),
            ("crank pin dry, μ = 0.2", Ideal, Dry, Ideal, 0.2, 0.0),
            ("crank pin lubricated", Ideal, Lubricated, Ideal, 0.0, 0.0),
            ("both pins dry", Ideal, Dry, Dry, 0.0, 0.0),
            (
                "both pins lubricated",
                Ideal,
                Lubricated,
                Lubricated,
                0.0,
                0.0,
            ),
            ("main bearing dry", Dry, Ideal, Ideal, 0.0, 0.0),
            ("main bearing dry, μ = 0.2", Dry, Ideal, Ideal, 0.2, 0.0),
            (
                "main bearing lubricated",
                Lubricated,
                Ideal,
                Ideal,
                0.0,
                0.0,
            ),
            ("all three dry", Dry, Dry, Dry, 0.0, 0.0),
            ("all three dry, gravity", Dry, Dry, Dry, 0.0, 9.81),
            (
                "all three lubricated",
                Lubricated,
                Lubricated,
                Lubricated,
                0.0,
                0.0,
            ),
        ];
        for (name, main_bearing, crank_pin, slider_pin, friction, gravity) in cases {
            let residual = |relative_tolerance| {
                let mut p = crank_pin_worn(
                    Parameters {
                        rod_formulation,
                        relative_tolerance,
                        gravity,
                        gravity_angle: f64::to_radians(40.0),
                        ..Parameters::default()
                    },
                    crank_pin,
                    0.5e-3,
                );
                p.joint.model = slider_pin;
                p.crank_pin.friction = friction;
                p.main_bearing = JointParameters {
                    model: main_bearing,
                    friction,
                    ..JointParameters::benchmark()
                };
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

/// An independent formulation of benchmark A with a dry, frictionless crank-pin clearance and an
/// ideal rod–slider joint, written for this test: the rigid rod in the coordinates (x_s, φ) of its
/// slider end and its direction u = (cos φ, sin φ) from A to B, the crank turning at the
/// prescribed speed, Lagrange's equations
/// ```text
/// [m_s + m        (m l/2) sin φ ] [ẍ_s]   [F_x − (m l/2) φ̇² cos φ     ]
/// [(m l/2) sin φ  m l²/4 + J    ] [φ̈  ] = [l (F_x sin φ − F_y cos φ)]
/// ```
/// (m, J = m l²/12 the rod's mass and central inertia, F the force of the crank pin on the rod at
/// A = (x_s, 0) − l u, the Lankarani–Nikravesh contact of the pin P = r_c (cos θ, sin θ) in the
/// eye with the impact velocity latched at each onset), integrated by classical Runge–Kutta with a
/// fixed 2e-8 s step. Over the first 3 ms (free flight of the pin across the clearance, then its
/// impacts) the mechanism's slider position agrees within 1e-3 of the clearance and the crank
/// pin's peak force within 1 %.
#[test]
fn a_worn_crank_pin_agrees_with_an_independent_formulation() {
    let p = crank_pin_worn(
        Parameters {
            relative_tolerance: 1e-8,
            ..Parameters::benchmark_a()
        },
        JointModel::Dry,
        0.5e-3,
    );
    let (t_end, samples) = (3e-3, 300);
    let (_, rows) = run(p.clone(), t_end, samples);

    let (r_c, l, m_s) = (p.crank_length, p.rod.length, p.slider_mass);
    let (m, omega) = (p.rod.mass(), BENCHMARK_SPEED);
    let inertia = m * l * l / 12.0;
    let joint = p.crank_pin;
    let stiffness = joint.contact_stiffness();
    let chi = 0.75 * (1.0 - joint.restitution * joint.restitution);
    // State [x_s, φ, ẋ_s, φ̇] at t = 0: pin centred in the eye, the ideal mechanism's velocities.
    let mut y = [r_c + l, 0.0, 0.0, -r_c * omega / l];
    let mut impact_velocity: Option<f64> = None;
    let kinematics = |t: f64, y: &[f64; 4]| {
        let (sin_t, cos_t) = math::sin_cos(omega * t);
        let (sin_p, cos_p) = math::sin_cos(y[1]);
        let a = [y[0] - l * cos_p, -l * sin_p];
        let a_dot = [y[2] + l * sin_p * y[3], -l * cos_p * y[3]];
        let e = [r_c * cos_t - a[0], r_c * sin_t - a[1]];
        let e_dot = [
            -r_c * omega * sin_t - a_dot[0],
            r_c * omega * cos_t - a_dot[1],
        ];
        let norm = math::hypot(e[0], e[1]);
        let n = [e[0] / norm, e[1] / norm];
        (norm - joint.clearance, e_dot[0] * n[0] + e_dot[1] * n[1], n)
    };
    let rhs = |t: f64, y: &[f64; 4], latched: Option<f64>| {
        let (delta, delta_dot, n) = kinematics(t, y);
        let f_n = match (delta > 0.0, latched) {
            (true, Some(v0)) => {
                (stiffness * delta * delta.sqrt() * (1.0 + chi * delta_dot / v0)).max(0.0)
            }
            (true, None) => {
                let v0 = delta_dot.max(1e-4);
                (stiffness * delta * delta.sqrt() * (1.0 + chi * delta_dot / v0)).max(0.0)
            }
            _ => 0.0,
        };
        // The pin pushes the eye along n (the force on the journal is −F_N n).
        let f = [f_n * n[0], f_n * n[1]];
        let (sin_p, cos_p) = math::sin_cos(y[1]);
        let (m11, m12, m22) = (m_s + m, 0.5 * m * l * sin_p, m * l * l / 4.0 + inertia);
        let r1 = f[0] - 0.5 * m * l * y[3] * y[3] * cos_p;
        let r2 = l * (f[0] * sin_p - f[1] * cos_p);
        let det = m11 * m22 - m12 * m12;
        let dy = [
            y[2],
            y[3],
            (m22 * r1 - m12 * r2) / det,
            (m11 * r2 - m12 * r1) / det,
        ];
        (dy, f_n)
    };
    let h = 2e-8;
    let steps_per_sample = (t_end / samples as f64 / h).round() as usize;
    let mut t = 0.0;
    let (mut worst_position, mut peak_force, mut reference_peak) = (0.0f64, 0.0f64, 0.0f64);
    for row in &rows[1..] {
        for _ in 0..steps_per_sample {
            let stage = |y: &[f64; 4], k: &[f64; 4], c: f64| {
                std::array::from_fn::<f64, 4, _>(|i| y[i] + c * k[i])
            };
            let (k1, _) = rhs(t, &y, impact_velocity);
            let (k2, _) = rhs(t + 0.5 * h, &stage(&y, &k1, 0.5 * h), impact_velocity);
            let (k3, _) = rhs(t + 0.5 * h, &stage(&y, &k2, 0.5 * h), impact_velocity);
            let (k4, _) = rhs(t + h, &stage(&y, &k3, h), impact_velocity);
            let (before, before_rate, _) = kinematics(t, &y);
            y = std::array::from_fn(|i| {
                y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i])
            });
            t += h;
            let (after, after_rate, _) = kinematics(t, &y);
            if after > 0.0 && impact_velocity.is_none() {
                let s = if before < 0.0 {
                    -before / (after - before)
                } else {
                    0.0
                };
                impact_velocity = Some((before_rate + s * (after_rate - before_rate)).max(1e-4));
            } else if after <= 0.0 {
                impact_velocity = None;
            }
            reference_peak = reference_peak.max(rhs(t, &y, impact_velocity).1);
        }
        worst_position = worst_position.max((row.slider_position - y[0]).abs());
        peak_force = peak_force.max(row.crank_pin_force_peak);
    }
    let force_error = (peak_force - reference_peak).abs() / reference_peak;
    println!(
        "crank-pin clearance vs the independent formulation over 3 ms: slider position within \
         {worst_position:.2e} m, peak crank-pin force {peak_force:.1} N against {reference_peak:.1} N \
         ({:.3} %)",
        100.0 * force_error
    );
    assert!(
        reference_peak > 1e3,
        "{reference_peak} N: no impact in the window"
    );
    assert!(
        worst_position < 1e-3 * joint.clearance,
        "{worst_position:e} m"
    );
    assert!(force_error < 0.01, "{force_error:e}");
}
