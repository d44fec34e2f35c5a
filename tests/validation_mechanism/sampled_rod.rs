//! The sampled (hyper-reduced) Craig–Bampton rod against the full quadrature it stands for.

use super::*;

/// The largest joint force peak and rod deformation-energy peak over two revolutions.
fn peaks(p: Parameters) -> (f64, f64) {
    let (_, rows) = run(p, 2.0 * REVOLUTION, 240);
    rows.iter().fold((0.0f64, 0.0f64), |(force, energy), o| {
        (
            force.max(o.joint_force_peak),
            energy.max(o.deformation_energy_peak),
        )
    })
}

/// Benchmark B (4 modes, dry joint, the defaults) with a rod reduced from 8 and from 32 elements:
/// with the sampled quadrature, the largest `joint.forcePeak` and `rod.deformationEnergyPeak` of two
/// revolutions are the full quadrature's within 0.5 %.
#[test]
fn a_sampled_rod_keeps_benchmark_bs_peaks() {
    for n_elements in [8, 32] {
        let at = |quadrature| {
            peaks(Parameters {
                n_elements,
                quadrature,
                ..Parameters::default()
            })
        };
        let (full, sampled) = (at(Quadrature::Full), at(Quadrature::Sampled));
        let error = |a: f64, b: f64| (b - a).abs() / a;
        println!(
            "{n_elements} elements: force peak {:.1} / {:.1} N ({:.3} %), energy peak {:.5} / {:.5} J \
             ({:.4} %)",
            full.0,
            sampled.0,
            100.0 * error(full.0, sampled.0),
            full.1,
            sampled.1,
            100.0 * error(full.1, sampled.1)
        );
        assert!(error(full.0, sampled.0) < 5e-3, "{full:?} {sampled:?}");
        assert!(error(full.1, sampled.1) < 5e-3, "{full:?} {sampled:?}");
    }
}
