//! The rows of one lubricated joint's heat balance ([`thermal_rows!`]), the same for the three
//! joints of [`super::joints`]: its thermal model and start, heat capacity and conductance to the
//! housing, its film temperature, effective viscosity and heat flow, and the cycle's hottest film.

/// Number of rows of each joint's heat balance ([`thermal_rows`]).
pub(super) const THERMAL_ROWS: usize = 8;

/// Every row of a joint's heat balance. Arguments: the variable-name prefix, its name starting a
/// description, and the 8 value references in the order of the rows.
macro_rules! thermal_rows {
    (
        $prefix:literal,
        $label:literal,
        [
            $model:ident,
            $start:ident,
            $capacity:ident,
            $conductance:ident,
            $temperature:ident,
            $viscosity:ident,
            $heat:ident,
            $temperature_cycle:ident $(,)?
        ]
    ) => {
        [
            Variable::enumeration(
                Vr::$model,
                concat!($prefix, ".thermalModel"),
                1,
                THERMAL_MODEL,
                concat!(
                    $label,
                    ": how the lubricated joint's oil gets its viscosity: ",
                    $prefix,
                    ".viscosity, constant (isoviscous), or oil.viscosity40/oil.viscosity100's law at the film's effective temperature, a state of the joint's heat balance (heatBalance)"
                ),
            ),
            Variable::enumeration(
                Vr::$start,
                concat!($prefix, ".thermalStart"),
                2,
                THERMAL_START,
                concat!(
                    $label,
                    ": where the heat balance's film temperature starts (thermalModel = heatBalance)"
                ),
            ),
            Variable::parameter(
                Vr::$capacity,
                concat!($prefix, ".heatCapacity"),
                20.0,
                0.1,
                1e6,
                "J/K",
                concat!(
                    $label,
                    ": heat capacity that follows the film's temperature (the film and the near-surface metal of journal and shell); it sets how fast the film temperature follows the load and the supply"
                ),
            ),
            Variable::parameter(
                Vr::$conductance,
                concat!($prefix, ".heatTransferCoefficient"),
                0.0,
                0.0,
                1e6,
                "W/K",
                concat!(
                    $label,
                    ": conductance from the film to the housing, at oil.supplyTemperature (0: the oil flow alone carries the heat away, the standards' adiabatic bearing)"
                ),
            ),
            Variable::output(
                Vr::$temperature,
                concat!($prefix, ".filmTemperature"),
                "K",
                concat!(
                    $label,
                    ": effective film temperature (the mean of the oil's inlet and outlet) of the heat balance; 0 without one (isoviscous, dry and ideal joints)"
                ),
            ),
            Variable::output(
                Vr::$viscosity,
                concat!($prefix, ".viscosityEffective"),
                "Pa.s",
                concat!(
                    $label,
                    ": the oil's viscosity in the film: at ",
                    $prefix,
                    ".filmTemperature with a heat balance, else ",
                    $prefix,
                    ".viscosity; 0 for dry and ideal joints"
                ),
            ),
            Variable::output(
                Vr::$heat,
                concat!($prefix, ".heatFlow"),
                "W",
                concat!(
                    $label,
                    ": heat the oil flowing through the bearing carries away to the circuit, rho c_p Q (T_out - T_in) = 2 rho c_p ",
                    $prefix,
                    ".oilFlow (",
                    $prefix,
                    ".filmTemperature - oil.supplyTemperature); 0 without a heat balance"
                ),
            ),
            Variable::peak(
                Vr::$temperature_cycle,
                concat!($prefix, ".filmTemperatureMaxCycle"),
                "K",
                concat!(
                    "Largest ",
                    $prefix,
                    ".filmTemperature over the last complete load cycle (at the internal steps' ends; see ",
                    $prefix,
                    ".filmThicknessMinCycle)"
                ),
            ),
        ]
    };
}

pub(super) use thermal_rows;
