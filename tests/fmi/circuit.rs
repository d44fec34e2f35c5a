//! The lubrication circuit's FMU through its C API: its steady start in closed form, the sump's
//! response to the bearings' heat against its first-order solution, its state (bit-exact,
//! serialized into another instance), the warning of an empty gallery and its refusals of bad
//! calls, each naming what was wrong; and its oil, by default the slider-crank's.

use fmi_sys::fmi2::*;

use crate::harness::{Instance, real_start};

/// Value reference of a circuit variable by name.
fn vr(name: &str) -> u32 {
    lube_circuit::variables::VARIABLES
        .iter()
        .find(|v| v.name == name)
        .map(|v| v.vr as u32)
        .unwrap_or_else(|| panic!("no variable {name}"))
}

const OUTPUTS: [&str; 5] = [
    "oil.supplyPressure",
    "oil.supplyTemperature",
    "sump.temperature",
    "relief.flow",
    "cooler.heatFlow",
];

fn outputs(m: &Instance) -> [f64; 5] {
    let v = m.get_reals(&OUTPUTS.map(vr));
    [v[0], v[1], v[2], v[3], v[4]]
}

/// A circuit whose bearings draw 0.4 and 0.6 cm³/s and return 6 W and 10 W, initialised at t = 0.
fn loaded_circuit(name: &str) -> Instance {
    let m = Instance::circuit(name);
    for (input, value) in [
        ("mainBearing.oilFlow", 0.6e-6),
        ("crankPin.oilFlow", 0.4e-6),
        ("mainBearing.heatFlow", 10.0),
        ("crankPin.heatFlow", 6.0),
    ] {
        assert_eq!(m.set_real(vr(input), value), fmi2Status_fmi2OK);
    }
    m.initialize();
    m
}

/// The circuit's oil properties start as the slider-crank's (each FMU owns its table, so this is
/// what keeps them one oil when a system runs on their start values).
#[test]
fn circuit_oil_starts_as_the_slider_cranks() {
    for name in ["oil.density", "oil.specificHeat"] {
        let circuit = real_start(lube_circuit::variables::VARIABLES, name);
        let crank = real_start(flexible_slider_crank::variables::VARIABLES, name);
        assert_eq!(
            circuit.to_bits(),
            crank.to_bits(),
            "{name}: {circuit} against {crank}"
        );
    }
}

/// The start: the gallery at the relief valve's steady pressure p_c + (Q_p − Q_b)/k_r for the
/// bearings' flows (defaults Q_p = 5 cm³/s, p_c = 2 bar, k_r = 1e-10 m³/(s Pa): 2.4 bar), the
/// sump at 40 °C, the supply half-way to the coolant's 35 °C (ε = 0.5), the cooler taking
/// ρ c_p Q_p ε (T_s − T_c) = 21.75 W. Then, the bearings' 16 W in, the sump relaxes towards
/// T_c + 16 W/(ρ c_p Q_p ε) with the time constant V_s/(Q_p ε) = 200 s: after 20 s of 1 ms steps
/// within 1e-9 of its first-order solution, the pressure unchanged within 1e-9.
#[test]
fn circuit_starts_steady_and_its_sump_relaxes_at_first_order() {
    let m = loaded_circuit("circuit-start");
    let pressure = 2e5 + (5e-6 - 1e-6) / 1e-10;
    let conductance = 870.0 * 2000.0 * 5e-6 * 0.5;
    let start = outputs(&m);
    let expected = [pressure, 310.65, 313.15, 4e-6, conductance * 5.0];
    for (x, e) in start.iter().zip(expected) {
        assert!((x - e).abs() <= 1e-12 * e, "{start:?} vs {expected:?}");
    }
    let h = 1e-3;
    for n in 0..20_000 {
        assert_eq!(m.do_step(n as f64 * h, h), fmi2Status_fmi2OK);
    }
    let [p, _, sump, _, _] = outputs(&m);
    let steady = 308.15 + 16.0 / conductance;
    let tau = 5e-4 / (5e-6 * 0.5);
    let exact = steady + (313.15 - steady) * libm::exp(-20.0 / tau);
    println!("sump {sump} K, first-order {exact} K, pressure {p} Pa");
    assert!((sump - exact).abs() <= 1e-9 * (313.15 - steady).abs());
    assert!((p - pressure).abs() <= 1e-9 * pressure);
    assert_eq!(m.get_integer(vr("solver.warnings")).1, 0);
}

