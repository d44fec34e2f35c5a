#![allow(clippy::all, missing_docs)]
use flexible_slider_crank::Parameters;
use flexible_slider_crank::integrator::OdeSystem;
use flexible_slider_crank::mechanism::SliderCrank;
use flexible_slider_crank::params::*;
use flexible_slider_crank::reduction::Boundary;
use std::time::Instant;
fn main() {
    let only = std::env::args().nth(1).unwrap_or_default();
    for (name, form, modes, bnd) in [
        ("rigid", RodFormulation::Rigid, 0, Boundary::Pins),
        ("cb4pins", RodFormulation::CraigBampton, 4, Boundary::Pins),
        (
            "cb4paper",
            RodFormulation::CraigBampton,
            4,
            Boundary::PositionsAndSlopes,
        ),
        ("full8", RodFormulation::Ancf, 0, Boundary::Pins),
    ] {
        if !only.is_empty() && only != name {
            continue;
        }
        for joint in [JointModel::Dry, JointModel::Lubricated] {
            let p = Parameters {
                rod_formulation: form,
                n_modes: modes,
                boundary: bnd,
                joint_model: joint,
                ..Parameters::default()
            };
            let mut m = SliderCrank::new(&p).unwrap();
            let mut y = m.initial_state(0.3, 500.0);
            let n = m.n_coordinates();
            y[1 + m.rod().end_offset()] += 5.2e-4; // into contact
            let mut dy = vec![0.0; y.len()];
            let t0 = Instant::now();
            let reps = 200_000;
            for i in 0..reps {
                y[n] += 1e-12 * (i % 3) as f64;
                m.rhs(0.0, &y, &mut dy);
            }
            println!(
                "{name} {joint:?}: {:.3} us per rhs",
                t0.elapsed().as_secs_f64() / reps as f64 * 1e6
            );
        }
    }
}
