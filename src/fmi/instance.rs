//! [`SliderCrankFmu`]: the slider-crank as an FMI 2.0 [`Model`] — parameters, inputs, the
//! simulation and the clock; the state machine, the C functions and every value check (against
//! the variable table, so every message quotes what the master sees in the XML) come from
//! `fmi-export`. Values are read and written by an exhaustive `match` on [`Vr`].

use fmi_export::interface::Fmi3Interface;
use fmi_export::model::{Context, Var};
use fmi_export::table::Enumeration;
use fmi_export::{FmuError, Model, State, Step, StepOutcome};

use super::outputs::{count_output, real_output, section_array, sensitivity};
use super::snapshot::FmuSnapshot;
use crate::error::{ModelError, Num};
use crate::params::{
    Parameters, integer_parameter, real_parameter, set_integer_parameter, set_real_parameter,
    set_string_parameter, string_parameter,
};
use crate::simulation::{Engine, Input, Inputs, Outputs};
use crate::variables::{Causality, ENUMERATIONS, Kind, LOG_CATEGORIES, VARIABLES, Variable, Vr};

impl From<ModelError> for FmuError {
    fn from(e: ModelError) -> Self {
        Self::Model(e.to_string())
    }
}

/// The model input of the input variable `v` (the generic layer has checked that it is one).
fn input_of(v: Var<Vr>) -> Result<Input, FmuError> {
    match v.vr {
        Vr::DriveSpeed => Ok(Input::DriveSpeed),
        Vr::DriveTorque => Ok(Input::DriveTorque),
        Vr::SliderForce => Ok(Input::SliderForce),
        Vr::OilSupplyTemperature => Ok(Input::OilSupplyTemperature),
        Vr::OilSupplyPressure => Ok(Input::OilSupplyPressure),
        _ => Err(FmuError::Invalid(format!("{} is not an input", v.name))),
    }
}

/// What the instance holds for the slider-crank: the master's logger, the inputs, the experiment
/// and the current point (on the clock grid), where the engine is.
pub(super) type Cx<'a> = Context<'a, Inputs>;

/// The slider-crank behind the FMI functions: parameters and the simulation engine (the inputs,
/// the experiment and the clock are the generic layer's, [`Context`]).
#[derive(Debug)]
pub struct SliderCrankFmu {
    pub(crate) parameters: Parameters,
    pub(crate) simulation: Option<Engine>,
}

impl SliderCrankFmu {
    /// The simulation engine, built from the current parameters at the current point if needed;
    /// until it runs, its start follows the inputs (it is built again in equilibrium with inputs
    /// that changed).
    pub(super) fn simulation(&mut self, cx: &Cx) -> Result<&mut Engine, FmuError> {
        let inputs = cx.inputs.stepping().value;
        if self
            .simulation
            .as_ref()
            .is_some_and(|sim| sim.start_differs(&inputs))
        {
            self.simulation = None;
        }
        if self.simulation.is_none() {
            let log = cx.log;
            let parameters = model_parameters(&self.parameters, cx.experiment.tolerance);
            if parameters.relative_tolerance != self.parameters.relative_tolerance {
                log.event(&format!(
                    "solver.relativeTolerance = {} tightened to {} by the tolerance of \
                     fmi2SetupExperiment",
                    Num(self.parameters.relative_tolerance),
                    Num(parameters.relative_tolerance)
                ));
            }
            let integrated = parameters.integration_tolerance();
            if integrated != parameters.relative_tolerance {
                log.event(&format!(
                    "integrated at rtol {} (solver.relativeTolerance = {}): the largest with \
                     mainBearing.model = dry",
                    Num(integrated),
                    Num(parameters.relative_tolerance)
                ));
            }
            let mut sim = Engine::new(parameters, inputs, cx.time)?;
            log.event(&format!(
                "model built: {:?} rod, {:?} joint, {:?} drive, {} states",
                self.parameters.rod_formulation,
                self.parameters.joint.model,
                self.parameters.drive_mode,
                sim.state().len()
            ));
            for warning in sim.take_warnings() {
                log.warning(&warning);
            }
            self.simulation = Some(sim);
        }
        self.simulation
            .as_mut()
            .ok_or_else(|| FmuError::Invalid("no simulation".into()))
    }

