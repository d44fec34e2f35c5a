//! The implicit step itself: the Newton matrix (forward-difference Jacobian, factorisation) and
//! the trial step of each scheme with its stage solves (see the module documentation of
//! [`super`] for the equations).

use super::{Failure, HISTORY, Implicit, MAX_ITERATIONS, NEWTON_TOLERANCE, Scheme};
use crate::error::ModelError;
use crate::integrator::control::{Tolerances, scaled_norm};
use crate::integrator::dense;
use crate::integrator::esdirk::Tableau;
use crate::integrator::generalized_alpha::GeneralizedAlpha;
use crate::integrator::system::MechanicalSystem;
use crate::math;

impl Implicit {
    /// ∂q̈/∂(q, q̇) at (t, y) by forward differences from f(t, y), evaluated afresh (the
    /// first-same-as-last stage derivative satisfies the stage equation only to the Newton
    /// tolerance, too coarse a base for differences).
    pub(super) fn jacobian<F: MechanicalSystem>(
        &mut self,
        f: &mut F,
        t: f64,
        y: &[f64],
    ) -> Result<(), ModelError> {
        let n_q = self.n_q;
        f.rhs(t, y, &mut self.base)?;
        self.stage.copy_from_slice(y);
        for (j, (&y_j, &scale)) in y
            .iter()
            .zip(&self.scales.absolute)
            .take(2 * n_q)
            .enumerate()
        {
            let delta = f64::EPSILON.sqrt() * y_j.abs().max(scale);
            self.stage[j] = y_j + delta;
            f.rhs(t, &self.stage, &mut self.rates)?;
            self.stage[j] = y_j;
            let column = if j < n_q {
                &mut self.state.jacobian_q[j * n_q..(j + 1) * n_q]
            } else {
                &mut self.state.jacobian_v[(j - n_q) * n_q..(j - n_q + 1) * n_q]
            };
            for (c, (a, a0)) in column.iter_mut().zip(
                self.rates[n_q..2 * n_q]
                    .iter()
                    .zip(&self.base[n_q..2 * n_q]),
            ) {
                *c = (a - a0) / delta;
            }
            // The quadrature rates' column of the same difference quotient.
            let rows = self.state.jacobian_w.chunks_exact_mut(2 * n_q);
            for (row, (a, a0)) in rows.zip(self.rates[2 * n_q..].iter().zip(&self.base[2 * n_q..]))
            {
                row[j] = (a - a0) / delta;
            }
        }
        self.find_varying_rates();
        self.state.stats.evaluations += 2 * n_q as u64 + 1;
        self.state.stats.jacobians += 1;
        self.state.jacobian_stale = false;
        self.state.h_factored = 0.0;
        self.jacobian_fresh = true;
        Ok(())
    }

    /// Factorises E = I − λ ∂a/∂q̇ − λκ ∂a/∂q for step h (not counted: restoring a state
    /// refactorises).
    pub(super) fn factorize(&mut self, h: f64) -> Result<(), ModelError> {
        let (lambda, kappa) = self.scheme.newton_coefficients(h);
        let n = self.n_q;
        let (jv, jq) = (&self.state.jacobian_v, &self.state.jacobian_q);
        for (j, column) in self.lu.matrix_mut().chunks_exact_mut(n).enumerate() {
            for (i, e) in column.iter_mut().enumerate() {
                let identity = if i == j { 1.0 } else { 0.0 };
                let k = j * n + i;
                *e = identity - lambda * jv[k] - lambda * kappa * jq[k];
            }
        }
        self.state.h_factored = h;
        self.lu.factorize()
    }

    /// One trial step of size h from (t, y): the candidate goes to `y_new`; returns the scaled
    /// error norm.
    pub(super) fn try_step<F: MechanicalSystem>(
        &mut self,
        f: &mut F,
        t: f64,
        y: &[f64],
        h: f64,
        use_history: bool,
    ) -> Result<f64, Failure> {
        self.step_rate = 0.0;
        if self.state.h_factored != h {
            self.state.stats.factorizations += 1;
            if self.factorize(h).is_err() {
                self.state.h_factored = 0.0;
                return Err(Failure::Singular);
            }
        }
        match self.scheme {
            Scheme::Esdirk(table) => self.try_esdirk(f, t, y, h, table, use_history),
            Scheme::GeneralizedAlpha(c) => self.try_generalized_alpha(f, t, y, h, c),
        }
    }

