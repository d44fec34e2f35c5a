//! FMU state: a complete, pointer-free snapshot of the model and its bytes.
//!
//! Layout (little-endian, inside the framing of `fmi2-slave`: magic, version, state machine,
//! checksum): the parameter count of the variable table and nModes (so a state from another build
//! or model is rejected), every parameter in table order, inputs, clock, the simulation snapshot.

use fmi2_slave::FmuError;

use super::variables::{Causality, Kind, VARIABLES, Vr};
use crate::integrator::{ImplicitState, IntegratorState, Stats};
use crate::mechanism::ContactState;
use crate::params::{
    Parameters, integer_parameter, real_parameter, set_integer_parameter, set_real_parameter,
};
use crate::simulation::{InputSignal, Inputs, PeakHold, Peaks, Snapshot};

/// Largest accepted vector length (states, Jacobian entries) in a state.
const MAX_LENGTH: usize = 1 << 20;
/// Everything needed to resume an instance exactly.
#[derive(Clone, Debug, PartialEq)]
pub struct FmuSnapshot {
    /// All parameters.
    pub parameters: Parameters,
    /// Input values and the derivatives set for the next step.
    pub inputs: InputSignal,
    /// Start time \[s\].
    pub start_time: f64,
    /// Stop time, if defined \[s\].
    pub stop_time: Option<f64>,
    /// The master's tolerance from fmi2SetupExperiment, if defined.
    pub tolerance: Option<f64>,
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

/// The ten numbers of an input signal: start, then value, first and second derivatives, each
/// as (drive speed, drive torque, slider force).
fn signal_values(s: &InputSignal) -> [f64; 10] {
    let mut v = [s.start; 10];
    for (k, i) in [s.value, s.derivatives[0], s.derivatives[1]]
        .iter()
        .enumerate()
    {
        v[1 + 3 * k..4 + 3 * k].copy_from_slice(&[i.drive_speed, i.drive_torque, i.slider_force]);
    }
    v
}

struct Writer<'a>(&'a mut Vec<u8>);

