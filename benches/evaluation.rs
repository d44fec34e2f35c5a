//! Criterion benchmarks of one evaluation of the mechanism, per rod model (dry joint, benchmark B,
//! 8 elements, state at 1 ms of a default run): the right-hand side f(t, y) (rod forces evaluated
//! on every call), and one Jacobian update of the implicit integrator (2n + 1 right-hand sides by
//! forward differences plus the LU factorisation of the n × n Newton matrix).

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use flexible_slider_crank::integrator::{ESDIRK54, Implicit, OdeSystem, Scheme};
use flexible_slider_crank::mechanism::{Contacts, Driven, SliderCrank};
use flexible_slider_crank::params::JointParameters;
use flexible_slider_crank::params::{JointModel, RodFormulation};
use flexible_slider_crank::reduction::Boundary;
use flexible_slider_crank::{InputSignal, Inputs, Parameters, Simulation};

/// Time of the benchmarked state \[s\].
const T: f64 = 1e-3;

fn cases() -> Vec<(&'static str, Parameters)> {
    let dry = Parameters {
        joint: JointParameters {
            model: JointModel::Dry,
            ..Parameters::default().joint
        },
        ..Parameters::default()
    };
    let rod = |formulation, boundary, n_modes| Parameters {
        rod_formulation: formulation,
        boundary,
        n_modes,
        ..dry.clone()
    };
    vec![
        ("rigid", rod(RodFormulation::Rigid, Boundary::Pins, 0)),
        (
            "cb4_pins",
            rod(RodFormulation::CraigBampton, Boundary::Pins, 4),
        ),
        (
            "cb8_pins",
            rod(RodFormulation::CraigBampton, Boundary::Pins, 8),
        ),
        (
            "cb4_positions_and_slopes",
            rod(
                RodFormulation::CraigBampton,
                Boundary::PositionsAndSlopes,
                4,
            ),
        ),
        ("full_ancf", rod(RodFormulation::Ancf, Boundary::Pins, 0)),
    ]
}

/// The mechanism and its state at [`T`] of a default run.
fn setup(p: &Parameters) -> (SliderCrank, Vec<f64>) {
    let mut sim = match Simulation::new(p.clone()) {
        Ok(sim) => sim,
        Err(e) => panic!("{e}"),
    };
    if let Err(e) = sim.advance_to(T) {
        panic!("{e}");
    }
    match SliderCrank::new(p) {
        Ok(mechanism) => (mechanism, sim.state().to_vec()),
        Err(e) => panic!("{e}"),
    }
}

fn evaluation(c: &mut Criterion) {
    let mut group = c.benchmark_group("evaluation");
    for (name, p) in cases() {
        let (mut mechanism, y) = setup(&p);
        let signal = InputSignal::held(Inputs::at_start(&p));
        let mut contacts = Contacts::default();
        let mut driven = Driven {
            mechanism: &mut mechanism,
            signal: &signal,
            contacts: &mut contacts,
        };
        let mut dy = vec![0.0; y.len()];
        // Two states that differ in a rod coordinate, taken in turn: every call evaluates the
        // rod's forces (the rod model reuses them for unchanged coordinates).
        let mut moved = y.clone();
        moved[1] += 1e-12;
        let states = [y.clone(), moved];
        let mut turn = 0;
        group.bench_function(format!("rhs/{name}"), |b| {
            b.iter(|| {
                turn ^= 1;
                driven.rhs(T, black_box(&states[turn]), &mut dy)
            })
        });
        let mut esdirk = match Implicit::new(
            Scheme::Esdirk(&ESDIRK54),
            y.len(),
            driven.mechanism.n_coordinates(),
            p.tolerances(),
            driven.mechanism.error_scales(),
        ) {
            Ok(esdirk) => esdirk,
            Err(e) => panic!("{e}"),
        };
        group.bench_function(format!("jacobian/{name}"), |b| {
            b.iter(|| esdirk.update_jacobian(&mut driven, T, black_box(&y), 1e-5))
        });
    }
    group.finish();
}

criterion_group!(benches, evaluation);
criterion_main!(benches);
