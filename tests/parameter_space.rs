//! Random parameter sets near the defaults: each gives a clean error naming a parameter,
//! or a run whose outputs are finite and whose energy balance holds, within the work limit.
//! A fixed-seed sample small enough for CI.

// Test code: a failed unwrap is a failed test, with its message.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use flexible_slider_crank::math;
use flexible_slider_crank::params::{ContactLaw, JointModel, RodFormulation};
use flexible_slider_crank::{ModelError, Parameters, Simulation};

/// A small deterministic generator (SplitMix64), uniform in [0, 1).
struct Random(u64);

impl Random {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        (z ^ (z >> 31)) as f64 / 2f64.powi(64)
    }

    /// `value` times a log-uniform factor in [1/4, 4].
    fn scale(&mut self, value: f64) -> f64 {
        value * math::powf(4.0, 2.0 * self.next() - 1.0)
    }
}

#[test]
fn random_sets_near_the_defaults_run_or_fail_cleanly() {
    let mut rng = Random(2026);
    let (mut ran, mut rejected) = (0, 0);
    for case in 0..12 {
        let mut p = Parameters {
            rod_formulation: [RodFormulation::Rigid, RodFormulation::CraigBampton][case % 2],
            ..Parameters::default()
        };
        p.joint.model = [JointModel::Dry, JointModel::Lubricated, JointModel::Ideal][case % 3];
        p.joint.contact_law = [
            ContactLaw::LankaraniNikravesh,
            ContactLaw::Flores,
            ContactLaw::HuGuo,
        ][case % 3];
        p.joint.clearance = rng.scale(p.joint.clearance);
        p.crank_initial_speed = Some(rng.scale(flexible_slider_crank::params::BENCHMARK_SPEED));
        p.joint.restitution = (rng.scale(p.joint.restitution)).min(1.0);
        p.joint.friction = 0.05 * rng.next();
        p.slider_mass = rng.scale(p.slider_mass);
        p.crank_length = rng.scale(p.crank_length);
        p.rod.youngs_modulus = rng.scale(p.rod.youngs_modulus);
        p.joint.viscosity = rng.scale(p.joint.viscosity);
        p.relative_tolerance = 1e-7;
        let sim = Simulation::new(p.clone());
        let mut sim = match sim {
            Err(ModelError::InvalidParameter { name, .. }) => {
                println!("case {case}: rejected, {name}");
                rejected += 1;
                continue;
            }
            Err(e) => panic!("case {case}: {e} for {p:?}"),
            Ok(sim) => sim,
        };
        let e0 = sim.energies().balance();
        let (mut residual, mut scale) = (0.0f64, 0.0f64);
        for i in 1..=20 {
            sim.advance_to(1e-4 * f64::from(i))
                .unwrap_or_else(|e| panic!("case {case}: {e} for {p:?}"));
            let o = sim.outputs().unwrap();
            let values = [
                o.slider_position,
                o.joint_force,
                o.joint_force_peak,
                o.slider_acceleration_peak,
                o.kinetic_energy,
                o.deformation_energy,
                o.dissipated_energy,
            ];
            assert!(values.iter().all(|v| v.is_finite()), "case {case}: {o:?}");
            let e = sim.energies();
            scale = scale.max(e.kinetic).max(e.drive_work.abs());
            residual = residual.max((e.balance() - e0).abs());
        }
        let rel = residual / scale;
        println!(
            "case {case}: {:?} rod, {:?} joint, c = {:.2e} m, ω₀ = {:.0} rad/s: balance residual {rel:.1e}, {} steps, warnings {:?}",
            p.rod_formulation,
            p.joint.model,
            p.joint.clearance,
            p.start_speed(flexible_slider_crank::params::BENCHMARK_SPEED),
            sim.stats().steps,
            sim.take_warnings()
        );
        assert!(rel < 1e-4, "case {case}: residual {rel:e} for {p:?}");
        ran += 1;
    }
    println!("{ran} ran, {rejected} rejected with a named parameter");
    assert!(ran >= 8);
}