    /// The outputs at the current point, with the inputs as outputs read them there.
    fn outputs(&mut self, cx: &Cx) -> Result<Outputs, FmuError> {
        Ok(self.simulation(cx)?.outputs(cx.time, cx.inputs.reading())?)
    }
}

impl Model for SliderCrankFmu {
    const GUID: &'static str = super::model_description::GUID;
    const LOG_CATEGORIES: &'static [(&'static str, &'static str)] = LOG_CATEGORIES;
    const STATE_MAGIC: [u8; 4] = *b"FSCS";
    const STATE_VERSION: u32 = 21;
    type Vr = Vr;
    type Inputs = Inputs;
    const VARIABLES: &'static [Variable] = VARIABLES;
    const ENUMERATIONS: &'static [Enumeration] = ENUMERATIONS;
    const MAX_INPUT_DERIVATIVE_ORDER: u32 =
        crate::variables::DESCRIPTION.max_input_derivative_order;
    const FMI3: Fmi3Interface = crate::variables::FMI3;
    const FMI3_TOKENS: [&'static str; 2] = [
        super::model_description::FMI3_TOKEN,
        super::model_description::FMI3_SCALAR_TOKEN,
    ];

    fn new() -> Self {
        Self {
            parameters: Parameters::default(),
            simulation: None,
        }
    }

    /// ∂y/∂u at the current state ([`super::outputs::sensitivity`]).
    fn output_sensitivity(
        &mut self,
        cx: &Cx,
        known: Var<Vr>,
        unknowns: &[Var<Vr>],
        column: &mut [f64],
    ) -> Result<(), FmuError> {
        let i = input_of(known)?;
        sensitivity(self.simulation(cx)?, cx, i, unknowns, column)
    }

    fn save(&self, out: &mut Vec<u8>) {
        self.snapshot().write(out);
    }

    fn load(&mut self, cx: &Cx, bytes: &[u8], apply: bool) -> Result<(), FmuError> {
        let mut snapshot = FmuSnapshot::read(bytes)?;
        // A load table is looked up where this instance's resources are.
        snapshot.parameters.resource_directory = self.parameters.resource_directory.clone();
        snapshot.validate()?;
        if apply {
            self.restore(cx, &snapshot)?;
        }
        Ok(())
    }

    /// fmi2ExitInitializationMode: builds the model (all parameter checks happen here).
    fn exit_initialization(&mut self, cx: &Cx) -> Result<(), FmuError> {
        self.simulation(cx)?;
        Ok(())
    }

    /// fmi2DoStep and fmi3DoStep: with `early_return`, the step stops
    /// at the end of the first internal step in which a joint comes into contact
    /// ([`crate::Simulation::advance_to_onset`]); with `pause`, it pauses after every internal
    /// step before its end ([`crate::Simulation::advance_pausing`]).
    fn do_step(&mut self, cx: &Cx, step: &Step) -> Result<StepOutcome, FmuError> {
        self.step(cx, step)
    }

    fn return_at_pause(&mut self, cx: &Cx) -> Result<Option<f64>, FmuError> {
        self.end_at_pause(cx)
    }

    fn get_array(&mut self, cx: &Cx, array: usize, value: &mut [f64]) -> Result<(), FmuError> {
        let rod_length = self.parameters.rod.length;
        section_array(array, value, rod_length, cx, || self.simulation(cx))
    }

