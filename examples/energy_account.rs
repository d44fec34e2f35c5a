//! The energy account over 0.5 s (about 42 crank revolutions at 5000 rpm) at several tolerances:
//! the drive work and the residual of the balance of the outputs (T + U + V_c + V_g + D_joint +
//! D_material − W_drive − W_slider, constant in exact arithmetic), for the dry, lubricated and
//! ideal joints with the default 4-mode rod, and the dry and lubricated joints with the rigid rod.
//!
//! `cargo run --release --example energy_account [rtol …]` prints one Markdown row per joint and
//! tolerance (default tolerances: 1e-2, 1e-3, 1e-4).

use std::error::Error;
use std::time::Instant;

use flexible_slider_crank::params::JointParameters;
use flexible_slider_crank::params::{JointModel, RodFormulation};
use flexible_slider_crank::{Parameters, Simulation};

/// Simulated time \[s\].
const DURATION: f64 = 0.5;
/// Communication step \[s\].
const STEP: f64 = 1e-4;

fn main() -> Result<(), Box<dyn Error>> {
    let tolerances: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| a.parse())
        .collect::<Result<_, _>>()?;
    let tolerances = if tolerances.is_empty() {
        vec![1e-2, 1e-3, 1e-4]
    } else {
        tolerances
    };
    println!(
        "| rod | joint | rtol | energy.driveWork [J] | largest residual [J] | residual / drive work | steps | wall time [s] |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    for (rod_formulation, joint_model) in [
        (RodFormulation::CraigBampton, JointModel::Dry),
        (RodFormulation::CraigBampton, JointModel::Lubricated),
        (RodFormulation::CraigBampton, JointModel::Ideal),
        (RodFormulation::Rigid, JointModel::Dry),
        (RodFormulation::Rigid, JointModel::Lubricated),
    ] {
        for &rtol in &tolerances {
            let start = Instant::now();
            let mut sim = Simulation::new(Parameters {
                joint: JointParameters {
                    model: joint_model,
                    ..Parameters::default().joint
                },
                relative_tolerance: rtol,
                rod_formulation,
                ..Parameters::default()
            })?;
            let b0 = sim.outputs()?.energy_balance();
            let mut residual = 0.0f64;
            let n = (DURATION / STEP).round() as usize;
            let mut o = sim.outputs()?;
            for i in 1..=n {
                sim.advance_to(DURATION * i as f64 / n as f64)?;
                o = sim.outputs()?;
                residual = residual.max((o.energy_balance() - b0).abs());
            }
            println!(
                "| {rod_formulation:?} | {joint_model:?} | {rtol:e} | {:.2} | {residual:.3} | {:.2e} | {} | {:.2} |",
                o.drive_work,
                residual / o.drive_work.abs(),
                sim.stats().steps,
                start.elapsed().as_secs_f64()
            );
        }
    }
    Ok(())
}
