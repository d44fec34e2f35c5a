//! The finite film's table and interpolation: the table is its generator's Reynolds solution, the
//! short film is its limit, the interpolant is symmetric and continuously differentiable.

use super::*;

/// (cos ψ, sin ψ).
fn direction(psi: f64) -> (f64, f64) {
    let (sin, cos) = math::sin_cos(psi);
    (cos, sin)
}

/// Nodes of the embedded table re-solved by `ratios` (the generator's function) agree with it to
/// the f32 rounding of the file (1e-6 of the largest ratio): short, middling and long bearings,
/// low and high eccentricity, both edges of the direction range.
#[test]
fn the_table_is_its_generators_solution() {
    for (k, i, j) in [(2, 6, 0), (10, 18, 20), (16, 24, 36), (12, 22, 17)] {
        let expected = ratios(
            ratio_node(k),
            eccentricity_node(i),
            direction_node(j),
            &mut Workspace::default(),
        );
        let scale = expected.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (r, e) in expected.iter().enumerate() {
            let t = tabulated(k, i, j, r).unwrap();
            assert!(
                (t - e).abs() <= 1e-6 * scale,
                "node ({k}, {i}, {j}) ratio {r}: table {t}, solution {e}"
            );
        }
    }
}

/// A very short bearing (λ = 1e-3) is the short film: force along the short film's, peak and
/// flow ratios 1 (to 1e-6: the correction is of order λ²/(1 − ε)).
#[test]
fn the_short_film_is_the_limit() {
    let film = FiniteFilm::new(1e-3).unwrap();
    for eps in [0.0, 0.3, 0.7, 0.95] {
        for psi in [-2.5, -1.5, 0.0, 0.4, 1.6, 3.0] {
            let short = FilmField::of_squeeze(eps, psi);
            let (f_r, f_t) = short.force();
            let magnitude = math::hypot(f_r, f_t);
            let t = film.ratios_at(eps, direction(psi));
            let expected = [f_r / magnitude, f_t / magnitude, 1.0, 1.0];
            for (a, b) in t.iter().zip(expected) {
                assert!(
                    (a - b).abs() < 1e-4,
                    "ε {eps}, ψ {psi}: {t:?} vs {expected:?}"
                );
            }
        }
    }
}

/// Mirroring the squeeze direction mirrors the film: T_r, T_p, T_q even in ψ, T_t odd (to
/// round-off), also between the tabulated directions.
#[test]
fn mirrored_directions_mirror_the_film() {
    let film = FiniteFilm::new(0.7).unwrap();
    for eps in [0.1, 0.55, 0.93] {
        for psi in [0.03, 0.9, 1.57, 2.8] {
            let a = film.ratios_at(eps, direction(psi));
            let b = film.ratios_at(eps, direction(-psi));
            let expected = [a[0], -a[1], a[2], a[3]];
            for (x, y) in b.iter().zip(expected) {
                assert!((x - y).abs() < 1e-12, "ε {eps}, ψ {psi}: {b:?} vs {a:?}");
            }
        }
    }
}

/// The interpolant is continuously differentiable across the cells' edges (what Newton's
/// method on the film force needs): at every edge crossed by a path in ε and in ψ the one-sided
/// slopes agree, their difference below 1 % of the slope's scale, where a merely continuous
/// interpolant jumps by tens of percent.
#[test]
fn the_ratios_have_continuous_slopes() {
    let film = FiniteFilm::new(0.5).unwrap();
    let h = 1e-7;
    // across ε edges (x = integer) at ψ = 1.2, and across ψ edges at ε = 0.8
    let at_x = |x: f64| {
        let sigma = sigma_node(x);
        film.ratios_at(1.0 - sigma * sigma, direction(1.2))
    };
    let at_y = |y: f64| {
        film.ratios_at(
            0.8,
            direction((y / (AROUND / 2) as f64 - 1.0) * std::f64::consts::PI),
        )
    };
    for (f, edges) in [
        (&at_x as &dyn Fn(f64) -> [f64; 4], [3.0, 11.0, 20.0]),
        (&at_y, [40.0, 47.0, 60.0]),
    ] {
        for edge in edges {
            let (below, at, above) = (f(edge - h), f(edge), f(edge + h));
            let (scale_a, scale_b) = (f(edge - 0.5), f(edge + 0.5));
            for r in 0..RATIOS {
                let left = (at[r] - below[r]) / h;
                let right = (above[r] - at[r]) / h;
                let scale = (scale_b[r] - scale_a[r]).abs().max(1e-3);
                assert!(
                    (left - right).abs() < 1e-2 * scale,
                    "edge {edge}, ratio {r}: slopes {left} and {right}"
                );
            }
        }
    }
}

/// A length-to-diameter ratio outside (0, 4] has no table.
#[test]
fn ratios_outside_the_table_are_refused() {
    for lambda in [0.0, -1.0, 4.01, f64::NAN] {
        assert!(FiniteFilm::new(lambda).is_err(), "{lambda}");
    }
    assert!(FiniteFilm::new(4.0).is_ok());
}
