//! Regression lock: the bits of every output of the FMU's variable table (Real, Integer and
//! Boolean, read through the FMI getters, so no output can escape it) and of every element of its
//! FMI 3 arrays (the rod's sections, at their default count) at each of the 240 communication
//! points of 1e-4 s of these runs, hashed per output (FNV-1a 64), must equal
//! `tests/data/regression_lock.txt`:
//! - `B`: the DefaultExperiment (benchmark B: 4-mode rod, dry rod–slider joint);
//! - `A`: the rigid rod;
//! - `lubricated`: the 4-mode rod with the lubricated rod–slider joint (the short film);
//! - `worn`: lubricated crank pin and main bearing (0.05 mm, 9 mm long, 0.04 Pa s, the short
//!   film) with the dry rod–slider joint, every journal settled (the three joints' laws at once);
//! - `finite`: `worn` with the finite film in both bearings;
//! - `rough`: `finite` with rough surfaces in both bearings (the asperity contact);
//! - `torque`: the torque drive under a constant 2 N m with a constant slider force;
//! - `machine`: a user's machine, every feature of it at once: the compressor of
//!   `studies/compressor.toml` with its crank-angle load table, counterweighted crank, lubricated
//!   crank pin and main bearing (finite film) and a dry piston pin in line contact with friction,
//!   with an offset guide, the rod's eye masses and gravity besides;
//! - `warm`: `machine` with a heat balance in both bearings (the film temperature a state);
//! - `fed`: `warm` with the crank pin fed through a hole in the journal (the crankshaft's
//!   drilling) and the main bearing through a circumferential groove (two lands);
//! - `ramp`: `B` with the drive speed ramped through its first and second derivatives, set at
//!   every communication point as a master that provides input derivatives sets them.
//!
//! An output locked as zeros at every point says why ([`ZEROS`], checked both ways): an ideal
//! joint, a dry joint's film, no gravity, a journal that never touches or never lifts off.
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
use fmi_export::reference::Slave;

/// One locked run: its parameters (and inputs), set by name before initialization, a load table
/// (a path in the repository) and an input ramped through its derivatives.
struct Case {
    name: &'static str,
    settings: &'static [(&'static str, f64)],
    table: Option<&'static str>,
    ramp: Option<Ramp>,
}

/// An input u(t) = u₀ + u̇₀ t + ü t²/2, set at every communication point with its first and
/// second derivatives there.
#[derive(Clone, Copy)]
struct Ramp {
    input: &'static str,
    coefficients: [f64; 3],
}

