//! ESDIRK5(4)7L[2]SA2: a 7-stage, 5th-order, L-stable, stiffly accurate singly diagonally implicit
//! Runge–Kutta method with an explicit first stage and a 4th-order embedded error estimate, for a
//! [`MechanicalSystem`] y = [q, q̇, w].
//!
//! ```text
//! Yᵢ = yₙ + h Σⱼ₍ⱼ<ᵢ₎ aᵢⱼ Kⱼ + hγ f(Yᵢ),   Kᵢ = f(Yᵢ),   yₙ₊₁ = Y₇ (stiffly accurate),   γ = 23/125
//! err = h Σ (bᵢ − b̂ᵢ) Kᵢ
//! ```
//! Each implicit stage is solved for its velocities Vᵢ only: with Qᵢ = Q̂ᵢ + hγVᵢ the stage
//! equation for the velocities is
//! ```text
//! R(V) = V − V̂ᵢ − hγ a(Q̂ᵢ + hγV, V) = 0,    (I − hγ ∂a/∂q̇ − h²γ² ∂a/∂q) ΔV = −R
//! ```
//! (simplified Newton on an n × n matrix, n the number of coordinates, instead of the 2n + m of the
//! first-order system). The accelerations of a converged stage are taken from the stage equation,
//! Aᵢ = (Vᵢ − V̂ᵢ)/(hγ), and the quadrature states w from their rates at the last iterate. The
//! Jacobian ∂a/∂(q, q̇) is computed by forward differences and reused across steps while Newton
//! converges fast; the iteration matrix is factorised only when hγ changes (kept for step-size
//! ratios in [1, 1.2], as RADAU5 does). Each stage starts from the cubic Hermite interpolant of
//! the velocities known so far (earlier stages, the last step's start).
//!
//! L-stability (R(∞) = 0) damps unresolved high frequencies. The error estimate is not filtered
//! by (I − hγJ)⁻¹ (Shampine's device, used by RADAU5): with a Jacobian reused over many steps
//! the filter hid real errors of the oil film, whose stiffness changes by orders of magnitude with
//! the eccentricity (measured: benchmark C at rtol 1e-4 peaked at 6 kN instead of 3.05 kN). The
//! coefficients are those of Kennedy & Carpenter (2016), table of
//! ESDIRK5(4)7L[2]SA₂ (stage order 2, all cᵢ in [0, 1]); a unit test checks every order condition.
//!
//! # References
//! - C. A. Kennedy, M. H. Carpenter (2016), Diagonally implicit Runge–Kutta methods for ordinary
//!   differential equations. A review, NASA/TM–2016–219173, §5.5 (ESDIRK5(4)7L[2]SA₂).
//! - E. Hairer, G. Wanner (1996), Solving Ordinary Differential Equations II, 2nd ed., §IV.8
//!   (simplified Newton, convergence rate, Jacobian reuse, error-estimate filtering).

use super::lu::Lu;
use super::{ErrorScales, MechanicalSystem, Stats, Tolerances, initial_step, scaled_norm};
use crate::error::ModelError;

/// Largest number of stages of a tableau.
const MAX_STAGES: usize = 7;
/// Largest number of Newton iterations per stage.
const MAX_ITERATIONS: usize = 7;
/// Newton stops when the estimated remaining error is below this fraction of the tolerance.
const NEWTON_TOLERANCE: f64 = 0.3;
/// A step whose slowest Newton convergence rate exceeds this asks for a new Jacobian.
const REUSE_RATE: f64 = 0.1;
/// Marks the start of the last accepted step among the predictor's known points.
const HISTORY: usize = usize::MAX;

