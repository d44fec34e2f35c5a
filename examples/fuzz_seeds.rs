//! Seeds for the `fmu_state` fuzz target: FMU states of the current format, serialized by the
//! FMU's own `fmi2*` functions (called in-process) from a few configurations — every rod, each
//! joint worn or lubricated, the torque drive — before initialization, after it and after a few
//! steps, each written without its closing checksum (the target appends it) to the directory
//! given.
//!
//! `cargo run --release --example fuzz_seeds -- DIR` (run by `packaging/fuzz.sh --update-corpus`,
//! which merges the seeds into the kept corpus).

// An example: a failed call ends it with its message; calling a C API needs unsafe.
#![allow(clippy::unwrap_used, clippy::expect_used, unsafe_code)]

use std::ffi::CString;

use flexible_slider_crank::fmi::GUID;
use flexible_slider_crank::fmi::fmi2_exports as fmi;
use flexible_slider_crank::variables::VARIABLES;
use fmi_sys::fmi2::*;

/// Integer settings (name, value) of each configuration.
const CONFIGURATIONS: [&[(&str, i32)]; 7] = [
    &[],
    &[("rod.formulation", 1)],
    &[("rod.formulation", 2), ("rod.nElements", 2)],
    &[("joint.model", 3)],
    &[("crankPin.model", 2), ("mainBearing.model", 3)],
    &[("drive.mode", 2), ("solver.method", 3)],
    &[("joint.contactGeometry", 2), ("crankPin.model", 3)],
];

fn vr(name: &str) -> u32 {
    VARIABLES.iter().find(|v| v.name == name).unwrap().vr as u32
}

fn ok(status: fmi2Status, what: &str) {
    assert_eq!(status, fmi2Status_fmi2OK, "{what}");
}

/// The serialized current state of instance `c`, without its checksum.
fn state(c: fmi2Component) -> Vec<u8> {
    let mut s: fmi2FMUstate = std::ptr::null_mut();
    let mut size = 0;
    // SAFETY: a live instance, a fresh state pointer and a buffer of the size the FMU asks for;
    // the state is freed once.
    unsafe {
        ok(fmi::fmi2GetFMUstate(c, &mut s), "fmi2GetFMUstate");
        ok(fmi::fmi2SerializedFMUstateSize(c, s, &mut size), "size");
        let mut bytes = vec![0u8; size];
        ok(
            fmi::fmi2SerializeFMUstate(c, s, bytes.as_mut_ptr().cast(), size),
            "fmi2SerializeFMUstate",
        );
        ok(fmi::fmi2FreeFMUstate(c, &mut s), "fmi2FreeFMUstate");
        bytes.truncate(size - std::mem::size_of::<u64>());
        bytes
    }
}

fn main() {
    let dir = std::path::PathBuf::from(std::env::args().nth(1).expect("usage: fuzz_seeds DIR"));
    std::fs::create_dir_all(&dir).unwrap();
    let callbacks = fmi2CallbackFunctions {
        logger: Some(fmi_sys::fmi2::logger::callback_logger_handler),
        allocateMemory: None,
        freeMemory: None,
        stepFinished: None,
        componentEnvironment: std::ptr::null_mut(),
    };
    let (name, guid) = (CString::new("seeds").unwrap(), CString::new(GUID).unwrap());
    let mut written = 0;
    for (k, settings) in CONFIGURATIONS.iter().enumerate() {
        // SAFETY: live strings and callbacks for each call; the instance is freed once, last.
        unsafe {
            let c = fmi::fmi2Instantiate(
                name.as_ptr(),
                fmi2Type_fmi2CoSimulation,
                guid.as_ptr(),
                std::ptr::null(),
                &callbacks,
                0,
                0,
            );
            assert!(!c.is_null(), "fmi2Instantiate");
            for &(variable, value) in *settings {
                ok(fmi::fmi2SetInteger(c, &vr(variable), 1, &value), variable);
            }
            let mut states = vec![state(c)];
            ok(fmi::fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), "setup");
            ok(fmi::fmi2EnterInitializationMode(c), "enter");
            ok(fmi::fmi2ExitInitializationMode(c), "exit");
            states.push(state(c));
            for n in 0..5 {
                ok(
                    fmi::fmi2DoStep(c, f64::from(n) * 1e-4, 1e-4, 1),
                    "fmi2DoStep",
                );
            }
            states.push(state(c));
            fmi::fmi2FreeInstance(c);
            for (j, bytes) in states.iter().enumerate() {
                std::fs::write(dir.join(format!("seed-{k}-{j}")), bytes).unwrap();
                written += 1;
            }
        }
    }
    println!("{written} FMU states written to {}", dir.display());
}
