//! Lubricated journal bearing: infinitely short bearing (Ocvirk; Pinkus–Sternlicht) with the film
//! acting where its pressure is positive (Gümbel/half-Sommerfeld cavitation on a moving region),
//! and dry contact taking over near metal contact.
//!
//! ```text
//! ε = |e|/c,  ε̇ = e·ė/(|e| c),  γ̇ = (e × ė)/|e|²,  w = ω_J + ω_B − 2γ̇   (ω_B = 0: slider)
//! P(θ) = (μL³/2c²) (ε w sin θ − 2ε̇ cos θ)/(1 + ε cos θ)³      (θ from the maximum film)
//!      = (μL³/2c²) A sin(θ − θ₁)/(1 + ε cos θ)³,   A = √((εw)² + (2ε̇)²),  θ₁ = atan2(2ε̇, εw)
//! F_r = R ∫ P cos θ dθ,  F_t = R ∫ P sin θ dθ   over Θ = (θ₁, θ₁ + π), where P > 0
//! force on the journal F = F_r n + F_t t,  on the bearing −F
//! shear moments  M_J = −T − |e| F_t/2   on the journal,   M_B = T − |e| F_t/2   on the bearing
//!                T = 2π μ R³ L (ω_J − ω_B) / (c √(1 − ε²))
//! ```
//! The film shear: T is the Couette shear of the relative rotation taken over the whole
//! circumference (engineering practice: the oil fills the cavitated zone in streamers), which
//! tends to Petroff's 2π μ R³ L (ω_J − ω_B)/c for a centred journal; −|e| F_t/2 on each surface is
//! the pressure-driven (Poiseuille) part. Together they balance the couple |e| F_t of the force
//! pair at the two centres, M_J + M_B + |e| F_t = 0, so the massless film transmits no net moment
//! (the journal bearing's friction torque with its pressure part e W sin φ / 2: Pinkus &
//! Sternlicht 1961; Hamrock, Schmid & Jacobson 2004). With them the film's power on journal and
//! bearing, F·ė + M_J ω_J + M_B ω_B = c ε̇ F_r − |e| F_t w/2 − T (ω_J − ω_B), is
//! −(c K_h/2) ∫_Θ (ε w sin θ − 2ε̇ cos θ)²/(1 + ε cos θ)³ dθ − T (ω_J − ω_B) ≤ 0 for ε ≤ ε_b:
//! the film never adds energy, also in a whirl (where its force alone, through the journal
//! centre, can). Above ε_b the clamped film's force is no pressure field's; its moments
//! keep the actual |e| (the moment balance) and T the clamped ε.
//! For ε̇ = 0, w > 0 the region is (0, π) and the forces are Flores's closed forms
//! F_r = −K_h 2ε²w/(1−ε²)², F_t = K_h πεw/(2(1−ε²)^{3/2}), K_h = μRL³/(2c²) (tested below).
//! The fixed π-film with its mirror image for w < 0 (docs/model.md §4 (i)) has a jump in F_t at w = 0;
//! the journal then chatters on it and the error-controlled integrator stalls (measured: 2.2 million
//! rejected steps in the first 0.5 ms of benchmark C). The positive-pressure region moves
//! continuously with (ε̇, w), so the force is continuous (docs/model.md §4 (ii)).
//! The integral is evaluated by composite Gauss–Legendre, 24 panels × 5 points: the integrand's
//! peak at ε = 0.95 has a width ≈ √((1 − ε)/ε) ≈ 0.23 rad, twice the panel width π/24.
//!
//! Hand-over (docs/model.md §4, continuous rule): for ε ≥ ε_b the film force is evaluated with ε
//! clamped to ε_b (actual ε̇ and w), and the dry contact force of [`DryContact`] is added whenever
//! δ = |e| − c > 0. Both pieces are continuous, so the total force is continuous in e.
//!
//! # References
//! - P. Flores, J. Ambrósio, J. C. P. Claro, H. M. Lankarani, C. S. Koshy (2006), A study on
//!   dynamics of mechanical systems including joints with clearance and lubrication, Mech. Mach.
//!   Theory 41, 247–261.
//! - O. Pinkus, B. Sternlicht (1961), Theory of Hydrodynamic Lubrication, McGraw-Hill.
//! - B. J. Hamrock, S. R. Schmid, B. O. Jacobson (2004), Fundamentals of Fluid Film Lubrication,
//!   2nd ed., Marcel Dekker (short journal bearings: pressure, friction torque, Petroff).
//! - L. L. G. Daniel, T. H. Machado, K. L. Cavalca (2016), Mech. Mach. Theory 99, 19 (time-dependent
//!   cavitation boundaries).
//! - docs/model.md §4 (pressure, sign convention verified against direct integration).

