//! Packaging: zips the shared libraries with `modelDescription.xml` and the documentation into an
//! FMU (FMI 2.0.4 §2.3), and the systems built from the workspace's FMUs.
//!
//! - `cargo run --release -p packaging`: builds the libraries for this machine (without `--release`,
//!   in the development profile, with the workspace's test programs: [`build_libraries`]) and writes
//!   `target/fmu/FlexibleSliderCrank.fmu`, `target/fmu/DcMotor.fmu` and
//!   `target/fmu/LubricationCircuit.fmu` with their one binary (`binaries/linux64` on Linux), the
//!   motor-crank system as an SSP, `target/fmu/MotorCrank.ssp`
//!   (`systems/motor-crank/SystemStructure.ssd` with both FMUs as resources), and as an OSP system
//!   structure, `target/fmu/motor-crank/` (`OspSystemStructure.xml` beside both FMUs), and the
//!   lubrication-circuit system alike (`systems/lube-crank/`: `target/fmu/LubeCrank.ssp`,
//!   `target/fmu/lube-crank/`). Each FMU
//!   carries the reference results of its DefaultExperiment (FMI-LS-REF), which are also written
//!   in the FMI cross-check layout under `target/fmu/compatibility/` ([`compatibility`]).
//! - `cargo run -p packaging -- --binaries DIR`: takes the libraries the release build
//!   (`packaging/release.sh`) made,
//!   `DIR/<platform>/<FlexibleSliderCrank|DcMotor|LubricationCircuit>.<so|dll|dylib>`
//!   for every platform folder present (FMI 2's linux64, win64, darwin64; FMI 3's own aarch64-linux,
//!   x86_64-darwin, aarch64-darwin), and writes the same files under `target/fmu/release/`.
//!
//! Beside each FMI 2 FMU goes its FMI 3.0 twin under `fmi3/` (`target/fmu/fmi3/`,
//! `target/fmu/release/fmi3/`): the same libraries, which export both `fmi2*` and `fmi3*`, in FMI
//! 3's platform folders ([`fmi3_platform`]; the macOS universal binary's slices apart), with the FMI 3
//! modelDescription.xml. The FMI 3 FMUs carry the input derivatives (`der(…)` inputs) and the
//! slider-crank's the rod's section arrays; their twins without either, for masters with a scalar
//! FMI 3 import (OMSimulator), go to `fmi3/scalar/`.
//!
//! The archive is reproducible: its entries come in a fixed order with a fixed time stamp.

mod archive;
mod compatibility;
mod documentation;

use std::error::Error;
use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use archive::{with_terminals, write_fmu, write_ssp};
use documentation::Edition;
use flexible_slider_crank::fmi::{
    MODEL_DESCRIPTION, MODEL_DESCRIPTION_FMI3, MODEL_DESCRIPTION_FMI3_SCALAR, MODEL_IDENTIFIER,
    TERMINALS_AND_ICONS_FMI3,
};

/// The workspace's FMU packages and their library names.
const FMU_PACKAGES: [(&str, &str); 3] = [
    ("flexible-slider-crank", "flexible_slider_crank"),
    ("dc-motor", "dc_motor"),
    ("lube-circuit", "lube_circuit"),
];

