//! Reference results: a model's experiment run through its [`Model`] interface the way a
//! fixed-step co-simulation master runs it, and written in the FMI project's convention for
//! compatibility information (`<model>_ref.csv`, `<model>_in.csv`, `<model>_ref.opt`), so that
//! any master's import of the FMU can be checked against them.
//!
//! [`Slave`] drives a model through the same checks as the exported functions. The run is that
//! of fmpy's `simulate_fmu`: fmi2SetupExperiment with the tolerance, start and
//! stop time, the inputs set in initialization mode and before every step, communication points
//! at start + n · step, every Real output recorded at each of them.

use std::fmt::Write as _;

use crate::error::FmuError;
use crate::experiment::Step;
use crate::instance::Instance;
use crate::logger::Logger;
use crate::model::{Model, Var};
use crate::state::{Call, Version};
use crate::table::{Causality, Kind, ValueReference};

/// A fixed-step experiment with constant inputs.
#[derive(Clone, Debug)]
pub struct Experiment {
    /// Start time \[s\].
    pub start: f64,
    /// Stop time \[s\].
    pub stop: f64,
    /// Communication step \[s\].
    pub step: f64,
    /// Relative tolerance passed to fmi2SetupExperiment.
    pub tolerance: f64,
    /// Inputs held at these values (name, value); the others keep their start values.
    pub inputs: Vec<(&'static str, f64)>,
}

/// A table over communication points: the names and, at every point, the time and the values
/// (a run's Real outputs, or an experiment's inputs).
#[derive(Clone, Debug, PartialEq)]
pub struct Results {
    /// Names of the columns.
    pub names: Vec<String>,
    /// Time and values at each communication point.
    pub rows: Vec<(f64, Vec<f64>)>,
}

/// One model driven by variable names, the way a master drives an FMU: an [`Instance`] with a
/// silent logger, called as the exported functions call it.
pub struct Slave<M: Model> {
    instance: Instance<M>,
}

impl<M: Model> Slave<M> {
    /// A new instance with every start value.
    pub fn new() -> Self {
        Self {
            instance: Instance::new(
                Logger::silent(M::LOG_CATEGORIES),
                None,
                Version::Fmi2,
                M::FMI3,
            ),
        }
    }

    /// The names of the model's Real outputs, in table order.
    pub fn real_outputs() -> Vec<&'static str> {
        M::VARIABLES
            .iter()
            .filter(|v| v.causality == Causality::Output && matches!(v.kind, Kind::Real { .. }))
            .map(|v| v.name)
            .collect()
    }

    fn variable(name: &str) -> Result<Var<M::Vr>, FmuError> {
        M::VARIABLES
            .iter()
            .find(|v| v.name == name)
            .ok_or_else(|| FmuError::Invalid(format!("no variable {name}")))
    }

    /// Makes the variables of `names` those of the next call, resolved as type `base`.
    fn call_on(&mut self, names: &[&str], base: &str) -> Result<(), FmuError> {
        let vrs = names
            .iter()
            .map(|name| Ok(Self::variable(name)?.vr.index()))
            .collect::<Result<Vec<_>, FmuError>>()?;
        self.instance.resolve(&vrs, base)
    }

    /// fmi2SetupExperiment.
    pub fn setup(
        &mut self,
        tolerance: Option<f64>,
        start: f64,
        stop: Option<f64>,
    ) -> Result<(), FmuError> {
        self.instance.setup_experiment((tolerance, start, stop))
    }

    /// fmi2EnterInitializationMode.
    pub fn enter_initialization(&mut self) {
        self.instance.succeeded(Call::EnterInitializationMode);
    }

    /// Sets a Real variable, or an Integer one to `value` (a whole number).
    pub fn set(&mut self, name: &str, value: f64) -> Result<(), FmuError> {
        match Self::variable(name)?.kind {
            Kind::Real { .. } => {
                self.call_on(&[name], "Real")?;
                self.instance.set_real(&[value])
            }
            _ => {
                let n = value as i32;
                if f64::from(n) != value {
                    return Err(FmuError::Invalid(format!(
                        "{name} = {value} is not a whole number"
                    )));
                }
                self.call_on(&[name], "Integer")?;
                self.instance.set_integer(&[n])
            }
        }
    }

    /// fmi2SetRealInputDerivatives of the input `name`: its first and second time derivatives at
    /// the current point, for the next step.
    pub fn set_derivatives(&mut self, name: &str, derivatives: [f64; 2]) -> Result<(), FmuError> {
        let vr = Self::variable(name)?.vr.index();
        self.instance
            .set_input_derivatives(&[vr, vr], &[1, 2], &derivatives)
    }

    /// Sets a String variable.
    pub fn set_string(&mut self, name: &str, value: &str) -> Result<(), FmuError> {
        self.call_on(&[name], "String")?;
        self.instance.set_string(&[value])
    }

    /// The values of the Real variables `names`.
    pub fn get(&mut self, names: &[&str]) -> Result<Vec<f64>, FmuError> {
        self.call_on(names, "Real")?;
        let mut values = vec![0.0; names.len()];
        self.instance.get_real(&mut values)?;
        Ok(values)
    }

