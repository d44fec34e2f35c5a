//! Renders `modelDescription.xml` and the GUID from the one variable table, `src/variables/`,
//! after checking it (dense value references, unique structured names, ranges, FMI 2 rules).

#[allow(dead_code, unused_imports)] // build.rs uses only the data, not every helper or re-export.
#[path = "src/variables/mod.rs"]
mod variables;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    println!("cargo::rerun-if-changed=src/variables");
    println!("cargo::rerun-if-changed=build.rs");
    fmi_export::build::build_script(&variables::DESCRIPTION, variables::FMI3)
}
