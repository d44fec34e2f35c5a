//! Unit tests of the ANCF rod.

use super::sections::{SectionResult, patch_weights, section_place};
use super::*;

/// The patch weights are the least-squares quadratic's values at 0, 1/2 and 1 (in element
/// lengths) from its four Gauss points, and each set sums to 1 (a constant is recovered).
#[test]
fn patch_weights_are_the_least_squares_quadratic() {
    let (a, b) = (0.5 - 0.5 / 3f64.sqrt(), 0.5 + 0.5 / 3f64.sqrt());
    let x = [a, b, 1.0 + a, 1.0 + b];
    let v = nalgebra::Matrix4x3::from_fn(|i, k| x[i].powi(k as i32));
    let fit = (v.transpose() * v).try_inverse().expect("regular") * v.transpose();
    for (at, weights) in [
        (0.0, PATCH_AT_END),
        (0.5, PATCH_AT_HALF),
        (1.0, PATCH_AT_NODE),
    ] {
        let row = nalgebra::RowVector3::new(1.0, at, at * at) * fit;
        for (w, expected) in weights.iter().zip(row.iter()) {
            assert!((w - expected).abs() < 1e-14, "at {at}: {w} vs {expected}");
        }
        assert!((weights.iter().sum::<f64>() - 1.0).abs() < 1e-14);
    }
}

/// The closed form of the patch weights anywhere on the patch is the least-squares quadratic's:
/// the weights w(u) are those of [1 u u²](VᵀV)⁻¹Vᵀ exactly when Vᵀw = [1 u u²] (a quadratic
/// through the four points is recovered wherever it is evaluated) and w lies in the range of V
/// (orthogonal to Vᵀ's null vector z = [a, −b, b, −a] for the points a, b, 1 + a, 1 + b).
#[test]
fn patch_weights_anywhere_are_the_least_squares_quadratic() {
    let (a, b) = (0.5 - 0.5 / 3f64.sqrt(), 0.5 + 0.5 / 3f64.sqrt());
    let points = [a, b, 1.0 + a, 1.0 + b];
    let null = [a, -b, b, -a];
    let dot = |u: &[f64; 4], v: &[f64; 4]| u.iter().zip(v).map(|(x, y)| x * y).sum::<f64>();
    for k in 0..3 {
        assert!(dot(&null, &points.map(|x| x.powi(k))).abs() < 1e-15);
    }
    let quadratic = |x: f64| 0.7 - 1.3 * x + 2.1 * x * x;
    for at in [0.0, 0.3, 0.5, 1.0, 1.25, 1.5, 2.0] {
        let w = patch_weights(at);
        let value = dot(&w, &points.map(quadratic));
        assert!((value - quadratic(at)).abs() < 1e-14, "at {at}: {value}");
        assert!(dot(&w, &null).abs() < 1e-15, "at {at}: {w:?}");
    }
}

/// A pinned beam of the benchmark-B rod under a uniform transverse load q small enough for the
/// linear theory: its deflection w(x) = q x (L³ − 2Lx² + x³)/(24 EI) and slope, and the nodal
/// coordinates of a rod of `n` elements that carry them exactly.
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
}

/// The pinned beam under a uniform load of the test below, at evenly spaced sections: the
/// recovered moment is the exact −q x (L − x)/2 everywhere (a quadratic), the axial force zero,
/// and the deflection the exact w(x) to the cubic (Hermite) interpolation's error between the
/// nodes, at most w (h/2)⁴/4! = q h⁴/(384 EI) for elements of length h.
#[test]
fn a_pinned_beam_under_a_uniform_load_has_the_exact_section_moments() {
    let beam = LoadedBeam::new();
    let (l, ei, q) = (beam.l, beam.ei, beam.q);
    let w = |x: f64| beam.w(x);
    let largest_moment = q * l * l / 8.0;
    for n in 2..=9 {
        let interpolation = q * (l / n as f64).powi(4) / (384.0 * ei);
        let (rod, e) = beam.rod(n);
        for sections in [2, 7, 11, 20] {
            for k in 0..sections {
                let place = section_place(k, sections);
                let x = place * l;
                let moment = rod.section_result(&e, SectionResult::BendingMoment, place);
                let expected = -q * x * (l - x) / 2.0;
                assert!(
                    (moment - expected).abs() < 1e-6 * largest_moment,
                    "{n} elements, section {k}/{sections}: {moment} vs {expected}"
                );
                let axial = rod.section_result(&e, SectionResult::AxialForce, place);
                assert!(axial.abs() < 1e-3 * q * l, "{n}, {k}/{sections}: {axial}");
                let deflection = rod.section_result(&e, SectionResult::Deflection, place);
                assert!(
                    (deflection - w(x)).abs() <= interpolation * (1.0 + 1e-6) + 1e-9 * w(0.5 * l),
                    "{n}, {k}/{sections}: {deflection} vs {}",
                    w(x)
                );
            }
        }
    }
}

