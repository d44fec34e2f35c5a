//! The variable table of the lubrication-circuit FMU: one row per FMI variable, in
//! value-reference order.
//!
//! Plain data over the table types of `fmi-export`: `build.rs` renders `modelDescription.xml`
//! from [`DESCRIPTION`], and the FMU reads and writes values through an exhaustive `match` on
//! [`Vr`], so the code and the XML cannot disagree.

pub use fmi_core::description::Description;
pub use fmi_core::interface::Fmi3Interface;
pub use fmi_core::table::{Causality, Kind, ValueReference};

/// One variable of this FMU.
pub type Variable = fmi_core::table::Variable<Vr>;

/// FMI 3 additions: none (no terminals, events or arrays).
pub const FMI3: Fmi3Interface = Fmi3Interface::NONE;

/// Everything modelDescription.xml says.
pub const DESCRIPTION: Description<Vr> = Description {
    model_identifier: "LubricationCircuit",
    description: "Lubrication circuit of a crank train: a pump with a pressure-relief valve feeding the bearings' gallery, a sump and an oil cooler; the bearings' oil and heat flows in, the oil's supply pressure and temperature out",
    author: "The FlexibleSliderCrank authors",
    version: env!("CARGO_PKG_VERSION"),
    copyright: "Copyright (c) 2026 The FlexibleSliderCrank authors",
    license: "MIT",
    generation_tool: "lube-circuit build.rs (fmi-export)",
    max_input_derivative_order: 2,
    max_output_derivative_order: 0,
    units: UNITS,
    display_units: &[],
    variable_display_units: &[],
    enumerations: &[],
    log_categories: LOG_CATEGORIES,
    default_experiment: (0.0, 1.0, 1e-6, 1e-3),
    variables: VARIABLES,
    feedthrough: &[],
    rate_feedthrough: &[],
    initial_dependency,
    provides_directional_derivative: true,
};

/// Units: name and SI base-unit exponents (kg, m, s, A, K, rad).
pub const UNITS: &[(&str, Option<[i32; 6]>, f64)] = &[
    ("s", Some([0, 0, 1, 0, 0, 0]), 1.0),
    ("1", Some([0, 0, 0, 0, 0, 0]), 1.0),
    ("K", Some([0, 0, 0, 0, 1, 0]), 1.0),
    ("Pa", Some([1, -1, -2, 0, 0, 0]), 1.0),
    ("W", Some([1, 2, -3, 0, 0, 0]), 1.0),
    ("m3", Some([0, 3, 0, 0, 0, 0]), 1.0),
    ("m3/s", Some([0, 3, -1, 0, 0, 0]), 1.0),
    ("m3/(s.Pa)", Some([-1, 4, 1, 0, 0, 0]), 1.0),
    ("kg/m3", Some([1, -3, 0, 0, 0, 0]), 1.0),
    ("J/(kg.K)", Some([0, 2, -2, 0, -1, 0]), 1.0),
];

/// Log categories.
pub const LOG_CATEGORIES: &[(&str, &str)] = &[
    ("logEvents", "Initialisation and step information"),
    ("logStatusWarning", "Warnings"),
    (
        "logStatusError",
        "Errors: illegal calls, invalid arguments and parameters",
    ),
    ("logAll", "Everything"),
];

/// Value references.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum Vr {
    PumpFlow = 0,
    ReliefPressure,
    ReliefConductance,
    GalleryVolume,
    GalleryBulkModulus,
    SumpVolume,
    OilDensity,
    OilSpecificHeat,
    CoolerEffectiveness,
    CoolantTemperature,
    SumpInitialTemperature,
    MainBearingOilFlow,
    CrankPinOilFlow,
    JointOilFlow,
    MainBearingHeatFlow,
    CrankPinHeatFlow,
    JointHeatFlow,
    SupplyPressure,
    SupplyTemperature,
    SumpTemperature,
    ReliefFlow,
    CoolerHeatFlow,
    SolverWarnings,
}

impl ValueReference for Vr {
    fn index(self) -> u32 {
        self as u32
    }
}

/// The inputs, in table order: the bearings' oil flows, then their heat flows.
pub const INPUTS: [Vr; 6] = [
    Vr::MainBearingOilFlow,
    Vr::CrankPinOilFlow,
    Vr::JointOilFlow,
    Vr::MainBearingHeatFlow,
    Vr::CrankPinHeatFlow,
    Vr::JointHeatFlow,
];

/// Whether an output depends, in initialization mode, on an input or a parameter: the
/// `dependencies` of ModelStructure/InitialUnknowns. The gallery starts at its steady pressure
/// for the bearings' oil flows (above cracking where the pump delivers more, else zero), where
/// the relief valve passes the pump's surplus, whatever its setting; the sump starts at
/// `sump.initialTemperature`; the supply temperature and the cooler's heat flow follow from the
/// sump's and the cooler's.
fn initial_dependency(unknown: Vr, known: Vr) -> bool {
    use Vr::*;
    let surplus = matches!(
        known,
        PumpFlow | MainBearingOilFlow | CrankPinOilFlow | JointOilFlow
    );
    match unknown {
        SupplyPressure => surplus || matches!(known, ReliefPressure | ReliefConductance),
        ReliefFlow => surplus,
        SupplyTemperature => matches!(
            known,
            SumpInitialTemperature | CoolerEffectiveness | CoolantTemperature
        ),
        SumpTemperature => known == SumpInitialTemperature,
        CoolerHeatFlow => matches!(
            known,
            SumpInitialTemperature
                | CoolerEffectiveness
                | CoolantTemperature
                | PumpFlow
                | OilDensity
                | OilSpecificHeat
        ),
        // The warnings count starts at zero.
        _ => false,
    }
}