impl Case {
    const fn plain(name: &'static str, settings: &'static [(&'static str, f64)]) -> Self {
        Self {
            name,
            settings,
            table: None,
            ramp: None,
        }
    }
}

const CASES: &[Case] = &[
    Case::plain("B", &[]),
    Case::plain("A", &[("rod.formulation", 1.0)]),
    Case::plain(
        "lubricated",
        &[("joint.model", 3.0), ("joint.filmModel", 1.0)],
    ),
    Case::plain("worn", &WORN),
    Case::plain("finite", &FINITE),
    Case::plain("rough", &ROUGH),
    Case::plain(
        "torque",
        &[
            ("drive.mode", 2.0),
            ("drive.torque", 2.0),
            ("slider.force", -50.0),
        ],
    ),
    Case {
        table: Some("studies/compressor_cycle.csv"),
        ..Case::plain("machine", &MACHINE)
    },
    Case {
        table: Some("studies/compressor_cycle.csv"),
        ..Case::plain("warm", &WARM)
    },
    Case {
        table: Some("studies/compressor_cycle.csv"),
        ..Case::plain("fed", &FED)
    },
    Case {
        ramp: Some(Ramp {
            input: "drive.speed",
            coefficients: [523.598_775_598_298_8, 4000.0, -1e5],
        }),
        ..Case::plain("ramp", &[])
    },
];

/// The compressor of `studies/compressor.toml` (crank 30 mm, rod 110 mm, 1500 rpm, lubricated crank
/// pin and main bearing with the finite film, a dry piston pin in line contact with friction, every
/// journal settled, a 2 %-damped rod), with an offset guide, the rod's eye masses and gravity besides
/// (its case adds the load table).
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

/// [`MACHINE`] with a heat balance in both bearings (the ISO VG 46 oil supplied at 40 °C, each
/// film settled at the start's steady temperature).
const WARM: [(&str, f64); 38] = {
    let mut warm = [("", 0.0); 38];
    let mut k = 0;
    while k < MACHINE.len() {
        warm[k] = MACHINE[k];
        k += 1;
    }
    warm[36] = ("crankPin.thermalModel", 2.0);
    warm[37] = ("mainBearing.thermalModel", 2.0);
    warm
};

/// [`WARM`] with a 4 mm hole in the crank pin's journal and a 4 mm circumferential groove in the
/// main bearing, the oil supplied at 2 bar.
const FED: [(&str, f64); 41] = {
    let mut fed = [("", 0.0); 41];
    let mut k = 0;
    while k < WARM.len() {
        fed[k] = WARM[k];
        k += 1;
    }
    fed[38] = ("crankPin.feed", 2.0);
    fed[39] = ("crankPin.feedLocation", 2.0);
    fed[40] = ("mainBearing.feed", 3.0);
    fed
};

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

/// [`FINITE`] with rough surfaces in both bearings: 2 µm combined roughness, the asperity contact
/// with its usual parameters and a boundary friction of 0.12.
const ROUGH: [(&str, f64); 17] = {
    let mut rough = [("", 0.0); 17];
    let mut k = 0;
    while k < FINITE.len() {
        rough[k] = FINITE[k];
        k += 1;
    }
    rough[13] = ("crankPin.roughness", 2e-6);
    rough[14] = ("crankPin.boundaryFriction", 0.12);
    rough[15] = ("mainBearing.roughness", 2e-6);
    rough[16] = ("mainBearing.boundaryFriction", 0.12);
    rough
};

/// FNV-1a 64 of each output's bits over the run's 240 communication points.
fn hashes(case: &Case) -> BTreeMap<&'static str, u64> {
    let mut slave = Slave::<SliderCrankFmu>::new();
    slave.setup(Some(1e-2), 0.0, Some(0.024)).unwrap();
    slave.enter_initialization();
    for &(name, value) in case.settings {
        slave.set(name, value).unwrap();
    }
    if let Some(table) = case.table {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(table);
        let path = path.to_str().unwrap();
        slave.set_string("slider.forceTable", path).unwrap();
    }
    let ramp = |t: f64| {
        case.ramp.map(
            |Ramp {
                 input,
                 coefficients: [u, rate, second],
             }| {
                let values = [u + t * (rate + 0.5 * t * second), rate + t * second, second];
                (input, values)
            },
        )
    };
    if let Some((input, [u, ..])) = ramp(0.0) {
        slave.set(input, u).unwrap();
    }
    slave.exit_initialization().unwrap();
    let names = Slave::<SliderCrankFmu>::outputs();
    let mut hashes: BTreeMap<&'static str, u64> = names
        .iter()
        .map(|&n| (n, 0xcbf2_9ce4_8422_2325u64))
        .collect();
    for k in 0..240 {
        let t = f64::from(k) * 1e-4;
        if let Some((input, [u, rate, second])) = ramp(t) {
            slave.set(input, u).unwrap();
            slave.set_derivatives(input, [rate, second]).unwrap();
        }
        slave.step(t, 1e-4).unwrap();
        let scalars = names.iter().zip(slave.output_values().unwrap());
        let arrays = slave.array_values().unwrap();
        let elements = arrays
            .iter()
            .flat_map(|(name, values)| values.iter().map(move |&v| (name, v)));
        for (name, value) in scalars.chain(elements) {
            let h = hashes.entry(name).or_insert(0xcbf2_9ce4_8422_2325u64);
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
    for case in CASES {
        for (name, hash) in hashes(case) {
            current.push_str(&format!("{} {name} {hash:016x}\n", case.name));
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

/// The outputs an ideal bearing reports as zeros.
const BEARING: &[&str] = &[
    "metalContactFractionCycle",
    "viscosityEffective",
    "contactOnsets",
    "contactOnsetsTotal",
    "eccentricityRatio",
    "eccentricityX",
    "eccentricityY",
    "energyDissipated",
    "filmPressurePeak",
    "filmPressurePeakCycle",
    "filmPressurePeakCycleAngle",
    "filmPressurePeakSinceStart",
    "filmThickness",
    "filmThicknessMin",
    "filmThicknessMinCycle",
    "filmThicknessMinCycleAngle",
    "filmThicknessMinSinceStart",
    "frictionPower",
    "frictionPowerMeanCycle",
    "frictionTorque",
    "inContact",
    "oilFlow",
    "oilFlowMeanCycle",
    "penetration",
];

const CRANK_JOINTS: &[&str] = &["crankPin.", "mainBearing."];
const ONSETS: &[&str] = &["contactOnsets", "contactOnsetsTotal"];
const TOUCH: &[&str] = &[
    "contactOnsets",
    "contactOnsetsTotal",
    "inContact",
    "metalContactFractionCycle",
    "penetration",
];
const JOINTS: &[&str] = &["joint.", "crankPin.", "mainBearing."];
const THERMAL: &[&str] = &["filmTemperature", "filmTemperatureMaxCycle", "heatFlow"];
const ASPERITY: &[&str] = &[
    "asperityForce",
    "asperityForcePeakCycle",
    "asperityFrictionPower",
    "asperityPressurePeak",
    "filmRatio",
];
const FILM: &[&str] = &[
    "viscosityEffective",
    "filmPressurePeak",
    "filmPressurePeakCycle",
    "filmPressurePeakSinceStart",
    "oilFlow",
    "oilFlowMeanCycle",
];

/// Why an output is zero at every communication point of a locked run: the runs, the outputs
/// (each prefix joined with each name) and the reason.
type Zero = (
    &'static [&'static str],
    &'static [&'static str],
    &'static [&'static str],
    &'static str,
);

const ZEROS: &[Zero] = &[
    (
        &["B", "ramp", "A", "lubricated", "torque"],
        CRANK_JOINTS,
        BEARING,
        "an ideal joint has no clearance, film or friction",
    ),
    (
        &[
            "B",
            "ramp",
            "A",
            "lubricated",
            "worn",
            "finite",
            "rough",
            "torque",
        ],
        &[""],
        &["energy.gravity"],
        "no gravity",
    ),
    (
        &[
            "B",
            "ramp",
            "A",
            "lubricated",
            "worn",
            "finite",
            "rough",
            "torque",
        ],
        &[""],
        &["energy.materialDamping"],
        "an undamped rod",
    ),
    (
        &["B", "ramp", "A", "lubricated", "worn", "finite", "rough"],
        &[""],
        &["energy.sliderWork", "slider.appliedForce"],
        "no slider force and no load table",
    ),
    (
        &[
            "B", "ramp", "A", "torque", "worn", "finite", "rough", "machine", "warm", "fed",
        ],
        &["joint."],
        FILM,
        "a dry rod-slider joint has no film",
    ),
    (
        &["B", "ramp", "A", "torque", "worn", "finite", "rough"],
        &["joint."],
        &["frictionPower", "frictionPowerMeanCycle"],
        "a dry joint without friction",
    ),
    (
        &["worn", "finite", "rough", "machine", "warm", "fed"],
        &["joint."],
        &["filmThicknessMinCycle", "filmThicknessMinSinceStart"],
        "the dry joint is settled on its wall",
    ),
    (
        &["machine", "warm", "fed"],
        &["joint."],
        &["filmThicknessMin"],
        "the dry piston pin stays on its wall",
    ),
    (
        &["A"],
        &[""],
        &[
            "rod.deformationEnergy",
            "rod.deformationEnergyPeak",
            "rod.midspanDeflection",
            "rod.section.deflection",
        ],
        "a rigid rod does not deform",
    ),
    (
        &["lubricated"],
        &["joint."],
        TOUCH,
        "the film keeps the journal off the wall",
    ),
    (
        &["lubricated"],
        &[""],
        &["energy.contact"],
        "the film keeps the journal off the wall",
    ),
    (
        &["worn"],
        CRANK_JOINTS,
        ONSETS,
        "the settled start is in dry contact and never lifts off",
    ),
    (
        &["worn", "finite", "rough"],
        CRANK_JOINTS,
        &["filmThicknessMinSinceStart"],
        "the journal touches its wall at the start",
    ),
    (
        &["finite", "rough"],
        CRANK_JOINTS,
        &["filmThicknessMinCycle"],
        "the journal touches its wall in each revolution",
    ),
    (
        &["machine", "warm", "fed"],
        &[""],
        &["cycle.number"],
        "no load cycle completes in 24 ms at 1500 rpm",
    ),
    (
        &["machine", "warm", "fed"],
        CRANK_JOINTS,
        TOUCH,
        "the oiled bearings never touch",
    ),
    (
        &["B", "ramp", "A", "worn", "torque", "machine", "warm", "fed"],
        &[""],
        &["solver.warnings"],
        "the run warns of nothing",
    ),
    (
        &[
            "B",
            "ramp",
            "A",
            "lubricated",
            "worn",
            "finite",
            "torque",
            "machine",
            "warm",
            "fed",
        ],
        JOINTS,
        ASPERITY,
        "smooth surfaces carry no asperity load",
    ),
    (
        &["rough"],
        &["joint."],
        ASPERITY,
        "a dry joint has no asperity contact",
    ),
    (
        &[
            "B",
            "ramp",
            "A",
            "lubricated",
            "worn",
            "finite",
            "rough",
            "torque",
            "machine",
        ],
        JOINTS,
        THERMAL,
        "an isoviscous film has no heat balance",
    ),
    (
        &["warm", "fed"],
        &["joint."],
        THERMAL,
        "a dry joint has no heat balance",
    ),
    (
        &[
            "B",
            "ramp",
            "A",
            "lubricated",
            "worn",
            "finite",
            "rough",
            "torque",
            "machine",
            "warm",
        ],
        JOINTS,
        &["feedFlow"],
        "an unfed film has no feed flow",
    ),
    (
        &["fed"],
        &["joint."],
        &["feedFlow"],
        "a dry joint has no feed",
    ),
];

/// Every output the lock holds as zeros (at all 240 points) is zero for a reason of [`ZEROS`], and
/// every output a reason names is zero in the runs it names: a lock of zeros says why.
#[test]
fn every_output_locked_as_zeros_says_why() {
    // The hash of 240 zeros, and of 240 arrays of zeros at the default number of sections.
    let sections = flexible_slider_crank::variables::FMI3.structural_parameters[0].start;
    let zero = |values: u64| {
        let mut zero = 0xcbf2_9ce4_8422_2325u64;
        for _ in 0..240 * 8 * values {
            zero = zero.wrapping_mul(0x100_0000_01b3);
        }
        format!("{zero:016x}")
    };
    let zero = [zero(1), zero(sections)];
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/regression_lock.txt");
    let locked = std::fs::read_to_string(path).unwrap();
    let zeros: std::collections::BTreeSet<String> = locked
        .lines()
        .filter_map(|l| l.rsplit_once(' '))
        .filter(|(_, hash)| zero.iter().any(|z| z == hash))
        .map(|(key, _)| key.to_string())
        .collect();
    let mut explained = std::collections::BTreeSet::new();
    for &(cases, prefixes, names, reason) in ZEROS {
        for case in cases {
            for prefix in prefixes {
                for name in names {
                    let key = format!("{case} {prefix}{name}");
                    assert!(zeros.contains(&key), "{key} is not zero ({reason})");
                    explained.insert(key);
                }
            }
        }
    }
    let unexplained: Vec<_> = zeros.difference(&explained).collect();
    assert!(
        unexplained.is_empty(),
        "locked as zeros without a reason: {unexplained:?}"
    );
}
