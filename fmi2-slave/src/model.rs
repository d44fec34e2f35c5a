//! [`Model`]: what a model supplies; [`Instance`]: one FMU instance of it — the model, the
//! master's logger and the state machine — and the framing of its serialized states.

use crate::error::FmuError;
use crate::logger::Logger;
use crate::number::Num;
use crate::state::State;
use crate::table::{Causality, Enumeration, Kind, ValueReference, Variable};

/// A co-simulation model behind the FMI functions. The generic layer resolves every value
/// reference to the model's [`Variable`] before a getter or setter sees it ([`resolve`]: it
/// exists and has the function's type) and checks that a value to set is settable in the current
/// state and inside its declared range ([`check_set_real`], [`check_set_integer`],
/// [`check_set_boolean`]): the callbacks receive typed, checked variables ([`Var`]) and only
/// dispatch. Every method that may need to log gets the instance's logger.
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
    /// The model's variable table, in value-reference order (the generic checks read it).
    const VARIABLES: &'static [Variable<Self::Vr>];
    /// The switch types its enumeration variables refer to.
    const ENUMERATIONS: &'static [Enumeration] = &[];
    /// The highest order of input derivatives it takes (0: canInterpolateInputs = false).
    const MAX_INPUT_DERIVATIVE_ORDER: u32 = 0;

    /// A model with every start value (fmi2Instantiate, fmi2Reset).
    fn new() -> Self;

    /// fmi2SetupExperiment.
    fn setup_experiment(
        &mut self,
        log: &Logger,
        tolerance: Option<f64>,
        start: f64,
        stop: Option<f64>,
    ) -> Result<(), FmuError>;

    /// fmi2ExitInitializationMode: every parameter check happens here at the latest.
    fn exit_initialization(&mut self, log: &Logger) -> Result<(), FmuError>;

    /// fmi2DoStep from `t` over `h`; [`FmuError::Discard`] if the step stopped early.
    fn do_step(&mut self, log: &Logger, t: f64, h: f64) -> Result<(), FmuError>;

    /// The time up to which the last step succeeded (fmi2LastSuccessfulTime).
    fn last_successful_time(&self) -> f64;

    /// fmi2GetReal.
    fn get_real(
        &mut self,
        log: &Logger,
        vars: &[Var<Self::Vr>],
        value: &mut [f64],
    ) -> Result<(), FmuError>;

    /// fmi2SetReal in machine state `state`.
    fn set_real(
        &mut self,
        state: State,
        vars: &[Var<Self::Vr>],
        value: &[f64],
    ) -> Result<(), FmuError>;

    /// fmi2GetInteger.
    fn get_integer(
        &mut self,
        log: &Logger,
        vars: &[Var<Self::Vr>],
        value: &mut [i32],
    ) -> Result<(), FmuError>;

    /// fmi2SetInteger in machine state `state`: by default no Integer variable is settable.
    fn set_integer(
        &mut self,
        _state: State,
        vars: &[Var<Self::Vr>],
        _value: &[i32],
    ) -> Result<(), FmuError> {
        not_settable(vars)
    }

    /// fmi2GetBoolean: a model with Boolean variables reads them here (by default it has none,
    /// and [`resolve`] refuses every value reference before this is called).
    fn get_boolean(
        &mut self,
        _log: &Logger,
        vars: &[Var<Self::Vr>],
        _value: &mut [i32],
    ) -> Result<(), FmuError> {
        match vars.first() {
            Some(v) => Err(FmuError::Invalid(format!("{} cannot be read", v.name))),
            None => Ok(()),
        }
    }

    /// fmi2SetBoolean: by default no Boolean variable is settable.
    fn set_boolean(
        &mut self,
        _state: State,
        vars: &[Var<Self::Vr>],
        _value: &[i32],
    ) -> Result<(), FmuError> {
        not_settable(vars)
    }

    /// fmi2SetRealInputDerivatives, the arguments checked ([`check_input_derivatives`]); called
    /// only for a model with [`Model::MAX_INPUT_DERIVATIVE_ORDER`] > 0 (the generic layer refuses
    /// the call otherwise), which implements it.
    fn set_real_input_derivatives(
        &mut self,
        _vars: &[Var<Self::Vr>],
        _order: &[i32],
        _value: &[f64],
    ) -> Result<(), FmuError> {
        Err(no_input_derivatives())
    }

    /// fmi2GetRealOutputDerivatives; by default none are provided.
    fn get_real_output_derivatives(
        &mut self,
        _log: &Logger,
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
        _log: &Logger,
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

    /// Parses and checks bytes written by [`Model::save`] and, if `apply`, resumes from them.
    /// Nothing changes when they are rejected.
    fn load(&mut self, log: &Logger, bytes: &[u8], apply: bool) -> Result<(), FmuError>;
}

