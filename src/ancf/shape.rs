//! Cubic Hermite shape functions of the planar ANCF element and their derivatives.
//!
//! ```text
//! r(x) = S(x) e,  S = [S₁ I₂, S₂ I₂, S₃ I₂, S₄ I₂],  ξ = x/l
//! S₁ = 1 − 3ξ² + 2ξ³   S₂ = l(ξ − 2ξ² + ξ³)   S₃ = 3ξ² − 2ξ³   S₄ = l(ξ³ − ξ²)
//! ```
//! S₁ + S₃ = 1 and S₂ + S₄ + l S₃ = x, so every linear field p + x t is represented exactly.
//!
//! # References
//! - docs/model.md §1.1; Exudyn `CObjectANCFCable2D::ComputeShapeFunctions`.

use nalgebra::Vector4;

/// Shape functions S₁…S₄ at ξ = x/l ∈ [0, 1] for an element of length `l`.
pub fn shape(xi: f64, l: f64) -> Vector4<f64> {
    let (xi2, xi3) = (xi * xi, xi * xi * xi);
    Vector4::new(
        1.0 - 3.0 * xi2 + 2.0 * xi3,
        l * (xi - 2.0 * xi2 + xi3),
        3.0 * xi2 - 2.0 * xi3,
        l * (xi3 - xi2),
    )
}

/// First derivatives ∂Sₖ/∂x at ξ = x/l.
pub fn shape_x(xi: f64, l: f64) -> Vector4<f64> {
    let xi2 = xi * xi;
    Vector4::new(
        (6.0 * xi2 - 6.0 * xi) / l,
        1.0 - 4.0 * xi + 3.0 * xi2,
        (6.0 * xi - 6.0 * xi2) / l,
        3.0 * xi2 - 2.0 * xi,
    )
}

/// Second derivatives ∂²Sₖ/∂x² at ξ = x/l.
pub fn shape_xx(xi: f64, l: f64) -> Vector4<f64> {
    Vector4::new(
        (12.0 * xi - 6.0) / (l * l),
        (6.0 * xi - 4.0) / l,
        (6.0 - 12.0 * xi) / (l * l),
        (6.0 * xi - 2.0) / l,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Partition of unity and exact representation of x, at many points (round-off only).
    #[test]
    fn partition_of_unity_and_linear_fields() {
        let l = 0.37;
        for i in 0..=20 {
            let xi = f64::from(i) / 20.0;
            let s = shape(xi, l);
            assert!((s[0] + s[2] - 1.0).abs() < 1e-15);
            assert!((s[1] + s[3] + l * s[2] - xi * l).abs() < 1e-15);
            let sx = shape_x(xi, l);
            assert!((sx[0] + sx[2]).abs() < 1e-13);
            assert!((sx[1] + sx[3] + l * sx[2] - 1.0).abs() < 1e-13);
        }
    }

    /// Derivatives equal central differences of the functions (step 1e-6: truncation ~1e-12).
    #[test]
    fn derivatives_match_central_differences() {
        let l = 0.8;
        let h = 1e-6;
        for i in 1..10 {
            let xi = f64::from(i) / 10.0;
            let fd = (shape(xi + h / l, l) - shape(xi - h / l, l)) / (2.0 * h);
            assert!((fd - shape_x(xi, l)).norm() < 1e-8);
            let fd2 = (shape_x(xi + h / l, l) - shape_x(xi - h / l, l)) / (2.0 * h);
            assert!((fd2 - shape_xx(xi, l)).norm() < 1e-7);
        }
    }

    /// Hermite interpolation conditions at the nodes.
    #[test]
    fn nodal_values() {
        let l = 2.0;
        assert_eq!(shape(0.0, l), Vector4::new(1.0, 0.0, 0.0, 0.0));
        assert_eq!(shape(1.0, l), Vector4::new(0.0, 0.0, 1.0, 0.0));
        assert_eq!(shape_x(0.0, l), Vector4::new(0.0, 1.0, 0.0, 0.0));
        assert_eq!(shape_x(1.0, l), Vector4::new(0.0, 0.0, 0.0, 1.0));
    }
}
