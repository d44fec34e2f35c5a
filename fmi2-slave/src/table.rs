//! Variable tables: the types in which a model states its FMI variables once, for the
//! modelDescription.xml ([`crate::description`]) and for its get/set code alike.

/// A model's value references: an enum whose discriminants are the positions in its table.
pub trait ValueReference: Copy + std::fmt::Debug + PartialEq + 'static {
    /// The FMI value reference.
    fn index(self) -> u32;
}

/// FMI causality.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Causality {
    /// Fixed parameter, set before initialisation ends.
    Parameter,
    /// Computed from parameters.
    CalculatedParameter,
    /// Continuous input.
    Input,
    /// Output.
    Output,
}

/// FMI variability.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Variability {
    /// Fixed after initialisation.
    Fixed,
    /// Changes at events (steps) only.
    Discrete,
    /// Continuous in time.
    Continuous,
}

/// Base type, start value and range of a variable.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// Real with unit and range.
    Real {
        /// Start value (None: calculated).
        start: Option<f64>,
        /// Smallest allowed value.
        min: f64,
        /// Largest allowed value.
        max: f64,
        /// Unit name, defined in the table's units.
        unit: &'static str,
    },
    /// Integer with range.
    Integer {
        /// Start value (None: calculated).
        start: Option<i32>,
        /// Smallest allowed value.
        min: i32,
        /// Largest allowed value.
        max: i32,
    },
    /// Boolean.
    Boolean,
    /// A switch: one of the items of one of the table's [`Enumeration`]s, numbered from 1. Declared as an
    /// FMI Integer of a named type with the items in its description (not as an FMI Enumeration,
    /// which some masters, libcosim among them, cannot set).
    Enumeration {
        /// Start item.
        start: i32,
        /// Index into the table's enumerations.
        type_index: usize,
    },
}

/// One FMI variable, with `V` the model's value-reference type.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Variable<V> {
    /// Value reference (its position in the table).
    pub vr: V,
    /// Structured name.
    pub name: &'static str,
    /// Causality.
    pub causality: Causality,
    /// Variability.
    pub variability: Variability,
    /// Type, start and range.
    pub kind: Kind,
    /// Description.
    pub description: &'static str,
}

/// The items of a switch as the variable descriptions show them: "1 = rigid, 2 = ancf, ...".
pub fn item_list(e: &Enumeration) -> String {
    let items: Vec<String> = (1..)
        .zip(e.items)
        .map(|(i, (item, _))| format!("{i} = {item}"))
        .collect();
    items.join(", ")
}

/// A switch type (an enumeration in meaning, an FMI Integer type in the XML): name and items
/// (name, description), numbered from 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Enumeration {
    /// Type name.
    pub name: &'static str,
    /// Items.
    pub items: &'static [(&'static str, &'static str)],
}
