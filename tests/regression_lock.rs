//! Regression lock: the bits of every output of the FMU's variable table (Real, Integer and
//! Boolean, read through the FMI getters, so no output can escape it) at each of the 240
//! communication points of 1e-4 s of these runs, hashed per output (FNV-1a 64), must equal
//! `tests/data/regression_lock.txt`:
//! - `B`: the DefaultExperiment (benchmark B: 4-mode rod, dry rod–slider joint);
//! - `A`: the rigid rod;
//! - `lubricated`: the 4-mode rod with the lubricated rod–slider joint (the short film);
//! - `worn`: lubricated crank pin and main bearing (0.05 mm, 9 mm long, 0.04 Pa s, the short
//!   film) with the dry rod–slider joint, every journal settled (the three joints' laws at once);
//! - `finite`: `worn` with the finite film in both bearings;
//! - `torque`: the torque drive under a constant 2 N m with a constant slider force;
//! - `machine`: a user's machine, every feature of it at once: the compressor of
//!   `studies/compressor.toml` with its crank-angle load table, counterweighted crank, lubricated
//!   crank pin and main bearing (finite film) and a dry piston pin in line contact with friction,
//!   with an offset guide, the rod's eye masses and gravity besides. Its 17 outputs locked as
//!   zeros are zeros by the physics: the oiled bearings never touch (contact onsets, penetration,
//!   in contact), the dry piston pin has no film (film pressure, oil flow) and rests on its wall
//!   (film thickness 0), and the run warns of nothing.
//!
//! This is a lock, not a validation: it holds the code's own results, right or wrong, so that a
//! change that moves any bit says so. A change meant to move results re-records the file with
//! `UPDATE_LOCK=1 cargo test --test regression_lock` and says why in its commit. The test fails
//! when an output of the table has no hash in the file: a new output is locked as soon as it
//! exists.

// Test code: a failed unwrap is a failed test, with its message.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::collections::BTreeMap;

use flexible_slider_crank::fmi::instance::SliderCrankFmu;
use fmi2_slave::reference::Slave;

/// The parameters (and inputs) of each locked run, set by name before initialization.
const CASES: &[(&str, &[(&str, f64)])] = &[
    ("B", &[]),
    ("A", &[("rod.formulation", 1.0)]),
    (
        "lubricated",
        &[("joint.model", 3.0), ("joint.filmModel", 1.0)],
    ),
    ("worn", &WORN),
    ("finite", &FINITE),
    (
        "torque",
        &[
            ("drive.mode", 2.0),
            ("drive.torque", 2.0),
            ("slider.force", -50.0),
        ],
    ),
    ("machine", &MACHINE),
];

/// The compressor of `studies/compressor.toml` (crank 30 mm, rod 110 mm, 1500 rpm, lubricated crank
/// pin and main bearing with the finite film, a dry piston pin in line contact with friction, every
/// journal settled, a 2 %-damped rod), with an offset guide, the rod's eye masses and gravity besides
/// ([`hashes`] adds its load table).
const MACHINE: [(&str, f64); 36] = [
    ("crank.length", 0.03),
    ("crank.mass", 0.8),
    ("crank.inertia", 4e-4),
    ("crank.centreOfMassRatio", -0.3),
    ("rod.length", 0.11),
    ("rod.dampingRatio", 0.02),
    ("rod.crankEndMass", 0.04),
    ("rod.sliderEndMass", 0.02),
    ("slider.mass", 0.35),
    ("slider.offset", 0.004),
    ("gravity", 9.81),
    ("drive.speed", 157.079_632_679_489_66),
    ("crank.initialSpeed", 157.079_632_679_489_66),
    ("crankPin.model", 3.0),
    ("crankPin.journalRadius", 0.012),
    ("crankPin.bearingLength", 0.016),
    ("crankPin.clearance", 20e-6),
    ("crankPin.viscosity", 0.02),
    ("crankPin.initialState", 2.0),
    ("crankPin.filmModel", 2.0),
    ("mainBearing.model", 3.0),
    ("mainBearing.journalRadius", 0.015),
    ("mainBearing.bearingLength", 0.02),
    ("mainBearing.clearance", 25e-6),
    ("mainBearing.viscosity", 0.02),
    ("mainBearing.initialState", 2.0),
    ("mainBearing.filmModel", 2.0),
    ("joint.model", 2.0),
    ("joint.journalRadius", 0.006),
    ("joint.bearingLength", 0.018),
    ("joint.clearance", 10e-6),
    ("joint.contactGeometry", 2.0),
    ("joint.friction", 0.1),
    ("joint.initialState", 2.0),
    ("rod.formulation", 3.0),
    ("slider.force", 0.0),
];

