//! Tests of the implicit integrators on a damped oscillator with a work integral.

use super::*;
use crate::integrator::{ESDIRK54, OdeSystem, dense};

/// Damped oscillator q̈ = −ω² q − c q̇ with a work integral w' = −c q̇².
struct Oscillator {
    omega: f64,
    damping: f64,
}

impl OdeSystem for Oscillator {
    fn rhs(&mut self, _t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), ModelError> {
        dy[0] = y[1];
        dy[1] = -self.omega * self.omega * y[0] - self.damping * y[1];
        dy[2] = -self.damping * y[1] * y[1];
        Ok(())
    }
}

impl MechanicalSystem for Oscillator {
    fn n_coordinates(&self) -> usize {
        1
    }
}

fn tolerances(rtol: f64) -> Tolerances {
    Tolerances::from_relative(rtol, 1.0)
}

/// The undamped oscillator (ω = 3) from (1, 0) over 10 periods with `scheme`: the global error
/// against the exact solution and the relative change of its energy.
fn oscillator_run(scheme: Scheme, rtol: f64) -> (f64, f64) {
    let omega = 3.0;
    let t_end = 10.0 * std::f64::consts::TAU / omega;
    let mut f = Oscillator {
        omega,
        damping: 0.0,
    };
    let mut integrator =
        Implicit::new(scheme, 3, 1, tolerances(rtol), ErrorScales::uniform(3)).unwrap();
    let (mut t, mut y) = (0.0, [1.0, 0.0, 0.0]);
    while t < t_end {
        integrator
            .step(&mut f, &mut t, &mut y, Some(t_end), u64::MAX)
            .unwrap();
    }
    let error = ((y[0] - crate::math::cos(omega * t)).powi(2)
        + (y[1] / omega + crate::math::sin(omega * t)).powi(2))
    .sqrt();
    let energy = y[0] * y[0] + (y[1] / omega).powi(2);
    (error, (1.0 - energy).abs())
}

/// The filtered error estimate solves (I − λJ) x = err for the first-order Jacobian
/// J = [0 I; ∂a/∂q ∂a/∂q̇] (checked by multiplying back), with the quadratures copied.
#[test]
fn filtered_error_solves_the_first_order_system() {
    let (n_q, n) = (2, 5);
    let mut integrator = Implicit::new(
        Scheme::Esdirk(&ESDIRK54),
        n,
        n_q,
        tolerances(1e-3),
        ErrorScales::uniform(n),
    )
    .unwrap();
    // Column-major ∂a/∂q (a stiff spring pair) and ∂a/∂q̇.
    integrator.state.jacobian_q = vec![-4e6, 1e6, 1e6, -3e6];
    integrator.state.jacobian_v = vec![-20.0, 1.0, 2.0, -30.0];
    // ω ≈ 2000 rad/s against h = 10 ms: the springs are far from resolved.
    let h = 1e-2;
    integrator.factorize(h).unwrap();
    integrator.err = vec![1e-9, -2e-9, 3e-3, 4e-3, 0.5];
    integrator.filter_error(h);
    let x = integrator.filtered.clone();
    let (lambda, _) = integrator.scheme.newton_coefficients(h);
    let jq = |i: usize, j: usize| integrator.state.jacobian_q[j * n_q + i];
    let jv = |i: usize, j: usize| integrator.state.jacobian_v[j * n_q + i];
    for i in 0..n_q {
        // Rows of (I − λJ) x: x_q − λ x_v, and x_v − λ (∂a/∂q x_q + ∂a/∂q̇ x_v).
        let row_q = x[i] - lambda * x[n_q + i];
        let coupling: f64 = (0..n_q)
            .map(|j| jq(i, j) * x[j] + jv(i, j) * x[n_q + j])
            .sum();
        let row_v = x[n_q + i] - lambda * coupling;
        assert!(
            (row_q - integrator.err[i]).abs() < 1e-12,
            "{row_q} {}",
            integrator.err[i]
        );
        assert!(
            (row_v - integrator.err[n_q + i]).abs() < 1e-9 * integrator.err[n_q + i].abs(),
            "{row_v} {}",
            integrator.err[n_q + i]
        );
    }
    assert_eq!(x[2 * n_q], 0.5);
    // The unresolved stiff error is damped: the filtered velocities are at least 5× below.
    for i in n_q..2 * n_q {
        assert!(x[i].abs() < 0.2 * integrator.err[i].abs(), "{x:?}");
    }
}

/// A work integral sums the rates of the converged stages: after one ESDIRK step of the damped
/// oscillator with its dissipated power −c q̇² as a quadrature, the quadrature's increment is
/// h Σ bᵢ (−c Vᵢ²) at the stages' velocities Vᵢ to second order in the last Newton update (1e-6
/// relative); at the last iterate's rates it differs by about h Σ bᵢ 2c Vᵢ ΔVᵢ (1e-4).
#[test]
fn quadrature_rates_are_those_of_the_converged_stages() {
    let mut f = Oscillator {
        omega: 3.0,
        damping: 0.5,
    };
    let tolerances = tolerances(1e-2);
    let mut integrator = Implicit::new(
        Scheme::Esdirk(&ESDIRK54),
        3,
        1,
        tolerances,
        ErrorScales::uniform(3),
    )
    .unwrap();
    let (y, h) = ([0.0, 3.0, 0.0], 0.05);
    f.rhs(0.0, &y, &mut integrator.k[0]).unwrap();
    integrator.jacobian(&mut f, 0.0, &y).unwrap();
    integrator.try_step(&mut f, 0.0, &y, h, false).ok().unwrap();
    let table = &ESDIRK54;
    let stage_rates: f64 = (0..table.stages)
        .map(|i| table.b[i] * -f.damping * integrator.k[i][0].powi(2))
        .sum();
    let increment = integrator.y_new[2] - y[2];
    let converged = h * stage_rates;
    assert!(
        (increment - converged).abs() < 1e-6 * converged.abs(),
        "{increment:e} against {converged:e}"
    );
}

