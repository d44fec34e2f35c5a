//! The infinitely short bearing's film (Ocvirk; Pinkus–Sternlicht), acting where its pressure is
//! positive (Gümbel/half-Sommerfeld cavitation on a moving region): the field of a state and its
//! integrals, by composite Gauss–Legendre quadrature.
//!
//! ```text
//! ε = |e|/c,  ε̇ = e·ė/(|e| c),  γ̇ = (e × ė)/|e|²,  w = ω_J + ω_B − 2γ̇
//! P(θ) = (μL³/2c²) (ε w sin θ − 2ε̇ cos θ)/(1 + ε cos θ)³      (θ from the maximum film)
//!      = (μL³/2c²) A sin(θ − θ₁)/(1 + ε cos θ)³,   A = √((εw)² + (2ε̇)²),  θ₁ = atan2(2ε̇, εw)
//! F_r = R ∫ P cos θ dθ,  F_t = R ∫ P sin θ dθ   over Θ = (θ₁, θ₁ + π), where P > 0
//! p(θ, z) = (3μ/c²) (L²/4 − z²) A sin(θ − θ₁)/(1 + ε cos θ)³   (its integral over the length is P)
//! side flow out of both ends  Q_s = L R ∫_Θ c A sin(θ − θ₁)/2 dθ = c R L A
//! ```
//! In the squeeze direction ψ of the finite film ([`super::reynolds`]), A = 2V and θ₁ = ψ + π/2.
//! For ε̇ = 0, w > 0 the region is (0, π) and the forces are Flores's closed forms
//! F_r = −K_h 2ε²w/(1−ε²)², F_t = K_h πεw/(2(1−ε²)^{3/2}), K_h = μRL³/(2c²).
//! The fixed π-film with its mirror image for w < 0 (docs/model.md §4 (i)) has a jump in F_t at
//! w = 0; the journal then chatters on it and the error-controlled integrator stalls (measured:
//! 2.2 million rejected steps in the first 0.5 ms of benchmark C). The positive-pressure region
//! moves continuously with (ε̇, w), so the force is continuous (docs/model.md §4 (ii)).
//! The integral is evaluated by composite Gauss–Legendre, 24 panels × 5 points: the integrand's
//! peak at ε = 0.95 has a width ≈ √((1 − ε)/ε) ≈ 0.23 rad, twice the panel width π/24.
//!
//! # References
//! - F. W. Ocvirk (1952), Short-bearing approximation for full journal bearings, NACA TN 2808.
//! - P. Flores, J. Ambrósio, J. C. P. Claro, H. M. Lankarani, C. S. Koshy (2006), A study on
//!   dynamics of mechanical systems including joints with clearance and lubrication, Mech. Mach.
//!   Theory 41, 247–261.
//! - L. L. G. Daniel, T. H. Machado, K. L. Cavalca (2016), Mech. Mach. Theory 99, 19 (time-dependent
//!   cavitation boundaries).

use std::f64::consts::PI;

use nalgebra::Vector2;

use super::kinematics::JointKinematics;
use crate::math;
use crate::quadrature::GAUSS_5;

/// Panels of the composite Gauss–Legendre rule over the pressure region.
const FILM_PANELS: usize = 24;
/// Nodes of the composite rule.
const FILM_NODES: usize = 5 * FILM_PANELS;

/// Offsets φ = θ − θ₁ ∈ (0, π) of the composite rule's nodes with their weights, sin φ and cos φ:
/// the node angles θ = θ₁ + φ then need only the angle-addition formulas, not a sine and cosine
/// per node (the film force is evaluated at every right-hand side).
#[derive(Clone, Debug, PartialEq)]
struct FilmRule {
    phi: [f64; FILM_NODES],
    weight: [f64; FILM_NODES],
    sin: [f64; FILM_NODES],
    cos: [f64; FILM_NODES],
}