    /// fmi2GetReal.
    fn get_real(&mut self, cx: &Cx, vars: &[Var<Vr>], values: &mut [f64]) -> Result<(), FmuError> {
        let mut outputs: Option<Outputs> = None;
        for (&v, value) in vars.iter().zip(values.iter_mut()) {
            if v.causality == Causality::Output {
                let o = match &outputs {
                    Some(o) => o,
                    None => outputs.insert(self.outputs(cx)?),
                };
                *value = real_output(o, v.vr).map_or_else(|| unreachable_type(v), Ok)?;
                continue;
            }
            let p = &self.parameters;
            if let Some(x) = real_parameter(p, v.vr) {
                *value = x;
                continue;
            }
            *value = match v.vr {
                Vr::JointContactStiffness => Engine::contact_stiffness(p),
                Vr::SolverIntegrationTolerance => {
                    model_parameters(p, cx.experiment.tolerance).integration_tolerance()
                }
                Vr::DriveSpeed => cx.inputs.reading().value.drive_speed,
                Vr::DriveTorque => cx.inputs.reading().value.drive_torque,
                Vr::SliderForce => cx.inputs.reading().value.slider_force,
                Vr::OilSupplyTemperature => cx.inputs.reading().value.oil_supply_temperature,
                Vr::OilSupplyPressure => cx.inputs.reading().value.oil_supply_pressure,
                _ => unreachable_type(v)?,
            };
        }
        Ok(())
    }

    /// fmi2SetReal of the Real parameters (the inputs are the generic layer's).
    fn set_real(
        &mut self,
        _state: State,
        vars: &[Var<Vr>],
        values: &[f64],
    ) -> Result<(), FmuError> {
        for (&v, &value) in vars.iter().zip(values) {
            if !set_real_parameter(&mut self.parameters, v.vr, value) {
                return unreachable_type(v);
            }
            // A parameter changed: the model is rebuilt when next needed.
            self.simulation = None;
        }
        Ok(())
    }

    /// fmi2GetRealOutputDerivatives: time derivatives of the kinematic outputs at the current
    /// communication point, from the equations of motion (order 1: crank.angle, crank.speed,
    /// slider.position, slider.velocity, joint.eccentricityX/Y, energy.driveWork; order 2:
    /// crank.angle, slider.position). Other outputs (forces, peaks, counters) have none.
    fn get_real_output_derivatives(
        &mut self,
        cx: &Cx,
        vars: &[Var<Vr>],
        orders: &[i32],
        values: &mut [f64],
    ) -> Result<(), FmuError> {
        let o = self.outputs(cx)?;
        for ((&v, &order), value) in vars.iter().zip(orders).zip(values.iter_mut()) {
            *value = match (v.vr, order) {
                (Vr::CrankAngle, 1) => o.crank_speed,
                (Vr::CrankAngle, 2) | (Vr::CrankSpeed, 1) => o.crank_acceleration,
                (Vr::SliderPosition, 1) => o.slider_velocity,
                (Vr::SliderPosition, 2) | (Vr::SliderVelocity, 1) => o.slider_acceleration,
                (Vr::JointEccentricityX, 1) => o.eccentricity_rate_x,
                (Vr::JointEccentricityY, 1) => o.eccentricity_rate_y,
                (Vr::EnergyDriveWork, 1) => o.crank_torque * o.crank_speed,
                _ => {
                    return Err(FmuError::Invalid(format!(
                        "{} has no derivative of order {order} \
                         (derivatives exist of order 1 for crank.angle, crank.speed, \
                         slider.position, slider.velocity, joint.eccentricityX/Y and \
                         energy.driveWork, of order 2 for crank.angle and slider.position)",
                        v.name
                    )));
                }
            };
        }
        Ok(())
    }

