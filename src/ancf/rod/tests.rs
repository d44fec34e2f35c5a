//! Unit tests of the ANCF rod.

use super::equilibrium::RodLoad;
use super::sections::{SectionResult, section_place};
use super::*;

/// A pinned beam of the benchmark-B rod under a uniform transverse load q small enough for the
/// linear theory: its deflection w(x) = q x (L³ − 2Lx² + x³)/(24 EI) and slope, and the nodal
/// coordinates of a rod of `n` elements that carry them exactly. The load is the rod's weight
/// under an upward gravity q/(ρA), held by the pin at x = 0 with the force −q L/2 (the other pin's
/// is the same): the [`RodLoad`] of the resultants.
struct LoadedBeam {
    p: RodProperties,
    l: f64,
    ei: f64,
    q: f64,
}

impl LoadedBeam {
    fn new() -> Self {
        let p = RodProperties::benchmark_b();
        let (l, ei) = (p.length, p.youngs_modulus * p.second_moment_of_area);
        Self {
            p,
            l,
            ei,
            q: 1e-5 * 8.0 * ei / (l * l),
        }
    }

    fn w(&self, x: f64) -> f64 {
        let (l, q) = (self.l, self.q);
        q * x * (l.powi(3) - 2.0 * l * x * x + x.powi(3)) / (24.0 * self.ei)
    }

    fn slope(&self, x: f64) -> f64 {
        let (l, q) = (self.l, self.q);
        q * (l.powi(3) - 6.0 * l * x * x + 4.0 * x.powi(3)) / (24.0 * self.ei)
    }

    /// The rod of `n` elements and its nodal coordinates on the deflected line.
    fn rod(&self, n: usize) -> (Rod, Vec<f64>) {
        let e = (0..=n)
            .flat_map(|k| {
                let x = self.l * k as f64 / n as f64;
                [x, self.w(x), 1.0, self.slope(x)]
            })
            .collect();
        (Rod::new(self.p, n).unwrap(), e)
    }

    fn load(&self) -> RodLoad {
        RodLoad {
            start_force: Vector2::new(0.0, -self.q * self.l / 2.0),
            start_moment: 0.0,
            gravity: Vector2::new(0.0, self.q / (self.p.density * self.p.area)),
        }
    }
}

/// The rod's `result` at `n` evenly spaced sections, at rest (no acceleration).
fn sections_at_rest(
    rod: &Rod,
    e: &[f64],
    load: &RodLoad,
    result: SectionResult,
    n: usize,
) -> Vec<f64> {
    let mut out = vec![0.0; n];
    rod.sections(e, &vec![0.0; e.len()], load, result, &mut out);
    out
}

/// The pinned beam under a uniform load of the test below, at evenly spaced sections: the
/// moment is the statics' −q x (L − x)/2 everywhere, the axial force the shear force's share
/// along the slightly turned tangent (at most q L/2 · |w'|, nothing in a straight rod), and the
/// deflection the exact w(x) to the cubic (Hermite) interpolation's error between the nodes, at
/// most w (h/2)⁴/4! = q h⁴/(384 EI) for elements of length h.
#[test]
fn a_pinned_beam_under_a_uniform_load_has_the_exact_section_moments() {
    let beam = LoadedBeam::new();
    let (l, ei, q) = (beam.l, beam.ei, beam.q);
    let w = |x: f64| beam.w(x);
    let largest_moment = q * l * l / 8.0;
    let largest_turn = beam.slope(0.0).abs();
    for n in 1..=9 {
        let interpolation = q * (l / n as f64).powi(4) / (384.0 * ei);
        let (rod, e) = beam.rod(n);
        for sections in [2, 7, 11, 20] {
            let resultant = |result| sections_at_rest(&rod, &e, &beam.load(), result, sections);
            let moments = resultant(SectionResult::BendingMoment);
            let axial = resultant(SectionResult::AxialForce);
            let deflections = resultant(SectionResult::Deflection);
            for k in 0..sections {
                let x = section_place(k, sections) * l;
                let expected = -q * x * (l - x) / 2.0;
                assert!(
                    (moments[k] - expected).abs() < 1e-12 * largest_moment,
                    "{n} elements, section {k}/{sections}: {} vs {expected}",
                    moments[k]
                );
                assert!(
                    axial[k].abs() <= q * l / 2.0 * largest_turn * (1.0 + 1e-6),
                    "{n}, {k}/{sections}: {}",
                    axial[k]
                );
                assert!(
                    (deflections[k] - w(x)).abs()
                        <= interpolation * (1.0 + 1e-6) + 1e-9 * w(0.5 * l),
                    "{n}, {k}/{sections}: {} vs {}",
                    deflections[k],
                    w(x)
                );
            }
        }
    }
}

