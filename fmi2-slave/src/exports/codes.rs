//! The status codes the exports return most.

use fmi_sys::fmi2::{fmi2Status, fmi2Status_fmi2Discard, fmi2Status_fmi2OK};

/// fmi2OK.
pub(crate) const OK: fmi2Status = fmi2Status_fmi2OK;
/// fmi2Discard.
pub(crate) const DISCARD: fmi2Status = fmi2Status_fmi2Discard;

/// fmi2OK for a call that succeeded without a value.
pub(crate) fn ok(_: ()) -> fmi2Status {
    OK
}
