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
        self.read(None, None, outputs::outputs)
    }

    /// [`Simulation::outputs`] with the inputs `inputs` as the caller holds them at the current
    /// time (their values and derivatives there): those of the interval that just ended while
    /// they have not changed (the same values, no derivatives set), else `inputs` (an output with
    /// direct feedthrough shows a value just set).
    pub fn outputs_seeing(&mut self, inputs: &InputSignal) -> Result<Outputs, ModelError> {
        self.read(Some(inputs), None, outputs::outputs)
    }

    /// [`Simulation::outputs_seeing`] with `input` moved by `delta` at the current time;
    /// nothing changes (the differences that give ∂y/∂u).
    pub fn outputs_with_input_moved(
        &mut self,
        inputs: &InputSignal,
        input: Input,
        delta: f64,
    ) -> Result<Outputs, ModelError> {
        self.read(Some(inputs), Some((input, delta)), outputs::outputs)
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
        self.read(Some(inputs), None, |mechanism, _, y, scratch, _, _| {
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
    /// the inputs [`Simulation::reading_inputs`] gives (`moved` by a difference if given) and the
    /// peak-hold values and warnings count. The inputs it sets stay the mechanism's until the
    /// next evaluation sets its own (every evaluation of a step, and every reading, does).
    fn read<T>(
        &mut self,
        inputs: Option<&InputSignal>,
        moved: Option<(Input, f64)>,
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
        let mut inputs = self.reading_inputs(inputs);
        if let Some((input, delta)) = moved {
            *inputs.value.get_mut(input) += delta;
        }
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
