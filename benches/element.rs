//! Criterion benchmarks of the rod kernels: element force and tangent, rod assembly for 4–64
//! elements, the Craig–Bampton reduced force for nModes = 2, 4, 8 (8 elements), and the default
//! 4-mode rod's force with the full and the sampled quadrature (8 and 32 elements).

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use faer::Mat;
use flexible_slider_crank::ancf::element::ElementVector;
use flexible_slider_crank::ancf::{Rod, RodProperties};
use flexible_slider_crank::math;
use flexible_slider_crank::reduction::{Boundary, Quadrature, RodModel};
use nalgebra::Vector2;

/// A deformed (bent and stretched) configuration: straight rod plus a smooth transverse bow.
fn deformed(rod: &Rod) -> Vec<f64> {
    let mut e = rod.straight_configuration(Vector2::zeros(), 0.3);
    for (k, node) in e.chunks_mut(4).enumerate() {
        let s = math::sin(k as f64 * 0.7);
        node[1] += 1e-4 * s;
        node[3] += 1e-3 * s;
    }
    e
}

fn rod(n: usize) -> Rod {
    match Rod::new(RodProperties::benchmark_b(), n) {
        Ok(rod) => rod,
        Err(e) => panic!("benchmark rod: {e}"),
    }
}

fn element(c: &mut Criterion) {
    let rod = rod(1);
    let e = ElementVector::from_column_slice(&deformed(&rod));
    let el = *rod.element();
    c.bench_function("element/elastic_force", |b| {
        b.iter(|| el.elastic_force(black_box(&e)))
    });
    c.bench_function("element/tangent_stiffness", |b| {
        b.iter(|| el.tangent_stiffness(black_box(&e)))
    });
}

fn assembly(c: &mut Criterion) {
    let mut group = c.benchmark_group("rod");
    for n in [4, 8, 16, 32, 64] {
        let rod = rod(n);
        let e = deformed(&rod);
        let e_dot = vec![0.0; e.len()];
        let mut q = vec![0.0; e.len()];
        let mut k = Mat::zeros(e.len(), e.len());
        group.bench_with_input(BenchmarkId::new("internal_force", n), &n, |b, _| {
            b.iter(|| rod.internal_force(black_box(&e), &e_dot, &mut q))
        });
        group.bench_with_input(BenchmarkId::new("tangent_stiffness", n), &n, |b, _| {
            b.iter(|| rod.tangent_stiffness(black_box(&e), k.as_mut()))
        });
    }
    group.finish();
}

fn reduced(c: &mut Criterion) {
    let mut models = vec![("full".to_string(), RodModel::full(rod(8)))];
    for m in [2, 4, 8] {
        models.push((
            format!("nModes={m}"),
            RodModel::craig_bampton(rod(8), m, Boundary::PositionsAndSlopes, Quadrature::Full),
        ));
    }
    model_forces(c, "model_force_8_elements", 8, models);
}

/// The 4-mode pin-interface rod (the default) with the full and the sampled quadrature, reduced
/// from 8 and from 32 elements.
fn sampled(c: &mut Criterion) {
    for n in [8, 32] {
        let models = [("full", Quadrature::Full), ("sampled", Quadrature::Sampled)]
            .map(|(name, q)| {
                let model = RodModel::craig_bampton(rod(n), 4, Boundary::Pins, q);
                (format!("pins, nModes=4, {name}"), model)
            })
            .into();
        model_forces(c, &format!("model_force_{n}_elements"), n, models);
    }
}

type Models = Vec<(String, Result<RodModel, flexible_slider_crank::ModelError>)>;

/// The internal force of each model in the deformed configuration of an `n`-element rod.
fn model_forces(c: &mut Criterion, group: &str, n: usize, models: Models) {
    let mut group = c.benchmark_group(group);
    let e = deformed(&rod(n));
    for (name, model) in models {
        let mut model = match model {
            Ok(model) => model,
            Err(e) => panic!("{name}: {e}"),
        };
        let p = model.model_coordinates(&e);
        let p_dot = vec![0.0; p.len()];
        let mut q = vec![0.0; p.len()];
        // Two configurations in turn, so that the model's reuse of the last force never applies.
        let mut moved = p.clone();
        moved[0] += 1e-12;
        let configurations = [p, moved];
        let mut turn = 0;
        group.bench_function(BenchmarkId::new("internal_force", &name), |b| {
            b.iter(|| {
                turn ^= 1;
                model.internal_force(black_box(&configurations[turn]), &p_dot, &mut q)
            })
        });
    }
    group.finish();
}

criterion_group!(benches, element, assembly, reduced, sampled);
criterion_main!(benches);
