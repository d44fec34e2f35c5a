//! Getting and setting values (FMI 3.0 §2.3.6): Float64 (with the independent variable `time`),
//! Int32, Int64 (the switches, FMI 3 Enumerations), Boolean and String; the FMU has no variable
//! of the other types, whose functions refuse every value reference.
#![allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]

use fmi_sys::fmi3::*;

use super::arrays::{get_float64, input_derivative, refuse_arrays, scalars};
use super::codes::with_instance;
use crate::calls;
use crate::checks::{check_set_real, lookup};
use crate::error::FmuError;
use crate::ffi::{slice, slice_mut};
use crate::fmi3::description::TIME_VALUE_REFERENCE;
use crate::instance::Instance;
use crate::model::{Model, Var};
use crate::state::Call;
use crate::status::{Status, ok};

/// The value references and values of a get call.
///
/// # Safety
/// As [`slice`] and [`slice_mut`], for `n` elements each.
unsafe fn get_args<'a, T>(
    vr: *const fmi3ValueReference,
    nvr: usize,
    values: *mut T,
    n: usize,
) -> Result<(&'a [u32], &'a mut [T]), FmuError> {
    scalars(nvr, n)?;
    // SAFETY: the caller's contract.
    unsafe {
        Ok((
            slice(vr, nvr, "valueReferences")?,
            slice_mut(values, n, "values")?,
        ))
    }
}

/// The value references and values of a set call.
///
/// # Safety
/// As [`slice`], for `n` elements each.
unsafe fn set_args<'a, T>(
    vr: *const fmi3ValueReference,
    nvr: usize,
    values: *const T,
    n: usize,
) -> Result<(&'a [u32], &'a [T]), FmuError> {
    scalars(nvr, n)?;
    // SAFETY: the caller's contract.
    unsafe {
        Ok((
            slice(vr, nvr, "valueReferences")?,
            slice(values, n, "values")?,
        ))
    }
}

/// Reads Float64 variables and arrays; `time` is the time the instance has reached.
pub unsafe fn fmi3GetFloat64<M: Model>(
    instance: fmi3Instance,
    valueReferences: *const fmi3ValueReference,
    nValueReferences: usize,
    values: *mut fmi3Float64,
    nValues: usize,
) -> fmi3Status {
    with_instance::<M>(instance, Call::GetReal, |inst| {
        // SAFETY: nValueReferences and nValues elements (FMI 3.0 §2.3.6).
        let (vr, values) = unsafe {
            (
                slice(valueReferences, nValueReferences, "valueReferences")?,
                slice_mut(values, nValues, "values")?,
            )
        };
        get_float64(inst, vr, values).map(ok)
    })
}

/// Writes Float64 parameters (before initialization ends) and inputs.
pub unsafe fn fmi3SetFloat64<M: Model>(
    instance: fmi3Instance,
    valueReferences: *const fmi3ValueReference,
    nValueReferences: usize,
    values: *const fmi3Float64,
    nValues: usize,
) -> fmi3Status {
    with_instance::<M>(instance, Call::SetReal, |inst| {
        // SAFETY: nValueReferences value references (FMI 3.0 §2.3.6).
        refuse_arrays(inst, unsafe {
            slice(valueReferences, nValueReferences, "valueReferences")
        }?)?;
        // SAFETY: nValueReferences and nValues elements (FMI 3.0 §2.3.6).
        let (vr, values) = unsafe { set_args(valueReferences, nValueReferences, values, nValues) }?;
        if vr.contains(&TIME_VALUE_REFERENCE) {
            return Err(FmuError::Invalid(
                "time is the independent variable and cannot be set".into(),
            ));
        }
        set_float64(inst, vr, values).map(ok)
    })
}

/// SetFloat64 of `vr`: the table's Real variables and the input derivatives, each checked
/// (settable now; in range, or finite) before any is set.
fn set_float64<M: Model>(
    inst: &mut Instance<M>,
    vr: &[u32],
    values: &[f64],
) -> Result<(), FmuError> {
    for (&r, &x) in vr.iter().zip(values) {
        match input_derivative(inst, r) {
            Some((k, order)) => inst.check_input_derivative(k, order, x)?,
            None => check_set_real(
                inst.machine().state(),
                &[lookup(M::VARIABLES, r, "Float64")?],
                &[x],
            )?,
        }
    }
    for (&r, &x) in vr.iter().zip(values) {
        match input_derivative(inst, r) {
            Some((k, order)) => inst.set_input_derivative(k, order, x)?,
            None => {
                inst.resolve(&[r], "Float64")?;
                inst.set_real(&[x])?;
            }
        }
    }
    Ok(())
}

