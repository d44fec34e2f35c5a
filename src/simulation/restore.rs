//! Snapshots of an [`Engine`]: taking one, and restoring it exactly.

use super::Engine;
use super::snapshot::Snapshot;
use crate::error::ModelError;

impl Engine {
    /// A complete snapshot of the simulation state.
    pub fn snapshot(&self) -> Snapshot {
        Snapshot {
            state: self.state.clone(),
            step_start: self.start.clone(),
            contact_start: self.contact_start,
            step_end: self.end.clone(),
            integrator: self.integrator.state(),
            contact: self.contacts,
            contact_at_start: self.mechanism.contact_at_start(),
            start_inputs: self.start_inputs,
            peaks: self.peaks,
            warnings: self.monitor.total,
        }
    }

    /// Restores a snapshot taken from an engine with the same parameters (the current point and
    /// the inputs are the caller's, restored with it).
    pub fn restore(&mut self, snapshot: &Snapshot) -> Result<(), ModelError> {
        self.last_read = None;
        let n = self.state.len();
        let lengths = [
            snapshot.state.len(),
            snapshot.step_start.y.len(),
            snapshot.step_start.f.len(),
            snapshot.step_end.y.len(),
            snapshot.step_end.f.len(),
        ];
        if lengths.iter().any(|&l| l != n) {
            return Err(ModelError::Numerical(format!(
                "snapshot has {lengths:?} states, this simulation {n}"
            )));
        }
        self.integrator.set_state(&snapshot.integrator)?;
        self.state.copy_from_slice(&snapshot.state);
        self.start.copy_from(&snapshot.step_start);
        self.contact_start = snapshot.contact_start;
        self.end.copy_from(&snapshot.step_end);
        self.contacts = snapshot.contact;
        self.mechanism
            .set_contact_at_start(snapshot.contact_at_start);
        self.start_inputs = snapshot.start_inputs;
        self.peaks = snapshot.peaks;
        self.monitor.total = snapshot.warnings;
        Ok(())
    }
}
