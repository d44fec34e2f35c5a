//! The ANCF rod against beam theory: rigid-body invariance, consistent tangent, Euler–Bernoulli
//! cantilever and frequencies, and the large-deflection elastica (docs/model.md §7, analytic anchors).

use faer::Mat;
use flexible_slider_crank::ancf::element::{ElementVector, Section};
use flexible_slider_crank::ancf::{Element, Rod, RodLoad, RodProperties};
use flexible_slider_crank::reduction::{Boundary, Quadrature, RodModel};
use nalgebra::{Rotation2, Vector2};

use crate::common::{Lcg, assert_close, frequencies, slender_rod, solve_static};

fn benchmark_rod(n: usize) -> Rod {
    Rod::new(RodProperties::benchmark_b(), n).unwrap()
}

/// For random rigid placements (translation + rotation) of the straight rod the
/// elastic force is zero to round-off (≤ 1e-9 EA) and so is the strain energy.
#[test]
fn rigid_motion_gives_zero_force_and_energy() {
    let rod = benchmark_rod(4);
    let ea = RodProperties::benchmark_b().youngs_modulus * RodProperties::benchmark_b().area;
    let mut rng = Lcg::new(7);
    let mut q = vec![0.0; rod.n_coordinates()];
    for _ in 0..20 {
        let origin = Vector2::new(rng.next(), rng.next());
        let angle = std::f64::consts::PI * rng.next();
        let e = rod.straight_configuration(origin, angle);
        rod.elastic_force(&e, &mut q);
        let max = q.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert!(
            max <= 1e-9 * ea,
            "rigid placement at {angle} rad: |Q| = {max:e} N"
        );
        // Round-off in |r'| − 1 is ~1e-16, so U/(EA L) ~ 1e-32; 1e-24 leaves wide margin.
        let u = rod.strain_energy(&e);
        assert!(u.abs() <= 1e-24 * ea * 0.12, "rigid placement: U = {u:e} J");
    }
}

/// A random deformed element state: straight element of length l, perturbed by `amp`.
fn deformed(rng: &mut Lcg, l: f64, amp: f64) -> ElementVector {
    let base = [0.0, 0.0, 1.0, 0.0, l, 0.0, 1.0, 0.0];
    let scale = [l, l, 1.0, 1.0, l, l, 1.0, 1.0];
    ElementVector::from_fn(|i, _| base[i] + amp * scale[i] * rng.next())
}

/// The analytic tangent equals central differences of the elastic force.
/// Step h = 1e-6 (relative): truncation O(h²) ~ 1e-12, round-off ~ 1e-16/h ~ 1e-10 of ‖K‖.
#[test]
fn tangent_equals_central_differences() {
    let mut rng = Lcg::new(11);
    for (section, l) in [
        (
            Section {
                ea: 4.644e7,
                ei: 868.3,
                rho_a: 1.75,
                damping: 0.0,
            },
            0.03,
        ),
        (
            Section {
                ea: 10.0,
                ei: 2.0,
                rho_a: 1.0,
                damping: 0.0,
            },
            1.0,
        ),
    ] {
        let element = Element::new(section, l);
        for _ in 0..10 {
            let e = deformed(&mut rng, l, 0.2);
            let k = element.tangent_stiffness(&e);
            let scale = k.abs().max();
            for j in 0..8 {
                let h = 1e-6 * if j % 4 < 2 { l } else { 1.0 };
                let mut ep = e;
                let mut em = e;
                ep[j] += h;
                em[j] -= h;
                let fd = (element.elastic_force(&ep) - element.elastic_force(&em)) / (2.0 * h);
                let err = (fd - k.column(j)).abs().max();
                assert!(
                    err <= 1e-6 * scale,
                    "column {j}: |K − FD| = {err:e}, ‖K‖ = {scale:e}"
                );
            }
            assert!((k - k.transpose()).abs().max() <= 1e-12 * scale);
        }
    }
}

/// The same on an assembled deformed rod, full and reduced (Vᵀ K_T V vs differences of Vᵀ Q(V p)).
#[test]
fn assembled_and_reduced_tangents_equal_central_differences() {
    let mut rng = Lcg::new(5);
    for n_modes in [
        None,
        Some((Boundary::PositionsAndSlopes, 0)),
        Some((Boundary::PositionsAndSlopes, 3)),
        Some((Boundary::PositionsAndSlopes, 6)),
        Some((Boundary::Pins, 0)),
        Some((Boundary::Pins, 5)),
    ] {
        let rod = benchmark_rod(4);
        let mut straight = rod.straight_configuration(Vector2::zeros(), 0.3);
        for v in straight.iter_mut() {
            *v += 0.004 * rng.next();
        }
        let mut model = match n_modes {
            None => RodModel::full(rod).unwrap(),
            Some((boundary, m)) => {
                RodModel::craig_bampton(rod, m, boundary, Quadrature::Full).unwrap()
            }
        };
        let p = model.model_coordinates(&straight);
        let n = p.len();
        let mut k = Mat::zeros(n, n);
        model.tangent_stiffness(&p, k.as_mut());
        let scale = (0..n)
            .flat_map(|i| (0..n).map(move |j| (i, j)))
            .fold(0.0f64, |m, (i, j)| m.max(k[(i, j)].abs()));
        let zero = vec![0.0; n];
        let (mut qp, mut qm) = (vec![0.0; n], vec![0.0; n]);
        for j in 0..n {
            let h = 1e-7;
            let (mut pp, mut pm) = (p.clone(), p.clone());
            pp[j] += h;
            pm[j] -= h;
            model.internal_force(&pp, &zero, &mut qp);
            model.internal_force(&pm, &zero, &mut qm);
            for i in 0..n {
                let fd = (qp[i] - qm[i]) / (2.0 * h);
                assert!(
                    (fd - k[(i, j)]).abs() <= 1e-6 * scale,
                    "nModes {n_modes:?}: K[{i},{j}] = {:e}, FD {fd:e}",
                    k[(i, j)]
                );
            }
        }
    }
}