use std::f64::consts::PI;

use nalgebra::Vector2;

use super::contact::DryContact;
use super::kinematics::{JointForce, JointKinematics};
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
struct FilmField {
    n: Vector2<f64>,
    eps: f64,
    amplitude: f64,
    sin1: f64,
    cos1: f64,
}

impl FilmField {
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
}

/// Constants of the lubricated joint.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JournalBearing {
    /// Dynamic viscosity μ \[Pa s\].
    pub viscosity: f64,
    /// Bearing length L \[m\].
    pub length: f64,
    /// Eccentricity ratio ε_b above which the film model is clamped and dry contact may act.
    pub switch_eccentricity: f64,
    /// Dry contact law (clearance, journal radius, friction, stiffness).
    pub dry: DryContact,
}

impl JournalBearing {
    /// Film coefficient K_h = μ R L³ / (2c²) \[N s\].
    pub fn film_coefficient(&self) -> f64 {
        let c = self.dry.clearance;
        self.viscosity * self.dry.journal_radius * self.length.powi(3) / (2.0 * c * c)
    }

    /// Film force on the journal over the positive-pressure region, ε clamped to ε_b.
    pub fn film_force(&self, k: &JointKinematics) -> Vector2<f64> {
        self.film(k).0
    }

    /// The film's pressure field in a state, `None` where it vanishes (a centred journal, or no
    /// wedge and no squeeze).
    fn field(&self, k: &JointKinematics) -> Option<FilmField> {
        let c = self.dry.clearance;
        let e_norm = k.e.norm();
        if e_norm <= 1e-12 * c {
            // Centred journal: the pressure amplitude εw → 0 and the direction is undefined.
            return None;
        }
        let n = k.e / e_norm;
        let eps = (e_norm / c).min(self.switch_eccentricity);
        let eps_dot = k.e.dot(&k.e_dot) / (e_norm * c);
        let gamma_dot = (k.e.x * k.e_dot.y - k.e.y * k.e_dot.x) / (e_norm * e_norm);
        let w = k.omega_journal + k.omega_bearing - 2.0 * gamma_dot;
        let amplitude = math::hypot(eps * w, 2.0 * eps_dot);
        if amplitude == 0.0 {
            return None;
        }
        // θ₁ = atan2(2ε̇, εw): its sine and cosine directly.
        Some(FilmField {
            n,
            eps,
            amplitude,
            sin1: 2.0 * eps_dot / amplitude,
            cos1: eps * w / amplitude,
        })
    }

    /// Film force on the journal and its tangential component F_t = F · t.
    fn film(&self, k: &JointKinematics) -> (Vector2<f64>, f64) {
        let Some(field) = self.field(k) else {
            return (Vector2::zeros(), 0.0);
        };
        let (mut f_r, mut f_t) = (0.0, 0.0);
        field.integrate(|p, _, sin, cos| {
            f_r += p * cos;
            f_t += p * sin;
        });
        let scale = self.film_coefficient();
        let t = Vector2::new(-field.n.y, field.n.x);
        (scale * (f_r * field.n + f_t * t), scale * f_t)
    }

