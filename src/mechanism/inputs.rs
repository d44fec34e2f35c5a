//! The mechanism's inputs, as values and as functions of time over a communication interval.

use fmi_core::signal::{InputValues, Polynomial};

use crate::joint::Contacts;

/// The oil's supply temperature when none is given: 40 °C \[K\].
pub const SUPPLY_TEMPERATURE: f64 = 313.15;

/// The oil's supply pressure when none is given: 2 bar above ambient \[Pa\].
pub const SUPPLY_PRESSURE: f64 = 2e5;

/// Inputs that the caller may change between steps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Inputs {
    /// Prescribed crank speed \[rad/s\] (speed drive).
    pub drive_speed: f64,
    /// Crank torque \[N m\] (torque drive).
    pub drive_torque: f64,
    /// External force on the slider along the guide \[N\].
    pub slider_force: f64,
    /// The oil's supply temperature, to the lubricated joints' heat balances \[K\].
    pub oil_supply_temperature: f64,
    /// The oil's supply (gauge) pressure, to the lubricated joints' feeds \[Pa\].
    pub oil_supply_pressure: f64,
}

/// One of the [`Inputs`], in the order of the input variables.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Input {
    /// [`Inputs::drive_speed`].
    DriveSpeed,
    /// [`Inputs::drive_torque`].
    DriveTorque,
    /// [`Inputs::slider_force`].
    SliderForce,
    /// [`Inputs::oil_supply_temperature`].
    OilSupplyTemperature,
    /// [`Inputs::oil_supply_pressure`].
    OilSupplyPressure,
}

impl Input {
    /// Every input, in the order of the input variables.
    pub const ALL: [Self; 5] = [
        Self::DriveSpeed,
        Self::DriveTorque,
        Self::SliderForce,
        Self::OilSupplyTemperature,
        Self::OilSupplyPressure,
    ];
}

impl Default for Inputs {
    /// No drive speed, torque or slider force; the oil supplied at [`SUPPLY_TEMPERATURE`] and
    /// [`SUPPLY_PRESSURE`].
    fn default() -> Self {
        Self {
            oil_supply_temperature: SUPPLY_TEMPERATURE,
            oil_supply_pressure: SUPPLY_PRESSURE,
            ..<Self as InputValues>::ZERO
        }
    }
}

impl Inputs {
    /// The inputs a model starts with when none are given: the prescribed speed equal to the
    /// crank's initial speed (`drive.speed`'s start value if it is not set), no torque, no slider
    /// force, the oil supplied at [`SUPPLY_TEMPERATURE`] and [`SUPPLY_PRESSURE`].
    pub fn at_start(p: &crate::params::Parameters) -> Self {
        Self {
            drive_speed: p
                .crank_initial_speed
                .unwrap_or(crate::params::BENCHMARK_SPEED),
            ..Self::default()
        }
    }

    /// The value of one input.
    pub fn get(&self, input: Input) -> f64 {
        match input {
            Input::DriveSpeed => self.drive_speed,
            Input::DriveTorque => self.drive_torque,
            Input::SliderForce => self.slider_force,
            Input::OilSupplyTemperature => self.oil_supply_temperature,
            Input::OilSupplyPressure => self.oil_supply_pressure,
        }
    }

    /// The value of one input, to change.
    pub fn get_mut(&mut self, input: Input) -> &mut f64 {
        match input {
            Input::DriveSpeed => &mut self.drive_speed,
            Input::DriveTorque => &mut self.drive_torque,
            Input::SliderForce => &mut self.slider_force,
            Input::OilSupplyTemperature => &mut self.oil_supply_temperature,
            Input::OilSupplyPressure => &mut self.oil_supply_pressure,
        }
    }
}

impl InputValues for Inputs {
    const LEN: usize = 5;
    const ZERO: Self = Self {
        drive_speed: 0.0,
        drive_torque: 0.0,
        slider_force: 0.0,
        oil_supply_temperature: 0.0,
        oil_supply_pressure: 0.0,
    };
    fn value(&self, k: usize) -> f64 {
        self.get(Input::ALL[k])
    }
    fn value_mut(&mut self, k: usize) -> &mut f64 {
        self.get_mut(Input::ALL[k])
    }
}

/// The inputs as functions of time over a communication interval: their values and first and
/// second time derivatives at `start`,
/// ```text
/// u(t) = u + u̇ (t − t₀) + ü (t − t₀)²/2
/// ```
/// (the polynomial input of FMI co-simulation; held inputs have zero derivatives).
pub type InputSignal = Polynomial<Inputs>;

/// What one evaluation of the mechanism depends on besides its state: the inputs at the
/// evaluation's time with the prescribed speed's rate there, and the joints' contact states. The
/// inputs and the contact states have their owners (the FMU's instance or a simulation, and the
/// simulation's engine); an evaluation borrows them.
#[derive(Clone, Copy, Debug)]
pub struct Conditions<'a> {
    /// The inputs' values.
    pub inputs: Inputs,
    /// dω_in/dt \[rad/s²\] (speed drive).
    pub drive_acceleration: f64,
    /// The joints' contact states.
    pub contacts: &'a Contacts,
}

impl<'a> Conditions<'a> {
    /// The inputs of `signal` at `t` with the contact states `contacts`.
    pub fn at(signal: &InputSignal, t: f64, contacts: &'a Contacts) -> Self {
        Self {
            inputs: signal.at(t),
            drive_acceleration: signal.rate(t).drive_speed,
            contacts,
        }
    }

    /// The inputs `inputs`, held (no rate), with the contact states `contacts`.
    pub fn held(inputs: Inputs, contacts: &'a Contacts) -> Self {
        Self {
            inputs,
            drive_acceleration: 0.0,
            contacts,
        }
    }
}
