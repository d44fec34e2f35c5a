//! Generalized-α coefficients (Chung & Hulbert 1993) for q̈ = a(t, q, q̇), in the form of Arnold &
//! Brüls (2007), which keeps the algorithmic acceleration ā apart from the true one a:
//! ```text
//! (1 − α_m) āₙ₊₁ + α_m āₙ = (1 − α_f) aₙ₊₁ + α_f aₙ,        aₙ₊₁ = a(tₙ₊₁, qₙ₊₁, q̇ₙ₊₁)
//! qₙ₊₁ = qₙ + h q̇ₙ + h² (½ − β) āₙ + h² β āₙ₊₁
//! q̇ₙ₊₁ = q̇ₙ + h (1 − γ) āₙ + h γ āₙ₊₁
//! α_m = (2ρ∞ − 1)/(ρ∞ + 1),   α_f = ρ∞/(ρ∞ + 1),   γ = ½ + α_f − α_m,   β = ¼ (γ + ½)²
//! ```
//! Second order, unconditionally stable on linear systems, with the spectral radius of the
//! amplification matrix tending to ρ∞ ∈ [0, 1] as ωh → ∞: ρ∞ = 1 is the trapezoidal rule (no
//! numerical dissipation), ρ∞ = 0 annihilates unresolved frequencies in one step, and low
//! frequencies are damped least for a given high-frequency dissipation (Chung & Hulbert's optimum).
//!
//! Local error estimate for the step-size control: the updates compared with quadratures of the
//! true accelerations at both ends,
//! ```text
//! e_q = h² [(½ − β) āₙ + β āₙ₊₁ − aₙ/3 − aₙ₊₁/6]       (exact for a linear in t: O(h⁴) reference)
//! e_q̇ = h  [(1 − γ) āₙ + γ āₙ₊₁ − aₙ/2 − aₙ₊₁/2]       (trapezoidal rule: O(h³) reference)
//! ```
//! In smooth motion ā approximates a at the shifted time tₙ + Δh, Δ = α_m − α_f (Arnold & Brüls
//! 2007), and e_q → (β + Δ/2 − 1/6) h³ q⃛, the position error of the method (h³ q⃛/12 for the
//! trapezoidal rule, as the Newmark-family estimate of Géradin & Cardona 2001, §11.5). Where the
//! acceleration jumps (a contact onset) ā lags a by the jump, and both estimates see it.
//!
//! # References
//! - J. Chung, G. M. Hulbert (1993), A time integration algorithm for structural dynamics with
//!   improved numerical dissipation: the generalized-α method, J. Appl. Mech. 60, 371–375.
//! - M. Arnold, O. Brüls (2007), Convergence of the generalized-α scheme for constrained mechanical
//!   systems, Multibody Syst. Dyn. 18, 185–202.
//! - M. Géradin, A. Cardona (2001), Flexible Multibody Dynamics: A Finite Element Approach, Wiley.

use crate::error::ModelError;

/// The coefficients of one generalized-α method.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GeneralizedAlpha {
    /// Spectral radius at infinity ρ∞.
    pub spectral_radius: f64,
    /// α_m.
    pub alpha_m: f64,
    /// α_f.
    pub alpha_f: f64,
    /// γ.
    pub gamma: f64,
    /// β.
    pub beta: f64,
}

impl GeneralizedAlpha {
    /// The optimal coefficients for a spectral radius at infinity ρ∞ ∈ [0, 1]
    /// (`solver.spectralRadius`).
    pub fn new(spectral_radius: f64) -> Result<Self, ModelError> {
        if !(0.0..=1.0).contains(&spectral_radius) {
            return Err(ModelError::invalid(
                "solver.spectralRadius",
                spectral_radius,
                "[0, 1]",
            ));
        }
        let rho = spectral_radius;
        let alpha_m = (2.0 * rho - 1.0) / (rho + 1.0);
        let alpha_f = rho / (rho + 1.0);
        let gamma = 0.5 + alpha_f - alpha_m;
        Ok(Self {
            spectral_radius: rho,
            alpha_m,
            alpha_f,
            gamma,
            beta: 0.25 * (gamma + 0.5).powi(2),
        })
    }

    /// ∂āₙ₊₁/∂aₙ₊₁ = (1 − α_f)/(1 − α_m).
    pub fn acceleration_weight(&self) -> f64 {
        (1.0 - self.alpha_f) / (1.0 - self.alpha_m)
    }

    /// The part of āₙ₊₁ known at the step start: (α_f aₙ − α_m āₙ)/(1 − α_m).
    pub fn known_acceleration(&self, a: f64, a_bar: f64) -> f64 {
        (self.alpha_f * a - self.alpha_m * a_bar) / (1.0 - self.alpha_m)
    }

