//! A small single-cylinder four-stroke engine at 3000 rpm: crank 22 mm, steel rod of 85 mm with an
//! 8 × 15 mm section (4 mode shapes), 0.25 kg piston; lubricated crank pin and main bearing
//! (10 mm journals, 15 mm long, 25 µm clearance, oil of 0.01 Pa s) and a dry piston pin (6 mm,
//! 20 µm); every journal settled. Its firing load comes from a polytropic cycle with a Wiebe
//! combustion pulse, fed to `slider.force` as a master with interpolated inputs does: at each
//! 1e-4 s communication point the quadratic over the next step, as its value and first and second
//! time derivatives. Shared by the bearing tests and `examples/bearing_design.rs`.
//!
//! The cycle (crank angle θ from the gas-exchange top dead centre, firing at θ = 360°): intake
//! and exhaust at p₀ = 1 bar; compression and expansion p_m = p₀ (V_bdc/V)^1.3 with the volume
//! V = V_c + A s(θ), s = r (1 − cos θ) + l − √(l² − r² sin² θ), compression ratio 9; combustion
//! p = p_m (1 + (λ − 1) x_b) with the Wiebe burnt fraction x_b = 1 − exp(−5 ((θ − 350°)/40°)³),
//! λ = 2.35; the exhaust valve opens at 500° and the pressure falls linearly to p₀ at the bottom
//! dead centre (540°). The piston (bore 50 mm) is pushed towards the crank by (p − p₀) A: a
//! firing peak of 5.2 kN at 16° after the firing top dead centre.

use std::f64::consts::PI;

use flexible_slider_crank::ancf::RodProperties;
use flexible_slider_crank::math;
use flexible_slider_crank::params::{JointModel, JointParameters, JournalStart};
use flexible_slider_crank::{InputSignal, ModelError, Outputs, Parameters, Simulation};

/// Crank speed: 3000 rpm \[rad/s\].
pub const SPEED: f64 = 3000.0 * 2.0 * PI / 60.0;
/// Crank radius and rod length \[m\].
const CRANK: f64 = 0.022;
const ROD: f64 = 0.085;
/// Communication step \[s\].
pub const STEP: f64 = 1e-4;
/// One four-stroke cycle, 720° \[s\].
pub const CYCLE: f64 = 4.0 * PI / SPEED;

/// The engine's parameters at the relative tolerance `rtol` (the library's default: 1e-2).
pub fn parameters(rtol: f64) -> Parameters {
    let bearing = JointParameters {
        model: JointModel::Lubricated,
        clearance: 25e-6,
        journal_radius: 0.01,
        bearing_length: 0.015,
        viscosity: 0.01,
        initial_state: JournalStart::Settled,
        ..JointParameters::benchmark()
    };
    let defaults = Parameters::default();
    Parameters {
        crank_length: CRANK,
        rod: RodProperties {
            length: ROD,
            area: 8e-3 * 15e-3,
            second_moment_of_area: 8e-3 * 15e-3f64.powi(3) / 12.0,
            outer_fibre_distance: 7.5e-3,
            ..defaults.rod
        },
        slider_mass: 0.25,
        crank_initial_speed: Some(SPEED),
        main_bearing: bearing,
        crank_pin: bearing,
        joint: JointParameters {
            model: JointModel::Dry,
            clearance: 20e-6,
            journal_radius: 6e-3,
            bearing_length: 0.018,
            initial_state: JournalStart::Settled,
            ..defaults.joint
        },
        relative_tolerance: rtol,
        ..defaults
    }
}

/// The gas force on the piston at the crank angle θ \[rad\] (negative: towards the crank) \[N\].
pub fn firing_load(theta: f64) -> f64 {
    let (p0, area, ratio, lambda) = (1e5, PI * 0.025 * 0.025, 9.0, 2.35);
    let deg = (theta * 180.0 / PI).rem_euclid(720.0);
    let (sin, cos) = math::sin_cos(theta);
    let stroke = CRANK * (1.0 - cos) + ROD - (ROD * ROD - CRANK * CRANK * sin * sin).sqrt();
    let clearance_volume = area * 2.0 * CRANK / (ratio - 1.0);
    let bottom = clearance_volume + area * 2.0 * CRANK;
    let polytropic = p0 * math::powf(bottom / (clearance_volume + area * stroke), 1.3);
    let burnt = if deg > 350.0 {
        1.0 - math::exp(-5.0 * ((deg - 350.0) / 40.0).powi(3))
    } else {
        0.0
    };
    let p = match deg {
        d if (180.0..=500.0).contains(&d) => polytropic * (1.0 + (lambda - 1.0) * burnt),
        d if d > 500.0 && d < 540.0 => {
            let open = polytropic * (1.0 + (lambda - 1.0) * burnt);
            p0 + (open - p0) * (540.0 - d) / 40.0
        }
        _ => p0,
    };
    -(p - p0) * area
}

/// Sets the firing load over the communication step from `t`: the quadratic through its values
/// at t, t + h/2 and t + h (h = [`STEP`], the crank at θ = Ω t), given as the value and first
/// and second time derivatives at t. Exact for a quadratic; at the cycle's kinks (the valve
/// events) its error is of the order of the load's change over one step, where derivatives
/// taken at one point would grow without bound as their difference step shrinks.
pub fn set_load(inputs: &mut InputSignal, t: f64) {
    let at = |s: f64| firing_load(SPEED * (t + s * STEP));
    let (f0, f1, f2) = (at(0.0), at(0.5), at(1.0));
    inputs.value.slider_force = f0;
    inputs.derivatives[0].slider_force = (4.0 * f1 - 3.0 * f0 - f2) / STEP;
    inputs.derivatives[1].slider_force = 4.0 * (f0 - 2.0 * f1 + f2) / (STEP * STEP);
}

/// Runs `cycles` cycles of the engine with the parameters `p`, calling `each` with the time and
/// the outputs at every communication point; returns the simulation.
pub fn run(
    p: Parameters,
    cycles: usize,
    mut each: impl FnMut(f64, &Outputs),
) -> Result<Simulation, ModelError> {
    let mut sim = Simulation::new(p)?;
    let mut inputs = *sim.inputs();
    let n = (cycles as f64 * CYCLE / STEP).round() as usize;
    for k in 0..n {
        set_load(&mut inputs, k as f64 * STEP);
        let t = (k + 1) as f64 * STEP;
        sim.advance_with(&inputs, t)?;
        each(t, &sim.outputs()?);
    }
    Ok(sim)
}
