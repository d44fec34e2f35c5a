//! Errors of the model library: invalid parameters and numerical failures.
//!
//! Every message names what went wrong with its value, so that the FMI layer can pass it to the
//! master's logger unchanged.

use std::fmt;

pub use fmi_core::number::Num;

/// An error of the model library.
#[derive(Clone, Debug, PartialEq)]
pub enum ModelError {
    /// A parameter is outside its allowed range.
    InvalidParameter {
        /// Parameter name, as the FMU exposes it (e.g. `rod.nElements`).
        name: &'static str,
        /// The rejected value.
        value: f64,
        /// The allowed range, in interval notation (e.g. `[1, 64]`).
        range: String,
    },
    /// A numerical operation failed (factorisation, eigenproblem, Newton iteration, step size).
    Numerical(String),
    /// A file a parameter names is missing or malformed; the message names the parameter, the
    /// file and what is wrong where.
    InvalidFile(String),
}

impl ModelError {
    /// Builds [`ModelError::InvalidParameter`].
    pub fn invalid(name: &'static str, value: f64, range: impl Into<String>) -> Self {
        Self::InvalidParameter {
            name,
            value,
            range: range.into(),
        }
    }
}

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::InvalidParameter { name, value, range } => {
                write!(
                    f,
                    "{name} = {} is outside the allowed range {range}",
                    Num(*value)
                )
            }
            Self::Numerical(what) | Self::InvalidFile(what) => f.write_str(what),
        }
    }
}

impl std::error::Error for ModelError {}

/// Checks that `value` is finite and strictly positive.
pub fn require_positive(name: &'static str, value: f64) -> Result<f64, ModelError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(ModelError::invalid(name, value, "(0, inf), finite"))
    }
}

/// Checks that `value` is finite and not negative.
pub fn require_non_negative(name: &'static str, value: f64) -> Result<f64, ModelError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(ModelError::invalid(name, value, "[0, inf), finite"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_parameter_value_and_range() {
        let e = require_positive("rod.area", -2.5).unwrap_err();
        assert_eq!(
            e.to_string(),
            "rod.area = -2.5 is outside the allowed range (0, inf), finite"
        );
        assert!(require_positive("rod.area", f64::NAN).is_err());
        assert!(require_non_negative("rod.stiffnessDamping", 0.0).is_ok());
        assert!(require_non_negative("rod.stiffnessDamping", f64::INFINITY).is_err());
    }
}