    /// fmi2GetInteger (Integer variables, the switches among them).
    fn get_integer(
        &mut self,
        cx: &Cx,
        vars: &[Var<Vr>],
        values: &mut [i32],
    ) -> Result<(), FmuError> {
        for (&v, value) in vars.iter().zip(values.iter_mut()) {
            if let Some(x) = integer_parameter(&self.parameters, v.vr) {
                *value = x;
                continue;
            }
            *value = match v.vr {
                Vr::SolverSteps => {
                    let steps = self.simulation(cx)?.stats().steps;
                    i32::try_from(steps).unwrap_or(i32::MAX)
                }
                Vr::SolverEvaluations => {
                    let evaluations = self.simulation(cx)?.stats().evaluations;
                    i32::try_from(evaluations).unwrap_or(i32::MAX)
                }
                vr => match count_output(&self.outputs(cx)?, vr) {
                    Some(count) => i32::try_from(count).unwrap_or(i32::MAX),
                    None => unreachable_type(v)?,
                },
            };
        }
        Ok(())
    }

    /// fmi2SetInteger (Integer parameters, the switches among them).
    fn set_integer(
        &mut self,
        _state: State,
        vars: &[Var<Vr>],
        values: &[i32],
    ) -> Result<(), FmuError> {
        for (&v, &value) in vars.iter().zip(values) {
            if !set_integer_parameter(&mut self.parameters, v.vr, value) {
                return unreachable_type(v);
            }
            self.simulation = None;
        }
        Ok(())
    }

    /// fmi2GetString (slider.forceTable).
    fn get_string(&mut self, vars: &[Var<Vr>], value: &mut Vec<String>) -> Result<(), FmuError> {
        for &v in vars {
            match string_parameter(&self.parameters, v.vr) {
                Some(text) => value.push(text.to_string()),
                None => return unreachable_type(v),
            }
        }
        Ok(())
    }

    /// fmi2SetString (slider.forceTable); the file is read when the model is built.
    fn set_string(
        &mut self,
        _state: State,
        vars: &[Var<Vr>],
        values: &[&str],
    ) -> Result<(), FmuError> {
        for (&v, &value) in vars.iter().zip(values) {
            if !set_string_parameter(&mut self.parameters, v.vr, value) {
                return unreachable_type(v);
            }
            self.simulation = None;
        }
        Ok(())
    }

    /// The FMU's resources, where a relative slider.forceTable is looked up after the working
    /// directory.
    fn set_resource_directory(&mut self, directory: Option<std::path::PathBuf>) {
        self.parameters.resource_directory = directory;
    }

    /// fmi2GetBoolean.
    fn get_boolean(
        &mut self,
        cx: &Cx,
        vars: &[Var<Vr>],
        values: &mut [i32],
    ) -> Result<(), FmuError> {
        for (&v, value) in vars.iter().zip(values.iter_mut()) {
            *value = match v.vr {
                Vr::JointInContact => i32::from(self.outputs(cx)?.in_contact),
                Vr::CrankPinInContact => i32::from(self.outputs(cx)?.crank_pin_in_contact),
                Vr::MainBearingInContact => i32::from(self.outputs(cx)?.main_bearing_in_contact),
                _ => unreachable_type(v)?,
            };
        }
        Ok(())
    }
}

/// The parameters a model is built with: `parameters` with `solver.relativeTolerance` tightened
/// to the master's fmi2SetupExperiment `tolerance` where that is smaller. The master's tolerance
/// never loosens the integration, and it counts only down to the smallest accepted
/// `solver.relativeTolerance`.
pub fn model_parameters(parameters: &Parameters, tolerance: Option<f64>) -> Parameters {
    let mut p = parameters.clone();
    if let Some(tolerance) = tolerance {
        let floor = match VARIABLES[Vr::SolverRelativeTolerance as usize].kind {
            Kind::Real { min, .. } => min,
            _ => 0.0,
        };
        p.relative_tolerance = p.relative_tolerance.min(tolerance.max(floor));
    }
    p
}

/// A value reference whose type was already checked cannot reach the wrong arm.
fn unreachable_type<T>(v: &Variable) -> Result<T, FmuError> {
    Err(FmuError::Invalid(format!(
        "variable {} has no value of this type",
        v.name
    )))
}

#[cfg(test)]
mod tests {
    use super::*;
    use fmi_export::signal::InputValues;

