//! One communication interval: the inputs applied at its start, the accepted steps through it, and
//! its end, the state there from the dense output of the last step. The steps may stop early at
//! a contact onset (an early return, which ends the interval there) or pause after each accepted
//! step for a master that reads the state inside the interval (FMI 3 intermediate update): a
//! paused interval resumes where it paused, on the same step sequence, or ends at the pause.

use fmi_core::clock::{on_clock_grid, on_clock_grid_below};

use super::failure;
use super::peaks::Peaks;
use super::step::{Advance, Interval, Mode, Onset};
use super::{Engine, InputRecord, InputSignal, Inputs};
use crate::error::{ModelError, Num};
use crate::mechanism::Driven;

/// How the steps through an interval ended.
enum Progress {
    /// At the interval's end; whether the last step, recorded in this call, was divided there.
    End {
        divided: bool,
    },
    Onset(Onset),
    Paused,
}

impl Engine {
    /// Integrates from the current point `t` towards `t_end` (rounded to the clock grid) with the
    /// next step's inputs of `inputs` ([`InputRecord::stepping`]: polynomials of time over the
    /// interval). An input that acts in the drive mode and is not the same function of time as
    /// over the last step restarts the step sequence here; a change of the prescribed speed is
    /// applied as an impulsive velocity adjustment through the constraints. An input that does
    /// not act (the torque with the speed drive, the speed with the torque drive) restarts
    /// nothing.
    ///
    /// With `mode.stop_at_onset` it stops early at the end of the first internal step in which a
    /// joint comes into contact (where the contact law switches on), if that is before `t_end`:
    /// the joint and the time reached, the step's end rounded down to the clock grid (at most one
    /// clock tick earlier; the step's extremes and onset belong to the interval that ends there).
    /// The step sequence is the one of a plain interval: continuing from the time reached loses
    /// nothing. With `mode.pause` it pauses after every accepted step ending before `t_end` (by a
    /// clock tick at least), with the state at the step's end the current one (the outputs read
    /// it at the pause's time); called again with `resume` and the same `t` and `t_end`, it
    /// resumes the paused interval, whose steps, peaks and results are those of an interval
    /// that never paused. [`Engine::end_at_pause`] ends it at the pause instead.
    ///
    /// On failure the engine stays at the last accepted step (the time it reached is the error's
    /// [`Engine::reached`]) and the error says why.
    pub fn advance(
        &mut self,
        t: f64,
        inputs: &InputRecord<Inputs>,
        t_end: f64,
        mode: Mode,
        resume: bool,
    ) -> Result<Advance, ModelError> {
        self.last_read = None;
        let t_end = on_clock_grid(t_end);
        let interval = if resume {
            if self.interval.t_end != t_end {
                return Err(ModelError::Numerical(format!(
                    "cannot resume the interval to t = {} s towards t = {} s",
                    Num(self.interval.t_end),
                    Num(t_end)
                )));
            }
            self.interval
        } else {
            self.begin_interval(t, inputs, t_end)?
        };
        let signal = inputs.stepping();
        match self.step_through(interval, signal, resume, mode)? {
            Progress::Paused => {
                self.state.copy_from_slice(&self.end.y);
                Ok(Advance::Paused(self.end.time))
            }
            Progress::Onset(onset) => {
                self.finish_interval(signal, onset.time, false)?;
                Ok(Advance::Onset(onset))
            }
            Progress::End { divided } => {
                self.finish_interval(signal, t_end, divided)?;
                Ok(Advance::Reached(t_end))
            }
        }
    }

    /// The time a failed interval reached: the end of the last accepted step, where the engine
    /// stays usable.
    pub fn reached(&self) -> f64 {
        self.end.time
    }

    /// Ends a paused interval at the pause, rounded down to the clock grid, as an early return
    /// does, the inputs `signal` those it was integrated with: the time reached, or None (the
    /// interval stays paused) where that is not after the interval's start.
    pub fn end_at_pause(&mut self, signal: &InputSignal) -> Result<Option<f64>, ModelError> {
        let reached = on_clock_grid_below(self.end.time);
        if reached <= self.interval.t_start {
            return Ok(None);
        }
        self.last_read = None;
        self.finish_interval(signal, reached, false)?;
        Ok(Some(reached))
    }