/// The pinned beam under a uniform load q: the largest stress is the mid-span moment's,
/// σ = (q L²/8) c/I, whether mid-span is a node (even n) or inside an element (odd n). The
/// signed field: the mid-span moment and both fibres' stresses, where the largest lies.
#[test]
fn a_pinned_beam_under_a_uniform_load_has_the_midspan_stress() {
    let beam = LoadedBeam::new();
    let (p, l, q) = (beam.p, beam.l, beam.q);
    let expected = q * l * l / 8.0 * p.outer_fibre_distance / p.second_moment_of_area;
    for n in 1..=9 {
        let (rod, e) = beam.rod(n);
        let stresses = rod.normal_stresses(&e, &vec![0.0; e.len()], &beam.load());
        let sigma = stresses.largest;
        // the axial force's share: at most the shear force along the turned tangent
        let direct = q * l / 2.0 * beam.slope(0.0).abs() / p.area;
        assert!(
            (sigma - expected).abs() < 1e-12 * expected + direct,
            "{n} elements: {sigma} vs {expected}"
        );
        // Bulging up (w > 0) the rod turns right: the moment −q L²/8 at mid-span, its fibres
        // at ±σ, no axial force there (the tangent is level); the largest stress at mid-span.
        let moment = q * l * l / 8.0;
        assert!(
            (stresses.midspan_moment + moment).abs() < 1e-12 * moment,
            "{n}: {stresses:?}"
        );
        assert!((stresses.max - expected).abs() < 1e-12 * expected + direct);
        assert!((stresses.min + expected).abs() < 1e-12 * expected + direct);
        assert!(
            stresses.midspan_axial_force.abs() < 1e-9 * q * l,
            "{n}: {stresses:?}"
        );
        assert!((stresses.location - 0.5).abs() < 1e-12, "{n}: {stresses:?}");
    }
}

/// A rod pulled by F along its axis at both ends carries N = F and no moment at every section,
/// σ = F/A everywhere, for one element and for several, in any direction.
#[test]
fn a_stretched_rod_carries_the_end_force() {
    let p = RodProperties::benchmark_b();
    let force = 2.5e3;
    for n in [1, 3, 8] {
        let rod = Rod::new(p, n).unwrap();
        let angle = 0.3;
        let e = rod.straight_configuration(Vector2::new(0.1, -0.2), angle);
        let load = RodLoad {
            start_force: -force * Vector2::new(math::cos(angle), math::sin(angle)),
            start_moment: 0.0,
            gravity: Vector2::zeros(),
        };
        for (result, expected) in [
            (SectionResult::AxialForce, force),
            (SectionResult::BendingMoment, 0.0),
        ] {
            for value in sections_at_rest(&rod, &e, &load, result, 9) {
                assert!((value - expected).abs() < 1e-12 * force * p.length.max(1.0));
            }
        }
        let sigma = rod.normal_stresses(&e, &vec![0.0; e.len()], &load).largest;
        let expected = force / p.area;
        assert!((sigma - expected).abs() < 1e-12 * expected, "{n}: {sigma}");
    }
}

