//! The oil of the lubricated joints' heat balances: its viscosity at 40 °C and 100 °C, density and
//! specific heat, and its supply temperature and pressure, inputs a lubrication-circuit model can
//! drive.

use super::vr::{Variable, Vr};

/// The oil's rows.
pub(super) const VARIABLES: &[Variable] = &[
    Variable::parameter(
        Vr::OilViscosity40,
        "oil.viscosity40",
        0.04,
        1e-5,
        100.0,
        "Pa.s",
        "Oil dynamic viscosity at 40 degC (the default: an ISO VG 46 mineral oil, 46 mm2/s at 870 kg/m3); with oil.viscosity100 it sets the viscosity-temperature law (Walther, ASTM D341) of every joint with thermalModel = heatBalance",
    ),
    Variable::parameter(
        Vr::OilViscosity100,
        "oil.viscosity100",
        0.0059,
        1e-6,
        10.0,
        "Pa.s",
        "Oil dynamic viscosity at 100 degC, below oil.viscosity40 (the default: 6.8 mm2/s at 870 kg/m3)",
    ),
    Variable::parameter(
        Vr::OilDensity,
        "oil.density",
        870.0,
        500.0,
        2000.0,
        "kg/m3",
        "Oil density (constant): converts the viscosities to the law's kinematic ones and the oil flow to a heat capacity flow",
    ),
    Variable::parameter(
        Vr::OilSpecificHeat,
        "oil.specificHeat",
        2000.0,
        500.0,
        5000.0,
        "J/(kg.K)",
        "Oil specific heat capacity",
    ),
    Variable::input(
        Vr::OilSupplyTemperature,
        "oil.supplyTemperature",
        313.15,
        200.0,
        600.0,
        "K",
        "Temperature at which the oil is fed to the bearings (the lubrication circuit's): the inlet of every heat balance and the housing's temperature (default 40 degC)",
    ),
];

/// The oil's supply pressure, the second input of a lubrication circuit.
pub(super) const SUPPLY: &[Variable] = &[Variable::input(
    Vr::OilSupplyPressure,
    "oil.supplyPressure",
    2e5,
    0.0,
    1e8,
    "Pa",
    "Gauge pressure at which the oil is fed to the bearings (the lubrication circuit's pump or gallery): it drives each fed joint's feedFlow through the clearance (default 2 bar)",
)];
