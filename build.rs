//! Renders `modelDescription.xml` and the GUID from the one variable table, `src/fmi/variables.rs`,
//! after checking it (dense value references, unique structured names, ranges, FMI 2 rules).

#[allow(dead_code)] // build.rs uses only the data, not every helper of the table.
#[path = "src/fmi/variables.rs"]
mod variables;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    println!("cargo::rerun-if-changed=src/fmi/variables.rs");
    println!("cargo::rerun-if-changed=build.rs");
    // A macOS dylib records its own name; the FMU's, not the build path (reproducible builds).
    if std::env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("macos") {
        println!("cargo::rustc-cdylib-link-arg=-Wl,-install_name,@rpath/FlexibleSliderCrank.dylib");
    }
    let (xml, guid) = fmi2_slave::description::model_description(&variables::DESCRIPTION)
        .map_err(|e| format!("variable table: {e}"))?;
    let out = std::path::PathBuf::from(std::env::var("OUT_DIR")?);
    std::fs::write(out.join("modelDescription.xml"), xml)?;
    std::fs::write(out.join("guid.txt"), guid)?;
    Ok(())
}
