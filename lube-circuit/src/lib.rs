//! An FMI 2.0 and FMI 3.0 co-simulation FMU of a crank train's lubrication circuit: a pump with a
//! pressure-relief valve feeding the bearings' gallery, a sump and an oil cooler. Its inputs are
//! the bearings' oil and heat flows, its outputs the oil's supply pressure and temperature:
//! coupled to the slider-crank FMU (whose `oil.supplyPressure` and `oil.supplyTemperature` it
//! drives) it closes the lubrication loop in a system (shipped as an SSP and an OSP system
//! structure). Built on the same FMI layer, `fmi-export`, as the slider-crank.
//!
//! [`circuit`] holds the equations, [`fmu`] the FMI model, [`variables`] the variable table.

pub mod circuit;
pub mod fmu;
pub mod variables;

fmi_export::model_identity!(variables::DESCRIPTION);

fmi_export::export_fmi2!(fmu::LubricationCircuitFmu);
fmi_export::export_fmi3!(fmu::LubricationCircuitFmu);
