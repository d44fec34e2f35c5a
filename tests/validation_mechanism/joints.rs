//! The clearance joints: every contact law, the clearance → 0 limit, benchmark A's impact physics and the lubricated orbit.

use super::*;

/// Low restitution (c_e = 0.3) with every contact law, at 50 rpm (slow,
/// persistent contact) and at 5000 rpm (impacts): the normal force never pulls (F · e ≤ 0 in
/// contact), the dissipated energy never decreases, the energy balance holds, the run completes.
#[test]
fn every_contact_law_handles_low_restitution() {
    for law in [
        ContactLaw::LankaraniNikravesh,
        ContactLaw::Flores,
        ContactLaw::HuGuo,
    ] {
        for rpm in [50.0, 5000.0] {
            let speed = rpm * std::f64::consts::TAU / 60.0;
            let p = Parameters {
                joint: JointParameters {
                    contact_law: law,
                    restitution: 0.3,
                    ..Parameters::default().joint
                },
                rod_formulation: RodFormulation::Rigid,
                crank_initial_speed: Some(speed),
                relative_tolerance: 1e-6,
                ..Parameters::default()
            };
            // A third of a revolution at 50 rpm, a whole one at 5000 rpm.
            let t_end = if rpm < 100.0 { 0.4 } else { REVOLUTION };
            let mut sim = Simulation::new(p).unwrap();
            let e0 = sim.energies().balance();
            let (mut residual, mut kinetic, mut dissipated) = (0.0f64, 0.0f64, 0.0f64);
            let mut contact_samples = 0;
            for i in 1..=400 {
                sim.advance_to(t_end * f64::from(i) / 400.0).unwrap();
                let o = sim.outputs().unwrap();
                if o.in_contact {
                    contact_samples += 1;
                    let pull =
                        o.joint_force_x * o.eccentricity_x + o.joint_force_y * o.eccentricity_y;
                    assert!(
                        pull <= 0.0,
                        "{law:?} at {rpm} rpm: tensile force, F·e = {pull:e}"
                    );
                }
                let e = sim.energies();
                kinetic = kinetic.max(e.kinetic);
                assert!(
                    e.dissipated() >= dissipated - 1e-9 * kinetic,
                    "{law:?} at {rpm} rpm: dissipated energy fell from {dissipated:e} to {:e}",
                    e.dissipated()
                );
                dissipated = e.dissipated();
                residual = residual.max((e.balance() - e0).abs());
            }
            let rel = residual / kinetic;
            println!(
                "{law:?}, c_e = 0.3, {rpm} rpm: in contact at {contact_samples}/400 samples, \
                 dissipated {dissipated:.3e} J, energy-balance residual {rel:.1e} of max kinetic energy"
            );
            assert!(contact_samples > 0);
            assert!(rel < 1e-5, "{law:?} at {rpm} rpm: residual {rel:e}");
        }
    }
}

/// RMS of the slider-acceleration difference to the ideal joint over the second revolution.
fn acceleration_error(p: Parameters, ideal: &[Outputs]) -> f64 {
    let (_, rows) = run(p, 2.0 * REVOLUTION, 400);
    let second = &rows[200..];
    let sum: f64 = second
        .iter()
        .zip(&ideal[200..])
        .map(|(a, b)| (a.slider_acceleration - b.slider_acceleration).powi(2))
        .sum();
    (sum / second.len() as f64).sqrt()
}

/// Clearance → 0 with the (stiffening) Hertz contact: the dry joint's slider
/// acceleration approaches the ideal joint's, the error falling monotonically over
/// c = 1e-4, 1e-5, 1e-6 m.
#[test]
fn vanishing_clearance_approaches_the_ideal_joint() {
    let base = Parameters {
        rod_formulation: RodFormulation::Rigid,
        ..Parameters::default()
    };
    let (_, ideal) = run(
        Parameters {
            joint: JointParameters {
                model: JointModel::Ideal,
                ..base.clone().joint
            },
            ..base.clone()
        },
        2.0 * REVOLUTION,
        400,
    );
    let errors: Vec<f64> = [1e-4, 1e-5, 1e-6]
        .iter()
        .map(|&c| {
            acceleration_error(
                Parameters {
                    joint: JointParameters {
                        clearance: c,
                        ..base.clone().joint
                    },
                    ..base.clone()
                },
                &ideal,
            )
        })
        .collect();
    println!(
        "RMS slider-acceleration error vs ideal for c = 1e-4, 1e-5, 1e-6 m: {errors:.1?} m/s²"
    );
    assert!(errors[0] > errors[1] && errors[1] > errors[2], "{errors:?}");
    assert!(errors[2] < 0.05 * 19_419.0, "{errors:?}");
}

