//! The load spectrum at the default settings: every impact of the first 60° of benchmark A
//! (rigid rod) and B (4 modes) against a converged run.

#[path = "../support/load_spectrum.rs"]
mod load_spectrum;

use load_spectrum::{benchmarks, converged, impacts, pair};

/// At the library's defaults every significant impact's peak force is within 2 % of the converged
/// run's and its onset within 0.1° of crank rotation, the first impact's peak within 0.5 %, for
/// the rigid rod and the 4-mode rod (the error control holds the journal's velocity in the
/// bearing to the tolerance on its own).
#[test]
fn every_impact_is_right_at_the_defaults() {
    for (name, p) in benchmarks().into_iter().take(2) {
        let (reference, _) = impacts(converged(&p)).unwrap();
        let (run, steps) = impacts(p).unwrap();
        let pairs = pair(&reference, &run);
        for (k, pair) in pairs.iter().enumerate() {
            println!(
                "{name} impact {k}: onset {:.2}° → {:.2}°, peak {:.0} → {:.0} N ({:+.2} %)",
                (pair.reference.onset * crate::BENCHMARK_SPEED).to_degrees(),
                (pair.run.onset * crate::BENCHMARK_SPEED).to_degrees(),
                pair.reference.peak,
                pair.run.peak,
                100.0 * (pair.run.peak / pair.reference.peak - 1.0)
            );
        }
        println!("{name}: {steps} steps");
        assert!(pairs.len() >= 5, "{name}: {} impacts", pairs.len());
        assert!(pairs[0].peak_error() <= 0.005, "{name}: {:?}", pairs[0]);
        for pair in &pairs {
            assert!(pair.peak_error() <= 0.02, "{name}: {pair:?}");
            assert!(pair.onset_error_degrees() <= 0.1, "{name}: {pair:?}");
        }
    }
}