    /// Every start value in the XML is bit-identical to the library default, so a master that
    /// applies all start values runs exactly the model of `Parameters::default()`.
    #[test]
    fn table_start_values_equal_the_library_defaults() {
        let p = Parameters::default();
        let start = |vr: Vr| match VARIABLES[vr as usize].kind {
            Kind::Real { start: Some(s), .. } => s,
            _ => 0.0,
        };
        let inputs = Inputs {
            drive_speed: start(Vr::DriveSpeed),
            ..Inputs::default()
        };
        assert_eq!(
            inputs.drive_speed.to_bits(),
            p.start_speed(inputs.drive_speed).to_bits()
        );
        assert_eq!(
            real_parameter(&p, Vr::CrankInitialSpeed).map(f64::to_bits),
            Some(inputs.drive_speed.to_bits())
        );
        for v in VARIABLES
            .iter()
            .filter(|v| v.causality == Causality::Parameter)
        {
            match v.kind {
                Kind::Real { start: Some(s), .. } => {
                    let default = real_parameter(&p, v.vr).unwrap();
                    assert_eq!(
                        s.to_bits(),
                        default.to_bits(),
                        "{}: {s} vs {default}",
                        v.name
                    );
                }
                Kind::Integer { start: Some(s), .. } | Kind::Enumeration { start: s, .. } => {
                    assert_eq!(Some(s), integer_parameter(&p, v.vr), "{}", v.name);
                }
                Kind::String { start } => {
                    assert_eq!(Some(start), string_parameter(&p, v.vr), "{}", v.name);
                }
                _ => panic!("{} has no start value", v.name),
            }
        }
    }

    /// The generic layer holds the inputs by their index among the input variables: that order
    /// is the model's (`Input::ALL`, the fields of `Inputs`).
    #[test]
    fn the_input_variables_are_the_models_inputs_in_order() {
        let inputs: Vec<&Variable> = VARIABLES
            .iter()
            .filter(|v| v.causality == Causality::Input)
            .collect();
        assert_eq!(inputs.len(), <Inputs as InputValues>::LEN);
        for (k, v) in inputs.into_iter().enumerate() {
            assert_eq!(input_of(v).unwrap(), Input::ALL[k], "{}", v.name);
        }
    }

    /// Setting then getting every parameter round-trips through the same mapping.
    #[test]
    fn every_parameter_round_trips() {
        let mut p = Parameters::default();
        for v in VARIABLES
            .iter()
            .filter(|v| v.causality == Causality::Parameter)
        {
            match v.kind {
                Kind::Real { max, .. } => {
                    assert!(set_real_parameter(&mut p, v.vr, max));
                    assert_eq!(real_parameter(&p, v.vr), Some(max), "{}", v.name);
                }
                Kind::Enumeration { type_index, .. } => {
                    let n = ENUMERATIONS[type_index].items.len() as i32;
                    assert!(set_integer_parameter(&mut p, v.vr, n));
                    assert_eq!(integer_parameter(&p, v.vr), Some(n), "{}", v.name);
                    assert!(!set_integer_parameter(&mut p, v.vr, n + 1));
                    // A restored state's integers are not range-checked before this: any i32
                    // must be refused without overflow (a case the fuzzer found).
                    for bad in [0, -1, i32::MIN, i32::MAX] {
                        assert!(!set_integer_parameter(&mut p, v.vr, bad), "{}", v.name);
                    }
                }
                Kind::Integer { max, .. } => {
                    assert!(set_integer_parameter(&mut p, v.vr, max));
                    assert_eq!(integer_parameter(&p, v.vr), Some(max), "{}", v.name);
                }
                Kind::String { .. } => {
                    assert!(set_string_parameter(&mut p, v.vr, "a/b c.csv"));
                    assert_eq!(string_parameter(&p, v.vr), Some("a/b c.csv"), "{}", v.name);
                }
                Kind::Boolean => panic!("{} is a Boolean parameter", v.name),
            }
        }
    }
}
