//! The work of a model's build script: both versions' modelDescription.xml from its table.

use crate::description::Description;
use crate::fmi2;
use crate::fmi3;
use crate::table::ValueReference;

/// The work of a model's build script: renders the FMI 2 modelDescription.xml and its GUID into
/// `OUT_DIR` (`modelDescription.xml`, `guid.txt`, for `include_str!`), the FMI 3 one with the
/// model's FMI 3 additions `fmi3` and its instantiation token (`fmi3/modelDescription.xml`,
/// `fmi3/token.txt`, and `fmi3/terminalsAndIcons.xml`, empty for a model without terminals), and
/// the FMI 3 one without arrays for masters that read every variable as a scalar
/// (`fmi3/scalar/modelDescription.xml`, `fmi3/scalar/token.txt`: the same as the first for a
/// model without arrays); and, for a macOS target, gives the dylib the FMU's name as its install
/// name (not the build path: reproducible builds).
pub fn build_script<V: ValueReference>(
    d: &Description<V>,
    fmi3: fmi3::interface::Fmi3Interface,
) -> Result<(), Box<dyn std::error::Error>> {
    let (xml, guid) =
        fmi2::description::model_description(d).map_err(|e| format!("variable table: {e}"))?;
    let (xml3, token) = fmi3::description::model_description(d, fmi3)?;
    let (scalar, scalar_token) = fmi3::description::model_description(d, fmi3.scalar())?;
    let terminals = fmi3::description::terminals_and_icons(d, fmi3)?.unwrap_or_default();
    let out = std::path::PathBuf::from(std::env::var("OUT_DIR")?);
    std::fs::write(out.join("modelDescription.xml"), xml)?;
    std::fs::write(out.join("guid.txt"), guid)?;
    std::fs::create_dir_all(out.join("fmi3/scalar"))?;
    std::fs::write(out.join("fmi3/modelDescription.xml"), xml3)?;
    std::fs::write(out.join("fmi3/token.txt"), token)?;
    std::fs::write(out.join("fmi3/scalar/modelDescription.xml"), scalar)?;
    std::fs::write(out.join("fmi3/scalar/token.txt"), scalar_token)?;
    std::fs::write(out.join("fmi3/terminalsAndIcons.xml"), terminals)?;
    if std::env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("macos") {
        println!(
            "cargo::rustc-cdylib-link-arg=-Wl,-install_name,@rpath/{}.dylib",
            d.model_identifier
        );
    }
    Ok(())
}
