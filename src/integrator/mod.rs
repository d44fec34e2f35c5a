//! Error-controlled time integration of the mechanism, y' = f(t, y).
//!
//! Three methods ([`Method`]):
//! - [`DormandPrince`]: the explicit embedded Runge–Kutta pair of Dormand and Prince, order 5 with a
//!   4th-order error estimate (the reference method). Its step is bounded by the highest frequency
//!   of the model, resolved or not.
//! - [`Implicit`] with [`ESDIRK54`]: an L-stable, stiffly accurate ESDIRK5(4) with simplified Newton
//!   on the mechanism's n coordinates. Its step is set by the accuracy of the motion, not by the
//!   stiffness of the rod or of the oil film.
//! - [`Implicit`] with [`GeneralizedAlpha`]: the second-order generalized-α method with the
//!   numerical dissipation as a parameter (spectral radius at infinity ρ∞, 1: none), as in
//!   structural and multibody codes; the same Newton iteration, one implicit stage per step.
//!
//! All run one step-control loop (`step_loop`: propose, try, accept or retry, the step sizes from
//! one controller) and measure the local error in one weighted norm: component i is compared with
//! `absolute · sᵢ + relative · rᵢ |yᵢ|` ([`ErrorScales`]), where the scales sᵢ carry each state's
//! units (positions, slopes, modal amplitudes, velocities and energies differ by orders of
//! magnitude) and rᵢ says whether a relative tolerance means anything for it (not for positions,
//! whose size depends on the origin); the mechanism provides them,
//! [`crate::mechanism::SliderCrank::error_scales`]. The implicit methods also hold single
//! quantities to the tolerance on their own, in max-norm ([`MechanicalSystem::held_errors`]: the dry
//! journal's normal velocity, which decides every impact).
//!
//! The default is the implicit method, chosen by measurement (BENCHMARKS.md, "Integrators"): over
//! two revolutions of benchmark B/C at the default tolerance it is faster than the explicit method
//! at its loosest accepted tolerance on every flexible rod, with every joint model (2.8–18× with
//! the ideal and lubricated joints, 1.2–2.2× with the dry one, whose held journal velocity resolves
//! the rod end's vibration; 4-mode rod, dry joint: 5 021 steps against 13 049; full rod,
//! lubricated: 359 against 150 148), with peak joint forces within 0.7 % of converged runs. The
//! explicit method stays the reference (conservation tests) and is cheaper only for the rigid rod,
//! where nothing is stiff. The generalized-α method is faster on the reduced rods with the dry
//! joint, with peak forces within 1 %, but filters part of the rod's vibration (slider-acceleration
//! RMS error 14 % against 3.5 % over the first 40° of benchmark B): it is offered for its
//! dissipation parameter, not as the default.
//!
//! # References
//! - J. R. Dormand, P. J. Prince (1980), A family of embedded Runge–Kutta formulae, J. Comput. Appl.
//!   Math. 6, 19–26.
//! - E. Hairer, S. P. Nørsett, G. Wanner (1993), Solving Ordinary Differential Equations I, 2nd ed.,
//!   §II.4 (step-size control, initial step) and §II.5 (DOPRI5).
//! - C. A. Kennedy, M. H. Carpenter (2016), Diagonally implicit Runge–Kutta methods for ordinary
//!   differential equations. A review, NASA/TM–2016–219173.
//! - E. Hairer, G. Wanner (1996), Solving Ordinary Differential Equations II, 2nd ed., §IV.8.

mod control;
pub mod dense;
mod dormand_prince;
mod esdirk;
mod generalized_alpha;
mod implicit;
mod step_loop;
mod system;

pub use control::{ErrorScales, Stats, Tolerances};

pub use dormand_prince::DormandPrince;
pub use esdirk::{ESDIRK54, Tableau};
pub use generalized_alpha::GeneralizedAlpha;
pub use implicit::{Implicit, ImplicitState, Scheme};
pub use system::{MechanicalSystem, OdeSystem};

use crate::error::ModelError;

/// The time-integration method.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Explicit Dormand–Prince 5(4) (the reference method).
    DormandPrince,
    /// L-stable implicit ESDIRK5(4)7L\[2\]SA₂ with simplified Newton.
    Esdirk,
    /// Implicit generalized-α with the spectral radius at infinity ρ∞ as a parameter.
    GeneralizedAlpha,
}

/// Integrator state that later steps depend on (for bit-exact snapshots).
#[derive(Clone, Debug, PartialEq)]
pub enum IntegratorState {
    /// Dormand–Prince: proposed next step, f at the current point and statistics.
    DormandPrince {
        /// Proposed next step \[s\].
        h: f64,
        /// f at the current point (empty: to be evaluated).
        derivative: Vec<f64>,
        /// Statistics.
        stats: Stats,
    },
    /// Implicit methods: step, Jacobian, Newton memory, algorithmic accelerations and statistics.
    Implicit(ImplicitState),
}

/// One of the [`Method`]s with its workspace.
#[derive(Clone, Debug)]
pub enum Integrator {
    /// Explicit Dormand–Prince.
    DormandPrince(Box<DormandPrince>),
    /// An implicit method.
    Implicit(Box<Implicit>),
}

