//! Runs the slider-crank through the Rust API and prints a CSV of the outputs to stdout.
//!
//! `cargo run --release --example simulate -- [rigid|ancf|craigBampton]
//! [ideal|dry|lubricated|short] [stop time s] [output interval s]` — defaults: benchmark B
//! (Craig–Bampton, 4 modes, dry joint), two crank revolutions at 5000 rpm, 1e-4 s; `lubricated` is
//! the joint's default finite film, `short` the lubricated joint with the short film (benchmark C's).
//!
//! Communication points follow fmpy's arithmetic (t_n = n·dt, step h = t_{n+1} − t_n, end t + h) and
//! values are printed in shortest round-trip form, so the FMU run through fmpy can be compared with
//! this library run bit for bit (packaging/python/tests/test_fmu.py).

use flexible_slider_crank::params::{FilmModel, JointModel, RodFormulation};
use flexible_slider_crank::{ModelError, Parameters, Simulation};

fn main() -> Result<(), ModelError> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut p = Parameters::default();
    match args.first().map(String::as_str) {
        Some("rigid") => p.rod_formulation = RodFormulation::Rigid,
        Some("ancf") => p.rod_formulation = RodFormulation::Ancf,
        _ => {}
    }
    match args.get(1).map(String::as_str) {
        Some("ideal") => p.joint.model = JointModel::Ideal,
        Some("lubricated") => p.joint.model = JointModel::Lubricated,
        Some("short") => {
            p.joint.model = JointModel::Lubricated;
            p.joint.film_model = FilmModel::Short;
        }
        _ => {}
    }
    let stop: f64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(0.024);
    let interval: f64 = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(1e-4);
    let mut sim = Simulation::new(p)?;
    println!(
        "time,crank_angle,crank_torque,slider_position,slider_velocity,slider_acceleration,\
         joint_force,eccentricity_x,eccentricity_y,penetration,midspan_deflection,\
         deformation_energy,kinetic_energy,drive_work,dissipated_energy"
    );
    let steps = (stop / interval).round() as usize;
    let mut t = 0.0;
    for i in 0..=steps {
        if i > 0 {
            let next = i as f64 * interval;
            let h = next - t;
            sim.advance_to(t + h)?;
            t = next;
        }
        let o = sim.outputs()?;
        println!(
            "{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e}",
            t,
            o.crank_angle,
            o.crank_torque,
            o.slider_position,
            o.slider_velocity,
            o.slider_acceleration,
            o.joint_force,
            o.eccentricity_x,
            o.eccentricity_y,
            o.penetration,
            o.midspan_deflection,
            o.deformation_energy,
            o.kinetic_energy,
            o.drive_work,
            o.dissipated_energy
        );
    }
    let s = sim.stats();
    eprintln!(
        "steps {}, rejected {}, evaluations {}",
        s.steps, s.rejected, s.evaluations
    );
    Ok(())
}
