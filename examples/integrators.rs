//! Integrator comparison: every rod model × joint model of benchmark B/C (two revolutions
//! at 5000 rpm, the DefaultExperiment), integrated with the explicit Dormand–Prince 5(4) at its
//! loosest accepted tolerance, with the implicit ESDIRK5(4) at the default tolerance, and with the
//! generalized-α method (default ρ∞) at the default and at its loosest accepted tolerance.
//!
//! For each run: wall time, accepted and rejected steps, right-hand-side evaluations (Jacobians
//! included), Newton iterations, Jacobians, LU factorisations, and the accuracy reached: the
//! relative error of the peak joint force and of the peak penetration over the two revolutions
//! (sampled every 10 µs) against a converged run of the same model (implicit, rtol 1e-8).
//!
//! `cargo run --release --example integrators` prints a Markdown table.

use std::error::Error;
use std::time::Instant;

use flexible_slider_crank::integrator::{Method, Stats};
use flexible_slider_crank::params::JointParameters;
use flexible_slider_crank::params::{EXPLICIT_MAX_TOLERANCE, JointModel, RodFormulation};
use flexible_slider_crank::reduction::Boundary;
use flexible_slider_crank::{Parameters, Simulation};

/// Samples over the DefaultExperiment's 24 ms.
const SAMPLES: usize = 2400;
/// Tolerance of the reference runs.
const REFERENCE_TOLERANCE: f64 = 1e-8;

/// Peaks, statistics and wall time of one run.
struct Run {
    force: f64,
    penetration: f64,
    stats: Stats,
    seconds: f64,
}

fn run(p: Parameters) -> Result<Run, Box<dyn Error>> {
    let start = Instant::now();
    let mut sim = Simulation::new(p)?;
    let (mut force, mut penetration) = (0.0f64, 0.0f64);
    for i in 1..=SAMPLES {
        sim.advance_to(0.024 * i as f64 / SAMPLES as f64)?;
        let o = sim.outputs()?;
        force = force.max(o.joint_force);
        penetration = penetration.max(o.penetration);
    }
    Ok(Run {
        force,
        penetration,
        stats: sim.stats(),
        seconds: start.elapsed().as_secs_f64(),
    })
}

fn relative(value: f64, reference: f64) -> String {
    if reference > 0.0 {
        format!("{:+.1e}", (value - reference) / reference)
    } else {
        "–".into()
    }
}

fn main() -> Result<(), Box<dyn Error>> {
    let rods = [
        ("rigid", RodFormulation::Rigid, 0, Boundary::Pins),
        (
            "CB 4 modes, pins",
            RodFormulation::CraigBampton,
            4,
            Boundary::Pins,
        ),
        (
            "CB 4 modes, positions and slopes",
            RodFormulation::CraigBampton,
            4,
            Boundary::PositionsAndSlopes,
        ),
        (
            "CB 8 modes, pins",
            RodFormulation::CraigBampton,
            8,
            Boundary::Pins,
        ),
        ("full ANCF", RodFormulation::Ancf, 0, Boundary::Pins),
    ];
    let methods = [
        ("explicit", Method::DormandPrince, EXPLICIT_MAX_TOLERANCE),
        (
            "implicit",
            Method::Esdirk,
            Parameters::default().relative_tolerance,
        ),
        (
            "generalized-α",
            Method::GeneralizedAlpha,
            Parameters::default().relative_tolerance,
        ),
        ("generalized-α", Method::GeneralizedAlpha, 3e-2),
    ];
    println!(
        "| rod (8 elements) | joint | method | rtol | wall [s] | steps | rejected | evaluations | Newton it. | Jacobians | LU | peak force error | peak penetration error |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for (rod_name, rod_formulation, n_modes, boundary) in rods {
        for joint in [JointModel::Ideal, JointModel::Dry, JointModel::Lubricated] {
            let base = Parameters {
                joint: JointParameters {
                    model: joint,
                    ..Parameters::default().joint
                },
                rod_formulation,
                n_modes,
                boundary,
                ..Parameters::default()
            };
            let reference = run(Parameters {
                method: Method::Esdirk,
                relative_tolerance: REFERENCE_TOLERANCE,
                ..base.clone()
            })?;
            for (method_name, method, rtol) in methods {
                let r = run(Parameters {
                    method,
                    relative_tolerance: rtol,
                    ..base.clone()
                })?;
                let s = r.stats;
                println!(
                    "| {rod_name} | {joint:?} | {method_name} | {rtol:e} | {:.3} | {} | {} | {} | {} | {} | {} | {} | {} |",
                    r.seconds,
                    s.steps,
                    s.rejected,
                    s.evaluations,
                    s.newton_iterations,
                    s.jacobians,
                    s.factorizations,
                    relative(r.force, reference.force),
                    relative(r.penetration, reference.penetration),
                );
            }
        }
    }
    Ok(())
}