    /// The largest film pressure at mid-length \[Pa\]: the short bearing's field
    /// p(θ, z) = (3μ/c²) (L²/4 − z²) A sin(θ − θ₁)/(1 + ε cos θ)³ (whose integral over the length
    /// is the P(θ) above) at z = 0, at its maximum over the pressure region, located from the
    /// largest node of the film's rule by Newton's method on d/dφ ln p = 0 (φ = θ − θ₁):
    /// ```text
    /// cot φ + 3ε sin θ/(1 + ε cos θ) = 0,   its derivative −1/sin²φ + 3ε (cos θ + ε)/(1 + ε cos θ)²
    /// ```
    /// For ε̇ = 0 the maximum is at cos θ* = (1 − √(1 + 24ε²))/(4ε). 0 without a film.
    pub fn peak_pressure(&self, k: &JointKinematics) -> f64 {
        let Some(field) = self.field(k) else {
            return 0.0;
        };
        let FilmField {
            eps, sin1, cos1, ..
        } = field;
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
        let c = self.dry.clearance;
        let shape = (sin_phi / (d * d * d)).max(best);
        3.0 * self.viscosity * self.length * self.length / (4.0 * c * c) * field.amplitude * shape
    }

    /// The rate at which the film dissipates energy \[W\], ≥ 0: its Couette shear
    /// T (ω_J − ω_B) and its pressure flow (c K_h/2) ∫_Θ A² sin²(θ − θ₁)/(1 + ε cos θ)³ dθ, which
    /// equal −(F·ė + M_J ω_J + M_B ω_B) for ε ≤ ε_b (module documentation); above ε_b, those of
    /// the film clamped there.
    pub fn film_loss(&self, k: &JointKinematics) -> f64 {
        let relative = k.omega_journal - k.omega_bearing;
        let eps = (k.e.norm() / self.dry.clearance).min(self.switch_eccentricity);
        let shear = self.petroff_coefficient() * relative * relative / (1.0 - eps * eps).sqrt();
        let Some(field) = self.field(k) else {
            return shear;
        };
        let mut flow = 0.0;
        field.integrate(|p, sin_phi, _, _| flow += p * field.amplitude * sin_phi);
        shear + 0.5 * self.dry.clearance * self.film_coefficient() * flow
    }

    /// Petroff's coefficient 2π μ R³ L / c \[N m s\]: the Couette shear torque of a centred
    /// journal per unit of relative speed ω_J − ω_B.
    pub fn petroff_coefficient(&self) -> f64 {
        let r = self.dry.journal_radius;
        std::f64::consts::TAU * self.viscosity * r * r * r * self.length / self.dry.clearance
    }

    /// The film's shear moments (M_J on the journal, M_B on the bearing) for its tangential
    /// force `f_t` on the journal: the Couette part ∓T with ε clamped to ε_b, and the pressure
    /// part −|e| F_t/2 on each (see the module documentation).
    fn shear_moments(&self, k: &JointKinematics, f_t: f64) -> (f64, f64) {
        let e_norm = k.e.norm();
        let eps = (e_norm / self.dry.clearance).min(self.switch_eccentricity);
        let couette = self.petroff_coefficient() * (k.omega_journal - k.omega_bearing)
            / (1.0 - eps * eps).sqrt();
        let pressure = 0.5 * e_norm * f_t;
        (-couette - pressure, couette - pressure)
    }

