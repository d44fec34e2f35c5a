//! Reference results: a model's experiment run through its [`Model`] interface the way a
//! fixed-step co-simulation master runs it, and written in the FMI project's convention for
//! compatibility information (`<model>_ref.csv`, `<model>_in.csv`, `<model>_ref.opt`), so that
//! any master's import of the FMU can be checked against them.
//!
//! The run is that of fmpy's `simulate_fmu`: fmi2SetupExperiment with the tolerance, start and
//! stop time, the inputs set in initialization mode and before every step, communication points
//! at start + n · step, every Real output recorded at each of them.

use std::fmt::Write as _;

use crate::error::FmuError;
use crate::logger::Logger;
use crate::model::Model;
use crate::state::State;
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

/// The recorded run: the Real outputs' names and, at every communication point, the time and
/// their values.
#[derive(Clone, Debug, PartialEq)]
pub struct Results {
    /// Names of the recorded outputs.
    pub names: Vec<&'static str>,
    /// Time and values at each communication point.
    pub rows: Vec<(f64, Vec<f64>)>,
}

/// Runs `experiment` on a new instance of `M`.
pub fn run<M: Model>(experiment: &Experiment) -> Result<Results, FmuError> {
    let log = Logger::new(
        None,
        std::ptr::null_mut(),
        "reference",
        false,
        M::LOG_CATEGORIES,
    );
    let mut model = M::new();
    let outputs: Vec<_> = M::VARIABLES
        .iter()
        .filter(|v| v.causality == Causality::Output && matches!(v.kind, Kind::Real { .. }))
        .collect();
    let output_vrs: Vec<u32> = outputs.iter().map(|v| v.vr.index()).collect();
    let mut inputs = Vec::with_capacity(experiment.inputs.len());
    for (name, value) in &experiment.inputs {
        let v = M::VARIABLES
            .iter()
            .find(|v| v.name == *name && v.causality == Causality::Input)
            .ok_or_else(|| FmuError::Invalid(format!("{name} is not an input")))?;
        inputs.push((v.vr.index(), *value));
    }
    let (vrs, values): (Vec<u32>, Vec<f64>) = inputs.into_iter().unzip();
    model.setup_experiment(
        &log,
        Some(experiment.tolerance),
        experiment.start,
        Some(experiment.stop),
    )?;
    model.set_real(State::InitializationMode, &vrs, &values)?;
    model.exit_initialization(&log)?;
    let mut results = Results {
        names: outputs.iter().map(|v| v.name).collect(),
        rows: Vec::new(),
    };
    let mut record = |model: &mut M, t: f64| -> Result<(), FmuError> {
        let mut row = vec![0.0; output_vrs.len()];
        model.get_real(&log, &output_vrs, &mut row)?;
        results.rows.push((t, row));
        Ok(())
    };
    let points = experiment.points();
    record(&mut model, points[0])?;
    for pair in points.windows(2) {
        let (t, next) = (pair[0], pair[1]);
        model.set_real(State::StepComplete, &vrs, &values)?;
        model.do_step(&log, t, next - t)?;
        record(&mut model, next)?;
    }
    Ok(results)
}

/// Python's `math.isclose` with its default relative tolerance 1e-9, as fmpy ends its loop.
fn is_close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(b.abs())
}

impl Results {
    /// `<model>_ref.csv`: a header of quoted names, then one line per communication point, every
    /// number in Rust's shortest representation that reads back to the same bits.
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
        let mut out = String::from("\"time\"");
        for (name, _) in &self.inputs {
            let _ = write!(out, ",\"{name}\"");
        }
        out.push('\n');
        for t in self.points() {
            let _ = write!(out, "{t:e}");
            for (_, value) in &self.inputs {
                let _ = write!(out, ",{value:e}");
            }
            out.push('\n');
        }
        Some(out)
    }
}
