//! Bit-for-bit regression lock of the DefaultExperiment's results: every output of benchmark B
//! (4-mode rod, dry joint), benchmark A (rigid rod) and the lubricated joint at the 240
//! communication points of 1e-4 s, hashed per output (FNV-1a 64 of the values' bits), equal to
//! `tests/data/reference.txt`. A change that moves any bit of these runs fails here and must say
//! why; `UPDATE_REFERENCE=1 cargo test --test reference` rewrites the file. New outputs are not in
//! the file until it is rewritten, so additions leave the existing ones locked.

// Test code: a failed unwrap is a failed test, with its message.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::collections::BTreeMap;

use flexible_slider_crank::params::JointParameters;
use flexible_slider_crank::params::{JointModel, RodFormulation};
use flexible_slider_crank::{Outputs, Parameters, Simulation};

/// Every output of `o` by name, as bits.
fn values(o: &Outputs) -> Vec<(&'static str, u64)> {
    let reals = [
        ("time", o.time),
        ("crank_angle", o.crank_angle),
        ("crank_speed", o.crank_speed),
        ("crank_acceleration", o.crank_acceleration),
        ("crank_torque", o.crank_torque),
        ("slider_position", o.slider_position),
        ("slider_velocity", o.slider_velocity),
        ("slider_acceleration", o.slider_acceleration),
        ("joint_force_x", o.joint_force_x),
        ("joint_force_y", o.joint_force_y),
        ("joint_force", o.joint_force),
        ("eccentricity_x", o.eccentricity_x),
        ("eccentricity_y", o.eccentricity_y),
        ("eccentricity_rate_x", o.eccentricity_rate_x),
        ("eccentricity_rate_y", o.eccentricity_rate_y),
        ("penetration", o.penetration),
        ("midspan_deflection", o.midspan_deflection),
        ("deformation_energy", o.deformation_energy),
        ("kinetic_energy", o.kinetic_energy),
        ("drive_work", o.drive_work),
        ("dissipated_energy", o.dissipated_energy),
        ("contact_energy", o.contact_energy),
        ("gravity_energy", o.gravity_energy),
        ("slider_work", o.slider_work),
        ("material_damping", o.material_damping),
        ("constraint_drift", o.constraint_drift),
        ("joint_force_peak", o.joint_force_peak),
        ("slider_acceleration_peak", o.slider_acceleration_peak),
        ("deformation_energy_peak", o.deformation_energy_peak),
        ("crank_pin_force_x", o.crank_pin_force_x),
        ("crank_pin_force_y", o.crank_pin_force_y),
        ("crank_pin_force", o.crank_pin_force),
        ("crank_pin_force_peak", o.crank_pin_force_peak),
        ("main_bearing_force_x", o.main_bearing_force_x),
        ("main_bearing_force_y", o.main_bearing_force_y),
        ("main_bearing_force", o.main_bearing_force),
        ("main_bearing_force_peak", o.main_bearing_force_peak),
        ("guide_force", o.guide_force),
        ("guide_force_peak", o.guide_force_peak),
        ("rod_stress", o.rod_stress),
        ("rod_stress_peak", o.rod_stress_peak),
        ("rod_axial_force_crank_pin", o.rod_axial_force_crank_pin),
        ("rod_axial_force_slider_pin", o.rod_axial_force_slider_pin),
    ];
    let mut v: Vec<(&'static str, u64)> = reals.iter().map(|&(n, x)| (n, x.to_bits())).collect();
    v.push(("in_contact", u64::from(o.in_contact)));
    v.push(("contact_onsets", o.contact_onsets));
    v.push(("contact_onsets_total", o.contact_onsets_total));
    v.push(("warnings", o.warnings));
    v
}

/// FNV-1a 64 of each output's bits over the run's 240 communication points.
fn hashes(p: Parameters) -> BTreeMap<&'static str, u64> {
    let mut sim = Simulation::new(p).unwrap();
    let mut hashes = BTreeMap::new();
    for k in 1..=240 {
        sim.advance_to(f64::from(k) * 1e-4).unwrap();
        for (name, bits) in values(&sim.outputs().unwrap()) {
            let h = hashes.entry(name).or_insert(0xcbf2_9ce4_8422_2325u64);
            for byte in bits.to_le_bytes() {
                *h = (*h ^ u64::from(byte)).wrapping_mul(0x100_0000_01b3);
            }
        }
    }
    hashes
}

#[test]
fn the_default_experiments_results_are_locked() {
    let cases = [
        ("B", Parameters::default()),
        (
            "A",
            Parameters {
                rod_formulation: RodFormulation::Rigid,
                ..Parameters::default()
            },
        ),
        (
            "lubricated",
            Parameters {
                joint: JointParameters {
                    model: JointModel::Lubricated,
                    ..Parameters::default().joint
                },
                ..Parameters::default()
            },
        ),
    ];
    let mut current = String::new();
    for (case, p) in cases {
        for (name, hash) in hashes(p) {
            current.push_str(&format!("{case} {name} {hash:016x}\n"));
        }
    }
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/reference.txt");
    if std::env::var_os("UPDATE_REFERENCE").is_some() {
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(&path, &current).unwrap();
    }
    let locked = std::fs::read_to_string(&path).unwrap();
    let now: BTreeMap<&str, &str> = current
        .lines()
        .map(|l| l.rsplit_once(' ').unwrap())
        .collect();
    let mut differ = Vec::new();
    for line in locked.lines() {
        let (key, hash) = line.rsplit_once(' ').unwrap();
        if now.get(key) != Some(&hash) {
            differ.push(key.to_string());
        }
    }
    assert!(differ.is_empty(), "outputs that changed: {differ:?}");
}
