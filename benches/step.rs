//! Criterion benchmark of whole simulations: one crank revolution (12 ms at 5000 rpm) of benchmark
//! B/C for each rod model (rigid, full ANCF 8 elements, Craig–Bampton 4 modes) × joint model
//! (ideal, dry, lubricated), default tolerance. Multiply by 83.3 for one simulated second.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use flexible_slider_crank::params::JointParameters;
use flexible_slider_crank::params::{BENCHMARK_SPEED, JointModel, RodFormulation};
use flexible_slider_crank::{Parameters, Simulation};

fn revolution(c: &mut Criterion) {
    let t_end = std::f64::consts::TAU / BENCHMARK_SPEED;
    let mut group = c.benchmark_group("one_revolution");
    group.sample_size(10);
    for rod in [
        RodFormulation::Rigid,
        RodFormulation::CraigBampton,
        RodFormulation::Ancf,
    ] {
        for joint in [JointModel::Ideal, JointModel::Dry, JointModel::Lubricated] {
            let p = Parameters {
                joint: JointParameters {
                    model: joint,
                    ..Parameters::default().joint
                },
                rod_formulation: rod,
                ..Parameters::default()
            };
            let id = BenchmarkId::new(format!("{rod:?}"), format!("{joint:?}"));
            group.bench_with_input(id, &p, |b, p| {
                b.iter(|| {
                    let mut sim = match Simulation::new(p.clone()) {
                        Ok(sim) => sim,
                        Err(e) => panic!("{e}"),
                    };
                    if let Err(e) = sim.advance_to(black_box(t_end)) {
                        panic!("{e}");
                    }
                    sim.stats().steps
                })
            });
        }
    }
    group.finish();
}

criterion_group!(benches, revolution);
criterion_main!(benches);