/// The refusal of input derivatives by a model that takes none.
pub fn no_input_derivatives() -> FmuError {
    FmuError::Invalid("input derivatives are not supported (canInterpolateInputs = false)".into())
}

/// A variable of a model's table, as the callbacks receive it.
pub type Var<V> = &'static Variable<V>;

/// An error for a non-empty set request on variables of a type the model has none settable of
/// (by their causality, [`check_settable`] refuses them before this is called).
pub fn not_settable<V>(vars: &[Var<V>]) -> Result<(), FmuError> {
    match vars.first() {
        Some(v) => Err(FmuError::Invalid(format!("{} cannot be set", v.name))),
        None => Ok(()),
    }
}

/// The variable of value reference `vr` in `table`, if it exists and is of FMI type `base`
/// ("Real", "Integer" — switches included — or "Boolean").
pub fn lookup<V: ValueReference>(
    table: &'static [Variable<V>],
    vr: u32,
    base: &str,
) -> Result<&'static Variable<V>, FmuError> {
    let v = table
        .get(vr as usize)
        .ok_or_else(|| FmuError::Invalid(format!("unknown value reference {vr}")))?;
    let matches = matches!(
        (v.kind, base),
        (Kind::Real { .. }, "Real")
            | (Kind::Integer { .. } | Kind::Enumeration { .. }, "Integer")
            | (Kind::Boolean, "Boolean")
    );
    if matches {
        Ok(v)
    } else {
        Err(FmuError::Invalid(format!(
            "value reference {vr} ({}) is not of type {base}",
            v.name
        )))
    }
}

/// Checks that `v` may be set in machine state `state`: parameters until initialization ends,
/// inputs always, nothing else.
pub fn check_settable<V>(state: State, v: &Variable<V>) -> Result<(), FmuError> {
    let ok = match v.causality {
        Causality::Parameter => {
            matches!(state, State::Instantiated | State::InitializationMode)
        }
        Causality::Input => true,
        _ => false,
    };
    if ok {
        Ok(())
    } else {
        Err(FmuError::Invalid(format!(
            "variable {} ({:?}) cannot be set in state {state:?}",
            v.name, v.causality
        )))
    }
}

/// Checks a Real value against the declared range of `v` (finite, within [min, max]).
pub fn check_real<V>(v: &Variable<V>, value: f64) -> Result<(), FmuError> {
    if let Kind::Real { min, max, unit, .. } = v.kind {
        if !(value.is_finite() && min <= value && value <= max) {
            return Err(FmuError::Invalid(format!(
                "{} = {} is outside the allowed range [{}, {}] {unit}",
                v.name,
                Num(value),
                Num(min),
                Num(max)
            )));
        }
    }
    Ok(())
}

/// Resolves each of `vrs` to its variable of `M`, which must be of FMI type `base`, into `out`
/// (cleared first; its capacity is reused, so that a call allocates only when it names more
/// variables than any call before).
pub fn resolve<M: Model>(
    vrs: &[u32],
    base: &str,
    out: &mut Vec<Var<M::Vr>>,
) -> Result<(), FmuError> {
    out.clear();
    for &vr in vrs {
        out.push(lookup(M::VARIABLES, vr, base)?);
    }
    Ok(())
}

