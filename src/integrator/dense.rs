//! Dense output over an accepted step of a mechanical system y = [q, q̇, w]:
//!
//! ```text
//! q(t₀ + sh) = H₀ q₀ + H₁ h q̇₀ + H₂ h² q̈₀ + H₃ h² q̈₁ + H₄ h q̇₁ + H₅ q₁     (quintic Hermite)
//! q̇(t₀ + sh) = dq/dt                                                   (its derivative, quartic)
//! w(t₀ + sh) = h₀₀ w₀ + h₁₀ h ẇ₀ + h₀₁ w₁ + h₁₁ h ẇ₁                     (cubic Hermite)
//! ```
//! with q̈ and ẇ the accelerations and rates of f at both ends. The position error is O(h⁶) and the
//! velocity error O(h⁵): the interpolant has the order of the 5th-order integrators, so outputs
//! between steps are as accurate as those at steps, and the step sequence need not stop at the
//! master's communication points.
//!
//! # References
//! - E. Hairer, S. P. Nørsett, G. Wanner (1993), Solving Ordinary Differential Equations I, 2nd ed.,
//!   §II.6 (dense output, Hermite interpolation).

/// An accepted step (t₀, y₀, f₀) → (t₀ + h, y₁, f₁): its ends, what its dense output is made of.
#[derive(Clone, Copy, Debug)]
pub struct Span<'a> {
    /// Start time t₀ \[s\].
    pub t0: f64,
    /// Step size h \[s\].
    pub h: f64,
    /// State at the start.
    pub y0: &'a [f64],
    /// Its derivative.
    pub f0: &'a [f64],
    /// State at the end.
    pub y1: &'a [f64],
    /// Its derivative.
    pub f1: &'a [f64],
}

/// Writes the state at t₀ + s·h (s ∈ [0, 1]) of the step `span` to `out`; the first `n_q` states
/// are coordinates, the next `n_q` their velocities.
pub fn interpolate(n_q: usize, span: &Span<'_>, s: f64, out: &mut [f64]) {
    let Span {
        h, y0, f0, y1, f1, ..
    } = *span;
    let (s2, s3) = (s * s, s * s * s);
    let (s4, s5) = (s3 * s, s3 * s2);
    let h0 = 1.0 - 10.0 * s3 + 15.0 * s4 - 6.0 * s5;
    let h1 = s - 6.0 * s3 + 8.0 * s4 - 3.0 * s5;
    let h2 = 0.5 * (s2 - 3.0 * s3 + 3.0 * s4 - s5);
    let h3 = 0.5 * (s3 - 2.0 * s4 + s5);
    let h4 = -4.0 * s3 + 7.0 * s4 - 3.0 * s5;
    let h5 = 10.0 * s3 - 15.0 * s4 + 6.0 * s5;
    let d0 = -30.0 * s2 + 60.0 * s3 - 30.0 * s4;
    let d1 = 1.0 - 18.0 * s2 + 32.0 * s3 - 15.0 * s4;
    let d2 = s - 4.5 * s2 + 6.0 * s3 - 2.5 * s4;
    let d3 = 1.5 * s2 - 4.0 * s3 + 2.5 * s4;
    let d4 = -12.0 * s2 + 28.0 * s3 - 15.0 * s4;
    let d5 = 30.0 * s2 - 60.0 * s3 + 30.0 * s4;
    for i in 0..n_q {
        let (q0, v0, a0) = (y0[i], y0[n_q + i], f0[n_q + i]);
        let (q1, v1, a1) = (y1[i], y1[n_q + i], f1[n_q + i]);
        out[i] = h0 * q0 + h1 * h * v0 + h2 * h * h * a0 + h3 * h * h * a1 + h4 * h * v1 + h5 * q1;
        out[n_q + i] = (d0 * q0 + d5 * q1) / h + d1 * v0 + d2 * h * a0 + d3 * h * a1 + d4 * v1;
    }
    let [c00, c10, c01, c11] = cubic_hermite(s);
    for i in 2 * n_q..y0.len() {
        out[i] = c00 * y0[i] + c10 * h * f0[i] + c01 * y1[i] + c11 * h * f1[i];
    }
}