impl FilmRule {
    fn new() -> Self {
        let panel = std::f64::consts::PI / FILM_PANELS as f64;
        let mut rule = Self {
            phi: [0.0; FILM_NODES],
            weight: [0.0; FILM_NODES],
            sin: [0.0; FILM_NODES],
            cos: [0.0; FILM_NODES],
        };
        for i in 0..FILM_PANELS {
            for (k, (xi, weight)) in GAUSS_5.on_unit_interval(panel).enumerate() {
                let phi = (i as f64 + xi) * panel;
                let (sin, cos) = math::sin_cos(phi);
                let m = 5 * i + k;
                rule.phi[m] = phi;
                rule.weight[m] = weight;
                rule.sin[m] = sin;
                rule.cos[m] = cos;
            }
        }
        rule
    }
}

fn film_rule() -> &'static FilmRule {
    static RULE: std::sync::OnceLock<FilmRule> = std::sync::OnceLock::new();
    RULE.get_or_init(FilmRule::new)
}

/// Newton iterations for the location of the film's peak pressure (quadratic convergence from
/// the largest of 120 nodes: 3 or 4 reach round-off).
const PEAK_ITERATIONS: usize = 8;

/// The film's pressure field in one state: the direction n = e/|e|, ε (clamped to ε_b), and the
/// amplitude A and phase θ₁ of εw sin θ − 2ε̇ cos θ = A sin(θ − θ₁).
#[derive(Clone, Copy, Debug)]
pub struct FilmField {
    /// The direction n = e/|e|.
    pub n: Vector2<f64>,
    /// The eccentricity ratio, clamped to ε_b.
    pub eps: f64,
    /// The amplitude A = √((εw)² + (2ε̇)²) \[1/s\].
    pub amplitude: f64,
    sin1: f64,
    cos1: f64,
}

impl FilmField {
    /// The field of a state of a bearing with clearance `c`, ε clamped to `switch_eccentricity`;
    /// `None` where it vanishes (a centred journal, or no wedge and no squeeze).
    pub fn of(k: &JointKinematics, c: f64, switch_eccentricity: f64) -> Option<Self> {
        let e_norm = k.e.norm();
        if e_norm <= 1e-12 * c {
            // Centred journal: the pressure amplitude εw → 0 and the direction is undefined.
            return None;
        }
        let n = k.e / e_norm;
        let eps = (e_norm / c).min(switch_eccentricity);
        let eps_dot = k.e.dot(&k.e_dot) / (e_norm * c);
        let gamma_dot = (k.e.x * k.e_dot.y - k.e.y * k.e_dot.x) / (e_norm * e_norm);
        let w = k.omega_journal + k.omega_bearing - 2.0 * gamma_dot;
        let amplitude = math::hypot(eps * w, 2.0 * eps_dot);
        if amplitude == 0.0 {
            return None;
        }
        // θ₁ = atan2(2ε̇, εw): its sine and cosine directly.
        Some(Self {
            n,
            eps,
            amplitude,
            sin1: 2.0 * eps_dot / amplitude,
            cos1: eps * w / amplitude,
        })
    }

    /// The field of a unit squeeze speed V = 1 (A = 2) in the direction `psi` at eccentricity
    /// ratio `eps`, n along x: the short film in the finite film's variables.
    pub fn of_squeeze(eps: f64, psi: f64) -> Self {
        let (sin, cos) = math::sin_cos(psi);
        Self {
            n: Vector2::x(),
            eps,
            amplitude: 2.0,
            sin1: cos,
            cos1: -sin,
        }
    }

    /// cos ψ and sin ψ of the squeeze direction ψ = θ₁ − π/2.
    pub fn squeeze_direction(&self) -> (f64, f64) {
        (self.sin1, -self.cos1)
    }

    /// The tangent t = ẑ × n.
    pub fn tangent(&self) -> Vector2<f64> {
        Vector2::new(-self.n.y, self.n.x)
    }

