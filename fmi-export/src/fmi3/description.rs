//! FMI 3.0 modelDescription.xml from the same variable table as FMI 2's ([`crate::fmi2::description`]):
//! Float64, Int32, Boolean and String variables, the switches as FMI 3 Enumerations, the
//! independent variable `time`, and ModelStructure by value reference (FMI 3.0 §2.4).
//!
//! The instantiation token is the description's own: an FNV-1a 128 hash of its text (with a
//! placeholder where the token goes), like the FMI 2 GUID, so that a change only FMI 3 sees (its
//! arrays, structural parameters, terminals' variables) changes it.

use std::fmt::Write as _;

use super::interface::{ArrayVariable, Fmi3Interface, StructuralParameter};
use crate::description::{Description, check};
use crate::table::{Causality, Kind, ValueReference, Variable};
use crate::xml::{
    GUID_PLACEHOLDER, attributes, escape, guid, header, log_categories_and_experiment,
    real_attributes, unit_definitions,
};

/// The value reference of the independent variable `time` (FMI 3.0 requires one; the table's
/// own value references are dense from 0, so this one stays clear of any it will ever have).
pub const TIME_VALUE_REFERENCE: u32 = 1_000_000;

/// The first value reference of the input derivatives ([`input_derivative_vr`]).
const INPUT_DERIVATIVES: u32 = 1_001_000;

/// The value reference of `der(u)` (`order` 1) or `der(u,2)`, the time derivative of a model's
/// `k`-th input `u` (in table order), in FMI 3. FMI 3.0 has no fmi3SetInputDerivatives: a model
/// that takes input derivatives (FMI 2's canInterpolateInputs) declares them in FMI 3 as inputs
/// of their own, whose `derivative` attribute names the variable they derive (FMI 3.0 §2.4.7.4);
/// a master sets them where it sets the inputs, for the next step.
pub fn input_derivative_vr(k: usize, order: u32) -> u32 {
    INPUT_DERIVATIVES + 1000 * (order - 1) + k as u32
}

/// The input (its index among `n` inputs) and the order, at most `max`, of the input derivative
/// of value reference `vr`, if it is one ([`input_derivative_vr`]).
pub fn input_derivative(vr: u32, n: usize, max: u32) -> Option<(usize, u32)> {
    let offset = vr.checked_sub(INPUT_DERIVATIVES)?;
    let (order, k) = (offset / 1000 + 1, (offset % 1000) as usize);
    (k < n && order <= max).then_some((k, order))
}

/// The FMI 3.0 modelDescription.xml of `d` with the FMI 3 additions `fmi3`, and its
/// instantiationToken.
pub fn model_description<V: ValueReference>(
    d: &Description<V>,
    fmi3: Fmi3Interface,
) -> Result<(String, String), String> {
    let template = render(d, fmi3)?;
    let token = guid(&template);
    Ok((template.replace(GUID_PLACEHOLDER, &token), token))
}

