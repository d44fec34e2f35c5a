//! Symbols, instantiation, arguments, ranges, logging, reset and FMU state.

use std::ffi::CStr;

use flexible_slider_crank::fmi::GUID;
use fmi_sys::fmi2::*;

use crate::harness::{
    Instance, callbacks, fmu, instantiate_raw, instantiate_with_logging, library_path, messages, vr,
};

const OK: fmi2Status = fmi2Status_fmi2OK;
const ERROR: fmi2Status = fmi2Status_fmi2Error;

/// Exactly the 34 fmi2* functions of a co-simulation FMU are exported (plus fmi-sys's
/// `callback_log`, docs/fmi.md §2), and the version strings are right.
#[test]
fn exports_exactly_the_34_functions() {
    let out = std::process::Command::new("nm")
        .args(["-D", "--defined-only"])
        .arg(library_path())
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    let mut names: Vec<&str> = text
        .lines()
        .filter_map(|l| l.split_whitespace().nth(2))
        .filter(|n| n.starts_with("fmi2"))
        .collect();
    names.sort_unstable();
    assert_eq!(names.len(), 34, "{names:?}");
    for n in [
        "fmi2DoStep",
        "fmi2GetRealStatus",
        "fmi2DeSerializeFMUstate",
        "fmi2GetDirectionalDerivative",
    ] {
        assert!(names.contains(&n), "{n} missing");
    }
    // SAFETY: static strings.
    unsafe {
        assert_eq!(
            CStr::from_ptr(fmu().fmi2GetVersion()).to_str().unwrap(),
            "2.0"
        );
        assert_eq!(
            CStr::from_ptr(fmu().fmi2GetTypesPlatform())
                .to_str()
                .unwrap(),
            "default"
        );
    }
}

/// Wrong GUID, empty or NULL name, Model Exchange, NULL callbacks or logger: NULL, with a message
/// whenever a logger was given.
#[test]
fn instantiate_rejects_bad_arguments() {
    let cb = callbacks();
    let cs = fmi2Type_fmi2CoSimulation;
    assert!(
        instantiate_raw(
            Some("guid"),
            cs,
            Some("{00000000-0000-0000-0000-000000000000}"),
            None,
            Some(&cb)
        )
        .is_null()
    );
    assert!(
        messages("guid")
            .iter()
            .any(|m| m.contains("Wrong GUID") && m.contains(GUID)),
        "{:?}",
        messages("guid")
    );
    assert!(instantiate_raw(Some("noguid"), cs, None, None, Some(&cb)).is_null());
    assert!(instantiate_raw(Some(""), cs, Some(GUID), None, Some(&cb)).is_null());
    assert!(messages("").iter().any(|m| m.contains("instanceName")));
    assert!(instantiate_raw(None, cs, Some(GUID), None, Some(&cb)).is_null());
    assert!(
        instantiate_raw(
            Some("me"),
            fmi2Type_fmi2ModelExchange,
            Some(GUID),
            None,
            Some(&cb)
        )
        .is_null()
    );
    assert!(messages("me").iter().any(|m| m.contains("co-simulation")));
    assert!(instantiate_raw(Some("nocb"), cs, Some(GUID), None, None).is_null());
    let no_logger = fmi2CallbackFunctions { logger: None, ..cb };
    assert!(instantiate_raw(Some("nolog"), cs, Some(GUID), None, Some(&no_logger)).is_null());
}

/// Resource URIs in every accepted form (and NULL) instantiate.
#[test]
fn resource_location_variants_are_accepted() {
    for uri in [
        Some("file:///tmp/fsc/resources"),
        Some("file:/tmp/fsc/resources/"),
        Some("file://localhost/tmp/fsc%20x/resources"),
        Some(""),
        None,
    ] {
        let c = instantiate_raw(
            Some("uri"),
            fmi2Type_fmi2CoSimulation,
            Some(GUID),
            uri,
            Some(&callbacks()),
        );
        assert!(!c.is_null(), "{uri:?}");
        // SAFETY: live instance, freed once.
        unsafe { fmu().fmi2FreeInstance(c) };
    }
}

