//! The bookkeeping of each accepted step: the peak-hold outputs' extremes at its end and inside
//! it, its contact onsets, and the check of a lubricated joint's peak inside it.

use super::cycle::CycleStep;
use super::peaks::{self, Peaks};
use super::sample::{Sample, force_series};
use super::within::{self, AcceptedStep, KnownEnds};
use super::{Engine, InputSignal};
use crate::error::ModelError;
use crate::joint::{Joint, JointRates, JointRole};
use crate::mechanism::layout::CRANK_ANGLE;
use crate::mechanism::{Conditions, Driven};

impl Engine {
    /// Evaluates the end of the step just accepted, integrated with the inputs `signal`, for the
    /// peak-hold outputs. A step that ends after the current interval (which it then ends,
    /// [`Engine::finish_interval`]) is divided at the interval's end: the interval takes its
    /// extremes before it, the step keeps those after it; the return value says whether it was.
    pub(super) fn record_step_end(&mut self, signal: &InputSignal) -> Result<bool, ModelError> {
        let end = self.contacts;
        let onsets = JointRole::ALL
            .map(|role| u64::from(!self.contact_start[role].in_contact && end[role].in_contact));
        let (at_end, from_joint_law) = self.step_end_sample(signal)?;
        let step = AcceptedStep {
            start: &self.start,
            end: &self.end,
            contact_start: self.contact_start,
            contact_end: end,
            signal,
        };
        let known = KnownEnds {
            start: self.end_sample.at(&self.start, signal, self.contact_start),
            end: (from_joint_law && self.contact_start == end).then_some(at_end),
        };
        let (t0, t1) = (self.start.time, self.end.time);
        let division = (t1 > self.interval.t_end).then(|| {
            let at = (self.interval.t_end - t0) / (t1 - t0);
            let (y, a) = (&mut self.y_sample, &mut self.a_sample);
            within::divided_step(&mut self.mechanism, &step, (0.0, at), known, y, a)
        });
        let within = match &division {
            Some(division) => division.whole,
            None => within::within_step(
                &mut self.mechanism,
                &step,
                known,
                &mut self.y_sample,
                &mut self.a_sample,
            ),
        };
        self.end_sample
            .store(&self.end, signal, end, from_joint_law.then_some(at_end));
        self.doubt_film_peaks(&within, signal)?;
        for role in JointRole::ALL {
            if onsets[role as usize] > 0
                && matches!(self.mechanism.joint(role), Joint::Lubricated(_))
            {
                self.monitor.metal_contact(role, self.end.time);
            }
        }
        let inside = match &division {
            Some(division) => {
                self.peaks.take_before(division.before);
                division.after
            }
            None => within.largest,
        };
        self.peaks.step_end = Peaks::from_sample(peaks::larger(at_end, inside), onsets);
        self.peaks.cycle_step = Some(self.cycle_step(at_end, &within, signal));
        self.peaks.pending = true;
        self.check_validity(None);
        Ok(division.is_some())
    }

    /// The peak-held magnitudes at the end of the step just accepted, under the contact states at
    /// its end, and whether they come from the joint law alone (the clearance joint's load, which
    /// is then the one the dense output gives there) rather than a whole evaluation.
    fn step_end_sample(&mut self, signal: &InputSignal) -> Result<(Sample, bool), ModelError> {
        let end = self.contacts;
        let c = Conditions::at(signal, self.end.time, &end);
        let film = self.mechanism.film_extremes(&self.end.y);
        Ok(match self.mechanism.clearance_joint_load(&self.end.y, &c) {
            Some((force, acceleration)) => {
                let loads = self.mechanism.loads(&self.end.y, &self.end.f, force, &end);
                (peaks::sample(force, acceleration, &loads, film), true)
            }
            None => {
                let ev = *self
                    .mechanism
                    .evaluate(&self.end.y, &c, &mut self.scratch)?;
                let loads = self
                    .mechanism
                    .loads(&self.end.y, &self.scratch, ev.joint_force, &end);
                let sample = peaks::sample(ev.joint_force, ev.slider_acceleration, &loads, film);
                (sample, false)
            }
        })
    }

