//! The DC motor's FMU through its C API: its steady start in closed form, its state (bit-exact,
//! serialized into another instance), its derivatives against the motor's equations and a
//! difference quotient, and its refusals of bad calls, each naming what was wrong.

use fmi_sys::fmi2::*;

use crate::harness::{Instance, motor};

/// Value reference of a motor variable by name.
fn vr(name: &str) -> u32 {
    dc_motor::variables::VARIABLES
        .iter()
        .find(|v| v.name == name)
        .map(|v| v.vr as u32)
        .unwrap_or_else(|| panic!("no variable {name}"))
}

/// A motor set to hold `torque` at `speed` (set-point and load speed), initialised at t = 0.
fn steady_motor(name: &str, speed: f64, torque: f64) -> Instance {
    let m = Instance::motor(name);
    assert_eq!(
        m.set_real(vr("shaft.initialTorque"), torque),
        fmi2Status_fmi2OK
    );
    assert_eq!(m.set_real(vr("speed.setPoint"), speed), fmi2Status_fmi2OK);
    assert_eq!(m.set_real(vr("shaft.speed"), speed), fmi2Status_fmi2OK);
    m.initialize();
    m
}

const OUTPUTS: [&str; 5] = [
    "shaft.torque",
    "motor.speed",
    "motor.current",
    "motor.voltage",
    "shaft.twist",
];

fn outputs(m: &Instance) -> Vec<f64> {
    m.get_reals(&OUTPUTS.map(vr))
}

/// The start holds the shaft torque at the set-point with the controller at rest:
/// i = (τ + b ω)/k, u = R i + k ω, φ = τ/k_s (defaults R = 0.2 Ω, k = 0.2 N m/A, b = 1e-4 N m s/rad,
/// k_s = 2e4 N m/rad), and the load held at that speed keeps it there.
#[test]
fn motor_starts_and_stays_in_steady_state() {
    let (speed, torque) = (300.0, 12.0);
    let m = steady_motor("motor-steady", speed, torque);
    let current = (torque + 1e-4 * speed) / 0.2;
    let expected = [
        torque,
        speed,
        current,
        0.2 * current + 0.2 * speed,
        torque / 2e4,
    ];
    let close = |a: &[f64], tol: f64| {
        a.iter()
            .zip(expected)
            .all(|(x, e)| (x - e).abs() <= tol * e.abs())
    };
    let start = outputs(&m);
    assert!(close(&start, 1e-14), "{start:?} vs {expected:?}");
    for n in 0..100 {
        assert_eq!(m.do_step(n as f64 * 1e-4, 1e-4), fmi2Status_fmi2OK);
    }
    let later = outputs(&m);
    assert!(close(&later, 1e-10), "{later:?} vs {expected:?}");
}

/// Restoring a state replays the run bit for bit, in the same and in another instance.
#[test]
fn motor_state_replays_bit_for_bit() {
    let m = steady_motor("motor-state", 300.0, 5.0);
    assert_eq!(m.set_real(vr("speed.setPoint"), 320.0), fmi2Status_fmi2OK);
    let h = 1e-4;
    let run = |m: &Instance, from: usize| {
        for n in from..from + 20 {
            let load = 300.0 + n as f64 * 0.1;
            assert_eq!(m.set_real(vr("shaft.speed"), load), fmi2Status_fmi2OK);
            assert_eq!(m.do_step(n as f64 * h, h), fmi2Status_fmi2OK);
        }
        outputs(m).iter().map(|x| x.to_bits()).collect::<Vec<_>>()
    };
    run(&m, 0);
    let state = m.get_state();
    let bytes = m.serialize(state);
    let first = run(&m, 20);
    assert_eq!(m.set_state(state), fmi2Status_fmi2OK);
    assert_eq!(run(&m, 20), first);
    m.free_state(state);

    let other = Instance::motor("motor-state-other");
    let (status, restored) = other.deserialize(&bytes);
    assert_eq!(status, fmi2Status_fmi2OK);
    assert_eq!(other.set_state(restored), fmi2Status_fmi2OK);
    assert_eq!(run(&other, 20), first);
    other.free_state(restored);
}

