//! Stability of the shaft's coupling to its load in co-simulation.
//!
//! A master exchanges the shaft torque τ and the load speed ω_L once per communication step h
//! and holds each over the step. For a load of inertia J_L (J_L dω_L/dt = τ, its other torques
//! aside) the coupled system is then a linear map per step of the motor state [i, ω, φ, z] and
//! ω_L, about any operating point where the voltage is inside its limit:
//!
//! ```text
//! Jacobi (both step from the same point):  x⁺ = Φ(h) x + Γ(h) ω_L,   ω_L⁺ = ω_L + h τ(x, ω_L)/J_L
//! motor first (Gauss–Seidel):              x⁺ = Φ(h) x + Γ(h) ω_L,   ω_L⁺ = ω_L + h τ(x⁺, ω_L)/J_L
//! ```
//!
//! with Φ, Γ the motor's own Runge–Kutta steps over h at held ω_L. The exchange is stable when
//! the spectral radius ρ of that map is below 1. The hold delays the torque the load feels by
//! about h/2, which turns the shaft's damping d_s negative for the ≈ 275 Hz torsional mode once
//! h is large enough: for the motor–crank system (J_L ≈ 0.0205 kg m²) ρ crosses 1 between 3e-4
//! and 3.5e-4 s with the Jacobi exchange and at 2e-3 s with the motor first, as the system's
//! measured stable steps do.
//!
//! # References
//! - M. Arnold (2010), Stability of sequential modular time integration methods for coupled
//!   multibody system models, J. Comput. Nonlinear Dynam. 5(3).

use nalgebra::SMatrix;

use crate::motor::{MotorInputs, MotorParameters, substeps};

/// The order in which a master exchanges the coupling variables.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Exchange {
    /// Both FMUs step from the same communication point (libcosim's fixed-step algorithm).
    Jacobi,
    /// The motor steps first; the load then steps with the motor's new shaft torque.
    MotorFirst,
}

/// Size of the perturbations that sample the map: small enough that the voltage stays far
/// inside its limit, so the samples are exact columns of the linear map.
const PERTURBATION: f64 = 1e-6;

/// Spectral radius ρ of one communication step of the shaft coupled to a load of inertia
/// `load_inertia` \[kg m²\], over `h` \[s\] in the motor's `n` Runge–Kutta steps.
pub fn growth(
    motor: &MotorParameters,
    load_inertia: f64,
    h: f64,
    n: u32,
    exchange: Exchange,
) -> f64 {
    let mut map = SMatrix::<f64, 5, 5>::zeros();
    for column in 0..5 {
        let mut x = [0.0; 4];
        let mut load_speed = 0.0;
        match x.get_mut(column) {
            Some(v) => *v = PERTURBATION,
            None => load_speed = PERTURBATION,
        }
        let held = motor.shaft_torque(&x, load_speed);
        motor.advance(&mut x, h, n, |_| MotorInputs {
            load_speed,
            set_point: 0.0,
        });
        let felt = match exchange {
            Exchange::Jacobi => held,
            Exchange::MotorFirst => motor.shaft_torque(&x, load_speed),
        };
        let next = [x[0], x[1], x[2], x[3], load_speed + h * felt / load_inertia];
        for (row, value) in next.iter().enumerate() {
            map[(row, column)] = value / PERTURBATION;
        }
    }
    map.complex_eigenvalues()
        .iter()
        .map(|lambda| lambda.norm())
        .fold(0.0, f64::max)
}

/// The largest communication step up to which the exchange is stable (ρ < 1 at every step
/// below it), the motor integrating in steps of at most `solver_step`: the first crossing of
/// ρ = 1, found by steps of 5 % from `solver_step` and bisection; infinite if there is none
/// below 1 s.
pub fn largest_stable_step(
    motor: &MotorParameters,
    load_inertia: f64,
    solver_step: f64,
    exchange: Exchange,
) -> f64 {
    let unstable =
        |h: f64| growth(motor, load_inertia, h, substeps(h, solver_step), exchange) > 1.0;
    let (mut stable, mut h) = (0.0, solver_step);
    while !unstable(h) {
        if h > 1.0 {
            return f64::INFINITY;
        }
        stable = h;
        h *= 1.05;
    }
    for _ in 0..40 {
        let mid = 0.5 * (stable + h);
        if unstable(mid) {
            h = mid;
        } else {
            stable = mid;
        }
    }
    stable
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::motor::tests::motor;

    /// The motor–crank system's measured stability (BENCHMARKS.md): Jacobi stable at 3e-4 s and
    /// unstable at 4e-4 s; motor first stable up to 1.5e-3 s and unstable at 2e-3 s.
    #[test]
    fn the_coupling_limits_match_the_systems_measured_ones() {
        let m = motor();
        let load = 0.0205;
        let rho = |h: f64, e| growth(&m, load, h, substeps(h, 1e-5), e);
        assert!(rho(3e-4, Exchange::Jacobi) < 1.0);
        assert!(rho(4e-4, Exchange::Jacobi) > 1.0);
        assert!(rho(1.5e-3, Exchange::MotorFirst) < 1.0);
        assert!(rho(2e-3, Exchange::MotorFirst) > 1.0);
        let limit = largest_stable_step(&m, load, 1e-5, Exchange::Jacobi);
        assert!((3e-4..3.5e-4).contains(&limit), "{limit}");
        // A heavier load allows a larger step.
        assert!(largest_stable_step(&m, 10.0 * load, 1e-5, Exchange::Jacobi) > limit);
    }
}