/// Checks that each of the Real variables `vars` is settable in `state` and its value inside the
/// declared range.
pub fn check_set_real<V>(state: State, vars: &[Var<V>], values: &[f64]) -> Result<(), FmuError> {
    for (v, &value) in vars.iter().zip(values) {
        check_settable(state, v)?;
        check_real(v, value)?;
    }
    Ok(())
}

/// Checks that each of the Integer variables `vars` of `M` (switches among them) is settable in
/// `state`, its value inside the declared range or one of the switch's items.
pub fn check_set_integer<M: Model>(
    state: State,
    vars: &[Var<M::Vr>],
    values: &[i32],
) -> Result<(), FmuError> {
    for (v, &value) in vars.iter().zip(values) {
        check_settable(state, v)?;
        let (min, max) = match v.kind {
            Kind::Integer { min, max, .. } => (min, max),
            Kind::Enumeration { type_index, .. } => {
                let items = M::ENUMERATIONS.get(type_index).map_or(0, |e| e.items.len());
                (1, i32::try_from(items).unwrap_or(i32::MAX))
            }
            _ => (0, -1),
        };
        if !(min..=max).contains(&value) {
            return Err(FmuError::Invalid(format!(
                "{} = {value} is outside the allowed range [{min}, {max}]",
                v.name
            )));
        }
    }
    Ok(())
}

/// Checks fmi2SetRealInputDerivatives' arguments: each of `vrs` a Real input of `M` (resolved
/// into `out`, as by [`resolve`]), each order from 1 to [`Model::MAX_INPUT_DERIVATIVE_ORDER`],
/// each value finite.
pub fn check_input_derivatives<M: Model>(
    vrs: &[u32],
    orders: &[i32],
    values: &[f64],
    out: &mut Vec<Var<M::Vr>>,
) -> Result<(), FmuError> {
    let max = M::MAX_INPUT_DERIVATIVE_ORDER;
    out.clear();
    for ((&vr, &order), &value) in vrs.iter().zip(orders).zip(values) {
        let v = check_causality::<M>(vr, Causality::Input, "vr")?;
        out.push(v);
        let order_ok = u32::try_from(order).is_ok_and(|o| (1..=max).contains(&o));
        if !order_ok || !value.is_finite() {
            return Err(FmuError::Invalid(format!(
                "derivative of order {order} of {} = {}: the order must be 1 to {max} and the \
                 value finite",
                v.name,
                Num(value)
            )));
        }
    }
    Ok(())
}

/// The Real variable `vr` of `M` if it has `causality`; else an error naming the argument `arg`.
pub fn check_causality<M: Model>(
    vr: u32,
    causality: Causality,
    arg: &str,
) -> Result<&'static Variable<M::Vr>, FmuError> {
    let v = lookup(M::VARIABLES, vr, "Real")?;
    if v.causality == causality {
        Ok(v)
    } else {
        Err(FmuError::Invalid(format!(
            "{arg}: value reference {vr} ({}) is not a Real {}",
            v.name,
            format!("{causality:?}").to_lowercase()
        )))
    }
}

/// Checks that each of the Boolean variables `vars` is settable in `state`.
pub fn check_set_boolean<V>(state: State, vars: &[Var<V>]) -> Result<(), FmuError> {
    for v in vars {
        check_settable(state, v)?;
    }
    Ok(())
}

/// Tolerance on the communication point: |t − t_expected| ≤ 1e-9 (1 + |t|).
pub const TIME_TOLERANCE: f64 = 1e-9;

/// Checks fmi2DoStep's arguments against an instance at `time` with stop time `stop`: the
/// communication point is the current time (within [`TIME_TOLERANCE`]), the step is positive and
/// finite, and t + h is not past the stop time.
pub fn check_step(time: f64, t: f64, h: f64, stop: Option<f64>) -> Result<(), FmuError> {
    if (t - time).abs() > TIME_TOLERANCE * (1.0 + t.abs()) {
        return Err(FmuError::Invalid(format!(
            "expected currentCommunicationPoint = {} s but was {} s",
            Num(time),
            Num(t)
        )));
    }
    if !(h > 0.0 && h.is_finite()) {
        return Err(FmuError::Invalid(format!(
            "communicationStepSize must be > 0 and finite but was {} s",
            Num(h)
        )));
    }
    let end = t + h;
    match stop {
        Some(stop) if end > stop + TIME_TOLERANCE * (1.0 + stop.abs()) => {
            Err(FmuError::Invalid(format!(
                "currentCommunicationPoint + communicationStepSize = {} s is past stopTime = {} s",
                Num(end),
                Num(stop)
            )))
        }
        _ => Ok(()),
    }
}

