//! modelDescription.xml from a variable table: checked, rendered, and identified by a GUID that
//! is a hash of the rendered text (FMI 2.0.4 §2.2), so a changed interface gets a new GUID.

use std::fmt::Write as _;

use crate::description::{Description, check};

use crate::table::{Causality, Kind, ValueReference, Variable, item_list};
use crate::xml::{
    GUID_PLACEHOLDER, attributes, escape, guid, header, log_categories_and_experiment,
    real_attributes, unit_definitions,
};

/// The rendered XML and its GUID.
pub fn model_description<V: ValueReference>(
    d: &Description<V>,
) -> Result<(String, String), String> {
    check(d)?;
    let template = render(d);
    let guid = guid(&template);
    Ok((template.replace(GUID_PLACEHOLDER, &guid), guid))
}

fn render<V: ValueReference>(d: &Description<V>) -> String {
    let mut x = header(d, ("2.0", "guid"), r#" numberOfEventIndicators="0""#);
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
