//! Kinematic constraints of the slider-crank and their Jacobian on the coordinates they touch,
//! s = [θ, r_A,x, r_A,y, r_B,x, r_B,y, x_s, x_G, y_G] (the crank's centre of mass r_G only for a
//! crank free in a clearance main bearing; the first six otherwise).
//!
//! ```text
//! crank pin     Φ = r_A − r_O − d (cos θ, sin θ)  γ = −d θ̇² (cos θ, sin θ)     (ideal)
//! rod–slider    Φ = r_B − (x_s, e)                γ = 0                        (ideal)
//! rigid rod     Φ = ½ (|r_B − r_A|² − l²)          γ = −|ṙ_B − ṙ_A|²
//! speed drive   Φ = θ − θ_d,  θ̇_d = ω_in          γ = 0
//! Φ_q q̈ = γ − 2α Φ̇ − β² Φ        (Baumgarte stabilisation)
//! ```
//! with the crank's reference point r_O and arm d: the fixed pivot r_O = 0 and d = r_c, or for the
//! free crank its centre of mass r_O = r_G and d = r_c − a (a: the pivot to centre-of-mass distance),
//! and e the guide line's offset from the crank pivot.
//!
//! # References
//! - J. Baumgarte (1972), Stabilization of constraints and integrals of motion in dynamical
//!   systems, Comput. Methods Appl. Mech. Eng. 1, 1–16.
//! - P. E. Nikravesh (1988), Computer-Aided Analysis of Mechanical Systems, Prentice-Hall, ch. 6.

use nalgebra::{SMatrix, SVector, Vector2};

/// Baumgarte gains α = β \[1/s\]: critically damped drift correction with a time constant of 10 ms
/// (about one crank revolution at 5000 rpm). The added eigenvalues (≈ −100 1/s) lie far inside the
/// stability region of the explicit steps (≤ 1e-4 s), so they cost no step-size reduction.
pub const BAUMGARTE: f64 = 100.0;

/// Largest number of coordinates in s.
pub const S_MAX: usize = 8;
/// Row-major constraint Jacobian on s (at most 6 rows).
pub type Jacobian = SMatrix<f64, 6, S_MAX>;
/// A vector over the constraint rows.
pub type Vector6 = SVector<f64, 6>;
/// A vector over s.
pub type VectorS = SVector<f64, S_MAX>;

/// Which constraints are active.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Active {
    /// Ideal crank pin.
    pub crank_pin: bool,
    /// Ideal rod–slider joint.
    pub ideal_joint: bool,
    /// Rigid rod length constraint.
    pub rigid_rod: bool,
    /// Speed drive.
    pub speed_drive: bool,
    /// The crank free in a clearance main bearing (its centre of mass in s).
    pub free_crank: bool,
}

impl Active {
    /// Number of coordinates in s: 6, or 8 with the free crank's centre of mass.
    pub fn s_len(self) -> usize {
        if self.free_crank { S_MAX } else { 6 }
    }
}

/// Evaluated constraints at (q, q̇).
#[derive(Clone, Copy, Debug)]
pub struct Constraints {
    /// Number of active rows k.
    pub rows: usize,
    /// Jacobian Φ_q on s; rows ≥ k are zero.
    pub jacobian: Jacobian,
    /// Φ.
    pub phi: Vector6,
    /// Φ̇.
    pub phi_dot: Vector6,
    /// γ (acceleration right-hand side without stabilisation).
    pub gamma: Vector6,
    /// Row of the ideal joint's x equation (the y equation follows), if active.
    pub ideal_row: Option<usize>,
    /// Row of the speed drive, if active.
    pub drive_row: Option<usize>,
}

/// Kinematic inputs of the constraints.
#[derive(Clone, Copy, Debug)]
pub struct ConstraintState {
    /// Crank angle θ and rate.
    pub theta: f64,
    /// Crank rate θ̇.
    pub theta_dot: f64,
    /// Drive angle θ_d and prescribed speed ω_in.
    pub theta_drive: f64,
    /// Prescribed speed ω_in.
    pub drive_speed: f64,
    /// Its rate dω_in/dt.
    pub drive_acceleration: f64,
    /// r_A and ṙ_A.
    pub r_a: Vector2<f64>,
    /// ṙ_A.
    pub v_a: Vector2<f64>,
    /// r_B.
    pub r_b: Vector2<f64>,
    /// ṙ_B.
    pub v_b: Vector2<f64>,
    /// x_s.
    pub x_s: f64,
    /// The guide line's y, e (the slider offset).
    pub guide: f64,
    /// ẋ_s.
    pub v_s: f64,
    /// The crank's reference point r_O: the pivot (0) or the free crank's centre of mass.
    pub r_o: Vector2<f64>,
    /// ṙ_O.
    pub v_o: Vector2<f64>,
}

