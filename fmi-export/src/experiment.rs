//! The experiment a master sets up and the clock of the communication steps, the same for every
//! model and both FMI versions: the checks of the tolerance, start and stop time
//! (fmi2SetupExperiment, fmi3EnterInitializationMode), the check of each step's communication
//! point and size ([`crate::checks::check_step`]), and the time reached after each step
//! (FMI 2's fmi2LastSuccessfulTime, FMI 3's lastSuccessfulTime), kept from what the model's step
//! says ([`StepOutcome`]). A model sees only checked values ([`Experiment`], [`Step`]).

use crate::checks::check_step;
use crate::codec::{ByteReader, ByteWriter, CodecError};
use crate::error::FmuError;
use crate::logger::Logger;
use crate::model::{Model, StepOutcome};
use crate::number::Num;

/// The experiment, checked: a finite start, a finite stop not before it, a finite positive
/// tolerance.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Experiment {
    /// The master's relative tolerance, if it gave one.
    pub tolerance: Option<f64>,
    /// Start time \[s\].
    pub start: f64,
    /// Stop time, if defined \[s\].
    pub stop: Option<f64>,
}

impl Experiment {
    /// The experiment of `tolerance`, `start` and `stop`, or an error naming the value out of
    /// range.
    pub fn new(tolerance: Option<f64>, start: f64, stop: Option<f64>) -> Result<Self, FmuError> {
        if let Some(tolerance) = tolerance {
            if !(tolerance.is_finite() && tolerance > 0.0) {
                return Err(FmuError::Invalid(format!(
                    "tolerance = {} must be finite and > 0",
                    Num(tolerance)
                )));
            }
        }
        if !start.is_finite() {
            return Err(FmuError::Invalid(format!(
                "startTime = {} is not finite",
                Num(start)
            )));
        }
        if let Some(stop) = stop {
            if !(stop.is_finite() && stop >= start) {
                return Err(FmuError::Invalid(format!(
                    "stopTime = {} must be finite and >= startTime = {}",
                    Num(stop),
                    Num(start)
                )));
            }
        }
        Ok(Self {
            tolerance,
            start,
            stop,
        })
    }
}

/// One communication step as the model receives it, checked against the clock.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Step {
    /// The communication point, the clock's time \[s\] (or, resuming a paused step, the same as
    /// when it paused).
    pub t: f64,
    /// The communication step size \[s\], > 0.
    pub h: f64,
    /// FMI 3's earlyReturnAllowed: the step may end before t + h at an event of the model.
    pub early_return: bool,
    /// FMI 3's intermediate update: the step may pause after an internal step before t + h
    /// ([`StepOutcome::Paused`]); called again with the same step, it resumes.
    pub pause: bool,
}

/// The experiment and how far the communication steps got.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Clock {
    /// The experiment set up.
    pub experiment: Experiment,
    /// The current communication point \[s\].
    pub time: f64,
    /// The time up to which the last step succeeded \[s\].
    pub last_successful_time: f64,
    /// A step paused inside (FMI 3 intermediate update): its next call resumes it unchecked.
    paused: bool,
}

impl Clock {
    /// Checks and sets up the experiment of `tolerance`, `start` and `stop`, and tells the model;
    /// the clock starts at `start`.
    pub fn setup<M: Model>(
        &mut self,
        model: &mut M,
        log: &Logger,
        tolerance: Option<f64>,
        start: f64,
        stop: Option<f64>,
    ) -> Result<(), FmuError> {
        let experiment = Experiment::new(tolerance, start, stop)?;
        model.setup_experiment(log, &experiment)?;
        *self = Self {
            experiment,
            time: start,
            last_successful_time: start,
            paused: false,
        };
        Ok(())
    }

