//! The calls FMI 2 and FMI 3 make alike, on an instance and plain values: creating and freeing an
//! instance, the logging switch, terminating and resetting, FMU states, String values, and the
//! derivatives. Each version's function checks its own pointer arguments (naming them as its
//! standard does), runs one of these through [`crate::ffi::with_instance`] and turns the
//! [`Status`] into its own code.
#![allow(unsafe_code)]

use std::ffi::{c_char, c_void};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::PathBuf;

use crate::checks::check_causality;
use crate::error::FmuError;
use crate::ffi::{slice_mut, string};
use crate::instance::Instance;
use crate::logger::Logger;
use crate::model::Model;
use crate::number::Num;
use crate::state::Version;
use crate::status::{Status, ok};
use crate::table::Causality;

/// A new instance of `M` named `name`, created through `version`, after checking the name and the
/// token (FMI 2's GUID, FMI 3's instantiation token) against the model's; None, the reason logged,
/// if either is wrong. The instance serves the FMI 3 interface its token names.
pub fn create<M: Model>(
    logger: Logger,
    name: &str,
    token: &str,
    resources: Option<PathBuf>,
    version: Version,
) -> Option<Box<Instance<M>>> {
    let (call, token_name) = match version {
        Version::Fmi2 => ("fmi2Instantiate", "GUID"),
        Version::Fmi3 => ("fmi3InstantiateCoSimulation", "instantiationToken"),
    };
    if name.is_empty() {
        logger.error(&format!("{call}: instanceName must not be NULL or empty."));
        return None;
    }
    let fmi3 = match version {
        Version::Fmi2 if token == M::GUID => M::FMI3,
        Version::Fmi3 if token == M::FMI3_TOKENS[0] => M::FMI3,
        Version::Fmi3 if token == M::FMI3_TOKENS[1] => M::FMI3.scalar(),
        _ => {
            let expected = match version {
                Version::Fmi2 => M::GUID.to_string(),
                Version::Fmi3 if M::FMI3_TOKENS[0] == M::FMI3_TOKENS[1] => {
                    M::FMI3_TOKENS[0].to_string()
                }
                Version::Fmi3 => format!(
                    "{} (with arrays) or {} (without)",
                    M::FMI3_TOKENS[0],
                    M::FMI3_TOKENS[1]
                ),
            };
            logger.error(&format!(
                "{call}: Wrong {token_name}: expected {expected}, got \"{token}\"."
            ));
            return None;
        }
    };
    logger.event(&format!(
        "{call}: instance \"{name}\" created (resources: {})",
        resources
            .as_ref()
            .map_or_else(|| "none".to_string(), |d| d.display().to_string())
    ));
    Some(Box::new(Instance::<M>::new(
        logger, resources, version, fmi3,
    )))
}

/// Frees an instance (NULL is a no-op).
///
/// # Safety
/// `c` is NULL or an instance of `M` from [`create`] (Box::into_raw), not yet freed; it is freed
/// once (FMI 2.0.4 §2.1.5, FMI 3.0 §2.3.1: no call on it afterwards).
pub unsafe fn free_instance<M: Model>(c: *mut c_void) {
    if !c.is_null() {
        // SAFETY: the caller's contract.
        let instance = unsafe { Box::from_raw(c.cast::<Instance<M>>()) };
        let _ = catch_unwind(AssertUnwindSafe(|| drop(instance)));
    }
}

/// Switches debug logging and, if `categories` is not empty, enables only those.
///
/// # Safety
/// Each pointer of `categories` is NULL or a NUL-terminated string valid during the call.
pub unsafe fn set_debug_logging<M: Model>(
    inst: &mut Instance<M>,
    on: bool,
    categories: &[*const c_char],
) -> Result<Status, FmuError> {
    let mut names = Vec::with_capacity(categories.len());
    for &p in categories {
        // SAFETY: the caller's contract.
        names.push(unsafe { string(p) }.ok_or(FmuError::Null("categories[i]"))?);
    }
    inst.logger_mut()
        .set_debug_logging(on, &names)
        .map_err(FmuError::Invalid)?;
    Ok(Status::Ok)
}

