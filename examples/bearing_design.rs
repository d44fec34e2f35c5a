//! A bearing designer's view of an engine cycle: the small single-cylinder engine of
//! `tests/support/engine.rs` (3000 rpm, lubricated crank pin and main bearing of 25 µm clearance,
//! a dry piston pin, a 5.2 kN firing load) over its second four-stroke cycle. Plots, against the
//! crank angle, the firing load and the forces on the two bearings, their smallest film thickness
//! and their largest film pressure over each 1e-4 s communication interval (the peak-hold
//! outputs), and their friction power; prints the cycle's extremes, the mean friction loss and
//! each joint's dissipation over the cycle, and the same cycle's extremes with the short film.
//!
//! `cargo run --release --example bearing_design` writes `target/bearing_design/bearing_design.png`.
//! The plot needs the DejaVu Sans font (Debian package fonts-dejavu-core).

use std::error::Error;

use flexible_slider_crank::params::FilmModel;
use plotters::prelude::*;

#[path = "../tests/support/engine.rs"]
mod engine;

const FONT: &str = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// One communication point of the second cycle: crank angle in the cycle \[deg\], firing load,
/// forces, film thicknesses, pressures and friction powers of the main bearing and the crank pin.
struct Row {
    angle: f64,
    load: f64,
    force: [f64; 2],
    thickness: [f64; 2],
    pressure: [f64; 2],
    power: [f64; 2],
}

/// A panel of the plot: caption, axis label, top of the axis, and the value of bearing k in a row.
type Panel<'a> = (&'a str, &'a str, f64, &'a dyn Fn(&Row, usize) -> f64);

/// The second cycle's rows with the bearings' film `film`, and each bearing's dissipation at the
/// cycle's start and end.
fn second_cycle(
    film: FilmModel,
) -> Result<(Vec<Row>, [[f64; 2]; 2]), flexible_slider_crank::ModelError> {
    let mut p = engine::parameters(1e-2);
    p.main_bearing.film_model = film;
    p.crank_pin.film_model = film;
    let mut rows = Vec::new();
    let mut dissipated = [[0.0; 2]; 2];
    engine::run(p, 2, |t, o| {
        if (t - engine::CYCLE).abs() < 0.5 * engine::STEP {
            dissipated[0] = [0, 1].map(|k| o.bearings[k].energy_dissipated);
        }
        if t <= engine::CYCLE + 0.5 * engine::STEP {
            return;
        }
        dissipated[1] = [0, 1].map(|k| o.bearings[k].energy_dissipated);
        let angle = (t - engine::CYCLE) * engine::SPEED * 180.0 / std::f64::consts::PI;
        rows.push(Row {
            angle,
            load: -engine::firing_load(engine::SPEED * t),
            force: [o.main_bearing_force_peak, o.crank_pin_force_peak],
            thickness: [0, 1].map(|k| o.bearings[k].film_thickness_min),
            pressure: [0, 1].map(|k| o.bearings[k].film_pressure_peak),
            power: [0, 1].map(|k| o.bearings[k].friction_power),
        });
    })?;
    Ok((rows, dissipated))
}

/// Prints each bearing's extremes, mean friction power and dissipation over the cycle.
fn summary(film: &str, rows: &[Row], dissipated: [[f64; 2]; 2]) {
    let names = ["main bearing", "crank pin"];
    for (k, name) in names.iter().enumerate() {
        let thinnest = rows.iter().map(|r| r.thickness[k]).fold(f64::MAX, f64::min);
        let pressure = rows.iter().map(|r| r.pressure[k]).fold(0.0, f64::max);
        let force = rows.iter().map(|r| r.force[k]).fold(0.0, f64::max);
        let mean_power = rows.iter().map(|r| r.power[k]).sum::<f64>() / rows.len() as f64;
        let energy = dissipated[1][k] - dissipated[0][k];
        println!(
            "{film} film, {name}: peak force {:.0} N, smallest film {:.2} µm, peak pressure \
             {:.1} MPa, mean friction power {mean_power:.2} W, dissipated over the cycle \
             {energy:.4} J ({:.2} W)",
            force,
            1e6 * thinnest,
            1e-6 * pressure,
            energy / engine::CYCLE
        );
    }
}

fn main() -> Result<(), Box<dyn Error>> {
    let (rows, dissipated) = second_cycle(FilmModel::Finite)?;
    summary("finite", &rows, dissipated);
    let (short, short_dissipated) = second_cycle(FilmModel::Short)?;
    summary("short", &short, short_dissipated);
    let names = ["main bearing", "crank pin"];

    let font: &'static [u8] = Box::leak(std::fs::read(FONT)?.into_boxed_slice());
    plotters::style::register_font("sans-serif", FontStyle::Normal, font)
        .map_err(|_| "cannot load the DejaVu Sans font")?;
    std::fs::create_dir_all("target/bearing_design")?;
    let path = "target/bearing_design/bearing_design.png";
    let root = BitMapBackend::new(path, (1200, 1100)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((4, 1));
    let colours = [BLUE, RED];
    let largest = |f: &dyn Fn(&Row) -> f64| rows.iter().map(f).fold(0.0, f64::max);
    let series: [Panel<'_>; 4] = [
        (
            "firing load (grey) and peak force on the bearings",
            "force [kN]",
            1.05e-3 * largest(&|r| r.load.max(r.force[0]).max(r.force[1])),
            &|r, k| 1e-3 * r.force[k],
        ),
        (
            "smallest film thickness (filmThicknessMin)",
            "film [µm]",
            1.05e6 * largest(&|r| r.thickness[0].max(r.thickness[1])),
            &|r, k| 1e6 * r.thickness[k],
        ),
        (
            "largest film pressure at mid-length (filmPressurePeak)",
            "pressure [MPa]",
            1.05e-6 * largest(&|r| r.pressure[0].max(r.pressure[1])),
            &|r, k| 1e-6 * r.pressure[k],
        ),
        (
            "friction power (frictionPower)",
            "power [W]",
            1.05 * largest(&|r| r.power[0].max(r.power[1])),
            &|r, k| r.power[k],
        ),
    ];
    for (i, (panel, (caption, unit, top, value))) in panels.iter().zip(series).enumerate() {
        let mut chart = ChartBuilder::on(panel)
            .caption(caption, ("sans-serif", 18))
            .margin(8)
            .x_label_area_size(30)
            .y_label_area_size(60)
            .build_cartesian_2d(0.0..720.0, 0.0..top)?;
        chart
            .configure_mesh()
            .x_desc("crank angle in the cycle [deg] (firing at 360)")
            .y_desc(unit)
            .draw()?;
        if i == 0 {
            chart.draw_series(LineSeries::new(
                rows.iter().map(|r| (r.angle, 1e-3 * r.load)),
                RGBColor(150, 150, 150).stroke_width(2),
            ))?;
        }
        for (k, (name, colour)) in names.iter().zip(colours).enumerate() {
            chart
                .draw_series(LineSeries::new(
                    rows.iter().map(|r| (r.angle, value(r, k))),
                    colour.stroke_width(1),
                ))?
                .label(*name)
                .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], colour));
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()?;
    }
    root.present()?;
    println!("wrote {path}");
    Ok(())
}
