//! FMU state: a complete, pointer-free snapshot of an instance and its byte serialisation.
//!
//! Layout (little-endian): magic `FSCS`, format version, the parameter count of the variable table
//! and nModes (so a state from another build or model is rejected), the state machine, every
//! parameter in table order, inputs, clock, the simulation snapshot, and an FNV-1a 64 checksum of
//! everything before it (a corrupted byte is rejected, never restored).

use super::error::FmuError;
use super::instance::{
    InputValues, integer_parameter, real_parameter, set_integer_parameter, set_real_parameter,
};
use super::state::State;
use super::variables::{Causality, Kind, VARIABLES};
use crate::integrator::Stats;
use crate::mechanism::{ContactState, Inputs};
use crate::params::Parameters;
use crate::simulation::Snapshot;

const MAGIC: &[u8; 4] = b"FSCS";
const VERSION: u32 = 1;
const STATES: [State; 6] = [
    State::Instantiated,
    State::InitializationMode,
    State::StepComplete,
    State::StepFailed,
    State::Terminated,
    State::Error,
];

/// Everything needed to resume an instance exactly.
#[derive(Clone, Debug, PartialEq)]
pub struct FmuSnapshot {
    /// State-machine state.
    pub state: State,
    /// All parameters.
    pub parameters: Parameters,
    /// Input values.
    pub inputs: InputValues,
    /// Start time \[s\].
    pub start_time: f64,
    /// Stop time, if defined \[s\].
    pub stop_time: Option<f64>,
    /// Current communication point \[s\].
    pub time: f64,
    /// Last successful time \[s\].
    pub last_successful_time: f64,
    /// Simulation state, once the model is built.
    pub simulation: Option<Snapshot>,
}

fn parameter_count() -> u32 {
    VARIABLES
        .iter()
        .filter(|v| v.causality == Causality::Parameter)
        .count() as u32
}

fn fnv64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3)
    })
}

struct Writer(Vec<u8>);

impl Writer {
    fn u8(&mut self, v: u8) {
        self.0.push(v);
    }
    fn u32(&mut self, v: u32) {
        self.0.extend_from_slice(&v.to_le_bytes());
    }
    fn u64(&mut self, v: u64) {
        self.0.extend_from_slice(&v.to_le_bytes());
    }
    fn f64(&mut self, v: f64) {
        self.u64(v.to_bits());
    }
}

struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Reader<'_> {
    fn take(&mut self, n: usize) -> Result<&[u8], FmuError> {
        let end = self
            .at
            .checked_add(n)
            .filter(|&e| e <= self.bytes.len())
            .ok_or_else(|| {
                FmuError::Invalid(format!("FMU state truncated: {} bytes", self.bytes.len()))
            })?;
        let out = &self.bytes[self.at..end];
        self.at = end;
        Ok(out)
    }
    fn u8(&mut self) -> Result<u8, FmuError> {
        Ok(self.take(1)?[0])
    }
    fn u32(&mut self) -> Result<u32, FmuError> {
        let mut b = [0; 4];
        b.copy_from_slice(self.take(4)?);
        Ok(u32::from_le_bytes(b))
    }
    fn u64(&mut self) -> Result<u64, FmuError> {
        let mut b = [0; 8];
        b.copy_from_slice(self.take(8)?);
        Ok(u64::from_le_bytes(b))
    }
    fn f64(&mut self) -> Result<f64, FmuError> {
        Ok(f64::from_bits(self.u64()?))
    }
    fn flag(&mut self) -> Result<bool, FmuError> {
        match self.u8()? {
            0 => Ok(false),
            1 => Ok(true),
            b => Err(FmuError::Invalid(format!(
                "FMU state: invalid flag byte {b}"
            ))),
        }
    }
}