    /// Divides the extremes of the pending step, which the interval ending at `t_end` ends
    /// inside, at `t_end` (a step that ends after the interval it started in is divided when it
    /// is recorded, [`Engine::record_step_end`]; this divides a step across an interval it did
    /// not start in, and one an interval ends inside early): the interval takes the step's
    /// extremes from the interval's start (or the step's, if later) to `t_end`, and the step
    /// keeps, for the intervals after, those from `t_end` to its end with its end's value. So
    /// each interval holds the extremes of the part of the solution inside it, whatever the
    /// internal steps' lengths against the communication step.
    pub(super) fn divide_pending_step(
        &mut self,
        signal: &InputSignal,
        t_end: f64,
    ) -> Result<(), ModelError> {
        let step = AcceptedStep {
            start: &self.start,
            end: &self.end,
            contact_start: self.contact_start,
            contact_end: self.contacts,
            signal,
        };
        if !within::sampled_inside(&self.mechanism, &step) {
            return Ok(());
        }
        let (t0, h) = (self.start.time, self.end.time - self.start.time);
        let from = ((self.interval.t_start - t0) / h).max(0.0);
        let at = (t_end - t0) / h;
        // the step's end as its recording kept it, where that is the dense output's there
        let known = KnownEnds {
            start: None,
            end: self.end_sample.at(&self.end, signal, self.contact_start),
        };
        let (y, a) = (&mut self.y_sample, &mut self.a_sample);
        let division = within::divided_step(&mut self.mechanism, &step, (from, at), known, y, a);
        self.peaks.take_before(division.before);
        let at_end = match self.end_sample.at(&self.end, signal, self.contacts) {
            Some(sample) => sample,
            None => self.step_end_sample(signal)?.0,
        };
        let onsets = self.peaks.step_end.contact_onsets;
        self.peaks.step_end = Peaks::from_sample(peaks::larger(at_end, division.after), onsets);
        Ok(())
    }

    /// What the step just accepted brings to the cycle results ([`super::cycle`]): its ends'
    /// times and crank angles, its samples, and each joint's friction power and oil flow at its
    /// ends.
    fn cycle_step(
        &self,
        at_end: Sample,
        within: &within::Within,
        signal: &InputSignal,
    ) -> CycleStep {
        let rates = [&self.start, &self.end].map(|point| {
            let pressure = signal.at(point.time).oil_supply_pressure;
            self.mechanism
                .joint_rates(&point.y, &self.contacts, pressure)
        });
        let ends =
            |f: fn(&JointRates) -> f64| std::array::from_fn(|i| [f(&rates[0][i]), f(&rates[1][i])]);
        CycleStep {
            from: 0.0,
            time: [self.start.time, self.end.time],
            angle: [self.start.y[CRANK_ANGLE], self.end.y[CRANK_ANGLE]],
            at_end,
            inside: within.largest,
            place: within.place,
            friction_power: ends(|r| r.friction_power),
            oil_flow: ends(|r| r.oil_flow),
            asperity_force: ends(|r| r.asperity_force),
            in_contact: std::array::from_fn(|i| {
                [
                    self.contact_start.0[i].in_contact,
                    self.contacts.0[i].in_contact,
                ]
            }),
            film_temperature: JointRole::ALL.map(|role| {
                [&self.start.y, &self.end.y]
                    .map(|y| self.mechanism.film_temperature(role, y).unwrap_or(0.0))
            }),
        }
    }

    /// Warns, once per joint, of a lubricated joint's force peak inside the step just accepted
    /// that the interpolant decides: one that rose more than [`within::PEAK_TOLERANCE`] above the
    /// step's ends ([`within::interpolated_peak`]) and differs by more than that from the force in
    /// the integrator's own solution at its place ([`crate::integrator::Integrator::state_within`],
    /// a partial step: the check costs a step only where such a rise occurs).
    fn doubt_film_peaks(
        &mut self,
        within: &within::Within,
        signal: &InputSignal,
    ) -> Result<(), ModelError> {
        let known = peaks::larger(
            self.peaks.since_start.sample(),
            self.peaks.interval.sample(),
        );
        for role in JointRole::ALL {
            let i = force_series(role);
            let film = matches!(self.mechanism.joint(role), Joint::Lubricated(_));
            let (value, rise) = (within.largest[i], within.rise[i]);
            if !(film && within::interpolated_peak(value, rise, known[i])) {
                continue;
            }
            let span = self.start.span_to(&self.end);
            let (t0, h) = (span.t0, span.h);
            let s = within.place[i];
            // under the contact states the step was integrated with
            let mut contacts = self.contact_start;
            let mut driven = Driven {
                mechanism: &mut self.mechanism,
                signal,
                contacts: &mut contacts,
            };
            let y = &mut self.y_sample;
            self.integrator.state_within(&mut driven, &span, s, y)?;
            let integrated = self
                .mechanism
                .joint_force(role, y, &contacts)
                .0
                .force
                .norm();
            if (integrated - value).abs() > within::PEAK_TOLERANCE * value {
                self.monitor.doubt_peak(role, t0 + s * h, value, integrated);
            }
        }
        Ok(())
    }
}
