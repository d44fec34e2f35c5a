//! The slider-crank against closed-form kinematics, energy conservation and the integrators' dissipation.

use super::*;

/// Rigid rod, ideal joints, 5000 rpm: slider x, ẋ, ẍ equal the closed form
/// x = r cos θ + √(l² − r² sin² θ) and its derivatives to 1e-6 over two revolutions
/// (relative to each quantity's amplitude; integrator rtol 1e-10).
#[test]
fn rigid_ideal_slider_follows_closed_form_kinematics() {
    let p = Parameters {
        joint: JointParameters {
            model: JointModel::Ideal,
            ..Parameters::default().joint
        },
        rod_formulation: RodFormulation::Rigid,
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
    for (rod, quadrature) in [
        (RodFormulation::Rigid, Quadrature::Full),
        (RodFormulation::CraigBampton, Quadrature::Full),
        (RodFormulation::CraigBampton, Quadrature::Sampled),
        (RodFormulation::Ancf, Quadrature::Full),
    ] {
        for joint in [JointModel::Ideal, JointModel::Dry, JointModel::Lubricated] {
            let p = Parameters {
                joint: JointParameters {
                    model: joint,
                    friction: 0.01,
                    ..Parameters::default().joint
                },
                rod_formulation: rod,
                quadrature,
                n_elements: 4,
                n_modes: 2,
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
                "{rod:?} rod ({quadrature:?}), {joint:?} joint: energy-balance residual {rel:.2e} \
                 of max kinetic energy"
            );
            assert!(
                rel < 1e-5,
                "{rod:?}/{quadrature:?}/{joint:?}: residual {rel:e}"
            );
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
        joint: JointParameters {
            restitution: 1.0,
            friction: 0.0,
            ..Parameters::default().joint
        },
        n_elements: 2,
        n_modes: 2,
        drive_mode: DriveMode::Torque,
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

/// Gravity in any direction of the plane: a crank held at rest (speed drive at 0 rad/s, ideal
/// joint) carries the weights of crank, rod and slider, and the drive torque is the virtual-work
/// value τ = −Σ mᵢ g·∂r_Gᵢ/∂θ, with gravity across the guide (gravityAngle = 0, along −y), along
/// the guide (−90°: a vertical guide with the slider above the pivot) and oblique (30°), for the
/// rigid rod (to 1e-9) and the 4-mode rod (to 1e-3: its static deformation moves the pins a little).
#[test]
fn a_crank_at_rest_carries_the_weights_in_any_direction() {
    let theta = 1.0;
    for (rod_formulation, tolerance) in [
        (RodFormulation::Rigid, 1e-9),
        (RodFormulation::CraigBampton, 1e-3),
    ] {
        for angle_deg in [0.0, -90.0, 30.0] {
            let p = Parameters {
                joint: JointParameters {
                    model: JointModel::Ideal,
                    ..Parameters::default().joint
                },
                rod_formulation,
                gravity: 500.0,
                gravity_angle: f64::to_radians(angle_deg),
                crank_initial_angle: theta,
                crank_initial_speed: Some(0.0),
                relative_tolerance: 1e-8,
                ..Parameters::default()
            };
            let g = p.gravity_vector();
            let (r, l) = (p.crank_length, p.rod.length);
            let (s, c) = math::sin_cos(theta);
            let dx_s = -r * s - r * r * s * c / (l * l - r * r * s * s).sqrt();
            let virtual_work = p.crank_mass * g.dot(&(0.5 * r * nalgebra::Vector2::new(-s, c)))
                + p.rod.mass() * g.dot(&(0.5 * nalgebra::Vector2::new(-r * s + dx_s, r * c)))
                + p.slider_mass * g.x * dx_s;
            let (_, rows) = run(p, 2e-3, 4);
            for o in &rows {
                let error = (o.crank_torque + virtual_work).abs() / virtual_work.abs();
                assert!(
                    error < tolerance,
                    "{rod_formulation:?}, gravity at {angle_deg}°, t = {}: torque {} N m, \
                     virtual work {} N m",
                    o.time,
                    o.crank_torque,
                    -virtual_work
                );
            }
        }
    }
}

/// A speed run-up through interpolated inputs: the master ramps drive.speed from 1500 to 3000 rpm
/// in 50 ms, setting the value and its first derivative at every 1e-4 s communication point, then
/// holds it. Rigid rod, ideal joint, default tolerance: slider.acceleration at every communication
/// point equals the closed form ẍ = x''(θ) ω² + x'(θ) ω̇ of the ramp as the step ended (the
/// crank's angular acceleration included) within 1e-3 of its peak.
#[test]
fn outputs_follow_a_ramped_drive_speed() {
    let (omega0, omega1, ramp) = (
        50.0 * std::f64::consts::PI,
        100.0 * std::f64::consts::PI,
        0.05,
    );
    let alpha = (omega1 - omega0) / ramp;
    let p = Parameters {
        joint: JointParameters {
            model: JointModel::Ideal,
            ..Parameters::default().joint
        },
        rod_formulation: RodFormulation::Rigid,
        ..Parameters::default()
    };
    let (r, l) = (p.crank_length, p.rod.length);
    let speed = |t: f64| omega0 + alpha * t.min(ramp);
    let angle = |t: f64| {
        let t_ramp = t.min(ramp);
        omega0 * t_ramp + 0.5 * alpha * t_ramp * t_ramp + omega1 * (t - t_ramp)
    };
    let slider_acceleration = |t: f64, rate: f64| {
        let (s, c) = math::sin_cos(angle(t));
        let root = (l * l - r * r * s * s).sqrt();
        let dx = -r * s - r * r * s * c / root;
        let ddx =
            -r * c - r * r * (c * c - s * s) / root - r.powi(4) * s * s * c * c / root.powi(3);
        ddx * speed(t).powi(2) + dx * rate
    };
    let inputs = flexible_slider_crank::Inputs {
        drive_speed: omega0,
        ..Default::default()
    };
    let mut sim = Simulation::with_inputs(p, inputs).unwrap();
    let mut inputs = *sim.inputs();
    let h = 1e-4;
    let peak = r * omega1 * omega1 * (1.0 + r / l);
    let mut worst = 0.0f64;
    for k in 0..600 {
        let t = f64::from(k) * h;
        let rate = if t < ramp - 1e-12 { alpha } else { 0.0 };
        inputs.value.drive_speed = speed(t);
        inputs.derivatives[0].drive_speed = rate;
        sim.advance_with(&inputs, t + h).unwrap();
        let o = sim.outputs().unwrap();
        let error = (o.slider_acceleration - slider_acceleration(t + h, rate)).abs() / peak;
        worst = worst.max(error);
    }
    println!("ramped drive speed: largest slider.acceleration error {worst:.2e} of its peak");
    assert!(worst < 1e-3, "{worst:e}");
}
