//! An instance's FMU state: the snapshot it takes of itself, and its restoration, which rebuilds
//! the model only when the snapshot's parameters differ from the instance's.

use fmi_export::FmuError;

use super::instance::{SliderCrankFmu, model_parameters};
use super::snapshot::FmuSnapshot;
use crate::simulation::Simulation;

impl SliderCrankFmu {
    /// Captures the complete state (parameters, inputs, the experiment it was built for,
    /// simulation).
    pub(super) fn snapshot(&self) -> FmuSnapshot {
        FmuSnapshot {
            parameters: self.parameters.clone(),
            inputs: self.inputs,
            start_time: self.start_time,
            tolerance: self.tolerance,
            simulation: self.simulation.as_ref().map(Simulation::snapshot),
        }
    }

    /// Restores a captured state; the model is rebuilt only if its parameters differ.
    pub(super) fn restore(&mut self, s: &FmuSnapshot) -> Result<(), FmuError> {
        let same_model = self.parameters == s.parameters
            && self.tolerance == s.tolerance
            && self.simulation.is_some();
        let mut simulation = if same_model {
            self.simulation.take()
        } else {
            None
        };
        if let Some(snap) = &s.simulation {
            if simulation.is_none() {
                simulation = Some(Simulation::new(model_parameters(
                    &s.parameters,
                    s.tolerance,
                ))?);
            }
            if let Some(sim) = &mut simulation {
                sim.restore(snap)?;
            }
        } else {
            simulation = None;
        }
        self.simulation = simulation;
        self.parameters = s.parameters.clone();
        self.inputs = s.inputs;
        self.start_time = s.start_time;
        self.tolerance = s.tolerance;
        Ok(())
    }
}
