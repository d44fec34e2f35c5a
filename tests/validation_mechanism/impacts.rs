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
/// the main bearing, and worn at all three joints: the worst peak and onset errors of the first
/// 60°'s significant impacts at each worn crank joint, against the converged run, each case held
/// at its own bound. Where one joint is worn the defaults hold 2 % and 0.1°; where the pins' impact
/// sequences feed each other (both pins worn; the rigid rod's crank pin with all three worn) the
/// later impacts drift further, and the bound is the one measured (BENCHMARKS.md, "Load spectrum").
/// The 4-mode rod's worn crank pin is judged by its first impact alone: the worst error of its
/// later ones spreads over 0.4–6.7 % across eleven runs that differ only in the ninth digit of the
/// tolerance (four of eleven within 2 %, with or without a change of the integrator that moves no
/// impact), so one trajectory cannot judge them.
#[test]
fn every_crank_joint_impact_is_right_at_the_defaults() {
    use JointModel::{Dry, Ideal};
    use JointRole::{CrankPin, MainBearing};
    // (case, main bearing, crank pin, rod–slider joint)
    let cases: [(&str, JointModel, JointModel, JointModel); 4] = [
        ("crank pin", Ideal, Dry, Ideal),
        ("both pins", Ideal, Dry, Dry),
        ("main bearing", Dry, Ideal, Ideal),
        ("all three", Dry, Dry, Dry),
    ];
    // (benchmark, case, joint measured, worst peak error, worst onset error [°]); the measured
    // values are in BENCHMARKS.md.
    const BOUNDS: [(&str, &str, JointRole, f64, f64); 10] = [
        ("rigid (A)", "crank pin", CrankPin, 0.02, 0.1),
        ("rigid (A)", "both pins", CrankPin, 0.21, 0.8),
        ("rigid (A)", "main bearing", MainBearing, 0.02, 0.1),
        ("rigid (A)", "all three", MainBearing, 0.02, 0.1),
        ("rigid (A)", "all three", CrankPin, 0.04, 0.3),
        ("4 modes (B)", "crank pin", CrankPin, 0.02, 0.1),
        ("4 modes (B)", "both pins", CrankPin, 0.12, 0.1),
        ("4 modes (B)", "main bearing", MainBearing, 0.02, 0.1),
        ("4 modes (B)", "all three", MainBearing, 0.02, 0.1),
        ("4 modes (B)", "all three", CrankPin, 0.02, 0.1),
    ];
    let benchmarks = benchmarks();
    for (name, case, role, peak_bound, onset_bound) in BOUNDS {
        let (_, base) = benchmarks.iter().find(|(n, _)| *n == name).unwrap();
        let &(_, main_bearing, crank_pin, slider_pin) =
            cases.iter().find(|(c, ..)| *c == case).unwrap();
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
        let (reference, _) = impacts_at(converged(&p), role).unwrap();
        let (run, steps) = impacts_at(p, role).unwrap();
        let pairs = pair(&reference, &run);
        let worst = |pairs: &[load_spectrum::Pair]| {
            pairs.iter().fold((0.0f64, 0.0f64), |(peak, onset), pair| {
                (
                    peak.max(pair.peak_error()),
                    onset.max(pair.onset_error_degrees()),
                )
            })
        };
        let (all, judged) = (worst(&pairs), worst(&pairs[..1.min(pairs.len())]));
        let judged = if (name, case) == ("4 modes (B)", "crank pin") {
            judged
        } else {
            all
        };
        println!(
            "{name}, {case} worn: {} {} impacts, worst peak error {:.2} %, worst onset error \
             {:.2}°, {steps} steps",
            pairs.len(),
            role.prefix(),
            100.0 * all.0,
            all.1
        );
        assert!(pairs.len() >= 2, "{name}, {case}: {} impacts", pairs.len());
        assert!(
            judged.0 <= peak_bound && judged.1 <= onset_bound,
            "{name}, {case}, {}: {pairs:?}",
            role.prefix()
        );
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
