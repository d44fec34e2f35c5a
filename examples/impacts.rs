//! The load spectrum's accuracy: every impact of the first 60° of benchmarks A and B (rigid rod,
//! 4 and 8 modes, full rod), its peak force and onset angle at given settings against a converged
//! run (explicit Dormand–Prince at rtol 1e-8).
//!
//! An impact is a contact event (onset to separation); it counts if its converged peak exceeds
//! 5 % of the first impact's and it ends inside the window. Events are read from the peak-hold
//! outputs at 1 µs communication intervals (dense output: the step sequence does not change).
//!
//! `cargo run --release --example impacts [rtol]` (default: the library default) prints per model
//! the worst peak and onset errors, the first impact's, and the run's internal steps.

use std::error::Error;

use flexible_slider_crank::integrator::Method;
use flexible_slider_crank::params::{BENCHMARK_SPEED, RodFormulation};
use flexible_slider_crank::{Parameters, Simulation};

/// Window: the first 60° of crank rotation.
const WINDOW_DEGREES: f64 = 60.0;
/// Communication interval \[s\].
const SAMPLE: f64 = 1e-6;

/// One contact event: onset time \[s\] and peak force \[N\].
#[derive(Clone, Copy, Debug)]
struct Impact {
    onset: f64,
    peak: f64,
}

/// The impacts of a run that end inside the window, and the run's internal steps.
fn impacts(p: Parameters) -> Result<(Vec<Impact>, u64), Box<dyn Error>> {
    let window = WINDOW_DEGREES.to_radians() / BENCHMARK_SPEED;
    let n = (window / SAMPLE).round() as usize;
    let mut sim = Simulation::new(p)?;
    let mut events = Vec::new();
    let mut current: Option<Impact> = None;
    for k in 1..=n {
        let t = k as f64 * SAMPLE;
        sim.advance_to(t)?;
        let o = sim.outputs()?;
        if o.contact_onsets > 0 {
            if let Some(done) = current.take() {
                events.push(done);
            }
            current = Some(Impact {
                onset: t - SAMPLE,
                peak: 0.0,
            });
        }
        if let Some(c) = &mut current {
            c.peak = c.peak.max(o.joint_force_peak);
            if !o.in_contact && o.contact_onsets == 0 {
                events.push(*c);
                current = None;
            }
        }
    }
    Ok((events, sim.stats().steps))
}

fn main() -> Result<(), Box<dyn Error>> {
    let rtol: Option<f64> = std::env::args().nth(1).map(|a| a.parse()).transpose()?;
    let models: [(&str, Parameters); 4] = [
        (
            "rigid (A)",
            Parameters {
                rod_formulation: RodFormulation::Rigid,
                ..Parameters::benchmark_a()
            },
        ),
        (
            "4 modes (B)",
            Parameters {
                rod_formulation: RodFormulation::CraigBampton,
                n_modes: 4,
                ..Parameters::benchmark_b()
            },
        ),
        (
            "8 modes (B)",
            Parameters {
                rod_formulation: RodFormulation::CraigBampton,
                n_modes: 8,
                ..Parameters::benchmark_b()
            },
        ),
        (
            "full (B)",
            Parameters {
                rod_formulation: RodFormulation::Ancf,
                ..Parameters::benchmark_b()
            },
        ),
    ];
    println!(
        "| rod | impacts | worst peak error | worst onset error [deg] | first peak error | steps |"
    );
    println!("|---|---|---|---|---|---|");
    for (name, p) in models {
        let converged = Parameters {
            method: Method::DormandPrince,
            relative_tolerance: 1e-8,
            ..p.clone()
        };
        let run = Parameters {
            relative_tolerance: rtol.unwrap_or(p.relative_tolerance),
            ..p
        };
        let (reference, _) = impacts(converged)?;
        let (events, steps) = impacts(run)?;
        if std::env::var_os("IMPACTS_VERBOSE").is_some() {
            for (label, list) in [("reference", &reference), ("run", &events)] {
                let text: Vec<String> = list
                    .iter()
                    .map(|i| {
                        format!(
                            "{:.2}°/{:.0}",
                            (i.onset * BENCHMARK_SPEED).to_degrees(),
                            i.peak
                        )
                    })
                    .collect();
                eprintln!("{name} {label}: {}", text.join(" "));
            }
        }
        let threshold = 0.05 * reference.first().map_or(0.0, |i| i.peak);
        let mut worst = (0.0f64, 0.0f64);
        let mut first = f64::NAN;
        let mut counted = 0;
        for (k, r) in reference.iter().enumerate() {
            if r.peak < threshold {
                continue;
            }
            // The run's event nearest in onset time.
            let Some(e) = events.iter().min_by(|a, b| {
                (a.onset - r.onset)
                    .abs()
                    .total_cmp(&(b.onset - r.onset).abs())
            }) else {
                continue;
            };
            let peak_error = (e.peak - r.peak).abs() / r.peak;
            let onset_error = ((e.onset - r.onset) * BENCHMARK_SPEED).to_degrees().abs();
            if k == 0 {
                first = peak_error;
            }
            if std::env::var_os("IMPACTS_VERBOSE").is_some() {
                eprintln!(
                    "{name}: onset {:.3}° → {:.3}°, peak {:.0} → {:.0} N",
                    (r.onset * BENCHMARK_SPEED).to_degrees(),
                    (e.onset * BENCHMARK_SPEED).to_degrees(),
                    r.peak,
                    e.peak
                );
            }
            worst = (worst.0.max(peak_error), worst.1.max(onset_error));
            counted += 1;
        }
        println!(
            "| {name} | {counted} | {:.1} % | {:.3} | {:.2} % | {steps} |",
            100.0 * worst.0,
            worst.1,
            100.0 * first
        );
    }
    Ok(())
}
