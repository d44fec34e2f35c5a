//! Elementary functions that give the same bits on every platform.
//!
//! `f64::sin`, `cos`, `powf`, `ln`, `exp`, `atan2` and `hypot` call the C library of the target (glibc on Linux,
//! mingw-w64's CRT on Windows, libSystem on macOS). Their results are faithful but not correctly
//! rounded, and they differ between those libraries in the last bit. With impacts such
//! differences grow without bound: the same FMU run on Windows and Linux would part at the first
//! contact. The model therefore takes these functions from the pure-Rust `libm` crate (a port of
//! musl's), compiled into the FMU, so that every platform computes the same numbers and an FMU
//! state saved on one platform continues bit for bit on another. `sqrt` and the arithmetic
//! operators are correctly rounded by IEEE 754 and need no replacement; `clippy.toml` disallows
//! the platform versions.

/// Whether `a` and `b` hold the same numbers, bit for bit (a zero's sign and a NaN's payload
/// included): what a memo compares its arguments by, where `==` would hold −0 and +0 equal and a
/// NaN unequal to itself. Inlined: memos are on the hot path, and a call there measured 2 % of the
/// undamped rod's run.
#[inline(always)]
pub fn same_bits(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
}

/// sin x.
#[inline]
pub fn sin(x: f64) -> f64 {
    libm::sin(x)
}

/// cos x.
#[inline]
pub fn cos(x: f64) -> f64 {
    libm::cos(x)
}

/// (sin x, cos x).
#[inline]
pub fn sin_cos(x: f64) -> (f64, f64) {
    libm::sincos(x)
}

/// xʸ.
#[inline]
pub fn powf(x: f64, y: f64) -> f64 {
    libm::pow(x, y)
}

/// The natural logarithm ln x.
#[inline]
pub fn ln(x: f64) -> f64 {
    libm::log(x)
}

/// The exponential eˣ.
#[inline]
pub fn exp(x: f64) -> f64 {
    libm::exp(x)
}

/// The angle of the point (x, y) from the x axis, in (−π, π].
#[inline]
pub fn atan2(y: f64, x: f64) -> f64 {
    libm::atan2(y, x)
}

/// √(x² + y²) without undue overflow or underflow.
#[inline]
pub fn hypot(x: f64, y: f64) -> f64 {
    libm::hypot(x, y)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The portable functions agree with the platform's to within a few units in the last place
    /// (they differ from one C library to another only there).
    #[test]
    fn agree_with_the_platform_library() {
        #[allow(clippy::disallowed_methods)]
        for k in 0..1000 {
            let x = -50.0 + 0.1037 * f64::from(k);
            let close = |a: f64, b: f64| {
                (a - b).abs() <= 4.0 * f64::EPSILON * a.abs().max(b.abs()).max(1.0)
            };
            assert!(close(sin(x), x.sin()), "sin {x}");
            assert!(close(cos(x), x.cos()), "cos {x}");
            assert_eq!(sin_cos(x), (sin(x), cos(x)), "sin_cos {x}");
            let base = 1e-3 + f64::from(k) * 0.37;
            assert!(close(powf(base, 1.5), base.powf(1.5)), "pow {base}");
            assert!(close(powf(base, -0.2), base.powf(-0.2)), "pow {base}");
            assert!(close(hypot(x, base), x.hypot(base)), "hypot {x} {base}");
            assert!(close(ln(base), base.ln()), "ln {base}");
            assert!(close(exp(0.1 * x), (0.1 * x).exp()), "exp {x}");
        }
    }
}
