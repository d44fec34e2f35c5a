//! Renders `modelDescription.xml` and the GUID from the one variable table, `src/fmi/variables.rs`,
//! after checking it (dense value references, unique structured names, ranges, FMI 2 rules).

use std::fmt::Write as _;

#[allow(dead_code)] // build.rs uses only the data, not every helper of the table.
#[path = "src/fmi/variables.rs"]
mod variables;

use variables::{
    Causality, DEFAULT_EXPERIMENT, ENUMERATIONS, FEEDTHROUGH, Kind, LOG_CATEGORIES, UNITS,
    VARIABLES, Variability,
};

const GUID_PLACEHOLDER: &str = "@GUID@";

fn fail(message: String) -> ! {
    panic!("variable table: {message}");
}

fn structured(name: &str) -> bool {
    name.split('.').all(|part| {
        let mut chars = part.chars();
        chars
            .next()
            .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
            && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
    })
}

fn check() {
    for (output, inputs) in FEEDTHROUGH {
        let causality = |vr: &variables::Vr| VARIABLES[*vr as usize].causality;
        if causality(output) != Causality::Output
            || inputs.iter().any(|u| causality(u) != Causality::Input)
        {
            fail(format!(
                "FEEDTHROUGH: {output:?} must be an output and {inputs:?} inputs"
            ));
        }
    }
    for (i, v) in VARIABLES.iter().enumerate() {
        if v.vr as usize != i {
            fail(format!(
                "{} has value reference {} at position {i}",
                v.name, v.vr as usize
            ));
        }
        if !structured(v.name) {
            fail(format!("{} is not a structured name", v.name));
        }
        if VARIABLES.iter().filter(|w| w.name == v.name).count() != 1 {
            fail(format!("{} is not unique", v.name));
        }
        match v.kind {
            Kind::Real {
                start,
                min,
                max,
                unit,
            } => {
                if !UNITS.iter().any(|(u, _)| *u == unit) {
                    fail(format!("{}: unit {unit} is not defined", v.name));
                }
                if let Some(s) = start {
                    if !(min <= s && s <= max) {
                        fail(format!("{}: start {s} outside [{min}, {max}]", v.name));
                    }
                }
            }
            Kind::Integer {
                start: Some(s),
                min,
                max,
            } if !(min <= s && s <= max) => {
                fail(format!("{}: start {s} outside [{min}, {max}]", v.name));
            }
            Kind::Enumeration { start, type_index } => {
                let n = ENUMERATIONS[type_index].items.len() as i32;
                if !(1..=n).contains(&start) {
                    fail(format!("{}: start {start} outside [1, {n}]", v.name));
                }
            }
            _ => {}
        }
        let has_start = match v.kind {
            Kind::Real { start, .. } => start.is_some(),
            Kind::Integer { start, .. } => start.is_some(),
            Kind::Boolean => false,
            Kind::Enumeration { .. } => true,
        };
        let needs_start = matches!(v.causality, Causality::Parameter | Causality::Input);
        if has_start != needs_start {
            fail(format!(
                "{}: start value {} for {:?}",
                v.name,
                if has_start { "given" } else { "missing" },
                v.causality
            ));
        }
    }
}

