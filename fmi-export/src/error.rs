//! Errors of the FMI layer, each mapped to an `fmi2Status` and a message for the master's logger.

use std::fmt;

/// Why an FMI call failed.
#[derive(Clone, Debug, PartialEq)]
pub enum FmuError {
    /// The call (named) is not allowed in the current state.
    IllegalCall(String),
    /// A pointer argument is NULL.
    Null(&'static str),
    /// Any other invalid argument or request; the message says which and why.
    Invalid(String),
    /// The model rejected the parameters or failed numerically; the message says why.
    Model(String),
    /// The integrator could not complete the step (fmi2Discard); simulation stopped at `time`.
    Discard {
        /// Last successful time \[s\].
        time: f64,
        /// Reason.
        reason: String,
    },
}

impl fmt::Display for FmuError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::IllegalCall(call) => write!(f, "{call}: Illegal call sequence."),
            Self::Null(argument) => write!(f, "Argument {argument} must not be NULL."),
            Self::Invalid(message) => f.write_str(message),
            Self::Model(message) => f.write_str(message),
            Self::Discard { time, reason } => {
                write!(
                    f,
                    "step discarded, last successful time {} s: {reason}",
                    crate::number::Num(*time)
                )
            }
        }
    }
}

impl std::error::Error for FmuError {}

impl From<crate::codec::CodecError> for FmuError {
    fn from(e: crate::codec::CodecError) -> Self {
        FmuError::Invalid(e.0)
    }
}
