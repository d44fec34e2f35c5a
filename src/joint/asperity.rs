//! Rough surfaces that touch: the Greenwood–Tripp asperity contact of a lubricated joint's
//! journal and bearing where the film comes down to the surfaces' roughness (mixed lubrication),
//! with a boundary friction coefficient.
//!
//! ```text
//! asperity pressure   p_a(h) = K E* F_5/2(h/σ),   K = (16√2 π/15) (σβη)² √(σ/β)
//! Gaussian integrals  F_n(λ) = (1/√(2π)) ∫_λ^∞ (s − λ)^n e^(−s²/2) ds,   F_n' = −n F_(n−1)
//! gap                 h(φ) = c − |e| cos φ   (φ from the thinnest film, n = e/|e|), clamped ≥ 0
//! normal force        F_a = R L ∫ p_a(h(φ)) cos φ dφ,   on the journal −F_a n
//! stored energy       V_a = R L ∫ [G(h(φ)) − G(c)] dφ,   G(h) = ∫_h^∞ p_a = K E* σ (2/7) F_7/2(h/σ)
//!                     (G(h) = G(0) − p_a(0) h for h < 0),   so that F_a = ∂V_a/∂|e|
//! friction            F_T = −μ_b c_d(|v_T|) F_a sgn(v_T)   at the contact point, as the dry contact's
//! ```
//! σ is the combined RMS roughness of the two surfaces, σβη the product of roughness, summit radius
//! β and summit density η (usually 0.03–0.05), σ/β the roughness over the summit radius (usually
//! 1e-4–1e-2), E* the contact modulus 1/E* = (1 − ν²)/E + (1 − ν²)/E of journal and bearing (the
//! convention of Greenwood & Williamson's E'; texts that write 2/E' fold the factor into K). The
//! asperities carry a noticeable load where the film is thinner than about 4σ (F_5/2(4) is 2e-5 of
//! F_5/2(0)); the Gaussian tail beyond h = 6σ, below 1e-10 of the touching pressure, is left out.
//! The film and the asperities carry the load together, each on the actual gap; where the gap
//! closes (|e| > c) the dry contact of [`super::contact`] takes over as the last resort, the
//! asperity pressure staying at its value at h = 0.
//!
//! The integrals F_n are tabulated once over λ ∈ [0, 6] (composite Simpson in s = λ + v², exact to
//! 1e-12) and interpolated by cubic Hermite polynomials with the exact slopes −n F_(n−1): the
//! pressure within 1e-7 of the integral (tested against a quadrature of the Gaussian itself). The
//! integral over the circumference runs over the arc where h < 6σ, by Gauss–Legendre panels.
//!
//! # References
//! - J. A. Greenwood, J. H. Tripp (1970–71), The contact of two nominally flat rough surfaces,
//!   Proc. Instn. Mech. Engrs. 185, 625–633.
//! - J. A. Greenwood, J. B. P. Williamson (1966), Contact of nominally flat surfaces, Proc. R. Soc.
//!   Lond. A 295, 300–319.
//! - S. Hu, N. Cheng et al. (1994), and the engine-bearing literature after it (σβη = 0.04,
//!   σ/β = 0.001 as usual values).

use std::f64::consts::{PI, TAU};
use std::sync::OnceLock;

use nalgebra::Vector2;

use super::contact::DryContact;
use super::kinematics::{JointForce, JointKinematics};
use crate::math;
use crate::quadrature::GAUSS_5;

/// The film ratio h/σ beyond which the asperities carry nothing.
pub const RATIO_LIMIT: f64 = 6.0;

/// Spacing of the tabulated film ratios.
const STEP: f64 = 0.02;
/// Number of tabulated film ratios, 0 … [`RATIO_LIMIT`].
const NODES: usize = 301;
/// Gauss–Legendre panels over the arc of contact.
const PANELS: usize = 4;

