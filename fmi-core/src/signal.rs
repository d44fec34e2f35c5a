//! Inputs as polynomials of time over a communication step (FMI 2.0.4 §4.2.1, FMI 3.0.2 §4.2.1):
//! after fmi2SetRealInputDerivatives (fmi3SetInputDerivatives) an input is
//! u(t) = u + u̇ τ + ü τ²/2 with τ = t − t₀ until the next communication point; held inputs have
//! zero derivatives. One type, [`Polynomial`], for every model: a model names its input values
//! ([`InputValues`]: by their index among its input variables, in table order).

use crate::codec::{ByteReader, ByteWriter, CodecError};

/// u(t₀ + τ) = u + u̇ τ + ü τ²/2.
pub fn value(u: f64, first: f64, second: f64, tau: f64) -> f64 {
    u + tau * (first + 0.5 * tau * second)
}

/// u̇(t₀ + τ) = u̇ + ü τ.
pub fn rate(first: f64, second: f64, tau: f64) -> f64 {
    first + tau * second
}

/// A model's input values, one per input variable, by its index among the model's inputs (in
/// the order of its variable table). A plain array serves; a model may name them in a struct.
pub trait InputValues: Copy + PartialEq + std::fmt::Debug {
    /// The number of inputs.
    const LEN: usize;
    /// Every input zero.
    const ZERO: Self;
    /// The value of input `k` (< [`InputValues::LEN`]).
    fn value(&self, k: usize) -> f64;
    /// The value of input `k`, to change.
    fn value_mut(&mut self, k: usize) -> &mut f64;
}

impl<const N: usize> InputValues for [f64; N] {
    const LEN: usize = N;
    const ZERO: Self = [0.0; N];
    fn value(&self, k: usize) -> f64 {
        self[k]
    }
    fn value_mut(&mut self, k: usize) -> &mut f64 {
        &mut self[k]
    }
}

/// Inputs `V` as polynomials of time from `start`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Polynomial<V> {
    /// t₀ \[s\].
    pub start: f64,
    /// u(t₀).
    pub value: V,
    /// u̇(t₀) and ü(t₀).
    pub derivatives: [V; 2],
}

impl<V: InputValues> Default for Polynomial<V> {
    /// Every input held at zero from t = 0.
    fn default() -> Self {
        Self::held(V::ZERO)
    }
}

impl<V: InputValues> Polynomial<V> {
    /// Inputs held at `value` (zero derivatives) from t = 0.
    pub fn held(value: V) -> Self {
        Self {
            start: 0.0,
            value,
            derivatives: [V::ZERO; 2],
        }
    }

    /// The values at `t`.
    pub fn at(&self, t: f64) -> V {
        let tau = t - self.start;
        let [first, second] = &self.derivatives;
        let mut out = V::ZERO;
        for k in 0..V::LEN {
            *out.value_mut(k) = value(self.value.value(k), first.value(k), second.value(k), tau);
        }
        out
    }

    /// The rates at `t`.
    pub fn rate(&self, t: f64) -> V {
        let tau = t - self.start;
        let [first, second] = &self.derivatives;
        let mut out = V::ZERO;
        for k in 0..V::LEN {
            *out.value_mut(k) = rate(first.value(k), second.value(k), tau);
        }
        out
    }

    /// Whether `other` is the same polynomial, bit for bit (a zero's sign included).
    pub fn same_bits(&self, other: &Self) -> bool {
        let values = |p: &Self| [p.value, p.derivatives[0], p.derivatives[1]];
        self.start.to_bits() == other.start.to_bits()
            && values(self)
                .iter()
                .zip(&values(other))
                .all(|(a, b)| (0..V::LEN).all(|k| a.value(k).to_bits() == b.value(k).to_bits()))
    }

    /// Whether any derivative is set.
    pub fn varies(&self) -> bool {
        self.derivatives != [V::ZERO; 2]
    }

    /// Holds the inputs from `t` on at the values the polynomials reach there (input derivatives
    /// hold for one communication step). Held inputs stay as they are.
    pub fn hold_at(&mut self, t: f64) {
        if self.varies() {
            *self = Self {
                start: t,
                ..Self::held(self.at(t))
            };
        }
    }