/// Every variable, in value-reference order.
pub const VARIABLES: &[Variable] = &[
    Variable::parameter(
        Vr::PumpFlow,
        "pump.flow",
        5e-6,
        1e-9,
        1.0,
        "m3/s",
        "Delivery of the fixed-displacement pump into the gallery (5 cm3/s = 0.3 L/min)",
    ),
    Variable::parameter(
        Vr::ReliefPressure,
        "relief.pressure",
        2e5,
        0.0,
        1e8,
        "Pa",
        "Gauge pressure at which the relief valve cracks open, returning the pump's surplus to the sump",
    ),
    Variable::parameter(
        Vr::ReliefConductance,
        "relief.conductance",
        1e-10,
        1e-15,
        1e-3,
        "m3/(s.Pa)",
        "Flow through the open relief valve per pascal above relief.pressure",
    ),
    Variable::parameter(
        Vr::GalleryVolume,
        "gallery.volume",
        2e-5,
        1e-9,
        1.0,
        "m3",
        "Oil volume of the gallery (pipes and drillings from the pump to the bearings): with gallery.bulkModulus its hydraulic capacitance",
    ),
    Variable::parameter(
        Vr::GalleryBulkModulus,
        "gallery.bulkModulus",
        1.5e9,
        1e6,
        1e11,
        "Pa",
        "Bulk modulus of the oil in the gallery (with the air it holds)",
    ),
    Variable::parameter(
        Vr::SumpVolume,
        "sump.volume",
        5e-4,
        1e-6,
        100.0,
        "m3",
        "Oil volume of the sump (well mixed)",
    ),
    Variable::parameter(
        Vr::OilDensity,
        "oil.density",
        870.0,
        500.0,
        2000.0,
        "kg/m3",
        "Oil density (the slider-crank's oil.density)",
    ),
    Variable::parameter(
        Vr::OilSpecificHeat,
        "oil.specificHeat",
        2000.0,
        500.0,
        5000.0,
        "J/(kg.K)",
        "Oil specific heat capacity (the slider-crank's oil.specificHeat)",
    ),
    Variable::parameter(
        Vr::CoolerEffectiveness,
        "cooler.effectiveness",
        0.5,
        0.0,
        1.0,
        "1",
        "Effectiveness of the oil cooler the pump's whole flow passes: the fraction of the sump's temperature above the coolant's it takes out (0: no cooler)",
    ),
    Variable::parameter(
        Vr::CoolantTemperature,
        "cooler.coolantTemperature",
        308.15,
        200.0,
        600.0,
        "K",
        "Temperature of the cooler's coolant (35 degC)",
    ),
    Variable::parameter(
        Vr::SumpInitialTemperature,
        "sump.initialTemperature",
        313.15,
        200.0,
        600.0,
        "K",
        "Temperature of the sump's oil at the start (40 degC)",
    ),
    Variable::input(
        Vr::MainBearingOilFlow,
        "mainBearing.oilFlow",
        0.0,
        0.0,
        1.0,
        "m3/s",
        "Oil flow through the main bearing, drawn from the gallery (the slider-crank's mainBearing.oilFlow)",
    ),
    Variable::input(
        Vr::CrankPinOilFlow,
        "crankPin.oilFlow",
        0.0,
        0.0,
        1.0,
        "m3/s",
        "Oil flow through the crank pin, drawn from the gallery (the slider-crank's crankPin.oilFlow)",
    ),
    Variable::input(
        Vr::JointOilFlow,
        "joint.oilFlow",
        0.0,
        0.0,
        1.0,
        "m3/s",
        "Oil flow through the rod-slider joint, drawn from the gallery (the slider-crank's joint.oilFlow)",
    ),
    Variable::input(
        Vr::MainBearingHeatFlow,
        "mainBearing.heatFlow",
        0.0,
        -1e9,
        1e9,
        "W",
        "Heat the main bearing's oil carries back to the sump (the slider-crank's mainBearing.heatFlow)",
    ),
    Variable::input(
        Vr::CrankPinHeatFlow,
        "crankPin.heatFlow",
        0.0,
        -1e9,
        1e9,
        "W",
        "Heat the crank pin's oil carries back to the sump (the slider-crank's crankPin.heatFlow)",
    ),
    Variable::input(
        Vr::JointHeatFlow,
        "joint.heatFlow",
        0.0,
        -1e9,
        1e9,
        "W",
        "Heat the rod-slider joint's oil carries back to the sump (the slider-crank's joint.heatFlow)",
    ),
    Variable::output(
        Vr::SupplyPressure,
        "oil.supplyPressure",
        "Pa",
        "Gauge pressure of the gallery: the bearings' supply pressure (to the slider-crank's oil.supplyPressure); 0 when the bearings draw more than the pump delivers",
    ),
    Variable::output(
        Vr::SupplyTemperature,
        "oil.supplyTemperature",
        "K",
        "Temperature of the oil leaving the cooler for the bearings (to the slider-crank's oil.supplyTemperature)",
    ),
    Variable::output(
        Vr::SumpTemperature,
        "sump.temperature",
        "K",
        "Temperature of the sump's oil",
    ),
    Variable::output(
        Vr::ReliefFlow,
        "relief.flow",
        "m3/s",
        "Flow the relief valve returns to the sump",
    ),
    Variable::output(
        Vr::CoolerHeatFlow,
        "cooler.heatFlow",
        "W",
        "Heat the cooler takes out of the oil",
    ),
    Variable::count(
        Vr::SolverWarnings,
        "solver.warnings",
        "Warnings since the start: each time the gallery empties (the bearings draw more oil than the pump delivers)",
    ),
];
