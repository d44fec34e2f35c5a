//! The heat balance against independent solutions: a steadily loaded bearing's settled film
//! temperature, eccentricity and oil flow against a steady calculation of its own (the reference
//! Reynolds solution, the Walther law written anew, the standards' heat balance); the film
//! temperature's response to a step of the supply temperature against the first-order solution its
//! heat capacity and conductances give; and the heat balance closing in thermal steady state.

use super::*;
use flexible_slider_crank::params::{OilParameters, ThermalModel, ThermalStart};
use flexible_slider_crank::{InputSignal, Inputs, Outputs};

/// The Walther equation (ASTM D341) through ν₄₀ and ν₁₀₀ \[mm²/s\], written here apart from the
/// product's: (ν(T), T(ν)) with T in K.
pub(super) fn walther(nu40: f64, nu100: f64) -> (impl Fn(f64) -> f64, impl Fn(f64) -> f64) {
    let w = |nu: f64| (nu + 0.7).log10().log10();
    let b = (w(nu40) - w(nu100)) / (373.15f64.log10() - 313.15f64.log10());
    let a = w(nu40) + b * 313.15f64.log10();
    (
        move |t: f64| math::powf(10.0, math::powf(10.0, a - b * t.log10())) - 0.7,
        move |nu: f64| math::powf(10.0, (a - w(nu)) / b),
    )
}

/// A main bearing of the compressor (R 15 mm, L 20 mm, c 25 µm, ISO VG 46, the supply at 40 °C)
/// with a heat balance, settled in temperature and position, under a steady load: the crank at 90°
/// turning at 157 rad/s, a 2 kN slider force, rigid rod, ideal crank pin and rod–slider joint.
/// At the start the FMU reports its film temperature, eccentricity, smallest film and oil flow; an
/// independent steady calculation for the load and speed it reports — the reference Reynolds
/// solution of the steady film for the eccentricity, the Walther law for the viscosity, the
/// friction power of the film's Couette and pressure shear, the heat balance
/// P = 2 ρ c_p Q (T − T_s) + k (T − T_s) — gives the same temperature within 1 K (measured
/// below), the smallest film within 3 % and the oil flow within 10 %; adiabatic and with a
/// conductance to the housing. The temperature holds its steady value over the first 0.2 ms.
#[test]
fn a_steadily_loaded_bearing_settles_at_the_independent_heat_balance() {
    let oil = OilParameters::default();
    let (rho, cp) = (oil.density, oil.specific_heat);
    let (nu, temperature_of) = walther(1e6 * oil.viscosity40 / rho, 1e6 * oil.viscosity100 / rho);
    for conductance in [0.0, 2.0] {
        let (p, inputs) = steadily_loaded_main_bearing(conductance);
        let main_bearing = p.main_bearing;
        let supply = inputs.oil_supply_temperature;
        let mut sim = Simulation::with_inputs(p.clone(), inputs).unwrap();
        let o = sim.outputs().unwrap();
        let b = o.bearings[JointRole::MainBearing as usize];
        let load = o.main_bearing_force;
        // The independent steady state: for each ε the viscosity that carries the load, its
        // temperature by the inverse law, and the heat balance's surplus there; ε by secant.
        let (c, r, l) = (25e-6, 0.015, 0.02);
        let lambda = l / (2.0 * r);
        let omega = 157.0;
        let steady = |eps: f64| {
            let film = reference::film(lambda, eps, reference::STEADY);
            let v = 0.5 * eps * omega;
            let per_viscosity = 12.0 * v * r.powi(4) / (c * c);
            let mu = load / (per_viscosity * math::hypot(film.force[0], film.force[1]));
            let t = temperature_of(1e6 * mu / rho);
            let couette = std::f64::consts::TAU * mu * r.powi(3) * l * omega * omega
                / (c * (1.0 - eps * eps).sqrt());
            let pressure = 0.5 * eps * c * (mu * per_viscosity * film.force[1]).abs() * omega;
            let flow = 2.0 * c * r * r * v * film.side_flow;
            let surplus = couette + pressure - (2.0 * rho * cp * flow + conductance) * (t - supply);
            (surplus, t, flow)
        };
        let e1 = secant(|eps| steady(eps).0, (0.5, 0.7), 1e-7);
        let (_, t, flow) = steady(e1);
        let h_min = c * (1.0 - e1);
        println!(
            "k = {conductance} W/K, {load:.1} N: film {:.3} K vs {t:.3} K, ε {:.4} vs {e1:.4}, h_min \
             {:.3} µm vs {:.3} µm, flow {:.4e} vs {flow:.4e} m3/s, viscosity {:.5} vs {:.5} Pa s",
            b.film_temperature,
            b.eccentricity_ratio,
            1e6 * b.film_thickness,
            1e6 * h_min,
            b.oil_flow,
            b.viscosity_effective,
            1e-6 * rho * nu(t),
        );
        assert!(
            t > supply + 3.0,
            "the film runs {} K above the supply",
            t - supply
        );
        assert!((b.film_temperature - t).abs() < 1.0);
        assert!((b.film_thickness / h_min - 1.0).abs() < 3e-2);
        assert!((b.oil_flow / flow - 1.0).abs() < 0.1);
        let heat = b.heat_flow + conductance * (b.film_temperature - supply);
        assert!(
            (heat / b.friction_power - 1.0).abs() < 1e-6,
            "{heat} W of {} W",
            b.friction_power
        );
        sim.advance_to(2e-4).unwrap();
        let later = sim.outputs().unwrap().bearings[JointRole::MainBearing as usize];
        assert!((later.film_temperature - b.film_temperature).abs() < 1e-3);
        // The isoviscous film at the supply's viscosity reports a thicker film than the bearing has.
        let cold = Parameters {
            main_bearing: JointParameters {
                thermal_model: ThermalModel::Isoviscous,
                viscosity: oil.viscosity40,
                ..main_bearing
            },
            ..p
        };
        let cold = Simulation::with_inputs(cold, inputs)
            .unwrap()
            .outputs()
            .unwrap();
        let cold = cold.bearings[JointRole::MainBearing as usize].film_thickness;
        println!("isoviscous at 40 degC: h_min {:.3} µm", 1e6 * cold);
        assert!(cold > 1.05 * b.film_thickness);
    }
}

