//! Planar ANCF beam: the gradient-deficient two-node Euler–Bernoulli element and the rod built from it.
//!
//! Each node carries 4 absolute coordinates, its position r and slope r_x = ∂r/∂x, so an element has
//! e = [r₁, r₁,ₓ, r₂, r₂,ₓ] ∈ ℝ⁸ and the rod with n elements has 4(n + 1) coordinates, node by node.
//! The mass matrix is constant; the elastic force is the only nonlinear term (docs/model.md §1).
//!
//! # References
//! - J. Gerstmayr, H. Irschik (2008), On the correct representation of bending in the absolute nodal
//!   coordinate formulation, J. Sound Vib. 318, 461–487.
//! - A. A. Shabana (2005), Dynamics of Multibody Systems, 3rd ed., ch. 7.
//! - Exudyn, `CObjectANCFCable2D` (shape functions, strain measures, Gauss orders).

pub mod element;
pub mod quarters;
pub mod rod;
pub mod shape;

pub use element::{Element, Section};
pub use rod::equilibrium::RodLoad;
pub use rod::sections::{SectionResult, section_place};
pub use rod::{NormalStresses, Rod, RodProperties};
