//! Accuracy of a run against a converged reference: benchmark B over the
//! first 40° of crank rotation (1.33 ms at 5000 rpm), sampled every microsecond from the dense
//! output (which does not change the step sequence).
//!
//! Measures: crank angle at the first contact onset, peak force of the first contact event,
//! maximum deformation energy over the window, and the RMS error of the slider acceleration over
//! the window relative to the reference's RMS. The reference is the full 8-element rod with the
//! explicit Dormand–Prince method at rtol 1e-10.
//!
//! `cargo run --release --example accuracy [rtol …]` prints one row per model and tolerance.

use std::error::Error;
use std::time::Instant;

use flexible_slider_crank::integrator::Method;
use flexible_slider_crank::params::{BENCHMARK_SPEED, EXPLICIT_MAX_TOLERANCE, RodFormulation};
use flexible_slider_crank::reduction::Boundary;
use flexible_slider_crank::{Parameters, Simulation};

/// Window: the first 40° of crank rotation.
const WINDOW_DEGREES: f64 = 40.0;
/// Sampling interval of the dense output \[s\].
const SAMPLE: f64 = 1e-6;

/// What a run shows over the window.
struct Response {
    onset_degrees: f64,
    first_peak: f64,
    max_energy: f64,
    acceleration: Vec<f64>,
    seconds: f64,
    steps: u64,
}

fn respond(p: Parameters) -> Result<Response, Box<dyn Error>> {
    let window = WINDOW_DEGREES.to_radians() / BENCHMARK_SPEED;
    let n = (window / SAMPLE).round() as usize;
    let start = Instant::now();
    let mut sim = Simulation::new(p)?;
    let mut r = Response {
        onset_degrees: f64::NAN,
        first_peak: 0.0,
        max_energy: 0.0,
        acceleration: Vec::with_capacity(n),
        seconds: 0.0,
        steps: 0,
    };
    let mut first_event = None;
    for i in 1..=n {
        sim.advance_to(i as f64 * SAMPLE)?;
        let o = sim.outputs()?;
        match (first_event, o.in_contact) {
            (None, true) => {
                first_event = Some(true);
                r.onset_degrees = o.crank_angle.to_degrees();
            }
            (Some(true), false) => first_event = Some(false),
            _ => {}
        }
        if first_event == Some(true) {
            r.first_peak = r.first_peak.max(o.joint_force);
        }
        r.max_energy = r.max_energy.max(o.deformation_energy);
        r.acceleration.push(o.slider_acceleration);
    }
    r.seconds = start.elapsed().as_secs_f64();
    r.steps = sim.stats().steps;
    Ok(r)
}

fn main() -> Result<(), Box<dyn Error>> {
    let tolerances: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| a.parse())
        .collect::<Result<_, _>>()?;
    let tolerances = if tolerances.is_empty() {
        vec![Parameters::default().relative_tolerance]
    } else {
        tolerances
    };
    let reference = respond(Parameters {
        rod_formulation: RodFormulation::Ancf,
        method: Method::DormandPrince,
        relative_tolerance: 1e-10,
        ..Parameters::default()
    })?;
    let rms = |v: &[f64]| (v.iter().map(|x| x * x).sum::<f64>() / v.len() as f64).sqrt();
    println!(
        "reference (full ANCF, 8 elements, Dormand–Prince, rtol 1e-10): onset {:.3}°, first peak {:.0} N, \
         U_max {:.4e} J, RMS acceleration {:.0} m/s² ({} steps, {:.1} s)",
        reference.onset_degrees,
        reference.first_peak,
        reference.max_energy,
        rms(&reference.acceleration),
        reference.steps,
        reference.seconds
    );
    println!(
        "| rod | method | boundary | rtol | onset error [°] | first peak error | U_max error | acceleration RMS error | steps |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for rtol in tolerances {
        for (rod, modes) in [(RodFormulation::CraigBampton, 4), (RodFormulation::Ancf, 0)] {
            for method in [
                Method::Esdirk,
                Method::GeneralizedAlpha,
                Method::DormandPrince,
            ] {
                for boundary in [Boundary::Pins, Boundary::PositionsAndSlopes] {
                    let skip = (rod == RodFormulation::Ancf
                        && boundary == Boundary::PositionsAndSlopes)
                        || (method == Method::DormandPrince && rtol > EXPLICIT_MAX_TOLERANCE);
                    if skip {
                        continue;
                    }
                    let r = respond(Parameters {
                        rod_formulation: rod,
                        n_modes: modes,
                        method,
                        boundary,
                        relative_tolerance: rtol,
                        ..Parameters::default()
                    })?;
                    let diff: Vec<f64> = r
                        .acceleration
                        .iter()
                        .zip(&reference.acceleration)
                        .map(|(a, b)| a - b)
                        .collect();
                    println!(
                        "| {rod:?} | {method:?} | {boundary:?} | {rtol:e} | {:.3} | {:.2e} | {:.2e} | {:.2e} | {} |",
                        r.onset_degrees - reference.onset_degrees,
                        (r.first_peak - reference.first_peak) / reference.first_peak,
                        (r.max_energy - reference.max_energy) / reference.max_energy,
                        rms(&diff) / rms(&reference.acceleration),
                        r.steps
                    );
                }
            }
        }
    }
    Ok(())
}