    /// The model's step from `t` over `h` (checked against the clock and the stop time, unless
    /// it resumes a paused step), the clock moved to where it ended: the communication point the
    /// model reached, the early return's time, the time a discarded step reached; a pause moves
    /// only the last successful time.
    pub fn step<M: Model>(
        &mut self,
        model: &mut M,
        log: &Logger,
        step: Step,
    ) -> Result<StepOutcome, FmuError> {
        if !self.paused {
            check_step(self.time, step.t, step.h, self.experiment.stop)?;
        }
        let outcome = model.do_step(log, &step);
        self.paused = false;
        match &outcome {
            Ok(StepOutcome::Completed { time } | StepOutcome::ReturnedEarly { time, .. })
            | Err(FmuError::Discard { time, .. }) => self.reach(*time),
            Ok(StepOutcome::Paused { time }) => {
                self.paused = true;
                self.last_successful_time = *time;
            }
            Err(_) => {}
        }
        outcome
    }

    /// Ends a paused step at the pause, if the model can ([`Model::return_at_pause`]): the time
    /// reached, or None (the step stays paused).
    pub fn return_at_pause<M: Model>(
        &mut self,
        model: &mut M,
        log: &Logger,
    ) -> Result<Option<f64>, FmuError> {
        let reached = model.return_at_pause(log)?;
        if let Some(time) = reached {
            self.paused = false;
            self.reach(time);
        }
        Ok(reached)
    }

    fn reach(&mut self, time: f64) {
        self.time = time;
        self.last_successful_time = time;
    }

    /// Appends the experiment and the times (a paused step is never saved: FMU states are not
    /// taken inside a step).
    pub fn write(&self, w: &mut ByteWriter) {
        let e = &self.experiment;
        w.f64(e.start);
        for x in [e.stop, e.tolerance] {
            w.flag(x.is_some());
            w.f64(x.unwrap_or(0.0));
        }
        w.f64(self.time);
        w.f64(self.last_successful_time);
    }

    /// Reads what [`Clock::write`] wrote, checked: a valid experiment, finite times.
    pub fn read(r: &mut ByteReader) -> Result<Self, FmuError> {
        let start = r.f64()?;
        let mut optional = || -> Result<Option<f64>, CodecError> {
            let defined = r.flag()?;
            let value = r.f64()?;
            Ok(defined.then_some(value))
        };
        let (stop, tolerance) = (optional()?, optional()?);
        let experiment = Experiment::new(tolerance, start, stop)
            .map_err(|e| FmuError::Invalid(format!("FMU state rejected: its experiment: {e}")))?;
        let (time, last_successful_time) = (r.f64()?, r.f64()?);
        if !(time.is_finite() && last_successful_time.is_finite()) {
            return Err(FmuError::Invalid(
                "FMU state rejected: a non-finite time".into(),
            ));
        }
        Ok(Self {
            experiment,
            time,
            last_successful_time,
            paused: false,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each value out of range is refused, naming it; the limits themselves are accepted.
    #[test]
    fn experiments_out_of_range_are_refused() {
        let refused = |tol, start, stop, name: &str| {
            let e = Experiment::new(tol, start, stop).unwrap_err().to_string();
            assert!(e.contains(name), "{e}");
        };
        refused(Some(0.0), 0.0, None, "tolerance = 0");
        refused(Some(f64::NAN), 0.0, None, "tolerance");
        refused(None, f64::INFINITY, None, "startTime");
        refused(None, 1.0, Some(0.5), "stopTime = 0.5");
        refused(None, 0.0, Some(f64::NAN), "stopTime");
        assert!(Experiment::new(Some(1e-12), -1.0, Some(-1.0)).is_ok());
    }

    /// The clock round-trips through its bytes; a corrupted time is refused.
    #[test]
    fn the_clock_round_trips() {
        let clock = Clock {
            experiment: Experiment::new(Some(1e-6), 0.5, Some(2.0)).unwrap(),
            time: 1.25,
            last_successful_time: 1.25,
            paused: false,
        };
        let mut bytes = Vec::new();
        clock.write(&mut ByteWriter(&mut bytes));
        assert_eq!(Clock::read(&mut ByteReader::new(&bytes)).unwrap(), clock);
        let mut bad = bytes.clone();
        let at = bad.len() - 16;
        bad[at..at + 8].copy_from_slice(&f64::NAN.to_le_bytes());
        assert!(Clock::read(&mut ByteReader::new(&bad)).is_err());
    }
}
