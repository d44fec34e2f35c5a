//! The slider-crank's step as the FMI layer asks for it: to the communication point, or early at
//! a contact onset, or paused after each internal step for the master's intermediate update.

use fmi_export::{FmuError, Logger, Step, StepOutcome};

use super::instance::SliderCrankFmu;
use crate::simulation::{Advance, Simulation};

impl SliderCrankFmu {
    /// The step `step` (checked against the clock): with `early_return` it stops at the end of the
    /// first internal step in which a joint comes into contact, with `pause` it pauses after every
    /// internal step before `t + h` (called again with the same step it resumes the paused one).
    pub(super) fn step(&mut self, log: &Logger, step: &Step) -> Result<StepOutcome, FmuError> {
        let Step {
            t,
            h,
            early_return,
            pause,
        } = *step;
        let resuming = self.simulation.as_ref().is_some_and(Simulation::is_paused);
        let end = t + h;
        let sim = self.simulation(log)?;
        if !resuming {
            sim.set_time(t);
        }
        let result = match (pause, early_return) {
            (true, _) => sim.advance_pausing(end, early_return),
            (false, true) => sim
                .advance_to_onset(end)
                .map(|onset| onset.map_or(Advance::Reached, Advance::Onset)),
            (false, false) => sim.advance_to(end).map(|()| Advance::Reached),
        };
        let (time, warnings) = (sim.time(), sim.take_warnings());
        for warning in &warnings {
            log.warning(warning);
        }
        if let Ok(Advance::Paused(time)) = result {
            return Ok(StepOutcome::Paused { time });
        }
        // Input derivatives hold for one communication step: the inputs are then held at the
        // values their polynomials reached.
        self.inputs = *sim.next_inputs();
        match result {
            Ok(Advance::Reached | Advance::Paused(_)) => Ok(StepOutcome::Completed { time: end }),
            Ok(Advance::Onset(onset)) => Ok(StepOutcome::ReturnedEarly {
                time: onset.time,
                event: onset.event(),
            }),
            Err(e) => Err(FmuError::Discard {
                time,
                reason: e.to_string(),
            }),
        }
    }

    /// Ends a paused step at the pause, on the clock grid: the time reached, or None where that
    /// is not after the step's start (the step stays paused).
    pub(super) fn end_at_pause(&mut self, log: &Logger) -> Result<Option<f64>, FmuError> {
        let sim = self.simulation(log)?;
        let reached = sim.end_at_pause()?;
        if reached.is_some() {
            self.inputs = *sim.next_inputs();
        }
        Ok(reached)
    }
}
