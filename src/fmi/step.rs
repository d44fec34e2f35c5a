//! The slider-crank's step as the FMI layer asks for it: to the communication point, or early at
//! a contact onset, or paused after each internal step for the master's intermediate update.

use fmi_export::{FmuError, Step, StepOutcome};

use super::instance::{Cx, SliderCrankFmu};
use crate::simulation::{Advance, Mode};

impl SliderCrankFmu {
    /// The step `step` (checked against the clock) from the current point: with `early_return`
    /// it stops at the end of the first internal step in which a joint comes into contact, with
    /// `pause` it pauses after every internal step before `t + h` (called again with `resume`
    /// it goes on with the paused one).
    pub(super) fn step(&mut self, cx: &Cx, step: &Step) -> Result<StepOutcome, FmuError> {
        let Step {
            t,
            h,
            early_return,
            pause,
            resume,
        } = *step;
        let engine = self.simulation(cx)?;
        let mode = Mode {
            stop_at_onset: early_return,
            pause,
        };
        let result = engine.advance(cx.time, cx.inputs, t + h, mode, resume);
        for warning in &engine.take_warnings() {
            cx.log.warning(warning);
        }
        match result {
            Ok(Advance::Paused(time)) => Ok(StepOutcome::Paused { time }),
            Ok(Advance::Reached(_)) => Ok(StepOutcome::Completed { time: t + h }),
            Ok(Advance::Onset(onset)) => Ok(StepOutcome::ReturnedEarly {
                time: onset.time,
                event: onset.event(),
            }),
            Err(e) => Err(FmuError::Discard {
                time: engine.reached(),
                reason: e.to_string(),
            }),
        }
    }

    /// Ends a paused step at the pause, on the clock grid: the time reached, or None where that
    /// is not after the step's start (the step stays paused).
    pub(super) fn end_at_pause(&mut self, cx: &Cx) -> Result<Option<f64>, FmuError> {
        Ok(self.simulation(cx)?.end_at_pause(cx.inputs.stepping())?)
    }
}
