//! The slider-crank with its integrator: the [`Engine`] the FMU drives with its instance's clock
//! and inputs, and the [`Simulation`] that drives it with its own — parameters in,
//! `advance_to(t)`, outputs out — for the examples, the benchmarks and the tests.

pub mod codec;
mod cycle;
mod end_sample;
mod engine;
mod failure;
mod interval;
mod onset;
mod outputs;
mod peaks;
mod reading;
mod record;
mod restore;
mod sample;
mod snapshot;
mod standalone;
mod step;
pub mod validity;
mod within;

pub use self::cycle::{Cycle, CycleHold, CycleStep, Extreme, JointCycle};
pub use self::engine::Engine;
pub use self::outputs::{BearingOutputs, Outputs};
pub use self::peaks::{PeakHold, Peaks};
pub use self::snapshot::Snapshot;
pub use self::standalone::{Simulation, SimulationSnapshot};
pub use self::step::{Advance, Mode, Onset, StepPoint};
pub use crate::ancf::{SectionResult, section_place};
pub use crate::mechanism::{Input, InputSignal, Inputs};
pub use fmi_core::signal::InputRecord;

pub use fmi_core::clock::{CLOCK_RESOLUTION, on_clock_grid};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Parameters;
    use fmi_core::signal::InputValues;

    /// An input that does not act in the drive mode (the torque with the speed drive) leaves the
    /// step sequence alone: the run equals one without it, bit for bit.
    #[test]
    fn an_input_that_does_not_act_restarts_nothing() {
        let mut held = Simulation::new(Parameters::default()).unwrap();
        let mut changed = held.clone();
        let mut inputs = *held.inputs();
        for k in 1..=20 {
            inputs.value.drive_torque = f64::from(k);
            let t = f64::from(k) * 1e-4;
            held.advance_to(t).unwrap();
            changed.advance_with(&inputs, t).unwrap();
        }
        assert_eq!(held.state(), changed.state());
        assert_eq!(held.stats(), changed.stats());
    }

    /// Input derivatives make the prescribed speed the polynomial ω + ω̇ (t − t₀) + ω̈ (t − t₀)²/2
    /// over one interval: the crank follows it (to the constraint stabilisation's accuracy), and
    /// held afterwards at the value the polynomial reached, it stays there.
    #[test]
    fn input_derivatives_make_the_input_a_polynomial_for_one_interval() {
        let mut sim = Simulation::new(Parameters::default()).unwrap();
        sim.advance_to(1e-4).unwrap();
        let mut inputs = *sim.inputs();
        let speed = inputs.value.drive_speed;
        let (rate, curvature, h) = (2.0e4, -3.0e7, 2e-4);
        inputs.derivatives[0].drive_speed = rate;
        inputs.derivatives[1].drive_speed = curvature;
        sim.advance_with(&inputs, 1e-4 + h).unwrap();
        let expected = speed + rate * h + 0.5 * curvature * h * h;
        let speed = sim.mechanism().layout().crank_speed();
        let crank_speed = sim.state()[speed];
        assert!(
            (crank_speed - expected).abs() < 1e-6 * expected,
            "{crank_speed} vs {expected}"
        );
        // (to the rounding of the communication points to the clock grid)
        let reached = sim.inputs().at(sim.time()).drive_speed;
        assert!((reached - expected).abs() < 1e-10 * expected, "{reached}");
        sim.advance_to(1e-4 + 2.0 * h).unwrap();
        assert_eq!(sim.inputs().derivatives, [<Inputs as InputValues>::ZERO; 2]);
        let held = sim.state()[speed];
        assert!(
            (held - expected).abs() < 1e-9 * expected,
            "{held} vs {expected}"
        );
    }
}