    /// Starts the interval from `t` to `t_end`: `inputs` applied, the interval's peaks cleared.
    fn begin_interval(
        &mut self,
        t: f64,
        inputs: &InputRecord<Inputs>,
        t_end: f64,
    ) -> Result<Interval, ModelError> {
        if !(t_end.is_finite() && t_end >= t) {
            return Err(ModelError::Numerical(format!(
                "cannot advance from t = {} s to t = {} s",
                Num(t),
                Num(t_end)
            )));
        }
        let limit = self.apply_inputs(t, inputs, t_end)?;
        self.peaks.interval = Peaks::default();
        self.interval = Interval {
            t_start: t,
            t_end,
            limit,
            work_start: self.work(),
        };
        Ok(self.interval)
    }

    /// Steps until the integrator's point reaches the interval's end (at most at its limit), with
    /// the inputs `signal`, recording each accepted step's peaks; on failure the engine stops at
    /// the last accepted step. If `mode.stop_at_onset`, it stops after the first step before the
    /// end in which a joint comes into contact (also a step pending from the last interval,
    /// unless `resumed`) with that joint and the step's end on the clock grid (rounded down,
    /// after the start); if `mode.pause`, after every accepted step before the end.
    fn step_through(
        &mut self,
        interval: Interval,
        signal: &InputSignal,
        resumed: bool,
        mode: Mode,
    ) -> Result<Progress, ModelError> {
        let Interval {
            t_start,
            t_end,
            limit,
            work_start,
        } = interval;
        let stop_at_onset = mode.stop_at_onset;
        if !resumed && self.peaks.pending && self.end.time <= t_end {
            self.peaks.take_step_end();
            if let Some(onset) = self.onset_before(t_start, t_end, stop_at_onset) {
                return Ok(Progress::Onset(onset));
            }
        }
        let mut divided = false;
        while self.end.time < t_end {
            let used = self.work() - work_start;
            let budget = (self.parameters.max_steps_per_interval as u64).saturating_sub(used);
            self.start.time = self.end.time;
            self.start.y.copy_from_slice(&self.end.y);
            self.contact_start = self.contacts;
            let mut driven = Driven {
                mechanism: &mut self.mechanism,
                signal,
                contacts: &mut self.contacts,
            };
            match self.integrator.step(
                &mut driven,
                &mut self.end.time,
                &mut self.end.y,
                limit,
                budget,
            ) {
                Ok(true) => {}
                Ok(false) => {
                    let error = failure::work_limit(
                        &self.parameters,
                        (t_start, t_end),
                        self.end.time,
                        self.integrator.step_size(),
                    );
                    return Err(self.stop_at_step_end(error));
                }
                Err(e) => {
                    let error = failure::step_failure(&self.parameters, e);
                    return Err(self.stop_at_step_end(error));
                }
            }
            let (f0, f1) = self.integrator.derivatives();
            self.start.f.copy_from_slice(f0);
            self.end.f.copy_from_slice(f1);
            divided = self.record_step_end(signal)?;
            if self.end.time <= t_end {
                self.peaks.take_step_end();
            }
            if let Some(onset) = self.onset_before(t_start, t_end, stop_at_onset) {
                return Ok(Progress::Onset(onset));
            }
            // (a step that ends within a clock tick of the end has reached it)
            if mode.pause && on_clock_grid(self.end.time) < t_end {
                return Ok(Progress::Paused);
            }
        }
        Ok(Progress::End { divided })
    }

    /// Ends the interval at `t_end`: the state there (the dense output of the last step, with
    /// the inputs `signal`, when it ends beyond, whose crossing of a cycle boundary before
    /// `t_end` completes the cycle, and whose extremes are divided there unless `divided`
    /// already, when it was recorded).
    fn finish_interval(
        &mut self,
        signal: &InputSignal,
        t_end: f64,
        divided: bool,
    ) -> Result<(), ModelError> {
        if t_end == self.end.time {
            self.state.copy_from_slice(&self.end.y);
        } else {
            self.peaks.complete_cycle_before(t_end);
            if !divided {
                self.divide_pending_step(signal, t_end)?;
            }
            let span = self.start.span_to(&self.end);
            // the contact states the step was integrated with
            let mut contacts = self.contact_start;
            let mut driven = Driven {
                mechanism: &mut self.mechanism,
                signal,
                contacts: &mut contacts,
            };
            let s = (t_end - span.t0) / span.h;
            self.integrator
                .dense_output(&mut driven, &span, s, &mut self.state)?;
            self.check_validity(Some(t_end));
        }
        Ok(())
    }

