//! The mechanism's inputs, as values and as functions of time over a communication interval.

use fmi_core::signal;

/// Inputs that the caller may change between steps.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Inputs {
    /// Prescribed crank speed \[rad/s\] (speed drive).
    pub drive_speed: f64,
    /// Crank torque \[N m\] (torque drive).
    pub drive_torque: f64,
    /// External force on the slider along the guide \[N\].
    pub slider_force: f64,
}

/// One of the [`Inputs`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Input {
    /// [`Inputs::drive_speed`].
    DriveSpeed,
    /// [`Inputs::drive_torque`].
    DriveTorque,
    /// [`Inputs::slider_force`].
    SliderForce,
}

impl Inputs {
    /// The inputs a model starts with when none are given: the prescribed speed equal to the
    /// crank's initial speed (`drive.speed`'s start value if it is not set), no torque, no slider
    /// force.
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
        }
    }

    /// The value of one input, to change.
    pub fn get_mut(&mut self, input: Input) -> &mut f64 {
        match input {
            Input::DriveSpeed => &mut self.drive_speed,
            Input::DriveTorque => &mut self.drive_torque,
            Input::SliderForce => &mut self.slider_force,
        }
    }

    fn combine(a: &Self, b: &Self, c: &Self, f: impl Fn(f64, f64, f64) -> f64) -> Self {
        Self {
            drive_speed: f(a.drive_speed, b.drive_speed, c.drive_speed),
            drive_torque: f(a.drive_torque, b.drive_torque, c.drive_torque),
            slider_force: f(a.slider_force, b.slider_force, c.slider_force),
        }
    }
}

/// The inputs as functions of time over a communication interval: their values and first and
/// second time derivatives at `start`,
/// ```text
/// u(t) = u + u̇ (t − t₀) + ü (t − t₀)²/2
/// ```
/// (the polynomial input of FMI 2.0 co-simulation; held inputs have zero derivatives).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct InputSignal {
    /// t₀ \[s\].
    pub start: f64,
    /// u(t₀).
    pub value: Inputs,
    /// u̇(t₀) and ü(t₀).
    pub derivatives: [Inputs; 2],
}

impl InputSignal {
    /// Inputs held at `value`.
    pub fn held(value: Inputs) -> Self {
        Self {
            value,
            ..Self::default()
        }
    }

    /// Values u(t) and rates u̇(t).
    pub fn at(&self, t: f64) -> (Inputs, Inputs) {
        let dt = t - self.start;
        let [first, second] = &self.derivatives;
        let value = Inputs::combine(&self.value, first, second, |u, d1, d2| {
            signal::value(u, d1, d2, dt)
        });
        let rate = Inputs::combine(first, second, second, |d1, d2, _| signal::rate(d1, d2, dt));
        (value, rate)
    }

    /// Whether the inputs that act (`acts`) are the same functions of time from `t` on in both.
    pub fn same_from(&self, other: &Self, t: f64, acts: impl Fn(Input) -> bool) -> bool {
        let (a, a_rate) = self.at(t);
        let (b, b_rate) = other.at(t);
        [Input::DriveSpeed, Input::DriveTorque, Input::SliderForce]
            .into_iter()
            .filter(|&i| acts(i))
            .all(|i| {
                a.get(i) == b.get(i)
                    && a_rate.get(i) == b_rate.get(i)
                    && self.derivatives[1].get(i) == other.derivatives[1].get(i)
            })
    }
}

/// What loads the mechanism: the inputs as functions of time, their values at the current time,
/// the load on the slider tied to the crank angle (`slider.forceTable`, added to the input), and
/// the speed drive's acceleration at the current time.
#[derive(Clone, Debug)]
pub(super) struct Loading {
    /// The inputs as functions of time.
    pub signal: InputSignal,
    /// The inputs at the time of the last `SliderCrank::set_time`.
    pub inputs: Inputs,
    /// The crank-angle load table, if any.
    pub table: Option<crate::load_table::LoadTable>,
    /// dω_in/dt at that time \[rad/s²\] (speed drive).
    pub drive_acceleration: f64,
}
