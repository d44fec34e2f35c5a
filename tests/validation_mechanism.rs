//! The slider-crank against closed-form kinematics, energy conservation and balance, the
//! clearance → 0 limit, benchmark A's impact physics, the lubricated orbit, and the determinism
//! the FMU relies on.

// Test code: a failed unwrap is a failed test, with its message.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use flexible_slider_crank::ancf::RodProperties;
use flexible_slider_crank::integrator::Method;
use flexible_slider_crank::math;
use flexible_slider_crank::params::{
    BENCHMARK_SPEED, ContactLaw, DriveMode, JointModel, RodFormulation,
};
use flexible_slider_crank::{Input, Outputs, Parameters, Simulation};

const REVOLUTION: f64 = std::f64::consts::TAU / BENCHMARK_SPEED;

/// Outputs at `n` equal intervals up to `t_end` (first row at t = 0).
fn run(p: Parameters, t_end: f64, n: usize) -> (Simulation, Vec<Outputs>) {
    let mut sim = Simulation::new(p).unwrap();
    let mut rows = vec![sim.outputs().unwrap()];
    for i in 1..=n {
        sim.advance_to(t_end * i as f64 / n as f64).unwrap();
        rows.push(sim.outputs().unwrap());
    }
    (sim, rows)
}

/// Rigid rod, ideal joints, 5000 rpm: slider x, ẋ, ẍ equal the closed form
/// x = r cos θ + √(l² − r² sin² θ) and its derivatives to 1e-6 over two revolutions
/// (relative to each quantity's amplitude; integrator rtol 1e-10).
#[test]
fn rigid_ideal_slider_follows_closed_form_kinematics() {
    let p = Parameters {
        rod_formulation: RodFormulation::Rigid,
        joint_model: JointModel::Ideal,
        relative_tolerance: 1e-10,
        ..Parameters::default()
    };
    let (r, l, w) = (p.crank_length, p.rod.length, BENCHMARK_SPEED);
    let (_, rows) = run(p, 2.0 * REVOLUTION, 400);
    let (mut ex, mut ev, mut ea) = (0.0f64, 0.0f64, 0.0f64);
    for o in &rows {
        let th = w * o.time;
        let (s, c) = math::sin_cos(th);
        let root = (l * l - r * r * s * s).sqrt();
        let x = r * c + root;
        let v = -r * w * s - r * r * w * s * c / root;
        let a = -r * w * w * c
            - r * r * w * w * (c * c - s * s) / root
            - r.powi(4) * w * w * s * s * c * c / root.powi(3);
        ex = ex.max((o.slider_position - x).abs() / (r + l));
        ev = ev.max((o.slider_velocity - v).abs() / (r * w));
        ea = ea.max((o.slider_acceleration - a).abs() / (r * w * w * (1.0 + r / l)));
        assert!((o.crank_angle - th).abs() < 1e-9);
    }
    println!("rigid ideal vs closed form: max rel. errors x {ex:.2e}, v {ev:.2e}, a {ea:.2e}");
    assert!(ex < 1e-6 && ev < 1e-6 && ea < 1e-6);
    let peak = rows
        .iter()
        .map(|o| o.slider_acceleration.abs())
        .fold(0.0, f64::max);
    // docs/model.md: ω² r (1 + r/l) = 19 419 m/s² at θ = 0.
    assert!(
        (peak - 19_419.0).abs() < 1.0,
        "peak slider acceleration {peak}"
    );
}

/// With every rod and joint model, speed-driven for one revolution,
/// T + U + V_c − W_drive − W_joint stays constant. The residual is reported relative to the
/// largest kinetic energy; with rtol = 1e-8 it must stay below 1e-5.
#[test]
fn energy_balance_holds_for_every_model() {
    for rod in [
        RodFormulation::Rigid,
        RodFormulation::CraigBampton,
        RodFormulation::Ancf,
    ] {
        for joint in [JointModel::Ideal, JointModel::Dry, JointModel::Lubricated] {
            let p = Parameters {
                rod_formulation: rod,
                joint_model: joint,
                n_elements: 4,
                n_modes: 2,
                friction: 0.01,
                relative_tolerance: 1e-8,
                ..Parameters::default()
            };
            let mut sim = Simulation::new(p).unwrap();
            let e0 = sim.energies().balance();
            let (mut residual, mut kinetic) = (0.0f64, 0.0f64);
            for i in 1..=60 {
                sim.advance_to(REVOLUTION * i as f64 / 60.0).unwrap();
                let e = sim.energies();
                residual = residual.max((e.balance() - e0).abs());
                kinetic = kinetic.max(e.kinetic);
            }
            let rel = residual / kinetic;
            println!(
                "{rod:?} rod, {joint:?} joint: energy-balance residual {rel:.2e} of max kinetic energy"
            );
            assert!(rel < 1e-5, "{rod:?}/{joint:?}: residual {rel:e}");
        }
    }
}