/// In any deformed state, the section at mid-span has the mid-span values of
/// [`Rod::normal_stresses`] (the same recovery from the same patch), for one element and many,
/// mid-span a node or inside an element.
#[test]
fn the_middle_section_has_the_midspan_resultants() {
    let p = RodProperties::benchmark_b();
    for n in 1..=7 {
        let rod = Rod::new(p, n).unwrap();
        let mut e = rod.straight_configuration(Vector2::new(0.0, 0.0), 0.2);
        for (i, value) in e.iter_mut().enumerate() {
            *value += 1e-4 * ((i * 7 % 11) as f64 - 5.0) / 5.0;
        }
        let stresses = rod.normal_stresses(&e);
        let axial = rod.section_result(&e, SectionResult::AxialForce, 0.5);
        let moment = rod.section_result(&e, SectionResult::BendingMoment, 0.5);
        let scale = |x: f64| 1e-12 * x.abs().max(1.0);
        assert!(
            (axial - stresses.midspan_axial_force).abs() < scale(stresses.midspan_axial_force),
            "{n}: {axial} vs {stresses:?}"
        );
        assert!(
            (moment - stresses.midspan_moment).abs() < scale(stresses.midspan_moment),
            "{n}: {moment} vs {stresses:?}"
        );
    }
}

/// Uniform stretch ε: σ = E ε, for one element and for several.
#[test]
fn a_stretched_rod_carries_e_times_the_strain() {
    let p = RodProperties::benchmark_b();
    for n in [1, 3, 8] {
        let rod = Rod::new(p, n).unwrap();
        let strain = 1e-4;
        let mut e = rod.straight_configuration(Vector2::new(0.1, -0.2), 0.3);
        for k in 0..=n {
            for d in 0..4 {
                e[4 * k + d] = if d < 2 {
                    let origin = [0.1, -0.2][d];
                    origin + (1.0 + strain) * (e[4 * k + d] - origin)
                } else {
                    (1.0 + strain) * e[4 * k + d]
                };
            }
        }
        let sigma = rod.normal_stresses(&e).largest;
        let expected = p.youngs_modulus * strain;
        assert!((sigma - expected).abs() < 1e-9 * expected, "{n}: {sigma}");
    }
}

/// A pinned beam under a uniform load q (small deflection, exact nodal values w(x) =
/// q x (L³ − 2Lx² + x³)/(24 EI)): the largest stress is the mid-span moment's,
/// σ = (q L²/8) c/I, whether mid-span is a node (even n) or inside an element (odd n), and
/// the recovered nodal moments are exact (a quadratic moment); the end moments are zero. The
/// signed field: the mid-span moment and both fibres' stresses, where the largest lies.
#[test]
fn a_pinned_beam_under_a_uniform_load_has_the_midspan_stress() {
    let beam = LoadedBeam::new();
    let (p, l, q) = (beam.p, beam.l, beam.q);
    let expected = q * l * l / 8.0 * p.outer_fibre_distance / p.second_moment_of_area;
    for n in 2..=9 {
        let (rod, e) = beam.rod(n);
        let stresses = rod.normal_stresses(&e);
        let sigma = stresses.largest;
        assert!(
            (sigma - expected).abs() < 1e-6 * expected,
            "{n} elements: {sigma} vs {expected}"
        );
        // Bulging up (w > 0) the rod turns right: the moment −q L²/8 at mid-span, its fibres
        // at ±σ, no axial force; the largest stress at mid-span.
        let moment = q * l * l / 8.0;
        assert!(
            (stresses.midspan_moment + moment).abs() < 1e-6 * moment,
            "{n}: {stresses:?}"
        );
        assert!((stresses.max - expected).abs() < 1e-6 * expected);
        assert!((stresses.min + expected).abs() < 1e-6 * expected);
        assert!(
            stresses.midspan_axial_force.abs() < 1e-3 * q * l,
            "{n}: {stresses:?}"
        );
        assert!(
            (stresses.location - 0.5).abs() < 0.5 / n as f64,
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
