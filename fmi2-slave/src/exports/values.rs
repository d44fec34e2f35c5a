//! Getting and setting values, their derivatives and directional derivatives.
#![allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]

use std::ffi::CString;

use fmi_sys::fmi2::*;

use super::codes::{OK, ok};
use crate::checks::{
    check_causality, check_input_derivatives, check_set_boolean, check_set_integer, check_set_real,
    check_set_string, resolve,
};
use crate::error::FmuError;
use crate::ffi::{slice, slice_mut, string, with_instance};
use crate::model::{Model, no_input_derivatives};
use crate::number::Num;
use crate::state::Call;
use crate::table::Causality;

/// Reads Real variables.
pub unsafe fn fmi2GetReal<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Real,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetReal, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?) };
        resolve::<M>(vr, "Real", &mut inst.variables)?;
        inst.model
            .get_real(&inst.logger, &inst.variables, value)
            .map(ok)
    })
}

/// Reads Integer variables (the switches among them).
pub unsafe fn fmi2GetInteger<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Integer,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetInteger, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?) };
        resolve::<M>(vr, "Integer", &mut inst.variables)?;
        inst.model
            .get_integer(&inst.logger, &inst.variables, value)
            .map(ok)
    })
}

/// Reads Boolean variables.
pub unsafe fn fmi2GetBoolean<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *mut fmi2Boolean,
) -> fmi2Status {
    with_instance::<M>(c, Call::GetBoolean, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?) };
        resolve::<M>(vr, "Boolean", &mut inst.variables)?;
        inst.model
            .get_boolean(&inst.logger, &inst.variables, value)
            .map(ok)
    })
}

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
        resolve::<M>(vr, "String", &mut inst.variables)?;
        let mut texts = Vec::with_capacity(nvr);
        inst.model.get_string(&inst.variables, &mut texts)?;
        inst.strings = texts
            .into_iter()
            .map(|t| CString::new(t.replace('\0', "")).unwrap_or_default())
            .collect();
        for (v, text) in value.iter_mut().zip(&inst.strings) {
            *v = text.as_ptr();
        }
        Ok(OK)
    })
}

/// Writes Real parameters (before initialization ends) and inputs.
pub unsafe fn fmi2SetReal<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Real,
) -> fmi2Status {
    with_instance::<M>(c, Call::SetReal, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice(value, nvr, "value")?) };
        resolve::<M>(vr, "Real", &mut inst.variables)?;
        check_set_real(inst.state, &inst.variables, value)?;
        inst.model
            .set_real(inst.state, &inst.variables, value)
            .map(ok)
    })
}

/// Writes Integer parameters, the switches among them (before initialization ends).
pub unsafe fn fmi2SetInteger<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Integer,
) -> fmi2Status {
    with_instance::<M>(c, Call::SetInteger, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice(value, nvr, "value")?) };
        resolve::<M>(vr, "Integer", &mut inst.variables)?;
        check_set_integer::<M>(inst.state, &inst.variables, value)?;
        inst.model
            .set_integer(inst.state, &inst.variables, value)
            .map(ok)
    })
}

/// No Boolean variable is settable: any value reference is an error.
pub unsafe fn fmi2SetBoolean<M: Model>(
    c: fmi2Component,
    vr: *const fmi2ValueReference,
    nvr: usize,
    value: *const fmi2Boolean,
) -> fmi2Status {
    with_instance::<M>(c, Call::SetBoolean, |inst| {
        // SAFETY: nvr elements each (FMI 2.0.4 §2.1.7).
        let (vr, value) = unsafe { (slice(vr, nvr, "vr")?, slice(value, nvr, "value")?) };
        resolve::<M>(vr, "Boolean", &mut inst.variables)?;
        check_set_boolean(inst.state, &inst.variables)?;
        inst.model
            .set_boolean(inst.state, &inst.variables, value)
            .map(ok)
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
        resolve::<M>(vr, "String", &mut inst.variables)?;
        check_set_string(inst.state, &inst.variables)?;
        let texts = value
            .iter()
            .zip(inst.variables.iter())
            .map(|(&p, v)| {
                // SAFETY: a NUL-terminated string of the master's (FMI 2.0.4 fmi2String).
                unsafe { string(p) }
                    .ok_or_else(|| FmuError::Invalid(format!("{}: value is NULL", v.name)))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let texts: Vec<&str> = texts.iter().map(String::as_str).collect();
        inst.model
            .set_string(inst.state, &inst.variables, &texts)
            .map(ok)
    })
}

/// The directional derivative Δy = (∂y/∂u) Δu of Real outputs y with respect to Real inputs
/// u at the current point, from the model's columns ∂y/∂uⱼ ([`Model::output_sensitivity`]).
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
        inst.variables.clear();
        for &vr in unknowns {
            let v = check_causality::<M>(vr, Causality::Output, "vUnknown_ref")?;
            inst.variables.push(v);
        }
        let knowns = knowns
            .iter()
            .zip(dv_known)
            .map(|(&vr, &dv)| {
                let v = check_causality::<M>(vr, Causality::Input, "vKnown_ref")?;
                if dv.is_finite() {
                    Ok((v, dv))
                } else {
                    Err(FmuError::Invalid(format!(
                        "dvKnown = {} for {} is not finite",
                        Num(dv),
                        v.name
                    )))
                }
            })
            .collect::<Result<Vec<_>, _>>()?;
        let mut column = vec![0.0; unknowns.len()];
        let mut sum = vec![0.0; unknowns.len()];
        for (known, dv) in knowns {
            inst.model
                .output_sensitivity(&inst.logger, known, &inst.variables, &mut column)?;
            for (s, c) in sum.iter_mut().zip(&column) {
                *s += c * dv;
            }
        }
        dv_unknown.copy_from_slice(&sum);
        Ok(OK)
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
        check_input_derivatives::<M>(vr, order, value, &mut inst.variables)?;
        inst.model
            .set_real_input_derivatives(&inst.variables, order, value)
            .map(ok)
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
        resolve::<M>(vr, "Real", &mut inst.variables)?;
        inst.model
            .get_real_output_derivatives(&inst.logger, &inst.variables, order, value)
            .map(ok)
    })
}