impl Constraints {
    /// Evaluates the active constraints for a crank whose pin is at `arm` d from its reference
    /// point r_O and, for a rigid rod, `length`.
    pub fn evaluate(active: Active, arm: f64, length: f64, s: &ConstraintState) -> Self {
        let mut c = Self {
            rows: 0,
            jacobian: Jacobian::zeros(),
            phi: Vector6::zeros(),
            phi_dot: Vector6::zeros(),
            gamma: Vector6::zeros(),
            ideal_row: None,
            drive_row: None,
        };
        let (sin, cos) = crate::math::sin_cos(s.theta);
        let mut push = |row: [f64; S_MAX], phi: f64, phi_dot: f64, gamma: f64| {
            let k = c.rows;
            for (j, v) in row.iter().enumerate() {
                c.jacobian[(k, j)] = *v;
            }
            c.phi[k] = phi;
            c.phi_dot[k] = phi_dot;
            c.gamma[k] = gamma;
            c.rows += 1;
            k
        };
        if active.crank_pin {
            let w2 = s.theta_dot * s.theta_dot;
            let centre = if active.free_crank { -1.0 } else { 0.0 };
            let (r, v) = (s.r_a - s.r_o, s.v_a - s.v_o);
            push(
                [arm * sin, 1.0, 0.0, 0.0, 0.0, 0.0, centre, 0.0],
                r.x - arm * cos,
                v.x + arm * sin * s.theta_dot,
                -arm * w2 * cos,
            );
            push(
                [-arm * cos, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, centre],
                r.y - arm * sin,
                v.y - arm * cos * s.theta_dot,
                -arm * w2 * sin,
            );
        }
        if active.ideal_joint {
            let k = push(
                [0.0, 0.0, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0],
                s.r_b.x - s.x_s,
                s.v_b.x - s.v_s,
                0.0,
            );
            push(
                [0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
                s.r_b.y - s.guide,
                s.v_b.y,
                0.0,
            );
            c.ideal_row = Some(k);
        }
        if active.rigid_rod {
            let d = s.r_b - s.r_a;
            let d_dot = s.v_b - s.v_a;
            push(
                [0.0, -d.x, -d.y, d.x, d.y, 0.0, 0.0, 0.0],
                0.5 * (d.norm_squared() - length * length),
                d.dot(&d_dot),
                -d_dot.norm_squared(),
            );
        }
        if active.speed_drive {
            let k = push(
                [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
                s.theta - s.theta_drive,
                s.theta_dot - s.drive_speed,
                s.drive_acceleration,
            );
            c.drive_row = Some(k);
        }
        c
    }

    /// Stabilised acceleration right-hand side γ − 2α Φ̇ − β² Φ.
    pub fn acceleration_rhs(&self) -> Vector6 {
        self.gamma - 2.0 * BAUMGARTE * self.phi_dot - BAUMGARTE * BAUMGARTE * self.phi
    }

    /// ‖Φ‖ over the active rows (position drift) \[m, rad mixed\].
    pub fn drift(&self) -> f64 {
        self.phi.norm()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Jacobian rows equal finite differences of Φ, for the fixed and the free crank.
    #[test]
    fn jacobian_matches_finite_differences() {
        for free_crank in [false, true] {
            jacobian_matches_finite_differences_of(Active {
                crank_pin: true,
                ideal_joint: true,
                rigid_rod: true,
                speed_drive: true,
                free_crank,
            });
        }
    }

    fn jacobian_matches_finite_differences_of(active: Active) {
        let state = |q: &[f64; S_MAX]| ConstraintState {
            theta: q[0],
            theta_dot: 0.0,
            theta_drive: 0.1,
            drive_speed: 0.0,
            drive_acceleration: 0.0,
            r_a: Vector2::new(q[1], q[2]),
            v_a: Vector2::zeros(),
            r_b: Vector2::new(q[3], q[4]),
            v_b: Vector2::zeros(),
            x_s: q[5],
            guide: 0.004,
            v_s: 0.0,
            r_o: if active.free_crank {
                Vector2::new(q[6], q[7])
            } else {
                Vector2::zeros()
            },
            v_o: Vector2::zeros(),
        };
        let q = [0.3, 0.04, 0.02, 0.15, 0.01, 0.16, 0.012, -0.003];
        let c = Constraints::evaluate(active, 0.05, 0.12, &state(&q));
        assert_eq!(c.rows, 6);
        for j in 0..active.s_len() {
            let (mut qp, mut qm) = (q, q);
            qp[j] += 1e-7;
            qm[j] -= 1e-7;
            let cp = Constraints::evaluate(active, 0.05, 0.12, &state(&qp));
            let cm = Constraints::evaluate(active, 0.05, 0.12, &state(&qm));
            for i in 0..6 {
                let fd = (cp.phi[i] - cm.phi[i]) / 2e-7;
                assert!((fd - c.jacobian[(i, j)]).abs() < 1e-8, "Φ_q[{i},{j}]");
            }
        }
    }
}
