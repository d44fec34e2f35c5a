//! Benchmark D: the lubricated joint handing over to dry contact and back.
//! Two revolutions at 5000 rpm; the journal crosses the switch eccentricity ratio ε_b = 0.95 in
//! both directions at least ten times, the joint force is continuous across every crossing, and
//! the energy balance holds throughout.

// Test code: a failed unwrap is a failed test, with its message.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use flexible_slider_crank::math;
use flexible_slider_crank::params::BENCHMARK_SPEED;
use flexible_slider_crank::{Parameters, Simulation};

/// Coarse sampling step \[s\].
const DT: f64 = 1e-6;
/// Fine samples per coarse step around a crossing.
const FINE: usize = 100;

#[test]
fn lubricated_joint_hands_over_to_dry_contact_continuously() {
    let p = Parameters {
        relative_tolerance: 1e-6,
        ..Parameters::benchmark_d()
    };
    let (c, switch) = (p.joint.clearance, p.joint.switch_eccentricity);
    let ratio = |sim: &mut Simulation| {
        let o = sim.outputs().unwrap();
        (
            math::hypot(o.eccentricity_x, o.eccentricity_y) / c,
            o.joint_force,
        )
    };
    let mut sim = Simulation::new(p.clone()).unwrap();
    let e0 = sim.energies().balance();
    let (mut residual, mut kinetic) = (0.0f64, 0.0f64);
    let (mut up, mut down, mut worst_jump) = (0, 0, 0.0f64);
    let (mut previous, _) = ratio(&mut sim);
    let n = (2.0 * std::f64::consts::TAU / BENCHMARK_SPEED / DT).round() as usize;
    let mut fine = Simulation::new(p).unwrap();
    for i in 1..=n {
        let before = sim.snapshot();
        sim.advance_to(DT * i as f64).unwrap();
        let (eps, _) = ratio(&mut sim);
        let e = sim.energies();
        kinetic = kinetic.max(e.kinetic);
        residual = residual.max((e.balance() - e0).abs());
        if (previous < switch) != (eps < switch) {
            if eps >= switch {
                up += 1;
            } else {
                down += 1;
            }
            // Resolve the crossing interval finely: the largest change of the force between
            // neighbouring samples, relative to the local force.
            fine.restore(&before).unwrap();
            let (_, mut f_prev) = ratio(&mut fine);
            for j in 1..=FINE {
                fine.advance_to(DT * ((i - 1) as f64 + j as f64 / FINE as f64))
                    .unwrap();
                let (_, f) = ratio(&mut fine);
                worst_jump = worst_jump.max((f - f_prev).abs() / f.max(f_prev));
                f_prev = f;
            }
        }
        previous = eps;
    }
    let residual = residual / kinetic;
    println!(
        "benchmark D, 2 revolutions: {up} crossings of ε = {switch} upwards, {down} downwards; \
         largest force change between 10 ns samples across a crossing {:.2} % of the local force; \
         energy-balance residual {residual:.1e} of the largest kinetic energy",
        100.0 * worst_jump
    );
    assert!(up >= 10 && down >= 10, "{up} up, {down} down");
    assert!(worst_jump <= 0.01, "jump {worst_jump}");
    assert!(residual < 1e-6, "residual {residual:e}");
}
