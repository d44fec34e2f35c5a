//! The experiment a master sets up and the clock of the communication steps, the same for every
//! model and both FMI versions: the checks of the tolerance, start and stop time
//! (fmi2SetupExperiment, fmi3EnterInitializationMode), the check of each step's communication
//! point and size ([`check_step`]), and the time reached after each step
//! (FMI 2's fmi2LastSuccessfulTime, FMI 3's lastSuccessfulTime), kept from what the model's step
//! says ([`StepOutcome`]). A model sees only checked values ([`Experiment`], [`Step`]); the clock
//! calls it through the closures the instance passes.

use crate::clock::on_clock_grid;
use crate::codec::{ByteReader, ByteWriter, CodecError};
use crate::error::FmuError;
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
    /// Whether the call resumes a paused step (set by the clock, [`Clock::step`]).
    pub resume: bool,
}

/// How a step that succeeded ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StepOutcome {
    /// At the communication point.
    Completed {
        /// The time reached \[s\]: t + h, or the point on the clock grid nearest it for a model
        /// that keeps its time there.
        time: f64,
    },
    /// Paused inside it after an internal step (FMI 3 intermediate update, [`Step::pause`]).
    Paused {
        /// The internal step's end \[s\].
        time: f64,
    },
    /// Before it, at an event of the model (FMI 3 early return).
    ReturnedEarly {
        /// The time reached \[s\], on the clock grid.
        time: f64,
        /// What happened there, for the log ("contact onset in crankPin").
        event: &'static str,
    },
}

/// Tolerance on the communication point: |t − t_expected| ≤ 1e-9 (1 + |t|).
pub const TIME_TOLERANCE: f64 = 1e-9;

/// Checks fmi2DoStep's arguments against an instance at `time` with stop time `stop`: the
/// communication point is the current time (within [`TIME_TOLERANCE`]), the step is positive and
/// finite, and t + h is not past the stop time.
pub fn check_step(time: f64, t: f64, h: f64, stop: Option<f64>) -> Result<(), FmuError> {
    if (t - time).abs() > TIME_TOLERANCE * (1.0 + t.abs()) {
        return Err(FmuError::Invalid(format!(
            "expected currentCommunicationPoint = {} s but was {} s",
            Num(time),
            Num(t)
        )));
    }
    if !(h > 0.0 && h.is_finite()) {
        return Err(FmuError::Invalid(format!(
            "communicationStepSize must be > 0 and finite but was {} s",
            Num(h)
        )));
    }
    let end = t + h;
    match stop {
        Some(stop) if end > stop + TIME_TOLERANCE * (1.0 + stop.abs()) => {
            Err(FmuError::Invalid(format!(
                "currentCommunicationPoint + communicationStepSize = {} s is past stopTime = {} s",
                Num(end),
                Num(stop)
            )))
        }
        _ => Ok(()),
    }
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
    /// Checks and sets up the experiment of `tolerance`, `start` and `stop` (the model reads it
    /// in its [`crate::model::Context`]); the clock starts at `start`.
    pub fn setup(
        &mut self,
        (tolerance, start, stop): (Option<f64>, f64, Option<f64>),
    ) -> Result<(), FmuError> {
        let experiment = Experiment::new(tolerance, start, stop)?;
        *self = Self {
            experiment,
            time: start,
            last_successful_time: start,
            paused: false,
        };
        Ok(())
    }

    /// The model's step `step` (`run`, [`crate::Model::do_step`]), checked against the clock and
    /// the stop time unless it resumes a paused step, the clock moved to where it ended: the
    /// communication point the model reached, the early return's time, the time a discarded step
    /// reached; a pause moves only the last successful time.
    pub fn step(
        &mut self,
        step: Step,
        run: impl FnOnce(&Step) -> Result<StepOutcome, FmuError>,
    ) -> Result<StepOutcome, FmuError> {
        if !self.paused {
            check_step(self.time, step.t, step.h, self.experiment.stop)?;
        }
        let outcome = run(&Step {
            resume: self.paused,
            ..step
        });
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

    /// A paused step ended at the pause (`reached`, [`crate::Model::return_at_pause`]), or not
    /// (None: it stays paused).
    pub fn return_at_pause(&mut self, reached: Option<f64>) {
        if let Some(time) = reached {
            self.paused = false;
            self.reach(time);
        }
    }

    /// The current point where a model computes: the communication point on the clock grid
    /// ([`crate::clock`]: every master's representation of the same point gives the same
    /// results), or while a step is paused inside, the time it paused at.
    pub fn now(&self) -> f64 {
        if self.paused {
            self.last_successful_time
        } else {
            on_clock_grid(self.time)
        }
    }

    /// Whether a step is paused inside (FMI 3 intermediate update).
    pub fn is_paused(&self) -> bool {
        self.paused
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
