//! The load spectrum's accuracy: every impact of the first 60° of benchmarks A and B (rigid rod,
//! 4 and 8 modes, full rod), its peak force and onset angle at given settings against a converged
//! run (explicit Dormand–Prince at rtol 1e-8); definitions in `tests/support/load_spectrum.rs`.
//!
//! `cargo run --release --example impacts [rtol [weight]]` (defaults: the library's
//! `solver.relativeTolerance` and `solver.impactErrorWeight`) prints per model the worst peak and
//! onset errors, the first impact's, and the run's internal steps; `IMPACTS_VERBOSE=1` also every
//! impact; `IMPACTS_QUADRATURE=sampled` runs the Craig–Bampton rods with `rod.quadrature = sampled`
//! (against their own converged runs).

use std::error::Error;

use flexible_slider_crank::Parameters;
use flexible_slider_crank::params::BENCHMARK_SPEED;
use flexible_slider_crank::reduction::Quadrature;

#[path = "../tests/support/load_spectrum.rs"]
mod load_spectrum;

use load_spectrum::{benchmarks, converged, impacts, pair};

fn main() -> Result<(), Box<dyn Error>> {
    let rtol: Option<f64> = std::env::args().nth(1).map(|a| a.parse()).transpose()?;
    let weight: Option<f64> = std::env::args().nth(2).map(|a| a.parse()).transpose()?;
    let verbose = std::env::var_os("IMPACTS_VERBOSE").is_some();
    println!(
        "| rod | impacts | worst peak error | worst onset error [deg] | first peak error | steps |"
    );
    println!("|---|---|---|---|---|---|");
    let quadrature = match std::env::var("IMPACTS_QUADRATURE").as_deref() {
        Ok("sampled") => Quadrature::Sampled,
        _ => Quadrature::Full,
    };
    for (name, p) in benchmarks() {
        let p = Parameters { quadrature, ..p };
        let (reference, _) = impacts(converged(&p))?;
        let run = Parameters {
            relative_tolerance: rtol.unwrap_or(p.relative_tolerance),
            impact_error_weight: weight.unwrap_or(p.impact_error_weight),
            ..p
        };
        let (events, steps) = impacts(run)?;
        let pairs = pair(&reference, &events);
        if verbose {
            for pair in &pairs {
                eprintln!(
                    "{name}: onset {:.3}° → {:.3}°, peak {:.0} → {:.0} N",
                    (pair.reference.onset * BENCHMARK_SPEED).to_degrees(),
                    (pair.run.onset * BENCHMARK_SPEED).to_degrees(),
                    pair.reference.peak,
                    pair.run.peak
                );
            }
        }
        let worst_peak = pairs.iter().map(|p| p.peak_error()).fold(0.0, f64::max);
        let worst_onset = pairs
            .iter()
            .map(|p| p.onset_error_degrees())
            .fold(0.0, f64::max);
        let first = pairs.first().map_or(f64::NAN, |p| p.peak_error());
        println!(
            "| {name} | {} | {:.1} % | {worst_onset:.3} | {:.2} % | {steps} |",
            pairs.len(),
            100.0 * worst_peak,
            100.0 * first
        );
    }
    Ok(())
}
