//! Clearance at every joint in one run: benchmark B's 4-mode rod at 5000 rpm with its dry
//! rod–slider joint (0.5 mm) and a lubricated crank pin and main bearing (each 0.05 mm radial
//! clearance, 9 mm long, L/D = 0.47, oil of 0.04 Pa s), every journal settled against its start
//! load, over two revolutions. Plots the force at each of the three joints — the main bearing, the
//! crank pin and the rod–slider joint — sampled every 2 µs, and prints their peaks.
//!
//! `cargo run --release --example worn_joints` writes `target/worn_joints/worn_joints.png`.
//! The plot needs the DejaVu Sans font (Debian package fonts-dejavu-core).

use std::error::Error;

use flexible_slider_crank::params::{JointModel, JointParameters, JournalStart};
use flexible_slider_crank::{Parameters, Simulation};
use plotters::prelude::*;

const FONT: &str = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
const SAMPLES: usize = 12_000;
const STOP: f64 = 0.024;

/// Benchmark B (4 modes) with the lubricated crank pin and main bearing of this example, every
/// journal settled.
pub fn parameters() -> Parameters {
    let bearing = JointParameters {
        model: JointModel::Lubricated,
        clearance: 5e-5,
        bearing_length: 9e-3,
        viscosity: 0.04,
        initial_state: JournalStart::Settled,
        ..JointParameters::benchmark()
    };
    let defaults = Parameters::default();
    Parameters {
        main_bearing: bearing,
        crank_pin: bearing,
        joint: JointParameters {
            initial_state: JournalStart::Settled,
            ..defaults.joint
        },
        ..defaults
    }
}

fn main() -> Result<(), Box<dyn Error>> {
    let mut sim = Simulation::new(parameters())?;
    let mut series: [Vec<(f64, f64)>; 3] = Default::default();
    for i in 1..=SAMPLES {
        let t = STOP * i as f64 / SAMPLES as f64;
        sim.advance_to(t)?;
        let o = sim.outputs()?;
        for (s, f) in
            series
                .iter_mut()
                .zip([o.main_bearing_force, o.crank_pin_force, o.joint_force])
        {
            s.push((1e3 * t, 1e-3 * f));
        }
    }
    let peak = |s: &[(f64, f64)]| s.iter().fold(0.0f64, |m, f| m.max(f.1));
    let o = sim.outputs()?;
    println!(
        "peak forces over two revolutions: main bearing {:.2} kN, crank pin {:.2} kN, rod-slider \
         joint {:.2} kN; {} steps, {} warnings",
        peak(&series[0]),
        peak(&series[1]),
        peak(&series[2]),
        sim.stats().steps,
        o.warnings
    );

    let font: &'static [u8] = Box::leak(std::fs::read(FONT)?.into_boxed_slice());
    plotters::style::register_font("sans-serif", FontStyle::Normal, font)
        .map_err(|_| "cannot load the DejaVu Sans font")?;
    std::fs::create_dir_all("target/worn_joints")?;
    let path = "target/worn_joints/worn_joints.png";
    let root = BitMapBackend::new(path, (1200, 900)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((3, 1));
    let names = [
        "mainBearing.force (lubricated, 0.05 mm)",
        "crankPin.force (lubricated, 0.05 mm)",
        "joint.force (rod-slider, dry, 0.5 mm)",
    ];
    for ((panel, s), name) in panels.iter().zip(&series).zip(names) {
        let mut chart = ChartBuilder::on(panel)
            .caption(name, ("sans-serif", 18))
            .margin(8)
            .x_label_area_size(30)
            .y_label_area_size(60)
            .build_cartesian_2d(0.0..1e3 * STOP, 0.0..1.05 * peak(s))?;
        chart
            .configure_mesh()
            .x_desc("time [ms]")
            .y_desc("force [kN]")
            .draw()?;
        chart.draw_series(LineSeries::new(s.clone(), BLACK.stroke_width(1)))?;
    }
    root.present()?;
    println!("wrote {path}");
    Ok(())
}