/// Restitution 1, no friction, free-spinning torque-driven crank with
/// zero torque: total energy is conserved to 1e-4 over one second (83 revolutions, ~300 impacts).
/// The model's conservation is checked with the non-dissipative explicit reference method; the
/// implicit method damps unresolved frequencies by design (its dissipation is measured by
/// `implicit_dissipation_falls_with_the_tolerance`).
#[test]
fn free_spinning_elastic_mechanism_conserves_energy() {
    for rod in [RodFormulation::Rigid, RodFormulation::CraigBampton] {
        let p = Parameters {
            rod_formulation: rod,
            method: Method::DormandPrince,
            relative_tolerance: 1e-8,
            // 10 ms intervals of the explicit method at rtol 1e-8 take ~55 000 steps each.
            max_steps_per_interval: 1_000_000,
            ..free_spin_parameters()
        };
        let run = free_spin(p, 0.01);
        println!(
            "{rod:?} rod, elastic contact, 1 s free spin: max relative energy change {:.2e} ({} steps)",
            run.change, run.steps
        );
        assert!(run.change < 1e-4, "{rod:?}: {:e}", run.change);
    }
}

/// The free-spinning elastic mechanism: restitution 1, no friction, torque drive with zero torque,
/// a 2-element rod (Craig–Bampton with 2 mode shapes unless changed).
fn free_spin_parameters() -> Parameters {
    Parameters {
        n_elements: 2,
        n_modes: 2,
        drive_mode: DriveMode::Torque,
        restitution: 1.0,
        friction: 0.0,
        ..Parameters::default()
    }
}

/// Total energy (kinetic + strain + contact) over 100 communication intervals of a free spin,
/// relative to the start.
struct FreeSpin {
    /// Largest |change|.
    change: f64,
    /// Largest loss (0 if it never fell).
    loss: f64,
    steps: u64,
}

fn free_spin(p: Parameters, interval: f64) -> FreeSpin {
    let mut sim = Simulation::new(p).unwrap();
    let e = sim.energies();
    let total0 = e.kinetic + e.strain + e.contact;
    let (mut change, mut loss) = (0.0f64, 0.0f64);
    for i in 1..=100 {
        sim.advance_to(interval * i as f64).unwrap();
        let e = sim.energies();
        assert_eq!(e.drive_work, 0.0);
        let relative = (e.kinetic + e.strain + e.contact - total0) / total0;
        change = change.max(relative.abs());
        loss = loss.max(-relative);
    }
    FreeSpin {
        change,
        loss,
        steps: sim.stats().steps,
    }
}

/// The free spin (Craig–Bampton rod, 8 revolutions of impacts in 0.1 s) with `method`: the largest
/// loss of total energy relative to the start, and the steps taken.
fn free_spin_energy_loss(method: Method, rtol: f64, spectral_radius: f64) -> (f64, u64) {
    let p = Parameters {
        method,
        relative_tolerance: rtol,
        spectral_radius,
        ..free_spin_parameters()
    };
    let run = free_spin(p, 1e-3);
    (run.loss, run.steps)
}

/// The implicit method's numerical dissipation is controlled by the tolerance: on the free-spinning
/// elastic mechanism, the largest loss of total energy falls by more than 10× per 100× tighter
/// tolerance.
#[test]
fn implicit_dissipation_falls_with_the_tolerance() {
    let mut losses = Vec::new();
    for rtol in [1e-2, 1e-4, 1e-6] {
        let (worst, steps) = free_spin_energy_loss(Method::Esdirk, rtol, 0.8);
        println!(
            "implicit, rtol {rtol:e}: largest relative energy loss over 0.1 s {worst:.2e} ({steps} steps)"
        );
        losses.push(worst);
    }
    // Measured: 1.6e-2, 7.7e-4, 1.5e-5 (a 20–50× smaller loss per 100× tighter tolerance).
    assert!(
        losses[0] > 10.0 * losses[1] && losses[1] > 10.0 * losses[2],
        "{losses:?}"
    );
}