    /// An ESDIRK trial step: the stages in turn, then the weighted sums and the embedded error.
    pub(super) fn try_esdirk<F: MechanicalSystem>(
        &mut self,
        f: &mut F,
        t: f64,
        y: &[f64],
        h: f64,
        table: &Tableau,
        use_history: bool,
    ) -> Result<f64, Failure> {
        let (n, n_q) = (y.len(), self.n_q);
        let hg = h * table.gamma;
        let Tableau {
            stages,
            a,
            b,
            b_hat,
            c,
            ..
        } = *table;
        for i in 1..stages {
            self.base.copy_from_slice(y);
            for (j, k) in self.k.iter().enumerate().take(i) {
                let w = h * a[i][j];
                for (base, kj) in self.base.iter_mut().zip(k) {
                    *base += w * kj;
                }
            }
            // Predictor: the cubic Hermite interpolant of the velocities (v, a known at stages
            // j < i and at the start of the last accepted step): between the closest known
            // points on either side of the stage time if there are such, otherwise from the
            // step start to the closest point (from the last step's start to this one's for the
            // first stage); a Taylor step without history.
            let done = &self.k[..i];
            let target = c[i] * h;
            let below = (0..i)
                .filter(|&j| c[j] < c[i])
                .max_by(|&a, &b| c[a].total_cmp(&c[b]));
            let above = (0..i)
                .filter(|&j| c[j] > c[i])
                .min_by(|&a, &b| c[a].total_cmp(&c[b]));
            let nearest = (0..i)
                .min_by(|&a, &b| (c[a] - c[i]).abs().total_cmp(&(c[b] - c[i]).abs()))
                .unwrap_or(0);
            let pair = match (below, above) {
                (Some(a), Some(b)) => Some((a, b)),
                _ if nearest > 0 => Some((0, nearest)),
                _ if use_history && !self.state.history.is_empty() => Some((HISTORY, 0)),
                _ => None,
            };
            let point = |j: usize| -> (f64, &[f64], &[f64]) {
                if j == HISTORY {
                    let (v, a) = self.state.history.split_at(n_q);
                    (-self.state.history_step, v, a)
                } else {
                    (c[j] * h, &done[j][..n_q], &done[j][n_q..2 * n_q])
                }
            };
            match pair {
                Some((a, b)) => {
                    let ((ta, va, aa), (tb, vb, ab)) = (point(a), point(b));
                    let dt = tb - ta;
                    let s = (target - ta) / dt;
                    let [h00, h10, h01, h11] = dense::cubic_hermite(s);
                    for m in 0..n_q {
                        self.stage[n_q + m] =
                            h00 * va[m] + h10 * dt * aa[m] + h01 * vb[m] + h11 * dt * ab[m];
                    }
                }
                None => {
                    for m in 0..n_q {
                        self.stage[n_q + m] = done[0][m] + target * done[0][n_q + m];
                    }
                }
            }
            let previous = &done[i - 1];
            self.rates[2 * n_q..].copy_from_slice(&previous[2 * n_q..]);
            self.solve_stage(f, t + c[i] * h, hg, hg, hg)?;
            let k = &mut self.k[i];
            for m in 0..n_q {
                let v = self.stage[n_q + m];
                k[m] = v;
                k[n_q + m] = (v - self.base[n_q + m]) / hg;
            }
            k[2 * n_q..].copy_from_slice(&self.rates[2 * n_q..]);
        }
        for m in 0..n {
            let (mut sum, mut diff) = (0.0, 0.0);
            for (j, k) in self.k.iter().enumerate() {
                sum += b[j] * k[m];
                diff += (b[j] - b_hat[j]) * k[m];
            }
            self.y_new[m] = y[m] + h * sum;
            self.err[m] = h * diff;
        }
        if !self.scales.held.is_empty() {
            self.filter_error(h);
            f.held_errors(&self.y_new, &self.filtered, &mut self.held);
        }
        Ok(scaled_norm(
            &self.err,
            &self.held,
            y,
            &self.y_new,
            &self.scales,
            &self.tolerances,
        ))
    }