    /// Calls `f(p, sin φ, sin θ, cos θ)` at each node of the film's rule over the pressure
    /// region θ = θ₁ + φ, φ ∈ (0, π), with p = wᵢ A sin φ/(1 + ε cos θ)³ (P(θ) dθ / K_h).
    #[inline]
    fn integrate(&self, mut f: impl FnMut(f64, f64, f64, f64)) {
        let rule = film_rule();
        for m in 0..FILM_NODES {
            let (sin_phi, cos_phi) = (rule.sin[m], rule.cos[m]);
            let cos = self.cos1 * cos_phi - self.sin1 * sin_phi;
            let sin = self.sin1 * cos_phi + self.cos1 * sin_phi;
            let d = 1.0 + self.eps * cos;
            f(
                rule.weight[m] * self.amplitude * sin_phi / (d * d * d),
                sin_phi,
                sin,
                cos,
            );
        }
    }

    /// (F_r, F_t)/K_h: the integrals ∫ A sin(θ − θ₁)/(1 + ε cos θ)³ (cos θ, sin θ) dθ over the
    /// pressure region.
    pub fn force(&self) -> (f64, f64) {
        let (mut f_r, mut f_t) = (0.0, 0.0);
        self.integrate(|p, _, sin, cos| {
            f_r += p * cos;
            f_t += p * sin;
        });
        (f_r, f_t)
    }

    /// The pressure flow's dissipation per c K_h/2: ∫_Θ A² sin²(θ − θ₁)/(1 + ε cos θ)³ dθ.
    pub fn flow_loss(&self) -> f64 {
        let mut flow = 0.0;
        self.integrate(|p, sin_phi, _, _| flow += p * self.amplitude * sin_phi);
        flow
    }

    /// The largest sin(θ − θ₁)/(1 + ε cos θ)³ over the pressure region, located from the
    /// largest node of the film's rule by Newton's method on d/dφ ln p = 0 (φ = θ − θ₁):
    /// ```text
    /// cot φ + 3ε sin θ/(1 + ε cos θ) = 0,   its derivative −1/sin²φ + 3ε (cos θ + ε)/(1 + ε cos θ)²
    /// ```
    /// For ε̇ = 0 the maximum is at cos θ* = (1 − √(1 + 24ε²))/(4ε).
    pub fn peak_shape(&self) -> f64 {
        let Self {
            eps, sin1, cos1, ..
        } = *self;
        let shape = |phi: f64| {
            let (sin_phi, cos_phi) = math::sin_cos(phi);
            let (sin, cos) = (
                sin1 * cos_phi + cos1 * sin_phi,
                cos1 * cos_phi - sin1 * sin_phi,
            );
            (sin_phi, cos_phi, sin, cos)
        };
        let rule = film_rule();
        let (mut best, mut phi) = (0.0, 0.0);
        for m in 0..FILM_NODES {
            let cos = cos1 * rule.cos[m] - sin1 * rule.sin[m];
            let d = 1.0 + eps * cos;
            let value = rule.sin[m] / (d * d * d);
            if value > best {
                (best, phi) = (value, rule.phi[m]);
            }
        }
        for _ in 0..PEAK_ITERATIONS {
            let (sin_phi, cos_phi, sin, cos) = shape(phi);
            let d = 1.0 + eps * cos;
            let slope = cos_phi / sin_phi + 3.0 * eps * sin / d;
            let curvature = -1.0 / (sin_phi * sin_phi) + 3.0 * eps * (cos + eps) / (d * d);
            if curvature >= 0.0 {
                break;
            }
            let next = (phi - slope / curvature).clamp(0.5 * phi, 0.5 * (phi + PI));
            let converged = (next - phi).abs() <= 1e-12;
            phi = next;
            if converged {
                break;
            }
        }
        let (sin_phi, _, _, cos) = shape(phi);
        let d = 1.0 + eps * cos;
        (sin_phi / (d * d * d)).max(best)
    }
}
