//! Craig–Bampton against the full rod: exactness with all modes, Rayleigh–Ritz bounds, rigid
//! motion, reduced mass, objectivity, and energy conservation.

use faer::{Mat, Side};
use flexible_slider_crank::ancf::{Rod, RodProperties};
use flexible_slider_crank::math;
use flexible_slider_crank::reduction::{Boundary, Quadrature, RodModel, max_modes};
use nalgebra::{Rotation2, Vector2};

use crate::common::{HeldRod, Lcg, assert_close, frequencies};

fn rod(n: usize) -> Rod {
    Rod::new(RodProperties::benchmark_b(), n).unwrap()
}

/// Both Craig–Bampton interfaces.
const BOUNDARIES: [Boundary; 2] = [Boundary::PositionsAndSlopes, Boundary::Pins];

/// A model of a rod with `n` elements: full (None), or reduced with an interface and nModes.
fn model(n: usize, spec: Option<(Boundary, usize)>) -> RodModel {
    match spec {
        None => RodModel::full(rod(n)).unwrap(),
        Some((boundary, m)) => {
            RodModel::craig_bampton(rod(n), m, boundary, Quadrature::Full).unwrap()
        }
    }
}

/// Every model of a rod with `n` elements: full, then nModes = 0 ..= max for each interface.
fn specs(n: usize) -> Vec<Option<(Boundary, usize)>> {
    let mut out = vec![None];
    for boundary in BOUNDARIES {
        out.extend((0..=max_modes(n, boundary)).map(|m| Some((boundary, m))));
    }
    out
}

fn label(spec: Option<(Boundary, usize)>) -> String {
    match spec {
        None => "full".into(),
        Some((boundary, m)) => format!("{boundary:?}, nModes = {m}"),
    }
}

/// Every model of a rod with `n` elements, labelled.
fn models(n: usize) -> Vec<(String, RodModel)> {
    specs(n)
        .into_iter()
        .map(|s| (label(s), model(n, s)))
        .collect()
}

/// Nodal coordinates of a circular arc of total angle `bend` [rad] starting at `origin` in
/// direction `angle`: a large, smooth initial bend.
fn arc(rod: &Rod, origin: Vector2<f64>, angle: f64, bend: f64) -> Vec<f64> {
    let length = rod.properties().length;
    let kappa = bend / length;
    let rot = Rotation2::new(angle);
    let h = length / rod.n_elements() as f64;
    (0..=rod.n_elements())
        .flat_map(|k| {
            let x = k as f64 * h;
            let r = origin
                + rot
                    * Vector2::new(
                        math::sin(kappa * x) / kappa,
                        (1.0 - math::cos(kappa * x)) / kappa,
                    );
            let t = rot * Vector2::new(math::cos(kappa * x), math::sin(kappa * x));
            [r.x, r.y, t.x, t.y]
        })
        .collect()
}

/// Rotates every (x, y) pair of a coordinate vector (nodal, or Craig–Bampton: boundary nodes and
/// mode pairs are all 2-vectors).
fn rotate(v: &[f64], angle: f64) -> Vec<f64> {
    let rot = Rotation2::new(angle);
    v.chunks(2)
        .flat_map(|c| {
            let r = rot * Vector2::new(c[0], c[1]);
            [r.x, r.y]
        })
        .collect()
}

/// Tangent stiffness of a model at p.
fn tangent(model: &mut RodModel, p: &[f64]) -> Mat<f64> {
    let n = p.len();
    let mut k = Mat::zeros(n, n);
    model.tangent_stiffness(p, k.as_mut());
    k
}

/// With all interior modes, V is square and invertible, so the reduced model is
/// the full one in other coordinates: equal free–free frequencies and an equal nonlinear transient.
#[test]
fn all_modes_reproduce_the_full_model() {
    for boundary in BOUNDARIES {
        all_modes_reproduce_the_full_model_with(boundary);
    }
}