/// NULL arrays with nvr > 0 are errors naming the argument; nvr = 0 with NULL arrays is OK;
/// unknown value references and wrong base types are errors.
#[test]
fn arguments_are_checked() {
    let inst = Instance::new("args");
    inst.initialize();
    // SAFETY: NULL pointers with nvr = 0 must not be read; with nvr = 1 the FMU must reject them.
    unsafe {
        assert_eq!(
            fmu().fmi2GetReal(inst.c, std::ptr::null(), 0, std::ptr::null_mut()),
            OK
        );
        let r = vr("slider.position");
        assert_eq!(
            fmu().fmi2GetReal(inst.c, &r, 1, std::ptr::null_mut()),
            ERROR
        );
    }
    assert!(
        inst.last_message()
            .contains("Argument value must not be NULL."),
        "{:?}",
        inst.messages()
    );
    for (name, check) in [
        (
            "unknown",
            Box::new(|i: &Instance| i.get_real(9999).0) as Box<dyn Fn(&Instance) -> fmi2Status>,
        ),
        (
            "wrong type",
            Box::new(|i: &Instance| i.get_real(vr("rod.nElements")).0),
        ),
        (
            "integer on real",
            Box::new(|i: &Instance| i.get_integer(vr("slider.position")).0),
        ),
    ] {
        let inst = Instance::new(&format!("args-{name}"));
        inst.initialize();
        assert_eq!(check(&inst), ERROR, "{name}");
        let m = inst.last_message();
        assert!(m.contains("value reference"), "{name}: {m}");
    }
    // fmi2GetDirectionalDerivative: outputs with respect to inputs, arrays checked.
    let inst = Instance::new("args-dd");
    inst.initialize();
    let derivative = |unknown: u32, known: u32, seed: *const f64| {
        let mut value = f64::NAN;
        // SAFETY: one value reference each, `seed` NULL or one value, `value` one value.
        let status = unsafe {
            fmu().fmi2GetDirectionalDerivative(inst.c, &unknown, 1, &known, 1, seed, &mut value)
        };
        (status, value)
    };
    let (acceleration, force) = (vr("slider.acceleration"), vr("slider.force"));
    let (status, value) = derivative(acceleration, force, &1.0);
    assert_eq!(status, OK);
    assert!(value.is_finite() && value != 0.0, "{value}");
    for (unknown, known, seed, expected) in [
        (
            vr("rod.length"),
            force,
            &1.0 as *const f64,
            "is not a Real output",
        ),
        (acceleration, vr("crank.speed"), &1.0, "is not a Real input"),
        (acceleration, force, std::ptr::null(), "must not be NULL"),
        (acceleration, force, &f64::NAN, "is not finite"),
    ] {
        let inst = Instance::new("args-dd-wrong");
        inst.initialize();
        let mut value = 0.0;
        // SAFETY: as above.
        let status = unsafe {
            fmu().fmi2GetDirectionalDerivative(inst.c, &unknown, 1, &known, 1, seed, &mut value)
        };
        assert_eq!(status, ERROR, "{expected}");
        assert!(
            inst.last_message().contains(expected),
            "{:?}",
            inst.messages()
        );
    }
}

/// Out-of-range and non-finite parameters and inputs: fmi2Error with a message naming the
/// variable, its value and the allowed range.
#[test]
fn out_of_range_values_name_variable_value_and_range() {
    let cases: [(&str, f64, &str); 4] = [
        (
            "rod.youngsModulus",
            -3.0,
            "rod.youngsModulus = -3 is outside the allowed range [1e6, 1e13] Pa",
        ),
        ("joint.clearance", f64::NAN, "joint.clearance = NaN"),
        (
            "joint.restitution",
            1.5,
            "joint.restitution = 1.5 is outside the allowed range [0.001, 1] 1",
        ),
        (
            "drive.torque",
            1e9,
            "drive.torque = 1e9 is outside the allowed range [-1e6, 1e6] N.m",
        ),
    ];
    for (name, value, expected) in cases {
        let inst = Instance::new(&format!("range-{name}"));
        assert_eq!(inst.set_real(vr(name), value), ERROR, "{name}");
        let m = inst.last_message();
        assert!(
            m.contains(expected) || (value.is_nan() && m.contains(name) && m.contains("NaN")),
            "{m}"
        );
    }
    let inst = Instance::new("range-int");
    assert_eq!(inst.set_integer(vr("joint.model"), 4), ERROR);
    assert!(
        inst.last_message()
            .contains("joint.model = 4 is outside the allowed range [1, 3]")
    );
    // Consistency errors surface at ExitInitializationMode, naming the parameter.
    let inst = Instance::new("range-modes");
    assert_eq!(inst.set_integer(vr("rod.nElements"), 2), OK);
    assert_eq!(inst.set_integer(vr("rod.nModes"), 5), OK);
    assert_eq!(inst.setup(0.0, None), OK);
    assert_eq!(inst.enter(), OK);
    assert_eq!(inst.exit(), ERROR);
    assert!(
        inst.last_message()
            .contains("rod.nModes = 5 is outside the allowed range [0, 4]"),
        "{:?}",
        inst.messages()
    );
}