/// Benchmark A (rigid rod, 0.5 mm dry clearance, c_e = 0.9, μ = 0, 5000 rpm):
/// free flight first (the journal starts centred), then impacts; over two revolutions the joint
/// force and slider acceleration show impact spikes well above the ideal joint's, and periods of
/// free flight (zero force) and of contact. Figures are printed for the user guide.
#[test]
fn benchmark_a_shows_flight_impact_and_contact() {
    let p = Parameters::benchmark_a();
    let mut sim = Simulation::new(p.clone()).unwrap();
    let dt = 2e-6;
    let steps = (2.0 * REVOLUTION / dt) as usize;
    let (mut first_contact, mut first_velocity, mut peak_first) = (None, 0.0, 0.0f64);
    let (mut peak_force, mut peak_acc, mut flight, mut contact) = (0.0f64, 0.0f64, 0usize, 0usize);
    for i in 1..=steps {
        sim.advance_to(i as f64 * dt).unwrap();
        let o = sim.outputs().unwrap();
        if o.in_contact {
            contact += 1;
            if first_contact.is_none() {
                first_contact = Some(o.time);
                first_velocity = sim.contacts()[JointRole::RodSlider].impact_velocity;
            }
            if first_contact.is_some_and(|t| o.time < t + 1e-4) {
                peak_first = peak_first.max(o.joint_force);
            }
        } else {
            flight += 1;
        }
        peak_force = peak_force.max(o.joint_force);
        peak_acc = peak_acc.max(o.slider_acceleration.abs());
    }
    let t0 = first_contact.expect("no contact in two revolutions");
    println!(
        "benchmark A: first contact at t = {t0:.4e} s (crank {:.1}°), impact velocity {first_velocity:.3} m/s, \
         first peak force {peak_first:.0} N; over two revolutions: peak force {peak_force:.0} N, \
         max |slider acceleration| {peak_acc:.0} m/s² ({:.1}× the ideal peak), {:.0} % of samples in contact",
        (t0 * BENCHMARK_SPEED).to_degrees(),
        peak_acc / 19_419.0,
        100.0 * contact as f64 / (contact + flight) as f64
    );
    assert!(first_velocity > 0.01, "impact velocity {first_velocity}");
    // Ideal-joint reaction peaks at 2.7 kN (rigid ideal run); impacts must exceed it clearly.
    assert!(peak_force > 2.0 * 2_719.0, "peak force {peak_force}");
    assert!(peak_acc > 2.0 * 19_419.0, "peak acceleration {peak_acc}");
    assert!(
        contact > 0 && flight > steps / 20,
        "flight {flight}, contact {contact}"
    );
}

/// Lubricated joint (benchmark C film, rigid rod) at moderate speed (1000 rpm): the
/// journal orbit stays inside the clearance circle and the film force is smooth: over the second
/// revolution (after the start-up transient in which the centred journal is pushed off-centre)
/// no sample-to-sample change exceeds 2 % of the peak at a 10 µs output interval.
#[test]
fn lubricated_orbit_stays_inside_the_clearance() {
    let speed = 1000.0 * std::f64::consts::TAU / 60.0;
    let p = Parameters {
        joint: JointParameters {
            model: JointModel::Lubricated,
            ..Parameters::default().joint
        },
        rod_formulation: RodFormulation::Rigid,
        crank_initial_speed: Some(speed),
        ..Parameters::default()
    };
    let period = std::f64::consts::TAU / speed;
    let c = p.joint.clearance;
    let (_, rows) = run(p, 2.0 * period, 12_000);
    let max_ratio = rows
        .iter()
        .map(|o| math::hypot(o.eccentricity_x, o.eccentricity_y) / c)
        .fold(0.0, f64::max);
    let peak = rows.iter().map(|o| o.joint_force).fold(0.0, f64::max);
    let jump = rows[6_000..]
        .windows(2)
        .map(|w| (w[1].joint_force - w[0].joint_force).abs())
        .fold(0.0, f64::max);
    println!(
        "lubricated, 1000 rpm: max eccentricity ratio {max_ratio:.3}, peak film force {peak:.1} N, largest step change {:.2} %",
        100.0 * jump / peak
    );
    assert!(max_ratio < 1.0 && rows.iter().all(|o| !o.in_contact));
    assert!(jump < 0.02 * peak);
}