/// Builds the three FMUs' cdylibs for this machine and returns the `.so` of each that cargo
/// reports, in the profile this program was built in: `cargo run --release -p packaging` packages
/// the release libraries (the FMUs to use), `cargo run -p packaging` the development ones (the same
/// results to the bit, about 1.3 times slower; the test command packages those).
///
/// The development libraries are built as the tests build them, with the whole workspace's test
/// programs: the tests' dev-dependencies turn on features of crates the libraries share (fmi-sys's,
/// libc's, log's …), and cargo builds a crate once per feature set. Built alone, the libraries and
/// every crate below them (faer, nalgebra) would be compiled a second time, and each build would
/// replace the other's `target/debug/lib*.so`.
fn build_libraries(root: &Path) -> Result<Libraries, Box<dyn Error>> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let mut args = vec!["build", "--lib", "--message-format=json"];
    if cfg!(debug_assertions) {
        args.extend(["--profile", "dev", "--workspace", "--tests"]);
    } else {
        args.extend(["--profile", "release"]);
        args.extend(
            FMU_PACKAGES
                .iter()
                .flat_map(|(package, _)| ["-p", *package]),
        );
    }
    let mut child = Command::new(cargo)
        .current_dir(root)
        .args(&args)
        .stdout(Stdio::piped())
        .spawn()?;
    let stdout = child.stdout.take().ok_or("no stdout from cargo")?;
    let mut built = Vec::new();
    for line in BufReader::new(stdout).lines() {
        let message: serde_json::Value = serde_json::from_str(&line?)?;
        let is_cdylib = message["target"]["crate_types"]
            .as_array()
            .is_some_and(|types| types.iter().any(|t| t == "cdylib"));
        if message["reason"] == "compiler-artifact" && is_cdylib {
            for file in message["filenames"].as_array().into_iter().flatten() {
                if let Some(path) = file.as_str().filter(|p| p.ends_with(".so")) {
                    let name = message["target"]["name"].as_str().unwrap_or_default();
                    built.push((name.to_owned(), PathBuf::from(path)));
                }
            }
        }
    }
    if !child.wait()?.success() {
        return Err(format!("cargo {} failed", args.join(" ")).into());
    }
    let library = |name: &str| {
        built
            .iter()
            .find(|(built_name, _)| built_name == name)
            .map(|(_, path)| vec![("linux64", path.clone())])
            .ok_or_else(|| format!("cargo reported no lib{name}.so"))
    };
    let [crank, motor, circuit] = FMU_PACKAGES.map(|(_, name)| library(name));
    Ok(Libraries {
        crank: crank?,
        motor: motor?,
        circuit: circuit?,
    })
}

/// The release build's platform folders and the file extension of their shared libraries: FMI
/// 2.0's (`darwin64` a universal binary), and those only FMI 3.0 can name: `aarch64-linux` and the
/// universal binary's two slices.
const PLATFORMS: [(&str, &str); 6] = [
    ("linux64", "so"),
    ("win64", "dll"),
    ("darwin64", "dylib"),
    ("aarch64-linux", "so"),
    ("x86_64-darwin", "dylib"),
    ("aarch64-darwin", "dylib"),
];

/// The FMI 3.0 platform tuple (FMI 3.0 §2.5.1.4) of a platform folder's library, if FMI 3 takes it
/// (not the universal binary: its slices have their own folders).
fn fmi3_platform(folder: &str) -> Option<&'static str> {
    match folder {
        "linux64" => Some("x86_64-linux"),
        "win64" => Some("x86_64-windows"),
        "x86_64-darwin" => Some("x86_64-darwin"),
        "aarch64-darwin" => Some("aarch64-darwin"),
        "aarch64-linux" => Some("aarch64-linux"),
        _ => None,
    }
}

