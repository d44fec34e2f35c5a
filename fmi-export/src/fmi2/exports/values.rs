//! Getting and setting values, their derivatives and directional derivatives.
#![allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]

use fmi_sys::fmi2::*;

use super::codes::with_instance;
use crate::calls;
use crate::ffi::{slice, slice_mut};
use crate::model::{Model, no_input_derivatives};
use crate::state::Call;
use crate::status::ok;

/// A get or set function of one FMI 2 type: the value references resolved as variables of
/// `$type_name`, then the instance's `$method` on the values.
macro_rules! scalar_call {
    ($(#[$doc:meta])* $name:ident, $call:ident, *$ptr:tt $c_type:ty, $slice:ident, $type_name:literal,
     $method:ident) => {
        $(#[$doc])*
        pub unsafe fn $name<M: Model>(
            c: fmi2Component,
            vr: *const fmi2ValueReference,
            nvr: usize,
            value: *$ptr $c_type,
        ) -> fmi2Status {
            with_instance::<M>(c, Call::$call, |inst| {
                // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
                let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, $slice(value, nvr, "value")?) };
                inst.resolve(vr, $type_name)?;
                inst.$method(value).map(ok)
            })
        }
    };
}

scalar_call!(
    /// Reads Real variables.
    fmi2GetReal, GetReal, *mut fmi2Real, slice_mut, "Real", get_real
);
scalar_call!(
    /// Reads Integer variables (the switches among them).
    fmi2GetInteger, GetInteger, *mut fmi2Integer, slice_mut, "Integer", get_integer
);
scalar_call!(
    /// Reads Boolean variables.
    fmi2GetBoolean, GetBoolean, *mut fmi2Boolean, slice_mut, "Boolean", get_boolean
);
scalar_call!(
    /// Writes Real parameters (before initialization ends) and inputs.
    fmi2SetReal, SetReal, *const fmi2Real, slice, "Real", set_real
);
scalar_call!(
    /// Writes Integer parameters, the switches among them (before initialization ends).
    fmi2SetInteger, SetInteger, *const fmi2Integer, slice, "Integer", set_integer
);
scalar_call!(
    /// Writes Boolean variables (the model says which are settable).
    fmi2SetBoolean, SetBoolean, *const fmi2Boolean, slice, "Boolean", set_boolean
);

/// Reads String variables; the strings stay valid until the next call on the instance.
pub unsafe fn fmi2GetString<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2String,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetString, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?) };
        calls::get_string(inst, vr, value)
    })
}

/// Writes String variables (parameters: before fmi2ExitInitializationMode).
pub unsafe fn fmi2SetString<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2String,
) -> fmi2Status {
    with_instance::<M>(c, Call::SetString, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice(value, nvr, "value")?) };
        // SAFETY: NUL-terminated strings of the master's (FMI 2.0.4 fmi2String).
        unsafe { calls::set_string(inst, vr, value) }
    })
}

/// The directional derivative Δy = (∂y/∂u) Δu of Real outputs y with respect to Real inputs
/// u at the current point ([`calls::directional_derivative`]).
pub unsafe fn fmi2GetDirectionalDerivative<M: Model>(
    c: fmi2Component,
    vUnknown_ref: *const fmi2ValueReference,
    nUnknown: usize,
    vKnown_ref: *const fmi2ValueReference,
    nKnown: usize,
    dvKnown: *const fmi2Real,
    dvUnknown: *mut fmi2Real,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetDirectionalDerivative, |inst| {
        // SAFETY: nUnknown and nKnown elements (FMI 2.0.4 §2.1.9).
        let (unknowns, knowns, dv_known, dv_unknown) = unsafe {
            (
                slice(vUnknown_ref, nUnknown, "vUnknown_ref")?,
                slice(vKnown_ref, nKnown, "vKnown_ref")?,
                slice(dvKnown, nKnown, "dvKnown")?,
                slice_mut(dvUnknown, nUnknown, "dvUnknown")?,
            )
        };
        calls::directional_derivative(
            inst,
            unknowns,
            knowns,
            dv_known,
            dv_unknown,
            ["vUnknown_ref", "vKnown_ref", "dvKnown"],
        )
    })
}

/// Sets first or second time derivatives of inputs at the current communication point; the
/// inputs are the resulting polynomials over the next communication step.
pub unsafe fn fmi2SetRealInputDerivatives<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    order: *const fmi2Integer,
    value: *const fmi2Real,
) -> fmi2Status {
    with_instance::<M>(c, Call::SetRealInputDerivatives, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §4.2.1).
        let (vr, order, value) = unsafe {
            (
                slice(vr, nvr, "vr")?,
                slice(order, nvr, "order")?,
                slice(value, nvr, "value")?,
            )
        };
        if M::MAX_INPUT_DERIVATIVE_ORDER == 0 {
            return Err(no_input_derivatives());
        }
        inst.set_input_derivatives(vr, order, value).map(ok)
    })
}

/// Time derivatives of the kinematic outputs at the current communication point.
pub unsafe fn fmi2GetRealOutputDerivatives<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    order: *const fmi2Integer,
    value: *mut fmi2Real,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetRealOutputDerivatives, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §4.2.1).
        let (vr, order, value) = unsafe {
            (
                slice(vr, nvr, "vr")?,
                slice(order, nvr, "order")?,
                slice_mut(value, nvr, "value")?,
            )
        };
        calls::output_derivatives(inst, vr, order, value)
    })
}