impl Integrator {
    /// An integrator for `n` states of a system with `n_q` coordinates and per-component scales;
    /// `spectral_radius` is ρ∞ of the generalized-α method (unused by the others).
    pub fn new(
        method: Method,
        spectral_radius: f64,
        n: usize,
        n_q: usize,
        tolerances: Tolerances,
        scales: ErrorScales,
    ) -> Result<Self, ModelError> {
        let scheme = match method {
            Method::DormandPrince => {
                return Ok(Self::DormandPrince(Box::new(
                    DormandPrince::new(n, tolerances)?.with_scales(scales)?,
                )));
            }
            Method::Esdirk => Scheme::Esdirk(&ESDIRK54),
            Method::GeneralizedAlpha => {
                Scheme::GeneralizedAlpha(GeneralizedAlpha::new(spectral_radius)?)
            }
        };
        Ok(Self::Implicit(Box::new(Implicit::new(
            scheme, n, n_q, tolerances, scales,
        )?)))
    }

    /// Takes one accepted step from (`*t`, `y`), ending at `limit` at the latest, in at most
    /// `max_attempts` trial steps (accepted or rejected); returns `false` when they ran out
    /// first. On failure or `false`, `*t`, `y` hold the last accepted point.
    pub fn step<F: MechanicalSystem>(
        &mut self,
        f: &mut F,
        t: &mut f64,
        y: &mut [f64],
        limit: Option<f64>,
        max_attempts: u64,
    ) -> Result<bool, ModelError> {
        match self {
            Self::DormandPrince(dp) => dp.step(f, t, y, limit, max_attempts),
            Self::Implicit(es) => es.step(f, t, y, limit, max_attempts),
        }
    }

    /// f at the start and at the end of the last accepted step.
    pub fn derivatives(&self) -> (&[f64], &[f64]) {
        match self {
            Self::DormandPrince(dp) => dp.derivatives(),
            Self::Implicit(es) => es.derivatives(),
        }
    }

    /// Dense output: the state at t₀ + s·h inside the accepted step `span`, written to `out`. The
    /// explicit method, whose steps resolve every frequency, uses the quintic Hermite
    /// interpolant ([`dense::interpolate`]); the implicit ones the same interpolant with its part
    /// beyond the cubic filtered by their Newton matrix ([`Implicit::dense_output`]), which keeps
    /// it from amplifying what the step left unresolved.
    pub fn dense_output<F: MechanicalSystem>(
        &mut self,
        f: &mut F,
        span: &dense::Span<'_>,
        s: f64,
        out: &mut [f64],
    ) -> Result<(), ModelError> {
        match self {
            Self::DormandPrince(_) => {
                dense::interpolate(f.n_coordinates(), span, s, out);
                Ok(())
            }
            Self::Implicit(es) => es.dense_output(f, span, s, out),
        }
    }

    /// The integrator's own solution at t₀ + s·h inside the accepted step `span`, written to
    /// `out`: the explicit method's [`Self::dense_output`]; for the implicit one, a step of its
    /// own from y₀ ([`Implicit::state_within`]), which costs a step, or the quintic Hermite
    /// interpolant if its Newton iteration fails (the failed step leaves no factorisation to
    /// filter it with).
    pub fn state_within<F: MechanicalSystem>(
        &mut self,
        f: &mut F,
        span: &dense::Span<'_>,
        s: f64,
        out: &mut [f64],
    ) -> Result<(), ModelError> {
        if let Self::Implicit(es) = self
            && es
                .state_within(f, span.t0, span.y0, span.f0, s * span.h, out)
                .is_ok()
        {
            return Ok(());
        }
        dense::interpolate(f.n_coordinates(), span, s, out);
        Ok(())
    }

    /// Forgets what depends on the current point (f there, step history) after the state was
    /// changed from outside.
    pub fn restart(&mut self) {
        match self {
            Self::DormandPrince(dp) => dp.restart(),
            Self::Implicit(es) => es.restart(),
        }
    }

    /// Statistics since construction.
    pub fn stats(&self) -> Stats {
        match self {
            Self::DormandPrince(dp) => dp.stats(),
            Self::Implicit(es) => es.stats(),
        }
    }

    /// The step size the next step will try \[s\].
    pub fn step_size(&self) -> f64 {
        match self {
            Self::DormandPrince(dp) => dp.step_size(),
            Self::Implicit(es) => es.state().h,
        }
    }

    /// The state later steps depend on.
    pub fn state(&self) -> IntegratorState {
        match self {
            Self::DormandPrince(dp) => {
                let (h, derivative, stats) = dp.state();
                IntegratorState::DormandPrince {
                    h,
                    derivative,
                    stats,
                }
            }
            Self::Implicit(es) => IntegratorState::Implicit(es.state().clone()),
        }
    }

    /// Restores a state taken from an integrator of the same method and dimensions.
    pub fn set_state(&mut self, state: &IntegratorState) -> Result<(), ModelError> {
        match (self, state) {
            (
                Self::DormandPrince(dp),
                IntegratorState::DormandPrince {
                    h,
                    derivative,
                    stats,
                },
            ) => dp.set_state(*h, derivative, *stats),
            (Self::Implicit(es), IntegratorState::Implicit(s)) => es.set_state(s),
            _ => Err(ModelError::Numerical(
                "snapshot of another integration method".into(),
            )),
        }
    }
}
