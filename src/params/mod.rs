//! Parameters of the slider-crank model, in SI units, with defaults = benchmark B (docs/model.md §5(b))
//! (steel ANCF rod, 8 elements, 4 mode shapes, dry clearance joint, 5000 rpm speed drive).
//!
//! Every check names the FMU parameter, its value and the allowed range.

mod access;
mod parameters;
mod validate;

pub use crate::joint::{
    ContactGeometry, ContactLaw, FeedLocation, FeedModel, FilmModel, JointModel, JointParameters,
    JointRole, JournalStart, OilParameters, ThermalModel, ThermalStart,
};
pub use access::{
    integer_parameter, real_parameter, set_integer_parameter, set_real_parameter,
    set_string_parameter, string_parameter,
};
pub use parameters::{
    BENCHMARK_SPEED, DEFAULT_MAX_STEPS_PER_INTERVAL, DEFAULT_SPECTRAL_RADIUS, DriveMode,
    EXPLICIT_MAX_TOLERANCE, GENERALIZED_ALPHA_MAX_TOLERANCE, InitialState, Parameters,
    RodFormulation,
};
