//! The implicit integrator: a one-step scheme with simplified Newton iterations on the velocities,
//! an error estimate and step-size control, for a [`MechanicalSystem`] y = [q, q̇, w]. Two schemes:
//! - [`Scheme::Esdirk`]: the L-stable ESDIRK5(4) of [`super::esdirk`] (the default): six implicit
//!   stages per step, 5th order, unresolved frequencies damped completely.
//! - [`Scheme::GeneralizedAlpha`]: the generalized-α method of [`super::generalized_alpha`]: one
//!   implicit stage per step, 2nd order, with the numerical dissipation ρ∞ as a parameter.
//!
//! Each implicit stage is solved for its velocities V only. Both schemes write the stage's
//! coordinates as Q = B_q + κV and its accelerations through V = B_v + λ a(Q, V), with B_q, B_v
//! known from the step start and earlier stages, so the stage equation and its Newton matrix are
//! ```text
//! R(V) = V − B_v − λ a(B_q + κV, V) = 0,    (I − λ ∂a/∂q̇ − λκ ∂a/∂q) ΔV = −R
//! ESDIRK:          κ = λ = hγ
//! generalized-α:   κ = hβ/γ,  λ = hγ (1 − α_f)/(1 − α_m)
//! ```
//! (simplified Newton on an n × n matrix, n the number of coordinates, instead of the 2n + m of the
//! first-order system). The accelerations of a converged stage are taken from the stage equation,
//! A = (V − B_v)/λ, and the quadrature states w from their rates at the converged stage (trapezoidal
//! rule for the generalized-α method): f is evaluated at the iterate before the last Newton update
//! ΔV, and the rates are moved to the update to first order, ẇ + ∂ẇ/∂q κΔV + ∂ẇ/∂q̇ ΔV, with the
//! quadrature rows of the Jacobian's difference quotients. The rates at the iterate itself are off
//! by the Newton update: the drive torque, a constraint force, carries the stiff rod's and the oil
//! film's forces, and an update within the Newton tolerance moves it by percents (summed so, the drive
//! work of 0.5 s with the lubricated joint is 3 % low at rtol 1e-2; docs/design.md, "Energy
//! account"). The Jacobian ∂a/∂(q, q̇) is computed by forward differences
//! and reused across steps while Newton converges fast; the iteration matrix is factorised only when
//! h changes (kept for step-size ratios in [1, 1.2], as RADAU5 does). Each ESDIRK stage starts from
//! the cubic Hermite interpolant of the velocities known so far (earlier stages, the last step's
//! start); the generalized-α stage from aₙ₊₁ = aₙ.
//!
//! The error estimate in the RMS over all components is not filtered by (I − hγJ)⁻¹ (Shampine's
//! device, used by RADAU5): with a Jacobian reused over many steps the filter hid real errors of
//! the oil film, whose stiffness changes by orders of magnitude with the eccentricity (measured:
//! benchmark C at rtol 1e-4 peaked at 6 kN instead of 3.05 kN). The quantities the system holds on
//! their own ([`super::ErrorScales::held`], the dry journal's normal velocity) are measured on the
//! filtered ESDIRK estimate: the rod-end vibration of unresolved stiff modes, which the L-stable
//! method damps, would otherwise set the step (a 64-element rod with 126 modes took 3.5× the
//! time).
//!
//! # References
//! - E. Hairer, G. Wanner (1996), Solving Ordinary Differential Equations II, 2nd ed., §IV.8
//!   (simplified Newton, convergence rate, Jacobian reuse, error-estimate filtering).

use super::control::{ErrorScales, Stats, Tolerances, initial_step, step_size};
use super::esdirk::Tableau;
use super::generalized_alpha::GeneralizedAlpha;
use super::step_loop::{self, Method, Trial};
use super::system::MechanicalSystem;
use crate::error::ModelError;
use crate::linalg::lu::Lu;

mod stages;
mod within;

/// Largest number of Newton iterations per stage.
const MAX_ITERATIONS: usize = 7;
/// Newton stops when the estimated remaining error is below this fraction of the tolerance.
const NEWTON_TOLERANCE: f64 = 0.3;
/// A step whose slowest Newton convergence rate exceeds this asks for a new Jacobian.
const REUSE_RATE: f64 = 0.1;
/// Step-size ratios for which the step (and the factorisation) is kept, as RADAU5 does.
const KEPT_STEP_RATIOS: std::ops::RangeInclusive<f64> = 1.0..=1.2;
/// A trial step whose Newton iteration failed with a fresh Jacobian is retried this much shorter.
const NEWTON_FAILURE_FACTOR: f64 = 0.25;
/// Marks the start of the last accepted step among the predictor's known points.
const HISTORY: usize = usize::MAX;