/// A rod turning at a steady ω about its first node, free at its other end: the pin pulls it
/// inwards with ρAω²L²/2, and its section carries the centripetal load of the part beyond it,
/// N(s) = ρAω²(L² − s²)/2, no moment, N = 0 at the free end.
#[test]
fn a_rotating_rod_carries_its_centripetal_load() {
    let p = RodProperties::benchmark_b();
    let (omega, angle): (f64, f64) = (150.0, 1.1);
    let rho_a = p.density * p.area;
    let l = p.length;
    let axis = Vector2::new(math::cos(angle), math::sin(angle));
    for n in [1, 2, 5] {
        let rod = Rod::new(p, n).unwrap();
        let e = rod.straight_configuration(Vector2::zeros(), angle);
        // every nodal vector (position and slope) turns with the rod: ë = −ω² e
        let e_ddot: Vec<f64> = e.iter().map(|v| -omega * omega * v).collect();
        let load = RodLoad {
            start_force: -rho_a * omega * omega * l * l / 2.0 * axis,
            start_moment: 0.0,
            gravity: Vector2::zeros(),
        };
        let scale = rho_a * omega * omega * l * l / 2.0;
        let sections = 11;
        let mut axial = vec![0.0; sections];
        let mut moments = vec![0.0; sections];
        rod.sections(&e, &e_ddot, &load, SectionResult::AxialForce, &mut axial);
        rod.sections(
            &e,
            &e_ddot,
            &load,
            SectionResult::BendingMoment,
            &mut moments,
        );
        for k in 0..sections {
            let s = section_place(k, sections) * l;
            let expected = rho_a * omega * omega * (l * l - s * s) / 2.0;
            assert!(
                (axial[k] - expected).abs() < 1e-12 * scale,
                "{n}, {k}: {}",
                axial[k]
            );
            assert!(
                moments[k].abs() < 1e-12 * scale * l,
                "{n}, {k}: {}",
                moments[k]
            );
        }
    }
}

/// The end section carries the other pin's force in any motion: a deformed, damped rod of the
/// full model accelerated by its equations of motion M ë = F − Q(e, ė) + Q_g under end forces
/// F_A and F_B at its pins has, at its last section, the axial force F_B · t and no moment (the
/// rod's momentum and angular momentum balances, which its elastic forces keep), and at mid-span
/// the mid-span values of [`Rod::normal_stresses`].
#[test]
fn the_end_section_carries_the_pin_force_in_any_motion() {
    let p = RodProperties {
        damping_ratio: 0.02,
        ..RodProperties::benchmark_b()
    };
    let gravity = Vector2::new(3.0, -9.81);
    let (f_a, f_b) = (Vector2::new(-1.5e3, 4.0e2), Vector2::new(1.2e3, -7.0e2));
    for n in 1..=6 {
        let rod = Rod::new(p, n).unwrap();
        let mut e = rod.straight_configuration(Vector2::new(0.02, 0.01), 0.4);
        let mut e_dot = vec![0.0; e.len()];
        for (i, (value, rate)) in e.iter_mut().zip(&mut e_dot).enumerate() {
            *value += 1e-6 * ((i * 7 % 11) as f64 - 5.0) / 5.0;
            *rate = 0.3 * ((i * 5 % 7) as f64 - 3.0);
        }
        let mut rhs = rod.gravity_force(gravity);
        let mut internal = vec![0.0; e.len()];
        rod.internal_force(&e, &e_dot, &mut internal);
        let last = rod.last_node_offset();
        for (i, value) in rhs.iter_mut().enumerate() {
            *value -= internal[i];
        }
        for d in 0..2 {
            rhs[d] += f_a[d];
            rhs[last + d] += f_b[d];
        }
        let m = rod.mass_matrix();
        let m = nalgebra::DMatrix::from_fn(e.len(), e.len(), |i, j| m[(i, j)]);
        let e_ddot = m
            .lu()
            .solve(&nalgebra::DVector::from_vec(rhs))
            .expect("regular");
        let load = RodLoad {
            start_force: f_a,
            start_moment: 0.0,
            gravity,
        };
        let mut axial = [0.0; 3];
        let mut moments = [0.0; 3];
        rod.sections(
            &e,
            e_ddot.as_slice(),
            &load,
            SectionResult::AxialForce,
            &mut axial,
        );
        rod.sections(
            &e,
            e_ddot.as_slice(),
            &load,
            SectionResult::BendingMoment,
            &mut moments,
        );
        let tangent = Vector2::new(e[last + 2], e[last + 3]).normalize();
        let scale = f_a.norm().max(f_b.norm());
        assert!(
            (axial[2] - f_b.dot(&tangent)).abs() < 1e-9 * scale,
            "{n}: {} vs {}",
            axial[2],
            f_b.dot(&tangent)
        );
        assert!(
            moments[2].abs() < 1e-9 * scale * p.length,
            "{n}: {}",
            moments[2]
        );
        let stresses = rod.normal_stresses(&e, e_ddot.as_slice(), &load);
        // one quadrature, two walks: equal to the rounding of the forces summed
        let force = scale + stresses.midspan_axial_force.abs();
        assert!(
            (axial[1] - stresses.midspan_axial_force).abs() < 1e-12 * force,
            "{n}: {stresses:?}"
        );
        assert!(
            (moments[1] - stresses.midspan_moment).abs() < 1e-12 * force * p.length,
            "{n}: {stresses:?}"
        );
    }
}

