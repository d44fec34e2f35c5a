//! Early return at a contact onset: the step in which a joint comes into contact ends an
//! interval early, at its end on the clock grid ([`Engine::advance`]).

use fmi_core::clock::on_clock_grid_below;

use super::Engine;
use super::step::Onset;
use crate::joint::JointRole;

impl Engine {
    /// If `stop_at_onset` and a joint came into contact in the last accepted step, which ends
    /// after `t_start` and before `t_end`: the joint and the step's end rounded down to the clock
    /// grid (a time after `t_start`).
    pub(super) fn onset_before(
        &self,
        t_start: f64,
        t_end: f64,
        stop_at_onset: bool,
    ) -> Option<Onset> {
        if !(stop_at_onset && self.end.time < t_end) {
            return None;
        }
        let reached = on_clock_grid_below(self.end.time);
        let onsets = self.peaks.step_end.contact_onsets;
        JointRole::ALL
            .into_iter()
            .find(|&role| onsets[role as usize] > 0)
            .filter(|_| t_start < reached)
            .map(|joint| Onset {
                joint,
                time: reached,
            })
    }
}
