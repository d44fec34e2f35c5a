//! Whole-FMU benchmark from Rust: the packaged FMU loaded with the `fmi` 0.8 crate and stepped with
//! fmi2DoStep over the DefaultExperiment (two revolutions, 1e-4 s) for each rod and joint model.
//! Prints a Markdown table (best of three runs; speed-up of the reduced over the full rod).
//!
//! `cargo run --release -p packaging && cargo run --release --example fmu_loop`

use std::error::Error;
use std::time::Instant;

use flexible_slider_crank::variables::VARIABLES;
use fmi::fmi2::import::Fmi2Import;
use fmi::fmi2::instance::{CoSimulation, Common};

fn vr(name: &str) -> Result<u32, Box<dyn Error>> {
    VARIABLES
        .iter()
        .find(|v| v.name == name)
        .map(|v| v.vr as u32)
        .ok_or_else(|| name.into())
}

fn run(
    import: &Fmi2Import,
    formulation: i32,
    joint: i32,
    modes: i32,
) -> Result<f64, Box<dyn Error>> {
    let start = Instant::now();
    let mut inst = import.instantiate_cs("bench", false, false)?;
    let vrs = [
        vr("rod.formulation")?,
        vr("joint.model")?,
        vr("rod.nModes")?,
    ];
    inst.set_integer(&vrs, &[formulation, joint, modes])?;
    inst.setup_experiment(None, 0.0, Some(0.024))?;
    inst.enter_initialization_mode()?;
    inst.exit_initialization_mode()?;
    let out = [vr("slider.acceleration")?];
    let mut value = [0.0];
    let mut t = 0.0;
    for n in 1..=240 {
        let next = f64::from(n) * 1e-4;
        inst.do_step(t, next - t, true)?;
        inst.get_real(&out, &mut value)?;
        t = next;
    }
    Ok(start.elapsed().as_secs_f64())
}

fn main() -> Result<(), Box<dyn Error>> {
    let import: Fmi2Import = fmi::import::from_path("target/fmu/FlexibleSliderCrank.fmu")?;
    let cases = [
        ("rigid", 1, 0),
        ("full ANCF, 8 elements", 2, 0),
        ("Craig-Bampton m=2", 3, 2),
        ("Craig-Bampton m=4", 3, 4),
        ("Craig-Bampton m=8", 3, 8),
    ];
    println!("| rod model | joint | wall time [s] | real-time factor | speed-up vs full |");
    println!("|---|---|---|---|---|");
    for (joint_name, joint) in [("dry", 2), ("lubricated", 3)] {
        let mut times = Vec::new();
        for (_, formulation, modes) in cases {
            let mut best = f64::INFINITY;
            for _ in 0..3 {
                best = best.min(run(&import, formulation, joint, modes)?);
            }
            times.push(best);
        }
        let full = times[1];
        for ((name, _, _), w) in cases.iter().zip(&times) {
            println!(
                "| {name} | {joint_name} | {w:.3} | {:.4} | {:.2} |",
                0.024 / w,
                full / w
            );
        }
    }
    Ok(())
}
