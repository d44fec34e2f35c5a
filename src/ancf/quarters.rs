//! An element's shape functions integrated over pieces of it, for the rod's section resultants
//! from the equilibrium of its parts ([`crate::ancf::rod::equilibrium`]).

use nalgebra::Vector4;

use crate::ancf::shape::{shape, shape_x};
use crate::quadrature::GAUSS_4;

/// The integrals of an element's shape functions over a piece of it ([`crate::ancf::rod::equilibrium`]).
#[derive(Clone, Copy, Debug)]
pub struct Piece {
    pub(crate) length: f64,
    pub(crate) single: [f64; 4],
    /// J_mn at 4m + n.
    pub(crate) double: [f64; 16],
}

impl Piece {
    /// The piece from `from` to `to` of an element of length `l`.
    pub fn new(l: f64, from: f64, to: f64) -> Self {
        let length = (to - from).max(0.0);
        let mut piece = Self {
            length,
            single: [0.0; 4],
            double: [0.0; 16],
        };
        for (node, weight) in GAUSS_4.on_unit_interval(length) {
            let s = shape((from + node * length) / l, l);
            for m in 0..4 {
                piece.single[m] += weight * s[m];
                for n in 0..4 {
                    piece.double[4 * m + n] += weight * s[m] * s[n];
                }
            }
        }
        piece
    }
}

/// An element's quarter pieces, and its shape functions and their slopes at the quarter points
/// (ξ = 0, 1/4, …, 1): what the stress scan reads, the same for every element of a rod.
#[derive(Clone, Copy, Debug)]
pub struct Quarters {
    pub(crate) pieces: [Piece; 4],
    pub(crate) shape: [Vector4<f64>; 5],
    pub(crate) slope: [Vector4<f64>; 5],
}

impl Quarters {
    /// The quarters of an element of length `l`.
    pub fn new(l: f64) -> Self {
        let xi = |k: usize| k as f64 / 4.0;
        Self {
            pieces: std::array::from_fn(|k| Piece::new(l, xi(k) * l, xi(k + 1) * l)),
            shape: std::array::from_fn(|k| shape(xi(k), l)),
            slope: std::array::from_fn(|k| shape_x(xi(k), l)),
        }
    }
}
