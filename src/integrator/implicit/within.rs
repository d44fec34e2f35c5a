//! The state inside an accepted step of the implicit integrator: its dense output (the filtered
//! interpolant) and its own solution there (a partial step).

use super::Implicit;
use crate::error::{ModelError, Num};
use crate::integrator::MechanicalSystem;
use crate::integrator::dense;

impl Implicit {
    /// The dense output: the state at t₀ + s·h inside the last accepted step `span`, (t₀, y₀, f₀)
    /// → (t₀ + h, y₁, f₁), written to `out`, from the quintic Hermite interpolant y₅
    /// ([`dense::interpolate`]) and the cubic one y₃ through the same ends without their
    /// accelerations ([`dense::cubic`]), their difference filtered by the Newton matrix:
    /// ```text
    /// y(t₀ + sh) = y₃ + (I − A)⁻¹ (y₅ − y₃),   A = [0  κI; λ ∂a/∂q  λ ∂a/∂q̇]
    /// (I − A)⁻¹ [d_q; d_v]:   E x_v = d_v + λ ∂a/∂q d_q,   x_q = d_q + κ x_v
    /// ```
    /// with E = I − λ ∂a/∂q̇ − λκ ∂a/∂q the factorised Newton matrix of the step (the stage
    /// equation of [`Implicit`]); the other states are the interpolant's (cubic Hermite in their
    /// rates).
    ///
    /// After a large implicit step the end accelerations carry the unresolved stiff components
    /// amplified (ω² times their amplitudes, ωh ≫ 1), and the quintic passes them on (about
    /// h² Δq̈/64 in mid-step); the filter divides what the quintic adds to the cubic by about
    /// (γωh)² for such a component and leaves the resolved motion's part, which E changes by
    /// O(h ∂a/∂q̇ + h² ∂a/∂q), nearly whole: O(h⁵) position and O(h⁴) velocity errors of the
    /// resolved motion, for one solve with the factorisation at hand. This is Shampine's filter
    /// of the error estimate (Hairer and Wanner, §IV.8) applied to the interpolant. Without a
    /// factorisation (none kept) it takes the method's own partial step,
    /// [`Implicit::state_within`].
    pub fn dense_output<F: MechanicalSystem>(
        &mut self,
        f: &mut F,
        span: &dense::Span<'_>,
        s: f64,
        out: &mut [f64],
    ) -> Result<(), ModelError> {
        let h_factored = self.state.h_factored;
        let dense::Span {
            t0, h, y0, f0, y1, ..
        } = *span;
        if h_factored == 0.0 {
            if self.state_within(f, t0, y0, f0, s * h, out).is_err() {
                dense::interpolate(self.n_q, span, s, out);
            }
            return Ok(());
        }
        let n_q = self.n_q;
        dense::interpolate(n_q, span, s, out);
        let cubic = &mut self.stage;
        dense::cubic(n_q, h, y0, y1, s, cubic);
        let (lambda, kappa) = self.scheme.newton_coefficients(h_factored);
        let x_v = &mut self.update;
        for (i, x) in x_v.iter_mut().enumerate() {
            *x = out[n_q + i] - cubic[n_q + i];
        }
        for (j, column) in self.state.jacobian_q.chunks_exact(n_q).enumerate() {
            let d_q = lambda * (out[j] - cubic[j]);
            for (x, &a) in x_v.iter_mut().zip(column) {
                *x += a * d_q;
            }
        }
        self.lu.solve(x_v);
        for (i, &x) in x_v.iter().enumerate() {
            out[i] += kappa * x;
            out[n_q + i] = cubic[n_q + i] + x;
        }
        Ok(())
    }

    /// The state at t₀ + Δt inside the last accepted step (t₀, y₀) → (t₁, y₁), written to
    /// `out`: one step of the method itself from y₀ (`f0` = f(t₀, y₀)), without error control.
    ///
    /// The integrator's own solution at that point, at the price of a step: what an interpolated
    /// value is checked against where it decides a result. It damps the unresolved stiff
    /// components as the step itself did, and leaves the step sequence untouched (Newton memory,
    /// history, statistics other than evaluations); the Newton matrix is refactorised for the
    /// next step.
    pub fn state_within<F: MechanicalSystem>(
        &mut self,
        f: &mut F,
        t0: f64,
        y0: &[f64],
        f0: &[f64],
        dt: f64,
        out: &mut [f64],
    ) -> Result<(), ModelError> {
        let (rate, steps, rejected) = (
            self.state.newton_rate,
            self.state.stats.steps,
            self.state.stats.rejected,
        );
        let factorizations = self.state.stats.factorizations;
        out.copy_from_slice(y0);
        self.k[0].copy_from_slice(f0);
        self.start_acceleration(true);
        let mut pieces = 1u32;
        let mut done = 0u32;
        let mut t = t0;
        let result = loop {
            let h = dt / f64::from(pieces);
            match self.try_step(f, t, out, h, false) {
                Ok(_) => {
                    out.copy_from_slice(&self.y_new);
                    t += h;
                    done += 1;
                    if done == pieces {
                        break Ok(());
                    }
                    let (first, rest) = self.k.split_at_mut(1);
                    first[0].copy_from_slice(&rest[rest.len() - 1]);
                    self.alpha_start.copy_from_slice(&self.alpha_end);
                }
                Err(_) if pieces < 8 && done == 0 => pieces *= 2,
                Err(_) => {
                    break Err(ModelError::Numerical(format!(
                        "partial step to t = {} s: Newton did not converge",
                        Num(t0 + dt)
                    )));
                }
            }
        };
        self.state.newton_rate = rate;
        self.state.stats.steps = steps;
        self.state.stats.rejected = rejected;
        self.state.stats.factorizations = factorizations;
        self.state.h_factored = 0.0;
        result
    }
}