impl Writer<'_> {
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
    fn f64s(&mut self, v: &[f64]) {
        self.u32(v.len() as u32);
        for x in v {
            self.f64(*x);
        }
    }
    fn contact(&mut self, c: &ContactState) {
        self.u8(u8::from(c.in_contact));
        self.f64(c.impact_velocity);
    }
    fn peaks(&mut self, p: &Peaks) {
        self.f64(p.joint_force);
        self.f64(p.slider_acceleration);
        self.f64(p.deformation_energy);
        self.u64(p.contact_onsets);
    }
    fn signal(&mut self, s: &InputSignal) {
        for x in signal_values(s) {
            self.f64(x);
        }
    }
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
    fn f64s(&mut self) -> Result<Vec<f64>, FmuError> {
        let n = self.u32()? as usize;
        if n > MAX_LENGTH {
            return Err(FmuError::Invalid(format!(
                "FMU state rejected: a vector of {n} values"
            )));
        }
        (0..n).map(|_| self.f64()).collect()
    }
    fn contact(&mut self) -> Result<ContactState, FmuError> {
        Ok(ContactState {
            in_contact: self.flag()?,
            impact_velocity: self.f64()?,
        })
    }
    fn peaks(&mut self) -> Result<Peaks, FmuError> {
        Ok(Peaks {
            joint_force: self.f64()?,
            slider_acceleration: self.f64()?,
            deformation_energy: self.f64()?,
            contact_onsets: self.u64()?,
        })
    }
    fn signal(&mut self) -> Result<InputSignal, FmuError> {
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
    fn stats(&mut self) -> Result<Stats, FmuError> {
        Ok(Stats {
            steps: self.u64()?,
            rejected: self.u64()?,
            evaluations: self.u64()?,
            newton_iterations: self.u64()?,
            jacobians: self.u64()?,
            factorizations: self.u64()?,
        })
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

/// `value` checked against the declared range of variable `vr` (finite, within [min, max]).
fn check_range(vr: Vr, value: f64) -> Result<(), FmuError> {
    let v = &VARIABLES[vr as usize];
    let (min, max) = match v.kind {
        Kind::Real { min, max, .. } => (min, max),
        Kind::Integer { min, max, .. } => (f64::from(min), f64::from(max)),
        _ => (f64::NEG_INFINITY, f64::INFINITY),
    };
    if value.is_finite() && min <= value && value <= max {
        Ok(())
    } else {
        Err(FmuError::Invalid(format!(
            "FMU state rejected: {} = {value:e} is outside the allowed range [{min:e}, {max:e}]",
            v.name
        )))
    }
}

impl FmuSnapshot {
    /// Checks what a hand-edited or foreign state could carry, as fmi2SetReal checks inputs:
    /// every parameter and input inside its declared range, finite times and states, the
    /// simulation's inputs equal to the instance's, and (once the model is built) consistent
    /// parameters.
    pub fn validate(&self) -> Result<(), FmuError> {
        for v in VARIABLES
            .iter()
            .filter(|v| v.causality == Causality::Parameter)
        {
            let value = match v.kind {
                Kind::Real { .. } => real_parameter(&self.parameters, v.vr),
                _ => integer_parameter(&self.parameters, v.vr).map(f64::from),
            };
            if let Some(value) = value {
                check_range(v.vr, value)?;
            }
        }
        let i = &self.inputs;
        check_range(Vr::DriveSpeed, i.value.drive_speed)?;
        check_range(Vr::DriveTorque, i.value.drive_torque)?;
        check_range(Vr::SliderForce, i.value.slider_force)?;
        let bad = |what: &str| Err(FmuError::Invalid(format!("FMU state rejected: {what}")));
        let times = [self.start_time, self.time, self.last_successful_time];
        if times.iter().any(|t| !t.is_finite()) || self.stop_time.is_some_and(|t| !t.is_finite()) {
            return bad("a non-finite time");
        }
        if self.tolerance.is_some_and(|t| !(t.is_finite() && t > 0.0)) {
            return bad("a tolerance that is not a finite positive number");
        }
        if let Some(s) = &self.simulation {
            self.parameters
                .validate()
                .map_err(|e| FmuError::Invalid(format!("FMU state rejected: {e}")))?;
            let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
            let vectors = [
                &s.state,
                &s.step_start.1,
                &s.step_start.2,
                &s.step_end.1,
                &s.step_end.2,
            ];
            if !(s.time.is_finite()
                && s.step_start.0.is_finite()
                && s.step_end.0.is_finite()
                && vectors.iter().all(|v| finite(v)))
            {
                return bad("a non-finite simulation time or state");
            }
            let signals = [&s.signal, &s.next, i];
            if !signals.iter().all(|x| finite(&signal_values(x))) {
                return bad("a non-finite input or input derivative");
            }
            if (s.next.value, s.next.derivatives) != (i.value, i.derivatives) {
                return bad("the simulation's inputs differ from the instance's");
            }
        }
        Ok(())
    }

    /// Appends the pointer-free bytes of the snapshot to `out`.
    pub fn write(&self, out: &mut Vec<u8>) {
        let mut w = Writer(out);
        w.u32(parameter_count());
        w.u32(self.parameters.n_modes as u32);
        for v in VARIABLES
            .iter()
            .filter(|v| v.causality == Causality::Parameter)
        {
            match v.kind {
                Kind::Real { .. } => w.f64(real_parameter(&self.parameters, v.vr).unwrap_or(0.0)),
                _ => w.u32(integer_parameter(&self.parameters, v.vr).unwrap_or(0) as u32),
            }
        }
        w.signal(&self.inputs);
        w.f64(self.start_time);
        for x in [self.stop_time, self.tolerance] {
            w.u8(u8::from(x.is_some()));
            w.f64(x.unwrap_or(0.0));
        }
        w.f64(self.time);
        w.f64(self.last_successful_time);
        w.u8(u8::from(self.simulation.is_some()));
        if let Some(s) = &self.simulation {
            w.f64(s.time);
            w.f64s(&s.state);
            w.f64(s.step_start.0);
            w.f64s(&s.step_start.1);
            w.f64s(&s.step_start.2);
            w.contact(&s.step_start.3);
            w.f64(s.step_end.0);
            w.f64s(&s.step_end.1);
            w.f64s(&s.step_end.2);
            match &s.integrator {
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
            w.contact(&s.contact);
            w.signal(&s.signal);
            w.signal(&s.next);
            w.peaks(&s.peaks.interval);
            w.peaks(&s.peaks.step_end);
            w.u8(u8::from(s.peaks.pending));
            w.u64(s.peaks.total_onsets);
            w.u64(s.warnings);
        }
    }

    /// Parses bytes written by [`FmuSnapshot::write`] (ranges are checked by
    /// [`FmuSnapshot::validate`]).
    pub fn read(body: &[u8]) -> Result<Self, FmuError> {
        let bad = |what: String| FmuError::Invalid(format!("FMU state rejected: {what}"));
        let mut r = Reader { bytes: body, at: 0 };
        let count = r.u32()?;
        if count != parameter_count() {
            return Err(bad(format!(
                "{count} parameters, this FMU has {}",
                parameter_count()
            )));
        }
        let n_modes = r.u32()?;
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
        let inputs = r.signal()?;
        let start_time = r.f64()?;
        let has_stop = r.flag()?;
        let stop = r.f64()?;
        let has_tolerance = r.flag()?;
        let tolerance = r.f64()?;
        let time = r.f64()?;
        let last_successful_time = r.f64()?;
        let simulation = if r.flag()? {
            let sim_time = r.f64()?;
            let state_vector = r.f64s()?;
            let step_start = (r.f64()?, r.f64s()?, r.f64s()?, r.contact()?);
            let step_end = (r.f64()?, r.f64s()?, r.f64s()?);
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
                    jacobian_stale: r.flag()?,
                    newton_rate: r.f64()?,
                    history: r.f64s()?,
                    history_step: r.f64()?,
                    derivative: r.f64s()?,
                    acceleration: r.f64s()?,
                    acceleration_start: r.f64s()?,
                    stats: r.stats()?,
                }),
                m => return Err(bad(format!("unknown integrator {m}"))),
            };
            let contact = r.contact()?;
            Some(Snapshot {
                time: sim_time,
                state: state_vector,
                step_start,
                step_end,
                integrator,
                contact,
                signal: r.signal()?,
                next: r.signal()?,
                peaks: PeakHold {
                    interval: r.peaks()?,
                    step_end: r.peaks()?,
                    pending: r.flag()?,
                    total_onsets: r.u64()?,
                },
                warnings: r.u64()?,
            })
        } else {
            None
        };
        if r.at != body.len() {
            return Err(bad(format!("{} trailing bytes", body.len() - r.at)));
        }
        Ok(Self {
            parameters,
            inputs,
            start_time,
            stop_time: has_stop.then_some(stop),
            tolerance: has_tolerance.then_some(tolerance),
            time,
            last_successful_time,
            simulation,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Simulation;

    fn snapshot() -> FmuSnapshot {
        let parameters = Parameters::default();
        let simulation = Simulation::new(parameters.clone()).unwrap().snapshot();
        FmuSnapshot {
            parameters,
            inputs: simulation.next,
            start_time: 0.0,
            stop_time: Some(0.024),
            tolerance: None,
            time: 0.0,
            last_successful_time: 0.0,
            simulation: Some(simulation),
        }
    }

    fn rejected(s: &FmuSnapshot) -> String {
        match s.validate() {
            Err(e) => e.to_string(),
            Ok(()) => panic!("accepted {s:?}"),
        }
    }

    /// A state that passes the checksum but carries values fmi2SetReal would refuse
    /// (non-finite or out-of-range inputs and parameters, non-finite times, an inconsistent
    /// simulation) is rejected with a message naming what is wrong.
    #[test]
    fn restored_states_are_range_checked() {
        snapshot().validate().unwrap();
        let mut s = snapshot();
        s.inputs.value.drive_speed = f64::NAN;
        assert!(rejected(&s).contains("drive.speed = NaN"));
        let mut s = snapshot();
        s.inputs.value.drive_speed = 1e9;
        assert!(rejected(&s).contains("drive.speed = 1e9"));
        let mut s = snapshot();
        s.time = f64::NAN;
        assert!(rejected(&s).contains("non-finite time"));
        let mut s = snapshot();
        s.parameters.clearance = 1.0;
        assert!(rejected(&s).contains("joint.clearance"));
        let mut s = snapshot();
        s.inputs.value.drive_torque = 5.0;
        assert!(rejected(&s).contains("inputs differ"));
        let mut s = snapshot();
        if let Some(sim) = &mut s.simulation {
            sim.state[0] = f64::INFINITY;
        }
        assert!(rejected(&s).contains("non-finite simulation"));
    }
}
