//! The slider-crank against closed-form kinematics, energy conservation and balance, the
//! clearance → 0 limit, benchmark A's impact physics, the lubricated orbit, and the determinism
//! the FMU relies on. The shared imports and helpers are here, the tests in the modules.

// Test code: a failed unwrap is a failed test, with its message.
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod balance;
mod bearings;
mod contract;
mod crank_pin;
mod domain;
mod impacts;
mod joints;
mod load_table;
mod loads;
mod machine;
mod motion;
mod sampled_rod;
mod start;

use flexible_slider_crank::ancf::RodProperties;
use flexible_slider_crank::integrator::Method;
use flexible_slider_crank::math;
use flexible_slider_crank::params::{
    BENCHMARK_SPEED, ContactLaw, DriveMode, FilmModel, InitialState, JointModel, JointParameters,
    JointRole, RodFormulation,
};
use flexible_slider_crank::reduction::Quadrature;
use flexible_slider_crank::{InputSignal, Outputs, Parameters, Simulation};

pub(crate) const REVOLUTION: f64 = std::f64::consts::TAU / BENCHMARK_SPEED;

/// Outputs at `n` equal intervals up to `t_end` (first row at t = 0).
pub(crate) fn run(p: Parameters, t_end: f64, n: usize) -> (Simulation, Vec<Outputs>) {
    let mut sim = Simulation::new(p).unwrap();
    let mut rows = vec![sim.outputs().unwrap()];
    for i in 1..=n {
        sim.advance_to(t_end * i as f64 / n as f64).unwrap();
        rows.push(sim.outputs().unwrap());
    }
    (sim, rows)
}
