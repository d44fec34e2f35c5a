//! What a damped rod costs and saves at the defaults (benchmark B: 4 modes, dry rod–slider joint,
//! two revolutions at 5000 rpm): for `rod.dampingRatio` 0, 1 % and 2 %, the internal steps,
//! right-hand-side evaluations and wall time; the largest joint force and rod stress of each
//! revolution against the same rod's run at tolerances down to 1e-7 (their spread says whether
//! that peak is a converged quantity at all); and every impact of the first 60° against its
//! converged run (`tests/support/load_spectrum.rs`).
//!
//! `cargo run --release --example damped_rod` prints the table; `… --example damped_rod -- time ζ n
//! [step]` only runs the defaults with that damping ratio n times, reading the outputs every
//! `step` seconds (1e-4 unless given; for timing whole processes, `packaging/benchmarks.sh
//! damping`).

use std::error::Error;
use std::time::Instant;

use flexible_slider_crank::{Parameters, Simulation};

#[path = "../tests/support/load_spectrum.rs"]
mod load_spectrum;

use load_spectrum::{benchmarks, converged, impacts, pair};

/// The largest joint force and rod stress of each revolution \[N, Pa\], with the run's steps,
/// evaluations and wall time \[s\].
struct Run {
    joint: [f64; 2],
    stress: [f64; 2],
    steps: u64,
    evaluations: u64,
    seconds: f64,
}

/// Benchmark B with 4 modes at the library's defaults, with the rod's damping ratio `zeta`.
fn benchmark_b(zeta: f64) -> Parameters {
    let [_, (_, mut p), ..] = benchmarks();
    p.rod.damping_ratio = zeta;
    p
}

/// Two revolutions (24 ms) read every `points`-th of them.
fn run(zeta: f64, rtol: f64, points: u32) -> Result<Run, Box<dyn Error>> {
    let mut p = benchmark_b(zeta);
    p.relative_tolerance = rtol;
    let start = Instant::now();
    let mut sim = Simulation::new(p)?;
    let (mut joint, mut stress) = ([0.0f64; 2], [0.0f64; 2]);
    for k in 1..=points {
        sim.advance_to(0.024 * f64::from(k) / f64::from(points))?;
        let o = sim.outputs()?;
        let revolution = usize::from(2 * k > points);
        joint[revolution] = joint[revolution].max(o.joint_force_peak);
        stress[revolution] = stress[revolution].max(o.rod_stress_peak);
    }
    Ok(Run {
        joint,
        stress,
        steps: sim.stats().steps,
        evaluations: sim.stats().evaluations,
        seconds: start.elapsed().as_secs_f64(),
    })
}

fn main() -> Result<(), Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if let [mode, zeta, n, step @ ..] = args.as_slice() {
        if mode == "time" {
            let step = step.first().map_or(Ok(1e-4), |s| s.parse::<f64>())?;
            let points = (0.024 / step).round() as u32;
            for _ in 0..n.parse::<u32>()? {
                run(
                    zeta.parse()?,
                    Parameters::default().relative_tolerance,
                    points,
                )?;
            }
            return Ok(());
        }
    }
    let references = [1e-4, 1e-5, 1e-6, 1e-7];
    println!(
        "| rod.dampingRatio | steps | evaluations | wall [s] | peak joint force, rev. 1 / 2 [kN] \
         | at rtol 1e-4 … 1e-7 | peak rod stress, rev. 1 / 2 [MPa] | at rtol 1e-4 … 1e-7 \
         | first-60° impacts: worst peak / onset error |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for zeta in [0.0, 0.01, 0.02] {
        let default = run(zeta, Parameters::default().relative_tolerance, 240)?;
        let tight = references
            .iter()
            .map(|&rtol| run(zeta, rtol, 240))
            .collect::<Result<Vec<_>, _>>()?;
        let span = |f: &dyn Fn(&Run) -> f64, scale: f64| {
            let (lo, hi) = tight
                .iter()
                .map(f)
                .fold((f64::INFINITY, 0.0f64), |(lo, hi), x| {
                    (lo.min(x), hi.max(x))
                });
            format!("{:.1}–{:.1}", lo * scale, hi * scale)
        };
        let p = benchmark_b(zeta);
        let (reference, _) = impacts(converged(&p))?;
        let (found, _) = impacts(p)?;
        let pairs = pair(&reference, &found);
        let peak = pairs.iter().map(|p| p.peak_error()).fold(0.0, f64::max);
        let onset = pairs
            .iter()
            .map(|p| p.onset_error_degrees())
            .fold(0.0, f64::max);
        println!(
            "| {zeta} | {} | {} | {:.3} | {:.2} / {:.2} | {} / {} | {:.1} / {:.1} | {} / {} | \
             {} impacts: {:.2} % / {:.2}° |",
            default.steps,
            default.evaluations,
            default.seconds,
            default.joint[0] * 1e-3,
            default.joint[1] * 1e-3,
            span(&|r| r.joint[0], 1e-3),
            span(&|r| r.joint[1], 1e-3),
            default.stress[0] * 1e-6,
            default.stress[1] * 1e-6,
            span(&|r| r.stress[0], 1e-6),
            span(&|r| r.stress[1], 1e-6),
            pairs.len(),
            100.0 * peak,
            onset
        );
    }
    Ok(())
}