/// An ESDIRK Butcher tableau: explicit first stage, γ on the diagonal, stiffly accurate (last row
/// of A = b), padded to the largest supported stage count.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tableau {
    /// Number of stages s.
    pub stages: usize,
    /// Diagonal coefficient γ.
    pub gamma: f64,
    /// Coefficients aᵢⱼ.
    pub a: [[f64; MAX_STAGES]; MAX_STAGES],
    /// Weights b (= last row of A).
    pub b: [f64; MAX_STAGES],
    /// Embedded weights b̂.
    pub b_hat: [f64; MAX_STAGES],
    /// Nodes cᵢ = Σⱼ aᵢⱼ.
    pub c: [f64; MAX_STAGES],
    /// Order of the embedded solution (sets the step-size exponent 1/(p̂ + 1)).
    pub embedded_order: i32,
}

/// Builds a tableau from the published strictly lower entries (rows 2 .. s − 1, columns ≥ 1),
/// γ, the nodes and the weights: b₁ and b̂₁ complete Σ = 1, the first column completes the row
/// sums cᵢ, and the last row is b.
const fn tableau(
    stages: usize,
    gamma: f64,
    lower: [[f64; MAX_STAGES]; MAX_STAGES],
    c: [f64; MAX_STAGES],
    b_tail: [f64; MAX_STAGES],
    b_hat_tail: [f64; MAX_STAGES],
    embedded_order: i32,
) -> Tableau {
    let mut b = b_tail;
    let mut b_hat = b_hat_tail;
    let (mut sum, mut sum_hat) = (0.0, 0.0);
    let mut j = 1;
    while j < stages {
        sum += b[j];
        sum_hat += b_hat[j];
        j += 1;
    }
    b[0] = 1.0 - sum;
    b_hat[0] = 1.0 - sum_hat;
    let mut a = lower;
    a[stages - 1] = b;
    let mut i = 1;
    while i < stages - 1 {
        a[i][i] = gamma;
        let mut row = 0.0;
        let mut j = 1;
        while j <= i {
            row += a[i][j];
            j += 1;
        }
        a[i][0] = c[i] - row;
        i += 1;
    }
    Tableau {
        stages,
        gamma,
        a,
        b,
        b_hat,
        c,
        embedded_order,
    }
}

/// ESDIRK5(4)7L\[2\]SA₂ (Kennedy & Carpenter 2016): 5th order, 6 implicit stages, γ = 23/125.
pub const ESDIRK54: Tableau = {
    let mut lower = [[0.0; MAX_STAGES]; MAX_STAGES];
    lower[2][1] = 791_020_047_304.0 / 3_561_426_431_547.0;
    lower[3][1] = -158_159_076_358.0 / 11_257_294_102_345.0;
    lower[3][2] = -85_517_644_447.0 / 5_003_708_988_389.0;
    lower[4][1] = -1_653_327_111_580.0 / 4_048_416_487_981.0;
    lower[4][2] = 1_514_767_744_496.0 / 9_099_671_765_375.0;
    lower[4][3] = 14_283_835_447_591.0 / 12_247_432_691_556.0;
    lower[5][1] = -4_540_011_970_825.0 / 8_418_487_046_959.0;
    lower[5][2] = -1_790_937_573_418.0 / 7_393_406_387_169.0;
    lower[5][3] = 10_819_093_665_085.0 / 7_266_595_846_747.0;
    lower[5][4] = 4_109_463_131_231.0 / 7_386_972_500_302.0;
    tableau(
        7,
        23.0 / 125.0,
        lower,
        [
            0.0,
            46.0 / 125.0,
            7_121_331_996_143.0 / 11_335_814_405_378.0,
            49.0 / 353.0,
            3_706_679_970_760.0 / 5_295_570_149_437.0,
            347.0 / 382.0,
            1.0,
        ],
        [
            0.0,
            -188_593_204_321.0 / 4_778_616_380_481.0,
            2_809_310_203_510.0 / 10_304_234_040_467.0,
            1_021_729_336_898.0 / 2_364_210_264_653.0,
            870_612_361_811.0 / 2_470_410_392_208.0,
            -1_307_970_675_534.0 / 8_059_683_598_661.0,
            23.0 / 125.0,
        ],
        [
            0.0,
            -582_099_335_757.0 / 7_214_068_459_310.0,
            615_023_338_567.0 / 3_362_626_566_945.0,
            3_192_122_436_311.0 / 6_174_152_374_399.0,
            6_156_034_052_041.0 / 14_430_468_657_929.0,
            -1_011_318_518_279.0 / 9_693_750_372_484.0,
            1_914_490_192_573.0 / 13_754_262_428_401.0,
        ],
        4,
    )
};

