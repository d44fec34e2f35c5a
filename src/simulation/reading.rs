//! Reading a simulation's outputs at the current time, with the inputs as they stand or with
//! one input moved (the differences that give the outputs' derivatives by the inputs).

use super::outputs::{self, Outputs};
use super::peaks::PeakHold;
use super::{Input, InputSignal, Simulation};
use crate::ancf::SectionResult;
use crate::error::ModelError;
use crate::mechanism::SliderCrank;

impl Simulation {
    /// Outputs at the current time (one right-hand-side evaluation, no allocation), with the
    /// inputs of the current step sequence (at a communication point those of the interval that
    /// just ended, as it ended: values and derivatives there, so the accelerations of a ramped
    /// drive speed include its rate; before the first step the start's).
    pub fn outputs(&mut self) -> Result<Outputs, ModelError> {
        let inputs = self.reading_inputs(None);
        self.outputs_of(inputs)
    }

    /// [`Simulation::outputs`] with the inputs `inputs` as the caller holds them at the current
    /// time (their values and derivatives there): those of the interval that just ended while
    /// they have not changed (the same values, no derivatives set), else `inputs` (an output with
    /// direct feedthrough shows a value just set).
    ///
    /// A reading is evaluated once: until the simulation next moves (a step, a restored snapshot,
    /// the clock set), a reading with the same inputs, bit for bit, gives back the outputs
    /// already read. A master that reads a communication point in several calls (one per
    /// variable, or one per type) pays for one evaluation.
    pub fn outputs_seeing(&mut self, inputs: &InputSignal) -> Result<Outputs, ModelError> {
        let inputs = self.reading_inputs(Some(inputs));
        self.outputs_of(inputs)
    }

    /// The outputs with the reading's inputs `inputs`: those last read if they saw the same
    /// ([`Simulation::outputs_seeing`]), else a new reading.
    fn outputs_of(&mut self, inputs: InputSignal) -> Result<Outputs, ModelError> {
        if let Some((seen, outputs)) = &self.last_read {
            if seen.same_bits(&inputs) {
                return Ok(*outputs);
            }
        }
        let outputs = self.read(inputs, outputs::outputs)?;
        self.last_read = Some((inputs, outputs));
        Ok(outputs)
    }

    /// [`Simulation::outputs_seeing`] with `input` moved by `delta` at the current time;
    /// nothing changes (the differences that give ∂y/∂u).
    pub fn outputs_with_input_moved(
        &mut self,
        inputs: &InputSignal,
        input: Input,
        delta: f64,
    ) -> Result<Outputs, ModelError> {
        let mut inputs = self.reading_inputs(Some(inputs));
        *inputs.value.get_mut(input) += delta;
        self.read(inputs, outputs::outputs)
    }

    /// The rod's `result` at `out.len()` evenly spaced sections from the crank pin to the slider
    /// pin (rod.section.*, [`crate::ancf::section_place`]) at the current time, with the inputs
    /// [`Simulation::outputs_seeing`] sees (one right-hand-side evaluation, no allocation).
    pub fn rod_sections(
        &mut self,
        inputs: &InputSignal,
        result: SectionResult,
        out: &mut [f64],
    ) -> Result<(), ModelError> {
        let inputs = self.reading_inputs(Some(inputs));
        self.read(inputs, |mechanism, _, y, scratch, _, _| {
            let joint_force = mechanism.evaluate(y, scratch)?.joint_force;
            mechanism.rod_sections(y, scratch, joint_force, result, out);
            Ok(())
        })
    }

    /// The inputs a reading sees: the current step sequence's, or `inputs` where they differ
    /// from the values those reach now or carry derivatives (see
    /// [`Simulation::outputs_seeing`]).
    fn reading_inputs(&self, inputs: Option<&InputSignal>) -> InputSignal {
        match inputs {
            Some(inputs) if inputs.varies() || inputs.value != self.signal.at(self.time) => {
                InputSignal {
                    start: self.time,
                    ..*inputs
                }
            }
            _ => self.signal,
        }
    }

    /// `read` of the mechanism in its current state and contact state, at the current time, with
    /// the inputs `inputs` (from [`Simulation::reading_inputs`]) and the peak-hold values and
    /// warnings count. The inputs it sets stay the mechanism's until the next evaluation sets its
    /// own (every evaluation of a step, and every reading, does).
    fn read<T>(
        &mut self,
        inputs: InputSignal,
        read: impl FnOnce(
            &mut SliderCrank,
            f64,
            &[f64],
            &mut [f64],
            &PeakHold,
            u64,
        ) -> Result<T, ModelError>,
    ) -> Result<T, ModelError> {
        let contact = self.contact_now();
        self.mechanism.set_inputs(&inputs, self.time);
        self.mechanism.with_contact_state(contact, |mechanism| {
            read(
                mechanism,
                self.time,
                &self.state,
                &mut self.scratch,
                &self.peaks,
                self.monitor.total,
            )
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Parameters;
    use crate::simulation::Advance;

    /// Every output's bits (the Debug form of an f64 tells every value apart, a zero's sign too).
    fn bits(o: &Outputs) -> String {
        format!("{o:?}")
    }

    /// A reading, checked: the outputs it gives are those a fresh evaluation gives, bit for bit,
    /// and reading again gives them back.
    fn read_checked(sim: &mut Simulation, inputs: &InputSignal) -> Outputs {
        let read = sim.outputs_seeing(inputs).unwrap();
        let seen = sim.reading_inputs(Some(inputs));
        let fresh = sim.read(seen, outputs::outputs).unwrap();
        assert_eq!(bits(&read), bits(&fresh));
        assert_eq!(bits(&sim.outputs_seeing(inputs).unwrap()), bits(&read));
        read
    }

    /// The outputs a reading gives back are the evaluation they stand for wherever the simulation
    /// moved since (a step, another input, a snapshot restored, a pause and its end, the clock
    /// set), and each move that changes them shows.
    #[test]
    fn a_reading_given_back_is_the_evaluation_it_stands_for() {
        let mut sim = Simulation::new(Parameters::default()).unwrap();
        let inputs = *sim.inputs();
        let start = read_checked(&mut sim, &inputs);
        let snapshot = sim.snapshot();
        sim.advance_with(&inputs, 1e-4).unwrap();
        let stepped = read_checked(&mut sim, &inputs);
        assert_ne!(stepped.crank_angle, start.crank_angle);
        let mut pushed = inputs;
        pushed.value.slider_force += 10.0;
        let pushed = read_checked(&mut sim, &pushed);
        assert_ne!(pushed.slider_applied_force, stepped.slider_applied_force);
        assert_eq!(bits(&read_checked(&mut sim, &inputs)), bits(&stepped));
        sim.restore(&snapshot).unwrap();
        assert_eq!(bits(&read_checked(&mut sim, &inputs)), bits(&start));
        sim.advance_with(&inputs, 1e-4).unwrap();
        let before = read_checked(&mut sim, &inputs);
        sim.set_time(2e-4);
        assert_ne!(read_checked(&mut sim, &inputs).time, before.time);
        let Advance::Paused(pause) = sim.advance_pausing(&inputs, 1e-3, false).unwrap() else {
            panic!("no pause before 1e-3 s");
        };
        let paused = read_checked(&mut sim, &inputs);
        assert_eq!(sim.end_at_pause().unwrap().is_some(), pause > 2e-4);
        assert_ne!(bits(&read_checked(&mut sim, &inputs)), bits(&paused));
    }
}
