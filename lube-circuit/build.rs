//! Renders `modelDescription.xml` and the GUID from the variable table, `src/variables.rs`.

#[allow(dead_code, unused_imports)] // build.rs uses only the data, not every helper of the table.
#[path = "src/variables.rs"]
mod variables;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    println!("cargo::rerun-if-changed=src/variables.rs");
    println!("cargo::rerun-if-changed=build.rs");
    fmi_export::build::build_script(&variables::DESCRIPTION, variables::FMI3)
}
