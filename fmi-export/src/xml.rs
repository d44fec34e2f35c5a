//! What FMI 2.0's and FMI 3.0's modelDescription.xml write alike: numbers, escapes, a
//! variable's causality, variability and initial attributes, a Real's range, UnitDefinitions,
//! LogCategories and DefaultExperiment, and the hash that identifies a description (FMI 2's GUID,
//! FMI 3's instantiation token).

use std::fmt::Write as _;

use crate::description::Description;
use crate::table::{Causality, ValueReference, Variability, Variable};

/// Where the GUID (FMI 3: the instantiation token) goes in a rendered description: its hash is
/// taken with this in its place.
pub(crate) const GUID_PLACEHOLDER: &str = "@GUID@";

/// A number as the descriptions write it: the shortest text that reads back to the same f64.
pub(crate) fn real(x: f64) -> String {
    format!("{x:?}")
}

/// Text with XML's special characters escaped, for an attribute value.
pub(crate) fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
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
                let attrs: String = ["kg", "m", "s", "A", "K", "rad"]
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

/// The XML declaration and the opening `fmiModelDescription` element of FMI `version` with its
/// `token` attribute (the GUID, or FMI 3's instantiation token) at [`GUID_PLACEHOLDER`] and the
/// version's `extra` attributes.
pub(crate) fn header<V>(d: &Description<V>, (version, token): (&str, &str), extra: &str) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription fmiVersion="{version}" modelName="{}" {token}="{GUID_PLACEHOLDER}"
  description="{}"
  author="{}" version="{}" copyright="{}" license="{}"
  generationTool="{}" variableNamingConvention="structured"{extra}>
"#,
        d.model_identifier,
        escape(d.description),
        escape(d.author),
        d.version,
        escape(d.copyright),
        escape(d.license),
        escape(d.generation_tool),
    )
}
