//! [`Instance`]: one FMU instance of a [`Model`] — the model, the master's logger, the state
//! machine, the clock and the inputs — the calls every FMI version makes on it, and the framing of
//! its serialized states ([`framing`]).

pub mod framing;

use crate::checks::{check_set_all, check_set_integer, check_set_real, check_settable};
use crate::error::FmuError;
use crate::experiment::{Clock, Step, StepOutcome};
use crate::interface::Fmi3Interface;
use crate::logger::Logger;
use crate::model::{Context, Model, Var};
use crate::number::Num;
use crate::signal::{InputRecord, InputValues};
use crate::state::{Call, Machine, Succeeded, Version};
use crate::table::{Causality, Kind, ValueReference};
use std::ffi::CString;
use std::path::PathBuf;

/// The [`Context`] of an instance (a macro, so that the model may be borrowed mutably beside it).
macro_rules! context {
    ($inst:expr) => {
        Context {
            log: &$inst.logger,
            inputs: &$inst.inputs,
            experiment: $inst.clock.experiment,
            time: $inst.clock.now(),
        }
    };
}

/// One FMU instance. Its fields are its own: the exported functions reach them through its
/// methods, and its state only through its [`Machine`].
#[derive(Debug)]
pub struct Instance<M: Model> {
    /// The master's logger.
    logger: Logger,
    /// Its place in the state machine.
    machine: Machine,
    /// The model.
    model: M,
    /// The experiment and the communication clock.
    clock: Clock,
    /// The inputs: what the master set for the next step, and what the last step ran with.
    inputs: InputRecord<M::Inputs>,
    /// The variables of the current call, resolved from its value references ([`Instance::resolve`]).
    variables: Vec<Var<M::Vr>>,
    /// The String values GetString returned last: the master may read them until the next
    /// call on this instance.
    strings: Vec<CString>,
    /// Integers of the current call in the model's representation (FMI 3's Int64 switches and
    /// Booleans); its capacity is reused.
    integers: Vec<i32>,
    /// The FMU's resources directory, from the instantiation (given to every new model).
    resources: Option<PathBuf>,
    /// The FMI version it was instantiated through.
    version: Version,
    /// What FMI 3 adds.
    fmi3: Fmi3Session,
}

/// What an FMI 3 instance holds beyond FMI 2's: the interface of its description, its structural
/// parameters, and what the master chose at instantiation.
#[derive(Debug)]
pub struct Fmi3Session {
    /// The interface of the description the instance was instantiated with
    /// ([`Model::FMI3_TOKENS`]).
    pub interface: Fmi3Interface,
    /// The values of the model's structural parameters, set in Configuration Mode; they size
    /// its arrays.
    pub structural: Vec<u64>,
    /// Whether the master allows fmi3DoStep to return early (earlyReturnAllowed).
    pub early_return_allowed: bool,
    /// Whether the master handles the model's events in Event Mode (eventModeUsed).
    pub event_mode_used: bool,
    /// The master's intermediate-update callback and its environment, for a model that provides
    /// intermediate update.
    pub intermediate_update: Option<IntermediateUpdate>,
}

impl Fmi3Session {
    /// The session of `interface`: its structural parameters at their start values, nothing
    /// chosen.
    fn new(interface: Fmi3Interface) -> Self {
        Self {
            interface,
            structural: interface
                .structural_parameters
                .iter()
                .map(|p| p.start)
                .collect(),
            early_return_allowed: false,
            event_mode_used: false,
            intermediate_update: None,
        }
    }
}

/// The master's FMI 3 intermediate-update callback with the environment it is called with.
#[derive(Clone, Copy, Debug)]
pub struct IntermediateUpdate {
    /// The callback.
    pub callback: unsafe extern "C" fn(
        *mut std::ffi::c_void,
        f64,
        bool,
        bool,
        bool,
        bool,
        *mut bool,
        *mut f64,
    ),
    /// The master's instance environment.
    pub environment: *mut std::ffi::c_void,
}

impl<M: Model> Instance<M> {
    /// A fresh instance of FMI `version` with the start values, its model told the FMU's
    /// resources directory, serving the FMI 3 interface `fmi3`.
    pub fn new(
        logger: Logger,
        resources: Option<PathBuf>,
        version: Version,
        fmi3: Fmi3Interface,
    ) -> Self {
        let mut model = M::new();
        model.set_resource_directory(resources.clone());
        Self {
            logger,
            machine: Machine::default(),
            model,
            clock: Clock::default(),
            inputs: Self::start_inputs(),
            variables: Vec::new(),
            strings: Vec::new(),
            integers: Vec::new(),
            resources,
            version,
            fmi3: Fmi3Session::new(fmi3),
        }
    }