/// Why a trial step failed before its error test.
enum Failure {
    /// Newton diverged or did not converge in [`MAX_ITERATIONS`].
    Newton,
    /// The iteration matrix could not be factorised.
    Singular,
    /// The system is not defined at an iterate (a singular configuration).
    Undefined(ModelError),
}

/// The one-step scheme of an [`Implicit`] integrator.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Scheme {
    /// A stiffly accurate ESDIRK tableau with an explicit first stage.
    Esdirk(&'static Tableau),
    /// The generalized-α method.
    GeneralizedAlpha(GeneralizedAlpha),
}

impl Scheme {
    /// Number of stage derivatives kept (the start's and the implicit stages').
    fn stages(&self) -> usize {
        match self {
            Self::Esdirk(table) => table.stages,
            Self::GeneralizedAlpha(_) => 2,
        }
    }

    /// The local error estimate is O(h^p): the step-size exponent is −1/p.
    fn error_order(&self) -> i32 {
        match self {
            Self::Esdirk(table) => table.embedded_order + 1,
            Self::GeneralizedAlpha(_) => 3,
        }
    }

    /// (λ, κ) of the stage equation for a step h (module documentation).
    fn newton_coefficients(&self, h: f64) -> (f64, f64) {
        match self {
            Self::Esdirk(table) => (h * table.gamma, h * table.gamma),
            Self::GeneralizedAlpha(c) => {
                (h * c.gamma * c.acceleration_weight(), h * c.beta / c.gamma)
            }
        }
    }
}

/// Everything of the integrator that later steps depend on, for bit-exact snapshots.
#[derive(Clone, Debug, PartialEq)]
pub struct ImplicitState {
    /// Proposed next step \[s\] (0: not yet known).
    pub h: f64,
    /// Step size of the current factorisation (0: none).
    pub h_factored: f64,
    /// ∂q̈/∂q, column-major n × n (empty until computed).
    pub jacobian_q: Vec<f64>,
    /// ∂q̈/∂q̇, column-major n × n.
    pub jacobian_v: Vec<f64>,
    /// ∂ẇ/∂(q, q̇), the quadrature rates' derivatives: row-major m × 2n (m quadratures), the
    /// columns of q first.
    pub jacobian_w: Vec<f64>,
    /// Whether the Jacobian is to be recomputed before the next step.
    pub jacobian_stale: bool,
    /// Last Newton convergence-rate estimate θ/(1 − θ), used for the first iteration's test.
    pub newton_rate: f64,
    /// Velocities and accelerations at the start of the last accepted step, [v; a] (empty: no
    /// history), and that step's size: the stage predictor extrapolates them.
    pub history: Vec<f64>,
    /// Size of the last accepted step \[s\].
    pub history_step: f64,
    /// f at the current point (the last stage of the last step; empty: to be evaluated).
    pub derivative: Vec<f64>,
    /// Generalized-α: the algorithmic accelerations ā at the current point (empty: ā = a there,
    /// as at the start or after a restart).
    pub acceleration: Vec<f64>,
    /// Generalized-α: ā at the start of the last accepted step (for its dense output).
    pub acceleration_start: Vec<f64>,
    /// Statistics.
    pub stats: Stats,
}

/// The implicit integrator with its workspace.
#[derive(Clone, Debug)]
pub struct Implicit {
    tolerances: Tolerances,
    scales: ErrorScales,
    n_q: usize,
    state: ImplicitState,
    /// Whether the Jacobian was computed at the start of the current step.
    jacobian_fresh: bool,
    /// The quadratures whose rates vary with (q, q̇), by the Jacobian's quadrature rows.
    varying_rates: Vec<usize>,
    /// Slowest Newton convergence rate θ of the current step.
    step_rate: f64,
    lu: Lu,
    scheme: Scheme,
    k: Vec<Vec<f64>>,
    base: Vec<f64>,
    stage: Vec<f64>,
    rates: Vec<f64>,
    update: Vec<f64>,
    y_new: Vec<f64>,
    err: Vec<f64>,
    /// The error estimate filtered by the Newton matrix (for the held quantities).
    filtered: Vec<f64>,
    /// The held quantities' errors of the trial step.
    held: Vec<f64>,
    /// Generalized-α: ā at the start of the trial step, and at its end.
    alpha_start: Vec<f64>,
    alpha_end: Vec<f64>,
}

