//! The byte codec of snapshots: little-endian numbers, length-prefixed vectors, flags, and the
//! model's small records (contact state, peaks, input signals, integrator statistics). Used by
//! [`super::Snapshot`] and by the FMU state that wraps it.

use super::peaks::Peaks;
use super::step::StepPoint;
use crate::integrator::Stats;
use crate::mechanism::{ContactState, Contacts, InputSignal, Inputs};

/// Largest accepted vector length (states, Jacobian entries) in a snapshot.
const MAX_LENGTH: usize = 1 << 20;

/// Why bytes could not be read.
#[derive(Clone, Debug, PartialEq)]
pub struct CodecError(pub String);

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

/// Appends little-endian values to a byte vector.
pub struct ByteWriter<'a>(pub &'a mut Vec<u8>);

impl ByteWriter<'_> {
    /// Writes a byte.
    pub fn u8(&mut self, v: u8) {
        self.0.push(v);
    }
    /// Writes a u32.
    pub fn u32(&mut self, v: u32) {
        self.0.extend_from_slice(&v.to_le_bytes());
    }
    /// Writes a u64.
    pub fn u64(&mut self, v: u64) {
        self.0.extend_from_slice(&v.to_le_bytes());
    }
    /// Writes an f64 by its bits.
    pub fn f64(&mut self, v: f64) {
        self.u64(v.to_bits());
    }
    /// Writes a vector: its length (u32), then its values.
    pub fn f64s(&mut self, v: &[f64]) {
        self.u32(v.len() as u32);
        for x in v {
            self.f64(*x);
        }
    }
    /// Writes the contact states of the joints.
    pub fn contact(&mut self, contacts: &Contacts) {
        for c in &contacts.0 {
            self.u8(u8::from(c.in_contact));
            self.f64(c.impact_velocity);
        }
    }
    /// Writes a step point: its time, state and derivative.
    pub fn step_point(&mut self, p: &StepPoint) {
        self.f64(p.time);
        self.f64s(&p.y);
        self.f64s(&p.f);
    }
    /// Writes peak values.
    pub fn peaks(&mut self, p: &Peaks) {
        self.f64(p.joint_force);
        self.f64(p.slider_acceleration);
        self.f64(p.deformation_energy);
        self.f64(p.crank_pin_force);
        self.f64(p.main_bearing_force);
        self.f64(p.guide_force);
        self.f64(p.rod_stress);
        for onsets in p.contact_onsets {
            self.u64(onsets);
        }
    }
    /// Writes an input signal ([`signal_values`]).
    pub fn signal(&mut self, s: &InputSignal) {
        for x in signal_values(s) {
            self.f64(x);
        }
    }
    /// Writes integrator statistics.
    pub fn stats(&mut self, s: &Stats) {
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

/// Reads what [`ByteWriter`] wrote, refusing truncated input, over-long vectors and invalid flags.
pub struct ByteReader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> ByteReader<'a> {
    /// A reader at the start of `bytes`.
    pub fn new(bytes: &'a [u8]) -> Self {
        Self { bytes, at: 0 }
    }

    /// Bytes not read yet.
    pub fn remaining(&self) -> usize {
        self.bytes.len() - self.at
    }

    /// The next `n` bytes.
    pub fn take(&mut self, n: usize) -> Result<&[u8], CodecError> {
        let end = self
            .at
            .checked_add(n)
            .filter(|&e| e <= self.bytes.len())
            .ok_or_else(|| {
                CodecError(format!("FMU state truncated: {} bytes", self.bytes.len()))
            })?;
        let out = &self.bytes[self.at..end];
        self.at = end;
        Ok(out)
    }
    /// Reads a byte.
    pub fn u8(&mut self) -> Result<u8, CodecError> {
        Ok(self.take(1)?[0])
    }
    /// Reads a u32.
    pub fn u32(&mut self) -> Result<u32, CodecError> {
        let mut b = [0; 4];
        b.copy_from_slice(self.take(4)?);
        Ok(u32::from_le_bytes(b))
    }
    /// Reads a u64.
    pub fn u64(&mut self) -> Result<u64, CodecError> {
        let mut b = [0; 8];
        b.copy_from_slice(self.take(8)?);
        Ok(u64::from_le_bytes(b))
    }
    /// Reads an f64.
    pub fn f64(&mut self) -> Result<f64, CodecError> {
        Ok(f64::from_bits(self.u64()?))
    }
    /// Reads a vector of at most 2^20 values.
    pub fn f64s(&mut self) -> Result<Vec<f64>, CodecError> {
        let n = self.u32()? as usize;
        if n > MAX_LENGTH {
            return Err(CodecError(format!(
                "FMU state rejected: a vector of {n} values"
            )));
        }
        (0..n).map(|_| self.f64()).collect()
    }
    /// Reads the contact states of the joints.
    pub fn contact(&mut self) -> Result<Contacts, CodecError> {
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
    pub fn step_point(&mut self) -> Result<StepPoint, CodecError> {
        Ok(StepPoint {
            time: self.f64()?,
            y: self.f64s()?,
            f: self.f64s()?,
        })
    }
    /// Reads peak values.
    pub fn peaks(&mut self) -> Result<Peaks, CodecError> {
        Ok(Peaks {
            joint_force: self.f64()?,
            slider_acceleration: self.f64()?,
            deformation_energy: self.f64()?,
            crank_pin_force: self.f64()?,
            main_bearing_force: self.f64()?,
            guide_force: self.f64()?,
            rod_stress: self.f64()?,
            contact_onsets: [self.u64()?, self.u64()?, self.u64()?],
        })
    }
    /// Reads an input signal.
    pub fn signal(&mut self) -> Result<InputSignal, CodecError> {
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
    pub fn stats(&mut self) -> Result<Stats, CodecError> {
        Ok(Stats {
            steps: self.u64()?,
            rejected: self.u64()?,
            evaluations: self.u64()?,
            newton_iterations: self.u64()?,
            jacobians: self.u64()?,
            factorizations: self.u64()?,
        })
    }
    /// Reads a flag: 0 or 1, any other byte is an error.
    pub fn flag(&mut self) -> Result<bool, CodecError> {
        match self.u8()? {
            0 => Ok(false),
            1 => Ok(true),
            b => Err(CodecError(format!("FMU state: invalid flag byte {b}"))),
        }
    }
}
