//! Reading the outputs at the current point, with the inputs as outputs read them or with one
//! input moved (the differences that give the outputs' derivatives by the inputs).

#[cfg(test)]
use super::on_clock_grid;
use super::outputs::{self, Outputs};
use super::peaks::PeakHold;
use super::{Engine, Input, InputSignal};
use crate::ancf::SectionResult;
use crate::error::ModelError;
use crate::mechanism::{Conditions, SliderCrank};

impl Engine {
    /// Outputs at the current point `t` with the inputs `inputs` as outputs read them there
    /// (their values and derivatives at `t`, [`super::InputRecord::reading`]): one right-hand-side
    /// evaluation, no allocation.
    ///
    /// A reading is evaluated once: until the engine next moves (a step, a restored snapshot, a
    /// pause's end), a reading at the same time with the same inputs, bit for bit, gives back the
    /// outputs already read. A master that reads a communication point in several calls (one per
    /// variable, or one per type) pays for one evaluation.
    pub fn outputs(&mut self, t: f64, inputs: &InputSignal) -> Result<Outputs, ModelError> {
        if let Some((seen_t, seen, outputs)) = &self.last_read {
            if seen_t.to_bits() == t.to_bits() && seen.same_bits(inputs) {
                return Ok(*outputs);
            }
        }
        let outputs = self.read(t, inputs, outputs::outputs)?;
        self.last_read = Some((t, *inputs, outputs));
        Ok(outputs)
    }

    /// [`Engine::outputs`] with `input` moved by `delta` at `t`; nothing changes (the differences
    /// that give ∂y/∂u).
    pub fn outputs_with_input_moved(
        &mut self,
        t: f64,
        inputs: &InputSignal,
        input: Input,
        delta: f64,
    ) -> Result<Outputs, ModelError> {
        let mut moved = *inputs;
        *moved.value.get_mut(input) += delta;
        self.read(t, &moved, outputs::outputs)
    }

    /// The rod's `result` at `out.len()` evenly spaced sections from the crank pin to the slider
    /// pin (rod.section.*, [`crate::ancf::section_place`]) at `t`, with the inputs `inputs` as
    /// [`Engine::outputs`] reads them (one right-hand-side evaluation, no allocation).
    pub fn rod_sections(
        &mut self,
        t: f64,
        inputs: &InputSignal,
        result: SectionResult,
        out: &mut [f64],
    ) -> Result<(), ModelError> {
        self.read(t, inputs, |mechanism, c, (_, y), scratch, _, _| {
            let joint_force = mechanism.evaluate(y, c, scratch)?.joint_force;
            mechanism.rod_sections(y, scratch, (joint_force, c.contacts), result, out);
            Ok(())
        })
    }

    /// `read` of the mechanism under the conditions at `t` (the inputs `inputs` there, the
    /// contact states at `t`), in its state at `t`, with the peak-hold values and warnings count.
    fn read<T>(
        &mut self,
        t: f64,
        inputs: &InputSignal,
        read: impl FnOnce(
            &mut SliderCrank,
            &Conditions,
            (f64, &[f64]),
            &mut [f64],
            &PeakHold,
            u64,
        ) -> Result<T, ModelError>,
    ) -> Result<T, ModelError> {
        let contact = self.contact_now(t);
        let c = Conditions::at(inputs, t, &contact);
        read(
            &mut self.mechanism,
            &c,
            (t, &self.state),
            &mut self.scratch,
            &self.peaks,
            self.monitor.total,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Parameters;
    use crate::simulation::{Advance, InputRecord, Inputs, Mode};

    /// Every output's bits (the Debug form of an f64 tells every value apart, a zero's sign too).
    fn bits(o: &Outputs) -> String {
        format!("{o:?}")
    }

    /// A reading, checked: the outputs it gives are those a fresh evaluation gives, bit for bit,
    /// and reading again gives them back.
    fn read_checked(engine: &mut Engine, t: f64, inputs: &InputSignal) -> Outputs {
        let read = engine.outputs(t, inputs).unwrap();
        let fresh = engine.read(t, inputs, outputs::outputs).unwrap();
        assert_eq!(bits(&read), bits(&fresh));
        assert_eq!(bits(&engine.outputs(t, inputs).unwrap()), bits(&read));
        read
    }

    /// The outputs a reading gives back are the evaluation they stand for wherever the engine
    /// moved since (a step, another input, a snapshot restored, a pause and its end, another
    /// time), and each move that changes them shows.
    #[test]
    fn a_reading_given_back_is_the_evaluation_it_stands_for() {
        let parameters = Parameters::default();
        let start_inputs = Inputs::at_start(&parameters);
        let mut engine = Engine::new(parameters, start_inputs, 0.0).unwrap();
        let mut inputs = InputRecord::held(start_inputs, 0.0);
        let start = read_checked(&mut engine, 0.0, inputs.reading());
        let snapshot = engine.snapshot();
        let plain = Mode::default();
        let step = |engine: &mut Engine, inputs: &mut InputRecord<Inputs>, t, t_end, mode| {
            inputs.begin_step();
            let advance = engine.advance(t, inputs, t_end, mode, false).unwrap();
            if let Advance::Reached(t) = advance {
                inputs.end_step(t);
            }
            advance
        };
        step(&mut engine, &mut inputs, 0.0, 1e-4, plain);
        let t = on_clock_grid(1e-4);
        let stepped = read_checked(&mut engine, t, inputs.reading());
        assert_ne!(stepped.crank_angle, start.crank_angle);
        let mut pushed = *inputs.reading();
        pushed.value.slider_force += 10.0;
        let pushed = read_checked(&mut engine, t, &pushed);
        assert_ne!(pushed.slider_applied_force, stepped.slider_applied_force);
        assert_eq!(
            bits(&read_checked(&mut engine, t, inputs.reading())),
            bits(&stepped)
        );
        let later = read_checked(&mut engine, 2e-4, inputs.reading());
        assert_ne!(later.time, stepped.time);
        engine.restore(&snapshot).unwrap();
        let mut inputs = InputRecord::held(start_inputs, 0.0);
        assert_eq!(
            bits(&read_checked(&mut engine, 0.0, inputs.reading())),
            bits(&start)
        );
        step(&mut engine, &mut inputs, 0.0, 1e-4, plain);
        let pausing = Mode {
            stop_at_onset: false,
            pause: true,
        };
        let Advance::Paused(pause) = step(&mut engine, &mut inputs, t, 1e-3, pausing) else {
            panic!("no pause before 1e-3 s");
        };
        let paused = read_checked(&mut engine, pause, inputs.reading());
        let ended = engine.end_at_pause(inputs.stepping()).unwrap().unwrap();
        assert_ne!(
            bits(&read_checked(&mut engine, ended, inputs.reading())),
            bits(&paused)
        );
    }
}
