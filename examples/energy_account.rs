//! The energy account over 0.5 s (about 42 crank revolutions at 5000 rpm) at several tolerances,
//! one joint worn at a time: for the 4-mode and the rigid rod, each joint (rod–slider joint, crank
//! pin, main bearing) dry, lubricated with the short film and with the finite film, and every joint
//! ideal. Prints `energy.driveWork` and `energy.dissipated` at the end, the largest residual of the
//! outputs' balance (T + U + V_c + V_g + D_joint + D_material − W_drive − W_slider, constant in exact
//! arithmetic) relative to the drive work, and the right-hand-side evaluations.
//!
//! `cargo run --release --example energy_account [rtol …]` prints one Markdown row per case and
//! tolerance (default tolerances: 1e-2, 1e-3, 1e-5); a case integrated at a tighter tolerance than
//! asked (a dry main bearing, at 1e-3 at most: `Parameters::integration_tolerance`) prints the row
//! of the tolerance it is integrated at once.

use std::error::Error;

use flexible_slider_crank::params::{FilmModel, JointModel, JointParameters, RodFormulation};
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
        vec![1e-2, 1e-3, 1e-5]
    } else {
        tolerances
    };
    println!(
        "| rod | worn joint | model | rtol | energy.driveWork [J] | energy.dissipated [J] | largest residual / drive work | evaluations |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    let models = [
        ("dry", JointModel::Dry, FilmModel::Finite),
        ("short film", JointModel::Lubricated, FilmModel::Short),
        ("finite film", JointModel::Lubricated, FilmModel::Finite),
    ];
    for (rod_name, rod_formulation) in [
        ("4 modes", RodFormulation::CraigBampton),
        ("rigid", RodFormulation::Rigid),
    ] {
        let mut cases = Vec::new();
        for joint in ["rod–slider", "crank pin", "main bearing"] {
            for (model_name, model, film_model) in models {
                let worn = JointParameters {
                    model,
                    film_model,
                    ..JointParameters::benchmark()
                };
                let mut p = Parameters {
                    rod_formulation,
                    joint: JointParameters::ideal(),
                    ..Parameters::default()
                };
                match joint {
                    "rod–slider" => p.joint = worn,
                    "crank pin" => p.crank_pin = worn,
                    _ => p.main_bearing = worn,
                }
                cases.push((joint, model_name, p));
            }
        }
        cases.push((
            "none",
            "ideal",
            Parameters {
                rod_formulation,
                joint: JointParameters::ideal(),
                ..Parameters::default()
            },
        ));
        for (joint, model, p) in cases {
            for &asked in &tolerances {
                let p = Parameters {
                    relative_tolerance: asked,
                    ..p.clone()
                };
                let rtol = p.integration_tolerance();
                if rtol != asked && tolerances.contains(&rtol) {
                    continue;
                }
                let mut sim = Simulation::new(p)?;
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
                    "| {rod_name} | {joint} | {model} | {rtol:e} | {:.2} | {:.2} | {:.2} % | {} |",
                    o.drive_work,
                    o.dissipated_energy,
                    100.0 * residual / o.drive_work.abs(),
                    sim.stats().evaluations,
                );
            }
        }
    }
    Ok(())
}