/// One FMU instance.
#[derive(Debug)]
pub struct Instance<M: Model> {
    /// The master's logger.
    pub logger: Logger,
    /// State-machine state.
    pub state: State,
    /// Set after a caught panic: only Reset and FreeInstance are accepted.
    pub poisoned: bool,
    /// The message of the event that put the instance in the Error or StepFailed state (the
    /// first error, the discarded step), for the calls refused there.
    pub cause: Option<String>,
    /// The model.
    pub model: M,
    /// The variables of the current call, resolved from its value references ([`resolve`]).
    pub variables: Vec<Var<M::Vr>>,
}

/// The states in the order of their byte in a serialized state.
const STATES: [State; 6] = [
    State::Instantiated,
    State::InitializationMode,
    State::StepComplete,
    State::StepFailed,
    State::Terminated,
    State::Error,
];

/// The checksum that ends a serialized state: FNV-1a 64 of every byte before it.
pub fn state_checksum(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3)
    })
}

impl<M: Model> Instance<M> {
    /// A fresh instance with the start values.
    pub fn new(logger: Logger) -> Self {
        Self {
            logger,
            state: State::Instantiated,
            poisoned: false,
            cause: None,
            model: M::new(),
            variables: Vec::new(),
        }
    }

    /// fmi2Reset: back to Instantiated with every start value.
    pub fn reset(&mut self) {
        self.state = State::Instantiated;
        self.poisoned = false;
        self.cause = None;
        self.model = M::new();
    }

    /// The serialized state: magic, version, state machine, the model's bytes, and an FNV-1a 64
    /// checksum of everything before it (a corrupted byte is rejected, never restored).
    pub fn serialize(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(1024);
        out.extend_from_slice(&M::STATE_MAGIC);
        out.extend_from_slice(&M::STATE_VERSION.to_le_bytes());
        out.push(STATES.iter().position(|s| *s == self.state).unwrap_or(0) as u8);
        self.model.save(&mut out);
        let checksum = state_checksum(&out);
        out.extend_from_slice(&checksum.to_le_bytes());
        out
    }

    /// Checks a serialized state and, if `apply`, resumes from it (state machine included).
    pub fn deserialize(&mut self, bytes: &[u8], apply: bool) -> Result<(), FmuError> {
        let bad = |what: String| FmuError::Invalid(format!("FMU state rejected: {what}"));
        if bytes.len() < 4 + 4 + 1 + 8 {
            return Err(bad(format!("{} bytes is too short", bytes.len())));
        }
        let (body, tail) = bytes.split_at(bytes.len() - 8);
        let mut sum = [0; 8];
        sum.copy_from_slice(tail);
        if state_checksum(body) != u64::from_le_bytes(sum) {
            return Err(bad("checksum mismatch (corrupted bytes)".into()));
        }
        if body[..4] != M::STATE_MAGIC {
            return Err(bad("wrong magic (not a state of this FMU)".into()));
        }
        let mut version = [0; 4];
        version.copy_from_slice(&body[4..8]);
        let version = u32::from_le_bytes(version);
        if version != M::STATE_VERSION {
            return Err(bad(format!(
                "format version {version}, expected {}",
                M::STATE_VERSION
            )));
        }
        let state = *STATES
            .get(usize::from(body[8]))
            .ok_or_else(|| bad("invalid state".into()))?;
        self.model.load(&self.logger, &body[9..], apply)?;
        if apply {
            self.state = state;
        }
        Ok(())
    }
}
