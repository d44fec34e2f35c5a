//! What the FMU relies on: cut-independent and restorable runs, rejected geometry, the work limit.

use super::*;

/// The result does not depend on how [0, T] is cut into advance_to calls beyond the
/// integration error itself (measured as the change from rtol to rtol/100; impacts amplify it far
/// above rtol), and restore-then-advance is bit-identical to never having stopped.
#[test]
fn cuts_do_not_matter_and_restore_is_bit_exact() {
    let p = Parameters {
        n_elements: 4,
        n_modes: 2,
        relative_tolerance: 1e-9,
        ..Parameters::default()
    };
    let t_end = 0.5 * REVOLUTION;
    let final_position = |p: Parameters, cuts: usize| run(p, t_end, cuts).1[cuts].slider_position;
    let one = final_position(p.clone(), 1);
    let many = final_position(p.clone(), 37);
    // At rtol 1e-11 the half revolution takes more internal steps than one interval may.
    let tighter = final_position(
        Parameters {
            relative_tolerance: 1e-11,
            max_steps_per_interval: 1_000_000,
            ..p.clone()
        },
        1,
    );
    let (cut_effect, integration_error) = ((one - many).abs(), (one - tighter).abs());
    println!(
        "slider position after half a revolution: one call vs 37 calls differ by {cut_effect:.2e} m; \
         integration error (rtol 1e-9 vs 1e-11) {integration_error:.2e} m"
    );
    assert!(
        cut_effect <= integration_error,
        "{cut_effect:e} > {integration_error:e}"
    );

    assert_restore_is_bit_exact(p, t_end);
    // The generalized-α method carries its algorithmic accelerations in the snapshot.
    assert_restore_is_bit_exact(
        Parameters {
            method: Method::GeneralizedAlpha,
            relative_tolerance: 1e-4,
            n_elements: 4,
            n_modes: 2,
            ..Parameters::default()
        },
        t_end,
    );
}

/// A snapshot at t_end/2, advanced to t_end in a new simulation, equals the uninterrupted run bit
/// for bit (state and statistics).
fn assert_restore_is_bit_exact(p: Parameters, t_end: f64) {
    let mut sim = Simulation::new(p.clone()).unwrap();
    sim.advance_to(0.5 * t_end).unwrap();
    let snap = sim.snapshot();
    sim.advance_to(t_end).unwrap();
    let reference = sim.state().to_vec();
    let mut other = Simulation::new(p).unwrap();
    other.restore(&snap).unwrap();
    other.advance_to(t_end).unwrap();
    assert_eq!(
        other.state(),
        &reference[..],
        "restore-then-advance is not bit-identical"
    );
    assert_eq!(other.stats(), sim.stats());
}

/// Bad input is a typed error naming the parameter.
#[test]
fn inconsistent_geometry_is_rejected() {
    let p = Parameters {
        crank_length: 0.2,
        ..Parameters::default()
    };
    let err = Simulation::new(p).unwrap_err().to_string();
    assert!(err.starts_with("rod.length = 0.12 is outside"), "{err}");
}

/// Bounded work: an interval that needs more internal steps than
/// `solver.maxStepsPerInterval` ends with an error that names the limit and the likely causes
/// that apply (friction and the contact here; not the material damping, which is off, nor the
/// default tolerance), at the last accepted step, and the simulation stays usable (snapshot,
/// restore with a higher limit, advance).
#[test]
fn work_limit_ends_an_interval_with_a_named_cause() {
    let p = Parameters {
        joint: JointParameters {
            friction: 0.3,
            ..Parameters::default().joint
        },
        max_steps_per_interval: 20,
        ..Parameters::default()
    };
    let mut sim = Simulation::new(p.clone()).unwrap();
    let message = sim.advance_to(2e-3).unwrap_err().to_string();
    println!("{message}");
    for name in [
        "solver.maxStepsPerInterval = 20",
        "joint.friction = 0.3",
        "joint.clearance = 0.0005 m",
    ] {
        assert!(message.contains(name), "{message}");
    }
    for name in ["rod.stiffnessDamping", "solver.relativeTolerance"] {
        assert!(!message.contains(name), "{message}");
    }
    let stopped = sim.time();
    assert!(stopped > 0.0 && stopped < 2e-3, "{stopped}");
    let attempts = sim.stats().steps + sim.stats().rejected;
    assert_eq!(attempts, 20);
    // Raising the limit goes on from where the interval stopped.
    let snapshot = sim.snapshot();
    let mut other = Simulation::new(Parameters {
        max_steps_per_interval: 50_000,
        ..p
    })
    .unwrap();
    other.restore(&snapshot).unwrap();
    other.advance_to(2e-3).unwrap();
    assert!(other.outputs().unwrap().slider_position.is_finite());
}
