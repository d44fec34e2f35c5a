//! Dormand–Prince 5(4) stepper (DOPRI5), allocation-free after construction.
//!
//! ```text
//! kᵢ = f(t + cᵢh, y + h Σⱼ aᵢⱼ kⱼ),  y₁ = y + h Σ bᵢ kᵢ (= stage 7, FSAL),  err = h Σ eᵢ kᵢ
//! h_new = h · min(5, max(0.2, 0.9 · err^(−1/5)))    (no growth right after a rejection;
//!                                                     the controller of `super::control::step_size`)
//! ```
//!
//! # References
//! - Dormand & Prince (1980); Hairer, Nørsett & Wanner (1993), Table II.5.2 and code DOPRI5.

use super::control::{ErrorScales, Stats, Tolerances, initial_step, step_size};
use super::step_loop::{self, Method, Trial};
use super::system::OdeSystem;
use crate::error::ModelError;

/// Order q of the error estimate: err = O(h⁵).
const ORDER: i32 = 5;
const C: [f64; 7] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0];
const A: [[f64; 6]; 7] = [
    [0.0; 6],
    [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
        0.0,
        0.0,
    ],
    [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
        0.0,
    ],
    [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ],
];
/// Error weights e = b − b̂.
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// Dormand–Prince 5(4) integrator with its workspace and statistics.
#[derive(Clone, Debug)]
pub struct DormandPrince {
    tolerances: Tolerances,
    /// Per-component error weights.
    scales: ErrorScales,
    k: [Vec<f64>; 7],
    y_stage: Vec<f64>,
    /// Proposed next step size (0: not yet known).
    h: f64,
    /// Whether k\[0\] holds f at the current point (first same as last).
    fsal: bool,
    stats: Stats,
}

impl DormandPrince {
    /// An integrator for `n` states.
    pub fn new(n: usize, tolerances: Tolerances) -> Result<Self, ModelError> {
        tolerances.validate()?;
        Ok(Self {
            tolerances,
            scales: ErrorScales::uniform(n),
            k: std::array::from_fn(|_| vec![0.0; n]),
            y_stage: vec![0.0; n],
            h: 0.0,
            fsal: false,
            stats: Stats::default(),
        })
    }

    /// Sets per-component error weights, one per state.
    pub fn with_scales(mut self, scales: ErrorScales) -> Result<Self, ModelError> {
        if scales.len() != self.scales.len() {
            return Err(ModelError::Numerical(format!(
                "{} scales for {} states",
                scales.len(),
                self.scales.len()
            )));
        }
        self.scales = scales;
        Ok(self)
    }

    /// Statistics since construction.
    pub fn stats(&self) -> Stats {
        self.stats
    }

    /// The step size the next step will try \[s\].
    pub fn step_size(&self) -> f64 {
        self.h
    }

    /// The state later steps depend on: proposed step, f at the current point (empty if not
    /// known) and statistics.
    pub fn state(&self) -> (f64, Vec<f64>, Stats) {
        let derivative = if self.fsal {
            self.k[0].clone()
        } else {
            Vec::new()
        };
        (self.h, derivative, self.stats)
    }

    /// Restores [`DormandPrince::state`].
    pub fn set_state(
        &mut self,
        h: f64,
        derivative: &[f64],
        stats: Stats,
    ) -> Result<(), ModelError> {
        self.fsal = match derivative.len() {
            0 => false,
            n if n == self.k[0].len() => {
                self.k[0].copy_from_slice(derivative);
                true
            }
            n => {
                return Err(ModelError::Numerical(format!(
                    "Dormand–Prince state with {n} derivatives for {} states",
                    self.k[0].len()
                )));
            }
        };
        self.h = h;
        self.stats = stats;
        Ok(())
    }

    /// Forgets f at the current point (the state was changed from outside).
    pub fn restart(&mut self) {
        self.fsal = false;
    }

    /// f at the start and at the end of the last accepted step.
    pub fn derivatives(&self) -> (&[f64], &[f64]) {
        (&self.k[6], &self.k[0])
    }

    /// Advances `y` from `*t` to exactly `t_end` for the system `f`, the last step shortened to
    /// end there.
    ///
    /// On failure (step below the minimum, non-finite state) `*t` and `y` hold the last accepted
    /// point and the error says where and why.
    pub fn advance<F: OdeSystem>(
        &mut self,
        f: &mut F,
        t: &mut f64,
        y: &mut [f64],
        t_end: f64,
    ) -> Result<(), ModelError> {
        self.fsal = false;
        while *t < t_end {
            self.step(f, t, y, Some(t_end), u64::MAX)?;
        }
        Ok(())
    }

    /// Takes one accepted step from (`*t`, `y`) by the shared loop (`step_loop::step`: retried
    /// when rejected, in at most `max_attempts` trial steps, ending at `limit` at the latest).
    /// Returns `false` when the attempts ran out before a step was accepted (`*t` and `y`
    /// unchanged).
    pub fn step<F: OdeSystem>(
        &mut self,
        f: &mut F,
        t: &mut f64,
        y: &mut [f64],
        limit: Option<f64>,
        max_attempts: u64,
    ) -> Result<bool, ModelError> {
        if !self.fsal {
            f.rhs(*t, y, &mut self.k[0])?;
            self.stats.evaluations += 1;
            self.fsal = true;
        }
        if self.h <= 0.0 {
            let (k0, rest) = self.k.split_at_mut(1);
            self.h = initial_step(
                f,
                *t,
                y,
                &k0[0],
                limit.unwrap_or(*t + self.tolerances.max_step),
                &self.tolerances,
                &self.scales,
                ORDER,
                &mut self.y_stage,
                &mut rest[0],
            )?;
            self.stats.evaluations += 1;
        }
        let tolerances = self.tolerances;
        step_loop::step(self, f, (t, y), limit, &tolerances, max_attempts)
    }