/// Writes to the coordinate and velocity rows `0 .. 2 n_q` of `out` the state at t₀ + s·h of the
/// cubic Hermite interpolant of the positions through q₀, q̇₀, q₁, q̇₁ and of its derivative
/// ([`cubic_velocities`]); other rows are untouched. It reads no accelerations. Position error
/// O(h⁴), velocity error O(h³) of the resolved motion.
pub fn cubic(n_q: usize, h: f64, y0: &[f64], y1: &[f64], s: f64, out: &mut [f64]) {
    let [c00, c10, c01, c11] = cubic_hermite(s);
    for i in 0..n_q {
        out[i] = c00 * y0[i] + c10 * h * y0[n_q + i] + c01 * y1[i] + c11 * h * y1[n_q + i];
    }
    cubic_velocities(n_q, h, y0, y1, s, out);
}

/// The cubic Hermite basis at s ∈ [0, 1]: p(s) = b₀ p₀ + b₁ h ṗ₀ + b₂ p₁ + b₃ h ṗ₁ takes the
/// values p₀, p₁ and the rates ṗ₀, ṗ₁ at the ends of an interval of length h.
/// ```text
/// b₀ = 2s³ − 3s² + 1,   b₁ = s³ − 2s² + s,   b₂ = −2s³ + 3s²,   b₃ = s³ − s²
/// ```
pub fn cubic_hermite(s: f64) -> [f64; 4] {
    let (s2, s3) = (s * s, s * s * s);
    [
        2.0 * s3 - 3.0 * s2 + 1.0,
        s3 - 2.0 * s2 + s,
        -2.0 * s3 + 3.0 * s2,
        s3 - s2,
    ]
}

/// The derivatives db/ds of the [`cubic_hermite`] basis at s.
pub fn cubic_hermite_rate(s: f64) -> [f64; 4] {
    let s2 = s * s;
    [
        6.0 * s2 - 6.0 * s,
        3.0 * s2 - 4.0 * s + 1.0,
        6.0 * s - 6.0 * s2,
        3.0 * s2 - 2.0 * s,
    ]
}

/// Writes to the velocity rows `n_q .. 2 n_q` of `out` the velocities at t₀ + s·h of the cubic
/// Hermite interpolant of the positions through q₀, q̇₀, q₁, q̇₁ (the derivative of the
/// [`cubic_hermite`] polynomial, a quadratic in s; other rows are untouched). It reads no
/// accelerations: after a large implicit step those carry the amplified, unresolved content of
/// the stiff modes, which the quintic's velocities pass on as a spurious oscillation of amplitude
/// about h Δq̈/32 in mid-step; the cubic's error is O(h³) of the resolved motion instead.
pub fn cubic_velocities(n_q: usize, h: f64, y0: &[f64], y1: &[f64], s: f64, out: &mut [f64]) {
    let [d0, d1, d2, d3] = cubic_hermite_rate(s);
    for i in 0..n_q {
        out[n_q + i] = (d0 * y0[i] + d2 * y1[i]) / h + d1 * y0[n_q + i] + d3 * y1[n_q + i];
    }
}