fn all_modes_reproduce_the_full_model_with(boundary: Boundary) {
    let n = 4;
    let mut full = RodModel::full(rod(n)).unwrap();
    let mut reduced =
        RodModel::craig_bampton(rod(n), max_modes(n, boundary), boundary, Quadrature::Full)
            .unwrap();
    let e0 = full
        .rod()
        .straight_configuration(Vector2::new(0.01, 0.02), 0.3);
    let p0 = reduced.model_coordinates(&e0);
    let k_full = tangent(&mut full, &e0);
    let k_red = tangent(&mut reduced, &p0);
    let all: Vec<usize> = (0..e0.len()).collect();
    let w_full = frequencies(k_full.as_ref(), full.mass_matrix(), &all);
    let w_red = frequencies(k_red.as_ref(), reduced.mass_matrix(), &all);
    // Three rigid modes (ω ≈ 0 up to round-off), then elastic ones equal to round-off.
    for (a, b) in w_full.iter().zip(&w_red).skip(3) {
        assert_close(*b, *a, 1e-8, 0.0, "free-free frequency, all modes vs full");
    }

    // Transient: pinned at node 0, released from a large bend under a tip load.
    let rod4 = rod(n);
    let bent = arc(&rod4, Vector2::zeros(), 0.3, 0.8);
    let mut load = vec![0.0; e0.len()];
    load[rod4.last_node_offset() + 1] = 500.0;
    let mut load_red = vec![0.0; p0.len()];
    reduced.project_force(&load, &mut load_red);
    let pb = reduced.model_coordinates(&bent);
    let times = [1e-4, 3e-4, 1e-3];
    let mut held_full = HeldRod::new(full, &[0, 1], &bent, load);
    let y_full = held_full.simulate(
        &held_full.state(&bent, &vec![0.0; bent.len()]),
        &times,
        1e-12,
    );
    let mut held_red = HeldRod::new(reduced, &[0, 1], &pb, load_red);
    let y_red = held_red.simulate(&held_red.state(&pb, &vec![0.0; pb.len()]), &times, 1e-12);
    for (yf, yr) in y_full.iter().zip(&y_red) {
        let ef = held_full.coordinates(yf);
        let pr = held_red.coordinates(yr);
        let er = held_red.model.nodal_coordinates(&pr).to_vec();
        let scale = ef.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let err = ef
            .iter()
            .zip(&er)
            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
        assert!(
            err <= 1e-8 * scale,
            "{boundary:?} transient: max |e_full − V p| = {err:e} (scale {scale:e})"
        );
    }
}

/// Pinned–pinned frequencies of the reduced rod bound the full ones from above and
/// decrease monotonically as nModes grows (nested Rayleigh–Ritz subspaces). Round-off margin 1e-10.
#[test]
fn reduced_frequencies_approach_the_full_ones_from_above() {
    for boundary in BOUNDARIES {
        reduced_frequencies_approach_the_full_ones_from_above_with(boundary);
    }
}