/// `%` and `#` in texts reach the logger intact (format "%s"; '#' doubled per FMI 2.0.4 §2.1.5).
#[test]
fn percent_and_hash_arrive_intact() {
    let c = instantiate_raw(
        Some("pct"),
        fmi2Type_fmi2CoSimulation,
        Some("%s%d%n #r3#"),
        None,
        Some(&callbacks()),
    );
    assert!(c.is_null());
    let m = messages("pct").pop().unwrap_or_default();
    assert!(m.contains("got \"%s%d%n ##r3##\""), "{m}");
}

/// With loggingOn = false no OK message is sent, but errors always are; fmi2SetDebugLogging turns
/// messages on, and an unknown category is an error naming it.
#[test]
fn logging_switch_and_categories() {
    let c = instantiate_with_logging(
        Some("quiet"),
        fmi2Type_fmi2CoSimulation,
        Some(GUID),
        None,
        Some(&callbacks()),
        false,
    );
    assert!(!c.is_null());
    let inst = Instance::adopt(c, "quiet");
    inst.initialize();
    assert!(inst.messages().is_empty(), "{:?}", inst.messages());
    let category = std::ffi::CString::new("logEvents").unwrap();
    let categories = [category.as_ptr()];
    // SAFETY: one valid category name.
    let status = unsafe { fmu().fmi2SetDebugLogging(inst.c, 1, 1, categories.as_ptr()) };
    assert_eq!(status, OK);
    assert_eq!(inst.reset(), OK);
    inst.initialize();
    assert!(
        inst.messages().iter().any(|m| m.starts_with("model built")),
        "{:?}",
        inst.messages()
    );
    let unknown = std::ffi::CString::new("logNoSuchThing").unwrap();
    let categories = [unknown.as_ptr()];
    // SAFETY: one valid (unknown) category name.
    let status = unsafe { fmu().fmi2SetDebugLogging(inst.c, 1, 1, categories.as_ptr()) };
    assert_eq!(status, ERROR);
    assert!(
        inst.last_message()
            .contains("unknown log category \"logNoSuchThing\""),
        "{:?}",
        inst.messages()
    );

    let c = instantiate_with_logging(
        Some("quiet-error"),
        fmi2Type_fmi2CoSimulation,
        Some(GUID),
        None,
        Some(&callbacks()),
        false,
    );
    let inst = Instance::adopt(c, "quiet-error");
    assert_eq!(inst.do_step(0.0, 1e-4), ERROR);
    assert!(
        inst.last_message().contains("Illegal call sequence"),
        "errors are always logged"
    );
}

/// Reset restores every start value; outputs are valid right after initialisation.
#[test]
fn reset_restores_start_values() {
    let inst = Instance::new("reset");
    assert_eq!(inst.set_real(vr("rod.length"), 0.2), OK);
    assert_eq!(inst.set_integer(vr("rod.nModes"), 2), OK);
    inst.initialize();
    assert_eq!(inst.get_real(vr("rod.length")).1, 0.2);
    assert_eq!(inst.reset(), OK);
    assert_eq!(inst.setup(0.0, None), OK);
    assert_eq!(inst.enter(), OK);
    assert_eq!(inst.get_real(vr("rod.length")), (OK, 0.12));
    assert_eq!(inst.get_integer(vr("rod.nModes")), (OK, 4));
    let (status, x) = inst.get_real(vr("slider.position"));
    let fresh = Instance::new("fresh");
    fresh.initialize();
    assert_eq!((status, x), (OK, fresh.get_real(vr("slider.position")).1));
    // Slider at r_c + l, shifted by the equilibrated rod's quasi-static stretch (a few µm).
    assert!((x - (0.05 + 0.12)).abs() < 1e-5, "slider at {x}");
    let (_, k) = inst.get_real(vr("joint.contactStiffness"));
    assert!((k - 6.61e10).abs() < 0.01e10, "{k}");
}

/// Communication points: a mismatched t, h ≤ 0 and steps past stopTime are errors; a rounded t is
/// accepted.
#[test]
fn do_step_checks_the_communication_point() {
    for (name, t, h) in [
        ("cp-t", 1e-3, 1e-4),
        ("cp-h0", 0.0, 0.0),
        ("cp-hneg", 0.0, -1e-4),
        ("cp-stop", 0.0, 2e-3),
    ] {
        let inst = Instance::new(name);
        assert_eq!(inst.setup(0.0, Some(1e-3)), OK);
        assert_eq!(inst.enter(), OK);
        assert_eq!(inst.exit(), OK);
        assert_eq!(inst.do_step(t, h), ERROR, "{name}");
        assert!(
            inst.last_message().starts_with("fmi2DoStep"),
            "{:?}",
            inst.messages()
        );
    }
    let inst = Instance::new("cp-round");
    inst.initialize();
    assert_eq!(inst.do_step(0.0, 1e-4), OK);
    assert_eq!(inst.do_step(1e-4 * (1.0 + 1e-12), 1e-4), OK);
}

