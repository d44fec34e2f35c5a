//! Packaging: zips the shared libraries with `modelDescription.xml` and the documentation into an
//! FMU (FMI 2.0.4 §2.3), and the systems built from the workspace's FMUs.
//!
//! - `cargo run --release -p packaging`: builds the libraries for this machine and writes
//!   `target/fmu/FlexibleSliderCrank.fmu` and `target/fmu/DcMotor.fmu` with their one binary
//!   (`binaries/linux64` on Linux), the motor-crank system as an SSP, `target/fmu/MotorCrank.ssp`
//!   (`systems/motor-crank/SystemStructure.ssd` with both FMUs as resources), and as an OSP system
//!   structure, `target/fmu/motor-crank/` (`OspSystemStructure.xml` beside both FMUs). Each FMU
//!   carries the reference results of its DefaultExperiment (FMI-LS-REF), which are also written
//!   in the FMI cross-check layout under `target/fmu/compatibility/` ([`compatibility`]).
//! - `cargo run --release -p packaging -- --binaries DIR`: takes the libraries the release build
//!   (`packaging/release.sh`) made, `DIR/<platform>/<FlexibleSliderCrank|DcMotor>.<so|dll|dylib>`
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

mod compatibility;
mod documentation;

use std::error::Error;
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use documentation::Edition;
use flexible_slider_crank::fmi::{
    MODEL_DESCRIPTION, MODEL_DESCRIPTION_FMI3, MODEL_DESCRIPTION_FMI3_SCALAR, MODEL_IDENTIFIER,
    TERMINALS_AND_ICONS_FMI3,
};
use zip::write::SimpleFileOptions;

/// Builds the cdylib of `package` in release mode and returns the path of the `.so` cargo reports.
fn build_library(root: &Path, package: &str) -> Result<PathBuf, Box<dyn Error>> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let mut child = Command::new(cargo)
        .current_dir(root)
        .args([
            "build",
            "--release",
            "--lib",
            "-p",
            package,
            "--message-format=json",
        ])
        .stdout(Stdio::piped())
        .spawn()?;
    let stdout = child.stdout.take().ok_or("no stdout from cargo")?;
    let mut library = None;
    for line in BufReader::new(stdout).lines() {
        let message: serde_json::Value = serde_json::from_str(&line?)?;
        let is_cdylib = message["target"]["crate_types"]
            .as_array()
            .is_some_and(|types| types.iter().any(|t| t == "cdylib"));
        if message["reason"] == "compiler-artifact" && is_cdylib {
            for file in message["filenames"].as_array().into_iter().flatten() {
                if let Some(path) = file.as_str().filter(|p| p.ends_with(".so")) {
                    library = Some(PathBuf::from(path));
                }
            }
        }
    }
    if !child.wait()?.success() {
        return Err("cargo build --release failed".into());
    }
    library.ok_or_else(|| "cargo reported no .so for the cdylib".into())
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

/// The packaging time, for modelDescription's generationDateAndTime: `SOURCE_DATE_EPOCH` if set,
/// else the commit time of the checked-out revision, else now — so that packaging the same
/// commit twice gives the same bytes.
fn generation_time(root: &Path) -> String {
    let from_env = std::env::var("SOURCE_DATE_EPOCH").ok();
    let from_git = || {
        let out = std::process::Command::new("git")
            .current_dir(root)
            .args(["log", "-1", "--format=%ct"])
            .output()
            .ok()?;
        out.status
            .success()
            .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
    };
    let now = || {
        std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map(|d| d.as_secs())
            .unwrap_or(0)
    };
    let seconds = from_env
        .or_else(from_git)
        .and_then(|s| s.parse::<u64>().ok())
        .unwrap_or_else(now);
    utc_date_time(seconds)
}

/// Seconds since 1970-01-01T00:00:00Z as an xs:dateTime in UTC (days to civil date after
/// H. Hinnant, "chrono-Compatible Low-Level Date Algorithms").
fn utc_date_time(seconds: u64) -> String {
    let (days, rest) = (seconds / 86_400, seconds % 86_400);
    let z = days + 719_468;
    let era = z / 146_097;
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + u64::from(month <= 2);
    format!(
        "{year:04}-{month:02}-{day:02}T{:02}:{:02}:{:02}Z",
        rest / 3600,
        rest % 3600 / 60,
        rest % 60
    )
}

/// `xml` with generationDateAndTime = `time` after its generationTool attribute (the attribute
/// is stamped at packaging, so the XML the build script renders, and its GUID, do not change
/// with the date).
fn stamped(xml: &str, time: &str) -> Result<String, Box<dyn Error>> {
    let at = xml
        .find("generationTool=")
        .ok_or("modelDescription.xml has no generationTool attribute")?;
    Ok(format!(
        "{}generationDateAndTime=\"{time}\"\n  {}",
        &xml[..at],
        &xml[at..]
    ))
}