/// ∂(shaft torque)/∂(load speed) = −d_s (τ = k_s φ + d_s (ω − ω_L)), and 0 for the rotor's speed,
/// which the load reaches only through the state.
#[test]
fn motor_directional_derivative_is_the_shafts_damping() {
    let m = steady_motor("motor-directional", 300.0, 5.0);
    let known = [vr("shaft.speed")];
    let unknown = [vr("shaft.torque"), vr("motor.speed")];
    let mut column = [f64::NAN; 2];
    // SAFETY: one known and two unknowns, with matching seeds and results.
    let status = unsafe {
        motor().fmi2GetDirectionalDerivative(
            m.c,
            unknown.as_ptr(),
            2,
            known.as_ptr(),
            1,
            [1.0].as_ptr(),
            column.as_mut_ptr(),
        )
    };
    assert_eq!(status, fmi2Status_fmi2OK);
    assert_eq!(column, [-2.0, 0.0]);
}

/// The rotor's acceleration from fmi2GetRealOutputDerivatives agrees with the difference quotient
/// of its speed over a short step, by the trapezoidal rule (error O(δ²)), while the motor
/// accelerates towards a raised set-point.
#[test]
fn motor_output_derivative_is_the_slope_of_its_output() {
    let m = steady_motor("motor-derivative", 300.0, 5.0);
    assert_eq!(m.set_real(vr("speed.setPoint"), 320.0), fmi2Status_fmi2OK);
    assert_eq!(m.do_step(0.0, 1e-3), fmi2Status_fmi2OK);
    let acceleration = |m: &Instance| {
        let mut value = f64::NAN;
        // SAFETY: one value reference, order and value.
        let status = unsafe {
            motor().fmi2GetRealOutputDerivatives(m.c, &vr("motor.speed"), 1, &1, &mut value)
        };
        assert_eq!(status, fmi2Status_fmi2OK);
        value
    };
    let delta = 1e-6;
    let (w0, a0) = (m.get_real(vr("motor.speed")).1, acceleration(&m));
    assert_eq!(m.do_step(1e-3, delta), fmi2Status_fmi2OK);
    let (w1, a1) = (m.get_real(vr("motor.speed")).1, acceleration(&m));
    let slope = (w1 - w0) / delta;
    println!("slope {slope} rad/s², derivatives {a0} and {a1}");
    assert!(slope > 100.0, "{slope}");
    assert!((slope - 0.5 * (a0 + a1)).abs() <= 1e-6 * slope.abs());
}

/// Bad calls return fmi2Error with a message naming what was wrong; after fmi2Reset the instance
/// runs again.
#[test]
fn motor_refuses_bad_calls() {
    let m = Instance::motor("motor-refusals");
    let refused = |status, named: &str| {
        assert_eq!(status, fmi2Status_fmi2Error);
        assert!(m.last_message().contains(named), "{}", m.last_message());
        assert_eq!(m.reset(), fmi2Status_fmi2OK);
    };
    refused(m.set_real(vr("motor.resistance"), 0.0), "motor.resistance");
    refused(m.set_real(vr("speed.setPoint"), f64::NAN), "speed.setPoint");
    refused(m.do_step(0.0, 1e-4), "fmi2DoStep");
    m.initialize();
    refused(m.do_step(0.5, 1e-4), "0.5");
    m.initialize();
    let state = m.get_state();
    let bytes = m.serialize(state);
    m.free_state(state);
    let (status, _) = m.deserialize(&bytes[..bytes.len() - 1]);
    refused(status, "FMU state");
    m.initialize();
    assert_eq!(m.do_step(0.0, 1e-4), fmi2Status_fmi2OK);
}
