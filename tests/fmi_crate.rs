//! The packaged `.fmu` through a third master, the Rust `fmi` 0.8 crate (unzip, modelDescription,
//! instantiate, step): its outputs equal the library's `Simulation` on the same communication
//! grid bit for bit (fmpy and libcosimpy are compared the same way in packaging/python).

// Test code: a failed unwrap is a failed test, with its message.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::PathBuf;

use flexible_slider_crank::variables::VARIABLES;
use flexible_slider_crank::{Parameters, Simulation};
use fmi::fmi2::import::Fmi2Import;
use fmi::fmi2::instance::{CoSimulation, Common};
use fmi::traits::FmiImport;

#[path = "support/development_build.rs"]
mod development_build;

/// Packages the development FMUs and returns the slider-crank's.
fn packaged_fmu() -> PathBuf {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let status = std::process::Command::new(development_build::build().join("packaging"))
        .current_dir(&root)
        .stdout(std::process::Stdio::null())
        .status()
        .unwrap();
    assert!(status.success(), "packaging failed");
    root.join("target/fmu/FlexibleSliderCrank.fmu")
}

fn vr(name: &str) -> u32 {
    VARIABLES
        .iter()
        .find(|v| v.name == name)
        .map(|v| v.vr as u32)
        .unwrap()
}

#[test]
fn fmi_crate_runs_the_fmu_like_the_library() {
    let import: Fmi2Import = fmi::import::from_path(packaged_fmu()).unwrap();
    let md = import.model_description();
    assert_eq!(md.fmi_version, "2.0");
    assert_eq!(md.guid, flexible_slider_crank::fmi::GUID);
    let mut inst = import.instantiate_cs("fmi-crate", false, true).unwrap();
    inst.setup_experiment(None, 0.0, Some(0.003)).unwrap();
    inst.enter_initialization_mode().unwrap();
    inst.exit_initialization_mode().unwrap();

    let names = [
        "slider.position",
        "slider.acceleration",
        "joint.force",
        "crank.torque",
    ];
    let vrs: Vec<u32> = names.iter().map(|n| vr(n)).collect();
    let mut sim = Simulation::new(Parameters::default()).unwrap();
    let dt = 1e-4;
    let mut t = 0.0;
    for n in 1..=30 {
        let next = n as f64 * dt;
        inst.do_step(t, next - t, true).unwrap();
        sim.advance_to(t + (next - t)).unwrap();
        t = next;
        let mut values = vec![0.0; vrs.len()];
        inst.get_real(&vrs, &mut values).unwrap();
        let o = sim.outputs().unwrap();
        let library = [
            o.slider_position,
            o.slider_acceleration,
            o.joint_force,
            o.crank_torque,
        ];
        assert_eq!(values, library, "t = {t}");
    }
    assert_eq!(inst.last_successful_time().unwrap(), 0.003);
    assert!(!inst.terminated().unwrap());
    inst.terminate().unwrap();
}