fn reduced_frequencies_approach_the_full_ones_from_above_with(boundary: Boundary) {
    let n = 8;
    let mut previous: Option<Vec<f64>> = None;
    let mut full = RodModel::full(rod(n)).unwrap();
    let e0 = full.rod().straight_configuration(Vector2::zeros(), 0.0);
    let k = tangent(&mut full, &e0);
    let end = full.end_node_offset();
    let keep: Vec<usize> = (0..e0.len())
        .filter(|&i| ![0, 1, end, end + 1].contains(&i))
        .collect();
    let w_full = frequencies(k.as_ref(), full.mass_matrix(), &keep);
    for m in 0..=max_modes(n, boundary) {
        let mut reduced = RodModel::craig_bampton(rod(n), m, boundary, Quadrature::Full).unwrap();
        let p0 = reduced.model_coordinates(&e0);
        let k = tangent(&mut reduced, &p0);
        let end = reduced.end_node_offset();
        let keep: Vec<usize> = (0..p0.len())
            .filter(|&i| ![0, 1, end, end + 1].contains(&i))
            .collect();
        let w = frequencies(k.as_ref(), reduced.mass_matrix(), &keep);
        for (i, (wr, wf)) in w.iter().zip(&w_full).enumerate() {
            assert!(
                *wr >= wf * (1.0 - 1e-10),
                "nModes {m}, mode {i}: {wr} below full {wf}"
            );
        }
        if let Some(prev) = &previous {
            for (i, (wr, wp)) in w.iter().zip(prev).enumerate() {
                assert!(
                    *wr <= wp * (1.0 + 1e-10),
                    "nModes {m}, mode {i}: {wr} above {wp} of nModes {}",
                    m - 1
                );
            }
        }
        if w.len() > 1 {
            println!(
                "{boundary:?}, nModes {m:2}: 2nd pinned-pinned frequency {:.1} Hz (full {:.1} Hz, error {:.2e})",
                w[1] / std::f64::consts::TAU,
                w_full[1] / std::f64::consts::TAU,
                (w[1] - w_full[1]) / w_full[1]
            );
        }
        previous = Some(w);
    }
    let last = previous.unwrap();
    for (wr, wf) in last.iter().zip(&w_full) {
        assert_close(*wr, *wf, 1e-8, 0.0, "all modes vs full");
    }
}

/// Any rigid placement with uniform stretch of the end nodes (η = 0) is reproduced
/// exactly at every node: r = o + x s t is a static solution, so Ψ contains it. Ψ comes from a
/// backward-stable Cholesky solve, so the error is ≲ cond(K_ii)·ε·|r|; cond(K_ii) ≈ 1e4 for 8
/// elements, hence 1e-11 relative (the coordinates here are O(1)).
#[test]
fn rigid_motion_of_the_end_nodes_is_exact() {
    let mut rng = Lcg::new(99);
    let n = 8;
    for (name, mut model) in models(n).into_iter().skip(1) {
        for _ in 0..5 {
            let stretch = 1.0 + 0.01 * rng.next();
            let angle = std::f64::consts::PI * rng.next();
            let origin = Vector2::new(rng.next(), rng.next());
            let t = stretch * Vector2::new(math::cos(angle), math::sin(angle));
            let length = model.rod().properties().length;
            let end = origin + length * t;
            let mut p = vec![0.0; model.n_coordinates()];
            match model.reduction().map(|cb| cb.boundary()) {
                Some(Boundary::Pins) => {
                    p[..4].copy_from_slice(&[origin.x, origin.y, end.x, end.y]);
                }
                _ => {
                    p[..8].copy_from_slice(&[origin.x, origin.y, t.x, t.y, end.x, end.y, t.x, t.y]);
                }
            }
            let e = model.nodal_coordinates(&p).to_vec();
            for k in 0..=n {
                let r = origin + (k as f64 * length / n as f64) * t;
                let expected = [r.x, r.y, t.x, t.y];
                for d in 0..4 {
                    assert_close(
                        e[4 * k + d],
                        expected[d],
                        0.0,
                        1e-11,
                        &format!("{name}, node {k}"),
                    );
                }
            }
        }
    }
}

/// The reduced mass is symmetric positive definite, and it is the exact projection.
#[test]
fn reduced_mass_is_symmetric_positive_definite() {
    for (name, model) in models(8) {
        let m = model.mass_matrix();
        let n = m.nrows();
        let scale = (0..n).fold(0.0f64, |s, i| s.max(m[(i, i)]));
        for i in 0..n {
            for j in 0..n {
                assert!(
                    (m[(i, j)] - m[(j, i)]).abs() <= 1e-15 * scale,
                    "{name}: asymmetric"
                );
            }
        }
        assert!(
            m.to_owned().llt(Side::Lower).is_ok(),
            "{name}: not positive definite"
        );
        if let Some(cb) = model.reduction() {
            let v = cb.basis();
            let projected = v.transpose() * model.rod().mass_matrix() * v;
            for i in 0..n {
                for j in 0..n {
                    assert!((projected[(i, j)] - m[(i, j)]).abs() <= 1e-14 * scale);
                }
            }
        }
    }
}

