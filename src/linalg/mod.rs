//! Small dense linear algebra of the hot path, written by hand where a measurement showed a
//! generic library call costing more in dispatch than the arithmetic (BENCHMARKS.md): the
//! integrator's Newton matrices ([`lu`]), the rod's constant mass matrix ([`band_cholesky`]) and
//! the mechanism's constraint system of at most six rows ([`small`]). Every routine works in
//! preallocated or stack storage and allocates nothing per call. Larger, one-off problems (the
//! Craig–Bampton eigenproblem) use `faer`, and so does the one-off sparse non-negative least
//! squares that picks the sampled rod's quadrature points ([`nnls`]).

pub mod band_cholesky;
pub mod lu;
pub mod nnls;
pub mod small;