/// Ends the simulation; outputs stay readable.
pub fn terminate<M: Model>(_inst: &mut Instance<M>) -> Result<Status, FmuError> {
    Ok(Status::Ok)
}

/// Back to Instantiated with every start value.
pub fn reset<M: Model>(inst: &mut Instance<M>) -> Result<Status, FmuError> {
    inst.reset();
    Ok(Status::Ok)
}

/// An FMU state as the master holds it: an opaque pointer to the serialized bytes.
type StateBytes = Vec<u8>;

/// Stores `bytes` in the master's state variable `*slot`: a new state if it is NULL, else the
/// state of this FMU it holds is overwritten.
///
/// # Safety
/// `slot` is NULL or points to the master's FMU-state variable, which is NULL or holds a state of
/// this FMU.
unsafe fn store(
    slot: *mut *mut c_void,
    bytes: StateBytes,
    name: &'static str,
) -> Result<Status, FmuError> {
    if slot.is_null() {
        return Err(FmuError::Null(name));
    }
    // SAFETY: the caller's contract: a non-NULL value is a Box<StateBytes> of this FMU.
    unsafe {
        if (*slot).is_null() {
            *slot = Box::into_raw(Box::new(bytes)).cast();
        } else {
            *(*slot).cast::<StateBytes>() = bytes;
        }
    }
    Ok(Status::Ok)
}

/// The bytes of a state of this FMU.
///
/// # Safety
/// `state` is NULL or a state of this FMU, valid during the call.
unsafe fn bytes_of<'a>(state: *mut c_void, name: &'static str) -> Result<&'a StateBytes, FmuError> {
    if state.is_null() {
        return Err(FmuError::Null(name));
    }
    // SAFETY: the caller's contract.
    Ok(unsafe { &*state.cast::<StateBytes>() })
}

/// Captures the complete instance state into the master's variable `*slot` (`name` its argument).
///
/// # Safety
/// As `store`.
pub unsafe fn get_state<M: Model>(
    inst: &mut Instance<M>,
    slot: *mut *mut c_void,
    name: &'static str,
) -> Result<Status, FmuError> {
    // SAFETY: the caller's contract.
    unsafe { store(slot, inst.serialize(), name) }
}

/// Restores a captured state, the state machine included.
///
/// # Safety
/// As `bytes_of`.
pub unsafe fn set_state<M: Model>(
    inst: &mut Instance<M>,
    state: *mut c_void,
    name: &'static str,
) -> Result<Status, FmuError> {
    // SAFETY: the caller's contract.
    let bytes = unsafe { bytes_of(state, name) }?;
    inst.deserialize(bytes, true).map(ok)
}

/// Frees the state in the master's variable `*slot` and sets it to NULL.
///
/// # Safety
/// As `store`; the state is freed once.
pub unsafe fn free_state(slot: *mut *mut c_void, name: &'static str) -> Result<Status, FmuError> {
    if slot.is_null() {
        return Err(FmuError::Null(name));
    }
    // SAFETY: the caller's contract.
    unsafe {
        if !(*slot).is_null() {
            drop(Box::from_raw((*slot).cast::<StateBytes>()));
            *slot = std::ptr::null_mut();
        }
    }
    Ok(Status::Ok)
}

/// The size of a state in bytes, written to `size[0]`.
///
/// # Safety
/// As `bytes_of`.
pub unsafe fn serialized_size(
    state: *mut c_void,
    size: &mut [usize],
    name: &'static str,
) -> Result<Status, FmuError> {
    // SAFETY: the caller's contract.
    size[0] = unsafe { bytes_of(state, name) }?.len();
    Ok(Status::Ok)
}