/// Why a trial step failed before its error test.
enum Failure {
    /// Newton diverged or did not converge in [`MAX_ITERATIONS`].
    Newton,
    /// The iteration matrix could not be factorised.
    Singular,
}

/// Everything of the integrator that later steps depend on, for bit-exact snapshots.
#[derive(Clone, Debug, PartialEq)]
pub struct EsdirkState {
    /// Proposed next step \[s\] (0: not yet known).
    pub h: f64,
    /// Step size of the current factorisation (0: none).
    pub h_factored: f64,
    /// ∂q̈/∂q, column-major n × n (empty until computed).
    pub jacobian_q: Vec<f64>,
    /// ∂q̈/∂q̇, column-major n × n.
    pub jacobian_v: Vec<f64>,
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
    /// Statistics.
    pub stats: Stats,
}

/// The ESDIRK5(4) integrator with its workspace.
#[derive(Clone, Debug)]
pub struct Esdirk {
    tolerances: Tolerances,
    scales: ErrorScales,
    n_q: usize,
    state: EsdirkState,
    /// Whether the Jacobian was computed at the start of the current step.
    jacobian_fresh: bool,
    /// Slowest Newton convergence rate θ of the current step.
    step_rate: f64,
    lu: Lu,
    table: &'static Tableau,
    k: Vec<Vec<f64>>,
    base: Vec<f64>,
    stage: Vec<f64>,
    rates: Vec<f64>,
    update: Vec<f64>,
    y_new: Vec<f64>,
    err: Vec<f64>,
}

impl Esdirk {
    /// An integrator for `n` states whose first 2·`n_q` are coordinates and velocities, with
    /// per-component scales (absolute tolerance = `tolerances.absolute` × scale).
    pub fn new(
        table: &'static Tableau,
        n: usize,
        n_q: usize,
        tolerances: Tolerances,
        scales: ErrorScales,
    ) -> Result<Self, ModelError> {
        tolerances.validate()?;
        if scales.len() != n || 2 * n_q > n {
            return Err(ModelError::Numerical(format!(
                "ESDIRK: {n} states, {n_q} coordinates and {} scales do not fit",
                scales.len()
            )));
        }
        Ok(Self {
            tolerances,
            scales,
            n_q,
            state: EsdirkState {
                h: 0.0,
                h_factored: 0.0,
                jacobian_q: vec![0.0; n_q * n_q],
                jacobian_v: vec![0.0; n_q * n_q],
                jacobian_stale: true,
                newton_rate: 1.0,
                history: Vec::new(),
                history_step: 0.0,
                derivative: Vec::new(),
                stats: Stats::default(),
            },
            jacobian_fresh: false,
            step_rate: 0.0,
            lu: Lu::new(n_q),
            table,
            k: vec![vec![0.0; n]; table.stages],
            base: vec![0.0; n],
            stage: vec![0.0; n],
            rates: vec![0.0; n],
            update: vec![0.0; n_q],
            y_new: vec![0.0; n],
            err: vec![0.0; n],
        })
    }

    /// Statistics since construction.
    pub fn stats(&self) -> Stats {
        self.state.stats
    }

    /// The state later steps depend on.
    pub fn state(&self) -> &EsdirkState {
        &self.state
    }

