//! Reading a simulation's outputs at the current time, with the inputs as they stand or with
//! one input moved (the differences that give the outputs' derivatives by the inputs).

use super::outputs::{self, Outputs};
use super::peaks::PeakHold;
use super::{Input, InputSignal, Simulation};
use crate::ancf::SectionResult;
use crate::error::ModelError;
use crate::mechanism::SliderCrank;

impl Simulation {
    /// Outputs at the current time (one right-hand-side evaluation, no allocation).
    ///
    /// The inputs they see: at a communication point those of the interval that just ended, as
    /// it ended (values and derivatives there, so the accelerations of a ramped drive speed include
    /// its rate), until an input or derivative is set; from then on the inputs as set (an output
    /// with direct feedthrough shows a value just set).
    pub fn outputs(&mut self) -> Result<Outputs, ModelError> {
        self.outputs_for(None)
    }

    /// The outputs at the current state with `input` moved by `delta` at the current time;
    /// nothing changes (the differences of [`Simulation::outputs`] that give ∂y/∂u).
    pub fn outputs_with_input_moved(
        &mut self,
        input: Input,
        delta: f64,
    ) -> Result<Outputs, ModelError> {
        self.outputs_for(Some((input, delta)))
    }

    /// The rod's `result` at `out.len()` evenly spaced sections from the crank pin to the slider
    /// pin (rod.section.*, [`crate::ancf::section_place`]) at the current time, with the inputs
    /// [`Simulation::outputs`] sees (one right-hand-side evaluation, no allocation).
    pub fn rod_sections(
        &mut self,
        result: SectionResult,
        out: &mut [f64],
    ) -> Result<(), ModelError> {
        self.read(None, |mechanism, _, y, scratch, _, _| {
            let joint_force = mechanism.evaluate(y, scratch)?.joint_force;
            mechanism.rod_sections(y, scratch, joint_force, result, out);
            Ok(())
        })
    }

    fn outputs_for(&mut self, moved: Option<(Input, f64)>) -> Result<Outputs, ModelError> {
        self.read(moved, outputs::outputs)
    }

    /// `read` of the mechanism in its current state and contact state, at the current time, with
    /// the inputs of [`Simulation::outputs`] (`moved` by a difference if given) and the peak-hold
    /// values and warnings count; the mechanism's inputs are restored afterwards.
    fn read<T>(
        &mut self,
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
        let current = *self.mechanism.input_signal();
        let mut inputs = if self.inputs_set {
            InputSignal {
                start: self.time,
                ..self.next
            }
        } else {
            current
        };
        if let Some((input, delta)) = moved {
            *inputs.value.get_mut(input) += delta;
        }
        self.mechanism.set_input_signal(inputs, self.time);
        let value = self.mechanism.with_contact_state(contact, |mechanism| {
            read(
                mechanism,
                self.time,
                &self.state,
                &mut self.scratch,
                &self.peaks,
                self.monitor.total,
            )
        });
        self.mechanism.set_input_signal(current, self.time);
        value
    }
}
