//! [`Model`]: what a model supplies, and the [`Context`] it computes in; the instance that
//! holds a model is [`crate::instance`]'s.

use crate::error::FmuError;
use crate::experiment::{Experiment, Step, StepOutcome};
use crate::interface::Fmi3Interface;
use crate::logger::Logger;
use crate::signal::{InputRecord, InputValues};
use crate::state::State;
use crate::table::{Enumeration, ValueReference, Variable};

/// What the instance holds that a model reads when it computes: the master's logger, the inputs
/// (values and derivatives, set by the master through the instance), the experiment and the
/// current communication point.
#[derive(Clone, Copy, Debug)]
pub struct Context<'a, I> {
    /// The master's logger.
    pub log: &'a Logger,
    /// The inputs, by their index among the model's inputs: those of the next step (during a
    /// step: of the step), those outputs read, and whether the step sequence may go on
    /// ([`InputRecord`]).
    pub inputs: &'a InputRecord<I>,
    /// The experiment set up (start, stop, tolerance).
    pub experiment: Experiment,
    /// The current point \[s\]: the communication point on the clock grid, or while a step is
    /// paused inside, the time it paused at ([`crate::experiment::Clock::now`]).
    pub time: f64,
}

/// A co-simulation model behind the FMI functions. The generic layer resolves every value
/// reference to the model's [`Variable`] before a getter or setter sees it ([`crate::checks::resolve`]: it
/// exists and has the function's type) and checks that a value to set is settable in the current
/// state and inside its declared range ([`crate::checks`]): the callbacks receive typed, checked variables ([`Var`]) and only
/// dispatch. Every method that computes gets the instance's [`Context`] (its logger among it).
pub trait Model: Sized + 'static {
    /// The GUID of the model's modelDescription.xml.
    const GUID: &'static str;
    /// Log categories (name, description), as in modelDescription.xml.
    const LOG_CATEGORIES: &'static [(&'static str, &'static str)];
    /// Four bytes that open every serialized state of this model.
    const STATE_MAGIC: [u8; 4];
    /// Version of the state format; a state of another version is rejected.
    const STATE_VERSION: u32;
    /// The model's value references.
    type Vr: ValueReference;
    /// Its input values, by their index among its input variables in table order (the
    /// instance holds them, [`Context::inputs`]).
    type Inputs: InputValues;
    /// The model's variable table, in value-reference order (the generic checks read it).
    const VARIABLES: &'static [Variable<Self::Vr>];
    /// The switch types its enumeration variables refer to.
    const ENUMERATIONS: &'static [Enumeration] = &[];
    /// The highest order of input derivatives it takes (0: canInterpolateInputs = false).
    const MAX_INPUT_DERIVATIVE_ORDER: u32 = 0;
    /// What its FMI 3 interface adds to the table: capabilities, structural parameters, arrays.
    const FMI3: Fmi3Interface = Fmi3Interface::NONE;
    /// The instantiation tokens of its FMI 3 descriptions (their hashes, as its build script
    /// writes them): the one of [`Model::FMI3`], and the one without arrays
    /// ([`Fmi3Interface::scalar`]; the same for a model without arrays). An instance serves the
    /// interface of the token it was instantiated with.
    const FMI3_TOKENS: [&'static str; 2];

    /// A model with every start value (instantiation, Reset).
    fn new() -> Self;

    /// ExitInitializationMode: every parameter check happens here at the latest.
    fn exit_initialization(&mut self, cx: &Context<Self::Inputs>) -> Result<(), FmuError>;

    /// fmi2DoStep and fmi3DoStep: the step `step` (checked against the clock), to its end, or
    /// early at an event of the model where `step.early_return` allows it (on the clock grid,
    /// [`crate::clock`]), or paused after an internal step where `step.pause` allows it (its state
    /// there the one the getters read; called again with the same step, it resumes); what
    /// happened is the outcome, and [`FmuError::Discard`] says where a failed step stopped.
    fn do_step(&mut self, cx: &Context<Self::Inputs>, step: &Step)
    -> Result<StepOutcome, FmuError>;

    /// Ends a paused step at the pause, as an early return (on the clock grid): the time
    /// reached, or None where the step cannot end there (it then stays paused). By default no
    /// step pauses.
    fn return_at_pause(&mut self, _cx: &Context<Self::Inputs>) -> Result<Option<f64>, FmuError> {
        Ok(None)
    }

    /// fmi2GetReal, fmi3GetFloat64 (of every Real variable but the inputs, which the instance
    /// answers).
    fn get_real(
        &mut self,
        cx: &Context<Self::Inputs>,
        vars: &[Var<Self::Vr>],
        value: &mut [f64],
    ) -> Result<(), FmuError>;

    /// fmi2SetReal, fmi3SetFloat64 in machine state `state` (of every Real variable but the
    /// inputs, which the instance holds).
    fn set_real(
        &mut self,
        state: State,
        vars: &[Var<Self::Vr>],
        value: &[f64],
    ) -> Result<(), FmuError>;

    /// fmi3GetFloat64 of the array `array` (its index in [`Model::FMI3`]'s arrays) at the current
    /// point: `value` has the length its structural parameter gives. A model with arrays
    /// implements it; the generic layer calls it for no other.
    fn get_array(
        &mut self,
        _cx: &Context<Self::Inputs>,
        array: usize,
        _value: &mut [f64],
    ) -> Result<(), FmuError> {
        Err(FmuError::Invalid(format!("array {array} cannot be read")))
    }

    /// fmi2GetInteger, fmi3GetInt32 and fmi3GetInt64 (the switches).
    fn get_integer(
        &mut self,
        cx: &Context<Self::Inputs>,
        vars: &[Var<Self::Vr>],
        value: &mut [i32],
    ) -> Result<(), FmuError>;

    /// fmi2SetInteger, fmi3SetInt32 and fmi3SetInt64 in machine state `state`: by default no Integer variable is settable.
    fn set_integer(
        &mut self,
        _state: State,
        vars: &[Var<Self::Vr>],
        _value: &[i32],
    ) -> Result<(), FmuError> {
        not_settable(vars)
    }

    /// GetBoolean: a model with Boolean variables reads them here (by default it has none,
    /// and [`crate::checks::resolve`] refuses every value reference before this is called).
    fn get_boolean(
        &mut self,
        _cx: &Context<Self::Inputs>,
        vars: &[Var<Self::Vr>],
        _value: &mut [i32],
    ) -> Result<(), FmuError> {
        match vars.first() {
            Some(v) => Err(FmuError::Invalid(format!("{} cannot be read", v.name))),
            None => Ok(()),
        }
    }

    /// SetBoolean: by default no Boolean variable is settable.
    fn set_boolean(
        &mut self,
        _state: State,
        vars: &[Var<Self::Vr>],
        _value: &[i32],
    ) -> Result<(), FmuError> {
        not_settable(vars)
    }

    /// GetString: a model with String variables writes their values to `value` (cleared
    /// first); by default it has none, and [`crate::checks::resolve`] refuses every value reference before this
    /// is called.
    fn get_string(
        &mut self,
        vars: &[Var<Self::Vr>],
        _value: &mut Vec<String>,
    ) -> Result<(), FmuError> {
        match vars.first() {
            Some(v) => Err(FmuError::Invalid(format!("{} cannot be read", v.name))),
            None => Ok(()),
        }
    }

    /// SetString: by default no String variable is settable.
    fn set_string(
        &mut self,
        _state: State,
        vars: &[Var<Self::Vr>],
        _value: &[&str],
    ) -> Result<(), FmuError> {
        not_settable(vars)
    }

    /// The directory of the FMU's unpacked `resources` folder, from the instantiation's
    /// resource location (FMI 2: a `file:` URI; FMI 3: a path), if the master gave one that names a directory here:
    /// for a model that reads files from it. By default it is not kept.
    fn set_resource_directory(&mut self, _directory: Option<std::path::PathBuf>) {}

    /// fmi2GetRealOutputDerivatives, fmi3GetOutputDerivatives; by default none are provided.
    fn get_real_output_derivatives(
        &mut self,
        _cx: &Context<Self::Inputs>,
        _vars: &[Var<Self::Vr>],
        _order: &[i32],
        _value: &mut [f64],
    ) -> Result<(), FmuError> {
        Err(FmuError::Invalid(
            "output derivatives are not provided (maxOutputDerivativeOrder = 0)".into(),
        ))
    }

    /// ∂y/∂u: the partial derivatives of the Real outputs `unknowns` with respect to the Real
    /// input `known` at the current point (one column of the Jacobian that
    /// fmi2GetDirectionalDerivative multiplies); both are already checked to be an output and
    /// an input. By default none are provided.
    fn output_sensitivity(
        &mut self,
        _cx: &Context<Self::Inputs>,
        _known: Var<Self::Vr>,
        _unknowns: &[Var<Self::Vr>],
        _column: &mut [f64],
    ) -> Result<(), FmuError> {
        Err(FmuError::Invalid(
            "directional derivatives are not provided (providesDirectionalDerivative = false)"
                .into(),
        ))
    }

    /// Appends the model's complete state (pointer-free) to `out`.
    fn save(&self, out: &mut Vec<u8>);

    /// Parses and checks bytes written by [`Model::save`] and, if `apply`, resumes from them, in
    /// the context (experiment, clock, inputs) restored with them. Nothing changes when they are
    /// rejected.
    fn load(
        &mut self,
        cx: &Context<Self::Inputs>,
        bytes: &[u8],
        apply: bool,
    ) -> Result<(), FmuError>;
}

/// The refusal of input derivatives by a model that takes none.
pub fn no_input_derivatives() -> FmuError {
    FmuError::Invalid("input derivatives are not supported (canInterpolateInputs = false)".into())
}

/// A variable of a model's table, as the callbacks receive it.
pub type Var<V> = &'static Variable<V>;

/// An error for a non-empty set request on variables of a type the model has none settable of
/// (by their causality, [`crate::checks::check_settable`] refuses them before this is called).
pub fn not_settable<V>(vars: &[Var<V>]) -> Result<(), FmuError> {
    match vars.first() {
        Some(v) => Err(FmuError::Invalid(format!("{} cannot be set", v.name))),
        None => Ok(()),
    }
}
