//! Snapshots of a [`Simulation`]: taking one, and restoring it exactly.

use super::Simulation;
use super::snapshot::Snapshot;
use crate::error::ModelError;

impl Simulation {
    /// A complete snapshot of the simulation state.
    pub fn snapshot(&self) -> Snapshot {
        Snapshot {
            time: self.time,
            state: self.state.clone(),
            step_start: (
                self.step_start,
                self.y_start.clone(),
                self.f_start.clone(),
                self.contact_start,
            ),
            step_end: (self.step_end, self.y_end.clone(), self.f_end.clone()),
            integrator: self.integrator.state(),
            contact: self.mechanism.contact_state(),
            signal: *self.mechanism.input_signal(),
            next: self.next,
            inputs_set: self.inputs_set,
            peaks: self.peaks,
            warnings: self.monitor.total,
        }
    }

    /// Restores a snapshot taken from a simulation with the same parameters.
    pub fn restore(&mut self, snapshot: &Snapshot) -> Result<(), ModelError> {
        let n = self.state.len();
        let lengths = [
            snapshot.state.len(),
            snapshot.step_start.1.len(),
            snapshot.step_start.2.len(),
            snapshot.step_end.1.len(),
            snapshot.step_end.2.len(),
        ];
        if lengths.iter().any(|&l| l != n) {
            return Err(ModelError::Numerical(format!(
                "snapshot has {lengths:?} states, this simulation {n}"
            )));
        }
        self.integrator.set_state(&snapshot.integrator)?;
        self.time = snapshot.time;
        self.state.copy_from_slice(&snapshot.state);
        self.step_start = snapshot.step_start.0;
        self.y_start.copy_from_slice(&snapshot.step_start.1);
        self.f_start.copy_from_slice(&snapshot.step_start.2);
        self.contact_start = snapshot.step_start.3;
        self.step_end = snapshot.step_end.0;
        self.y_end.copy_from_slice(&snapshot.step_end.1);
        self.f_end.copy_from_slice(&snapshot.step_end.2);
        self.mechanism.set_contact_state(snapshot.contact);
        self.mechanism
            .set_input_signal(snapshot.signal, snapshot.time);
        self.next = snapshot.next;
        self.inputs_set = snapshot.inputs_set;
        self.peaks = snapshot.peaks;
        self.monitor.total = snapshot.warnings;
        Ok(())
    }
}
