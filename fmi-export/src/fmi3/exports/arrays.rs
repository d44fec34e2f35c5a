//! Configuration Mode, structural parameters and arrays (FMI 3.0 §2.3.5, §2.3.6): the
//! structural parameters are UInt64 values set only in Configuration Mode, and a get call's
//! `nValues` counts every element of the arrays it names.
#![allow(unsafe_code, non_snake_case, clippy::missing_safety_doc)]

use fmi_sys::fmi3::*;

use super::codes::with_instance;
use crate::checks::lookup;
use crate::error::FmuError;
use crate::ffi::{slice, slice_mut};
use crate::fmi3::description::TIME_VALUE_REFERENCE;
use crate::instance::Instance;
use crate::model::Model;
use crate::signal::InputValues;
use crate::state::{Call, State};
use crate::status::Status;

/// Checks that a call gives one value per value reference: every variable of the type is a
/// scalar (FMI 3.0 §2.3.6: nValues is the total size of the variables named; only Float64 has
/// arrays, [`get_float64`]).
pub(super) fn scalars(n_value_references: usize, n_values: usize) -> Result<(), FmuError> {
    if n_values == n_value_references {
        Ok(())
    } else {
        Err(FmuError::Invalid(format!(
            "nValues = {n_values} but nValueReferences = {n_value_references}: every variable \
             of this FMU is a scalar"
        )))
    }
}

/// Enters Configuration Mode, where the structural parameters are set.
pub unsafe fn fmi3EnterConfigurationMode<M: Model>(instance: fmi3Instance) -> fmi3Status {
    with_instance::<M>(instance, Call::EnterConfigurationMode, |inst| {
        if inst.fmi3().interface.structural_parameters.is_empty() {
            return Err(FmuError::Invalid(
                "not supported: the FMU has no structural parameters".into(),
            ));
        }
        Ok(Status::Ok)
    })
}

/// Leaves Configuration Mode: the structural parameters are fixed from here on.
pub unsafe fn fmi3ExitConfigurationMode<M: Model>(instance: fmi3Instance) -> fmi3Status {
    with_instance::<M>(instance, Call::ExitConfigurationMode, |_| Ok(Status::Ok))
}

/// Reads structural parameters.
pub unsafe fn fmi3GetUInt64<M: Model>(
    instance: fmi3Instance,
    valueReferences: *const fmi3ValueReference,
    nValueReferences: usize,
    values: *mut fmi3UInt64,
    nValues: usize,
) -> fmi3Status {
    with_instance::<M>(instance, Call::GetUInt64, |inst| {
        scalars(nValueReferences, nValues)?;
        // SAFETY: nValueReferences and nValues elements (FMI 3.0 §2.3.6).
        let (vr, values) = unsafe {
            (
                slice(valueReferences, nValueReferences, "valueReferences")?,
                slice_mut(values, nValues, "values")?,
            )
        };
        for (&r, value) in vr.iter().zip(values) {
            let (index, _) = structural(inst, r)?;
            *value = inst.fmi3().structural[index];
        }
        Ok(Status::Ok)
    })
}

/// Sets structural parameters, each inside its range, in Configuration Mode only (the call is
/// legal wherever a setter is; its variables are refused outside Configuration Mode).
pub unsafe fn fmi3SetUInt64<M: Model>(
    instance: fmi3Instance,
    valueReferences: *const fmi3ValueReference,
    nValueReferences: usize,
    values: *const fmi3UInt64,
    nValues: usize,
) -> fmi3Status {
    with_instance::<M>(instance, Call::SetUInt64, |inst| {
        scalars(nValueReferences, nValues)?;
        // SAFETY: nValueReferences and nValues elements (FMI 3.0 §2.3.6).
        let (vr, values) = unsafe {
            (
                slice(valueReferences, nValueReferences, "valueReferences")?,
                slice(values, nValues, "values")?,
            )
        };
        for (&r, &value) in vr.iter().zip(values) {
            let (_, p) = structural(inst, r)?;
            let current = inst.machine().state();
            if current != State::ConfigurationMode {
                return Err(FmuError::Invalid(format!(
                    "{} is a structural parameter: it is set in Configuration Mode only \
                     (fmi3EnterConfigurationMode), not in the {:?} state",
                    p.name, current
                )));
            }
            if !(p.min..=p.max).contains(&value) {
                return Err(FmuError::Invalid(format!(
                    "{} = {value} is outside the allowed range [{}, {}]",
                    p.name, p.min, p.max
                )));
            }
        }
        for (&r, &value) in vr.iter().zip(values) {
            let index = structural(inst, r)?.0;
            inst.fmi3_mut().structural[index] = value;
        }
        Ok(Status::Ok)
    })
}

