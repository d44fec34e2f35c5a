//! The slider-crank mechanism: crank (angle θ), connecting rod (rigid, ANCF or Craig–Bampton), and
//! slider (abscissa x_s) on a frictionless guide through the crank pivot.
//!
//! Equations of motion in index-1 form with Baumgarte stabilisation (Sun et al. 2015 eq. 1):
//! ```text
//! M q̈ = Q(q, q̇, t) − Φ_qᵀ λ,     Φ_q q̈ = γ − 2α Φ̇ − β² Φ,     q = [θ, p, x_s]
//! M = diag(I_O, M_rod, m_s)  constant      (I_O: crank inertia about the pivot)
//! ```
//! Φ_q touches only s = [θ, r_A, r_B, x_s], so with G = M⁻¹E_s (constant, E_s selects s) and
//! W = E_sᵀ M⁻¹ E_s (6 × 6, constant): λ = (C W Cᵀ)⁻¹ (C a₀ − rhs), q̈ = a₀ − G Cᵀ λ, a₀ = M⁻¹Q. One
//! solve with the rod's stored Cholesky factor and a ≤ 6 × 6 Cholesky per evaluation, no allocation.
//!
//! State vector y = [q, q̇, θ_d, W_drive, W_joint, W_external, D_material]: the drive angle (speed
//! drive), the work of the drive, of the joint forces and of the external slider force, and the
//! energy dissipated by the rod's material damping, integrated with the motion (with the same
//! error control) so that the energy balance converges with the integrator tolerance. D_material
//! is present only for a rod with material damping: an identically zero component would change
//! the RMS error norm, and with it every undamped result.
//!
//! # References
//! - Sun et al. (2015), Mech. Mach. Theory 85, eqs. (1)–(3).
//! - P. Flores et al. (2008), Kinematics and Dynamics of Multibody Systems with Imperfect Joints.
//! - docs/model.md §0, §3–§8.

pub mod constraints;
mod energy;
mod error_scales;
mod events;
mod inputs;
mod joints;
pub mod layout;
mod loads;
mod parts;
pub mod rod_body;
mod scales;
mod schur;
mod slider_crank;
mod start;

pub use crate::joint::{ContactState, Contacts};
pub use energy::{Energies, JointEnergy};
pub use events::{CONTACT_ONSET_PENETRATION, Driven};
pub use inputs::{Conditions, Input, InputSignal, Inputs, SUPPLY_PRESSURE, SUPPLY_TEMPERATURE};
pub use layout::StateLayout;
pub use loads::{Loads, RigidRodResultants, rigid_rod_stress};
pub use slider_crank::{Evaluation, SliderCrank};
pub use start::Reaction;