    /// Restores a state taken from an integrator of the same dimensions.
    pub fn set_state(&mut self, state: &EsdirkState) -> Result<(), ModelError> {
        let n2 = self.n_q * self.n_q;
        let history_ok = (state.history.is_empty() || state.history.len() == 2 * self.n_q)
            && (state.derivative.is_empty() || state.derivative.len() == self.k[0].len());
        if state.jacobian_q.len() != n2 || state.jacobian_v.len() != n2 || !history_ok {
            return Err(ModelError::Numerical(format!(
                "ESDIRK state has a {}-entry Jacobian, this integrator {n2}",
                state.jacobian_q.len()
            )));
        }
        self.state = state.clone();
        self.jacobian_fresh = false;
        // The factorisation is a function of (Jacobian, h_factored): rebuild it.
        if self.state.h_factored > 0.0 && self.factorize(self.state.h_factored).is_err() {
            self.state.h_factored = 0.0;
        }
        Ok(())
    }

    /// Forgets f at the current point and the step history after the state was changed from
    /// outside (an impulsive velocity change): the next stages are predicted from the current
    /// point only.
    pub fn restart(&mut self) {
        self.state.derivative.clear();
        self.state.history.clear();
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
        self.jacobian(f, t, y);
        self.factorize(h)
    }

    /// f at the start and at the end of the last accepted step.
    pub fn derivatives(&self) -> (&[f64], &[f64]) {
        (&self.k[self.table.stages - 1], &self.k[0])
    }

    /// Takes one accepted step from (`*t`, `y`), retrying rejected ones; with a `limit` the step
    /// ends there at the latest (exactly, when the proposal reaches it or nearly does). On
    /// failure `*t` and `y` hold the last accepted point.
    pub fn step<F: MechanicalSystem>(
        &mut self,
        f: &mut F,
        t: &mut f64,
        y: &mut [f64],
        limit: Option<f64>,
    ) -> Result<(), ModelError> {
        if self.state.derivative.is_empty() {
            f.rhs(*t, y, &mut self.k[0]);
            self.state.stats.evaluations += 1;
        } else {
            self.k[0].copy_from_slice(&self.state.derivative);
        }
        let Tolerances {
            max_step, min_step, ..
        } = self.tolerances;
        if self.state.h <= 0.0 {
            let (k0, rest) = self.k.split_at_mut(1);
            self.state.h = initial_step(
                f,
                *t,
                y,
                &k0[0],
                limit.unwrap_or(*t + max_step),
                &self.tolerances,
                &self.scales,
                self.table.embedded_order + 1,
                &mut self.stage,
                &mut rest[0],
            );
            self.state.stats.evaluations += 1;
        }
        let mut rejected_last = false;
        loop {
            if self.state.jacobian_stale {
                self.jacobian(f, *t, y);
            }
            let proposal = self.state.h.min(max_step);
            let last = limit.is_some_and(|end| 1.01 * proposal >= end - *t);
            let (h, t_new) = match limit {
                Some(end) if last => (end - *t, end),
                _ => (proposal, *t + proposal),
            };
            match self.try_step(f, *t, y, h, true) {
                Err(failure) => {
                    self.state.stats.rejected += 1;
                    rejected_last = true;
                    if self.jacobian_fresh || matches!(failure, Failure::Singular) {
                        self.state.h = 0.25 * h;
                    } else {
                        self.state.jacobian_stale = true;
                        self.state.h = h;
                    }
                }
                Ok(err) if err > 1.0 => {
                    self.state.stats.rejected += 1;
                    rejected_last = true;
                    self.state.h = h
                        * (0.9 * err.powf(-1.0 / f64::from(self.table.embedded_order + 1)))
                            .clamp(0.2, 1.0);
                }
                Ok(err) => {
                    if let Some(factor) = f.check_step(*t, y, t_new, &self.y_new) {
                        self.state.stats.rejected += 1;
                        rejected_last = true;
                        self.state.h = h * factor.clamp(1e-3, 0.99);
                    } else {
                        self.accept(f, t, y, t_new, h, err, last, rejected_last);
                        return Ok(());
                    }
                }
            }
            if self.state.h < min_step {
                return Err(ModelError::Numerical(format!(
                    "step size {:.3e} s fell below the minimum {min_step:.3e} s at t = {} s \
                     (implicit integrator)",
                    self.state.h, *t
                )));
            }
        }
    }

