//! The slider-crank's records in the byte codec of snapshots (`fmi_core::codec`): contact
//! state, peaks, input signals, integrator statistics, step points. Used by [`super::Snapshot`]
//! and by the FMU state that wraps it.

pub use fmi_core::codec::{ByteReader, ByteWriter, CodecError};

use super::peaks::{Peaks, Sample};
use super::step::StepPoint;
use crate::integrator::Stats;
use crate::mechanism::{ContactState, Contacts, InputSignal, Inputs};

/// The ten numbers of an input signal: start, then value, first and second derivatives, each
/// as (drive speed, drive torque, slider force).
pub fn signal_values(s: &InputSignal) -> [f64; 10] {
    let mut v = [s.start; 10];
    for (k, i) in [s.value, s.derivatives[0], s.derivatives[1]]
        .iter()
        .enumerate()
    {
        v[1 + 3 * k..4 + 3 * k].copy_from_slice(&[i.drive_speed, i.drive_torque, i.slider_force]);
    }
    v
}

/// Writes the slider-crank's records.
pub trait WriteRecords {
    /// Writes the contact states of the joints.
    fn contact(&mut self, contacts: &Contacts);
    /// Writes a step point: its time, state and derivative.
    fn step_point(&mut self, p: &StepPoint);
    /// Writes peak values.
    fn peaks(&mut self, p: &Peaks);
    /// Writes an input signal ([`signal_values`]).
    fn signal(&mut self, s: &InputSignal);
    /// Writes integrator statistics.
    fn stats(&mut self, s: &Stats);
}

impl WriteRecords for ByteWriter<'_> {
    /// Writes the contact states of the joints.
    fn contact(&mut self, contacts: &Contacts) {
        for c in &contacts.0 {
            self.flag(c.in_contact);
            self.f64(c.impact_velocity);
        }
    }
    /// Writes a step point: its time, state and derivative.
    fn step_point(&mut self, p: &StepPoint) {
        self.f64(p.time);
        self.f64s(&p.y);
        self.f64s(&p.f);
    }
    /// Writes peak values.
    fn peaks(&mut self, p: &Peaks) {
        for x in p.sample() {
            self.f64(x);
        }
        for onsets in p.contact_onsets {
            self.u64(onsets);
        }
    }
    /// Writes an input signal ([`signal_values`]).
    fn signal(&mut self, s: &InputSignal) {
        for x in signal_values(s) {
            self.f64(x);
        }
    }
    /// Writes integrator statistics.
    fn stats(&mut self, s: &Stats) {
        for x in [
            s.steps,
            s.rejected,
            s.evaluations,
            s.newton_iterations,
            s.jacobians,
            s.factorizations,
        ] {
            self.u64(x);
        }
    }
}

/// Reads the slider-crank's records.
pub trait ReadRecords {
    /// Reads the contact states of the joints.
    fn contact(&mut self) -> Result<Contacts, CodecError>;
    /// Reads a step point.
    fn step_point(&mut self) -> Result<StepPoint, CodecError>;
    /// Reads peak values.
    fn peaks(&mut self) -> Result<Peaks, CodecError>;
    /// Reads an input signal.
    fn signal(&mut self) -> Result<InputSignal, CodecError>;
    /// Reads integrator statistics.
    fn stats(&mut self) -> Result<Stats, CodecError>;
}

impl ReadRecords for ByteReader<'_> {
    /// Reads the contact states of the joints.
    fn contact(&mut self) -> Result<Contacts, CodecError> {
        let mut contacts = Contacts::default();
        for c in &mut contacts.0 {
            *c = ContactState {
                in_contact: self.flag()?,
                impact_velocity: self.f64()?,
            };
        }
        Ok(contacts)
    }
    /// Reads a step point.
    fn step_point(&mut self) -> Result<StepPoint, CodecError> {
        Ok(StepPoint {
            time: self.f64()?,
            y: self.f64s()?,
            f: self.f64s()?,
        })
    }
    /// Reads peak values.
    fn peaks(&mut self) -> Result<Peaks, CodecError> {
        let mut sample = Sample::default();
        for x in &mut sample {
            *x = self.f64()?;
        }
        Ok(Peaks::from_sample(
            sample,
            [self.u64()?, self.u64()?, self.u64()?],
        ))
    }
    /// Reads an input signal.
    fn signal(&mut self) -> Result<InputSignal, CodecError> {
        let start = self.f64()?;
        let mut inputs = [Inputs::default(); 3];
        for i in &mut inputs {
            *i = Inputs {
                drive_speed: self.f64()?,
                drive_torque: self.f64()?,
                slider_force: self.f64()?,
            };
        }
        let [value, first, second] = inputs;
        Ok(InputSignal {
            start,
            value,
            derivatives: [first, second],
        })
    }
    /// Reads integrator statistics.
    fn stats(&mut self) -> Result<Stats, CodecError> {
        Ok(Stats {
            steps: self.u64()?,
            rejected: self.u64()?,
            evaluations: self.u64()?,
            newton_iterations: self.u64()?,
            jacobians: self.u64()?,
            factorizations: self.u64()?,
        })
    }
}
