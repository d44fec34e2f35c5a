//! Mode-count study (Sun et al. 2015, docs/model.md §2 and §7): the Craig–Bampton rod against the full
//! ANCF rod (8 elements, benchmark B steel rod, 5000 rpm) for the dry joint (benchmark B), the
//! lubricated joint (benchmark C), and a dry crank pin (benchmark B's clearance joint moved to the
//! crank pin, the rod–slider joint ideal). For each nModes it reports the error in the maximum deformation
//! energy over the second revolution (e_U), the RMS slider-acceleration error over the point-wise
//! horizon, the error of the peak joint force over two revolutions, and the wall time and speed-up.
//!
//! The point-wise horizon is measured, not chosen: the run with all modes kept is the full model
//! in other coordinates, so where its slider acceleration departs from the full run's by more than
//! 1 % of the peak, round-off and step-sequence differences amplified by the impacts dominate and
//! point-wise comparison says nothing about the reduction. Beyond it only statistics (e_U, peak
//! force) are compared (docs/model.md §6).
//!
//! Both Craig–Bampton interfaces are studied (`rod.boundary`): pins only (the default) and the
//! paper's end-node positions and slopes. Every run, full and reduced, uses the default implicit
//! integrator at rtol 1e-6, so that the errors are those of the reduction, not of the time step.
//!
//! `cargo run --release --example mode_study` prints the tables and writes
//! `target/mode_study/mode_study.csv` and `target/mode_study/mode_study.png`.
//! The plot needs the DejaVu Sans font (Debian package fonts-dejavu-core).

use std::error::Error;
use std::time::Instant;

use flexible_slider_crank::params::JointParameters;
use flexible_slider_crank::params::{BENCHMARK_SPEED, JointModel, RodFormulation};
use flexible_slider_crank::reduction::{Boundary, max_modes};
use flexible_slider_crank::{Parameters, Simulation};
use plotters::prelude::*;

const SAMPLES_PER_REVOLUTION: usize = 1200;
/// Mode counts studied; the last run of each interface keeps every mode ([`max_modes`]).
const MODES: [usize; 7] = [0, 1, 2, 3, 4, 6, 8];
/// Elements of the rod.
const ELEMENTS: usize = 8;
/// Relative tolerance of every run.
const TOLERANCE: f64 = 1e-6;
const FONT: &str = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// Sampled response of one run.
struct Run {
    acceleration: Vec<f64>,
    force: Vec<f64>,
    energy: Vec<f64>,
    seconds: f64,
}

fn simulate(p: Parameters) -> Result<Run, Box<dyn Error>> {
    let revolution = std::f64::consts::TAU / BENCHMARK_SPEED;
    let n = 2 * SAMPLES_PER_REVOLUTION;
    // The force of the worn joint: the rod–slider joint's, or the crank pin's when only it is worn.
    let crank_pin_worn = p.joint.model == JointModel::Ideal;
    let start = Instant::now();
    let mut sim = Simulation::new(p)?;
    let mut run = Run {
        acceleration: vec![],
        force: vec![],
        energy: vec![],
        seconds: 0.0,
    };
    for i in 1..=n {
        sim.advance_to(2.0 * revolution * i as f64 / n as f64)?;
        let o = sim.outputs()?;
        run.acceleration.push(o.slider_acceleration);
        run.force.push(if crank_pin_worn {
            o.crank_pin_force
        } else {
            o.joint_force
        });
        run.energy.push(o.deformation_energy);
    }
    run.seconds = start.elapsed().as_secs_f64();
    Ok(run)
}

fn max(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |m, x| m.max(*x))
}

/// Number of samples over which `control` (all modes) follows `full` point-wise to 1 % of the peak.
fn pointwise_horizon(full: &Run, control: &Run) -> usize {
    let peak = full.acceleration.iter().fold(0.0f64, |m, a| m.max(a.abs()));
    full.acceleration
        .iter()
        .zip(&control.acceleration)
        .position(|(a, b)| (a - b).abs() > 0.01 * peak)
        .unwrap_or(full.acceleration.len())
}

/// Relative error of the maximum of `reduced` against that of `full` over samples `window`.
fn max_error(full: &[f64], reduced: &[f64], window: std::ops::Range<usize>) -> f64 {
    let reference = max(&full[window.clone()]);
    (max(&reduced[window]) - reference).abs() / reference
}

/// Errors of a reduced run against the full one: (e_U over the second revolution, e_U over the
/// point-wise horizon, slider acceleration over the horizon, peak force).
fn errors(full: &Run, reduced: &Run, horizon: usize) -> (f64, f64, f64, f64) {
    let k = SAMPLES_PER_REVOLUTION;
    let e_u = max_error(&full.energy, &reduced.energy, k..2 * k);
    let e_u_horizon = max_error(&full.energy, &reduced.energy, 0..horizon);
    let diff: f64 = (0..horizon)
        .map(|i| (reduced.acceleration[i] - full.acceleration[i]).powi(2))
        .sum();
    let norm: f64 = full.acceleration[..horizon].iter().map(|a| a * a).sum();
    let e_a = (diff / norm).sqrt();
    let f_full = max(&full.force);
    let e_f = (max(&reduced.force) - f_full).abs() / f_full;
    (e_u, e_u_horizon, e_a, e_f)
}