/// The Gaussian integral F_n(λ) by composite Simpson's rule in s = λ + v²:
/// (2/√(2π)) ∫₀^3.5 v^(2n+1) e^(−(λ + v²)²/2) dv (the rest is below 1e-14 for λ ≥ 0).
pub fn gaussian_integral(n: f64, lambda: f64) -> f64 {
    let intervals = 700;
    let h = 3.5 / intervals as f64;
    let f = |v: f64| {
        let s = lambda + v * v;
        math::powf(v, 2.0 * n + 1.0) * math::exp(-0.5 * s * s)
    };
    let mut sum = f(0.0) + f(3.5);
    for i in 1..intervals {
        sum += if i % 2 == 1 { 4.0 } else { 2.0 } * f(i as f64 * h);
    }
    2.0 / TAU.sqrt() * sum * h / 3.0
}

/// F_3/2, F_5/2, F_7/2 at the nodes λ_k = k [`STEP`].
struct Table([[f64; NODES]; 3]);

fn table() -> &'static Table {
    static TABLE: OnceLock<Table> = OnceLock::new();
    TABLE.get_or_init(|| {
        let mut t = [[0.0; NODES]; 3];
        for (row, n) in t.iter_mut().zip([1.5, 2.5, 3.5]) {
            for (k, value) in row.iter_mut().enumerate() {
                *value = gaussian_integral(n, k as f64 * STEP);
            }
        }
        Table(t)
    })
}

impl Table {
    /// F_n(λ) for n = 5/2 (`order` 1) or 7/2 (`order` 2) by cubic Hermite interpolation with the
    /// slopes −n F_(n−1); λ clamped to ≥ 0, 0 beyond [`RATIO_LIMIT`].
    fn value(&self, order: usize, lambda: f64) -> f64 {
        let lambda = lambda.max(0.0);
        if lambda >= RATIO_LIMIT {
            return 0.0;
        }
        let x = lambda / STEP;
        let k = (x as usize).min(NODES - 2);
        let t = x - k as f64;
        let n = 1.5 + order as f64;
        let (f0, f1) = (self.0[order][k], self.0[order][k + 1]);
        let (d0, d1) = (
            -n * STEP * self.0[order - 1][k],
            -n * STEP * self.0[order - 1][k + 1],
        );
        let (t2, t3) = (t * t, t * t * t);
        (2.0 * t3 - 3.0 * t2 + 1.0) * f0
            + (t3 - 2.0 * t2 + t) * d0
            + (-2.0 * t3 + 3.0 * t2) * f1
            + (t3 - t2) * d1
    }
}

/// F_5/2(λ), tabulated (module documentation).
pub fn f52(lambda: f64) -> f64 {
    table().value(1, lambda)
}

/// F_7/2(λ), tabulated (module documentation).
pub fn f72(lambda: f64) -> f64 {
    table().value(2, lambda)
}

/// What the asperities do in one state.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct AsperityState {
    /// The normal force F_a they carry \[N\].
    pub force: f64,
    /// The largest asperity pressure, at the thinnest film \[Pa\].
    pub pressure_peak: f64,
    /// The boundary friction's power −F_T v_T ≥ 0 \[W\].
    pub friction_power: f64,
}

/// Constants of the asperity contact of a lubricated joint.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Asperity {
    /// Combined RMS roughness σ > 0 \[m\].
    pub roughness: f64,
    /// K E* \[Pa\] (module documentation).
    pub pressure_scale: f64,
    /// Boundary friction coefficient μ_b.
    pub friction: f64,
    /// Bearing length L \[m\].
    pub length: f64,
}

impl Asperity {
    /// The asperity contact of roughness σ, σβη `density_product`, σ/β `roughness_ratio`,
    /// Young's modulus `youngs_modulus` and Poisson ratio `poisson_ratio` of both surfaces,
    /// boundary friction `friction`, over the bearing length `length`.
    pub fn new(
        roughness: f64,
        density_product: f64,
        roughness_ratio: f64,
        (youngs_modulus, poisson_ratio): (f64, f64),
        friction: f64,
        length: f64,
    ) -> Self {
        let k = 16.0 * std::f64::consts::SQRT_2 * PI / 15.0
            * density_product
            * density_product
            * roughness_ratio.sqrt();
        let modulus = youngs_modulus / (2.0 * (1.0 - poisson_ratio * poisson_ratio));
        Self {
            roughness,
            pressure_scale: k * modulus,
            friction,
            length,
        }
    }

