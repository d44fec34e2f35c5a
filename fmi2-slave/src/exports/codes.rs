//! The status codes the exports return most.

use fmi_sys::fmi2::{fmi2Status, fmi2Status_fmi2Discard, fmi2Status_fmi2OK};

/// fmi2OK.
pub(super) const OK: fmi2Status = fmi2Status_fmi2OK;
/// fmi2Discard.
pub(super) const DISCARD: fmi2Status = fmi2Status_fmi2Discard;

/// fmi2OK for a call that succeeded without a value.
pub(super) fn ok(_: ()) -> fmi2Status {
    OK
}