    /// The master's logger.
    pub fn logger(&self) -> &Logger {
        &self.logger
    }

    /// The master's logger, to switch its debug logging.
    pub fn logger_mut(&mut self) -> &mut Logger {
        &mut self.logger
    }

    /// Its place in the state machine.
    pub fn machine(&self) -> &Machine {
        &self.machine
    }

    /// The logger and the state machine, to record how a call ended.
    pub fn logger_and_machine(&mut self) -> (&Logger, &mut Machine) {
        (&self.logger, &mut self.machine)
    }

    /// `call` succeeded: the state it leads to ([`Machine::succeeded`]).
    pub fn succeeded(&mut self, call: Call) {
        let how = Succeeded {
            event_mode: self.fmi3.event_mode_used,
            paused: self.clock.is_paused(),
        };
        self.machine.succeeded(call, how);
    }

    /// The FMI version it was instantiated through.
    pub fn version(&self) -> Version {
        self.version
    }

    /// The experiment and the clock.
    pub fn clock(&self) -> &Clock {
        &self.clock
    }

    /// What FMI 3 adds.
    pub fn fmi3(&self) -> &Fmi3Session {
        &self.fmi3
    }

    /// What FMI 3 adds, to change (at instantiation, in Configuration Mode).
    pub fn fmi3_mut(&mut self) -> &mut Fmi3Session {
        &mut self.fmi3
    }

    /// Resolves `vrs` to the model's variables of FMI type `base`, the variables of the call
    /// ([`crate::checks::lookup`]).
    pub fn resolve(&mut self, vrs: &[u32], base: &str) -> Result<(), FmuError> {
        self.resolve_by(vrs, |vr| crate::checks::lookup(M::VARIABLES, vr, base))
    }

    /// Makes `variable(vr)` of each of `vrs` the variables of the call (the vector's capacity is
    /// reused, so that a call allocates only when it names more variables than any before).
    pub fn resolve_by(
        &mut self,
        vrs: &[u32],
        variable: impl Fn(u32) -> Result<Var<M::Vr>, FmuError>,
    ) -> Result<(), FmuError> {
        self.variables.clear();
        for &vr in vrs {
            self.variables.push(variable(vr)?);
        }
        Ok(())
    }

    /// The variables of the call.
    pub fn variables(&self) -> &[Var<M::Vr>] {
        &self.variables
    }

    /// Reset: back to Instantiated with every start value.
    pub fn reset(&mut self) {
        self.model = M::new();
        self.model.set_resource_directory(self.resources.clone());
        self.clock = Clock::default();
        self.inputs = Self::start_inputs();
        self.fmi3.structural = Fmi3Session::new(self.fmi3.interface).structural;
    }

    /// The model's input variables, in table order.
    fn input_variables() -> impl Iterator<Item = Var<M::Vr>> {
        M::VARIABLES
            .iter()
            .filter(|v| v.causality == Causality::Input)
    }

    /// The inputs at their start values, held from t = 0.
    fn start_inputs() -> InputRecord<M::Inputs> {
        let mut value = <M::Inputs as InputValues>::ZERO;
        for (k, v) in Self::input_variables().enumerate().take(M::Inputs::LEN) {
            if let Kind::Real { start: Some(s), .. } = v.kind {
                *value.value_mut(k) = s;
            }
        }
        InputRecord::held(value, 0.0)
    }

    /// The index of the input variable `v` among the model's inputs.
    fn input_index(v: Var<M::Vr>) -> Result<usize, FmuError> {
        let k = M::VARIABLES[..v.vr.index() as usize]
            .iter()
            .filter(|w| w.causality == Causality::Input)
            .count();
        if v.causality == Causality::Input && k < M::Inputs::LEN {
            Ok(k)
        } else {
            Err(FmuError::Invalid(format!("{} is not an input", v.name)))
        }
    }

    /// fmi2SetupExperiment, fmi3EnterInitializationMode: the experiment checked and set up, the
    /// clock at its start.
    pub fn setup_experiment(
        &mut self,
        experiment: (Option<f64>, f64, Option<f64>),
    ) -> Result<(), FmuError> {
        self.clock.setup(experiment)?;
        self.inputs.start_at(self.clock.now());
        Ok(())
    }

