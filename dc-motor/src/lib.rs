//! An FMI 2.0 and FMI 3.0 co-simulation FMU of a DC motor with a PI speed controller, driving a load through
//! a torsional shaft: the load's speed in, the shaft torque out. Coupled to the torque-driven
//! slider-crank FMU it makes a motor–mechanism system (shipped as an SSP and an OSP system
//! structure). Built on the same FMI layer, `fmi-export`, as the slider-crank.
//!
//! [`motor`] holds the equations, [`coupling`] the stability of the shaft's coupling to its load,
//! [`fmu`] the FMI model, [`variables`] the variable table.

pub mod coupling;
pub mod fmu;
pub mod motor;
pub mod variables;

fmi_export::model_identity!(variables::DESCRIPTION);

fmi_export::export_fmi2!(fmu::DcMotorFmu);
fmi_export::export_fmi3!(fmu::DcMotorFmu);