/// The compressor's main bearing (R 15 mm, L 20 mm, c 25 µm, the finite film, ISO VG 46 supplied
/// at 40 °C and 2 bar) with a heat balance of conductance `conductance` to the housing \[W/K\],
/// settled in temperature and position, steadily loaded: the crank at 90° turning at 157 rad/s,
/// a 2 kN slider force, rigid rod, ideal crank pin and rod–slider joint. Its parameters and
/// inputs.
pub(super) fn steadily_loaded_main_bearing(conductance: f64) -> (Parameters, Inputs) {
    let main_bearing = JointParameters {
        model: JointModel::Lubricated,
        clearance: 25e-6,
        journal_radius: 0.015,
        bearing_length: 0.02,
        initial_state: JournalStart::Settled,
        film_model: FilmModel::Finite,
        thermal_model: ThermalModel::HeatBalance,
        thermal_start: ThermalStart::Settled,
        heat_transfer_coefficient: conductance,
        switch_eccentricity: 0.99,
        ..JointParameters::benchmark()
    };
    let p = Parameters {
        main_bearing,
        joint: JointParameters::ideal(),
        rod_formulation: RodFormulation::Rigid,
        crank_initial_angle: std::f64::consts::FRAC_PI_2,
        drive_mode: DriveMode::Speed,
        relative_tolerance: 1e-6,
        ..Parameters::default()
    };
    let mut inputs = Inputs::at_start(&p);
    inputs.drive_speed = 157.0;
    inputs.slider_force = -2000.0;
    inputs.oil_supply_pressure = 2e5;
    (p, inputs)
}

/// The root of `surplus` between the eccentricity ratios `start` by secant, to `tolerance`.
pub(super) fn secant(surplus: impl Fn(f64) -> f64, start: (f64, f64), tolerance: f64) -> f64 {
    let (mut e0, mut e1) = start;
    let (mut s0, mut s1) = (surplus(e0), surplus(e1));
    for _ in 0..30 {
        if (e1 - e0).abs() < tolerance {
            break;
        }
        let e2 = (e1 - s1 * (e1 - e0) / (s1 - s0)).clamp(0.05, 0.98);
        (e0, s0) = (e1, s1);
        e1 = e2;
        s1 = surplus(e1);
    }
    e1
}

/// The rigid rod with a worn, lubricated rod–slider joint (50 µm clearance, 9 mm long) with a heat
/// balance of heat capacity `capacity` and conductance `conductance` to the housing.
fn worn_and_heated(capacity: f64, conductance: f64) -> Parameters {
    Parameters {
        joint: JointParameters {
            model: JointModel::Lubricated,
            clearance: 5e-5,
            bearing_length: 9e-3,
            thermal_model: ThermalModel::HeatBalance,
            heat_capacity: capacity,
            heat_transfer_coefficient: conductance,
            ..JointParameters::benchmark()
        },
        rod_formulation: RodFormulation::Rigid,
        ..Parameters::default()
    }
}