    /// Ends a failed interval at the last accepted step (where the engine stays usable) and
    /// passes the error on.
    fn stop_at_step_end(&mut self, error: ModelError) -> ModelError {
        self.state.copy_from_slice(&self.end.y);
        error
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Simulation;
    use crate::params::Parameters;

    /// Pausing after every accepted step changes nothing: 3 ms of the defaults' impacts in 0.5 ms
    /// intervals, paused at every step with the outputs read there, end each interval on the
    /// same state, bit for bit, as without pauses; every pause lies inside its interval, at the
    /// time of the state there.
    #[test]
    fn pausing_after_every_step_changes_nothing() {
        let mut plain = Simulation::new(Parameters::default()).unwrap();
        let mut paused = plain.clone();
        let inputs = *plain.inputs();
        let mut pauses = 0;
        for k in 1..=6 {
            let (t_start, t_end) = (f64::from(k - 1) * 5e-4, f64::from(k) * 5e-4);
            plain.advance_to(t_end).unwrap();
            while let Advance::Paused(t) = paused.advance_pausing(&inputs, t_end, false).unwrap() {
                assert!(t_start < t && t < t_end, "{t}");
                assert!(paused.is_paused());
                assert_eq!(paused.time(), t);
                assert_eq!(paused.outputs().unwrap().time, t);
                pauses += 1;
            }
            assert!(!paused.is_paused());
            assert_eq!(
                (paused.time(), paused.state()),
                (plain.time(), plain.state())
            );
        }
        assert!(pauses > 20, "{pauses} pauses");
    }

    /// Each interval holds the extremes of the solution inside it, also where the internal steps
    /// are longer than the communication step and a step's peak lies in an earlier interval than
    /// its end: the lubricated joint's force (sampled inside every step) peaks over 1 µs
    /// intervals within 2e-3 of its largest value of the largest of its values every 0.1 µs
    /// inside each, through the first millisecond (internal steps of several microseconds; the
    /// steps do not depend on the communication points). The peak-hold samples the quintic
    /// Hermite interpolant, the outputs the integrator's dense output, whose part beyond the
    /// cubic is filtered: they differ by 1.1e-3 of the largest value here. A step's peak taken
    /// into the interval where the step ends, wherever it lies in the step, errs by 4.3 %.
    #[test]
    fn each_interval_holds_the_peak_inside_it() {
        use crate::params::JointModel;
        let mut p = Parameters::default();
        p.joint.model = JointModel::Lubricated;
        let mut coarse = Simulation::new(p).unwrap();
        let mut fine = coarse.clone();
        let (n, sub): (u32, usize) = (1000, 10);
        let mut values = vec![fine.outputs().unwrap().joint_force];
        for k in 1..=n * sub as u32 {
            fine.advance_to(f64::from(k) * 1e-7).unwrap();
            values.push(fine.outputs().unwrap().joint_force);
        }
        let largest = values.iter().copied().fold(0.0, f64::max);
        let mut worst: f64 = 0.0;
        for j in 1..=n {
            coarse.advance_to(f64::from(j) * 1e-6).unwrap();
            let peak = coarse.outputs().unwrap().joint_force_peak;
            let inside = values[(j as usize - 1) * sub..=j as usize * sub]
                .iter()
                .copied()
                .fold(0.0, f64::max);
            worst = worst.max((peak - inside).abs() / largest);
        }
        assert!(
            coarse.stats().steps < u64::from(n / 2),
            "{:?}",
            coarse.stats()
        );
        assert!(worst < 2e-3, "{worst:e}");
    }

    /// Ending at a pause is an early return there: the time reached is the step's end rounded
    /// down to the clock grid, and the next interval starts from it.
    #[test]
    fn ending_at_a_pause_is_an_early_return_on_the_clock_grid() {
        let mut sim = Simulation::new(Parameters::default()).unwrap();
        let inputs = *sim.inputs();
        let Advance::Paused(t) = sim.advance_pausing(&inputs, 1e-3, false).unwrap() else {
            panic!("no pause");
        };
        let reached = sim.end_at_pause().unwrap().unwrap();
        assert!(!sim.is_paused());
        assert_eq!(reached, on_clock_grid_below(t));
        assert_eq!(sim.time(), reached);
        sim.advance_to(1e-3).unwrap();
        assert_eq!(sim.time(), on_clock_grid(1e-3));
    }
}