/// Objectivity. The same loaded, vibrating rod (pinned at node 0, released from a
/// bend, tip load fixed relative to the rod) at orientations 0°, 30°, 90°, 180° gives the same
/// response rotated, for every nModes. The integrator's step sequence depends on the orientation
/// (componentwise error norm), so agreement is to the integration tolerance (1e-12), checked at 1e-8.
#[test]
fn response_is_independent_of_orientation() {
    let n = 4;
    let times = [5e-5, 2e-4];
    for spec in specs(n) {
        let name = label(spec);
        let mut reference: Option<Vec<Vec<f64>>> = None;
        for degrees in [0.0f64, 30.0, 90.0, 180.0] {
            let angle = degrees.to_radians();
            let model = model(n, spec);
            let rod_n = rod(n);
            let bent = arc(
                &rod_n,
                Rotation2::new(angle) * Vector2::new(0.05, 0.0),
                angle,
                0.5,
            );
            let p0 = model.model_coordinates(&bent);
            let mut load = vec![0.0; rod_n.n_coordinates()];
            let tip = rod_n.last_node_offset();
            let force = Rotation2::new(angle) * Vector2::new(-300.0, 800.0);
            load[tip] = force.x;
            load[tip + 1] = force.y;
            let mut load_p = vec![0.0; p0.len()];
            model.project_force(&load, &mut load_p);
            let mut held = HeldRod::new(model, &[0, 1], &p0, load_p);
            let y0 = held.state(&p0, &vec![0.0; p0.len()]);
            let states = held.simulate(&y0, &times, 1e-12);
            let responses: Vec<Vec<f64>> = states
                .iter()
                .map(|y| {
                    let p = held.coordinates(y);
                    rotate(held.model.nodal_coordinates(&p), -angle)
                })
                .collect();
            match &reference {
                None => reference = Some(responses),
                Some(r0) => {
                    for (a, b) in responses.iter().zip(r0) {
                        let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                        let err = a
                            .iter()
                            .zip(b)
                            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
                        assert!(
                            err <= 1e-8 * scale,
                            "{name} at {degrees}°: rotated response differs by {err:e}"
                        );
                    }
                }
            }
        }
    }
}

/// Undamped free vibration of a pinned–free rod released from a large bend (1 rad arc)
/// conserves kinetic + strain energy to 1e-6 relative over 100 periods of its first bending mode
/// (β₁L = 3.9266), integrated with DOPRI5 at rtol = 1e-10; full and reduced.
#[test]
fn free_vibration_conserves_energy() {
    let n = 4;
    let p = RodProperties::benchmark_b();
    let omega1 = 3.9266f64.powi(2)
        * (p.youngs_modulus * p.second_moment_of_area / (p.density * p.area * p.length.powi(4)))
            .sqrt();
    let period = std::f64::consts::TAU / omega1;
    let times: Vec<f64> = (1..=200).map(|i| i as f64 * 0.5 * period).collect();
    for spec in [
        None,
        Some((Boundary::PositionsAndSlopes, 2)),
        Some((Boundary::Pins, 2)),
    ] {
        let (name, model) = (label(spec), model(n, spec));
        let bent = arc(model.rod(), Vector2::zeros(), 0.4, 1.0);
        let p0 = model.model_coordinates(&bent);
        let nc = p0.len();
        let mut held = HeldRod::new(model, &[0, 1], &p0, vec![0.0; nc]);
        let y0 = held.state(&p0, &vec![0.0; nc]);
        let e0 = held.energy(&y0);
        let states = held.simulate(&y0, &times, 1e-10);
        let drift = states
            .iter()
            .fold(0.0f64, |m, y| m.max((held.energy(y) - e0).abs()))
            / e0;
        println!(
            "{name}: initial energy {e0:.6e} J, max relative drift over 100 periods {drift:.2e}"
        );
        assert!(drift <= 1e-6, "{name}: energy drift {drift:e}");
    }
}
