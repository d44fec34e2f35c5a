//! Benchmark D: the lubricated joint driven into metal contact — a 40× thinner lubricant
//! than benchmark C and a 0.5 kg slider — over two revolutions at 5000 rpm. Plots the eccentricity
//! ratio ε = |e|/c against the switch ratio ε_b (film alone below, film at ε_b plus dry contact
//! above) and the joint force, sampled every 2 µs.
//!
//! `cargo run --release --example handover` writes `target/handover/handover.png`.
//! The plot needs the DejaVu Sans font (Debian package fonts-dejavu-core).

use std::error::Error;

use flexible_slider_crank::math;
use flexible_slider_crank::{Parameters, Simulation};
use plotters::prelude::*;

const FONT: &str = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
const SAMPLES: usize = 12_000;
const STOP: f64 = 0.024;

fn main() -> Result<(), Box<dyn Error>> {
    let p = Parameters::benchmark_d();
    let (c, switch) = (p.joint.clearance, p.joint.switch_eccentricity);
    let mut sim = Simulation::new(p)?;
    let mut ratio = Vec::with_capacity(SAMPLES);
    let mut force = Vec::with_capacity(SAMPLES);
    for i in 1..=SAMPLES {
        let t = STOP * i as f64 / SAMPLES as f64;
        sim.advance_to(t)?;
        let o = sim.outputs()?;
        ratio.push((1e3 * t, math::hypot(o.eccentricity_x, o.eccentricity_y) / c));
        force.push((1e3 * t, 1e-3 * o.joint_force));
    }
    let o = sim.outputs()?;
    println!(
        "benchmark D: max ε = {:.3}, {} contact onsets, {} steps",
        ratio.iter().fold(0.0f64, |m, r| m.max(r.1)),
        o.contact_onsets_total,
        sim.stats().steps
    );

    let font: &'static [u8] = Box::leak(std::fs::read(FONT)?.into_boxed_slice());
    plotters::style::register_font("sans-serif", FontStyle::Normal, font)
        .map_err(|_| "cannot load the DejaVu Sans font")?;
    std::fs::create_dir_all("target/handover")?;
    let root = BitMapBackend::new("target/handover/handover.png", (1200, 700)).into_drawing_area();
    root.fill(&WHITE)?;
    let (top, bottom) = root.split_vertically(350);
    let mut chart = ChartBuilder::on(&top)
        .caption(
            "Benchmark D: lubricated joint handing over to dry contact",
            ("sans-serif", 20),
        )
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..1e3 * STOP, 0.0..1.05)?;
    chart
        .configure_mesh()
        .x_desc("time [ms]")
        .y_desc("eccentricity ratio |e|/c")
        .draw()?;
    chart
        .draw_series(LineSeries::new(ratio, BLUE.stroke_width(1)))?
        .label("eccentricity ratio")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLUE));
    chart
        .draw_series(LineSeries::new(
            vec![(0.0, switch), (1e3 * STOP, switch)],
            RED.stroke_width(2),
        ))?
        .label("switch ratio: dry contact model takes over")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], RED));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .border_style(BLACK)
        .background_style(WHITE)
        .draw()?;
    let peak = force.iter().fold(0.0f64, |m, f| m.max(f.1));
    let mut chart = ChartBuilder::on(&bottom)
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..1e3 * STOP, 0.0..1.05 * peak)?;
    chart
        .configure_mesh()
        .x_desc("time [ms]")
        .y_desc("joint force [kN]")
        .draw()?;
    chart.draw_series(LineSeries::new(force, BLACK.stroke_width(1)))?;
    root.present()?;
    println!("wrote target/handover/handover.png");
    Ok(())
}