impl Implicit {
    /// An integrator for `n` states whose first 2·`n_q` are coordinates and velocities, with
    /// per-component scales (absolute tolerance = `tolerances.absolute` × scale).
    pub fn new(
        scheme: Scheme,
        n: usize,
        n_q: usize,
        tolerances: Tolerances,
        scales: ErrorScales,
    ) -> Result<Self, ModelError> {
        tolerances.validate()?;
        if scales.len() != n || 2 * n_q > n {
            return Err(ModelError::Numerical(format!(
                "implicit integrator: {n} states, {n_q} coordinates and {} scales do not fit",
                scales.len()
            )));
        }
        let n_held = scales.held.len();
        Ok(Self {
            tolerances,
            scales,
            n_q,
            state: ImplicitState {
                h: 0.0,
                h_factored: 0.0,
                jacobian_q: vec![0.0; n_q * n_q],
                jacobian_v: vec![0.0; n_q * n_q],
                jacobian_w: vec![0.0; 2 * n_q * (n - 2 * n_q)],
                jacobian_stale: true,
                newton_rate: 1.0,
                history: Vec::new(),
                history_step: 0.0,
                derivative: Vec::new(),
                acceleration: Vec::new(),
                acceleration_start: Vec::new(),
                stats: Stats::default(),
            },
            jacobian_fresh: false,
            varying_rates: Vec::with_capacity(n - 2 * n_q),
            step_rate: 0.0,
            lu: Lu::new(n_q),
            scheme,
            k: vec![vec![0.0; n]; scheme.stages()],
            base: vec![0.0; n],
            stage: vec![0.0; n],
            rates: vec![0.0; n],
            update: vec![0.0; n_q],
            y_new: vec![0.0; n],
            err: vec![0.0; n],
            filtered: vec![0.0; n],
            held: vec![0.0; n_held],
            alpha_start: vec![0.0; n_q],
            alpha_end: vec![0.0; n_q],
        })
    }

    /// Statistics since construction.
    pub fn stats(&self) -> Stats {
        self.state.stats
    }

    /// The state later steps depend on.
    pub fn state(&self) -> &ImplicitState {
        &self.state
    }

    /// Restores a state taken from an integrator of the same dimensions.
    pub fn set_state(&mut self, state: &ImplicitState) -> Result<(), ModelError> {
        let n2 = self.n_q * self.n_q;
        let fits = |v: &[f64], len: usize| v.is_empty() || v.len() == len;
        let vectors_ok = fits(&state.history, 2 * self.n_q)
            && fits(&state.derivative, self.k[0].len())
            && fits(&state.acceleration, self.n_q)
            && fits(&state.acceleration_start, self.n_q);
        let n_w = 2 * self.n_q * (self.k[0].len() - 2 * self.n_q);
        if state.jacobian_q.len() != n2
            || state.jacobian_v.len() != n2
            || state.jacobian_w.len() != n_w
            || !vectors_ok
        {
            return Err(ModelError::Numerical(format!(
                "implicit integrator state has a {}-entry Jacobian, this integrator {n2}",
                state.jacobian_q.len()
            )));
        }
        self.state = state.clone();
        self.jacobian_fresh = false;
        self.find_varying_rates();
        // The factorisation is a function of (Jacobian, h_factored): rebuild it.
        if self.state.h_factored > 0.0 && self.factorize(self.state.h_factored).is_err() {
            self.state.h_factored = 0.0;
        }
        Ok(())
    }

    /// Forgets f at the current point and the step history after the state was changed from
    /// outside (an impulsive velocity change): the next stages are predicted from the current
    /// point only, and the generalized-α recursion starts afresh (ā = a).
    pub fn restart(&mut self) {
        self.state.derivative.clear();
        self.state.history.clear();
        self.state.acceleration.clear();
    }

    /// Generalized-α: sets ā at the start of the trial steps from the current point (or from the
    /// last accepted step's start, for its dense output); a there (`k[0]`) if none is stored.
    fn start_acceleration(&mut self, of_last_step: bool) {
        if !matches!(self.scheme, Scheme::GeneralizedAlpha(_)) {
            return;
        }
        let stored = if of_last_step {
            &self.state.acceleration_start
        } else {
            &self.state.acceleration
        };
        let source = if stored.is_empty() {
            &self.k[0][self.n_q..2 * self.n_q]
        } else {
            stored
        };
        self.alpha_start.copy_from_slice(source);
    }

    /// Evaluates ∂q̈/∂(q, q̇) at (t, y) afresh and factorises the Newton matrix for step size h:
    /// the work of one Jacobian update within a step (used by the benchmarks).
    pub fn update_jacobian<F: MechanicalSystem>(
        &mut self,
        f: &mut F,
        t: f64,
        y: &[f64],
        h: f64,
    ) -> Result<(), ModelError> {
        self.jacobian(f, t, y)?;
        self.factorize(h)
    }

