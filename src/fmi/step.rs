//! The slider-crank's step as the FMI layer asks for it: to the communication point, or early at
//! a contact onset, or paused after each internal step for the master's intermediate update.

use fmi_export::{FmuError, Step, StepOutcome};

use super::instance::{Cx, SliderCrankFmu};
use crate::simulation::{Advance, Simulation};

impl SliderCrankFmu {
    /// The step `step` (checked against the clock): with `early_return` it stops at the end of the
    /// first internal step in which a joint comes into contact, with `pause` it pauses after every
    /// internal step before `t + h` (called again with the same step it resumes the paused one).
    pub(super) fn step(&mut self, cx: &Cx, step: &Step) -> Result<StepOutcome, FmuError> {
        let Step {
            t,
            h,
            early_return,
            pause,
        } = *step;
        let resuming = self.simulation.as_ref().is_some_and(Simulation::is_paused);
        let end = t + h;
        let sim = self.simulation(cx)?;
        if !resuming {
            sim.set_time(t);
        }
        let inputs = cx.inputs;
        let result = match (pause, early_return) {
            (true, _) => sim.advance_pausing(inputs, end, early_return),
            (false, true) => sim
                .advance_to_onset(inputs, end)
                .map(|onset| onset.map_or(Advance::Reached, Advance::Onset)),
            (false, false) => sim.advance_with(inputs, end).map(|()| Advance::Reached),
        };
        let (time, warnings) = (sim.time(), sim.take_warnings());
        for warning in &warnings {
            cx.log.warning(warning);
        }
        match result {
            Ok(Advance::Paused(time)) => Ok(StepOutcome::Paused { time }),
            Ok(Advance::Reached) => Ok(StepOutcome::Completed { time: end }),
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
    pub(super) fn end_at_pause(&mut self, cx: &Cx) -> Result<Option<f64>, FmuError> {
        Ok(self.simulation(cx)?.end_at_pause()?)
    }
}