    /// Film force and shear moments, plus dry contact when the journal touches the bearing.
    pub fn force(&self, k: &JointKinematics, impact_velocity: f64) -> JointForce {
        let dry = self.dry.force(k, impact_velocity);
        let (film, f_t) = self.film(k);
        let (journal, bearing) = self.shear_moments(k, f_t);
        JointForce {
            force: film + dry.force,
            moment: dry.moment + journal,
            bearing_moment: dry.bearing_moment + bearing,
            ..dry
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::joint::ContactLaw;
    use crate::joint::hertz_stiffness;

    fn bearing() -> JournalBearing {
        JournalBearing {
            viscosity: 0.4,
            length: 0.04,
            switch_eccentricity: 0.95,
            dry: DryContact {
                elastic: crate::joint::Elastic::Point(hertz_stiffness(0.010, 0.0095, 207e9, 0.3)),
                clearance: 0.5e-3,
                journal_radius: 0.0095,
                restitution: 0.9,
                law: ContactLaw::LankaraniNikravesh,
                friction: 0.0,
                friction_v0: 1e-4,
                friction_v1: 1e-3,
            },
        }
    }

    /// K_h = μ R L³/(2c²) (docs/model.md §4) with benchmark C's bearing (docs/model.md §5(b) and
    /// §5(a): μ = 0.4 Pa s, L = 40 mm, journal radius 9.5 mm, clearance 0.5 mm):
    /// 0.4 · 0.0095 · 0.04³ / (2 · 0.0005²) = 0.48640 N s.
    #[test]
    fn film_coefficient_of_benchmark_c() {
        assert!((bearing().film_coefficient() - 0.48640).abs() < 1e-9);
    }

    /// Steady load (ε̇ = 0, γ̇ = 0): the attitude angle satisfies tan φ = π√(1−ε²)/(4ε) and the
    /// radial force pushes the journal back to the centre.
    #[test]
    fn steady_attitude_angle() {
        let b = bearing();
        let eps: f64 = 0.6;
        let k = JointKinematics {
            e: Vector2::new(eps * b.dry.clearance, 0.0),
            e_dot: Vector2::zeros(),
            omega_journal: 100.0,
            omega_bearing: 0.0,
        };
        let f = b.film_force(&k);
        assert!(f.x < 0.0);
        let tan_phi = f.y.abs() / f.x.abs();
        let expected = std::f64::consts::PI * (1.0 - eps * eps).sqrt() / (4.0 * eps);
        assert!((tan_phi - expected).abs() < 1e-12 * expected);
    }

    /// With ε̇ = 0 and w > 0 the positive-pressure region is (0, π): Flores's closed forms.
    /// Quadrature error measured 2.4e-9 at ε = 0.95 (the worst case, peaked integrand), < 1e-12
    /// below ε = 0.9; bound 1e-8.
    #[test]
    fn pure_rotation_matches_the_closed_form() {
        let b = bearing();
        let kh = b.film_coefficient();
        for eps in [0.1f64, 0.5, 0.9, 0.95] {
            let w = 300.0;
            let k = JointKinematics {
                e: Vector2::new(0.0, eps * b.dry.clearance),
                e_dot: Vector2::zeros(),
                omega_journal: w,
                omega_bearing: 0.0,
            };
            let f = b.film_force(&k);
            let s = 1.0 - eps * eps;
            let f_r = -kh * 2.0 * eps * eps * w / (s * s);
            let f_t = kh * std::f64::consts::PI * eps * w / (2.0 * math::powf(s, 1.5));
            // n = +y, t = −x.
            assert!(
                (f.y - f_r).abs() <= 1e-8 * f_r.abs(),
                "ε = {eps}: F_r {} vs {f_r}",
                f.y
            );
            assert!(
                (-f.x - f_t).abs() <= 1e-8 * f_t.abs(),
                "ε = {eps}: F_t {} vs {f_t}",
                -f.x
            );
        }
    }

    /// Pure squeeze (w = 0, ε̇ > 0): region (π/2, 3π/2), a purely radial restoring force equal to
    /// −K_h ε̇ ∫ 2cos²θ/(1+ε cos θ)³ dθ over it, checked against a fine midpoint sum.
    #[test]
    fn pure_squeeze_is_radial_and_restoring() {
        let b = bearing();
        let eps = 0.6;
        let eps_dot = 20.0;
        let c = b.dry.clearance;
        let k = JointKinematics {
            e: Vector2::new(eps * c, 0.0),
            e_dot: Vector2::new(eps_dot * c, 0.0),
            omega_journal: 0.0,
            omega_bearing: 0.0,
        };
        let f = b.film_force(&k);
        let m = 200_000;
        let pi = std::f64::consts::PI;
        let reference: f64 = (0..m)
            .map(|i| {
                let th = 0.5 * pi + (i as f64 + 0.5) * pi / m as f64;
                -2.0 * eps_dot * math::cos(th) * math::cos(th) / (1.0 + eps * math::cos(th)).powi(3)
                    * pi
                    / m as f64
            })
            .sum::<f64>()
            * b.film_coefficient();
        assert!(f.y.abs() < 1e-9 * f.x.abs());
        assert!(
            (f.x - reference).abs() < 1e-6 * reference.abs(),
            "{} vs {reference}",
            f.x
        );
    }

    /// The force is continuous where the mirrored π-film jumps: across w = 0 with ε̇ ≠ 0.
    #[test]
    fn force_is_continuous_across_zero_wedge_speed() {
        let b = bearing();
        let c = b.dry.clearance;
        let at = |omega: f64| JointKinematics {
            e: Vector2::new(0.7 * c, 0.0),
            e_dot: Vector2::new(-3e-3, 0.0),
            omega_journal: omega,
            omega_bearing: 0.0,
        };
        let below = b.film_force(&at(-1e-9));
        let above = b.film_force(&at(1e-9));
        assert!((below - above).norm() <= 1e-6 * below.norm());
    }

    /// Squeeze film resists approach to the wall (ε̇ > 0 ⇒ outward motion pushed back).
    #[test]
    fn squeeze_film_resists_approach() {
        let b = bearing();
        let k = JointKinematics {
            e: Vector2::new(0.0, 0.5 * b.dry.clearance),
            e_dot: Vector2::new(0.0, 0.1),
            omega_journal: 0.0,
            omega_bearing: 0.0,
        };
        assert!(b.film_force(&k).y < 0.0);
    }

    /// Petroff: a lightly loaded journal (ε = 0.01) turning at 300 rad/s in a bearing turning at
    /// −20 rad/s has the friction moment −2π μ R³ L (ω_J − ω_B)/c on it (3 %; the film's own
    /// terms add 0.005 %), the bearing the opposite, and the film's loss is the moment times the
    /// relative speed.
    #[test]
    fn a_lightly_loaded_journal_has_petroffs_torque() {
        let b = bearing();
        let (c, r, mu, l) = (b.dry.clearance, b.dry.journal_radius, b.viscosity, b.length);
        let k = JointKinematics {
            e: Vector2::new(0.01 * c, 0.0),
            e_dot: Vector2::zeros(),
            omega_journal: 300.0,
            omega_bearing: -20.0,
        };
        let petroff = std::f64::consts::TAU * mu * r * r * r * l * 320.0 / c;
        let f = b.force(&k, 1.0);
        assert!(
            (f.moment + petroff).abs() < 0.03 * petroff,
            "{} vs {petroff}",
            f.moment
        );
        assert!((f.bearing_moment - petroff).abs() < 0.03 * petroff);
        let loss = b.film_loss(&k);
        assert!(
            (loss - petroff * 320.0).abs() < 0.03 * petroff * 320.0,
            "{loss}"
        );
    }

    /// The steady short bearing's peak pressure at mid-length (ε̇ = 0, wedge speed w):
    /// p_max = 3μ|w|/c² · L²/4 · ε sin θ*/(1 + ε cos θ*)³, cos θ* = (1 − √(1 + 24ε²))/(4ε),
    /// for ε from 0.1 to 0.95 and both senses of rotation (1e-9; 3 % asked).
    #[test]
    fn the_steady_peak_pressure_is_the_short_bearings() {
        let b = bearing();
        let (c, mu, l) = (b.dry.clearance, b.viscosity, b.length);
        for eps in [0.1f64, 0.4, 0.8, 0.95] {
            for w in [250.0f64, -90.0] {
                let k = JointKinematics {
                    e: Vector2::new(0.0, eps * c),
                    e_dot: Vector2::zeros(),
                    omega_journal: w,
                    omega_bearing: 0.0,
                };
                let cos = (1.0 - (1.0 + 24.0 * eps * eps).sqrt()) / (4.0 * eps);
                let sin = (1.0 - cos * cos).sqrt();
                let expected = 3.0 * mu * w.abs() / (c * c) * l * l / 4.0 * eps * sin
                    / (1.0 + eps * cos).powi(3);
                let p = b.peak_pressure(&k);
                assert!(
                    (p - expected).abs() <= 1e-9 * expected,
                    "ε = {eps}, w = {w}: {p} vs {expected}"
                );
            }
        }
    }

    /// The film transmits no net moment (M_J + M_B + |e| F_t = 0) and never adds energy, also in
    /// a whirl: for journals whirling, squeezing and turning in every combination below ε_b, its
    /// power on journal and bearing F·ė + M_J ω_J + M_B ω_B is −film_loss (1e-9), ≤ 0. In a
    /// whirl slower than half the journal's speed (oil whirl) the force alone does positive work.
    #[test]
    fn the_film_transmits_no_moment_and_dissipates() {
        let b = bearing();
        let c = b.dry.clearance;
        let mut force_alone_adds = false;
        for eps in [0.2f64, 0.6, 0.9] {
            for (radial, whirl) in [
                (0.0, 0.0),
                (0.3, 0.0),
                (-0.2, 150.0),
                (0.05, -80.0),
                (0.0, 60.0),
            ] {
                for (omega_journal, omega_bearing) in [(200.0, 0.0), (200.0, 60.0), (-50.0, 0.0)] {
                    let (sin, cos) = math::sin_cos(0.7);
                    let n = Vector2::new(cos, sin);
                    let t = Vector2::new(-sin, cos);
                    let e = eps * c * n;
                    let k = JointKinematics {
                        e,
                        e_dot: radial * c * 100.0 * n + eps * c * whirl * t,
                        omega_journal,
                        omega_bearing,
                    };
                    let f = b.force(&k, 1.0);
                    let f_t = f.force.dot(&t);
                    let couple = f.moment + f.bearing_moment + e.norm() * f_t;
                    assert!(couple.abs() < 1e-12 * f.moment.abs().max(1e-9), "{couple}");
                    let power = k.power(&f);
                    let loss = b.film_loss(&k);
                    assert!(
                        (power + loss).abs() <= 1e-9 * loss,
                        "ε {eps}, ė ({radial}, {whirl}), ω ({omega_journal}, {omega_bearing}): \
                         {power} vs −{loss}"
                    );
                    force_alone_adds |= f.force.dot(&k.e_dot) > 0.0;
                }
            }
        }
        assert!(force_alone_adds);
    }

    /// The force is continuous across the switch ratio ε_b and across metal contact (δ = 0).
    #[test]
    fn hand_over_is_continuous() {
        let b = bearing();
        let c = b.dry.clearance;
        let at = |r: f64| JointKinematics {
            e: Vector2::new(r * c, 0.0),
            e_dot: Vector2::new(0.02, 0.01),
            omega_journal: 50.0,
            omega_bearing: 0.0,
        };
        for r in [b.switch_eccentricity, 1.0] {
            let below = b.force(&at(r * (1.0 - 1e-9)), 0.1).force;
            let above = b.force(&at(r * (1.0 + 1e-9)), 0.1).force;
            assert!(
                (below - above).norm() <= 1e-6 * below.norm(),
                "jump at ε = {r}: {below:?} vs {above:?}"
            );
        }
    }
}
