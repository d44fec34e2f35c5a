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

    /// The same functions of time, written from `t` on: the values and rates there, the second
    /// derivatives as they are (a Taylor shift of each polynomial).
    pub fn continued_at(&self, t: f64) -> Self {
        Self {
            start: t,
            value: self.at(t),
            derivatives: [self.rate(t), self.derivatives[1]],
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

/// The inputs of one model instance, with one owner: what the master set at the current
/// communication point for the next step, and what the last step was integrated with.
///
/// - Values and derivatives set at a communication point make the polynomial of the next step
///   ([`InputRecord::stepping`]); an input whose derivatives are not set there is held over it (input
///   derivatives hold for one communication step).
/// - At the point a step ends, until an input or a derivative is set there, an output reads the
///   inputs as that step ended: the values its polynomials reached and their rates
///   ([`InputRecord::reading`]: the derivative the step was integrated with, so that an acceleration
///   under a prescribed speed ramp includes the ramp's rate). Once the master sets an input there,
///   outputs read what the next step will be integrated with.
/// - Whether an input is the same function of time over the next step as over the last one
///   ([`InputRecord::continues`]) tells a model whether its step sequence may go on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InputRecord<V> {
    /// The next step's inputs, from the current point.
    next: Polynomial<V>,
    /// The last step's inputs, continued to the current point ([`Polynomial::continued_at`]).
    last: Polynomial<V>,
    /// Whether outputs read `last`: at a step's end, before anything is set there.
    reading_last: bool,
}

impl<V: InputValues> InputRecord<V> {
    /// Inputs held at `value` from `t` on, no step taken.
    pub fn held(value: V, t: f64) -> Self {
        let held = Polynomial {
            start: t,
            ..Polynomial::held(value)
        };
        Self {
            next: held,
            last: held,
            reading_last: false,
        }
    }

    /// The inputs the next step is integrated with (during a step: the step's).
    pub fn stepping(&self) -> &Polynomial<V> {
        &self.next
    }

    /// The inputs the last step was integrated with, continued to the current point (before the
    /// first step: the start's).
    pub fn last(&self) -> &Polynomial<V> {
        &self.last
    }

    /// The inputs an output reads at the current point: as the last step ended there, until an
    /// input or a derivative is set; else those of the next step.
    pub fn reading(&self) -> &Polynomial<V> {
        if self.reading_last {
            &self.last
        } else {
            &self.next
        }
    }

    /// Whether the input `k` is the same function of time from the current point `t` on over the
    /// next step as it was over the last one (values, rates and second derivatives there).
    pub fn continues(&self, k: usize, t: f64) -> bool {
        self.last.same_from(&self.next, t, |j| j == k)
    }

    /// Sets the value of input `k` at the current point.
    pub fn set_value(&mut self, k: usize, x: f64) {
        *self.next.value.value_mut(k) = x;
        self.reading_last = false;
    }

    /// Sets the `order`-th derivative (1 or 2) of input `k` at the current point; None for
    /// another order.
    pub fn set_derivative(&mut self, k: usize, order: usize, x: f64) -> Option<()> {
        let derivative = self.next.derivatives.get_mut(order.checked_sub(1)?)?;
        *derivative.value_mut(k) = x;
        self.reading_last = false;
        Some(())
    }

    /// Sets every value and derivative of the next step at once, to those of `inputs` at the
    /// current point (`inputs.start` is not read).
    pub fn set(&mut self, inputs: &Polynomial<V>) {
        self.next = Polynomial {
            start: self.next.start,
            ..*inputs
        };
        self.reading_last = false;
    }

    /// Moves the current point to `t` before any step (the experiment's start): every input held
    /// from there at its value.
    pub fn start_at(&mut self, t: f64) {
        *self = Self::held(self.next.value, t);
    }

    /// A step begins: outputs now read its inputs.
    pub fn begin_step(&mut self) {
        self.reading_last = false;
    }

    /// A step ended at `t`: the step's inputs, continued there, are what outputs read; the next
    /// step holds each input at the value it reached until its derivatives are set again.
    pub fn end_step(&mut self, t: f64) {
        self.last = self.next.continued_at(t);
        self.next = Polynomial {
            start: t,
            ..Polynomial::held(self.last.value)
        };
        self.reading_last = true;
    }

    /// Whether every number is finite.
    pub fn is_finite(&self) -> bool {
        self.next.is_finite() && self.last.is_finite()
    }

    /// Writes the next step's and the last step's polynomials and the reading flag.
    pub fn write(&self, w: &mut ByteWriter) {
        self.next.write(w);
        self.last.write(w);
        w.flag(self.reading_last);
    }

    /// Reads what [`InputRecord::write`] wrote.
    pub fn read(r: &mut ByteReader) -> Result<Self, CodecError> {
        Ok(Self {
            next: Polynomial::read(r)?,
            last: Polynomial::read(r)?,
            reading_last: r.flag()?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_polynomial_is_its_taylor_series_and_continues_as_one() {
        let s = Polynomial {
            start: 1.0,
            value: [2.0, -1.0],
            derivatives: [[3.0, 0.0], [4.0, 0.5]],
        };
        // u(t₀ + 0.5) = u + u̇ 0.5 + ü 0.125, u̇ = u̇ + ü 0.5.
        assert_eq!(s.at(1.5), [2.0 + 1.5 + 0.5, -1.0 + 0.0625]);
        assert_eq!(s.rate(1.5), [3.0 + 2.0, 0.25]);
        let c = s.continued_at(1.5);
        assert_eq!(c.value, [4.0, -0.9375]);
        assert_eq!(c.derivatives, [[5.0, 0.25], [4.0, 0.5]]);
        assert_eq!(c.at(1.5), s.at(1.5));
        assert!((c.at(2.25)[1] - s.at(2.25)[1]).abs() < 1e-15);
    }

    /// At the point a step ends, outputs read the step's inputs as they ended (values and
    /// rates); once anything is set there they read the next step's, which holds each input whose
    /// derivatives are not set again; an input re-set to the same function of time continues.
    #[test]
    fn a_record_reads_the_step_that_ended_until_the_next_is_set() {
        let mut record = InputRecord::held([1.0, 2.0], 0.0);
        record.set_derivative(0, 1, 3.0).unwrap();
        record.set_derivative(0, 2, 4.0).unwrap();
        assert!(!record.continues(0, 0.0) && record.continues(1, 0.0));
        record.begin_step();
        assert_eq!(record.reading().derivatives, [[3.0, 0.0], [4.0, 0.0]]);
        record.end_step(0.5);
        let reached = 1.0 + 0.5 * (3.0 + 0.5 * 0.5 * 4.0);
        assert_eq!(record.reading().at(0.5), [reached, 2.0]);
        assert_eq!(record.reading().rate(0.5), [3.0 + 0.5 * 4.0, 0.0]);
        assert_eq!(*record.last(), record.reading().continued_at(0.5));
        assert_eq!(
            *record.stepping(),
            Polynomial::held([reached, 2.0]).starting(0.5)
        );
        assert!(
            !record.continues(0, 0.5),
            "derivatives not set again hold the input"
        );
        record.set_derivative(0, 1, 5.0).unwrap();
        record.set_derivative(0, 2, 4.0).unwrap();
        assert_eq!(record.reading(), record.stepping());
        assert!(
            record.continues(0, 0.5),
            "the same ramp set again continues"
        );
        record.set_value(1, 7.0);
        assert!(!record.continues(1, 0.5));
        assert_eq!(record.set_derivative(0, 3, 1.0), None);
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