    /// The ESDIRK error estimate filtered by the Newton matrix, (I − hγJ)⁻¹ err, written to
    /// `filtered` (Shampine's device, Hairer & Wanner §IV.8): the unresolved stiff components, which
    /// the L-stable method damps, no longer count as error. With J = [0 I; ∂a/∂q ∂a/∂q̇] and
    /// λ = hγ the block system reduces to the Newton matrix already factorised:
    /// ```text
    /// x_v = (I − λ ∂a/∂q̇ − λ² ∂a/∂q)⁻¹ (e_v + λ ∂a/∂q e_q),   x_q = e_q + λ x_v
    /// ```
    /// (quadrature components copied). Used for the held quantities only: for the RMS over all
    /// components a Jacobian reused over many steps hid real errors (module documentation).
    pub(super) fn filter_error(&mut self, h: f64) {
        let n_q = self.n_q;
        let (lambda, _) = self.scheme.newton_coefficients(h);
        let (e_q, rest) = self.err.split_at(n_q);
        let velocities = &mut self.filtered[n_q..2 * n_q];
        velocities.copy_from_slice(&rest[..n_q]);
        for (column, &e) in self.state.jacobian_q.chunks_exact(n_q).zip(e_q) {
            for (x, &j) in velocities.iter_mut().zip(column) {
                *x += lambda * j * e;
            }
        }
        self.lu.solve(velocities);
        let (coordinates, rest) = self.filtered.split_at_mut(n_q);
        for ((x_q, &e), &x_v) in coordinates.iter_mut().zip(e_q).zip(&rest[..n_q]) {
            *x_q = e + lambda * x_v;
        }
        rest[n_q..].copy_from_slice(&self.err[2 * n_q..]);
    }

    /// A generalized-α trial step: one implicit stage for (qₙ₊₁, q̇ₙ₊₁), the trapezoidal rule for
    /// the quadratures, and the local error of coordinates and velocities
    /// ([`GeneralizedAlpha::local_error`]); ā at the start is `alpha_start`, at the end `alpha_end`.
    pub(super) fn try_generalized_alpha<F: MechanicalSystem>(
        &mut self,
        f: &mut F,
        t: f64,
        y: &[f64],
        h: f64,
        c: GeneralizedAlpha,
    ) -> Result<f64, Failure> {
        let (n, n_q) = (y.len(), self.n_q);
        let (lambda, kappa) = self.scheme.newton_coefficients(h);
        let weight = c.acceleration_weight();
        let f0 = &self.k[0];
        for m in 0..n_q {
            let (a0, a_bar0) = (f0[n_q + m], self.alpha_start[m]);
            let known = c.known_acceleration(a0, a_bar0);
            let v_hat = y[n_q + m] + h * ((1.0 - c.gamma) * a_bar0 + c.gamma * known);
            let q_hat = y[m] + h * y[n_q + m] + h * h * ((0.5 - c.beta) * a_bar0 + c.beta * known);
            self.alpha_end[m] = known;
            self.base[m] = q_hat - kappa * v_hat;
            self.base[n_q + m] = v_hat;
            self.stage[n_q + m] = v_hat + lambda * a0;
        }
        for m in 2 * n_q..n {
            self.base[m] = y[m] + 0.5 * h * f0[m];
            self.rates[m] = f0[m];
        }
        self.solve_stage(f, t + h, lambda, kappa, 0.5 * h)?;
        let (k0, k1) = self.k.split_at_mut(1);
        let (k0, k1) = (&k0[0], &mut k1[0]);
        for m in 0..n_q {
            let v = self.stage[n_q + m];
            let a = (v - self.base[n_q + m]) / lambda;
            let (a0, a_bar0) = (k0[n_q + m], self.alpha_start[m]);
            let a_bar1 = self.alpha_end[m] + weight * a;
            self.alpha_end[m] = a_bar1;
            self.y_new[m] = self.base[m] + kappa * v;
            self.y_new[n_q + m] = v;
            k1[m] = v;
            k1[n_q + m] = a;
            let (e_q, e_v) = c.local_error(h, a0, a, a_bar0, a_bar1);
            self.err[m] = e_q;
            self.err[n_q + m] = e_v;
        }
        for m in 2 * n_q..n {
            self.y_new[m] = self.base[m] + 0.5 * h * self.rates[m];
        }
        k1[2 * n_q..].copy_from_slice(&self.rates[2 * n_q..]);
        f.held_errors(&self.y_new, &self.err, &mut self.held);
        Ok(scaled_norm(
            &self.err[..2 * n_q],
            &self.held,
            &y[..2 * n_q],
            &self.y_new[..2 * n_q],
            &self.scales,
            &self.tolerances,
        ))
    }