/// Tip displacement (along, across) the undeformed axis of a cantilever clamped at node 0 under a
/// transverse tip load with α = P L²/EI, solved by Newton in `steps` load increments, and the
/// rod's largest normal stress under the tip load and the clamp's reaction, read from the solved
/// rod's internal force at the clamped coordinates (the force, and the moment r,ₓ × Q of the
/// slope's generalised force).
fn cantilever_tip(rod: Rod, alpha: f64, steps: usize) -> (f64, f64, f64) {
    let p = rod.properties();
    let (length, ei) = (p.length, p.youngs_modulus * p.second_moment_of_area);
    let tip = rod.last_node_offset();
    let mut model = RodModel::full(rod).unwrap();
    let mut e = model.rod().straight_configuration(Vector2::zeros(), 0.0);
    let mut load = vec![0.0; e.len()];
    load[tip + 1] = alpha * ei / (length * length);
    solve_static(&mut model, &mut e, &[0, 1, 2, 3], &load, steps);
    let mut q = vec![0.0; e.len()];
    model.internal_force(&e, &vec![0.0; e.len()], &mut q);
    let reaction = RodLoad {
        start_force: Vector2::new(q[0], q[1]),
        start_moment: e[2] * q[3] - e[3] * q[2],
        gravity: Vector2::zeros(),
    };
    let at_rest = vec![0.0; e.len()];
    let stress = model.rod().normal_stresses(&e, &at_rest, &reaction).largest;
    (length - e[tip], e[tip + 1], stress)
}

/// Small tip load, 4 elements: v = P L³/(3 EI) within 0.1 %, and the largest stress is the
/// clamped end's, σ = P L c/I (its moment from the clamp's reaction), within 0.1 %. Cubic Hermite elements reproduce the linear cubic solution exactly; at α = 1e-4
/// the geometric nonlinearity is ~α².
#[test]
fn linear_cantilever_tip_deflection() {
    let rod = benchmark_rod(4);
    let p = *rod.properties();
    let length = p.length;
    let alpha = 1e-4;
    let (_, v, stress) = cantilever_tip(rod, alpha, 1);
    let expected = alpha * length / 3.0;
    assert_close(v, expected, 1e-3, 0.0, "tip deflection");
    let root_stress = alpha * p.youngs_modulus * p.outer_fibre_distance / length;
    assert_close(stress, root_stress, 1e-3, 0.0, "clamped-end stress");
    println!(
        "linear cantilever, 4 elements: v = {v:.9e} m, PL³/3EI = {expected:.9e} m, rel. error {:.2e}",
        (v - expected).abs() / expected
    );
}

/// Large deflection with 16 elements against the elastica, whose tip displacements are the
/// elliptic-integral solution tabulated by Mattiasson (1981) (docs/model.md §7, Literature):
/// u/L and v/L within 0.5 %.
#[test]
fn large_deflection_matches_elastica() {
    for (alpha, u_ref, v_ref, steps) in [(1.0, 0.05643, 0.30172, 4), (10.0, 0.55500, 0.81061, 20)] {
        let (u, v, _) = cantilever_tip(slender_rod(16), alpha, steps);
        println!(
            "elastica α = {alpha}: u/L = {u:.5} (ref {u_ref}, err {:.2e}), v/L = {v:.5} (ref {v_ref}, err {:.2e})",
            (u - u_ref).abs() / u_ref,
            (v - v_ref).abs() / v_ref
        );
        assert_close(u, u_ref, 5e-3, 0.0, &format!("u/L at α = {alpha}"));
        assert_close(v, v_ref, 5e-3, 0.0, &format!("v/L at α = {alpha}"));
    }
}

/// Euler–Bernoulli ω_k = (β_k L)² √(EI/(ρA L⁴)).
fn euler_bernoulli(beta_l: f64, p: &RodProperties) -> f64 {
    let ei = p.youngs_modulus * p.second_moment_of_area;
    let rho_a = p.density * p.area;
    beta_l * beta_l * (ei / (rho_a * p.length.powi(4))).sqrt()
}