    /// The state at t₀ + Δt inside the last accepted step (t₀, y₀) → (t₁, y₁), written to
    /// `out`: one step of the method itself from y₀ (`f0` = f(t₀, y₀)), without error control.
    ///
    /// This is the implicit method's dense output. A polynomial through the step's ends would
    /// amplify the unresolved stiff components (their accelerations are ω² times their
    /// amplitudes, ωh ≫ 1 once the step has grown past them); the method's own step damps them
    /// as the step itself did. It leaves the step sequence untouched (Newton memory, history,
    /// statistics other than evaluations); the Newton matrix is refactorised for the next step.
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
                }
                Err(_) if pieces < 8 && done == 0 => pieces *= 2,
                Err(_) => {
                    break Err(ModelError::Numerical(format!(
                        "dense output at t = {} s: Newton did not converge",
                        t0 + dt
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

    /// Accepts the step just computed: hooks, state, FSAL, next step size, Jacobian policy.
    #[allow(clippy::too_many_arguments)]
    fn accept<F: MechanicalSystem>(
        &mut self,
        f: &mut F,
        t: &mut f64,
        y: &mut [f64],
        t_new: f64,
        h: f64,
        err: f64,
        last: bool,
        rejected_last: bool,
    ) {
        self.state.stats.steps += 1;
        let n_q = self.n_q;
        self.state.history.resize(2 * n_q, 0.0);
        self.state.history[..n_q].copy_from_slice(&y[n_q..2 * n_q]);
        self.state.history[n_q..].copy_from_slice(&self.k[0][n_q..2 * n_q]);
        self.state.history_step = h;
        f.accept_step(*t, y, t_new, &self.y_new);
        *t = t_new;
        y.copy_from_slice(&self.y_new);
        self.k.swap(0, self.table.stages - 1);
        self.state.derivative.clone_from(&self.k[0]);
        self.jacobian_fresh = false;
        if self.step_rate > REUSE_RATE {
            self.state.jacobian_stale = true;
        }
        let mut factor = (0.9
            * err
                .max(1e-10)
                .powf(-1.0 / f64::from(self.table.embedded_order + 1)))
        .clamp(0.2, 5.0);
        if rejected_last {
            factor = factor.min(1.0);
        }
        // Keep h (and the factorisation) for small increases, as RADAU5 does.
        if (1.0..=1.2).contains(&factor) && !self.state.jacobian_stale {
            factor = 1.0;
        }
        // Keep the unclamped proposal when the last step was shortened to hit t_end.
        if !last || h >= self.state.h {
            self.state.h = h * factor;
        }
    }

    /// ∂q̈/∂(q, q̇) at (t, y) by forward differences from f(t, y), evaluated afresh (the
    /// first-same-as-last stage derivative satisfies the stage equation only to the Newton
    /// tolerance, too coarse a base for differences).
    fn jacobian<F: MechanicalSystem>(&mut self, f: &mut F, t: f64, y: &[f64]) {
        let n_q = self.n_q;
        f.rhs(t, y, &mut self.base);
        self.stage.copy_from_slice(y);
        for (j, (&y_j, &scale)) in y
            .iter()
            .zip(&self.scales.absolute)
            .take(2 * n_q)
            .enumerate()
        {
            let delta = f64::EPSILON.sqrt() * y_j.abs().max(scale);
            self.stage[j] = y_j + delta;
            f.rhs(t, &self.stage, &mut self.rates);
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
        }
        self.state.stats.evaluations += 2 * n_q as u64 + 1;
        self.state.stats.jacobians += 1;
        self.state.jacobian_stale = false;
        self.state.h_factored = 0.0;
        self.jacobian_fresh = true;
    }

    /// Factorises E = I − hγ ∂a/∂q̇ − (hγ)² ∂a/∂q (not counted: restoring a state refactorises).
    fn factorize(&mut self, h: f64) -> Result<(), ModelError> {
        let hg = h * self.table.gamma;
        let n = self.n_q;
        let (jv, jq) = (&self.state.jacobian_v, &self.state.jacobian_q);
        for (j, column) in self.lu.matrix_mut().chunks_exact_mut(n).enumerate() {
            for (i, e) in column.iter_mut().enumerate() {
                let identity = if i == j { 1.0 } else { 0.0 };
                let k = j * n + i;
                *e = identity - hg * jv[k] - hg * hg * jq[k];
            }
        }
        self.state.h_factored = h;
        self.lu.factorize()
    }

    /// One trial step of size h from (t, y): the candidate goes to `y_new`; returns the scaled
    /// error norm.
    fn try_step<F: MechanicalSystem>(
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
        let (n, n_q) = (y.len(), self.n_q);
        let hg = h * self.table.gamma;
        let Tolerances {
            relative, absolute, ..
        } = self.tolerances;
        let Tableau {
            stages,
            a,
            b,
            b_hat,
            c,
            ..
        } = *self.table;
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
            let (done, todo) = self.k.split_at_mut(i);
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
                    let (s2, s3) = (s * s, s * s * s);
                    let (h00, h10) = (2.0 * s3 - 3.0 * s2 + 1.0, s3 - 2.0 * s2 + s);
                    let (h01, h11) = (-2.0 * s3 + 3.0 * s2, s3 - s2);
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
            let mut previous_norm = f64::INFINITY;
            let mut rate = self.state.newton_rate.max(f64::EPSILON).powf(0.8);
            let mut converged = false;
            for iteration in 0..MAX_ITERATIONS {
                for m in 0..n_q {
                    self.stage[m] = self.base[m] + hg * self.stage[n_q + m];
                }
                for m in 2 * n_q..n {
                    self.stage[m] = self.base[m] + hg * self.rates[m];
                }
                f.rhs(t + c[i] * h, &self.stage, &mut self.rates);
                self.state.stats.evaluations += 1;
                self.state.stats.newton_iterations += 1;
                for m in 0..n_q {
                    self.update[m] =
                        self.base[n_q + m] + hg * self.rates[n_q + m] - self.stage[n_q + m];
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
                    sum += (dv / sc_v).powi(2) + (hg * dv / sc_q).powi(2);
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
                    converged = true;
                    break;
                }
                previous_norm = norm;
            }
            if !converged {
                return Err(Failure::Newton);
            }
            self.state.newton_rate = rate;
            let k = &mut todo[0];
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
        Ok(scaled_norm(
            &self.err,
            y,
            &self.y_new,
            &self.scales,
            &self.tolerances,
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrator::OdeSystem;

    /// Damped oscillator q̈ = −ω² q − c q̇ with a work integral w' = −c q̇².
    struct Oscillator {
        omega: f64,
        damping: f64,
    }

    impl OdeSystem for Oscillator {
        fn rhs(&mut self, _t: f64, y: &[f64], dy: &mut [f64]) {
            dy[0] = y[1];
            dy[1] = -self.omega * self.omega * y[0] - self.damping * y[1];
            dy[2] = -self.damping * y[1] * y[1];
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

    /// Harmonic oscillator over 10 periods: the global error follows the tolerance, and the energy
    /// integral closes.
    #[test]
    fn oscillator_error_follows_tolerance() {
        let omega = 3.0;
        let t_end = 10.0 * std::f64::consts::TAU / omega;
        let mut errors = Vec::new();
        for rtol in [1e-6, 1e-9] {
            let mut f = Oscillator {
                omega,
                damping: 0.0,
            };
            let mut es =
                Esdirk::new(&ESDIRK54, 3, 1, tolerances(rtol), ErrorScales::uniform(3)).unwrap();
            let (mut t, mut y) = (0.0, [1.0, 0.0, 0.0]);
            while t < t_end {
                es.step(&mut f, &mut t, &mut y, Some(t_end)).unwrap();
            }
            let err = ((y[0] - (omega * t).cos()).powi(2)
                + (y[1] / omega + (omega * t).sin()).powi(2))
            .sqrt();
            errors.push(err);
        }
        assert!(errors[0] < 1e-4 && errors[1] < 1e-7, "{errors:?}");
        assert!(errors[0] / errors[1] > 100.0, "{errors:?}");
    }

    /// The published coefficients satisfy every order condition: the 17 of order ≤ 5 for b and
    /// the 8 of order ≤ 4 for b̂ (rooted trees, Butcher), to round-off of 13-digit rationals.
    #[test]
    fn tableau_satisfies_the_order_conditions() {
        const S: usize = 7;
        let t = &ESDIRK54;
        assert_eq!(t.stages, S);
        let (a, b, b_hat) = (t.a, t.b, t.b_hat);
        let dot = |u: &[f64; S], v: &[f64; S]| (0..S).map(|i| u[i] * v[i]).sum::<f64>();
        let mul = |u: &[f64; S], v: &[f64; S]| -> [f64; S] { std::array::from_fn(|i| u[i] * v[i]) };
        let apply = |v: &[f64; S]| -> [f64; S] {
            std::array::from_fn(|i| (0..S).map(|j| a[i][j] * v[j]).sum())
        };
        let one = [1.0; S];
        let c = apply(&one);
        for (i, (sum, node)) in c.iter().zip(&t.c).enumerate() {
            assert!((sum - node).abs() < 1e-15, "row sum {i}");
        }
        let c2 = mul(&c, &c);
        let c3 = mul(&c2, &c);
        let ac = apply(&c);
        let ac2 = apply(&c2);
        let aac = apply(&ac);
        // (tree value, 1/γ(t)) for all rooted trees up to order 4.
        let order4 = |w: &[f64; S]| {
            [
                (dot(w, &one), 1.0),
                (dot(w, &c), 1.0 / 2.0),
                (dot(w, &c2), 1.0 / 3.0),
                (dot(w, &ac), 1.0 / 6.0),
                (dot(w, &c3), 1.0 / 4.0),
                (dot(w, &mul(&c, &ac)), 1.0 / 8.0),
                (dot(w, &ac2), 1.0 / 12.0),
                (dot(w, &aac), 1.0 / 24.0),
            ]
        };
        for (value, expected) in order4(&b).into_iter().chain(order4(&b_hat)) {
            assert!((value - expected).abs() < 1e-12, "{value} vs {expected}");
        }
        let order5 = [
            (dot(&b, &mul(&c3, &c)), 1.0 / 5.0),
            (dot(&b, &mul(&c2, &ac)), 1.0 / 10.0),
            (dot(&b, &mul(&c, &ac2)), 1.0 / 15.0),
            (dot(&b, &mul(&c, &aac)), 1.0 / 30.0),
            (dot(&b, &mul(&ac, &ac)), 1.0 / 20.0),
            (dot(&b, &apply(&c3)), 1.0 / 20.0),
            (dot(&b, &apply(&mul(&c, &ac))), 1.0 / 40.0),
            (dot(&b, &apply(&ac2)), 1.0 / 60.0),
            (dot(&b, &apply(&aac)), 1.0 / 120.0),
        ];
        for (value, expected) in order5 {
            assert!((value - expected).abs() < 1e-12, "{value} vs {expected}");
        }
        // Stiffly accurate (last row = b, hence R(∞) = 0 with γ on the diagonal), and an embedded
        // solution that differs.
        assert_eq!(a[S - 1], b);
        assert!((1..S).all(|i| a[i][i] == t.gamma));
        assert!(b_hat.iter().zip(&b).any(|(x, y)| x != y));
    }
}