/// The structural parameter with value reference `vr`, with its index; any other value reference
/// is refused, named.
fn structural<M: Model>(
    inst: &Instance<M>,
    vr: u32,
) -> Result<(usize, &'static crate::fmi3::interface::StructuralParameter), FmuError> {
    let interface = inst.fmi3().interface;
    interface.structural_parameter(vr).ok_or_else(|| match vr {
        TIME_VALUE_REFERENCE => {
            FmuError::Invalid(format!("value reference {vr} (time) is not of type UInt64"))
        }
        _ => match interface.array(vr) {
            Some((_, a)) => FmuError::Invalid(format!(
                "value reference {vr} ({}) is not of type UInt64",
                a.name
            )),
            None => lookup(M::VARIABLES, vr, "UInt64")
                .err()
                .unwrap_or_else(|| FmuError::Invalid(format!("unknown value reference {vr}"))),
        },
    })
}

/// The input and the order of the input derivative `der(u)` of value reference `vr`, if it is
/// one that `inst`'s description declares ([`crate::fmi3::description::input_derivative`]).
pub(super) fn input_derivative<M: Model>(inst: &Instance<M>, vr: u32) -> Option<(usize, u32)> {
    let (n, max) = (M::Inputs::LEN, M::MAX_INPUT_DERIVATIVE_ORDER);
    let declared = inst.fmi3().interface.input_derivatives;
    crate::fmi3::description::input_derivative(vr, n, max).filter(|_| declared)
}

/// The number of values of the Float64 variable `vr`: its array's size, or 1.
fn size<M: Model>(inst: &Instance<M>, vr: u32) -> usize {
    let fmi3 = inst.fmi3();
    fmi3.interface.array(vr).map_or(1, |(_, a)| {
        usize::try_from(fmi3.structural[a.dimension]).unwrap_or(usize::MAX)
    })
}

/// fmi3GetFloat64: `time` (the time reached), the table's Float64 variables (each run of them in
/// one call of the model, so it computes its outputs once) and the arrays, whose elements
/// `values` holds in order; `values.len()` must be their total size.
pub fn get_float64<M: Model>(
    inst: &mut Instance<M>,
    vr: &[u32],
    values: &mut [f64],
) -> Result<(), FmuError> {
    let total = vr
        .iter()
        .fold(0usize, |n, &r| n.saturating_add(size(inst, r)));
    if total != values.len() {
        return Err(FmuError::Invalid(format!(
            "nValues = {} but the variables named have {total} element{}",
            values.len(),
            if total == 1 { "" } else { "s" }
        )));
    }
    let (mut i, mut at) = (0, 0);
    while i < vr.len() {
        let r = vr[i];
        if r == TIME_VALUE_REFERENCE {
            values[at] = inst.clock().last_successful_time;
            (i, at) = (i + 1, at + 1);
        } else if let Some((index, _)) = inst.fmi3().interface.array(r) {
            let n = size(inst, r);
            inst.get_array(index, &mut values[at..at + n])?;
            (i, at) = (i + 1, at + n);
        } else if let Some((k, order)) = input_derivative(inst, r) {
            values[at] = inst.input_derivative(k, order);
            (i, at) = (i + 1, at + 1);
        } else {
            let table = |r: u32| {
                r != TIME_VALUE_REFERENCE
                    && inst.fmi3().interface.array(r).is_none()
                    && input_derivative(inst, r).is_none()
            };
            let run = vr[i..].iter().take_while(|&&r| table(r)).count();
            inst.resolve(&vr[i..i + run], "Float64")?;
            inst.get_real(&mut values[at..at + run])?;
            (i, at) = (i + run, at + run);
        }
    }
    Ok(())
}

/// The refusal of a Float64 array in a set call: every array is computed.
pub fn refuse_arrays<M: Model>(inst: &Instance<M>, vr: &[u32]) -> Result<(), FmuError> {
    match vr.iter().find_map(|&r| inst.fmi3().interface.array(r)) {
        Some((_, a)) => Err(FmuError::Invalid(format!(
            "{} is computed by the FMU and cannot be set",
            a.name
        ))),
        None => Ok(()),
    }
}