/// Restoring a state replays the run bit for bit, in the same and in another instance.
#[test]
fn circuit_state_replays_bit_for_bit() {
    let m = loaded_circuit("circuit-state");
    let h = 1e-4;
    let run = |m: &Instance, from: usize| {
        for n in from..from + 20 {
            let flow = 1e-6 * (1.0 + 0.5 * libm::sin(n as f64 * 0.3));
            assert_eq!(m.set_real(vr("crankPin.oilFlow"), flow), fmi2Status_fmi2OK);
            assert_eq!(m.do_step(n as f64 * h, h), fmi2Status_fmi2OK);
        }
        outputs(m).map(f64::to_bits)
    };
    run(&m, 0);
    let state = m.get_state();
    let bytes = m.serialize(state);
    let first = run(&m, 20);
    assert_eq!(m.set_state(state), fmi2Status_fmi2OK);
    assert_eq!(run(&m, 20), first);
    m.free_state(state);

    let other = Instance::circuit("circuit-state-other");
    let (status, restored) = other.deserialize(&bytes);
    assert_eq!(status, fmi2Status_fmi2OK);
    assert_eq!(other.set_state(restored), fmi2Status_fmi2OK);
    assert_eq!(run(&other, 20), first);
    other.free_state(restored);
}

/// Bearings that draw more than the pump delivers empty the gallery: its pressure falls to zero,
/// and the FMU warns once, naming the flows.
#[test]
fn circuit_warns_when_its_gallery_empties() {
    let m = loaded_circuit("circuit-starved");
    assert_eq!(m.set_real(vr("joint.oilFlow"), 6e-6), fmi2Status_fmi2OK);
    for n in 0..100 {
        assert_eq!(m.do_step(n as f64 * 1e-4, 1e-4), fmi2Status_fmi2OK);
    }
    assert_eq!(m.get_real(vr("oil.supplyPressure")).1, 0.0);
    assert_eq!(m.get_integer(vr("solver.warnings")).1, 1);
    let warned: Vec<_> = m
        .messages()
        .into_iter()
        .filter(|s| s.contains("gallery is empty"))
        .collect();
    assert_eq!(warned.len(), 1, "{warned:?}");
    assert!(warned[0].contains("pump.flow = 5e-6"), "{}", warned[0]);
}

/// Bad calls return fmi2Error with a message naming what was wrong; after fmi2Reset the instance
/// runs again.
#[test]
fn circuit_refuses_bad_calls() {
    let m = Instance::circuit("circuit-refusals");
    let refused = |status, named: &str| {
        assert_eq!(status, fmi2Status_fmi2Error);
        assert!(m.last_message().contains(named), "{}", m.last_message());
        assert_eq!(m.reset(), fmi2Status_fmi2OK);
    };
    refused(
        m.set_real(vr("cooler.effectiveness"), 1.5),
        "cooler.effectiveness",
    );
    refused(
        m.set_real(vr("crankPin.oilFlow"), -1e-6),
        "crankPin.oilFlow",
    );
    refused(
        m.set_real(vr("oil.supplyPressure"), 1e5),
        "oil.supplyPressure",
    );
    refused(m.do_step(0.0, 1e-4), "fmi2DoStep");
    m.initialize();
    let state = m.get_state();
    let bytes = m.serialize(state);
    m.free_state(state);
    let (status, _) = m.deserialize(&bytes[..bytes.len() - 1]);
    refused(status, "FMU state");
    m.initialize();
    assert_eq!(m.do_step(0.0, 1e-4), fmi2Status_fmi2OK);
}
