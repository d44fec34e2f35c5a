//! modelDescription.xml from a variable table: checked, rendered, and identified by a GUID that
//! is a hash of the rendered text (FMI 2.0.4 §2.2), so a changed interface gets a new GUID.

use std::fmt::Write as _;

pub use fmi_core::description::{Description, check};

use crate::table::{Causality, Kind, ValueReference, Variability, Variable, item_list};

/// Where the GUID (FMI 3: the instantiation token) goes in a rendered description: its hash is
/// taken with this in its place.
pub(crate) const GUID_PLACEHOLDER: &str = "@GUID@";

/// The rendered XML and its GUID.
pub fn model_description<V: ValueReference>(
    d: &Description<V>,
) -> Result<(String, String), String> {
    check(d)?;
    let template = render(d);
    let guid = guid(&template);
    Ok((template.replace(GUID_PLACEHOLDER, &guid), guid))
}

pub(crate) fn real(x: f64) -> String {
    format!("{x:?}")
}

pub(crate) fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn render<V: ValueReference>(d: &Description<V>) -> String {
    let mut x = String::new();
    let _ = writeln!(x, r#"<?xml version="1.0" encoding="UTF-8"?>"#);
    let _ = writeln!(
        x,
        r#"<fmiModelDescription fmiVersion="2.0" modelName="{}" guid="{GUID_PLACEHOLDER}"
  description="{}"
  author="{}" version="{}" copyright="{}" license="{}"
  generationTool="{}" variableNamingConvention="structured" numberOfEventIndicators="0">"#,
        d.model_identifier,
        escape(d.description),
        escape(d.author),
        d.version,
        escape(d.copyright),
        escape(d.license),
        escape(d.generation_tool),
    );
    let _ = writeln!(
        x,
        r#"  <CoSimulation modelIdentifier="{}" needsExecutionTool="false" canHandleVariableCommunicationStepSize="true" canInterpolateInputs="{}" maxOutputDerivativeOrder="{}" canRunAsynchronuously="false" canBeInstantiatedOnlyOncePerProcess="false" canNotUseMemoryManagementFunctions="true" canGetAndSetFMUstate="true" canSerializeFMUstate="true" providesDirectionalDerivative="{}"/>"#,
        d.model_identifier,
        d.max_input_derivative_order > 0,
        d.max_output_derivative_order,
        d.provides_directional_derivative
    );
    x.push_str(&unit_definitions(d));
    if !d.enumerations.is_empty() {
        x.push_str("  <TypeDefinitions>\n");
    }
    // Switches are Integer types, not FMI Enumerations, so that masters without Enumeration
    // support (libcosim drops such variables) can set them; the items are named in the
    // descriptions of the type (with each item's meaning) and of the variable.
    for e in d.enumerations {
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
    if !d.enumerations.is_empty() {
        x.push_str("  </TypeDefinitions>\n");
    }
    x.push_str(&log_categories_and_experiment(d));
    x.push_str("  <ModelVariables>\n");
    for (i, v) in d.variables.iter().enumerate() {
        let (causality, variability, initial) = attributes(v);
        let description = match v.kind {
            Kind::Enumeration { type_index, .. } => format!(
                "{} ({})",
                v.description,
                item_list(&d.enumerations[type_index])
            ),
            _ => v.description.to_string(),
        };
        let _ = writeln!(
            x,
            r#"    <!-- {} --><ScalarVariable name="{}" valueReference="{}" description="{}" causality="{causality}" variability="{variability}"{initial}>"#,
            i + 1,
            v.name,
            v.vr.index(),
            escape(&description)
        );
        let element = match v.kind {
            Kind::Real {
                start,
                min,
                max,
                unit,
            } => {
                format!(
                    r#"<Real unit="{unit}"{}/>"#,
                    real_attributes(d, v.vr, start, min, max)
                )
            }
            Kind::Integer { start, min, max } => match start {
                Some(s) => format!(r#"<Integer min="{min}" max="{max}" start="{s}"/>"#),
                None => "<Integer/>".to_string(),
            },
            Kind::Boolean => "<Boolean/>".to_string(),
            Kind::String { start } => format!(r#"<String start="{}"/>"#, escape(start)),
            Kind::Enumeration { start, type_index } => format!(
                r#"<Integer declaredType="{}" start="{start}"/>"#,
                d.enumerations[type_index].name
            ),
        };
        let _ = writeln!(x, "      {element}\n    </ScalarVariable>");
    }
    x.push_str("  </ModelVariables>\n  <ModelStructure>\n    <Outputs>\n");
    let index = |f: &dyn Fn(&Variable<V>) -> bool| -> Vec<usize> {
        d.variables
            .iter()
            .enumerate()
            .filter(|(_, v)| f(v))
            .map(|(i, _)| i + 1)
            .collect()
    };
    for i in index(&|v| v.causality == Causality::Output) {
        let inputs = d
            .feedthrough
            .iter()
            .find(|(output, _)| output.index() as usize + 1 == i)
            .map_or(&[][..], |(_, inputs)| inputs);
        let dependencies: Vec<String> =
            inputs.iter().map(|u| (u.index() + 1).to_string()).collect();
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
        let unknown = d.variables[i - 1].vr;
        let dependencies: Vec<String> = index(&|v| {
            matches!(v.causality, Causality::Input | Causality::Parameter)
                && (d.initial_dependency)(unknown, v.vr)
        })
        .iter()
        .map(ToString::to_string)
        .collect();
        let _ = writeln!(
            x,
            r#"      <Unknown index="{i}" dependencies="{}"/>"#,
            dependencies.join(" ")
        );
    }
    x.push_str("    </InitialUnknowns>\n  </ModelStructure>\n</fmiModelDescription>\n");
    x
}

/// The causality, the variability and the initial attribute (with its leading space, or empty) of
/// a variable, the same in FMI 2 and FMI 3: parameters are exact, outputs and calculated
/// parameters calculated.
pub(crate) fn attributes<V>(v: &Variable<V>) -> (&'static str, &'static str, &'static str) {
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
        Causality::Input => "",
    };
    (causality, variability, initial)
}

/// The attributes of a Real variable after its unit, the same in FMI 2 and FMI 3: its display unit,
/// a finite min and max, its start.
pub(crate) fn real_attributes<V: ValueReference>(
    d: &Description<V>,
    vr: V,
    start: Option<f64>,
    min: f64,
    max: f64,
) -> String {
    let mut a = String::new();
    if let Some((_, display)) = d.variable_display_units.iter().find(|(v, _)| *v == vr) {
        let _ = write!(a, r#" displayUnit="{display}""#);
    }
    if min.is_finite() {
        let _ = write!(a, r#" min="{}""#, real(min));
    }
    if max.is_finite() {
        let _ = write!(a, r#" max="{}""#, real(max));
    }
    if let Some(s) = start {
        let _ = write!(a, r#" start="{}""#, real(s));
    }
    a
}

/// UnitDefinitions, the same in FMI 2 and FMI 3: each unit with its base-unit exponents and
/// display units.
pub(crate) fn unit_definitions<V>(d: &Description<V>) -> String {
    let mut x = String::from("  <UnitDefinitions>\n");
    for (name, base, factor) in d.units {
        let displays: String = d
            .display_units
            .iter()
            .filter(|(unit, _, _)| unit == name)
            .map(|(_, display, factor)| {
                format!(
                    r#"<DisplayUnit name="{display}" factor="{}"/>"#,
                    real(*factor)
                )
            })
            .collect();
        let base = match base {
            Some(e) => {
                let attrs: String = ["kg", "m", "s", "A", "rad"]
                    .iter()
                    .zip(e)
                    .filter(|(_, v)| **v != 0)
                    .map(|(k, v)| format!(r#" {k}="{v}""#))
                    .collect();
                let factor = if *factor == 1.0 {
                    String::new()
                } else {
                    format!(r#" factor="{}""#, real(*factor))
                };
                format!("<BaseUnit{attrs}{factor}/>")
            }
            None => String::new(),
        };
        if base.is_empty() && displays.is_empty() {
            let _ = writeln!(x, r#"    <Unit name="{name}"/>"#);
        } else {
            let _ = writeln!(x, r#"    <Unit name="{name}">{base}{displays}</Unit>"#);
        }
    }
    x.push_str("  </UnitDefinitions>\n");
    x
}

/// LogCategories and DefaultExperiment, the same in FMI 2 and FMI 3.
pub(crate) fn log_categories_and_experiment<V>(d: &Description<V>) -> String {
    let mut x = String::from("  <LogCategories>\n");
    for (name, description) in d.log_categories {
        let _ = writeln!(
            x,
            r#"    <Category name="{name}" description="{description}"/>"#
        );
    }
    let (start, stop, tolerance, step) = d.default_experiment;
    let _ = writeln!(
        x,
        r#"  </LogCategories>
  <DefaultExperiment startTime="{}" stopTime="{}" tolerance="{}" stepSize="{}"/>"#,
        real(start),
        real(stop),
        real(tolerance),
        real(step)
    );
    x
}

/// FNV-1a, 128 bits, written as a braced GUID.
pub(crate) fn guid(text: &str) -> String {
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