/// The generalized-α method's numerical dissipation is its parameter: on the free-spinning elastic
/// mechanism at rtol 1e-2, the largest loss of total energy grows as `solver.spectralRadius` falls
/// from 1 (no numerical dissipation) to 0.
#[test]
fn generalized_alpha_dissipation_follows_the_spectral_radius() {
    let mut losses = Vec::new();
    for rho in [1.0, 0.8, 0.0] {
        let (worst, steps) = free_spin_energy_loss(Method::GeneralizedAlpha, 1e-2, rho);
        println!(
            "generalized-α, ρ∞ = {rho}: largest relative energy loss over 0.1 s {worst:.2e} ({steps} steps)"
        );
        losses.push(worst);
    }
    // Measured: 0 (ρ∞ = 1, 107 977 steps), 9.3e-3 (0.8, 30 666), 2.0e-2 (0, 8 792).
    assert!(losses[0] < losses[1] && losses[1] < losses[2], "{losses:?}");
}

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
                rod_formulation: RodFormulation::Rigid,
                contact_law: law,
                restitution: 0.3,
                crank_initial_speed: speed,
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
            joint_model: JointModel::Ideal,
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
                    clearance: c,
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
/// free flight (zero force) and of contact. Figures are printed for the README.
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
                first_velocity = sim.mechanism().contact_state().impact_velocity;
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
        rod_formulation: RodFormulation::Rigid,
        joint_model: JointModel::Lubricated,
        crank_initial_speed: speed,
        ..Parameters::default()
    };
    let period = std::f64::consts::TAU / speed;
    let c = p.clearance;
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

/// The result does not depend on how [0, T] is cut into advance_to calls beyond the
/// integration error itself (measured as the change from rtol to rtol/100; impacts amplify it far
/// above rtol), and restore-then-advance is bit-identical to never having stopped.
#[test]
fn cuts_do_not_matter_and_restore_is_bit_exact() {
    let p = Parameters {
        n_elements: 4,
        n_modes: 2,
        relative_tolerance: 1e-9,
        ..Parameters::default()
    };
    let t_end = 0.5 * REVOLUTION;
    let final_position = |p: Parameters, cuts: usize| run(p, t_end, cuts).1[cuts].slider_position;
    let one = final_position(p.clone(), 1);
    let many = final_position(p.clone(), 37);
    let tighter = final_position(
        Parameters {
            relative_tolerance: 1e-11,
            ..p.clone()
        },
        1,
    );
    let (cut_effect, integration_error) = ((one - many).abs(), (one - tighter).abs());
    println!(
        "slider position after half a revolution: one call vs 37 calls differ by {cut_effect:.2e} m; \
         integration error (rtol 1e-9 vs 1e-11) {integration_error:.2e} m"
    );
    assert!(
        cut_effect <= integration_error,
        "{cut_effect:e} > {integration_error:e}"
    );

    assert_restore_is_bit_exact(p, t_end);
    // The generalized-α method carries its algorithmic accelerations in the snapshot.
    assert_restore_is_bit_exact(
        Parameters {
            method: Method::GeneralizedAlpha,
            relative_tolerance: 1e-4,
            n_elements: 4,
            n_modes: 2,
            ..Parameters::default()
        },
        t_end,
    );
}

/// A snapshot at t_end/2, advanced to t_end in a new simulation, equals the uninterrupted run bit
/// for bit (state and statistics).
fn assert_restore_is_bit_exact(p: Parameters, t_end: f64) {
    let mut sim = Simulation::new(p.clone()).unwrap();
    sim.advance_to(0.5 * t_end).unwrap();
    let snap = sim.snapshot();
    sim.advance_to(t_end).unwrap();
    let reference = sim.state().to_vec();
    let mut other = Simulation::new(p).unwrap();
    other.restore(&snap).unwrap();
    other.advance_to(t_end).unwrap();
    assert_eq!(
        other.state(),
        &reference[..],
        "restore-then-advance is not bit-identical"
    );
    assert_eq!(other.stats(), sim.stats());
}

/// Bad input is a typed error naming the parameter.
#[test]
fn inconsistent_geometry_is_rejected() {
    let p = Parameters {
        crank_length: 0.2,
        ..Parameters::default()
    };
    let err = Simulation::new(p).unwrap_err().to_string();
    assert!(err.starts_with("rod.length = 0.12 is outside"), "{err}");
}