/// A worn, lubricated rod–slider joint with a heat balance (50 µm clearance, 9 mm long, an oil of
/// constant viscosity 0.05 Pa s, heat capacity 5 J/K, a conductance of 100 W/K to the housing), the
/// supply stepped by +10 K at 50 ms: the film temperature's difference from the same run without
/// the step follows the first-order response 10 K (1 − e^(−(t − t₁)/τ)), τ = C/(k + 2 ρ c_p Q̄) with
/// the run's mean oil flow Q̄ (the response of C dT/dt = P − (2 ρ c_p Q + k)(T − T_s), whose
/// friction power and flow the constant viscosity makes independent of T), within 2 % of the
/// step.
#[test]
fn the_film_temperature_follows_a_supply_step_as_a_first_order_system() {
    let oil = OilParameters {
        viscosity40: 0.05,
        viscosity100: 0.05,
        ..OilParameters::default()
    };
    let (capacity, conductance) = (5.0, 100.0);
    let mut p = worn_and_heated(capacity, conductance);
    p.joint.thermal_start = ThermalStart::Supply;
    p.oil = oil;
    let (t1, t_end, step) = (0.05, 0.35, 1e-3);
    let run = |stepped: bool| -> Vec<Outputs> {
        let mut sim = Simulation::new(p.clone()).unwrap();
        let mut inputs = *sim.inputs();
        let mut rows = Vec::new();
        for k in 1..=((t_end / step) as usize) {
            let t = k as f64 * step;
            if stepped && t > t1 {
                inputs = InputSignal::held(Inputs {
                    oil_supply_temperature: 323.15,
                    ..inputs.value
                });
            }
            sim.advance_with(&inputs, t).unwrap();
            rows.push(sim.outputs().unwrap());
        }
        rows
    };
    let (stepped, steady) = (run(true), run(false));
    let joint = |o: &Outputs| o.bearings[JointRole::RodSlider as usize];
    let mean_flow = steady.iter().map(|o| joint(o).oil_flow).sum::<f64>() / steady.len() as f64;
    let g = conductance + 2.0 * oil.density * oil.specific_heat * mean_flow;
    let tau = capacity / g;
    let mut worst = 0.0f64;
    for (a, b) in stepped.iter().zip(&steady) {
        if a.time <= t1 {
            continue;
        }
        let difference = joint(a).film_temperature - joint(b).film_temperature;
        let first_order = 10.0 * (1.0 - math::exp(-(a.time - t1) / tau));
        worst = worst.max((difference - first_order).abs());
    }
    println!(
        "τ = {tau:.4} s (G = {g:.2} W/K, mean flow {mean_flow:.3e} m3/s): largest deviation {worst:.4} K; film {:.2} K at the end",
        joint(&stepped[stepped.len() - 1]).film_temperature
    );
    assert!(tau > 0.01 && tau < 0.1);
    assert!(worst < 0.2, "{worst} K off the first-order response");
}

/// In thermal steady state the heat balance closes: the worn joint with the ISO VG 46 oil's
/// viscosity law, settled in temperature at the start and run through 30 revolutions (the
/// transient of a 0.2 J/K film, τ about 40 ms, has died to 1e-3), the last revolution's mean
/// friction power equals the mean heat the oil and the housing take within 0.1 % (trapezoidal
/// rule over 10 µs samples).
#[test]
fn the_heat_balance_closes_in_thermal_steady_state() {
    let conductance = 2.0;
    let p = worn_and_heated(0.2, conductance);
    let revolution = std::f64::consts::TAU / flexible_slider_crank::params::BENCHMARK_SPEED;
    let mut sim = Simulation::new(p).unwrap();
    sim.advance_to(29.0 * revolution).unwrap();
    let supply = sim.inputs().value.oil_supply_temperature;
    let n = 1200;
    let mut rows = vec![sim.outputs().unwrap()];
    for k in 1..=n {
        sim.advance_to((29.0 + k as f64 / n as f64) * revolution)
            .unwrap();
        rows.push(sim.outputs().unwrap());
    }
    let joint = |o: &Outputs| o.bearings[JointRole::RodSlider as usize];
    let trapezoid = |f: &dyn Fn(&Outputs) -> f64| {
        rows.windows(2)
            .map(|w| 0.5 * (w[1].time - w[0].time) * (f(&w[0]) + f(&w[1])))
            .sum::<f64>()
    };
    let friction = trapezoid(&|o| joint(o).friction_power);
    let carried =
        trapezoid(&|o| joint(o).heat_flow + conductance * (joint(o).film_temperature - supply));
    let stored = 0.2 * (joint(&rows[n]).film_temperature - joint(&rows[0]).film_temperature);
    println!(
        "over the revolution: friction {friction:.6e} J, carried away {carried:.6e} J, stored \
         {stored:.3e} J; film {:.2}–{:.2} K",
        rows.iter()
            .map(|o| joint(o).film_temperature)
            .fold(f64::INFINITY, f64::min),
        rows.iter()
            .map(|o| joint(o).film_temperature)
            .fold(0.0, f64::max),
    );
    assert!((carried / friction - 1.0).abs() < 1e-3);
}
