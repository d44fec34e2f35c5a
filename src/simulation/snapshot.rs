//! A complete, restorable state of a simulation, and its bytes.

use super::codec::{ByteReader, ByteWriter, CodecError, ReadRecords, WriteRecords};
use super::peaks::PeakHold;
use super::step::StepPoint;
use crate::integrator::{ImplicitState, IntegratorState};
use crate::mechanism::{Contacts, Input, Inputs};
use fmi_core::signal::InputValues;

/// A complete, restorable state of an [`super::Engine`] (its parameters, and the current point
/// and the inputs, which its owner holds, excepted).
#[derive(Clone, Debug, PartialEq)]
pub struct Snapshot {
    /// State at the current point.
    pub state: Vec<f64>,
    /// The start of the last accepted step.
    pub step_start: StepPoint,
    /// The contact state at the step's start.
    pub contact_start: Contacts,
    /// The end of the last accepted step (the integrator's point, at or after the current one).
    pub step_end: StepPoint,
    /// Integrator state (step size, f at the step end, Jacobian, statistics).
    pub integrator: IntegratorState,
    /// Contact states at the step end.
    pub contact: Contacts,
    /// The elastic energy each joint's contact stored at the start \[J\].
    pub contact_at_start: [f64; 3],
    /// The inputs the start state is in equilibrium with.
    pub start_inputs: Inputs,
    /// Peak-hold outputs.
    pub peaks: PeakHold,
    /// Warnings raised since the start.
    pub warnings: u64,
}

impl Snapshot {
    /// Whether every time, state and start input is a finite number.
    pub fn is_finite(&self) -> bool {
        let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
        let start = &self.start_inputs;
        finite(&self.state)
            && finite(&self.contact_at_start)
            && self.step_start.is_finite()
            && self.step_end.is_finite()
            && finite(&Input::ALL.map(|input| start.get(input)))
    }

    /// Appends the pointer-free bytes of the snapshot.
    pub fn write(&self, w: &mut ByteWriter<'_>) {
        w.f64s(&self.state);
        w.step_point(&self.step_start);
        w.contact(&self.contact_start);
        w.step_point(&self.step_end);
        match &self.integrator {
            IntegratorState::DormandPrince {
                h,
                derivative,
                stats,
            } => {
                w.u8(0);
                w.f64(*h);
                w.f64s(derivative);
                w.stats(stats);
            }
            IntegratorState::Implicit(e) => {
                w.u8(1);
                w.f64(e.h);
                w.f64(e.h_factored);
                w.f64s(&e.jacobian_q);
                w.f64s(&e.jacobian_v);
                w.f64s(&e.jacobian_w);
                w.u8(u8::from(e.jacobian_stale));
                w.f64(e.newton_rate);
                w.f64s(&e.history);
                w.f64(e.history_step);
                w.f64s(&e.derivative);
                w.f64s(&e.acceleration);
                w.f64s(&e.acceleration_start);
                w.stats(&e.stats);
            }
        }
        w.contact(&self.contact);
        self.contact_at_start.iter().for_each(|&e| w.f64(e));
        for input in Input::ALL {
            w.f64(self.start_inputs.get(input));
        }
        w.peaks(&self.peaks.interval);
        w.peaks(&self.peaks.step_end);
        w.u8(u8::from(self.peaks.pending));
        for total in self.peaks.total_onsets {
            w.u64(total);
        }
        w.peaks(&self.peaks.since_start);
        w.cycle_step(&self.peaks.cycle_step);
        w.cycles(&self.peaks.cycles);
        w.u64(self.warnings);
    }

    /// Reads a snapshot written by [`Snapshot::write`] (finiteness is checked by
    /// [`Snapshot::is_finite`]).
    pub fn read(r: &mut ByteReader<'_>) -> Result<Self, CodecError> {
        let state_vector = r.f64s()?;
        let step_start = r.step_point()?;
        let contact_start = r.contact()?;
        let step_end = r.step_point()?;
        let integrator = match r.u8()? {
            0 => IntegratorState::DormandPrince {
                h: r.f64()?,
                derivative: r.f64s()?,
                stats: r.stats()?,
            },
            1 => IntegratorState::Implicit(ImplicitState {
                h: r.f64()?,
                h_factored: r.f64()?,
                jacobian_q: r.f64s()?,
                jacobian_v: r.f64s()?,
                jacobian_w: r.f64s()?,
                jacobian_stale: r.flag()?,
                newton_rate: r.f64()?,
                history: r.f64s()?,
                history_step: r.f64()?,
                derivative: r.f64s()?,
                acceleration: r.f64s()?,
                acceleration_start: r.f64s()?,
                stats: r.stats()?,
            }),
            m => {
                return Err(CodecError(format!(
                    "FMU state rejected: unknown integrator {m}"
                )));
            }
        };
        let contact = r.contact()?;
        let contact_at_start = [r.f64()?, r.f64()?, r.f64()?];
        Ok(Self {
            state: state_vector,
            step_start,
            contact_start,
            step_end,
            integrator,
            contact,
            contact_at_start,
            start_inputs: {
                let mut start = <Inputs as InputValues>::ZERO;
                for input in Input::ALL {
                    *start.get_mut(input) = r.f64()?;
                }
                start
            },
            peaks: PeakHold {
                interval: r.peaks()?,
                step_end: r.peaks()?,
                pending: r.flag()?,
                total_onsets: [r.u64()?, r.u64()?, r.u64()?],
                since_start: r.peaks()?,
                cycle_step: r.cycle_step()?,
                cycles: r.cycles()?,
            },
            warnings: r.u64()?,
        })
    }
}