/// Bounded work: an interval that needs more internal steps than
/// `solver.maxStepsPerInterval` ends with an error that names the limit and the likely causes,
/// at the last accepted step, and the simulation stays usable (snapshot, restore with a higher
/// limit, advance).
#[test]
fn work_limit_ends_an_interval_with_a_named_cause() {
    let p = Parameters {
        friction: 0.3,
        max_steps_per_interval: 20,
        ..Parameters::default()
    };
    let mut sim = Simulation::new(p.clone()).unwrap();
    let message = sim.advance_to(2e-3).unwrap_err().to_string();
    println!("{message}");
    for name in [
        "solver.maxStepsPerInterval = 20",
        "joint.friction = 0.3",
        "rod.stiffnessDamping",
        "solver.relativeTolerance",
    ] {
        assert!(message.contains(name), "{message}");
    }
    let stopped = sim.time();
    assert!(stopped > 0.0 && stopped < 2e-3, "{stopped}");
    let attempts = sim.stats().steps + sim.stats().rejected;
    assert_eq!(attempts, 20);
    // Raising the limit goes on from where the interval stopped.
    let snapshot = sim.snapshot();
    let mut other = Simulation::new(Parameters {
        max_steps_per_interval: 50_000,
        ..p
    })
    .unwrap();
    other.restore(&snapshot).unwrap();
    other.advance_to(2e-3).unwrap();
    assert!(other.outputs().unwrap().slider_position.is_finite());
}

/// The energy account from the outputs alone: energy.kinetic + rod.deformationEnergy +
/// energy.contact + energy.gravity + energy.dissipated + energy.materialDamping −
/// energy.driveWork − energy.sliderWork, constant in exact arithmetic.
fn output_balance(o: &Outputs) -> f64 {
    o.kinetic_energy
        + o.deformation_energy
        + o.contact_energy
        + o.gravity_energy
        + o.dissipated_energy
        + o.material_damping
        - o.drive_work
        - o.slider_work
}

/// Largest |balance(t) − balance(0)| of the outputs over a run, relative to the largest kinetic
/// energy.
fn output_balance_residual(rows: &[Outputs]) -> f64 {
    let kinetic = rows.iter().fold(0.0f64, |m, o| m.max(o.kinetic_energy));
    let start = output_balance(&rows[0]);
    rows.iter()
        .fold(0.0f64, |m, o| m.max((output_balance(o) - start).abs()))
        / kinetic
}

/// Energy account: from the outputs alone the balance closes with the dry joint and
/// gravity (before energy.contact was an output, it was off by 2.6e-3 of the kinetic energy on
/// benchmark B).
#[test]
fn energy_outputs_close_the_balance() {
    let p = Parameters {
        gravity: 9.81,
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
/// and a slider force, with friction 0.1, with gravity 9.81 and with material damping 1e-5 s
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
                friction: 0.1,
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
            sim.set_input(Input::DriveTorque, torque);
            sim.set_input(Input::SliderForce, slider_force);
            let mut rows = vec![sim.outputs().unwrap()];
            for i in 1..=60 {
                sim.advance_to(REVOLUTION * f64::from(i) / 60.0).unwrap();
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

/// Validity warnings over 2 ms in steps of 0.1 ms (until a step fails).
fn warnings_over_2_ms(mut sim: Simulation) -> Vec<String> {
    let mut warnings = Vec::new();
    for i in 1..=20 {
        if sim.advance_to(1e-4 * f64::from(i)).is_err() {
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
    stiff_drive.crank_initial_speed = 0.0;
    let cases = [
        (
            "joint penetration",
            Parameters {
                journal_radius: 1e-4,
                ..Parameters::default()
            },
        ),
        (
            "slider position",
            Parameters {
                crank_initial_speed: 1e4,
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
            crank_initial_speed: 1e4,
            ..Parameters::default()
        })
        .unwrap(),
    );
    assert!(!at_limit.iter().any(|w| w.contains("crank speed")));
    let mut sim = Simulation::new(stiff_drive).unwrap();
    sim.set_input(Input::DriveTorque, 1e6);
    let warnings = warnings_over_2_ms(sim);
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
                crank_initial_speed: 0.0,
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
/// is too stiff to integrate: the interval fails with a message naming the clearance and the
/// joint model, and the simulation stays at its last accepted step.
#[test]
fn a_failing_step_names_the_likely_parameters() {
    let p = Parameters {
        joint_model: JointModel::Lubricated,
        clearance: 1e-9,
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