    /// The names of the model's outputs of every type but String (Real, Integer, Boolean), in
    /// table order.
    pub fn outputs() -> Vec<&'static str> {
        M::VARIABLES
            .iter()
            .filter(|v| v.causality == Causality::Output && !matches!(v.kind, Kind::String { .. }))
            .map(|v| v.name)
            .collect()
    }

    /// The values of every output of [`Slave::outputs`], each read through the getter of its
    /// type (fmi2GetReal, fmi2GetInteger, fmi2GetBoolean); Integer and Boolean values are
    /// converted to f64 exactly.
    pub fn output_values(&mut self) -> Result<Vec<f64>, FmuError> {
        let mut values = Vec::new();
        for v in M::VARIABLES
            .iter()
            .filter(|v| v.causality == Causality::Output)
        {
            values.push(match v.kind {
                Kind::Real { .. } => self.get(&[v.name])?[0],
                Kind::Integer { .. } | Kind::Enumeration { .. } => {
                    let mut n = [0];
                    self.call_on(&[v.name], "Integer")?;
                    self.instance.get_integer(&mut n)?;
                    f64::from(n[0])
                }
                Kind::String { .. } => continue,
                Kind::Boolean => {
                    let mut b = [0];
                    self.call_on(&[v.name], "Boolean")?;
                    self.instance.get_boolean(&mut b)?;
                    f64::from(b[0])
                }
            });
        }
        Ok(values)
    }

    /// Each FMI 3 array of the model ([`Model::FMI3`]) with its values at the current point
    /// (fmi3GetFloat64 of the array), at the size its structural parameter's start value gives.
    pub fn array_values(&mut self) -> Result<Vec<(&'static str, Vec<f64>)>, FmuError> {
        let fmi3 = M::FMI3;
        fmi3.arrays
            .iter()
            .enumerate()
            .map(|(k, a)| {
                let n = fmi3.structural_parameters[a.dimension].start;
                let mut values = vec![0.0; usize::try_from(n).unwrap_or(0)];
                self.instance.get_array(k, &mut values)?;
                Ok((a.name, values))
            })
            .collect()
    }

    /// fmi2ExitInitializationMode.
    pub fn exit_initialization(&mut self) -> Result<(), FmuError> {
        self.instance.exit_initialization()?;
        self.instance.succeeded(Call::ExitInitializationMode);
        Ok(())
    }

    /// fmi2DoStep from `t` over `h`.
    pub fn step(&mut self, t: f64, h: f64) -> Result<(), FmuError> {
        let step = Step {
            t,
            h,
            early_return: false,
            pause: false,
            resume: false,
        };
        self.instance.step(step).map(|_| ())
    }
}

impl<M: Model> Default for Slave<M> {
    fn default() -> Self {
        Self::new()
    }
}

/// Runs `experiment` on a new instance of `M`.
pub fn run<M: Model>(experiment: &Experiment) -> Result<Results, FmuError> {
    let mut slave = Slave::<M>::new();
    let outputs = Slave::<M>::real_outputs();
    slave.setup(
        Some(experiment.tolerance),
        experiment.start,
        Some(experiment.stop),
    )?;
    slave.enter_initialization();
    let set_inputs = |slave: &mut Slave<M>| -> Result<(), FmuError> {
        for (name, value) in &experiment.inputs {
            slave.set(name, *value)?;
        }
        Ok(())
    };
    set_inputs(&mut slave)?;
    slave.exit_initialization()?;
    let points = experiment.points();
    let mut rows = vec![(points[0], slave.get(&outputs)?)];
    for pair in points.windows(2) {
        let (t, next) = (pair[0], pair[1]);
        set_inputs(&mut slave)?;
        slave.step(t, next - t)?;
        rows.push((next, slave.get(&outputs)?));
    }
    let names = outputs.iter().map(ToString::to_string).collect();
    Ok(Results { names, rows })
}

/// Python's `math.isclose` with its default relative tolerance 1e-9, as fmpy ends its loop.
fn is_close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(b.abs())
}

impl Results {
    /// The table as CSV in the cross-check convention: a header of quoted names, then one line
    /// per communication point, every number in Rust's shortest representation that reads back
    /// to the same bits.
    pub fn csv(&self) -> String {
        let mut out = String::from("\"time\"");
        for name in &self.names {
            let _ = write!(out, ",\"{name}\"");
        }
        out.push('\n');
        for (t, row) in &self.rows {
            let _ = write!(out, "{t:e}");
            for x in row {
                let _ = write!(out, ",{x:e}");
            }
            out.push('\n');
        }
        out
    }
}

impl Experiment {
    /// `<model>_ref.opt`: the settings that reproduce the reference results.
    pub fn options(&self) -> String {
        format!(
            "StartTime,{:e}\nStopTime,{:e}\nStepSize,{:e}\nRelTol,{:e}\n",
            self.start, self.stop, self.step, self.tolerance
        )
    }

    /// The communication points start + n · step up to the stop time.
    fn points(&self) -> Vec<f64> {
        let mut points = vec![self.start];
        for n in 1u32.. {
            let t = points[points.len() - 1];
            if t > self.stop || is_close(t, self.stop) {
                break;
            }
            points.push(self.start + f64::from(n) * self.step);
        }
        points
    }

    /// `<model>_in.csv` for the inputs held at their values, or None without inputs. It has a
    /// row at every communication point: a master that interpolates the table linearly then
    /// reads each value exactly, whatever its interpolation formula.
    pub fn input_csv(&self) -> Option<String> {
        if self.inputs.is_empty() {
            return None;
        }
        let values: Vec<f64> = self.inputs.iter().map(|(_, v)| *v).collect();
        let table = Results {
            names: self.inputs.iter().map(|(n, _)| n.to_string()).collect(),
            rows: self
                .points()
                .into_iter()
                .map(|t| (t, values.clone()))
                .collect(),
        };
        Some(table.csv())
    }
}