    /// One trial step of size `h` from (t, y); the candidate is left in `y_stage` and k[6] holds
    /// f at it. Returns the scaled error norm (∞ for a non-finite candidate), or the error of a
    /// stage where f is not defined.
    fn try_step<F: OdeSystem>(
        &mut self,
        f: &mut F,
        t: f64,
        y: &[f64],
        h: f64,
    ) -> Result<f64, ModelError> {
        for s in 1..7 {
            for (i, (stage, &y_i)) in self.y_stage.iter_mut().zip(y).enumerate() {
                let incr: f64 = (0..s).map(|j| A[s][j] * self.k[j][i]).sum();
                *stage = y_i + h * incr;
            }
            self.stats.evaluations += 1;
            f.rhs(t + C[s] * h, &self.y_stage, &mut self.k[s])?;
        }
        let Tolerances {
            relative, absolute, ..
        } = self.tolerances;
        let mut sum = 0.0;
        for (i, (&y_i, &stage)) in y.iter().zip(&self.y_stage).enumerate() {
            let err: f64 = h * (0..7).map(|j| E[j] * self.k[j][i]).sum::<f64>();
            let scale = absolute * self.scales.absolute[i]
                + relative * self.scales.relative[i] * y_i.abs().max(stage.abs());
            sum += (err / scale).powi(2);
        }
        let norm = (sum / y.len().max(1) as f64).sqrt();
        Ok(if norm.is_finite() {
            norm
        } else {
            f64::INFINITY
        })
    }
}

impl<F: OdeSystem> Method<F> for DormandPrince {
    fn proposal(&mut self) -> &mut f64 {
        &mut self.h
    }

    fn stats(&mut self) -> &mut Stats {
        &mut self.stats
    }

    fn error_order(&self) -> i32 {
        ORDER
    }

    /// A stage where f is not defined rejects the step as a non-finite error estimate would.
    fn trial(&mut self, f: &mut F, t: f64, y: &[f64], h: f64) -> Trial {
        match self.try_step(f, t, y, h) {
            Ok(err) => Trial::Error(err),
            Err(e) => Trial::Undefined(step_size::rejected(f64::INFINITY, ORDER), e),
        }
    }

    fn candidate(&self) -> &[f64] {
        &self.y_stage
    }

    /// The candidate and its derivative (k₇, the next step's k₁: first same as last).
    fn commit(&mut self, y: &mut [f64], _h: f64, err: f64, rejected_last: bool) -> f64 {
        y.copy_from_slice(&self.y_stage);
        self.k.swap(0, 6);
        step_size::accepted(err, ORDER, rejected_last)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tolerances(rtol: f64) -> Tolerances {
        Tolerances::from_relative(rtol, 1.0)
    }

    /// Harmonic oscillator over 10 periods: the global error follows the tolerance.
    #[test]
    fn harmonic_oscillator_error_follows_tolerance() {
        let omega = 3.0;
        let mut f = |_t: f64, y: &[f64], dy: &mut [f64]| {
            dy[0] = y[1];
            dy[1] = -omega * omega * y[0];
        };
        let t_end = 10.0 * std::f64::consts::TAU / omega;
        let mut errors = Vec::new();
        for rtol in [1e-6, 1e-9] {
            let mut dp = DormandPrince::new(2, tolerances(rtol)).unwrap();
            let (mut t, mut y) = (0.0, [1.0, 0.0]);
            // Cut [0, T] into uneven pieces: the end is hit exactly each time.
            for piece in [0.37, 1.0, 2.5, t_end] {
                dp.advance(&mut f, &mut t, &mut y, piece.min(t_end))
                    .unwrap();
                assert_eq!(t, piece.min(t_end));
            }
            let err = ((y[0] - crate::math::cos(omega * t)).powi(2)
                + (y[1] / omega + crate::math::sin(omega * t)).powi(2))
            .sqrt();
            errors.push(err);
            let stats = dp.stats();
            assert!(stats.steps > 10 && stats.evaluations >= 6 * stats.steps);
        }
        // 10 periods: global error ≲ 100·tol; tightening by 1e3 must gain at least 100×.
        assert!(errors[0] < 1e-4 && errors[1] < 1e-7, "{errors:?}");
        assert!(errors[0] / errors[1] > 100.0, "{errors:?}");
    }

    /// A blow-up is reported as an error at the minimum step, not an endless loop.
    #[test]
    fn finite_time_blow_up_fails_cleanly() {
        let mut f = |_t: f64, y: &[f64], dy: &mut [f64]| dy[0] = y[0] * y[0];
        let mut dp = DormandPrince::new(1, tolerances(1e-8)).unwrap();
        let (mut t, mut y) = (0.0, [1.0]);
        let err = dp.advance(&mut f, &mut t, &mut y, 2.0).unwrap_err();
        assert!(err.to_string().contains("fell below the minimum"), "{err}");
        assert!(t < 1.01 && y[0] > 1e3, "stopped at t = {t}, y = {}", y[0]);
    }
}