    /// ExitInitializationMode (the model's checks).
    pub fn exit_initialization(&mut self) -> Result<(), FmuError> {
        self.model.exit_initialization(&context!(self))
    }

    /// The step `step` checked against the clock ([`Clock::step`]); where it ends (completed,
    /// returned early or discarded, not paused) the inputs end their step there
    /// ([`InputRecord::end_step`]: input derivatives hold for one step).
    pub fn step(&mut self, step: Step) -> Result<StepOutcome, FmuError> {
        self.inputs.begin_step();
        let cx = context!(self);
        let model = &mut self.model;
        let outcome = self.clock.step(step, |s| model.do_step(&cx, s));
        if let Ok(StepOutcome::Completed { .. } | StepOutcome::ReturnedEarly { .. })
        | Err(FmuError::Discard { .. }) = &outcome
        {
            self.inputs.end_step(self.clock.now());
        }
        outcome
    }

    /// Ends a paused step at the pause ([`Model::return_at_pause`]): the time reached, or None
    /// (it stays paused).
    pub fn return_at_pause(&mut self) -> Result<Option<f64>, FmuError> {
        let reached = self.model.return_at_pause(&context!(self))?;
        self.clock.return_at_pause(reached);
        if reached.is_some() {
            self.inputs.end_step(self.clock.now());
        }
        Ok(reached)
    }

    /// GetReal, GetFloat64 of the variables of the call ([`Instance::variables`]).
    pub fn get_real(&mut self, value: &mut [f64]) -> Result<(), FmuError> {
        self.model.get_real(&context!(self), &self.variables, value)
    }

    /// SetReal, SetFloat64 of the variables of the call, checked first
    /// ([`crate::checks::check_set_real`]): the inputs kept here, the others set in the model.
    pub fn set_real(&mut self, value: &[f64]) -> Result<(), FmuError> {
        let current = self.machine.state();
        check_set_real(current, &self.variables, value)?;
        for (&v, &x) in self.variables.iter().zip(value) {
            if v.causality == Causality::Input {
                self.inputs.set_value(Self::input_index(v)?, x);
            } else {
                self.model.set_real(current, &[v], &[x])?;
            }
        }
        Ok(())
    }

    /// SetInteger (FMI 3: SetInt32) of the variables of the call, checked first
    /// ([`crate::checks::check_set_integer`]).
    pub fn set_integer(&mut self, value: &[i32]) -> Result<(), FmuError> {
        let current = self.machine.state();
        check_set_integer::<M>(current, &self.variables, value)?;
        self.model.set_integer(current, &self.variables, value)
    }

    /// FMI 3 SetInt64 and SetBoolean of the variables of the call: each value made the model's
    /// integer by `convert` (which refuses what it cannot be), then set as [`Instance::set_integer`]
    /// (`boolean`: as Booleans).
    pub fn set_converted<T: Copy>(
        &mut self,
        value: &[T],
        boolean: bool,
        convert: impl Fn(Var<M::Vr>, T) -> Result<i32, FmuError>,
    ) -> Result<(), FmuError> {
        let mut integers = std::mem::take(&mut self.integers);
        integers.clear();
        for (&v, &x) in self.variables.iter().zip(value) {
            integers.push(convert(v, x)?);
        }
        let set = if boolean {
            self.set_boolean(&integers)
        } else {
            self.set_integer(&integers)
        };
        self.integers = integers;
        set
    }

    /// SetBoolean of the variables of the call, checked first.
    pub fn set_boolean(&mut self, value: &[i32]) -> Result<(), FmuError> {
        let current = self.machine.state();
        check_set_all(current, &self.variables)?;
        self.model.set_boolean(current, &self.variables, value)
    }

    /// SetString of the variables of the call, checked first.
    pub fn set_string(&mut self, value: &[&str]) -> Result<(), FmuError> {
        let current = self.machine.state();
        check_set_all(current, &self.variables)?;
        self.model.set_string(current, &self.variables, value)
    }

    /// GetString of the variables of the call: the values, valid until the next call on the
    /// instance.
    pub fn get_string(&mut self) -> Result<&[CString], FmuError> {
        let mut texts = Vec::with_capacity(self.variables.len());
        self.model.get_string(&self.variables, &mut texts)?;
        self.strings = texts
            .into_iter()
            .map(|t| CString::new(t.replace('\0', "")).unwrap_or_default())
            .collect();
        Ok(&self.strings)
    }

