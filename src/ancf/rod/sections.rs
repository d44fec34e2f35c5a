//! The rod's results at sections along it: its deflection from the chord (from its shape) and its
//! section resultants, the axial force and the bending moment, from the equilibrium of its parts
//! ([`super::equilibrium`]), so that its end sections carry its pins' forces.

use nalgebra::Vector2;

use super::Rod;
use super::equilibrium::RodLoad;

/// A result along the rod, per section.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SectionResult {
    /// Displacement perpendicular to the chord from the first to the last node, positive to the
    /// left of the chord's direction \[m\].
    Deflection,
    /// Axial force, tension positive \[N\].
    AxialForce,
    /// Bending moment, positive where the rod turns left (counter-clockwise curvature) \[N m\].
    BendingMoment,
}

/// The place of section `k` of `n` ≥ 2 evenly spaced ones from the first node (k = 0) to the
/// last (k = n − 1), as a fraction of the rod's length.
pub fn section_place(k: usize, n: usize) -> f64 {
    k as f64 / n.saturating_sub(1).max(1) as f64
}

impl Rod {
    /// The rod's `result` at `out.len()` evenly spaced sections ([`section_place`]) for the nodal
    /// coordinates `e`, their accelerations `e_ddot` and the load `load`.
    pub fn sections(
        &self,
        e: &[f64],
        e_ddot: &[f64],
        load: &RodLoad,
        result: SectionResult,
        out: &mut [f64],
    ) {
        let n = out.len();
        if result == SectionResult::Deflection {
            for (k, value) in out.iter_mut().enumerate() {
                *value = self.deflection(e, section_place(k, n));
            }
            return;
        }
        let places = (0..n).map(|k| section_place(k, n));
        let mut k = 0;
        self.resultants(e, e_ddot, load, places, |_, axial, moment| {
            out[k] = match result {
                SectionResult::AxialForce => axial,
                _ => moment,
            };
            k += 1;
        });
    }

    /// Displacement of the material point at `place` perpendicular to the chord from the first
    /// node to the last, positive to the left of the chord's direction \[m\].
    pub fn deflection(&self, e: &[f64], place: f64) -> f64 {
        let last = self.last_node_offset();
        let a = Vector2::new(e[0], e[1]);
        let chord = Vector2::new(e[last], e[last + 1]) - a;
        let r = self.position(e, place.clamp(0.0, 1.0) * self.properties.length) - a;
        (chord.x * r.y - chord.y * r.x) / chord.norm()
    }
}
