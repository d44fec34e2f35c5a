#![allow(clippy::all, missing_docs)]
use flexible_slider_crank::integrator::Method;
use flexible_slider_crank::params::*;
use flexible_slider_crank::reduction::Boundary;
use flexible_slider_crank::{Parameters, Simulation};
use std::time::Instant;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let rtol: f64 = args.get(1).map(|s| s.parse().unwrap()).unwrap_or(1e-6);
    let filter = args.get(2).cloned().unwrap_or_default();
    let cases = [
        ("rigid", RodFormulation::Rigid, 0, Boundary::Pins),
        (
            "cb4paper",
            RodFormulation::CraigBampton,
            4,
            Boundary::PositionsAndSlopes,
        ),
        ("cb4pins", RodFormulation::CraigBampton, 4, Boundary::Pins),
        ("cb8pins", RodFormulation::CraigBampton, 8, Boundary::Pins),
        ("full8", RodFormulation::Ancf, 0, Boundary::Pins),
    ];
    for (name, form, modes, bnd) in cases {
        if !filter.is_empty() && !name.contains(&filter) {
            continue;
        }
        for joint in [JointModel::Ideal, JointModel::Dry, JointModel::Lubricated] {
            for method in [Method::DormandPrince, Method::Esdirk] {
                let p = Parameters {
                    rod_formulation: form,
                    n_modes: modes,
                    boundary: bnd,
                    joint_model: joint,
                    method,
                    relative_tolerance: rtol,
                    ..Parameters::default()
                };
                let t0 = Instant::now();
                let mut sim = Simulation::new(p).unwrap();
                let mut peak: f64 = 0.0;
                let mut ok = true;
                for i in 1..=240 {
                    if let Err(e) = sim.advance_to(1e-4 * i as f64) {
                        println!("ERR {e}");
                        ok = false;
                        break;
                    }
                    peak = peak.max(sim.outputs().unwrap().joint_force);
                }
                let w = t0.elapsed().as_secs_f64();
                let s = sim.stats();
                println!(
                    "{name:9} {joint:10?} {method:13?} wall {w:7.3}s steps {:6} rej {:5} evals {:7} newton {:7} jac {:4} lu {:5} peakF {peak:8.0} {}",
                    s.steps,
                    s.rejected,
                    s.evaluations,
                    s.newton_iterations,
                    s.jacobians,
                    s.factorizations,
                    if ok { "" } else { "FAILED" }
                );
            }
        }
    }
}