fn main() -> Result<(), Box<dyn Error>> {
    std::fs::create_dir_all("target/mode_study")?;
    let mut csv = String::from(
        "joint,boundary,n_modes,energy_error,energy_error_horizon,acceleration_error,peak_force_error,wall_time_s,speed_up\n",
    );
    let mut curves = Vec::new();
    for (name, joint, crank_pin) in [
        ("dry", JointModel::Dry, JointModel::Ideal),
        ("lubricated", JointModel::Lubricated, JointModel::Ideal),
        ("crank-pin dry", JointModel::Ideal, JointModel::Dry),
    ] {
        let base = Parameters {
            joint: JointParameters {
                model: joint,
                ..Parameters::default().joint
            },
            crank_pin: JointParameters {
                model: crank_pin,
                ..JointParameters::benchmark()
            },
            n_elements: ELEMENTS,
            relative_tolerance: TOLERANCE,
            ..Parameters::default()
        };
        let full = simulate(Parameters {
            rod_formulation: RodFormulation::Ancf,
            ..base.clone()
        })?;
        println!(
            "\n{name} joint, {ELEMENTS} elements: full ANCF model {:.2} s, max U (2nd rev.) {:.4} J, peak force {:.0} N",
            full.seconds,
            max(&full.energy[SAMPLES_PER_REVOLUTION..]),
            max(&full.force)
        );
        for (boundary_name, boundary) in [
            ("pins", Boundary::Pins),
            ("positionsAndSlopes", Boundary::PositionsAndSlopes),
        ] {
            let modes: Vec<usize> = MODES
                .into_iter()
                .chain([max_modes(ELEMENTS, boundary)])
                .collect();
            let runs = modes
                .iter()
                .map(|&m| {
                    simulate(Parameters {
                        rod_formulation: RodFormulation::CraigBampton,
                        n_modes: m,
                        boundary,
                        ..base.clone()
                    })
                })
                .collect::<Result<Vec<_>, _>>()?;
            let horizon = pointwise_horizon(&full, &runs[modes.len() - 1]);
            let revolution_ms = 1e3 * std::f64::consts::TAU / BENCHMARK_SPEED;
            println!(
                "rod.boundary = {boundary_name}: point-wise horizon (all-modes run within 1 % of the full run) {:.2} ms ({:.2} revolutions)",
                revolution_ms * horizon as f64 / SAMPLES_PER_REVOLUTION as f64,
                horizon as f64 / SAMPLES_PER_REVOLUTION as f64
            );
            println!(
                "| nModes | e_U (2nd rev.) | e_U (horizon) | e_accel | e_Fpeak | wall [s] | speed-up |"
            );
            println!("|---|---|---|---|---|---|---|");
            let mut curve = Vec::new();
            for (&m, reduced) in modes.iter().zip(&runs) {
                let (e_u, e_uh, e_a, e_f) = errors(&full, reduced, horizon);
                let speed_up = full.seconds / reduced.seconds;
                println!(
                    "| {m} | {e_u:.1e} | {e_uh:.1e} | {e_a:.1e} | {e_f:.1e} | {:.2} | {speed_up:.2} |",
                    reduced.seconds
                );
                csv.push_str(&format!(
                    "{name},{boundary_name},{m},{e_u:.6e},{e_uh:.6e},{e_a:.6e},{e_f:.6e},{:.4},{speed_up:.3}\n",
                    reduced.seconds
                ));
                curve.push((m, e_uh, e_a, e_f));
            }
            curves.push((format!("{name} joint, {boundary_name}"), curve));
        }
    }
    std::fs::write("target/mode_study/mode_study.csv", csv)?;
    plot(&curves)?;
    println!("\nwrote target/mode_study/mode_study.csv and target/mode_study/mode_study.png");
    Ok(())
}

/// Errors of one reduced run: (nModes, e_U over the horizon, acceleration, peak force).
type Point = (usize, f64, f64, f64);
type Curve = Vec<Point>;
/// A plotted error measure: label, colour, and how to read it from a point.
type Measure = (&'static str, RGBColor, fn(&Point) -> f64);

fn plot(curves: &[(String, Curve)]) -> Result<(), Box<dyn Error>> {
    let font: &'static [u8] = Box::leak(std::fs::read(FONT)?.into_boxed_slice());
    plotters::style::register_font("sans-serif", FontStyle::Normal, font)
        .map_err(|_| "cannot load the DejaVu Sans font")?;
    let root =
        BitMapBackend::new("target/mode_study/mode_study.png", (1200, 1500)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((3, 2));
    for (area, (name, curve)) in panels.iter().zip(curves) {
        let mut chart = ChartBuilder::on(area)
            .caption(
                format!("Craig-Bampton vs full ANCF, {name}"),
                ("sans-serif", 20),
            )
            .margin(15)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(0f64..16f64, (1e-8f64..10f64).log_scale())?;
        chart
            .configure_mesh()
            .x_desc("nModes")
            .y_desc("relative error")
            .y_label_formatter(&|v| format!("{v:.0e}"))
            .draw()?;
        let series: [Measure; 3] = [
            ("max deformation energy (point-wise horizon)", BLUE, |c| c.1),
            ("slider acceleration RMS (point-wise horizon)", RED, |c| c.2),
            ("peak joint force", GREEN, |c| c.3),
        ];
        for (label, color, value) in series {
            let points: Vec<(f64, f64)> = curve
                .iter()
                .map(|c| (c.0 as f64, value(c).max(1e-8)))
                .collect();
            chart
                .draw_series(LineSeries::new(points.clone(), color.stroke_width(2)))?
                .label(label)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color));
            chart.draw_series(
                points
                    .into_iter()
                    .map(|p| Circle::new(p, 4, color.filled())),
            )?;
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerLeft)
            .border_style(BLACK)
            .background_style(WHITE)
            .draw()?;
    }
    root.present()?;
    Ok(())
}
