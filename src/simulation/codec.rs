//! The slider-crank's records in the byte codec of snapshots (`fmi_core::codec`): contact
//! state, peaks, input signals, integrator statistics, step points. Used by [`super::Snapshot`]
//! and by the FMU state that wraps it.

pub use fmi_core::codec::{ByteReader, ByteWriter, CodecError};

use super::cycle::{Cycle, CycleHold, CycleStep, Extreme, JointCycle};
use super::peaks::Peaks;
use super::sample::{SERIES, Sample};
use super::step::StepPoint;
use crate::integrator::Stats;
use crate::mechanism::{ContactState, Contacts};

/// Writes the slider-crank's records.
pub trait WriteRecords {
    /// Writes the contact states of the joints.
    fn contact(&mut self, contacts: &Contacts);
    /// Writes a step point: its time, state and derivative.
    fn step_point(&mut self, p: &StepPoint);
    /// Writes peak values.
    fn peaks(&mut self, p: &Peaks);
    /// Writes integrator statistics.
    fn stats(&mut self, s: &Stats);
    /// Writes the cycle results.
    fn cycles(&mut self, c: &CycleHold);
    /// Writes a pending step's contribution to the cycle results.
    fn cycle_step(&mut self, step: &Option<CycleStep>);
}

/// The numbers of a cycle, in the codec's order.
fn cycle_values(c: &Cycle) -> Vec<f64> {
    let mut v = vec![c.start, c.end, c.start_angle];
    for j in &c.joints {
        for e in [
            j.eccentricity_ratio,
            j.film_pressure,
            j.force,
            j.asperity_force,
            j.film_temperature,
        ] {
            v.extend([e.value, e.angle]);
        }
        v.extend([j.friction_energy, j.oil_volume, j.metal_contact_time]);
    }
    v
}

/// The numbers of a step's contribution, in the codec's order.
fn cycle_step_values(s: &CycleStep) -> Vec<f64> {
    let mut v = [[s.from].as_slice(), &s.time, &s.angle].concat();
    for sample in [s.at_end, s.inside, s.place] {
        v.extend(sample);
    }
    for rates in [s.friction_power, s.oil_flow, s.asperity_force] {
        v.extend(rates.into_iter().flatten());
    }
    v.extend(s.in_contact.into_iter().flatten().map(f64::from));
    v.extend(s.film_temperature.into_iter().flatten());
    v
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
    /// Writes the cycle results.
    fn cycles(&mut self, c: &CycleHold) {
        self.f64(c.period);
        self.f64s(&cycle_values(&c.current));
        self.flag(c.last.is_some());
        if let Some(last) = &c.last {
            self.f64s(&cycle_values(last));
        }
        self.u64(c.completed);
    }
    /// Writes a pending step's contribution to the cycle results.
    fn cycle_step(&mut self, step: &Option<CycleStep>) {
        self.flag(step.is_some());
        if let Some(step) = step {
            self.f64s(&cycle_step_values(step));
        }
    }
}

/// The numbers of one joint's cycle results in [`cycle_values`].
const JOINT_CYCLE_VALUES: usize = 13;

/// The cycle of [`cycle_values`].
fn cycle_from(v: &[f64]) -> Result<Cycle, CodecError> {
    if v.len() != 3 + 3 * JOINT_CYCLE_VALUES {
        return Err(CodecError(format!(
            "FMU state rejected: a cycle of {} numbers",
            v.len()
        )));
    }
    let extreme = |k: usize| Extreme {
        value: v[k],
        angle: v[k + 1],
    };
    Ok(Cycle {
        start: v[0],
        end: v[1],
        start_angle: v[2],
        joints: std::array::from_fn(|i| {
            let k = 3 + JOINT_CYCLE_VALUES * i;
            JointCycle {
                eccentricity_ratio: extreme(k),
                film_pressure: extreme(k + 2),
                force: extreme(k + 4),
                asperity_force: extreme(k + 6),
                film_temperature: extreme(k + 8),
                friction_energy: v[k + 10],
                oil_volume: v[k + 11],
                metal_contact_time: v[k + 12],
            }
        }),
    })
}

/// The step contribution of [`cycle_step_values`].
fn cycle_step_from(v: &[f64]) -> Result<CycleStep, CodecError> {
    if v.len() != 5 + 3 * SERIES + 30 {
        return Err(CodecError(format!(
            "FMU state rejected: a cycle step of {} numbers",
            v.len()
        )));
    }
    let sample = |k: usize| -> Sample { std::array::from_fn(|i| v[5 + k * SERIES + i]) };
    let rates =
        |k: usize| -> [[f64; 2]; 3] { std::array::from_fn(|i| [v[k + 2 * i], v[k + 2 * i + 1]]) };
    Ok(CycleStep {
        from: v[0],
        time: [v[1], v[2]],
        angle: [v[3], v[4]],
        at_end: sample(0),
        inside: sample(1),
        place: sample(2),
        friction_power: rates(5 + 3 * SERIES),
        oil_flow: rates(5 + 3 * SERIES + 6),
        asperity_force: rates(5 + 3 * SERIES + 12),
        in_contact: std::array::from_fn(|i| {
            let k = 5 + 3 * SERIES + 18 + 2 * i;
            [v[k] != 0.0, v[k + 1] != 0.0]
        }),
        film_temperature: rates(5 + 3 * SERIES + 24),
    })
}

/// Reads the slider-crank's records.
pub trait ReadRecords {
    /// Reads the contact states of the joints.
    fn contact(&mut self) -> Result<Contacts, CodecError>;
    /// Reads a step point.
    fn step_point(&mut self) -> Result<StepPoint, CodecError>;
    /// Reads peak values.
    fn peaks(&mut self) -> Result<Peaks, CodecError>;
    /// Reads integrator statistics.
    fn stats(&mut self) -> Result<Stats, CodecError>;
    /// Reads the cycle results.
    fn cycles(&mut self) -> Result<CycleHold, CodecError>;
    /// Reads a pending step's contribution to the cycle results.
    fn cycle_step(&mut self) -> Result<Option<CycleStep>, CodecError>;
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
    /// Reads the cycle results.
    fn cycles(&mut self) -> Result<CycleHold, CodecError> {
        let period = self.f64()?;
        let current = cycle_from(&self.f64s()?)?;
        let last = if self.flag()? {
            Some(cycle_from(&self.f64s()?)?)
        } else {
            None
        };
        Ok(CycleHold {
            period,
            current,
            last,
            completed: self.u64()?,
        })
    }
    /// Reads a pending step's contribution to the cycle results.
    fn cycle_step(&mut self) -> Result<Option<CycleStep>, CodecError> {
        if self.flag()? {
            Ok(Some(cycle_step_from(&self.f64s()?)?))
        } else {
            Ok(None)
        }
    }
}