    /// f at the start and at the end of the last accepted step.
    pub fn derivatives(&self) -> (&[f64], &[f64]) {
        (&self.k[self.scheme.stages() - 1], &self.k[0])
    }

    /// Takes one accepted step from (`*t`, `y`) by the shared loop (`step_loop::step`: retried
    /// when rejected, in at most `max_attempts` trial steps, ending at `limit` at the latest).
    /// Returns `false` when the attempts ran out before a step was accepted; then, as on failure,
    /// `*t` and `y` hold the last accepted point.
    pub fn step<F: MechanicalSystem>(
        &mut self,
        f: &mut F,
        t: &mut f64,
        y: &mut [f64],
        limit: Option<f64>,
        max_attempts: u64,
    ) -> Result<bool, ModelError> {
        if self.state.derivative.is_empty() {
            f.rhs(*t, y, &mut self.k[0])?;
            self.state.stats.evaluations += 1;
        } else {
            self.k[0].copy_from_slice(&self.state.derivative);
        }
        self.start_acceleration(false);
        if self.state.h <= 0.0 {
            let (k0, rest) = self.k.split_at_mut(1);
            self.state.h = initial_step(
                f,
                *t,
                y,
                &k0[0],
                limit.unwrap_or(*t + self.tolerances.max_step),
                &self.tolerances,
                &self.scales,
                self.scheme.error_order(),
                &mut self.stage,
                &mut rest[0],
            )?;
            self.state.stats.evaluations += 1;
        }
        let tolerances = self.tolerances;
        step_loop::step(self, f, (t, y), limit, &tolerances, max_attempts)
    }
}

impl<F: MechanicalSystem> Method<F> for Implicit {
    fn proposal(&mut self) -> &mut f64 {
        &mut self.state.h
    }

    fn stats(&mut self) -> &mut Stats {
        &mut self.state.stats
    }

    fn error_order(&self) -> i32 {
        self.scheme.error_order()
    }

    /// The trial step with the Jacobian renewed first if stale. A failed Newton iteration, or
    /// one that reached a point where the system is not defined, is retried with the same step
    /// and a fresh Jacobian, or, if the Jacobian was fresh or the matrix singular, with
    /// [`NEWTON_FAILURE_FACTOR`] times the step (a Jacobian that cannot be evaluated, too).
    fn trial(&mut self, f: &mut F, t: f64, y: &[f64], h: f64) -> Trial {
        if self.state.jacobian_stale {
            if let Err(e) = self.jacobian(f, t, y) {
                return Trial::Undefined(NEWTON_FAILURE_FACTOR, e);
            }
        }
        let retry = |failure: Failure, factor: f64| match failure {
            Failure::Undefined(e) => Trial::Undefined(factor, e),
            _ => Trial::Failed(factor),
        };
        match self.try_step(f, t, y, h, true) {
            Ok(err) => Trial::Error(err),
            Err(failure) if self.jacobian_fresh || matches!(failure, Failure::Singular) => {
                retry(failure, NEWTON_FAILURE_FACTOR)
            }
            Err(failure) => {
                self.state.jacobian_stale = true;
                retry(failure, 1.0)
            }
        }
    }

    fn candidate(&self) -> &[f64] {
        &self.y_new
    }

    /// The candidate, the predictor's history (the step's start), the derivative at the new
    /// point (first same as last), the Jacobian policy, and the next step's factor, 1 for small
    /// increases while the Jacobian is kept (the factorisation with it, as RADAU5 does).
    fn commit(&mut self, y: &mut [f64], h: f64, err: f64, rejected_last: bool) -> f64 {
        let n_q = self.n_q;
        self.state.history.resize(2 * n_q, 0.0);
        self.state.history[..n_q].copy_from_slice(&y[n_q..2 * n_q]);
        self.state.history[n_q..].copy_from_slice(&self.k[0][n_q..2 * n_q]);
        self.state.history_step = h;
        y.copy_from_slice(&self.y_new);
        self.k.swap(0, self.scheme.stages() - 1);
        self.state.derivative.clone_from(&self.k[0]);
        if matches!(self.scheme, Scheme::GeneralizedAlpha(_)) {
            self.state.acceleration_start.clone_from(&self.alpha_start);
            self.state.acceleration.clone_from(&self.alpha_end);
        }
        self.jacobian_fresh = false;
        if self.step_rate > REUSE_RATE {
            self.state.jacobian_stale = true;
        }
        let factor = step_size::accepted(err, self.scheme.error_order(), rejected_last);
        if KEPT_STEP_RATIOS.contains(&factor) && !self.state.jacobian_stale {
            1.0
        } else {
            factor
        }
    }
}

#[cfg(test)]
mod tests;