/// ESDIRK on the oscillator: the global error follows the tolerance (5th order).
#[test]
fn oscillator_error_follows_tolerance() {
    let errors: Vec<f64> = [1e-6, 1e-9]
        .iter()
        .map(|&rtol| oscillator_run(Scheme::Esdirk(&ESDIRK54), rtol).0)
        .collect();
    assert!(errors[0] < 1e-4 && errors[1] < 1e-7, "{errors:?}");
    assert!(errors[0] / errors[1] > 100.0, "{errors:?}");
}

/// Generalized-α on the oscillator: the global error falls with the tolerance (second order,
/// more than 10× per 100×), and with ρ∞ = 1 (trapezoidal rule, no numerical dissipation) the energy of
/// the linear oscillator is kept to the Newton tolerance, while ρ∞ = 0 loses some.
#[test]
fn generalized_alpha_converges_and_its_dissipation_is_the_parameter() {
    let run = |rho: f64, rtol: f64| {
        oscillator_run(
            Scheme::GeneralizedAlpha(GeneralizedAlpha::new(rho).unwrap()),
            rtol,
        )
    };
    let (coarse, _) = run(0.8, 1e-4);
    let (fine, _) = run(0.8, 1e-6);
    println!("ρ∞ = 0.8: error {coarse:.2e} at rtol 1e-4, {fine:.2e} at 1e-6");
    assert!(fine < 1e-2 && coarse / fine > 10.0, "{coarse:e} {fine:e}");
    let (_, kept) = run(1.0, 1e-3);
    let (_, lost) = run(0.0, 1e-3);
    println!("energy change at rtol 1e-3: {kept:.2e} with ρ∞ = 1, {lost:.2e} with ρ∞ = 0");
    assert!(kept < 1e-6 && lost > 100.0 * kept, "{kept:e} {lost:e}");
}

/// Two uncoupled springs, q̈ᵢ = −ωᵢ² qᵢ: a resolved one and a stiff one.
struct Springs([f64; 2]);

impl OdeSystem for Springs {
    fn rhs(&mut self, _t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), ModelError> {
        for i in 0..2 {
            dy[i] = y[2 + i];
            dy[2 + i] = -self.0[i] * self.0[i] * y[i];
        }
        Ok(())
    }
}

impl MechanicalSystem for Springs {
    fn n_coordinates(&self) -> usize {
        2
    }
}

/// The dense output keeps the quintic's accuracy on a resolved spring (ω h = 0.03: within 1e-11
/// of cos 3t, where the cubic alone is 2e-9 off) and does not pass on a stiff spring's amplified
/// end accelerations (ω h = 100, ends at a deviation of 1e-6 with q̈ = −ω² q): it stays within
/// twice the ends' deviation, where the unfiltered quintic reaches 3e-4.
#[test]
fn dense_output_filters_only_the_unresolved() {
    let omega = [3.0, 1e4];
    let mut f = Springs(omega);
    let mut integrator = Implicit::new(
        Scheme::Esdirk(&ESDIRK54),
        4,
        2,
        tolerances(1e-3),
        ErrorScales::uniform(4),
    )
    .unwrap();
    integrator.state.jacobian_q = vec![-omega[0] * omega[0], 0.0, 0.0, -omega[1] * omega[1]];
    integrator.state.jacobian_v = vec![0.0; 4];
    let (t0, h) = (0.1, 1e-2);
    integrator.factorize(h).unwrap();
    let mut end = |t: f64| {
        let (q, v) = (crate::math::cos(3.0 * t), -3.0 * crate::math::sin(3.0 * t));
        let deviation = 1e-6;
        let y = [q, deviation, v, 0.0];
        let mut dy = [0.0; 4];
        f.rhs(t, &y, &mut dy).unwrap();
        (y, dy)
    };
    let ((y0, f0), (y1, f1)) = (end(t0), end(t0 + h));
    let s = 0.5;
    let span = dense::Span {
        t0,
        h,
        y0: &y0,
        f0: &f0,
        y1: &y1,
        f1: &f1,
    };
    let mut out = [0.0; 4];
    integrator.dense_output(&mut f, &span, s, &mut out).unwrap();
    let exact = crate::math::cos(3.0 * (t0 + s * h));
    assert!((out[0] - exact).abs() < 1e-11, "{}", out[0] - exact);
    assert!(out[1].abs() < 2e-6, "{}", out[1]);
    let mut cubic = [0.0; 4];
    dense::cubic(2, h, &y0, &y1, s, &mut cubic);
    assert!((cubic[0] - exact).abs() > 1e-9, "{}", cubic[0] - exact);
    let mut quintic = [0.0; 4];
    dense::interpolate(2, &span, s, &mut quintic);
    assert!(quintic[1].abs() > 1e-4, "{}", quintic[1]);
}
