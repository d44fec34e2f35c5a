//! What a fine communication grid costs and how accurate its values are: two revolutions of
//! benchmark B/C (24 ms at 5000 rpm, 4-mode rod, the library's defaults) read every 10 µs
//! (2 400 points) and every 100 µs (240, the DefaultExperiment), for the undamped and damped rods
//! with the dry rod–slider joint and for the lubricated one.
//!
//! For each case: the wall time of each grid (best of five runs) and their ratio; and, at the
//! 10 µs points of the first 60° of crank rotation (2 ms, the impacts of the load-spectrum check;
//! later the impact sequences of runs at different tolerances drift apart in time, so that
//! values at the same instant no longer compare), the largest error of the joint force, slider
//! acceleration, crank torque, rod stress and slider velocity against the same model run at rtol
//! 1e-8 (explicit Dormand–Prince, read at the same points), as a fraction of the reference's
//! range over that window.
//!
//! `cargo run --release --example communication_points` prints a Markdown table.

use std::error::Error;
use std::time::Instant;

use flexible_slider_crank::integrator::Method;
use flexible_slider_crank::params::RodFormulation;
use flexible_slider_crank::{Parameters, Simulation};

/// The run's length \[s\].
const END: f64 = 0.024;
/// The window the values are compared over: the first 60° at 5000 rpm \[s\].
const WINDOW: f64 = 0.002;
/// The compared outputs' names.
const NAMES: [&str; 5] = [
    "joint.force",
    "slider.acceleration",
    "crank.torque",
    "rod.stress",
    "slider.velocity",
];

/// The compared outputs at one point.
type Values = [f64; NAMES.len()];

/// The compared outputs at every point of a run with `points` points, and its wall time \[s\].
fn run(p: &Parameters, points: u32) -> Result<(Vec<Values>, f64), Box<dyn Error>> {
    let start = Instant::now();
    let mut sim = Simulation::new(p.clone())?;
    let mut values = Vec::with_capacity(points as usize);
    for k in 1..=points {
        sim.advance_to(END * f64::from(k) / f64::from(points))?;
        let o = sim.outputs()?;
        values.push([
            o.joint_force,
            o.slider_acceleration,
            o.crank_torque,
            o.rod_stress,
            o.slider_velocity,
        ]);
    }
    Ok((values, start.elapsed().as_secs_f64()))
}

/// The shortest wall time of five runs \[s\].
fn best(p: &Parameters, points: u32) -> Result<f64, Box<dyn Error>> {
    let mut best = f64::INFINITY;
    for _ in 0..5 {
        best = best.min(run(p, points)?.1);
    }
    Ok(best)
}

fn main() -> Result<(), Box<dyn Error>> {
    let b = Parameters {
        rod_formulation: RodFormulation::CraigBampton,
        n_modes: 4,
        ..Parameters::benchmark_b()
    };
    let damped = |zeta| {
        let mut p = b.clone();
        p.rod.damping_ratio = zeta;
        p
    };
    let lubricated = Parameters {
        rod_formulation: RodFormulation::CraigBampton,
        n_modes: 4,
        ..Parameters::benchmark_c()
    };
    let cases = [
        ("dry, undamped", b.clone()),
        ("dry, ζ = 1 %", damped(0.01)),
        ("dry, ζ = 2 %", damped(0.02)),
        ("lubricated, undamped", lubricated),
    ];
    print!("| case | 100 µs grid [s] | 10 µs grid [s] | ratio |");
    for name in NAMES {
        print!(" {name} error |");
    }
    println!();
    println!("|---|---|---|---|{}", "---|".repeat(NAMES.len()));
    for (name, p) in cases {
        let coarse = best(&p, 240)?;
        let fine = best(&p, 2400)?;
        let (values, _) = run(&p, 2400)?;
        let reference = Parameters {
            method: Method::DormandPrince,
            relative_tolerance: 1e-8,
            ..p.clone()
        };
        let (exact, _) = run(&reference, 2400)?;
        let window = (WINDOW / END * 2400.0).round() as usize;
        let (values, exact) = (&values[..window], &exact[..window]);
        print!(
            "| {name} | {coarse:.3} | {fine:.3} | {:.2} |",
            fine / coarse
        );
        for i in 0..NAMES.len() {
            let (lo, hi) = exact
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), e| {
                    (lo.min(e[i]), hi.max(e[i]))
                });
            let error = values
                .iter()
                .zip(exact)
                .map(|(v, e)| (v[i] - e[i]).abs())
                .fold(0.0, f64::max);
            print!(" {:.1e} |", error / (hi - lo));
        }
        println!();
    }
    Ok(())
}
