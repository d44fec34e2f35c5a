//! [`Simulation`]: the [`Engine`] with a clock and inputs of its own, for a program that drives
//! the model directly (the examples, the benchmarks, the tests). The FMU drives the engine with its
//! instance's clock and inputs instead; either way one owner holds each.

use fmi_core::clock::on_clock_grid;
use fmi_core::signal::InputRecord;

use super::engine::Engine;
use super::outputs::Outputs;
use super::peaks::PeakHold;
use super::snapshot::Snapshot;
use super::step::{Advance, Mode, Onset};
use crate::ancf::SectionResult;
use crate::error::ModelError;
use crate::integrator::Stats;
use crate::mechanism::{Contacts, Energies, Input, InputSignal, Inputs, SliderCrank};
use crate::params::Parameters;

/// A complete, restorable state of a [`Simulation`].
#[derive(Clone, Debug, PartialEq)]
pub struct SimulationSnapshot {
    /// The current time \[s\].
    pub time: f64,
    /// The inputs.
    pub inputs: InputRecord<Inputs>,
    /// The engine's state.
    pub engine: Snapshot,
}

/// The slider-crank simulation: parameters in, `advance_to(t)`, outputs out.
///
/// It holds the current time and the inputs ([`InputRecord`]: a step is integrated with the
/// inputs given for it, [`Simulation::advance_with`]; [`Simulation::advance_to`] holds them at the
/// values they reached, input derivatives holding for one interval) and drives an [`Engine`] with
/// them.
#[derive(Clone, Debug)]
pub struct Simulation {
    engine: Engine,
    /// The current time \[s\] (while an interval is paused: the pause's).
    time: f64,
    inputs: InputRecord<Inputs>,
    /// Whether an interval is paused ([`Simulation::advance_pausing`]).
    paused: bool,
}

impl Simulation {
    /// A simulation at t = 0 in the initial state of the parameters (docs/model.md §7), with
    /// the inputs of [`Inputs::at_start`] (the drive speed at the crank's initial speed).
    pub fn new(parameters: Parameters) -> Result<Self, ModelError> {
        let inputs = Inputs::at_start(&parameters);
        Self::with_inputs(parameters, inputs)
    }

    /// A simulation at t = 0 whose inputs start at `inputs` ([`Engine::new`]): they hold until
    /// others are passed ([`Simulation::advance_with`]).
    pub fn with_inputs(parameters: Parameters, inputs: Inputs) -> Result<Self, ModelError> {
        Ok(Self {
            engine: Engine::new(parameters, inputs, 0.0)?,
            time: 0.0,
            inputs: InputRecord::held(inputs, 0.0),
            paused: false,
        })
    }

    /// The engine it drives.
    pub fn engine(&self) -> &Engine {
        &self.engine
    }

    /// The parameters.
    pub fn parameters(&self) -> &Parameters {
        self.engine.parameters()
    }

    /// The mechanism.
    pub fn mechanism(&self) -> &SliderCrank {
        self.engine.mechanism()
    }

    /// Current time \[s\].
    pub fn time(&self) -> f64 {
        self.time
    }

    /// The state vector at the current time ([`Engine::state`]).
    pub fn state(&self) -> &[f64] {
        self.engine.state()
    }

    /// The inputs as outputs read them now: as the last interval ended until others are passed
    /// ([`InputRecord::reading`]).
    pub fn inputs(&self) -> &InputSignal {
        self.inputs.reading()
    }

    /// The joints' contact states at the last accepted step's end ([`Engine::contacts`]).
    pub fn contacts(&self) -> &Contacts {
        self.engine.contacts()
    }

    /// Integrator statistics since the start.
    pub fn stats(&self) -> Stats {
        self.engine.stats()
    }

    /// Peak-hold extremes, contact onsets and cycle results ([`PeakHold`]).
    pub fn peaks(&self) -> &PeakHold {
        self.engine.peaks()
    }

    /// Warnings raised since the last call ([`Engine::take_warnings`]).
    pub fn take_warnings(&mut self) -> Vec<String> {
        self.engine.take_warnings()
    }

    /// Energies of the current state.
    pub fn energies(&mut self) -> Energies {
        self.engine.energies(self.time)
    }

    /// A complete snapshot: the time, the inputs and the engine's.
    pub fn snapshot(&self) -> SimulationSnapshot {
        SimulationSnapshot {
            time: self.time,
            inputs: self.inputs,
            engine: self.engine.snapshot(),
        }
    }

    /// Restores a snapshot of a simulation with the same parameters.
    pub fn restore(&mut self, snapshot: &SimulationSnapshot) -> Result<(), ModelError> {
        self.engine.restore(&snapshot.engine)?;
        self.time = snapshot.time;
        self.inputs = snapshot.inputs;
        self.paused = false;
        Ok(())
    }

    /// Integrates to `t_end` (rounded to the clock grid) with the inputs held as they are (at the
    /// values they reached: input derivatives hold for one interval). On failure the simulation
    /// stays at the last accepted point ([`Simulation::time`]) and the error says why.
    pub fn advance_to(&mut self, t_end: f64) -> Result<(), ModelError> {
        self.advance(t_end, Mode::default()).map(|_| ())
    }

