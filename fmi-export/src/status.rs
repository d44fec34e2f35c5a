//! The status of a call, free of either FMI version's C type: the core returns it, and each
//! version's functions turn it into their own code (FMI 2.0.4 §2.1.3 fmi2Status, FMI 3.0 §2.2.3
//! fmi3Status: the same five values).

/// How a call ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// It did what was asked.
    Ok,
    /// It did, with something the master should know (logged).
    Warning,
    /// It could not do it, and nothing changed (or a step ended early, FMI 2's fmi2Discard).
    Discard,
    /// It failed; the instance is in the Error state.
    Error,
    /// It failed beyond repair (never returned by this layer: a caught panic is an Error that
    /// poisons the instance).
    Fatal,
}

/// [`Status::Ok`] for a call that succeeded without a value.
pub fn ok(_: ()) -> Status {
    Status::Ok
}