fn real(x: f64) -> String {
    format!("{x:?}")
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn render() -> String {
    let mut x = String::new();
    let _ = writeln!(x, r#"<?xml version="1.0" encoding="UTF-8"?>"#);
    let _ = writeln!(
        x,
        r#"<fmiModelDescription fmiVersion="2.0" modelName="FlexibleSliderCrank" guid="{GUID_PLACEHOLDER}"
  description="Flexible slider-crank mechanism with a clearance joint: planar ANCF connecting rod reduced by Craig-Bampton component mode synthesis (Sun et al., Mech. Mach. Theory 85, 2015)"
  version="{}" generationTool="flexible-slider-crank build.rs" variableNamingConvention="structured" numberOfEventIndicators="0">"#,
        env!("CARGO_PKG_VERSION")
    );
    let _ = writeln!(
        x,
        r#"  <CoSimulation modelIdentifier="FlexibleSliderCrank" needsExecutionTool="false" canHandleVariableCommunicationStepSize="true" canInterpolateInputs="true" maxOutputDerivativeOrder="2" canRunAsynchronuously="false" canBeInstantiatedOnlyOncePerProcess="false" canNotUseMemoryManagementFunctions="true" canGetAndSetFMUstate="true" canSerializeFMUstate="true" providesDirectionalDerivative="false"/>"#
    );
    x.push_str("  <UnitDefinitions>\n");
    for (name, base) in UNITS {
        match base {
            Some(e) => {
                let attrs: String = ["kg", "m", "s", "rad"]
                    .iter()
                    .zip(e)
                    .filter(|(_, v)| **v != 0)
                    .map(|(k, v)| format!(r#" {k}="{v}""#))
                    .collect();
                let _ = writeln!(x, r#"    <Unit name="{name}"><BaseUnit{attrs}/></Unit>"#);
            }
            None => {
                let _ = writeln!(x, r#"    <Unit name="{name}"/>"#);
            }
        }
    }
    x.push_str("  </UnitDefinitions>\n  <TypeDefinitions>\n");
    // Switches are Integer types, not FMI Enumerations, so that masters without Enumeration
    // support (libcosim drops such variables) can set them; the items are named in the
    // descriptions of the type (with each item's meaning) and of the variable.
    for e in ENUMERATIONS {
        let items: Vec<String> = e
            .items
            .iter()
            .enumerate()
            .map(|(i, (item, description))| format!("{} = {item}: {description}", i + 1))
            .collect();
        let _ = writeln!(
            x,
            r#"    <SimpleType name="{}" description="{}">
      <Integer min="1" max="{}"/>
    </SimpleType>"#,
            e.name,
            escape(&items.join("; ")),
            e.items.len()
        );
    }
    x.push_str("  </TypeDefinitions>\n  <LogCategories>\n");
    for (name, description) in LOG_CATEGORIES {
        let _ = writeln!(
            x,
            r#"    <Category name="{name}" description="{description}"/>"#
        );
    }
    let (start, stop, tolerance, step) = DEFAULT_EXPERIMENT;
    let _ = writeln!(
        x,
        r#"  </LogCategories>
  <DefaultExperiment startTime="{}" stopTime="{}" tolerance="{}" stepSize="{}"/>
  <ModelVariables>"#,
        real(start),
        real(stop),
        real(tolerance),
        real(step)
    );
    for (i, v) in VARIABLES.iter().enumerate() {
        let causality = match v.causality {
            Causality::Parameter => "parameter",
            Causality::CalculatedParameter => "calculatedParameter",
            Causality::Input => "input",
            Causality::Output => "output",
        };
        let variability = match v.variability {
            Variability::Fixed => "fixed",
            Variability::Discrete => "discrete",
            Variability::Continuous => "continuous",
        };
        let initial = match v.causality {
            Causality::Parameter => r#" initial="exact""#,
            Causality::CalculatedParameter | Causality::Output => r#" initial="calculated""#,
            _ => "",
        };
        let description = match v.kind {
            Kind::Enumeration { type_index, .. } => format!(
                "{} ({})",
                v.description,
                variables::item_list(&ENUMERATIONS[type_index])
            ),
            _ => v.description.to_string(),
        };
        let _ = writeln!(
            x,
            r#"    <!-- {} --><ScalarVariable name="{}" valueReference="{}" description="{}" causality="{causality}" variability="{variability}"{initial}>"#,
            i + 1,
            v.name,
            v.vr as u32,
            escape(&description)
        );
        let element = match v.kind {
            Kind::Real {
                start,
                min,
                max,
                unit,
            } => {
                let mut a = format!(r#"<Real unit="{unit}""#);
                if min.is_finite() {
                    let _ = write!(a, r#" min="{}""#, real(min));
                }
                if max.is_finite() {
                    let _ = write!(a, r#" max="{}""#, real(max));
                }
                if let Some(s) = start {
                    let _ = write!(a, r#" start="{}""#, real(s));
                }
                a + "/>"
            }
            Kind::Integer { start, min, max } => match start {
                Some(s) => format!(r#"<Integer min="{min}" max="{max}" start="{s}"/>"#),
                None => "<Integer/>".to_string(),
            },
            Kind::Boolean => "<Boolean/>".to_string(),
            Kind::Enumeration { start, type_index } => format!(
                r#"<Integer declaredType="{}" start="{start}"/>"#,
                ENUMERATIONS[type_index].name
            ),
        };
        let _ = writeln!(x, "      {element}\n    </ScalarVariable>");
    }
    x.push_str("  </ModelVariables>\n  <ModelStructure>\n    <Outputs>\n");
    let index = |f: &dyn Fn(&variables::Variable) -> bool| -> Vec<usize> {
        VARIABLES
            .iter()
            .enumerate()
            .filter(|(_, v)| f(v))
            .map(|(i, _)| i + 1)
            .collect()
    };
    for i in index(&|v| v.causality == Causality::Output) {
        let inputs = FEEDTHROUGH
            .iter()
            .find(|(output, _)| *output as usize + 1 == i)
            .map_or(&[][..], |(_, inputs)| inputs);
        let dependencies: Vec<String> = inputs
            .iter()
            .map(|u| (*u as usize + 1).to_string())
            .collect();
        let _ = writeln!(
            x,
            r#"      <Unknown index="{i}" dependencies="{}"/>"#,
            dependencies.join(" ")
        );
    }
    x.push_str("    </Outputs>\n    <InitialUnknowns>\n");
    for i in index(&|v| {
        matches!(
            v.causality,
            Causality::Output | Causality::CalculatedParameter
        )
    }) {
        let _ = writeln!(x, r#"      <Unknown index="{i}"/>"#);
    }
    x.push_str("    </InitialUnknowns>\n  </ModelStructure>\n</fmiModelDescription>\n");
    x
}

/// FNV-1a, 128 bits, written as a braced GUID.
fn guid(text: &str) -> String {
    let mut h: u128 = 0x6c62_272e_07bb_0142_62b8_2175_6295_c58d;
    for b in text.bytes() {
        h ^= u128::from(b);
        h = h.wrapping_mul(0x0000_0000_0100_0000_0000_0000_0000_013b);
    }
    let s = format!("{h:032x}");
    format!(
        "{{{}-{}-{}-{}-{}}}",
        &s[0..8],
        &s[8..12],
        &s[12..16],
        &s[16..20],
        &s[20..32]
    )
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    println!("cargo::rerun-if-changed=src/fmi/variables.rs");
    println!("cargo::rerun-if-changed=build.rs");
    check();
    let template = render();
    let guid = guid(&template);
    let xml = template.replace(GUID_PLACEHOLDER, &guid);
    let out = std::path::PathBuf::from(std::env::var("OUT_DIR")?);
    std::fs::write(out.join("modelDescription.xml"), xml)?;
    std::fs::write(out.join("guid.txt"), guid)?;
    Ok(())
}
