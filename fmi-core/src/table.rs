//! Variable tables: the types in which a model states its FMI variables once, for the
//! modelDescription.xml ([`crate::description::Description`]) and for its get/set code alike.

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
    /// String (a file name, for instance).
    String {
        /// Start value.
        start: &'static str,
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

impl<V: Copy> Variable<V> {
    /// A fixed String parameter.
    pub const fn string(
        vr: V,
        name: &'static str,
        start: &'static str,
        description: &'static str,
    ) -> Self {
        Self {
            vr,
            name,
            causality: Causality::Parameter,
            variability: Variability::Fixed,
            kind: Kind::String { start },
            description,
        }
    }

    /// A fixed Real parameter.
    pub const fn parameter(
        vr: V,
        name: &'static str,
        start: f64,
        min: f64,
        max: f64,
        unit: &'static str,
        description: &'static str,
    ) -> Self {
        Self {
            vr,
            name,
            causality: Causality::Parameter,
            variability: Variability::Fixed,
            kind: Kind::Real {
                start: Some(start),
                min,
                max,
                unit,
            },
            description,
        }
    }

    /// A continuous Real output.
    pub const fn output(
        vr: V,
        name: &'static str,
        unit: &'static str,
        description: &'static str,
    ) -> Self {
        Self {
            vr,
            name,
            causality: Causality::Output,
            variability: Variability::Continuous,
            kind: Kind::Real {
                start: None,
                min: f64::NEG_INFINITY,
                max: f64::INFINITY,
                unit,
            },
            description,
        }
    }

    /// This Real variable as a calculated parameter: fixed, non-negative, computed from the
    /// parameters.
    pub const fn calculated(self) -> Self {
        let kind = match self.kind {
            Kind::Real { unit, .. } => Kind::Real {
                start: None,
                min: 0.0,
                max: f64::INFINITY,
                unit,
            },
            other => other,
        };
        Self {
            causality: Causality::CalculatedParameter,
            variability: Variability::Fixed,
            kind,
            ..self
        }
    }

    /// A peak-hold output: a Real that changes only at communication points.
    pub const fn peak(
        vr: V,
        name: &'static str,
        unit: &'static str,
        description: &'static str,
    ) -> Self {
        Self {
            variability: Variability::Discrete,
            ..Self::output(vr, name, unit, description)
        }
    }

    /// A counter output (Integer, discrete, non-negative).
    pub const fn count(vr: V, name: &'static str, description: &'static str) -> Self {
        Self {
            vr,
            name,
            causality: Causality::Output,
            variability: Variability::Discrete,
            kind: Kind::Integer {
                start: None,
                min: 0,
                max: i32::MAX,
            },
            description,
        }
    }

    /// A continuous Real input.
    pub const fn input(
        vr: V,
        name: &'static str,
        start: f64,
        min: f64,
        max: f64,
        unit: &'static str,
        description: &'static str,
    ) -> Self {
        Self {
            causality: Causality::Input,
            variability: Variability::Continuous,
            ..Self::parameter(vr, name, start, min, max, unit, description)
        }
    }

    /// A switch parameter (an item of the table's enumeration `type_index`).
    pub const fn enumeration(
        vr: V,
        name: &'static str,
        start: i32,
        type_index: usize,
        description: &'static str,
    ) -> Self {
        Self {
            vr,
            name,
            causality: Causality::Parameter,
            variability: Variability::Fixed,
            kind: Kind::Enumeration { start, type_index },
            description,
        }
    }

    /// A fixed Integer parameter.
    pub const fn integer(
        vr: V,
        name: &'static str,
        start: i32,
        min: i32,
        max: i32,
        description: &'static str,
    ) -> Self {
        Self {
            vr,
            name,
            causality: Causality::Parameter,
            variability: Variability::Fixed,
            kind: Kind::Integer {
                start: Some(start),
                min,
                max,
            },
            description,
        }
    }
}