/// The description with [`GUID_PLACEHOLDER`] for its token.
fn render<V: ValueReference>(d: &Description<V>, fmi3: Fmi3Interface) -> Result<String, String> {
    check(d)?;
    check_interface(d, fmi3)?;
    let mut x = header(d, ("3.0", "instantiationToken"), "");
    let _ = writeln!(
        x,
        r#"  <CoSimulation modelIdentifier="{}" canHandleVariableCommunicationStepSize="true" canGetAndSetFMUState="true" canSerializeFMUState="true" providesDirectionalDerivatives="{}" maxOutputDerivativeOrder="{}" hasEventMode="{}" mightReturnEarlyFromDoStep="{}" providesIntermediateUpdate="{}" canReturnEarlyAfterIntermediateUpdate="{}"/>"#,
        d.model_identifier,
        d.provides_directional_derivative,
        d.max_output_derivative_order,
        fmi3.has_event_mode,
        fmi3.might_return_early,
        fmi3.provides_intermediate_update,
        fmi3.can_return_early_after_intermediate_update,
    );
    x.push_str(&unit_definitions(d));
    if !d.enumerations.is_empty() {
        x.push_str("  <TypeDefinitions>\n");
        for e in d.enumerations {
            let _ = writeln!(x, r#"    <EnumerationType name="{}">"#, e.name);
            for (i, (item, description)) in (1..).zip(e.items) {
                let _ = writeln!(
                    x,
                    r#"      <Item name="{item}" value="{i}" description="{}"/>"#,
                    escape(description)
                );
            }
            x.push_str("    </EnumerationType>\n");
        }
        x.push_str("  </TypeDefinitions>\n");
    }
    x.push_str(&log_categories_and_experiment(d));
    x.push_str("  <ModelVariables>\n");
    let time_unit = if d.units.iter().any(|(u, _, _)| *u == "s") {
        r#" unit="s""#
    } else {
        ""
    };
    let _ = writeln!(
        x,
        r#"    <Float64 name="time" valueReference="{TIME_VALUE_REFERENCE}" causality="independent" variability="continuous" description="Simulation time"{time_unit}/>"#
    );
    for p in fmi3.structural_parameters {
        x.push_str(&structural_parameter(p));
    }
    for v in d.variables {
        x.push_str(&variable(d, v, fmi3.provides_intermediate_update));
    }
    for order in 1..=input_derivative_order(d, fmi3) {
        for (k, v) in inputs(d).enumerate() {
            let (name, derives) = match order {
                1 => (format!("der({})", v.name), v.vr.index()),
                _ => (
                    format!("der({},{order})", v.name),
                    input_derivative_vr(k, order - 1),
                ),
            };
            let _ = writeln!(
                x,
                r#"    <Float64 name="{name}" valueReference="{}" description="{}" causality="input" variability="continuous" derivative="{derives}" start="0"/>"#,
                input_derivative_vr(k, order),
                escape(&format!(
                    "Time derivative of order {order} of {} at the communication point, for the \
                     next step (the input is then its Taylor polynomial over the step; not set \
                     again, the input is held)",
                    v.name
                )),
            );
        }
    }
    for a in fmi3.arrays {
        x.push_str(&array(fmi3, a));
    }
    x.push_str("  </ModelVariables>\n  <ModelStructure>\n");
    let vrs = |f: &dyn Fn(&Variable<V>) -> bool| -> Vec<V> {
        d.variables.iter().filter(|v| f(v)).map(|v| v.vr).collect()
    };
    let list = |vrs: &[V]| -> String {
        let numbers: Vec<String> = vrs.iter().map(|vr| vr.index().to_string()).collect();
        numbers.join(" ")
    };
    for output in vrs(&|v| v.causality == Causality::Output) {
        let inputs = feedthrough(d, output);
        let _ = writeln!(
            x,
            r#"    <Output valueReference="{}" dependencies="{}{}"/>"#,
            output.index(),
            list(inputs),
            rates(d, fmi3, inputs)
        );
    }
    for a in fmi3.arrays {
        if a.causality == Causality::Output {
            let _ = writeln!(x, r#"    <Output valueReference="{}"/>"#, a.vr);
        }
    }
    for unknown in vrs(&|v| {
        matches!(
            v.causality,
            Causality::Output | Causality::CalculatedParameter
        )
    }) {
        let knowns = vrs(&|v| {
            matches!(v.causality, Causality::Input | Causality::Parameter)
                && (d.initial_dependency)(unknown, v.vr)
        });
        let _ = writeln!(
            x,
            r#"    <InitialUnknown valueReference="{}" dependencies="{}{}"/>"#,
            unknown.index(),
            list(&knowns),
            rates(d, fmi3, feedthrough(d, unknown))
        );
    }
    for a in fmi3.arrays {
        let _ = writeln!(x, r#"    <InitialUnknown valueReference="{}"/>"#, a.vr);
    }
    x.push_str("  </ModelStructure>\n</fmiModelDescription>\n");
    Ok(x)
}

/// The model's Real inputs, in table order.
fn inputs<V: ValueReference>(d: &Description<V>) -> impl Iterator<Item = &Variable<V>> {
    d.variables
        .iter()
        .filter(|v| v.causality == Causality::Input)
}

/// The highest order of the input derivatives declared (0: none).
fn input_derivative_order<V: ValueReference>(d: &Description<V>, fmi3: Fmi3Interface) -> u32 {
    if fmi3.input_derivatives {
        d.max_input_derivative_order
    } else {
        0
    }
}

/// The inputs an output depends on at once ([`Description::feedthrough`]).
fn feedthrough<V: ValueReference>(d: &Description<V>, output: V) -> &'static [V] {
    d.feedthrough
        .iter()
        .find(|(o, _)| *o == output)
        .map_or(&[][..], |(_, inputs)| inputs)
}

/// The value references, each after a space, of `der(u)` of the inputs `u` among `direct` whose
/// rate an output reads at once ([`Description::rate_feedthrough`]), where `der(u)` is declared.
fn rates<V: ValueReference>(d: &Description<V>, fmi3: Fmi3Interface, direct: &[V]) -> String {
    inputs(d)
        .enumerate()
        .filter(|(_, v)| direct.contains(&v.vr) && d.rate_feedthrough.contains(&v.vr))
        .filter(|_| input_derivative_order(d, fmi3) > 0)
        .map(|(k, _)| format!(" {}", input_derivative_vr(k, 1)))
        .collect()
}

/// Checks the FMI 3 additions: value references unique and outside the table's, start values
/// in range, each array's dimension a structural parameter and its unit defined.
fn check_interface<V: ValueReference>(
    d: &Description<V>,
    fmi3: Fmi3Interface,
) -> Result<(), String> {
    let extra = fmi3
        .structural_parameters
        .iter()
        .map(|p| (p.vr, p.name))
        .chain(fmi3.arrays.iter().map(|a| (a.vr, a.name)))
        .chain((1..=input_derivative_order(d, fmi3)).flat_map(|order| {
            inputs(d)
                .enumerate()
                .map(move |(k, v)| (input_derivative_vr(k, order), v.name))
        }));
    let mut seen = vec![TIME_VALUE_REFERENCE];
    for (vr, name) in extra {
        if seen.contains(&vr) || d.variables.iter().any(|v| v.vr.index() == vr) {
            return Err(format!("{name}: value reference {vr} is taken"));
        }
        seen.push(vr);
    }
    for p in fmi3.structural_parameters {
        if !(p.min..=p.max).contains(&p.start) {
            return Err(format!(
                "{}: start {} outside [{}, {}]",
                p.name, p.start, p.min, p.max
            ));
        }
    }
    for a in fmi3.arrays {
        if a.dimension >= fmi3.structural_parameters.len() {
            return Err(format!(
                "{}: dimension {} is no structural parameter",
                a.name, a.dimension
            ));
        }
        if !d.units.iter().any(|(u, _, _)| *u == a.unit) {
            return Err(format!("{}: unit {} is not defined", a.name, a.unit));
        }
    }
    Ok(())
}

/// A structural parameter's element.
fn structural_parameter(p: &StructuralParameter) -> String {
    format!(
        r#"    <UInt64 name="{}" valueReference="{}" description="{}" causality="structuralParameter" variability="fixed" start="{}" min="{}" max="{}"/>"#,
        p.name,
        p.vr,
        escape(p.description),
        p.start,
        p.min,
        p.max
    ) + "\n"
}

/// An array's element, with its `<Dimension>`.
fn array(fmi3: Fmi3Interface, a: &ArrayVariable) -> String {
    let (causality, variability, intermediate) = match a.causality {
        Causality::CalculatedParameter => ("calculatedParameter", "fixed", ""),
        _ if fmi3.provides_intermediate_update => {
            ("output", "continuous", r#" intermediateUpdate="true""#)
        }
        _ => ("output", "continuous", ""),
    };
    format!(
        r#"    <Float64 name="{}" valueReference="{}" description="{}" causality="{causality}" variability="{variability}"{intermediate} unit="{}">
      <Dimension valueReference="{}"/>
    </Float64>"#,
        a.name,
        a.vr,
        escape(a.description),
        a.unit,
        fmi3.structural_parameters[a.dimension].vr,
    ) + "\n"
}

/// One variable's element; with `intermediate`, an output is readable in intermediate update.
fn variable<V: ValueReference>(d: &Description<V>, v: &Variable<V>, intermediate: bool) -> String {
    let (causality, variability, initial) = attributes(v);
    let intermediate = if intermediate && v.causality == Causality::Output {
        r#" intermediateUpdate="true""#
    } else {
        ""
    };
    let common = format!(
        r#"name="{}" valueReference="{}" description="{}" causality="{causality}" variability="{variability}"{initial}{intermediate}"#,
        v.name,
        v.vr.index(),
        escape(v.description)
    );
    match v.kind {
        Kind::Real {
            start,
            min,
            max,
            unit,
        } => {
            let attributes = real_attributes(d, v.vr, start, min, max);
            format!("    <Float64 {common} unit=\"{unit}\"{attributes}/>\n")
        }
        Kind::Integer { start, min, max } => match start {
            Some(s) => {
                format!(r#"    <Int32 {common} min="{min}" max="{max}" start="{s}"/>"#) + "\n"
            }
            None => format!("    <Int32 {common}/>\n"),
        },
        Kind::Boolean => format!("    <Boolean {common}/>\n"),
        Kind::String { start } => format!(
            "    <String {common}>\n      <Start value=\"{}\"/>\n    </String>\n",
            escape(start)
        ),
        Kind::Enumeration { start, type_index } => {
            format!(
                r#"    <Enumeration {common} declaredType="{}" start="{start}"/>"#,
                d.enumerations[type_index].name
            ) + "\n"
        }
    }
}

/// The terminalsAndIcons.xml of `fmi3`'s terminals (FMI 3.0 §2.4.9), every member a variable of
/// `d`; None for a model without terminals.
pub fn terminals_and_icons<V: ValueReference>(
    d: &Description<V>,
    fmi3: Fmi3Interface,
) -> Result<Option<String>, String> {
    if fmi3.terminals.is_empty() {
        return Ok(None);
    }
    let mut x = String::from(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<fmiTerminalsAndIcons fmiVersion=\"3.0\">\n  <Terminals>\n",
    );
    for t in fmi3.terminals {
        let _ = writeln!(
            x,
            r#"    <Terminal name="{}" matchingRule="bus" terminalKind="{}" description="{}">"#,
            t.name,
            t.kind,
            escape(t.description)
        );
        for (member, name) in t.members {
            if !d.variables.iter().any(|v| v.name == *name) {
                return Err(format!("terminal {}: no variable {name}", t.name));
            }
            let _ = writeln!(
                x,
                r#"      <TerminalMemberVariable variableName="{name}" memberName="{member}" variableKind="signal"/>"#
            );
        }
        x.push_str("    </Terminal>\n");
    }
    x.push_str("  </Terminals>\n</fmiTerminalsAndIcons>\n");
    Ok(Some(x))
}
