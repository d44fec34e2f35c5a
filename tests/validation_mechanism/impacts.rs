//! The load spectrum at the default settings: every impact of the first 60° of benchmark A
//! (rigid rod) and B (4 modes) against a converged run.

#[path = "../support/load_spectrum.rs"]
mod load_spectrum;

use flexible_slider_crank::params::{JointModel, JointParameters, JointRole};
use load_spectrum::{benchmarks, converged, impacts, impacts_at, pair};

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

/// The same at the crank's joints: benchmark A's and B's dry clearance moved to the crank pin, to
/// the main bearing, and worn at all three joints: every significant impact of the first 60° at
/// each worn crank joint within 2 % in peak and 0.1° in onset of the converged run. Asserted where
/// the defaults hold it (`ASSERTED`); measured and printed for the others, some of whose later
/// impacts miss that bound (BENCHMARKS.md, "Load spectrum").
#[test]
fn every_crank_joint_impact_is_right_at_the_defaults() {
    use JointModel::{Dry, Ideal};
    use JointRole::{CrankPin, MainBearing};
    // (case, main bearing, crank pin, rod–slider joint, the joints measured)
    let cases: [(&str, JointModel, JointModel, JointModel, &[JointRole]); 4] = [
        ("crank pin", Ideal, Dry, Ideal, &[CrankPin]),
        ("both pins", Ideal, Dry, Dry, &[CrankPin]),
        ("main bearing", Dry, Ideal, Ideal, &[MainBearing]),
        ("all three", Dry, Dry, Dry, &[MainBearing, CrankPin]),
    ];
    const ASSERTED: &[(&str, &str, JointRole)] = &[
        ("rigid (A)", "crank pin", CrankPin),
        ("rigid (A)", "main bearing", MainBearing),
        ("rigid (A)", "all three", MainBearing),
        ("4 modes (B)", "crank pin", CrankPin),
        ("4 modes (B)", "main bearing", MainBearing),
        ("4 modes (B)", "all three", MainBearing),
        ("4 modes (B)", "all three", CrankPin),
    ];
    for (name, base) in benchmarks().into_iter().take(2) {
        for (case, main_bearing, crank_pin, slider_pin, measured) in cases {
            let worn = |model| JointParameters {
                model,
                ..JointParameters::benchmark()
            };
            let p = crate::Parameters {
                joint: JointParameters {
                    model: slider_pin,
                    ..base.joint
                },
                crank_pin: worn(crank_pin),
                main_bearing: worn(main_bearing),
                ..base.clone()
            };
            for &role in measured {
                let (reference, _) = impacts_at(converged(&p), role).unwrap();
                let (run, steps) = impacts_at(p.clone(), role).unwrap();
                let pairs = pair(&reference, &run);
                let worst = pairs.iter().fold((0.0f64, 0.0f64), |(peak, onset), pair| {
                    (
                        peak.max(pair.peak_error()),
                        onset.max(pair.onset_error_degrees()),
                    )
                });
                println!(
                    "{name}, {case} worn: {} {} impacts, worst peak error {:.2} %, worst onset \
                     error {:.2}°, {steps} steps",
                    pairs.len(),
                    role.prefix(),
                    100.0 * worst.0,
                    worst.1
                );
                assert!(pairs.len() >= 2, "{name}, {case}: {} impacts", pairs.len());
                if ASSERTED.contains(&(name, case, role)) {
                    assert!(worst.0 <= 0.02 && worst.1 <= 0.1, "{name}: {pairs:?}");
                }
            }
        }
    }
}

/// A realistically damped rod at the defaults (`rod.dampingRatio` = 1 % and 2 % of its first
/// bending mode): every significant impact of the first 60° within 2 % in peak and 0.1° in onset
/// of its own converged run (measured 1.2 % and 0.3 %), in fewer steps than the undamped rod's
/// (measured 182 and 142 against 485: the damped rod's vibration after an impact dies out
/// instead of setting the step).
#[test]
fn a_damped_rods_impacts_are_right_at_the_defaults() {
    let (_, undamped) = impacts(flexible_slider_crank::Parameters::default()).unwrap();
    for zeta in [0.01, 0.02] {
        let mut p = flexible_slider_crank::Parameters::default();
        p.rod.damping_ratio = zeta;
        let (reference, _) = impacts(converged(&p)).unwrap();
        let (run, steps) = impacts(p).unwrap();
        let pairs = pair(&reference, &run);
        let worst = pairs.iter().map(|p| p.peak_error()).fold(0.0, f64::max);
        println!(
            "rod.dampingRatio = {zeta}: {} impacts, worst peak error {:.2} %, {steps} steps \
             (undamped {undamped})",
            pairs.len(),
            100.0 * worst
        );
        assert!(pairs.len() >= 3, "{zeta}: {} impacts", pairs.len());
        for pair in &pairs {
            assert!(pair.peak_error() <= 0.02, "{zeta}: {pair:?}");
            assert!(pair.onset_error_degrees() <= 0.1, "{zeta}: {pair:?}");
        }
        assert!(steps < undamped);
    }
}