/// Writes the FMU `path`: modelDescription.xml, the binaries, documentation/index.html and the
/// images of `images` (files of `image_dir`) it shows, and the `extras` (name in the archive,
/// contents).
fn write_fmu(
    path: &Path,
    (identifier, xml): (&str, &str),
    binaries: &[(&str, PathBuf)],
    documentation: &str,
    images: &[PathBuf],
    extras: &[(String, Vec<u8>)],
) -> Result<(), Box<dyn Error>> {
    let mut zip = zip::ZipWriter::new(std::fs::File::create(path)?);
    let options = zip_options();
    zip.start_file("modelDescription.xml", options)?;
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    zip.write_all(stamped(xml, &generation_time(root))?.as_bytes())?;
    for (platform, library) in binaries {
        let ext = library.extension().and_then(|e| e.to_str()).unwrap_or("so");
        zip.start_file(format!("binaries/{platform}/{identifier}.{ext}"), options)?;
        zip.write_all(&std::fs::read(library)?)?;
    }
    zip.start_file("documentation/index.html", options)?;
    zip.write_all(documentation.as_bytes())?;
    for image in images {
        if !image.exists() {
            return Err(format!(
                "the documentation shows {}, which is missing",
                image.display()
            )
            .into());
        }
        let name = image
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or("image");
        zip.start_file(format!("documentation/{name}"), options)?;
        zip.write_all(&std::fs::read(image)?)?;
    }
    for (name, contents) in extras {
        zip.start_file(name.as_str(), options)?;
        zip.write_all(contents)?;
    }
    zip.finish()?;
    Ok(())
}

/// An FMI 3 FMU's extra entries: `entries` and its terminalsAndIcons.xml, if it has terminals.
fn with_terminals(mut entries: Vec<(String, Vec<u8>)>, terminals: &str) -> Vec<(String, Vec<u8>)> {
    if !terminals.is_empty() {
        entries.push((
            "terminalsAndIcons/terminalsAndIcons.xml".into(),
            terminals.as_bytes().to_vec(),
        ));
    }
    entries
}

/// Deflated entries with a fixed time stamp, so that the same inputs give the same bytes.
fn zip_options() -> SimpleFileOptions {
    SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated)
        .last_modified_time(zip::DateTime::default())
}

/// A zip of `entries` (name in the archive, file).
fn write_zip(path: &Path, entries: &[(String, PathBuf)]) -> Result<(), Box<dyn Error>> {
    let mut zip = zip::ZipWriter::new(std::fs::File::create(path)?);
    for (name, file) in entries {
        zip.start_file(name.as_str(), zip_options())?;
        zip.write_all(&std::fs::read(file)?)?;
    }
    zip.finish()?;
    Ok(())
}

/// The SSP archive `ssp` of the system structure in `system` with `fmus` as its resources.
fn write_ssp(system: &Path, ssp: &Path, fmus: [&PathBuf; 2]) -> Result<(), Box<dyn Error>> {
    let mut entries = vec![(
        "SystemStructure.ssd".to_string(),
        system.join("SystemStructure.ssd"),
    )];
    for fmu in fmus {
        let name = fmu
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or("model.fmu");
        entries.push((format!("resources/{name}"), fmu.clone()));
    }
    write_zip(ssp, &entries)
}

