//! An instance's FMU state: the snapshot it takes of itself, and its restoration, which rebuilds
//! the model only when the snapshot's parameters differ from the instance's.

use fmi_export::FmuError;

use super::instance::{Cx, SliderCrankFmu, model_parameters};
use super::snapshot::FmuSnapshot;
use crate::simulation::Engine;

impl SliderCrankFmu {
    /// Captures the complete state (parameters, simulation; the inputs and the experiment are
    /// the generic layer's).
    pub(super) fn snapshot(&self) -> FmuSnapshot {
        FmuSnapshot {
            parameters: self.parameters.clone(),
            simulation: self.simulation.as_ref().map(Engine::snapshot),
        }
    }

    /// Restores a captured state, with `cx` the context (experiment, inputs) restored with it;
    /// the model is rebuilt only if the parameters it is built with differ.
    pub(super) fn restore(&mut self, cx: &Cx, s: &FmuSnapshot) -> Result<(), FmuError> {
        let parameters = model_parameters(&s.parameters, cx.experiment.tolerance);
        let same_model = self
            .simulation
            .as_ref()
            .is_some_and(|sim| *sim.parameters() == parameters);
        let mut simulation = if same_model {
            self.simulation.take()
        } else {
            None
        };
        if let Some(snap) = &s.simulation {
            if simulation.is_none() {
                let inputs = cx.inputs.stepping().value;
                simulation = Some(Engine::new(parameters, inputs, cx.time)?);
            }
            if let Some(sim) = &mut simulation {
                sim.restore(snap)?;
            }
        } else {
            simulation = None;
        }
        self.simulation = simulation;
        self.parameters = s.parameters.clone();
        Ok(())
    }
}