/// First three transverse frequencies of the straight rod along x: pinned–pinned (end transverse
/// positions fixed) and free–free (rigid modes skipped). At the unstressed straight state the
/// tangent decouples axial (x) and transverse (y) coordinates, so the y-block is the bending problem.
fn bending_frequencies(n: usize) -> ([f64; 3], [f64; 3]) {
    let rod = benchmark_rod(n);
    let mut model = RodModel::full(rod).unwrap();
    let e0 = model.rod().straight_configuration(Vector2::zeros(), 0.0);
    let nc = e0.len();
    let mut k = Mat::zeros(nc, nc);
    model.tangent_stiffness(&e0, k.as_mut());
    for i in (0..nc).step_by(2) {
        for j in (1..nc).step_by(2) {
            assert_eq!(
                k[(i, j)],
                0.0,
                "axial–transverse coupling at the straight state"
            );
        }
    }
    let m = model.mass_matrix();
    let transverse: Vec<usize> = (1..nc).step_by(2).collect();
    let pinned: Vec<usize> = transverse
        .iter()
        .copied()
        .filter(|&i| i != 1 && i != nc - 3)
        .collect();
    let pp = frequencies(k.as_ref(), m, &pinned);
    let ff = frequencies(k.as_ref(), m, &transverse);
    ([pp[0], pp[1], pp[2]], [ff[2], ff[3], ff[4]])
}

/// 16 elements, the first three bending frequencies within 0.5 % of Euler–Bernoulli;
/// the observed convergence order in element size is reported and must be the consistent-mass
/// cubic element's h⁴ (2(p + 1 − m) with p = 3, m = 2).
#[test]
fn bending_frequencies_match_euler_bernoulli_and_converge_at_order_four() {
    let p = RodProperties::benchmark_b();
    let pi = std::f64::consts::PI;
    let pp_exact = [pi, 2.0 * pi, 3.0 * pi].map(|b| euler_bernoulli(b, &p));
    let ff_exact = [4.73004, 7.85321, 10.99561].map(|b| euler_bernoulli(b, &p));
    let (pp, ff) = bending_frequencies(16);
    for k in 0..3 {
        println!(
            "mode {}: pinned-pinned {:.2} Hz (EB {:.2}), free-free {:.2} Hz (EB {:.2})",
            k + 1,
            pp[k] / (2.0 * pi),
            pp_exact[k] / (2.0 * pi),
            ff[k] / (2.0 * pi),
            ff_exact[k] / (2.0 * pi)
        );
        assert_close(
            pp[k],
            pp_exact[k],
            5e-3,
            0.0,
            &format!("pinned-pinned mode {}", k + 1),
        );
        // βL is tabulated to 6 digits: 1e-5 relative uncertainty, far inside 0.5 %.
        assert_close(
            ff[k],
            ff_exact[k],
            5e-3,
            0.0,
            &format!("free-free mode {}", k + 1),
        );
    }
    let errors: Vec<[f64; 3]> = [2, 4, 8]
        .iter()
        .map(|&n| {
            let (pp, _) = bending_frequencies(n);
            std::array::from_fn(|k| (pp[k] - pp_exact[k]) / pp_exact[k])
        })
        .collect();
    for k in 0..3 {
        let orders: Vec<f64> = errors
            .windows(2)
            .map(|w| (w[0][k] / w[1][k]).log2())
            .collect();
        println!(
            "pinned-pinned mode {}: errors n=2,4,8 {:?}, observed orders {orders:.2?}",
            k + 1,
            errors.iter().map(|e| e[k]).collect::<Vec<_>>()
        );
        // Frequencies approach from above (Rayleigh–Ritz) at order 4 once in the asymptotic range.
        assert!(errors.iter().all(|e| e[k] > 0.0));
        let last = orders[orders.len() - 1];
        assert!(
            (3.7..=4.3).contains(&last),
            "mode {}: observed order {last}",
            k + 1
        );
    }
}

/// Rotating a deformed element rotates its force and leaves its energy unchanged.
#[test]
fn element_is_objective() {
    let mut rng = Lcg::new(3);
    let element = Element::new(
        Section {
            ea: 100.0,
            ei: 3.0,
            rho_a: 1.0,
            damping: 0.5,
        },
        0.5,
    );
    let e = deformed(&mut rng, 0.5, 0.2);
    let e_dot = deformed(&mut rng, 0.5, 1.0);
    let rot = Rotation2::new(1.1);
    let rotate = |v: &ElementVector| {
        ElementVector::from_fn(|i, _| {
            let r = rot * Vector2::new(v[2 * (i / 2)], v[2 * (i / 2) + 1]);
            r[i % 2]
        })
    };
    let (er, edr) = (rotate(&e), rotate(&e_dot));
    let (q, _) = element.internal_force(&e, &e_dot);
    let (qr, _) = element.internal_force(&er, &edr);
    assert!((rotate(&q) - qr).abs().max() <= 1e-12 * q.abs().max());
    assert_close(
        element.strain_energy(&er),
        element.strain_energy(&e),
        1e-13,
        0.0,
        "energy",
    );
}