    /// The quadrature rates of a converged stage moved from the last iterate, where f was
    /// evaluated, to the stage's velocities after the last Newton update ΔV (and its coordinates,
    /// moved by κΔV), to first order: ẇ += ∂ẇ/∂q κΔV + ∂ẇ/∂q̇ ΔV.
    fn correct_rates(&mut self, kappa: f64) {
        let n_q = self.n_q;
        for &i in &self.varying_rates {
            let (w_q, w_v) = self.state.jacobian_w[i * 2 * n_q..(i + 1) * 2 * n_q].split_at(n_q);
            let rate = &mut self.rates[2 * n_q + i];
            for ((&a, &b), &dv) in w_q.iter().zip(w_v).zip(&self.update) {
                *rate += (kappa * a + b) * dv;
            }
        }
    }

    /// The quadratures whose rates depend on (q, q̇) by the Jacobian's quadrature rows (the
    /// others, such as the drive angle's, need no correction).
    pub(super) fn find_varying_rates(&mut self) {
        let rows = self.state.jacobian_w.chunks_exact(2 * self.n_q);
        self.varying_rates.clear();
        self.varying_rates.extend(
            rows.enumerate()
                .filter(|(_, row)| row.iter().any(|&d| d != 0.0))
                .map(|(i, _)| i),
        );
    }

    /// Solves one stage equation R(V) = V − B_v − λ a(B_q + κV, V) = 0 by simplified Newton
    /// (module documentation): `base` holds [B_q, B_v, B_w], the velocity part of `stage` the
    /// predicted V and the quadrature part of `rates` the predicted rates ġ; the quadratures are
    /// w = B_w + μ ġ. On return `stage` holds the last iterate with V updated, and `rates` f at
    /// the last iterate with the quadrature rates moved to the updated V ([`Self::correct_rates`]).
    pub(super) fn solve_stage<F: MechanicalSystem>(
        &mut self,
        f: &mut F,
        t: f64,
        lambda: f64,
        kappa: f64,
        mu: f64,
    ) -> Result<(), Failure> {
        let (n, n_q) = (self.stage.len(), self.n_q);
        let Tolerances {
            relative, absolute, ..
        } = self.tolerances;
        let mut previous_norm = f64::INFINITY;
        let mut rate = math::powf(self.state.newton_rate.max(f64::EPSILON), 0.8);
        for iteration in 0..MAX_ITERATIONS {
            for m in 0..n_q {
                self.stage[m] = self.base[m] + kappa * self.stage[n_q + m];
            }
            for m in 2 * n_q..n {
                self.stage[m] = self.base[m] + mu * self.rates[m];
            }
            self.state.stats.evaluations += 1;
            self.state.stats.newton_iterations += 1;
            f.rhs(t, &self.stage, &mut self.rates)
                .map_err(Failure::Undefined)?;
            for m in 0..n_q {
                self.update[m] =
                    self.base[n_q + m] + lambda * self.rates[n_q + m] - self.stage[n_q + m];
            }
            self.lu.solve(&mut self.update);
            let mut sum = 0.0;
            for m in 0..n_q {
                let dv = self.update[m];
                if !dv.is_finite() {
                    return Err(Failure::Newton);
                }
                let v = &mut self.stage[n_q + m];
                *v += dv;
                let sc_v = absolute * self.scales.absolute[n_q + m]
                    + relative * self.scales.relative[n_q + m] * v.abs();
                let sc_q = absolute * self.scales.absolute[m]
                    + relative * self.scales.relative[m] * self.stage[m].abs();
                sum += (dv / sc_v).powi(2) + (kappa * dv / sc_q).powi(2);
            }
            let norm = (sum / (2 * n_q) as f64).sqrt();
            if iteration > 0 {
                let theta = norm / previous_norm;
                if theta >= 1.0 {
                    return Err(Failure::Newton);
                }
                rate = theta / (1.0 - theta);
                self.step_rate = self.step_rate.max(theta);
            }
            if rate * norm <= NEWTON_TOLERANCE || norm == 0.0 {
                self.state.newton_rate = rate;
                self.correct_rates(kappa);
                return Ok(());
            }
            previous_norm = norm;
        }
        Err(Failure::Newton)
    }
}