    /// Integrates to `t_end` as [`Simulation::advance_to`] does, with `inputs` (their values and
    /// derivatives at the current time: the polynomials of [`InputSignal`] over the interval;
    /// `inputs.start` is not read); see [`Engine::advance`].
    pub fn advance_with(&mut self, inputs: &InputSignal, t_end: f64) -> Result<(), ModelError> {
        self.inputs.set(inputs);
        self.advance(t_end, Mode::default()).map(|_| ())
    }

    /// [`Simulation::advance_with`] that stops early at the end of the first internal step in
    /// which a joint comes into contact, if that is before `t_end` ([`Engine::advance`]).
    pub fn advance_to_onset(
        &mut self,
        inputs: &InputSignal,
        t_end: f64,
    ) -> Result<Option<Onset>, ModelError> {
        self.inputs.set(inputs);
        let mode = Mode {
            stop_at_onset: true,
            pause: false,
        };
        match self.advance(t_end, mode)? {
            Advance::Onset(onset) => Ok(Some(onset)),
            _ => Ok(None),
        }
    }

    /// [`Simulation::advance_with`] (or [`Simulation::advance_to_onset`] if `stop_at_onset`) that
    /// pauses after every accepted step ending before `t_end`, with the time and the state at the
    /// step's end the current ones. Called again with the same `t_end` it resumes the paused
    /// interval (with the inputs it began with); [`Simulation::end_at_pause`] ends it at the
    /// pause instead.
    pub fn advance_pausing(
        &mut self,
        inputs: &InputSignal,
        t_end: f64,
        stop_at_onset: bool,
    ) -> Result<Advance, ModelError> {
        if !self.paused {
            self.inputs.set(inputs);
        }
        let mode = Mode {
            stop_at_onset,
            pause: true,
        };
        self.advance(t_end, mode)
    }

    /// Whether an interval is paused ([`Simulation::advance_pausing`]).
    pub fn is_paused(&self) -> bool {
        self.paused
    }

    /// Ends a paused interval at the pause, rounded down to the clock grid, as an early return
    /// does: the time reached, or None (the interval stays paused) where that is not after the
    /// interval's start.
    pub fn end_at_pause(&mut self) -> Result<Option<f64>, ModelError> {
        if !self.paused {
            return Ok(None);
        }
        let reached = self.engine.end_at_pause(self.inputs.stepping())?;
        if let Some(time) = reached {
            self.reach(time);
        }
        Ok(reached)
    }

    /// The interval from the current time towards `t_end` in `mode`, or the paused one resumed.
    fn advance(&mut self, t_end: f64, mode: Mode) -> Result<Advance, ModelError> {
        let resume = self.paused;
        if !resume {
            self.inputs.begin_step();
        }
        let result = self
            .engine
            .advance(self.time, &self.inputs, t_end, mode, resume);
        self.paused = false;
        match result {
            Ok(Advance::Paused(time)) => {
                self.paused = true;
                self.time = time;
            }
            Ok(Advance::Reached(time) | Advance::Onset(Onset { time, .. })) => self.reach(time),
            Err(_) => self.reach(self.engine.reached()),
        }
        result
    }

    /// An interval ended at `time`.
    fn reach(&mut self, time: f64) {
        self.paused = false;
        self.time = time;
        self.inputs.end_step(time);
    }

    /// Moves the clock to `time` (rounded to the clock grid) before the first step, without
    /// changing the state: the simulation then starts there.
    pub fn start_at(&mut self, time: f64) -> Result<(), ModelError> {
        let time = on_clock_grid(time);
        let inputs = self.inputs.stepping().value;
        self.engine = Engine::new(self.engine.parameters().clone(), inputs, time)?;
        self.inputs.start_at(time);
        self.time = time;
        Ok(())
    }

    /// Outputs at the current time with the inputs as outputs read them
    /// ([`Simulation::inputs`]; see [`Engine::outputs`]).
    pub fn outputs(&mut self) -> Result<Outputs, ModelError> {
        self.engine.outputs(self.time, self.inputs.reading())
    }

    /// Outputs at the current time with the inputs `inputs` instead (their values and
    /// derivatives now; `inputs.start` is not read).
    pub fn outputs_seeing(&mut self, inputs: &InputSignal) -> Result<Outputs, ModelError> {
        let inputs = InputSignal {
            start: self.time,
            ..*inputs
        };
        self.engine.outputs(self.time, &inputs)
    }

    /// [`Simulation::outputs`] with `input` moved by `delta`; nothing changes.
    pub fn outputs_with_input_moved(
        &mut self,
        input: Input,
        delta: f64,
    ) -> Result<Outputs, ModelError> {
        let inputs = *self.inputs.reading();
        self.engine
            .outputs_with_input_moved(self.time, &inputs, input, delta)
    }

    /// The rod's `result` at `out.len()` evenly spaced sections at the current time
    /// ([`Engine::rod_sections`]).
    pub fn rod_sections(
        &mut self,
        result: SectionResult,
        out: &mut [f64],
    ) -> Result<(), ModelError> {
        let inputs = *self.inputs.reading();
        self.engine.rod_sections(self.time, &inputs, result, out)
    }
}
