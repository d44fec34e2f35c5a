//! FMU state: a complete, pointer-free snapshot of the model and its bytes.
//!
//! Layout (little-endian, inside the framing of `fmi-export`: magic, version, state machine,
//! checksum): the parameter count of the variable table and nModes (so a state from another build
//! or model is rejected), every parameter in table order (a String as its length and bytes),
//! whether crank.initialSpeed was set, inputs, the start time and tolerance the model was built
//! for, the simulation snapshot (the clock is the framing's).

use fmi_export::FmuError;
use fmi_export::checks::check_real;

use crate::params::{
    Parameters, integer_parameter, real_parameter, set_integer_parameter, set_real_parameter,
    set_string_parameter, string_parameter,
};
use crate::simulation::codec::{ByteReader, ByteWriter};
use crate::simulation::{InputSignal, Snapshot};
use crate::variables::{Causality, Kind, VARIABLES, Vr};

/// Everything needed to resume an instance exactly.
#[derive(Clone, Debug, PartialEq)]
pub struct FmuSnapshot {
    /// All parameters.
    pub parameters: Parameters,
    /// Input values and the derivatives set for the next step.
    pub inputs: InputSignal,
    /// Start time, where the simulation is built \[s\].
    pub start_time: f64,
    /// The master's tolerance, if defined.
    pub tolerance: Option<f64>,
    /// Simulation state, once the model is built.
    pub simulation: Option<Snapshot>,
}

fn parameter_count() -> u32 {
    VARIABLES
        .iter()
        .filter(|v| v.causality == Causality::Parameter)
        .count() as u32
}

/// `value` checked against the declared range of variable `vr`, as fmi2SetReal checks it.
fn check_range(vr: Vr, value: f64) -> Result<(), FmuError> {
    check_real(&VARIABLES[vr as usize], value).map_err(|e| rejected(&e.to_string()))
}

/// The error for a state that cannot be restored, saying why.
fn rejected(what: &str) -> FmuError {
    FmuError::Invalid(format!("FMU state rejected: {what}"))
}

impl FmuSnapshot {
    /// Checks what a hand-edited or foreign state could carry, as fmi2SetReal checks inputs:
    /// every parameter and input inside its declared range, finite times and states, the
    /// simulation's inputs equal to the instance's, and (once the model is built) consistent
    /// parameters.
    pub fn validate(&self) -> Result<(), FmuError> {
        self.parameters
            .check_declared_ranges()
            .map_err(|e| rejected(&e.to_string()))?;
        let i = &self.inputs;
        check_range(Vr::DriveSpeed, i.value.drive_speed)?;
        check_range(Vr::DriveTorque, i.value.drive_torque)?;
        check_range(Vr::SliderForce, i.value.slider_force)?;
        if !self.start_time.is_finite() {
            return Err(rejected("a non-finite start time"));
        }
        if self.tolerance.is_some_and(|t| !(t.is_finite() && t > 0.0)) {
            return Err(rejected("a tolerance that is not a finite positive number"));
        }
        if let Some(s) = &self.simulation {
            self.parameters
                .validate()
                .map_err(|e| FmuError::Invalid(format!("FMU state rejected: {e}")))?;
            if !s.is_finite() {
                return Err(rejected("a non-finite simulation time, state or input"));
            }
            if (s.next.value, s.next.derivatives) != (i.value, i.derivatives) {
                return Err(rejected(
                    "the simulation's inputs differ from the instance's",
                ));
            }
        }
        Ok(())
    }

    /// Appends the pointer-free bytes of the snapshot to `out`.
    pub fn write(&self, out: &mut Vec<u8>) {
        let mut w = ByteWriter(out);
        w.u32(parameter_count());
        w.u32(self.parameters.n_modes as u32);
        for v in VARIABLES
            .iter()
            .filter(|v| v.causality == Causality::Parameter)
        {
            match v.kind {
                Kind::Real { .. } => w.f64(real_parameter(&self.parameters, v.vr).unwrap_or(0.0)),
                Kind::String { .. } => {
                    w.str(string_parameter(&self.parameters, v.vr).unwrap_or(""))
                }
                _ => w.u32(integer_parameter(&self.parameters, v.vr).unwrap_or(0) as u32),
            }
        }
        // Whether crank.initialSpeed was set (unset, the crank starts at drive.speed).
        w.u8(u8::from(self.parameters.crank_initial_speed.is_some()));
        self.inputs.write(&mut w);
        w.f64(self.start_time);
        w.u8(u8::from(self.tolerance.is_some()));
        w.f64(self.tolerance.unwrap_or(0.0));
        w.u8(u8::from(self.simulation.is_some()));
        if let Some(s) = &self.simulation {
            s.write(&mut w);
        }
    }

    /// Parses bytes written by [`FmuSnapshot::write`] (ranges are checked by
    /// [`FmuSnapshot::validate`]).
    pub fn read(body: &[u8]) -> Result<Self, FmuError> {
        let mut r = ByteReader::new(body);
        let count = r.u32()?;
        if count != parameter_count() {
            return Err(rejected(&format!(
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
                Kind::String { .. } => set_string_parameter(&mut parameters, v.vr, &r.str()?),
                _ => set_integer_parameter(&mut parameters, v.vr, r.u32()? as i32),
            };
            if !ok {
                return Err(rejected(&format!("invalid value of {}", v.name)));
            }
        }
        if !r.flag()? {
            parameters.crank_initial_speed = None;
        }
        if parameters.n_modes as u32 != n_modes {
            return Err(rejected(&format!(
                "nModes {} in the header, {} in the parameters",
                n_modes, parameters.n_modes
            )));
        }
        let inputs = InputSignal::read(&mut r)?;
        let start_time = r.f64()?;
        let has_tolerance = r.flag()?;
        let tolerance = r.f64()?;
        let simulation = if r.flag()? {
            Some(Snapshot::read(&mut r)?)
        } else {
            None
        };
        if r.remaining() != 0 {
            return Err(rejected(&format!("{} trailing bytes", r.remaining())));
        }
        Ok(Self {
            parameters,
            inputs,
            start_time,
            tolerance: has_tolerance.then_some(tolerance),
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
            tolerance: None,
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
        assert!(rejected(&s).contains("drive.speed = 1e9 is outside"));
        let mut s = snapshot();
        s.start_time = f64::NAN;
        assert!(rejected(&s).contains("non-finite start time"));
        let mut s = snapshot();
        s.parameters.joint.clearance = 1.0;
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
