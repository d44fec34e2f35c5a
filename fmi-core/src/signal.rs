//! Inputs as polynomials of time over a communication step (FMI 2.0.4 §4.2.1): after
//! fmi2SetRealInputDerivatives an input is u(t) = u + u̇ τ + ü τ²/2 with τ = t − t₀ until the next
//! communication point; held inputs have zero derivatives.

/// u(t₀ + τ) = u + u̇ τ + ü τ²/2.
pub fn value(u: f64, first: f64, second: f64, tau: f64) -> f64 {
    u + tau * (first + 0.5 * tau * second)
}

/// u̇(t₀ + τ) = u̇ + ü τ.
pub fn rate(first: f64, second: f64, tau: f64) -> f64 {
    first + tau * second
}

/// `N` inputs as polynomials from `start`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Polynomial<const N: usize> {
    /// t₀ \[s\].
    pub start: f64,
    /// u(t₀).
    pub value: [f64; N],
    /// u̇(t₀) and ü(t₀).
    pub derivatives: [[f64; N]; 2],
}

impl<const N: usize> Default for Polynomial<N> {
    fn default() -> Self {
        Self {
            start: 0.0,
            value: [0.0; N],
            derivatives: [[0.0; N]; 2],
        }
    }
}

impl<const N: usize> Polynomial<N> {
    /// The values at `t`.
    pub fn at(&self, t: f64) -> [f64; N] {
        let tau = t - self.start;
        let [first, second] = self.derivatives;
        std::array::from_fn(|k| value(self.value[k], first[k], second[k], tau))
    }

    /// The rates at `t`.
    pub fn rate(&self, t: f64) -> [f64; N] {
        let tau = t - self.start;
        let [first, second] = self.derivatives;
        std::array::from_fn(|k| rate(first[k], second[k], tau))
    }
}