/// Writes a state as pointer-free bytes into the master's `size` bytes at `out`.
///
/// # Safety
/// As `bytes_of`; `out` is NULL or `size` writable bytes.
pub unsafe fn serialize(
    state: *mut c_void,
    out: *mut u8,
    size: usize,
    [state_name, out_name]: [&'static str; 2],
) -> Result<Status, FmuError> {
    // SAFETY: the caller's contract.
    let bytes = unsafe { bytes_of(state, state_name) }?;
    if size < bytes.len() {
        return Err(FmuError::Invalid(format!(
            "size = {size} is smaller than the serialized state ({} bytes)",
            bytes.len()
        )));
    }
    // SAFETY: the caller's contract.
    let out = unsafe { slice_mut(out, bytes.len(), out_name) }?;
    out.copy_from_slice(bytes);
    Ok(Status::Ok)
}

/// Reads a state from bytes (checked: magic, version, contents, checksum) into the master's
/// variable `*slot`.
///
/// # Safety
/// As `store`.
pub unsafe fn deserialize<M: Model>(
    inst: &mut Instance<M>,
    bytes: &[u8],
    slot: *mut *mut c_void,
    name: &'static str,
) -> Result<Status, FmuError> {
    if slot.is_null() {
        return Err(FmuError::Null(name));
    }
    inst.deserialize(bytes, false)?;
    // SAFETY: the caller's contract.
    unsafe { store(slot, bytes.to_vec(), name) }
}

/// Reads String variables; the strings stay valid until the next call on the instance.
pub fn get_string<M: Model>(
    inst: &mut Instance<M>,
    vr: &[u32],
    value: &mut [*const c_char],
) -> Result<Status, FmuError> {
    inst.resolve(vr, "String")?;
    for (v, text) in value.iter_mut().zip(inst.get_string()?) {
        *v = text.as_ptr();
    }
    Ok(Status::Ok)
}

/// Writes String variables (parameters: before initialization ends).
///
/// # Safety
/// Each pointer of `value` is NULL or a NUL-terminated string valid during the call.
pub unsafe fn set_string<M: Model>(
    inst: &mut Instance<M>,
    vr: &[u32],
    value: &[*const c_char],
) -> Result<Status, FmuError> {
    inst.resolve(vr, "String")?;
    let texts = value
        .iter()
        .zip(inst.variables())
        .map(|(&p, v)| {
            // SAFETY: the caller's contract.
            unsafe { string(p) }
                .ok_or_else(|| FmuError::Invalid(format!("{}: value is NULL", v.name)))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let texts: Vec<&str> = texts.iter().map(String::as_str).collect();
    inst.set_string(&texts).map(ok)
}

/// The directional derivative Δy = (∂y/∂u) Δu of Real outputs y (`unknowns`) with respect to Real
/// inputs u (`knowns`, with their increments `seed`) at the current point, from the model's
/// columns ∂y/∂uⱼ ([`Model::output_sensitivity`]), into `sensitivity`. `names` are the version's
/// names of the unknowns', the knowns' and the seed's arguments, for messages.
pub fn directional_derivative<M: Model>(
    inst: &mut Instance<M>,
    unknowns: &[u32],
    knowns: &[u32],
    seed: &[f64],
    sensitivity: &mut [f64],
    [unknowns_name, knowns_name, seed_name]: [&'static str; 3],
) -> Result<Status, FmuError> {
    inst.resolve_by(unknowns, |vr| {
        check_causality::<M>(vr, Causality::Output, unknowns_name)
    })?;
    let knowns = knowns
        .iter()
        .zip(seed)
        .map(|(&vr, &dv)| {
            let v = check_causality::<M>(vr, Causality::Input, knowns_name)?;
            if dv.is_finite() {
                Ok((v, dv))
            } else {
                Err(FmuError::Invalid(format!(
                    "{seed_name} = {} for {} is not finite",
                    Num(dv),
                    v.name
                )))
            }
        })
        .collect::<Result<Vec<_>, _>>()?;
    let mut column = vec![0.0; unknowns.len()];
    let mut sum = vec![0.0; unknowns.len()];
    for (known, dv) in knowns {
        inst.output_sensitivity(known, &mut column)?;
        for (s, c) in sum.iter_mut().zip(&column) {
            *s += c * dv;
        }
    }
    sensitivity.copy_from_slice(&sum);
    Ok(Status::Ok)
}

/// Time derivatives of the outputs `vr` of the orders `order` at the current communication point.
pub fn output_derivatives<M: Model>(
    inst: &mut Instance<M>,
    vr: &[u32],
    order: &[i32],
    value: &mut [f64],
) -> Result<Status, FmuError> {
    inst.resolve(vr, "Real")?;
    inst.get_output_derivatives(order, value).map(ok)
}
