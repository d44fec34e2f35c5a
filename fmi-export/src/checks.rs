//! The checks of the generic layer on every call's arguments, against the model's variable table
//! and the instance's state: a value reference names a variable of the call's type, a value to
//! set is settable now and inside its declared range (or one of a switch's items), input
//! derivatives are of an allowed order, and a step starts at the current time and ends by the
//! stop time. Each refusal names the variable, the value and what is allowed.

use crate::error::FmuError;
use crate::model::{Model, Var};
use crate::number::Num;
use crate::state::State;
use crate::table::{Causality, Kind, ValueReference, Variable};

/// The variable of value reference `vr` in `table`, if it exists and is of FMI type `base`: FMI 2's
/// "Real", "Integer" (switches included), "Boolean" or "String", or FMI 3's "Float64", "Int32"
/// and "Int64" (the switches, FMI 3 Enumerations).
pub fn lookup<V: ValueReference>(
    table: &'static [Variable<V>],
    vr: u32,
    base: &str,
) -> Result<&'static Variable<V>, FmuError> {
    let v = table
        .get(vr as usize)
        .ok_or_else(|| FmuError::Invalid(format!("unknown value reference {vr}")))?;
    let matches = matches!(
        (v.kind, base),
        (Kind::Real { .. }, "Real" | "Float64")
            | (Kind::Integer { .. } | Kind::Enumeration { .. }, "Integer")
            | (Kind::Integer { .. }, "Int32")
            | (Kind::Enumeration { .. }, "Int64")
            | (Kind::Boolean, "Boolean")
            | (Kind::String { .. }, "String")
    );
    if matches {
        Ok(v)
    } else {
        Err(FmuError::Invalid(format!(
            "value reference {vr} ({}) is not of type {base}",
            v.name
        )))
    }
}

/// Checks that `v` may be set in machine state `state`: parameters until initialization ends,
/// inputs always, nothing else.
pub fn check_settable<V>(state: State, v: &Variable<V>) -> Result<(), FmuError> {
    let ok = match v.causality {
        Causality::Parameter => {
            matches!(state, State::Instantiated | State::InitializationMode)
        }
        // FMI 3's Configuration Mode sets structural parameters only.
        Causality::Input => state != State::ConfigurationMode,
        _ => false,
    };
    if ok {
        Ok(())
    } else {
        Err(FmuError::Invalid(format!(
            "variable {} ({:?}) cannot be set in state {state:?}",
            v.name, v.causality
        )))
    }
}

/// Checks a Real value against the declared range of `v` (finite, within [min, max]).
pub fn check_real<V>(v: &Variable<V>, value: f64) -> Result<(), FmuError> {
    if let Kind::Real { min, max, unit, .. } = v.kind {
        if !(value.is_finite() && min <= value && value <= max) {
            return Err(FmuError::Invalid(format!(
                "{} = {} is outside the allowed range [{}, {}] {unit}",
                v.name,
                Num(value),
                Num(min),
                Num(max)
            )));
        }
    }
    Ok(())
}

/// Resolves each of `vrs` to its variable of `M`, which must be of FMI type `base`, into `out`
/// (cleared first; its capacity is reused, so that a call allocates only when it names more
/// variables than any call before).
pub fn resolve<M: Model>(
    vrs: &[u32],
    base: &str,
    out: &mut Vec<Var<M::Vr>>,
) -> Result<(), FmuError> {
    out.clear();
    for &vr in vrs {
        out.push(lookup(M::VARIABLES, vr, base)?);
    }
    Ok(())
}

/// Checks that each of the Real variables `vars` is settable in `state` and its value inside the
/// declared range.
pub fn check_set_real<V>(state: State, vars: &[Var<V>], values: &[f64]) -> Result<(), FmuError> {
    for (v, &value) in vars.iter().zip(values) {
        check_settable(state, v)?;
        check_real(v, value)?;
    }
    Ok(())
}

/// Checks that each of the Integer variables `vars` of `M` (switches among them) is settable in
/// `state`, its value inside the declared range or one of the switch's items.
pub fn check_set_integer<M: Model>(
    state: State,
    vars: &[Var<M::Vr>],
    values: &[i32],
) -> Result<(), FmuError> {
    for (v, &value) in vars.iter().zip(values) {
        check_settable(state, v)?;
        let (min, max) = match v.kind {
            Kind::Integer { min, max, .. } => (min, max),
            Kind::Enumeration { type_index, .. } => {
                let items = M::ENUMERATIONS.get(type_index).map_or(0, |e| e.items.len());
                (1, i32::try_from(items).unwrap_or(i32::MAX))
            }
            _ => (0, -1),
        };
        if !(min..=max).contains(&value) {
            return Err(FmuError::Invalid(format!(
                "{} = {value} is outside the allowed range [{min}, {max}]",
                v.name
            )));
        }
    }
    Ok(())
}

/// Checks fmi2SetRealInputDerivatives' arguments: each of `vrs` a Real input of `M` (resolved
/// into `out`, as by [`resolve`]), each order from 1 to [`Model::MAX_INPUT_DERIVATIVE_ORDER`],
/// each value finite.
pub fn check_input_derivatives<M: Model>(
    vrs: &[u32],
    orders: &[i32],
    values: &[f64],
    out: &mut Vec<Var<M::Vr>>,
) -> Result<(), FmuError> {
    let max = M::MAX_INPUT_DERIVATIVE_ORDER;
    out.clear();
    for ((&vr, &order), &value) in vrs.iter().zip(orders).zip(values) {
        let v = check_causality::<M>(vr, Causality::Input, "vr")?;
        out.push(v);
        let order_ok = u32::try_from(order).is_ok_and(|o| (1..=max).contains(&o));
        if !order_ok || !value.is_finite() {
            return Err(FmuError::Invalid(format!(
                "derivative of order {order} of {} = {}: the order must be 1 to {max} and the \
                 value finite",
                v.name,
                Num(value)
            )));
        }
    }
    Ok(())
}

/// The Real variable `vr` of `M` if it has `causality`; else an error naming the argument `arg`.
pub fn check_causality<M: Model>(
    vr: u32,
    causality: Causality,
    arg: &str,
) -> Result<&'static Variable<M::Vr>, FmuError> {
    let v = lookup(M::VARIABLES, vr, "Real")?;
    if v.causality == causality {
        Ok(v)
    } else {
        Err(FmuError::Invalid(format!(
            "{arg}: value reference {vr} ({}) is not a Real {}",
            v.name,
            format!("{causality:?}").to_lowercase()
        )))
    }
}

/// Checks that each of the variables `vars` (Boolean, String: no range) is settable in `state`.
pub fn check_set_all<V>(state: State, vars: &[Var<V>]) -> Result<(), FmuError> {
    vars.iter().try_for_each(|v| check_settable(state, v))
}