impl FmuSnapshot {
    /// Pointer-free bytes of the snapshot.
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut w = Writer(Vec::with_capacity(1024));
        w.0.extend_from_slice(MAGIC);
        w.u32(VERSION);
        w.u32(parameter_count());
        w.u32(self.parameters.n_modes as u32);
        w.u8(STATES.iter().position(|s| *s == self.state).unwrap_or(0) as u8);
        for v in VARIABLES
            .iter()
            .filter(|v| v.causality == Causality::Parameter)
        {
            match v.kind {
                Kind::Real { .. } => w.f64(real_parameter(&self.parameters, v.vr).unwrap_or(0.0)),
                _ => w.u32(integer_parameter(&self.parameters, v.vr).unwrap_or(0) as u32),
            }
        }
        let i = &self.inputs;
        for x in [
            i.drive_speed,
            i.drive_torque,
            i.slider_force,
            self.start_time,
        ] {
            w.f64(x);
        }
        w.u8(u8::from(self.stop_time.is_some()));
        w.f64(self.stop_time.unwrap_or(0.0));
        w.f64(self.time);
        w.f64(self.last_successful_time);
        w.u8(u8::from(self.simulation.is_some()));
        if let Some(s) = &self.simulation {
            w.f64(s.time);
            w.u32(s.state.len() as u32);
            for x in &s.state {
                w.f64(*x);
            }
            w.f64(s.proposed_step);
            w.u64(s.stats.steps);
            w.u64(s.stats.rejected);
            w.u64(s.stats.evaluations);
            w.u8(u8::from(s.contact.in_contact));
            w.f64(s.contact.impact_velocity);
            w.f64(s.inputs.drive_speed);
            w.f64(s.inputs.drive_torque);
            w.f64(s.inputs.slider_force);
            w.u8(u8::from(s.speed_changed));
        }
        let checksum = fnv64(&w.0);
        w.u64(checksum);
        w.0
    }

    /// Parses and checks bytes written by [`FmuSnapshot::to_bytes`].
    pub fn from_bytes(bytes: &[u8]) -> Result<Self, FmuError> {
        let bad = |what: String| FmuError::Invalid(format!("FMU state rejected: {what}"));
        if bytes.len() < 8 + 4 + 12 {
            return Err(bad(format!("{} bytes is too short", bytes.len())));
        }
        let (body, tail) = bytes.split_at(bytes.len() - 8);
        let mut sum = [0; 8];
        sum.copy_from_slice(tail);
        if fnv64(body) != u64::from_le_bytes(sum) {
            return Err(bad("checksum mismatch (corrupted bytes)".into()));
        }
        let mut r = Reader { bytes: body, at: 0 };
        if r.take(4)? != MAGIC {
            return Err(bad("wrong magic (not a FlexibleSliderCrank state)".into()));
        }
        let version = r.u32()?;
        if version != VERSION {
            return Err(bad(format!("format version {version}, expected {VERSION}")));
        }
        let count = r.u32()?;
        if count != parameter_count() {
            return Err(bad(format!(
                "{count} parameters, this FMU has {}",
                parameter_count()
            )));
        }
        let n_modes = r.u32()?;
        let state = *STATES
            .get(usize::from(r.u8()?))
            .ok_or_else(|| bad("invalid state".into()))?;
        let mut parameters = Parameters::default();
        for v in VARIABLES
            .iter()
            .filter(|v| v.causality == Causality::Parameter)
        {
            let ok = match v.kind {
                Kind::Real { .. } => set_real_parameter(&mut parameters, v.vr, r.f64()?),
                _ => set_integer_parameter(&mut parameters, v.vr, r.u32()? as i32),
            };
            if !ok {
                return Err(bad(format!("invalid value of {}", v.name)));
            }
        }
        if parameters.n_modes as u32 != n_modes {
            return Err(bad(format!(
                "nModes {} in the header, {} in the parameters",
                n_modes, parameters.n_modes
            )));
        }
        let inputs = InputValues {
            drive_speed: r.f64()?,
            drive_torque: r.f64()?,
            slider_force: r.f64()?,
        };
        let start_time = r.f64()?;
        let has_stop = r.flag()?;
        let stop = r.f64()?;
        let time = r.f64()?;
        let last_successful_time = r.f64()?;
        let simulation = if r.flag()? {
            let sim_time = r.f64()?;
            let n = r.u32()? as usize;
            if n > 1 << 16 {
                return Err(bad(format!("{n} states")));
            }
            let state_vector = (0..n).map(|_| r.f64()).collect::<Result<Vec<_>, _>>()?;
            let proposed_step = r.f64()?;
            let stats = Stats {
                steps: r.u64()?,
                rejected: r.u64()?,
                evaluations: r.u64()?,
            };
            let contact = ContactState {
                in_contact: r.flag()?,
                impact_velocity: r.f64()?,
            };
            let sim_inputs = Inputs {
                drive_speed: r.f64()?,
                drive_torque: r.f64()?,
                slider_force: r.f64()?,
            };
            Some(Snapshot {
                time: sim_time,
                state: state_vector,
                proposed_step,
                stats,
                contact,
                inputs: sim_inputs,
                speed_changed: r.flag()?,
            })
        } else {
            None
        };
        if r.at != body.len() {
            return Err(bad(format!("{} trailing bytes", body.len() - r.at)));
        }
        Ok(Self {
            state,
            parameters,
            inputs,
            start_time,
            stop_time: has_stop.then_some(stop),
            time,
            last_successful_time,
            simulation,
        })
    }
}
