//! String variables (slider.forceTable) through the C API: set and get, refused where the
//! standard refuses them, kept in the FMU state, and a relative table path found in the
//! resources directory that fmi2Instantiate's `file:` URI names.

use std::path::PathBuf;

use flexible_slider_crank::load_table::LoadTable;
use fmi_sys::fmi2::*;

use super::harness::{Instance, vr};

/// A resources directory whose name has a space (escaped as %20 in its URI) holding `table.csv`:
/// the directory and its URI.
fn resources(tag: &str) -> (PathBuf, String) {
    let dir = std::env::temp_dir().join(format!("fsc resources {tag} {}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("table.csv"),
        "angle,force\n0,-100\n90,-900\n180,-700\n",
    )
    .unwrap();
    let uri = format!("file://{}", dir.display()).replace(' ', "%20");
    (dir, uri)
}

/// A relative slider.forceTable is read from the resources directory; fmi2GetString returns the
/// value set; slider.appliedForce is the input plus the table at crank.angle.
#[test]
fn a_relative_table_is_found_in_the_resources() {
    let (dir, uri) = resources("found");
    let fmu = Instance::with_resources("string-found", Some(&uri));
    let table = vr("slider.forceTable");
    assert_eq!(fmu.setup(0.0, None), fmi2Status_fmi2OK);
    assert_eq!(fmu.enter(), fmi2Status_fmi2OK);
    assert_eq!(
        fmu.get_string(table),
        (fmi2Status_fmi2OK, Some(String::new()))
    );
    assert_eq!(fmu.set_string(table, "table.csv"), fmi2Status_fmi2OK);
    assert_eq!(fmu.set_real(vr("slider.force"), -50.0), fmi2Status_fmi2OK);
    assert_eq!(fmu.exit(), fmi2Status_fmi2OK, "{:?}", fmu.messages());
    assert_eq!(
        fmu.get_string(table),
        (fmi2Status_fmi2OK, Some("table.csv".to_string()))
    );
    assert_eq!(
        fmu.do_step(0.0, 1e-3),
        fmi2Status_fmi2OK,
        "{:?}",
        fmu.messages()
    );
    let [angle, applied] = fmu.get_reals(&[vr("crank.angle"), vr("slider.appliedForce")])[..]
    else {
        unreachable!()
    };
    let load = LoadTable::read(&dir.join("table.csv").to_string_lossy(), 360.0, None).unwrap();
    assert_eq!(applied, -50.0 + load.at(angle));
    assert!(applied < -150.0, "{applied}");
}

/// A String is refused where it is not a String variable, with a NULL value, and after
/// initialization (a fixed parameter), each with a message naming the variable; a missing file
/// fails fmi2ExitInitializationMode with a message naming the variable and the file. (Each
/// refusal leaves its instance in the error state: one instance per case.)
#[test]
fn string_values_are_checked() {
    let table = vr("slider.forceTable");
    let refused = |name: &str, call: &dyn Fn(&Instance) -> fmi2Status, expected: &str| {
        let fmu = Instance::new(name);
        assert_eq!(fmu.setup(0.0, None), fmi2Status_fmi2OK);
        assert_eq!(fmu.enter(), fmi2Status_fmi2OK);
        assert_eq!(call(&fmu), fmi2Status_fmi2Error, "{name}");
        let message = fmu.last_message();
        assert!(message.contains(expected), "{name}: {message}");
    };
    refused(
        "string-not-a-string",
        &|fmu| fmu.set_string(vr("crank.length"), "x"),
        "crank.length",
    );
    refused(
        "string-get-not-a-string",
        &|fmu| fmu.get_string(vr("crank.length")).0,
        "crank.length",
    );
    refused(
        "string-null",
        &|fmu| {
            let null: fmi2String = std::ptr::null();
            // SAFETY: one value reference and one (NULL) string pointer.
            unsafe { super::harness::fmu().fmi2SetString(fmu.c, &table, 1, &null) }
        },
        "slider.forceTable: value is NULL",
    );
    refused(
        "string-missing-file",
        &|fmu| {
            assert_eq!(
                fmu.set_string(table, "no such table.csv"),
                fmi2Status_fmi2OK
            );
            fmu.exit()
        },
        "slider.forceTable = \"no such table.csv\": no such file",
    );
    refused(
        "string-fixed",
        &|fmu| {
            assert_eq!(fmu.exit(), fmi2Status_fmi2OK);
            fmu.set_string(table, "table.csv")
        },
        "slider.forceTable",
    );
}

/// The table's name travels in the FMU state: an instance that restores a serialized state of
/// another (with the same resources) reads the same table and steps on bit-identically.
#[test]
fn the_table_is_kept_in_the_fmu_state() {
    let (_, uri) = resources("state");
    let a = Instance::with_resources("string-state-a", Some(&uri));
    assert_eq!(
        a.set_string(vr("slider.forceTable"), "table.csv"),
        fmi2Status_fmi2OK
    );
    a.initialize();
    assert_eq!(a.do_step(0.0, 5e-4), fmi2Status_fmi2OK);
    let state = a.get_state();
    let bytes = a.serialize(state);
    a.free_state(state);

    let b = Instance::with_resources("string-state-b", Some(&uri));
    b.initialize();
    let (status, restored) = b.deserialize(&bytes);
    assert_eq!(status, fmi2Status_fmi2OK);
    assert_eq!(
        b.set_state(restored),
        fmi2Status_fmi2OK,
        "{:?}",
        b.messages()
    );
    b.free_state(restored);
    assert_eq!(
        b.get_string(vr("slider.forceTable")).1.as_deref(),
        Some("table.csv")
    );
    let outputs = [
        vr("slider.appliedForce"),
        vr("joint.force"),
        vr("crank.angle"),
    ];
    for t in [5e-4, 1e-3] {
        assert_eq!(a.do_step(t, 5e-4), fmi2Status_fmi2OK);
        assert_eq!(b.do_step(t, 5e-4), fmi2Status_fmi2OK);
        let (x, y) = (a.get_reals(&outputs), b.get_reals(&outputs));
        assert_eq!(
            x.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
            y.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
        );
    }
}