/// A get or set function of one FMI 3 type: one value per value reference, each resolved as a
/// variable of `$type_name`, then `$body` on the instance and the values.
macro_rules! scalar_call {
    ($(#[$doc:meta])* $name:ident, $call:ident, *$ptr:tt $c_type:ty, $args:ident, $type_name:literal,
     |$inst:ident, $values:ident| $body:expr) => {
        $(#[$doc])*
        pub unsafe fn $name<M: Model>(
            instance: fmi3Instance,
            valueReferences: *const fmi3ValueReference,
            nValueReferences: usize,
            values: *$ptr $c_type,
            nValues: usize,
        ) -> fmi3Status {
            with_instance::<M>(instance, Call::$call, |$inst| {
                // SAFETY: nValueReferences and nValues elements (FMI 3.0 §2.3.6).
                let args = unsafe { $args(valueReferences, nValueReferences, values, nValues) };
                let (vr, $values) = args?;
                $inst.resolve(vr, $type_name)?;
                $body.map(ok)
            })
        }
    };
}

scalar_call!(
    /// Reads Int32 variables.
    fmi3GetInt32, GetInteger, *mut fmi3Int32, get_args, "Int32",
    |inst, values| inst.get_integer(values)
);
scalar_call!(
    /// Writes Int32 parameters (before initialization ends).
    fmi3SetInt32, SetInteger, *const fmi3Int32, set_args, "Int32",
    |inst, values| inst.set_integer(values)
);
scalar_call!(
    /// Reads the switches (FMI 3 Enumerations, exchanged as Int64).
    fmi3GetInt64, GetInt64, *mut fmi3Int64, get_args, "Int64",
    |inst, values| inst.get_converted(values, false, i64::from)
);
scalar_call!(
    /// Writes the switches (before initialization ends), each one of its type's items.
    fmi3SetInt64, SetInt64, *const fmi3Int64, set_args, "Int64",
    |inst, values| inst.set_converted(values, false, |v: Var<M::Vr>, value: i64| {
        i32::try_from(value)
            .map_err(|_| FmuError::Invalid(format!("{} = {value} is not one of its items", v.name)))
    })
);
scalar_call!(
    /// Reads Boolean variables.
    fmi3GetBoolean, GetBoolean, *mut fmi3Boolean, get_args, "Boolean",
    |inst, values| inst.get_converted(values, true, |flag| flag != 0)
);
scalar_call!(
    /// Writes Boolean variables (the model says which are settable).
    fmi3SetBoolean, SetBoolean, *const fmi3Boolean, set_args, "Boolean",
    |inst, values| inst.set_converted(values, true, |_, b| Ok(i32::from(b)))
);

/// Reads String variables; the strings stay valid until the next call on the instance.
pub unsafe fn fmi3GetString<M: Model>(
    instance: fmi3Instance,
    valueReferences: *const fmi3ValueReference,
    nValueReferences: usize,
    values: *mut fmi3String,
    nValues: usize,
) -> fmi3Status {
    with_instance::<M>(instance, Call::GetString, |inst| {
        // SAFETY: nValueReferences elements each (FMI 3.0 §2.3.6).
        let (vr, values) = unsafe { get_args(valueReferences, nValueReferences, values, nValues)? };
        calls::get_string(inst, vr, values)
    })
}

/// Writes String parameters (before initialization ends).
pub unsafe fn fmi3SetString<M: Model>(
    instance: fmi3Instance,
    valueReferences: *const fmi3ValueReference,
    nValueReferences: usize,
    values: *const fmi3String,
    nValues: usize,
) -> fmi3Status {
    with_instance::<M>(instance, Call::SetString, |inst| {
        // SAFETY: nValueReferences elements each, NUL-terminated strings (FMI 3.0 §2.3.6).
        unsafe {
            let (vr, values) = set_args(valueReferences, nValueReferences, values, nValues)?;
            calls::set_string(inst, vr, values)
        }
    })
}

/// A get or set function of a type the FMU has no variable of (`call` names it, `type_name` the
/// type): an empty request succeeds, any value reference is refused, naming its variable.
///
/// # Safety
/// `valueReferences` is NULL or points to `nValueReferences` value references.
pub unsafe fn no_variable_of_type<M: Model>(
    instance: fmi3Instance,
    call: &'static str,
    type_name: &str,
    valueReferences: *const fmi3ValueReference,
    nValueReferences: usize,
) -> fmi3Status {
    let call = match (type_name, call.starts_with("fmi3Get")) {
        ("Clock", _) => Call::Other(call),
        (_, true) => Call::GetOther(call),
        (_, false) => Call::SetOther(call),
    };
    with_instance::<M>(instance, call, |_| {
        // SAFETY: the caller's contract.
        let vr = unsafe { slice(valueReferences, nValueReferences, "valueReferences") }?;
        match vr.first() {
            None => Ok(Status::Ok),
            Some(&TIME_VALUE_REFERENCE) => Err(FmuError::Invalid(format!(
                "value reference {TIME_VALUE_REFERENCE} (time) is not of type {type_name}"
            ))),
            Some(&r) => lookup(M::VARIABLES, r, type_name).map(|_| Status::Ok),
        }
    })
}