/// Get/Set FMU state is bit-exact; serialization round-trips into another instance; a corrupted
/// byte, a truncated buffer, a foreign magic, an older format version (named in the message) and
/// a too-small serialization buffer are rejected.
#[test]
fn fmu_state_is_bit_exact_and_checked() {
    let outputs = [
        vr("slider.position"),
        vr("joint.force"),
        vr("rod.deformationEnergy"),
    ];
    let a = Instance::new("state-a");
    assert_eq!(a.set_integer(vr("rod.nModes"), 2), OK);
    a.initialize();
    for i in 0..5 {
        assert_eq!(a.do_step(f64::from(i) * 1e-4, 1e-4), OK);
    }
    let state = a.get_state();
    let bytes = a.serialize(state);
    assert_eq!(a.do_step(5e-4, 3e-4), OK);
    let reference = a.get_reals(&outputs);
    assert_eq!(a.set_state(state), OK);
    assert_eq!(a.do_step(5e-4, 3e-4), OK);
    assert_eq!(a.get_reals(&outputs), reference);
    a.free_state(state);

    let b = Instance::new("state-b");
    let (status, restored) = b.deserialize(&bytes);
    assert_eq!(status, OK);
    assert_eq!(b.set_state(restored), OK);
    assert_eq!(b.do_step(5e-4, 3e-4), OK, "{:?}", b.messages());
    assert_eq!(b.get_reals(&outputs), reference);
    assert_eq!(b.get_integer(vr("rod.nModes")), (OK, 2));
    b.free_state(restored);

    for (name, bad) in [
        ("flip", {
            let mut v = bytes.clone();
            v[40] ^= 1;
            v
        }),
        ("truncate", bytes[..bytes.len() - 9].to_vec()),
        ("magic", {
            let mut v = bytes.clone();
            v[0] = b'X';
            v
        }),
        ("version", {
            // An older format, with a valid checksum.
            let mut v = bytes[..bytes.len() - 8].to_vec();
            v[4..8].copy_from_slice(&1u32.to_le_bytes());
            v.extend_from_slice(&fmi_export::instance::framing::state_checksum(&v).to_le_bytes());
            v
        }),
    ] {
        let c = Instance::new(&format!("state-{name}"));
        let (status, st) = c.deserialize(&bad);
        assert_eq!(status, ERROR, "{name}");
        assert!(st.is_null());
        assert!(c.last_message().contains("FMU state"), "{:?}", c.messages());
        if name == "version" {
            assert!(
                c.last_message().contains("format version 1, expected"),
                "{:?}",
                c.messages()
            );
        }
    }
    let d = Instance::new("state-small");
    let st = d.get_state();
    let mut buffer = [0u8; 8];
    // SAFETY: an 8-byte buffer, declared as such.
    let status =
        unsafe { fmu().fmi2SerializeFMUstate(d.c, st, buffer.as_mut_ptr().cast(), buffer.len()) };
    assert_eq!(status, ERROR);
    // The state was captured before the error; it is still freed properly.
    let mut st = st;
    // SAFETY: a state of this FMU, freed once.
    unsafe { fmu().fmi2FreeFMUstate(d.c, &mut st) };
}

/// Status getters: LastSuccessfulTime and Terminated answer; the rest say Discard.
#[test]
fn status_getters() {
    let inst = Instance::new("status");
    inst.initialize();
    assert_eq!(inst.do_step(0.0, 2e-4), OK);
    let mut t = 0.0;
    let mut b = 1;
    let mut s = 0;
    // SAFETY: writable outputs.
    unsafe {
        assert_eq!(
            fmu().fmi2GetRealStatus(inst.c, fmi2StatusKind_fmi2LastSuccessfulTime, &mut t),
            OK
        );
        assert_eq!(
            fmu().fmi2GetBooleanStatus(inst.c, fmi2StatusKind_fmi2Terminated, &mut b),
            OK
        );
        assert_eq!(
            fmu().fmi2GetStatus(inst.c, fmi2StatusKind_fmi2DoStepStatus, &mut s),
            fmi2Status_fmi2Discard
        );
    }
    assert_eq!((t, b), (2e-4, 0));
}
