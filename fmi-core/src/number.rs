//! One number format for every message: the shortest decimal that reads back as the same `f64`,
//! plain from 1e-4 up to 1e6 (`0.01`, `523.5987755982989`, `-3`) and in scientific notation
//! outside (`1e-9`, `1e6`, `2.5e20`).

use std::fmt;

/// An `f64` shown in the one number format of the messages.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Num(pub f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        let magnitude = x.abs();
        if x == 0.0 || !x.is_finite() || (1e-4..1e6).contains(&magnitude) {
            // Rust's Display of f64 is the shortest round-trip decimal, never in exponent form.
            write!(f, "{x}")
        } else {
            write!(f, "{x:e}")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Plain in the middle range, scientific outside, and always the shortest form that reads
    /// back as the same number.
    #[test]
    fn numbers_are_shortest_and_round_trip() {
        for (x, text) in [
            (0.01, "0.01"),
            (-3.0, "-3"),
            (7.634, "7.634"),
            (1e-5, "1e-5"),
            (0.0001, "0.0001"),
            (523.598_775_598_298_9, "523.5987755982989"),
            (2.5e20, "2.5e20"),
            (1e6, "1e6"),
            (999_999.5, "999999.5"),
            (1e9, "1e9"),
            (0.0, "0"),
            (f64::INFINITY, "inf"),
            (f64::NAN, "NaN"),
        ] {
            assert_eq!(Num(x).to_string(), text);
        }
        for x in [
            1.0 / 3.0,
            4.637e-10,
            123_456.789,
            -2.243_589_743_589_743_6e-4,
        ] {
            let text = Num(x).to_string();
            assert_eq!(
                text.parse::<f64>().unwrap().to_bits(),
                x.to_bits(),
                "{text}"
            );
        }
    }
}