/// Writes the accelerations at t₀ + s·h of the same interpolant (the second derivative of the
/// quintic, a cubic in s) to the velocity rows `n_q .. 2 n_q` of `out`; other rows are untouched.
pub fn acceleration(n_q: usize, span: &Span<'_>, s: f64, out: &mut [f64]) {
    let Span {
        h, y0, f0, y1, f1, ..
    } = *span;
    let (s2, s3) = (s * s, s * s * s);
    let e0 = -60.0 * s + 180.0 * s2 - 120.0 * s3;
    let e1 = -36.0 * s + 96.0 * s2 - 60.0 * s3;
    let e2 = 1.0 - 9.0 * s + 18.0 * s2 - 10.0 * s3;
    let e3 = 3.0 * s - 12.0 * s2 + 10.0 * s3;
    let e4 = -24.0 * s + 84.0 * s2 - 60.0 * s3;
    let e5 = 60.0 * s - 180.0 * s2 + 120.0 * s3;
    for i in 0..n_q {
        let (q0, v0, a0) = (y0[i], y0[n_q + i], f0[n_q + i]);
        let (q1, v1, a1) = (y1[i], y1[n_q + i], f1[n_q + i]);
        out[n_q + i] = (e0 * q0 + e5 * q1) / (h * h) + (e1 * v0 + e4 * v1) / h + e2 * a0 + e3 * a1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A quintic q(t) (with q̇, q̈) and a cubic w(t) are reproduced exactly (to round-off) at every
    /// s, over a step that does not start at 0.
    #[test]
    fn reproduces_quintic_positions_and_cubic_quadratures() {
        let q =
            |t: f64| 1.0 + 2.0 * t - t * t + 0.5 * t.powi(3) + 0.3 * t.powi(4) - 0.7 * t.powi(5);
        let v = |t: f64| 2.0 - 2.0 * t + 1.5 * t * t + 1.2 * t.powi(3) - 3.5 * t.powi(4);
        let a = |t: f64| -2.0 + 3.0 * t + 3.6 * t * t - 14.0 * t.powi(3);
        let w = |t: f64| 0.2 - t + 0.4 * t.powi(3);
        let dw = |t: f64| -1.0 + 1.2 * t * t;
        let (t0, h) = (0.3, 0.7);
        let t1 = t0 + h;
        let y0 = [q(t0), v(t0), w(t0)];
        let f0 = [v(t0), a(t0), dw(t0)];
        let y1 = [q(t1), v(t1), w(t1)];
        let f1 = [v(t1), a(t1), dw(t1)];
        let span = Span {
            t0,
            h,
            y0: &y0,
            f0: &f0,
            y1: &y1,
            f1: &f1,
        };
        let mut out = [0.0; 3];
        for s in [0.0, 0.1, 0.5, 0.77, 1.0] {
            interpolate(1, &span, s, &mut out);
            let t = t0 + s * h;
            assert!((out[0] - q(t)).abs() < 1e-14, "q at s = {s}");
            assert!((out[1] - v(t)).abs() < 1e-13, "v at s = {s}");
            assert!((out[2] - w(t)).abs() < 1e-14, "w at s = {s}");
            acceleration(1, &span, s, &mut out);
            assert!((out[1] - a(t)).abs() < 1e-12, "a at s = {s}: {}", out[1]);
        }
    }

    /// The cubic Hermite basis takes the end values and rates, and its rates are its
    /// derivatives (central differences); the cubic velocities reproduce a cubic's exactly.
    #[test]
    fn cubic_hermite_interpolates_and_differentiates() {
        assert_eq!(cubic_hermite(0.0), [1.0, 0.0, 0.0, 0.0]);
        assert_eq!(cubic_hermite(1.0), [0.0, 0.0, 1.0, 0.0]);
        assert_eq!(cubic_hermite_rate(0.0), [0.0, 1.0, 0.0, 0.0]);
        assert_eq!(cubic_hermite_rate(1.0), [0.0, 0.0, 0.0, 1.0]);
        let d = 1e-6;
        for s in [0.1, 0.37, 0.8] {
            let (plus, minus) = (cubic_hermite(s + d), cubic_hermite(s - d));
            for (k, rate) in cubic_hermite_rate(s).into_iter().enumerate() {
                assert!(
                    ((plus[k] - minus[k]) / (2.0 * d) - rate).abs() < 1e-9,
                    "{k} at {s}"
                );
            }
        }
        let q = |t: f64| 0.4 - 1.5 * t + 2.0 * t * t - 0.8 * t.powi(3);
        let v = |t: f64| -1.5 + 4.0 * t - 2.4 * t * t;
        let (t0, h) = (0.2, 0.5);
        let (y0, y1) = ([q(t0), v(t0)], [q(t0 + h), v(t0 + h)]);
        let mut out = [0.0; 2];
        for s in [0.0, 0.3, 0.5, 1.0] {
            cubic_velocities(1, h, &y0, &y1, s, &mut out);
            assert!((out[1] - v(t0 + s * h)).abs() < 1e-13, "v at s = {s}");
        }
    }
}