/// The binaries an FMI 2.0 FMU can carry: those of FMI 2's platform folders.
fn fmi2_binaries(binaries: &[(&'static str, PathBuf)]) -> Vec<(&'static str, PathBuf)> {
    binaries
        .iter()
        .filter(|(platform, _)| ["linux64", "win64", "darwin64"].contains(platform))
        .cloned()
        .collect()
}

/// The binaries FMI 3 takes, in FMI 3's platform folders.
fn fmi3_binaries(binaries: &[(&str, PathBuf)]) -> Vec<(&'static str, PathBuf)> {
    binaries
        .iter()
        .filter_map(|(folder, path)| Some((fmi3_platform(folder)?, path.clone())))
        .collect()
}

/// The release binaries of `identifier` under `dir/<platform>/`: (platform folder, path).
fn release_binaries(
    dir: &Path,
    identifier: &str,
) -> Result<Vec<(&'static str, PathBuf)>, Box<dyn Error>> {
    let found: Vec<_> = PLATFORMS
        .iter()
        .map(|(platform, ext)| {
            (
                *platform,
                dir.join(platform).join(format!("{identifier}.{ext}")),
            )
        })
        .filter(|(_, path)| path.exists())
        .collect();
    if found.is_empty() {
        return Err(format!(
            "no {identifier}.<so|dll|dylib> under {}/<platform>",
            dir.display()
        )
        .into());
    }
    Ok(found)
}

/// An FMU of the workspace that goes beside the slider-crank into systems: its model
/// identifier, its model descriptions (FMI 2.0, FMI 3.0, FMI 3.0 without input derivatives), its
/// FMI 3 terminals, its documentation and the reference results of its DefaultExperiment.
struct Companion {
    identifier: &'static str,
    descriptions: [&'static str; 3],
    terminals: &'static str,
    documentation: fn(Edition) -> String,
    references: compatibility::References,
}

impl Companion {
    /// The DC motor.
    fn motor() -> Result<Self, Box<dyn Error>> {
        Ok(Self {
            identifier: dc_motor::MODEL_IDENTIFIER,
            descriptions: [
                dc_motor::MODEL_DESCRIPTION,
                dc_motor::MODEL_DESCRIPTION_FMI3,
                dc_motor::MODEL_DESCRIPTION_FMI3_SCALAR,
            ],
            terminals: dc_motor::TERMINALS_AND_ICONS_FMI3,
            documentation: documentation::motor,
            references: compatibility::motor()?,
        })
    }

    /// The lubrication circuit.
    fn circuit() -> Result<Self, Box<dyn Error>> {
        Ok(Self {
            identifier: lube_circuit::MODEL_IDENTIFIER,
            descriptions: [
                lube_circuit::MODEL_DESCRIPTION,
                lube_circuit::MODEL_DESCRIPTION_FMI3,
                lube_circuit::MODEL_DESCRIPTION_FMI3_SCALAR,
            ],
            terminals: "",
            documentation: documentation::circuit,
            references: compatibility::circuit()?,
        })
    }

    /// Writes its FMI 2.0 FMU into `out_dir` with the libraries of FMI 2's platform folders among
    /// `libraries` (and its cross-check files), its FMI 3.0 twins into `out_dir/fmi3/` and
    /// `out_dir/fmi3/scalar/` with every library. Returns the three FMUs' paths.
    fn write(
        &self,
        out_dir: &Path,
        libraries: &[(&'static str, PathBuf)],
    ) -> Result<[PathBuf; 3], Box<dyn Error>> {
        let file = format!("{}.fmu", self.identifier);
        let paths = [
            out_dir.join(&file),
            out_dir.join("fmi3").join(&file),
            out_dir.join("fmi3").join("scalar").join(&file),
        ];
        let fmi2 = &fmi2_binaries(libraries);
        write_fmu(
            &paths[0],
            (self.identifier, self.descriptions[0]),
            fmi2,
            &(self.documentation)(Edition::Fmi2),
            &[],
            &self.references.fmu_entries(),
        )?;
        self.references
            .write_cross_check(out_dir, &paths[0], fmi2)?;
        for (k, edition) in [(1, Edition::Fmi3), (2, Edition::Fmi3Scalar)] {
            write_fmu(
                &paths[k],
                (self.identifier, self.descriptions[k]),
                &fmi3_binaries(libraries),
                &(self.documentation)(edition),
                &[],
                &with_terminals(self.references.fmu_entries(), self.terminals),
            )?;
        }
        Ok(paths)
    }
}

/// The system `name` of `root/systems/<folder>/` made of the FMI 2 FMUs `fmus` (its SSP
/// `out_dir/<name>.ssp` and its OSP system structure `out_dir/<folder>/` beside them) and of the
/// FMI 3 FMUs every master loads, `fmus3` (`out_dir/fmi3/<name>.ssp`). Returns the SSP, the FMI 3
/// SSP and the OSP folder.
fn write_system(
    (root, out_dir): (&Path, &Path),
    (folder, name): (&str, &str),
    fmus: [&PathBuf; 2],
    fmus3: [&PathBuf; 2],
) -> Result<[PathBuf; 3], Box<dyn Error>> {
    let system = root.join("systems").join(folder);
    let ssp = out_dir.join(format!("{name}.ssp"));
    write_ssp(&system, &ssp, fmus)?;
    let ssp3 = out_dir.join("fmi3").join(format!("{name}.ssp"));
    write_ssp(&system, &ssp3, fmus3)?;
    let osp = out_dir.join(folder);
    std::fs::create_dir_all(&osp)?;
    std::fs::copy(
        system.join("OspSystemStructure.xml"),
        osp.join("OspSystemStructure.xml"),
    )?;
    for fmu in fmus {
        if let Some(file) = fmu.file_name() {
            std::fs::copy(fmu, osp.join(file))?;
        }
    }
    Ok([ssp, ssp3, osp])
}

/// The shared libraries to package, each as (platform folder, path).
struct Libraries {
    crank: Vec<(&'static str, PathBuf)>,
    motor: Vec<(&'static str, PathBuf)>,
    circuit: Vec<(&'static str, PathBuf)>,
}

/// Writes the three FMUs into `out_dir` with the libraries of FMI 2's platform folders, their FMI
/// 3.0 twins into `out_dir/fmi3/` with every library (without arrays and input derivatives into
/// `out_dir/fmi3/scalar/`), and the systems made of them: the motor-crank system
/// (`MotorCrank.ssp`, `motor-crank/` with its OSP system structure, `fmi3/MotorCrank.ssp`) and
/// the lubrication-circuit system (`LubeCrank.ssp`, `lube-crank/`, `fmi3/LubeCrank.ssp`).
/// Returns the paths written.
fn package(
    root: &Path,
    out_dir: &Path,
    libraries: &Libraries,
) -> Result<Vec<PathBuf>, Box<dyn Error>> {
    std::fs::create_dir_all(out_dir.join("fmi3").join("scalar"))?;
    let crank_binaries = &fmi2_binaries(&libraries.crank);
    let (guide, images) = documentation::slider_crank(root, Edition::Fmi2)?;
    let crank_references = compatibility::slider_crank()?;
    let crank_fmu = out_dir.join(format!("{MODEL_IDENTIFIER}.fmu"));
    write_fmu(
        &crank_fmu,
        (MODEL_IDENTIFIER, MODEL_DESCRIPTION),
        crank_binaries,
        &guide,
        &images,
        &crank_references.fmu_entries(),
    )?;
    crank_references.write_cross_check(out_dir, &crank_fmu, crank_binaries)?;
    let fmi3 = out_dir.join("fmi3");
    let crank_fmu3 = fmi3.join(format!("{MODEL_IDENTIFIER}.fmu"));
    let crank_fmu3_scalar = fmi3.join("scalar").join(format!("{MODEL_IDENTIFIER}.fmu"));
    for (fmu, description, edition) in [
        (&crank_fmu3, MODEL_DESCRIPTION_FMI3, Edition::Fmi3),
        (
            &crank_fmu3_scalar,
            MODEL_DESCRIPTION_FMI3_SCALAR,
            Edition::Fmi3Scalar,
        ),
    ] {
        let (guide, _) = documentation::slider_crank(root, edition)?;
        write_fmu(
            fmu,
            (MODEL_IDENTIFIER, description),
            &fmi3_binaries(&libraries.crank),
            &guide,
            &images,
            &with_terminals(crank_references.fmu_entries(), TERMINALS_AND_ICONS_FMI3),
        )?;
    }
    let [motor_fmu, motor_fmu3, motor_fmu3_scalar] =
        Companion::motor()?.write(out_dir, &libraries.motor)?;
    let [circuit_fmu, circuit_fmu3, circuit_fmu3_scalar] =
        Companion::circuit()?.write(out_dir, &libraries.circuit)?;
    let [ssp, motor_ssp3, motor_osp] = write_system(
        (root, out_dir),
        ("motor-crank", "MotorCrank"),
        [&motor_fmu, &crank_fmu],
        [&motor_fmu3_scalar, &crank_fmu3_scalar],
    )?;
    compatibility::system()?.write_system(out_dir, &ssp)?;
    let lube = write_system(
        (root, out_dir),
        ("lube-crank", "LubeCrank"),
        [&circuit_fmu, &crank_fmu],
        [&circuit_fmu3_scalar, &crank_fmu3_scalar],
    )?;
    let mut written = vec![
        crank_fmu,
        motor_fmu,
        circuit_fmu,
        crank_fmu3,
        crank_fmu3_scalar,
        motor_fmu3,
        motor_fmu3_scalar,
        circuit_fmu3,
        circuit_fmu3_scalar,
        motor_ssp3,
        ssp,
        motor_osp,
    ];
    written.extend(lube);
    written.push(out_dir.join("compatibility"));
    Ok(written)
}

fn main() -> Result<(), Box<dyn Error>> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    let args: Vec<String> = std::env::args().skip(1).collect();
    let written = match args.as_slice() {
        [] => package(
            &root,
            &root.join("target").join("fmu"),
            &build_libraries(&root)?,
        )?,
        [flag, dir] if flag == "--binaries" => {
            let dir = PathBuf::from(dir);
            let libraries = Libraries {
                crank: release_binaries(&dir, MODEL_IDENTIFIER)?,
                motor: release_binaries(&dir, dc_motor::MODEL_IDENTIFIER)?,
                circuit: release_binaries(&dir, lube_circuit::MODEL_IDENTIFIER)?,
            };
            package(
                &root,
                &root.join("target").join("fmu").join("release"),
                &libraries,
            )?
        }
        _ => return Err("usage: packaging [--binaries DIR]".into()),
    };
    for path in written {
        println!("{}", path.canonicalize()?.display());
    }
    Ok(())
}
