//! The rod's results at a section anywhere along it: its deflection from the chord and its
//! section resultants, the axial force N = EA ε and the bending moment M = EI κ, recovered from
//! the Gauss-point strains by the same least-squares quadratic over two neighbouring elements as
//! [`Rod::normal_stresses`] (superconvergent patch recovery; O. C. Zienkiewicz, J. Z. Zhu (1992),
//! Int. J. Numer. Meth. Eng. 33, 1331–1364), so a section at a node or an element's mid-point has
//! the values the stresses are taken from.

use nalgebra::Vector2;

use super::{GAUSS_POINTS, Rod};

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

/// Weights of the four Gauss-point values of a patch (two neighbouring elements, its points at
/// a, b, 1 + a, 1 + b element lengths from its start, a, b = (1 ∓ 1/√3)/2) in the value at `u`
/// element lengths from its start of their least-squares quadratic q(t) = c₀ + c₁ t + c₂ t².
/// About the patch's middle node, t = u − 1, the points ±a', ±b' are symmetric, so the normal
/// equations split: c₁ = Σ tᵢ gᵢ / S₂ and [4 S₂; S₂ S₄] [c₀; c₂] = [Σ gᵢ; Σ tᵢ² gᵢ] with
/// S_k = Σ tᵢᵏ.
pub fn patch_weights(u: f64) -> [f64; 4] {
    let (a, b) = GAUSS_POINTS;
    let points = [a - 1.0, b - 1.0, a, b];
    let s2: f64 = points.iter().map(|t| t * t).sum();
    let s4: f64 = points.iter().map(|t| t.powi(4)).sum();
    let det = 4.0 * s4 - s2 * s2;
    let t = u - 1.0;
    points.map(|p| ((s4 - s2 * p * p) + t * t * (4.0 * p * p - s2)) / det + t * p / s2)
}

impl Rod {
    /// The rod's `result` at `place`, a fraction of its length from its first node (clamped to
    /// [0, 1]), for the nodal coordinates `e`.
    pub fn section_result(&self, e: &[f64], result: SectionResult, place: f64) -> f64 {
        let place = place.clamp(0.0, 1.0);
        match result {
            SectionResult::Deflection => self.deflection(e, place),
            SectionResult::AxialForce => {
                let p = &self.properties;
                p.youngs_modulus * p.area * self.recovered_strains(e, place).0
            }
            SectionResult::BendingMoment => {
                let p = &self.properties;
                p.youngs_modulus * p.second_moment_of_area * self.recovered_strains(e, place).1
            }
        }
    }

    /// Displacement of the material point at `place` perpendicular to the chord from the first
    /// node to the last, positive to the left of the chord's direction \[m\].
    pub fn deflection(&self, e: &[f64], place: f64) -> f64 {
        let last = self.last_node_offset();
        let a = Vector2::new(e[0], e[1]);
        let chord = Vector2::new(e[last], e[last + 1]) - a;
        let r = self.position(e, place * self.properties.length) - a;
        (chord.x * r.y - chord.y * r.x) / chord.norm()
    }

    /// The axial strain ε and the curvature κ at `place` ∈ [0, 1], recovered from the Gauss points
    /// of the patch the recovered nodal and mid-point values of [`Rod::normal_stresses`] come
    /// from: a node's from the patch on its left, a place inside element j from patch j (elements
    /// j and j + 1), the last element's from the last patch; a one-element rod's linear field
    /// through its two Gauss points.
    fn recovered_strains(&self, e: &[f64], place: f64) -> (f64, f64) {
        let n = self.n_elements;
        let x = place * n as f64;
        let strains = |j| {
            self.element
                .strain_at_stress_points(&Self::element_coordinates(e, j))
        };
        if n == 1 {
            let ([g1, g2], (a, b)) = (strains(0), GAUSS_POINTS);
            let w = (x - a) / (b - a);
            return (g1.0 + w * (g2.0 - g1.0), g1.1 + w * (g2.1 - g1.1));
        }
        let j = (x.ceil() as usize).saturating_sub(1).min(n - 2);
        let ([g1, g2], [g3, g4]) = (strains(j), strains(j + 1));
        patch_weights(x - j as f64)
            .iter()
            .zip([g1, g2, g3, g4])
            .fold((0.0, 0.0), |(eps, kappa), (w, g)| {
                (eps + w * g.0, kappa + w * g.1)
            })
    }
}
