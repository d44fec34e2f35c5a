//! What a model's FMI 3 interface declares beyond the variable table it shares with FMI 2: its
//! co-simulation capabilities, its structural parameters and its arrays (FMI 2 has neither).

use crate::table::Causality;

/// A model's FMI 3 additions: rendered into its FMI 3 modelDescription.xml and read by the
/// `fmi3*` functions (`fmi-export`'s `fmi3` module).
#[derive(Clone, Copy, Debug)]
pub struct Fmi3Interface {
    /// mightReturnEarlyFromDoStep: fmi3DoStep may end before the communication point (at an event
    /// of the model) when the master allows it.
    pub might_return_early: bool,
    /// hasEventMode: with the master's consent (eventModeUsed), an early return at an event asks
    /// for Event Mode, where the discrete variables that changed there are read.
    pub has_event_mode: bool,
    /// providesIntermediateUpdate: with the master's callback, fmi3DoStep pauses after each
    /// internal step before the communication point, and the master reads the outputs there
    /// (no input is set there).
    pub provides_intermediate_update: bool,
    /// canReturnEarlyAfterIntermediateUpdate: the master may ask, at such a pause, for the step
    /// to end there (if it allowed early return).
    pub can_return_early_after_intermediate_update: bool,
    /// The structural parameters, in the order [`ArrayVariable::dimension`] counts them.
    pub structural_parameters: &'static [StructuralParameter],
    /// The Float64 arrays, in the order the model's `Model::get_array` counts them.
    pub arrays: &'static [ArrayVariable],
    /// Terminals: the variables a system editor connects together, grouped
    /// (`terminalsAndIcons/terminalsAndIcons.xml`, FMI 3.0 §2.4.9).
    pub terminals: &'static [Terminal],
    /// Whether a model that takes input derivatives declares them, as inputs `der(u)` whose
    /// `derivative` attribute names the input they derive (FMI 3.0 §2.4.7.4).
    pub input_derivatives: bool,
}

impl Fmi3Interface {
    /// No early return, no structural parameter, no array.
    pub const NONE: Self = Self {
        might_return_early: false,
        has_event_mode: false,
        provides_intermediate_update: false,
        can_return_early_after_intermediate_update: false,
        structural_parameters: &[],
        arrays: &[],
        terminals: &[],
        input_derivatives: true,
    };

    /// The interface without arrays and structural parameters, and without the input
    /// derivatives' variables: what a master with a scalar FMI 3 import can load. OMSimulator 3.0
    /// asks every variable it lists for one value, an array too, and takes a `derivative`
    /// attribute for a state's, read as a variable index (a second derivative's, the value
    /// reference of the first, crashes it). The capabilities and terminals stay; the inputs are
    /// held over each step.
    pub const fn scalar(self) -> Self {
        Self {
            structural_parameters: &[],
            arrays: &[],
            input_derivatives: false,
            ..self
        }
    }

    /// The structural parameter with value reference `vr`, with its index.
    pub fn structural_parameter(&self, vr: u32) -> Option<(usize, &'static StructuralParameter)> {
        let parameters: &'static [StructuralParameter] = self.structural_parameters;
        parameters.iter().enumerate().find(|(_, p)| p.vr == vr)
    }

    /// The array with value reference `vr`, with its index.
    pub fn array(&self, vr: u32) -> Option<(usize, &'static ArrayVariable)> {
        let arrays: &'static [ArrayVariable] = self.arrays;
        arrays.iter().enumerate().find(|(_, a)| a.vr == vr)
    }
}

/// A structural parameter: a UInt64 count that sizes arrays (causality structuralParameter,
/// variability fixed), set only in Configuration Mode (FMI 3.0 §2.3.5).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StructuralParameter {
    /// Value reference, outside the variable table's.
    pub vr: u32,
    /// Structured name.
    pub name: &'static str,
    /// Description.
    pub description: &'static str,
    /// Start value.
    pub start: u64,
    /// Smallest allowed value.
    pub min: u64,
    /// Largest allowed value.
    pub max: u64,
}

/// A one-dimensional Float64 array whose size is the value of a structural parameter
/// (`<Dimension valueReference=…>`, FMI 3.0 §2.4.7.2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArrayVariable {
    /// Value reference, outside the variable table's.
    pub vr: u32,
    /// Structured name.
    pub name: &'static str,
    /// Description.
    pub description: &'static str,
    /// Output (continuous) or calculated parameter (fixed).
    pub causality: Causality,
    /// Unit name, defined in the table's units.
    pub unit: &'static str,
    /// Index of the structural parameter that sizes it.
    pub dimension: usize,
}

/// A terminal: signals a system editor connects in one go to the same-named members of a
/// terminal of another FMU (matchingRule "bus": the members both have).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Terminal {
    /// Name.
    pub name: &'static str,
    /// terminalKind: what kind of connector it is.
    pub kind: &'static str,
    /// Description.
    pub description: &'static str,
    /// Its members: (memberName, the variable's name).
    pub members: &'static [(&'static str, &'static str)],
}