    /// Local error estimates (e_q, e_q̇) of one coordinate over a step h from its true and
    /// algorithmic accelerations at both ends (module documentation).
    pub fn local_error(&self, h: f64, a0: f64, a1: f64, a_bar0: f64, a_bar1: f64) -> (f64, f64) {
        let position = (0.5 - self.beta) * a_bar0 + self.beta * a_bar1 - a0 / 3.0 - a1 / 6.0;
        let velocity = (1.0 - self.gamma) * a_bar0 + self.gamma * a_bar1 - 0.5 * (a0 + a1);
        (h * h * position, h * velocity)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Matrix3, Vector3};

    /// One step of the method on the undamped oscillator q̈ = −ω² q as the map (q, hq̇, h²ā) →
    /// next, solved exactly for aₙ₊₁ (linear).
    fn step(c: &GeneralizedAlpha, wh: f64, x: [f64; 3]) -> [f64; 3] {
        let [q, v, ab] = x;
        let w2 = wh * wh;
        let a_n = -w2 * q;
        let known = c.known_acceleration(a_n, ab);
        let k = c.acceleration_weight();
        // a₁ = −w² q₁, q₁ = q + v + (½ − β) ab + β (known + k a₁)
        let q_rest = q + v + (0.5 - c.beta) * ab + c.beta * known;
        let q1 = q_rest / (1.0 + w2 * c.beta * k);
        let a1 = -w2 * q1;
        let ab1 = known + k * a1;
        let v1 = v + (1.0 - c.gamma) * ab + c.gamma * ab1;
        [q1, v1, ab1]
    }

    /// The spectral radius of the amplification matrix tends to ρ∞ as ωh → ∞, and stays within
    /// 1e-4 of 1 for resolved frequencies (ωh ≤ 0.1), its deficit falling as (ωh)⁴: little
    /// dissipation of the physics.
    #[test]
    fn spectral_radius_at_infinity_is_the_parameter() {
        for rho in [0.0, 0.3, 0.8, 1.0] {
            let c = GeneralizedAlpha::new(rho).unwrap();
            // Eigenvalues of the amplification matrix, built column by column from unit states.
            let radius = |wh: f64| {
                let columns: Vec<Vector3<f64>> = (0..3)
                    .map(|j| {
                        let mut unit = [0.0; 3];
                        unit[j] = 1.0;
                        Vector3::from(step(&c, wh, unit))
                    })
                    .collect();
                Matrix3::from_columns(&columns)
                    .complex_eigenvalues()
                    .iter()
                    .map(|l| l.norm())
                    .fold(0.0, f64::max)
            };
            let high = radius(1e6);
            assert!((high - rho).abs() < 1e-3, "ρ∞ = {rho}: radius {high}");
            let (low, lower) = (radius(0.1), radius(0.05));
            println!(
                "ρ∞ = {rho}: 1 − radius {:.2e} at ωh = 0.1, {:.2e} at 0.05",
                1.0 - low,
                1.0 - lower
            );
            assert!(
                low <= 1.0 + 1e-12 && low > 1.0 - 1e-4,
                "ρ∞ = {rho}: radius {low} at ωh = 0.1"
            );
            if rho < 1.0 {
                // The damping of resolved frequencies falls as (ωh)⁴ (measured ratio 16).
                assert!(
                    (1.0 - low) > 12.0 * (1.0 - lower),
                    "ρ∞ = {rho}: {low} {lower}"
                );
            }
        }
    }

    /// Trapezoidal rule at ρ∞ = 1 (α_m = α_f = ½, γ = ½, β = ¼); for a = q⃛ t (ā = a at ρ∞ = 1)
    /// the position estimate is h³ q⃛/12, the trapezoidal rule's error, and the velocity estimate
    /// vanishes (exact for linear a). Out-of-range values are errors naming the parameter.
    #[test]
    fn coefficients_error_estimate_and_range() {
        let c = GeneralizedAlpha::new(1.0).unwrap();
        assert_eq!(
            (c.alpha_m, c.alpha_f, c.gamma, c.beta),
            (0.5, 0.5, 0.5, 0.25)
        );
        let (h, jerk) = (0.1, 2.0);
        let (e_q, e_v) = c.local_error(h, 0.0, jerk * h, 0.0, jerk * h);
        assert!((e_q - h.powi(3) * jerk / 12.0).abs() < 1e-15, "{e_q}");
        assert_eq!(e_v, 0.0);
        for bad in [-0.1, 1.1, f64::NAN] {
            let e = GeneralizedAlpha::new(bad).unwrap_err().to_string();
            assert!(e.contains("solver.spectralRadius"), "{e}");
        }
    }
}