    /// The model's FMI 3 integers of the call, converted by `convert` from the model's.
    pub fn get_converted<T>(
        &mut self,
        value: &mut [T],
        boolean: bool,
        convert: impl Fn(i32) -> T,
    ) -> Result<(), FmuError> {
        let mut integers = std::mem::take(&mut self.integers);
        integers.clear();
        integers.resize(value.len(), 0);
        let got = if boolean {
            self.get_boolean(&mut integers)
        } else {
            self.get_integer(&mut integers)
        };
        for (v, &n) in value.iter_mut().zip(&integers) {
            *v = convert(n);
        }
        self.integers = integers;
        got
    }

    /// Checks that the `order`-th derivative (1 or 2) of the `k`-th input may be set to `x` now:
    /// where its input may be set, finite.
    pub fn check_input_derivative(&self, k: usize, order: u32, x: f64) -> Result<(), FmuError> {
        let input = Self::input_variables()
            .nth(k)
            .ok_or_else(|| FmuError::Invalid(format!("no input {k}")))?;
        check_settable(self.machine.state(), input)?;
        if !x.is_finite() {
            return Err(FmuError::Invalid(format!(
                "the derivative of order {order} of {} = {} is not finite",
                input.name,
                Num(x)
            )));
        }
        Ok(())
    }

    /// Sets the `order`-th derivative (1 or 2) of the `k`-th input to `x` at the current point,
    /// for the next step (checked by [`Instance::check_input_derivative`]).
    pub fn set_input_derivative(&mut self, k: usize, order: u32, x: f64) -> Result<(), FmuError> {
        self.check_input_derivative(k, order, x)?;
        self.inputs
            .set_derivative(k, order as usize, x)
            .ok_or_else(|| FmuError::Invalid(format!("order {order}")))
    }

    /// The `order`-th derivative (1 or 2) of the `k`-th input as outputs read it now.
    pub fn input_derivative(&self, k: usize, order: u32) -> f64 {
        let reading = self.inputs.reading();
        reading.derivatives[order as usize - 1].value(k)
    }

    /// fmi2SetRealInputDerivatives of the inputs `vr`, checked first
    /// ([`crate::checks::check_input_derivatives`]): the `order`-th derivatives at the current
    /// communication point, for the next step.
    pub fn set_input_derivatives(
        &mut self,
        vr: &[u32],
        order: &[i32],
        value: &[f64],
    ) -> Result<(), FmuError> {
        crate::checks::check_input_derivatives::<M>(vr, order, value, &mut self.variables)?;
        for ((&v, &order), &x) in self.variables.iter().zip(order).zip(value) {
            let k = Self::input_index(v)?;
            usize::try_from(order)
                .ok()
                .and_then(|order| self.inputs.set_derivative(k, order, x))
                .ok_or_else(|| FmuError::Invalid(format!("order {order}")))?;
        }
        Ok(())
    }

    /// GetInteger (FMI 3: GetInt32, GetInt64) of the variables of the call.
    pub fn get_integer(&mut self, value: &mut [i32]) -> Result<(), FmuError> {
        self.model
            .get_integer(&context!(self), &self.variables, value)
    }

    /// GetBoolean of the variables of the call.
    pub fn get_boolean(&mut self, value: &mut [i32]) -> Result<(), FmuError> {
        self.model
            .get_boolean(&context!(self), &self.variables, value)
    }

    /// FMI 3: GetFloat64 of the array `array` ([`Model::get_array`]).
    pub fn get_array(&mut self, array: usize, value: &mut [f64]) -> Result<(), FmuError> {
        self.model.get_array(&context!(self), array, value)
    }

    /// The output derivatives of the variables of the call ([`Model::get_real_output_derivatives`]).
    pub fn get_output_derivatives(
        &mut self,
        order: &[i32],
        value: &mut [f64],
    ) -> Result<(), FmuError> {
        self.model
            .get_real_output_derivatives(&context!(self), &self.variables, order, value)
    }

    /// ∂y/∂u of the outputs of the call with respect to `known` ([`Model::output_sensitivity`]).
    pub fn output_sensitivity(
        &mut self,
        known: Var<M::Vr>,
        column: &mut [f64],
    ) -> Result<(), FmuError> {
        self.model
            .output_sensitivity(&context!(self), known, &self.variables, column)
    }
}
