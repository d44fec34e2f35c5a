//! The constraint solve of an evaluation: the Schur complement C W Cᵀ of the constraint Jacobian C
//! on the coordinates s it touches (W = E_sᵀ M⁻¹ E_s, see [`super::constraints`]), and the
//! multipliers' accelerations M⁻¹ Cᵀ λ applied to all coordinates.

use super::constraints::{Constraints, S_MAX, Vector6, VectorS};
use super::layout::{CRANK_ANGLE, PIN_A};
use super::slider_crank::SliderCrank;
use crate::error::ModelError;
use crate::linalg::small;

impl SliderCrank {
    /// Solves (C W Cᵀ) x = r on the k active rows (rows of C beyond k are zero; x is zero there).
    pub(super) fn solve_schur(&self, c: &Constraints, r: Vector6) -> Result<Vector6, ModelError> {
        let (k, n) = (c.rows, self.active.s_len());
        let mut cw = [[0.0; S_MAX]; 6];
        for (i, row) in cw.iter_mut().enumerate().take(k) {
            for (j, v) in row.iter_mut().enumerate().take(n) {
                *v = (0..n).map(|m| c.jacobian[(i, m)] * self.w[(m, j)]).sum();
            }
        }
        let mut s = [[0.0; 6]; 6];
        for (i, row) in s.iter_mut().enumerate().take(k) {
            for (j, v) in row.iter_mut().enumerate().take(i + 1) {
                *v = (0..n).map(|m| cw[i][m] * c.jacobian[(j, m)]).sum();
            }
        }
        let mut x = [0.0; 6];
        x[..k].copy_from_slice(&r.as_slice()[..k]);
        small::cholesky_solve(
            &s,
            k,
            &mut x,
            "singular constraint Jacobian (locked configuration)",
        )?;
        Ok(Vector6::from(x))
    }

    /// Adds −G μ to the accelerations (or velocities) `out` for μ on s: M⁻¹ Cᵀλ applied.
    pub(super) fn subtract_compliance(&self, mu: &VectorS, out: &mut [f64]) {
        let l = self.layout;
        let n_rod = l.rod().len();
        out[CRANK_ANGLE] -= mu[0] / self.crank.inertia;
        out[l.slider()] -= mu[5] / self.slider.mass;
        if let Some(g) = l.crank_centre() {
            out[g] -= mu[6] / self.crank.mass;
            out[g + 1] -= mu[7] / self.crank.mass;
        }
        for j in 0..4 {
            let column = &self.rod_data.compliance[j * n_rod..(j + 1) * n_rod];
            for (o, g) in out[l.rod()].iter_mut().zip(column) {
                *o -= g * mu[1 + j];
            }
        }
    }

    /// Values of `v` (length n) on s.
    pub(super) fn on_s(&self, v: &[f64]) -> VectorS {
        let l = self.layout;
        let b = l.pin_b();
        let centre = l.crank_centre().map_or([0.0; 2], |g| [v[g], v[g + 1]]);
        VectorS::from([
            v[CRANK_ANGLE],
            v[PIN_A],
            v[PIN_A + 1],
            v[b],
            v[b + 1],
            v[l.slider()],
            centre[0],
            centre[1],
        ])
    }
}