#[test]
fn invalid_input_names_the_parameter() {
    let p = RodProperties::benchmark_b();
    let err = Rod::new(p, 0).unwrap_err();
    assert_eq!(
        err.to_string(),
        "rod.nElements = 0 is outside the allowed range [1, 64]"
    );
    let err = Rod::new(
        RodProperties {
            youngs_modulus: -1.0,
            ..p
        },
        4,
    )
    .unwrap_err();
    assert!(err.to_string().starts_with("rod.youngsModulus = -1"));
    for (name, bad) in [
        ("rod.length", RodProperties { length: 0.0, ..p }),
        (
            "rod.density",
            RodProperties {
                density: f64::NAN,
                ..p
            },
        ),
        ("rod.area", RodProperties { area: -1e-4, ..p }),
        (
            "rod.secondMomentOfArea",
            RodProperties {
                second_moment_of_area: 0.0,
                ..p
            },
        ),
        (
            "rod.stiffnessDamping",
            RodProperties {
                stiffness_damping: -1.0,
                ..p
            },
        ),
    ] {
        match Rod::new(bad, 4) {
            Err(ModelError::InvalidParameter { name: n, .. }) => assert_eq!(n, name),
            other => panic!("{name}: expected an invalid-parameter error, got {other:?}"),
        }
    }
    assert!(Rod::new(p, 65).is_err());
}

/// Total mass from the assembled matrix: 1ᵀ M_x 1 = ρ A L.
#[test]
fn assembled_mass_is_total_mass() {
    let rod = Rod::new(RodProperties::benchmark_b(), 8).unwrap();
    let m = rod.mass_matrix();
    let mut total = 0.0;
    for i in (0..rod.n_coordinates()).step_by(4) {
        for j in (0..rod.n_coordinates()).step_by(4) {
            total += m[(i, j)];
        }
    }
    let expected = rod.properties().mass();
    assert!(
        (total - expected).abs() < 1e-14 * expected * 10.0,
        "{total} vs {expected}"
    );
}

#[test]
fn position_interpolates_the_straight_rod() {
    let rod = Rod::new(RodProperties::benchmark_b(), 3).unwrap();
    let e = rod.straight_configuration(Vector2::new(1.0, 2.0), 0.5);
    for x in [0.0, 0.013, 0.06, 0.119, 0.12] {
        let r = rod.position(&e, x);
        let expected = Vector2::new(1.0 + x * math::cos(0.5), 2.0 + x * math::sin(0.5));
        assert!((r - expected).norm() < 1e-15 * 10.0);
    }
}
