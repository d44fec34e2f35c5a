//! What modelDescription.xml says about one model, as data ([`Description`]), and the checks of
//! it that hold for every FMI version's rendering ([`check`]).

use crate::table::{Causality, Enumeration, Kind, ValueReference, Variable};

/// Everything modelDescription.xml says about one model.
#[derive(Clone, Copy, Debug)]
pub struct Description<V: 'static> {
    /// modelName and modelIdentifier (the shared library's name).
    pub model_identifier: &'static str,
    /// Model description.
    pub description: &'static str,
    /// Author.
    pub author: &'static str,
    /// Model version.
    pub version: &'static str,
    /// Copyright notice.
    pub copyright: &'static str,
    /// License.
    pub license: &'static str,
    /// generationTool.
    pub generation_tool: &'static str,
    /// Highest order of fmi2SetRealInputDerivatives (0: canInterpolateInputs = false).
    pub max_input_derivative_order: u32,
    /// maxOutputDerivativeOrder.
    pub max_output_derivative_order: u32,
    /// Units: name, SI base-unit exponents (kg, m, s, A, K, rad) or None where FMI 2's integer
    /// exponents cannot express the unit, and the factor to the base unit (1 for SI units).
    pub units: &'static [(&'static str, Option<[i32; 6]>, f64)],
    /// Display units: (unit, display unit, factor), the display value being factor × value.
    pub display_units: &'static [(&'static str, &'static str, f64)],
    /// The display unit a master shows a variable in by default.
    pub variable_display_units: &'static [(V, &'static str)],
    /// Switch types.
    pub enumerations: &'static [Enumeration],
    /// Log categories: name and description.
    pub log_categories: &'static [(&'static str, &'static str)],
    /// DefaultExperiment: start, stop, tolerance, step size.
    pub default_experiment: (f64, f64, f64, f64),
    /// The variables, in value-reference order.
    pub variables: &'static [Variable<V>],
    /// Direct feedthrough: each output with the inputs it depends on without a step (outputs
    /// not listed depend on none).
    pub feedthrough: &'static [(V, &'static [V])],
    /// The inputs whose rate (the first derivative set for the next step) an output that depends
    /// on them at once reads as well (a prescribed speed's: the acceleration it prescribes).
    pub rate_feedthrough: &'static [V],
    /// Whether an initial unknown (an output or a calculated parameter) depends, in
    /// initialization mode, on a known (an input or a parameter: FMI 2.0 makes every variable
    /// with initial = "exact" a known), listed as the `dependencies` of
    /// ModelStructure/InitialUnknowns.
    pub initial_dependency: fn(unknown: V, known: V) -> bool,
    /// providesDirectionalDerivative: whether the model gives ∂y/∂u (the FMI layer's
    /// `Model::output_sensitivity`).
    pub provides_directional_derivative: bool,
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

/// Checks the table: dense value references, unique structured names, defined units, starts
/// inside ranges, starts exactly for parameters and inputs, feedthrough from inputs to outputs.
pub fn check<V: ValueReference>(d: &Description<V>) -> Result<(), String> {
    let (variables, enumerations) = (d.variables, d.enumerations);
    for (vr, display) in d.variable_display_units {
        let v = &variables[vr.index() as usize];
        let unit = match v.kind {
            Kind::Real { unit, .. } => unit,
            _ => {
                return Err(format!(
                    "{}: a display unit for a non-Real variable",
                    v.name
                ));
            }
        };
        if !d
            .display_units
            .iter()
            .any(|(u, n, _)| *u == unit && n == display)
        {
            return Err(format!(
                "{}: display unit {display} is not defined for {unit}",
                v.name
            ));
        }
    }
    for (output, inputs) in d.feedthrough {
        let causality = |vr: &V| variables[vr.index() as usize].causality;
        if causality(output) != Causality::Output
            || inputs.iter().any(|u| causality(u) != Causality::Input)
        {
            return Err(format!(
                "d.feedthrough: {output:?} must be an output and {inputs:?} inputs"
            ));
        }
    }
    for (i, v) in variables.iter().enumerate() {
        if v.vr.index() as usize != i {
            return Err(format!(
                "{} has value reference {} at position {i}",
                v.name,
                v.vr.index()
            ));
        }
        if !structured(v.name) {
            return Err(format!("{} is not a structured name", v.name));
        }
        if variables.iter().filter(|w| w.name == v.name).count() != 1 {
            return Err(format!("{} is not unique", v.name));
        }
        match v.kind {
            Kind::Real {
                start,
                min,
                max,
                unit,
            } => {
                if !d.units.iter().any(|(u, _, _)| *u == unit) {
                    return Err(format!("{}: unit {unit} is not defined", v.name));
                }
                if let Some(s) = start {
                    if !(min <= s && s <= max) {
                        return Err(format!("{}: start {s} outside [{min}, {max}]", v.name));
                    }
                }
            }
            Kind::Integer {
                start: Some(s),
                min,
                max,
            } if !(min <= s && s <= max) => {
                return Err(format!("{}: start {s} outside [{min}, {max}]", v.name));
            }
            Kind::Enumeration { start, type_index } => {
                let n = enumerations[type_index].items.len() as i32;
                if !(1..=n).contains(&start) {
                    return Err(format!("{}: start {start} outside [1, {n}]", v.name));
                }
            }
            _ => {}
        }
        let has_start = match v.kind {
            Kind::Real { start, .. } => start.is_some(),
            Kind::Integer { start, .. } => start.is_some(),
            Kind::Boolean => false,
            Kind::Enumeration { .. } | Kind::String { .. } => true,
        };
        let needs_start = matches!(v.causality, Causality::Parameter | Causality::Input);
        if has_start != needs_start {
            return Err(format!(
                "{}: start value {} for {:?}",
                v.name,
                if has_start { "given" } else { "missing" },
                v.causality
            ));
        }
    }
    Ok(())
}
