//! The archives: an FMU (FMI 2.0.4 §2.3, FMI 3.0 §2.5) with its model description stamped with
//! the packaging time, and an SSP. Reproducible: entries in a fixed order with a fixed time
//! stamp, the generation time the commit's.

use std::error::Error;
use std::io::Write;
use std::path::{Path, PathBuf};

use zip::write::SimpleFileOptions;

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
pub(crate) fn write_fmu(
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
pub(crate) fn with_terminals(
    mut entries: Vec<(String, Vec<u8>)>,
    terminals: &str,
) -> Vec<(String, Vec<u8>)> {
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
pub(crate) fn write_ssp(
    system: &Path,
    ssp: &Path,
    fmus: [&PathBuf; 2],
) -> Result<(), Box<dyn Error>> {
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