/// Lubricated crank pin and main bearing with the short film, the dry rod–slider joint, every
/// journal settled.
const WORN: [(&str, f64); 13] = [
    ("joint.initialState", 2.0),
    ("crankPin.model", 3.0),
    ("crankPin.clearance", 5e-5),
    ("crankPin.bearingLength", 9e-3),
    ("crankPin.viscosity", 0.04),
    ("crankPin.initialState", 2.0),
    ("crankPin.filmModel", 1.0),
    ("mainBearing.model", 3.0),
    ("mainBearing.clearance", 5e-5),
    ("mainBearing.bearingLength", 9e-3),
    ("mainBearing.viscosity", 0.04),
    ("mainBearing.initialState", 2.0),
    ("mainBearing.filmModel", 1.0),
];

/// [`WORN`] with the finite film in both bearings.
const FINITE: [(&str, f64); 13] = {
    let mut finite = WORN;
    finite[6].1 = 2.0;
    finite[12].1 = 2.0;
    finite
};

/// FNV-1a 64 of each output's bits over the run's 240 communication points.
fn hashes(settings: &[(&str, f64)]) -> BTreeMap<&'static str, u64> {
    let mut slave = Slave::<SliderCrankFmu>::new();
    slave.setup(Some(1e-2), 0.0, Some(0.024)).unwrap();
    slave.enter_initialization();
    for &(name, value) in settings {
        slave.set(name, value).unwrap();
    }
    if std::ptr::eq(settings, MACHINE.as_slice()) {
        let table = concat!(env!("CARGO_MANIFEST_DIR"), "/studies/compressor_cycle.csv");
        slave.set_string("slider.forceTable", table).unwrap();
    }
    slave.exit_initialization().unwrap();
    let names = Slave::<SliderCrankFmu>::outputs();
    let mut hashes: BTreeMap<&'static str, u64> = names
        .iter()
        .map(|&n| (n, 0xcbf2_9ce4_8422_2325u64))
        .collect();
    for k in 0..240 {
        slave.step(f64::from(k) * 1e-4, 1e-4).unwrap();
        for (name, value) in names.iter().zip(slave.output_values().unwrap()) {
            let h = hashes.get_mut(name).unwrap();
            for byte in value.to_bits().to_le_bytes() {
                *h = (*h ^ u64::from(byte)).wrapping_mul(0x100_0000_01b3);
            }
        }
    }
    hashes
}

#[test]
fn every_output_of_the_locked_runs_is_bit_identical() {
    let mut current = String::new();
    for &(case, settings) in CASES {
        for (name, hash) in hashes(settings) {
            current.push_str(&format!("{case} {name} {hash:016x}\n"));
        }
    }
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/regression_lock.txt");
    if std::env::var_os("UPDATE_LOCK").is_some() {
        std::fs::write(&path, &current).unwrap();
    }
    let locked = std::fs::read_to_string(&path).unwrap();
    let locked: BTreeMap<&str, &str> = locked
        .lines()
        .map(|l| l.rsplit_once(' ').unwrap())
        .collect();
    let mut changed = Vec::new();
    let mut unlocked = Vec::new();
    for line in current.lines() {
        let (key, hash) = line.rsplit_once(' ').unwrap();
        match locked.get(key) {
            Some(&h) if h == hash => {}
            Some(_) => changed.push(key.to_string()),
            None => unlocked.push(key.to_string()),
        }
    }
    assert!(changed.is_empty(), "outputs that changed: {changed:?}");
    assert!(
        unlocked.is_empty(),
        "outputs with no hash in the lock (re-record it): {unlocked:?}"
    );
    assert_eq!(
        locked.len(),
        current.lines().count(),
        "the lock holds outputs the table no longer has"
    );
}