    /// Whether the inputs `k` with `acts(k)` are the same functions of time from `t` on in both.
    pub fn same_from(&self, other: &Self, t: f64, acts: impl Fn(usize) -> bool) -> bool {
        let (a, a_rate) = (self.at(t), self.rate(t));
        let (b, b_rate) = (other.at(t), other.rate(t));
        (0..V::LEN).filter(|&k| acts(k)).all(|k| {
            a.value(k) == b.value(k)
                && a_rate.value(k) == b_rate.value(k)
                && self.derivatives[1].value(k) == other.derivatives[1].value(k)
        })
    }

    /// Whether every number is finite.
    pub fn is_finite(&self) -> bool {
        self.start.is_finite()
            && [self.value, self.derivatives[0], self.derivatives[1]]
                .iter()
                .all(|v| (0..V::LEN).all(|k| v.value(k).is_finite()))
    }

    /// Writes t₀, then the values, the first and the second derivatives, each in input order.
    pub fn write(&self, w: &mut ByteWriter) {
        w.f64(self.start);
        for v in [&self.value, &self.derivatives[0], &self.derivatives[1]] {
            (0..V::LEN).for_each(|k| w.f64(v.value(k)));
        }
    }

    /// Reads what [`Polynomial::write`] wrote.
    pub fn read(r: &mut ByteReader) -> Result<Self, CodecError> {
        let mut s = Self {
            start: r.f64()?,
            ..Self::default()
        };
        let [first, second] = &mut s.derivatives;
        for v in [&mut s.value, first, second] {
            for k in 0..V::LEN {
                *v.value_mut(k) = r.f64()?;
            }
        }
        Ok(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_polynomial_is_its_taylor_series_and_holds_where_it_ends() {
        let mut s = Polynomial {
            start: 1.0,
            value: [2.0, -1.0],
            derivatives: [[3.0, 0.0], [4.0, 0.5]],
        };
        // u(t₀ + 0.5) = u + u̇ 0.5 + ü 0.125, u̇ = u̇ + ü 0.5.
        assert_eq!(s.at(1.5), [2.0 + 1.5 + 0.5, -1.0 + 0.0625]);
        assert_eq!(s.rate(1.5), [3.0 + 2.0, 0.25]);
        s.hold_at(1.5);
        assert_eq!(s, Polynomial::held([4.0, -0.9375]).starting(1.5));
        assert_eq!(s.at(7.0), [4.0, -0.9375]);
        assert!(!s.varies());
    }

    #[test]
    fn inputs_that_do_not_act_may_differ() {
        let a = Polynomial::held([1.0, 2.0]);
        let mut b = a;
        b.derivatives[1][1] = 1.0;
        assert!(a.same_from(&b, 0.0, |k| k == 0));
        assert!(!a.same_from(&b, 0.0, |_| true));
    }

    #[test]
    fn the_same_bits_tell_apart_what_equality_does_not() {
        let a = Polynomial::held([0.0, 2.0]).starting(0.5);
        assert!(a.same_bits(&a.clone()));
        let mut negative_zero = a;
        negative_zero.value[0] = -0.0;
        assert_eq!(a, negative_zero);
        assert!(!a.same_bits(&negative_zero));
        for change in [
            |p: &mut Polynomial<[f64; 2]>| p.start = 0.25,
            |p: &mut Polynomial<[f64; 2]>| p.value[1] = 3.0,
            |p: &mut Polynomial<[f64; 2]>| p.derivatives[0][1] = 1.0,
            |p: &mut Polynomial<[f64; 2]>| p.derivatives[1][0] = 1.0,
        ] {
            let mut b = a;
            change(&mut b);
            assert!(!a.same_bits(&b));
        }
    }

    #[test]
    fn a_polynomial_reads_back_what_it_wrote() {
        let s = Polynomial {
            start: 0.25,
            value: [1.0, 2.0, 3.0],
            derivatives: [[4.0, 5.0, 6.0], [7.0, 8.0, 9.0]],
        };
        let mut bytes = Vec::new();
        s.write(&mut ByteWriter(&mut bytes));
        assert_eq!(bytes.len(), 10 * 8);
        let mut r = ByteReader::new(&bytes);
        assert_eq!(Polynomial::read(&mut r), Ok(s));
        assert_eq!(r.remaining(), 0);
    }

    impl<V: InputValues> Polynomial<V> {
        fn starting(self, start: f64) -> Self {
            Self { start, ..self }
        }
    }
}
