//! The lubricated joint against closed forms: Flores's short-film forces, Petroff, the peak pressure,
//! continuity, and the film's power.

use super::*;
use crate::joint::ContactLaw;
use crate::joint::hertz_stiffness;
use crate::math;

fn bearing() -> JournalBearing {
    JournalBearing {
        viscosity: 0.4,
        length: 0.04,
        lands: 1.0,
        feed: None,
        switch_eccentricity: 0.95,
        film: Film::Short,
        asperity: None,
        heat_balance: None,
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
        viscosity: None,
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
            viscosity: None,
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
        viscosity: None,
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
        viscosity: None,
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
        viscosity: None,
    };
    assert!(b.film_force(&k).y < 0.0);
}

/// Petroff: a lightly loaded journal (ε = 0.01) turning at 300 rad/s in a bearing turning at
/// −20 rad/s has the friction moment −2π μ R³ L (ω_J − ω_B)/c on it within 0.03 % (measured
/// 0.015 %: the shear's 1/√(1 − ε²) adds 0.005 %, the film pressure's moment ε c W/2 of order
/// ε² (L/R)² the rest), the bearing the opposite, and the film's loss is the moment times the
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
        viscosity: None,
    };
    let petroff = std::f64::consts::TAU * mu * r * r * r * l * 320.0 / c;
    let f = b.force(&k, 1.0);
    assert!(
        (f.moment + petroff).abs() < 3e-4 * petroff,
        "{} vs {petroff}",
        f.moment
    );
    assert!((f.bearing_moment - petroff).abs() < 3e-4 * petroff);
    let loss = b.film_loss(&k);
    assert!(
        (loss - petroff * 320.0).abs() < 3e-4 * petroff * 320.0,
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
                viscosity: None,
            };
            let cos = (1.0 - (1.0 + 24.0 * eps * eps).sqrt()) / (4.0 * eps);
            let sin = (1.0 - cos * cos).sqrt();
            let expected =
                3.0 * mu * w.abs() / (c * c) * l * l / 4.0 * eps * sin / (1.0 + eps * cos).powi(3);
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
                    viscosity: None,
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
        viscosity: None,
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
