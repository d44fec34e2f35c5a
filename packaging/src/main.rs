//! Packaging: zips the shared libraries with `modelDescription.xml` and the documentation into an
//! FMU (FMI 2.0.4 §2.3).
//!
//! - `cargo run --release -p packaging`: builds the library for this machine and writes
//!   `target/fmu/FlexibleSliderCrank.fmu` with its one binary (`binaries/linux64` on Linux).
//! - `cargo run --release -p packaging -- --binaries DIR`: takes the libraries the release build
//!   (`packaging/release.sh`) made, `DIR/<platform>/FlexibleSliderCrank.<so|dll|dylib>` for
//!   every FMI platform folder present (linux64, win64, darwin64), and writes
//!   `target/fmu/release/FlexibleSliderCrank.fmu`.
//!
//! The archive is reproducible: its entries come in a fixed order with a fixed time stamp.

use std::error::Error;
use std::fmt::Write as _;
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use flexible_slider_crank::fmi::variables::{Causality, ENUMERATIONS, Kind, VARIABLES};
use flexible_slider_crank::fmi::{GUID, MODEL_DESCRIPTION, MODEL_IDENTIFIER};
use zip::write::SimpleFileOptions;

/// Builds the cdylib in release mode and returns the path of the `.so` cargo reports.
fn build_library(root: &Path) -> Result<PathBuf, Box<dyn Error>> {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let mut child = Command::new(cargo)
        .current_dir(root)
        .args([
            "build",
            "--release",
            "--lib",
            "-p",
            "flexible-slider-crank",
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

/// documentation/index.html: model, parameters, inputs and outputs with units (from the variable
/// table), validation status and the plots.
fn documentation(readme_validation: &str) -> String {
    let rows = |causality: Causality| {
        let mut t = String::from(
            "<table><tr><th>name</th><th>unit</th><th>start</th><th>range</th><th>description</th></tr>\n",
        );
        for v in VARIABLES.iter().filter(|v| v.causality == causality) {
            let (unit, start, range) = match v.kind {
                Kind::Real {
                    start,
                    min,
                    max,
                    unit,
                } => (
                    unit.to_string(),
                    start.map_or(String::new(), |s| format!("{s}")),
                    if min.is_finite() {
                        format!("[{min}, {max}]")
                    } else {
                        String::new()
                    },
                ),
                Kind::Integer { start, min, max } => (
                    String::new(),
                    start.map_or(String::new(), |s| s.to_string()),
                    format!("[{min}, {max}]"),
                ),
                Kind::Boolean => (String::new(), String::new(), "true/false".into()),
                Kind::Enumeration { start, type_index } => {
                    let items = ENUMERATIONS[type_index].items;
                    let names: Vec<String> = items
                        .iter()
                        .enumerate()
                        .map(|(i, (n, _))| format!("{}={n}", i + 1))
                        .collect();
                    (
                        String::new(),
                        items[(start - 1) as usize].0.to_string(),
                        names.join(", "),
                    )
                }
            };
            let _ = writeln!(
                t,
                "<tr><td><code>{}</code></td><td>{unit}</td><td>{start}</td><td>{range}</td><td>{}</td></tr>",
                v.name, v.description
            );
        }
        t + "</table>\n"
    };
    format!(
        r#"<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>FlexibleSliderCrank</title>
<style>body{{font-family:sans-serif;max-width:1100px;margin:auto}}table{{border-collapse:collapse}}td,th{{border:1px solid #ccc;padding:3px 6px;font-size:90%}}</style></head>
<body>
<h1>FlexibleSliderCrank — FMI 2.0 co-simulation FMU</h1>
<p>Slider-crank mechanism: rigid crank, connecting rod as planar ANCF beam (full or reduced by Craig–Bampton
component mode synthesis, or rigid), slider on a straight guide; the rod–slider joint is ideal, a dry clearance
joint (Lankarani–Nikravesh contact with Coulomb–Ambrósio friction) or a lubricated short journal bearing
(with dry contact near metal contact). Drive: prescribed crank speed or crank torque. The internal integrator is
an error-controlled Dormand–Prince 5(4) method that locates contact onsets. After Sun et al., Mech. Mach.
Theory 85 (2015) 106–115. GUID <code>{GUID}</code>.</p>
<p>Defaults: benchmark B (steel rod 0.12 m, 0.21 kg, 8 elements, 4 mode shapes, dry joint with 0.5 mm
clearance, 5000 rpm). DefaultExperiment: two crank revolutions (0.024 s), step 1e-4 s.</p>
<h2>Parameters</h2>{}
<h2>Calculated parameters</h2>{}
<h2>Inputs</h2>{}
<h2>Outputs</h2>{}
<h2>Example run</h2><p><img src="demo.png" alt="demo run" width="100%"></p>
<h2>Validation</h2>{readme_validation}
<p><img src="mode_study.png" alt="mode study" width="100%"></p>
</body></html>
"#,
        rows(Causality::Parameter),
        rows(Causality::CalculatedParameter),
        rows(Causality::Input),
        rows(Causality::Output)
    )
}

/// The README's validation section, as preformatted text for the HTML page.
fn validation_summary(root: &Path) -> String {
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap_or_default();
    let section = readme
        .split("\n## ")
        .find(|s| s.starts_with("Validation"))
        .unwrap_or("Validation: see README.md");
    let escaped = section
        .replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;");
    format!("<pre style=\"white-space:pre-wrap\">{escaped}</pre>")
}

/// FMI 2.0 platform folders and the file extension of their shared libraries.
const PLATFORMS: [(&str, &str); 3] = [("linux64", "so"), ("win64", "dll"), ("darwin64", "dylib")];

/// The binaries to package: (platform folder, path of the library).
fn binaries(
    root: &Path,
    from: Option<&Path>,
) -> Result<Vec<(&'static str, PathBuf)>, Box<dyn Error>> {
    let Some(dir) = from else {
        return Ok(vec![("linux64", build_library(root)?)]);
    };
    let found: Vec<_> = PLATFORMS
        .iter()
        .map(|(platform, ext)| {
            (
                *platform,
                dir.join(platform).join(format!("{MODEL_IDENTIFIER}.{ext}")),
            )
        })
        .filter(|(_, path)| path.exists())
        .collect();
    if found.is_empty() {
        return Err(format!(
            "no {MODEL_IDENTIFIER}.<so|dll|dylib> under {}/<platform>",
            dir.display()
        )
        .into());
    }
    Ok(found)
}

fn main() -> Result<(), Box<dyn Error>> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    let args: Vec<String> = std::env::args().skip(1).collect();
    let from = match args.as_slice() {
        [] => None,
        [flag, dir] if flag == "--binaries" => Some(PathBuf::from(dir)),
        _ => return Err("usage: packaging [--binaries DIR]".into()),
    };
    let binaries = binaries(&root, from.as_deref())?;
    let out_dir = match from {
        None => root.join("target").join("fmu"),
        Some(_) => root.join("target").join("fmu").join("release"),
    };
    std::fs::create_dir_all(&out_dir)?;
    let fmu = out_dir.join(format!("{MODEL_IDENTIFIER}.fmu"));
    let mut zip = zip::ZipWriter::new(std::fs::File::create(&fmu)?);
    let options = SimpleFileOptions::default().compression_method(zip::CompressionMethod::Deflated);
    zip.start_file("modelDescription.xml", options)?;
    zip.write_all(MODEL_DESCRIPTION.as_bytes())?;
    for (platform, library) in &binaries {
        let ext = library.extension().and_then(|e| e.to_str()).unwrap_or("so");
        zip.start_file(
            format!("binaries/{platform}/{MODEL_IDENTIFIER}.{ext}"),
            options,
        )?;
        zip.write_all(&std::fs::read(library)?)?;
    }
    zip.start_file("documentation/index.html", options)?;
    zip.write_all(documentation(&validation_summary(&root)).as_bytes())?;
    for image in ["demo.png", "mode_study.png"] {
        let path = root.join("modelDescription/documentation").join(image);
        if path.exists() {
            zip.start_file(format!("documentation/{image}"), options)?;
            zip.write_all(&std::fs::read(path)?)?;
        }
    }
    zip.finish()?;
    println!("{}", fmu.canonicalize()?.display());
    Ok(())
}