    /// The asperity pressure p_a at the gap `h` \[Pa\] (the value at 0 for h < 0).
    pub fn pressure(&self, h: f64) -> f64 {
        self.pressure_scale * f52(h / self.roughness)
    }

    /// G(h) = ∫_h^∞ p_a, continued linearly for h < 0 \[N/m\].
    fn energy_density(&self, h: f64) -> f64 {
        let sigma = self.roughness;
        let at = |h: f64| self.pressure_scale * sigma * (2.0 / 7.0) * f72(h / sigma);
        if h >= 0.0 {
            at(h)
        } else {
            at(0.0) - self.pressure(0.0) * h
        }
    }

    /// The normal force F_a and the stored energy V_a at the eccentricity `e_norm` in the
    /// clearance `clearance` of a journal of radius `radius` (module documentation).
    pub fn normal(&self, e_norm: f64, clearance: f64, radius: f64) -> (f64, f64) {
        // the arc |φ| < φ_c where h = c − |e| cos φ < 6σ (outside it G and p_a vanish)
        if e_norm <= 0.0 {
            return (0.0, 0.0);
        }
        let bound = (clearance - RATIO_LIMIT * self.roughness) / e_norm;
        if bound >= 1.0 {
            return (0.0, 0.0);
        }
        let arc = if bound <= -1.0 { PI } else { libm::acos(bound) };
        // in metal contact the pressure is constant over |φ| < φ₀ (h ≤ 0) and kinks at φ₀: a
        // panel of its own
        let closed = if e_norm > clearance {
            libm::acos(clearance / e_norm)
        } else {
            0.0
        };
        let panels = std::iter::once((0.0, closed))
            .chain((0..PANELS).map(|p| {
                let width = (arc - closed) / PANELS as f64;
                (closed + p as f64 * width, width)
            }))
            .filter(|&(_, width)| width > 0.0);
        let (mut force, mut energy) = (0.0, 0.0);
        for (start, width) in panels {
            for (xi, w) in GAUSS_5.on_unit_interval(width) {
                let cos = math::cos(start + xi * width);
                let h = clearance - e_norm * cos;
                force += w * self.pressure(h.max(0.0)) * cos;
                energy += w * self.energy_density(h);
            }
        }
        // both halves of the arc, less the centred journal's energy (0 unless c < 6σ)
        let scale = radius * self.length;
        let centred = TAU * self.energy_density(clearance);
        (2.0 * scale * force, scale * (2.0 * energy - centred))
    }

    /// The asperities' force and moments on journal and bearing, their stored energy, and what a
    /// designer reads off them, in the state `k` of a joint whose dry contact is `dry`.
    pub fn force(&self, k: &JointKinematics, dry: &DryContact) -> (JointForce, AsperityState) {
        let e_norm = k.e.norm();
        let (f_a, potential) = self.normal(e_norm, dry.clearance, dry.journal_radius);
        if f_a == 0.0 {
            return (
                JointForce {
                    potential,
                    ..JointForce::default()
                },
                AsperityState::default(),
            );
        }
        let n = k.normal();
        let t = Vector2::new(-n.y, n.x);
        let v_t = dry.slip_speed(k, &t);
        let f_t = -self.friction * dry.friction_factor(v_t) * f_a * v_t.signum();
        let bearing_radius = dry.journal_radius + dry.clearance;
        (
            JointForce {
                force: -f_a * n + f_t * t,
                moment: dry.journal_radius * f_t,
                bearing_moment: -bearing_radius * f_t,
                potential,
            },
            AsperityState {
                force: f_a,
                pressure_peak: self.pressure((dry.clearance - e_norm).max(0.0)),
                friction_power: -f_t * v_t,
            },
        )
    }
}

#[cfg(test)]
mod tests;