/// Writes both FMUs into `out_dir` with the libraries of FMI 2's platform folders among
/// `binaries` (the slider-crank's) and `motor_libraries`, their FMI 3.0 twins into `out_dir/fmi3/`
/// with every library (without arrays and input derivatives into `out_dir/fmi3/scalar/`), and the
/// motor-crank system made of the FMI 2 FMUs: `MotorCrank.ssp` and `motor-crank/` (OSP system
/// structure beside both FMUs), and of the FMI 3 FMUs every master loads, `fmi3/MotorCrank.ssp`.
/// Returns the paths written.
fn package(
    root: &Path,
    out_dir: &Path,
    binaries: &[(&'static str, PathBuf)],
    motor_libraries: &[(&'static str, PathBuf)],
) -> Result<Vec<PathBuf>, Box<dyn Error>> {
    std::fs::create_dir_all(out_dir)?;
    let crank_binaries = &fmi2_binaries(binaries);
    let motor_binaries = &fmi2_binaries(motor_libraries);
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
    let motor = (dc_motor::MODEL_IDENTIFIER, dc_motor::MODEL_DESCRIPTION);
    let motor_references = compatibility::motor()?;
    let motor_fmu = out_dir.join(format!("{}.fmu", motor.0));
    write_fmu(
        &motor_fmu,
        motor,
        motor_binaries,
        &documentation::motor(Edition::Fmi2),
        &[],
        &motor_references.fmu_entries(),
    )?;
    crank_references.write_cross_check(out_dir, &crank_fmu, crank_binaries)?;
    motor_references.write_cross_check(out_dir, &motor_fmu, motor_binaries)?;
    let fmi3 = out_dir.join("fmi3");
    std::fs::create_dir_all(&fmi3)?;
    std::fs::create_dir_all(fmi3.join("scalar"))?;
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
            &fmi3_binaries(binaries),
            &guide,
            &images,
            &with_terminals(crank_references.fmu_entries(), TERMINALS_AND_ICONS_FMI3),
        )?;
    }
    let motor_fmu3 = fmi3.join(format!("{}.fmu", motor.0));
    let motor_fmu3_scalar = fmi3.join("scalar").join(format!("{}.fmu", motor.0));
    for (fmu, description, edition) in [
        (&motor_fmu3, dc_motor::MODEL_DESCRIPTION_FMI3, Edition::Fmi3),
        (
            &motor_fmu3_scalar,
            dc_motor::MODEL_DESCRIPTION_FMI3_SCALAR,
            Edition::Fmi3Scalar,
        ),
    ] {
        write_fmu(
            fmu,
            (motor.0, description),
            &fmi3_binaries(motor_libraries),
            &documentation::motor(edition),
            &[],
            &with_terminals(
                motor_references.fmu_entries(),
                dc_motor::TERMINALS_AND_ICONS_FMI3,
            ),
        )?;
    }
    let system = root.join("systems/motor-crank");
    let ssp = out_dir.join("MotorCrank.ssp");
    let fmus = [&motor_fmu, &crank_fmu];
    write_ssp(&system, &ssp, fmus)?;
    // the same system of the FMI 3 FMUs every master loads
    let ssp3 = fmi3.join("MotorCrank.ssp");
    write_ssp(&system, &ssp3, [&motor_fmu3_scalar, &crank_fmu3_scalar])?;
    compatibility::system()?.write_system(out_dir, &ssp)?;
    let osp = out_dir.join("motor-crank");
    std::fs::create_dir_all(&osp)?;
    std::fs::copy(
        system.join("OspSystemStructure.xml"),
        osp.join("OspSystemStructure.xml"),
    )?;
    for fmu in fmus {
        if let Some(name) = fmu.file_name() {
            std::fs::copy(fmu, osp.join(name))?;
        }
    }
    Ok(vec![
        crank_fmu,
        motor_fmu,
        crank_fmu3,
        crank_fmu3_scalar,
        motor_fmu3,
        motor_fmu3_scalar,
        ssp3,
        ssp,
        osp,
        out_dir.join("compatibility"),
    ])
}

fn main() -> Result<(), Box<dyn Error>> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    let args: Vec<String> = std::env::args().skip(1).collect();
    let written = match args.as_slice() {
        [] => {
            let crank = build_library(&root, "flexible-slider-crank")?;
            let motor = build_library(&root, "dc-motor")?;
            package(
                &root,
                &root.join("target").join("fmu"),
                &[("linux64", crank)],
                &[("linux64", motor)],
            )?
        }
        [flag, dir] if flag == "--binaries" => {
            let dir = PathBuf::from(dir);
            package(
                &root,
                &root.join("target").join("fmu").join("release"),
                &release_binaries(&dir, MODEL_IDENTIFIER)?,
                &release_binaries(&dir, dc_motor::MODEL_IDENTIFIER)?,
            )?
        }
        _ => return Err("usage: packaging [--binaries DIR]".into()),
    };
    for path in written {
        println!("{}", path.canonicalize()?.display());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dates_are_utc_civil_dates() {
        // Against Python's datetime: the epoch, a leap day, the last day of February 2100 (no leap year), a time of day.
        assert_eq!(utc_date_time(0), "1970-01-01T00:00:00Z");
        assert_eq!(utc_date_time(951_782_400), "2000-02-29T00:00:00Z");
        assert_eq!(utc_date_time(4_107_542_399), "2100-02-28T23:59:59Z");
        assert_eq!(utc_date_time(1_795_575_696), "2026-11-25T03:01:36Z");
    }

    #[test]
    fn the_stamp_goes_before_generation_tool() {
        let xml = "<fmiModelDescription a=\"1\"\n  generationTool=\"t\">";
        let out = stamped(xml, "2026-11-25T00:00:00Z").unwrap();
        assert_eq!(
            out,
            "<fmiModelDescription a=\"1\"\n  generationDateAndTime=\"2026-11-25T00:00:00Z\"\n  generationTool=\"t\">"
        );
        assert!(stamped("<fmiModelDescription>", "x").is_err());
    }
}
