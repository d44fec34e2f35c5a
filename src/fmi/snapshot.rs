//! FMU state: a complete, pointer-free snapshot of the model and its bytes.
//!
//! Layout (little-endian, inside the framing of `fmi-export`: magic, version, state machine,
//! clock, inputs, checksum): the parameter count of the variable table and nModes (so a state
//! from another build or model is rejected), every parameter in table order (a String as its
//! length and bytes), whether crank.initialSpeed was set, the simulation snapshot.

use fmi_export::FmuError;

use crate::params::{
    Parameters, integer_parameter, real_parameter, set_integer_parameter, set_real_parameter,
    set_string_parameter, string_parameter,
};
use crate::simulation::Snapshot;
use crate::simulation::codec::{ByteReader, ByteWriter};
use crate::variables::{Causality, Kind, VARIABLES};

/// Everything needed to resume an instance exactly.
#[derive(Clone, Debug, PartialEq)]
pub struct FmuSnapshot {
    /// All parameters.
    pub parameters: Parameters,
    /// Simulation state, once the model is built.
    pub simulation: Option<Snapshot>,
}

fn parameter_count() -> u32 {
    VARIABLES
        .iter()
        .filter(|v| v.causality == Causality::Parameter)
        .count() as u32
}

/// The error for a state that cannot be restored, saying why.
fn rejected(what: &str) -> FmuError {
    FmuError::Invalid(format!("FMU state rejected: {what}"))
}

impl FmuSnapshot {
    /// Checks what a hand-edited or foreign state could carry, as fmi2SetReal checks
    /// parameters: every parameter inside its declared range, finite times, states and inputs,
    /// and (once the model is built) consistent parameters. The instance's inputs, clock and
    /// experiment are the generic layer's to check.
    pub fn validate(&self) -> Result<(), FmuError> {
        self.parameters
            .check_declared_ranges()
            .map_err(|e| rejected(&e.to_string()))?;
        if let Some(s) = &self.simulation {
            self.parameters
                .validate()
                .map_err(|e| FmuError::Invalid(format!("FMU state rejected: {e}")))?;
            if !s.is_finite() {
                return Err(rejected("a non-finite simulation time, state or input"));
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
            simulation,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simulation::{Engine, Inputs};

    fn snapshot() -> FmuSnapshot {
        let parameters = Parameters::default();
        let inputs = Inputs::at_start(&parameters);
        let simulation = Engine::new(parameters.clone(), inputs, 0.0)
            .unwrap()
            .snapshot();
        FmuSnapshot {
            parameters,
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
    /// (out-of-range parameters, a non-finite simulation) is rejected with a message naming
    /// what is wrong.
    #[test]
    fn restored_states_are_range_checked() {
        snapshot().validate().unwrap();
        let mut s = snapshot();
        s.parameters.joint.clearance = 1.0;
        assert!(rejected(&s).contains("joint.clearance"));
        let mut s = snapshot();
        if let Some(sim) = &mut s.simulation {
            sim.state[0] = f64::INFINITY;
        }
        assert!(rejected(&s).contains("non-finite simulation"));
    }
}
