//! The joints as a bearing designer reads them: each joint's dissipation and its account, the
//! ideal joint's outputs, the line contact of a pin under a steady load, and the lubricated
//! joints' peaks at the default tolerance against converged runs (an engine cycle with a sharp
//! combustion rise, and the lubricated benchmarks).

use super::*;

#[path = "../support/engine.rs"]
mod engine;

/// The lubricated crank pin and main bearing of `examples/worn_joints.rs` (0.05 mm, 9 mm long,
/// 0.04 Pa s) with the dry rod–slider joint, every journal settled.
fn worn() -> Parameters {
    let bearing = JointParameters {
        model: JointModel::Lubricated,
        clearance: 5e-5,
        bearing_length: 9e-3,
        viscosity: 0.04,
        initial_state: flexible_slider_crank::params::JournalStart::Settled,
        ..JointParameters::benchmark()
    };
    Parameters {
        crank_pin: bearing,
        main_bearing: bearing,
        joint: JointParameters {
            initial_state: flexible_slider_crank::params::JournalStart::Settled,
            friction: 0.1,
            ..JointParameters::benchmark()
        },
        ..Parameters::default()
    }
}

/// Each joint's own dissipation over one revolution with all three joints worn: each is positive
/// at the end (the films' shear, the dry joint's impacts and friction all dissipate), the friction
/// and hysteresis powers are never negative, and the account closes (the outputs' balance residual below 1e-3 of the
/// kinetic energy at rtol 1e-6). The ideal joints of the defaults report zeros but their load
/// over the cycle.
#[test]
fn each_joint_dissipates_its_share_of_the_total() {
    let (_, rows) = run(
        Parameters {
            relative_tolerance: 1e-6,
            ..worn()
        },
        REVOLUTION,
        120,
    );
    for o in &rows {
        for b in &o.bearings {
            assert!(b.friction_power >= 0.0, "t = {}: {b:?}", o.time);
            assert!(b.hysteresis_power >= 0.0, "t = {}: {b:?}", o.time);
        }
    }
    let last = rows[rows.len() - 1];
    for (role, b) in JointRole::ALL.iter().zip(&last.bearings) {
        println!(
            "{role:?}: dissipated {:.4e} J, friction torque {:+.4e} N m, friction power {:.4e} W",
            b.energy_dissipated, b.friction_torque, b.friction_power
        );
        assert!(b.energy_dissipated > 0.0, "{role:?}");
    }
    let residual = balance::output_balance_residual(&rows);
    println!("energy balance residual {residual:.2e} of the kinetic energy");
    assert!(residual < 1e-3, "{residual:e}");
    let (_, rows) = run(Parameters::default(), 0.1 * REVOLUTION, 10);
    for o in &rows {
        for role in [JointRole::MainBearing, JointRole::CrankPin] {
            // an ideal joint has no clearance: only its load over the cycle
            let b = o.bearings[role as usize];
            let load = flexible_slider_crank::simulation::BearingOutputs {
                force_peak_cycle: b.force_peak_cycle,
                force_peak_cycle_angle: b.force_peak_cycle_angle,
                ..Default::default()
            };
            assert_eq!(b, load, "{role:?} at {}", o.time);
            assert!(b.force_peak_cycle > 0.0);
        }
    }
}

/// Film thickness h = c (1 − ε) with ε = |e|/c from the eccentricity outputs, at every
/// communication point of the worn run (the minimum over an interval never above the value at
/// its end, and the minimum since the start never above the interval's); 0 in metal contact.
#[test]
fn film_thickness_is_the_gap() {
    let (_, rows) = run(worn(), REVOLUTION, 120);
    let mut in_contact = 0;
    for o in &rows[1..] {
        let e = [
            (o.main_bearing_eccentricity_x, o.main_bearing_eccentricity_y),
            (o.crank_pin_eccentricity_x, o.crank_pin_eccentricity_y),
            (o.eccentricity_x, o.eccentricity_y),
        ];
        let clearance = [5e-5, 5e-5, 5e-4];
        for ((b, (x, y)), c) in o.bearings.iter().zip(e).zip(clearance) {
            let ratio = math::hypot(x, y) / c;
            assert!((b.eccentricity_ratio - ratio).abs() < 1e-12, "{b:?}");
            let expected = (c * (1.0 - ratio)).max(0.0);
            assert!((b.film_thickness - expected).abs() < 1e-12 * c, "{b:?}");
            assert!(b.film_thickness_min <= b.film_thickness);
            assert!(b.film_thickness_min_since_start <= b.film_thickness_min);
            assert!(b.film_pressure_peak_since_start >= b.film_pressure_peak);
            in_contact += usize::from(ratio > 1.0 && b.film_thickness == 0.0);
        }
    }
    assert!(in_contact > 0, "no metal contact in the run");
}

/// Johnson's line contact in the mechanism: the slider pin of the benchmark's 40 mm long
/// bearing, settled against a steady 2 kN slider force with the crank at rest, sinks into its
/// bearing the closed form's δ = (F/(π L E*)) (ln(4π L c E*/F) − 1), E* = E/(2(1 − ν²)), for the
/// force F it carries (1e-6), against the point contact's (F/K)^(2/3): 1.22 µm against 9.84 µm.
#[test]
fn a_long_pin_sinks_as_the_line_contact_says() {
    let j = JointParameters::benchmark();
    let depth = |contact_geometry| {
        let p = Parameters {
            rod_formulation: RodFormulation::Rigid,
            crank_initial_speed: Some(0.0),
            crank_initial_angle: 0.5,
            joint: JointParameters {
                initial_state: flexible_slider_crank::params::JournalStart::Settled,
                contact_geometry,
                ..j
            },
            ..Parameters::default()
        };
        let inputs = flexible_slider_crank::Inputs {
            slider_force: -2e3,
            ..Default::default()
        };
        let o = Simulation::with_inputs(p, inputs)
            .unwrap()
            .outputs()
            .unwrap();
        (o.penetration, o.joint_force)
    };
    let modulus = j.youngs_modulus / (2.0 * (1.0 - j.poisson_ratio * j.poisson_ratio));
    let johnson = |f: f64| {
        let x = f / (std::f64::consts::PI * j.bearing_length * modulus);
        x * (math::ln(4.0 * j.clearance / x) - 1.0)
    };
    let hertz = |f: f64| math::powf(f / j.contact_stiffness(), 2.0 / 3.0);
    let (line, line_force) = depth(flexible_slider_crank::params::ContactGeometry::Cylinder);
    let (point, point_force) = depth(flexible_slider_crank::params::ContactGeometry::Point);
    println!(
        "the slider pin under {line_force:.1} N: line contact {line:.4e} m (Johnson {:.4e}), \
         point {point:.4e} m (Hertz {:.4e})",
        johnson(line_force),
        hertz(point_force)
    );
    assert!((line - johnson(line_force)).abs() < 1e-6 * line, "{line}");
    assert!((point - hertz(point_force)).abs() < 1e-6 * point, "{point}");
    assert!(point > 7.0 * line);
}

/// What a bearing designer reads over the second cycle: the peaks of the three joint forces, of
/// the crank pin's and the main bearing's film pressures, and their smallest film thicknesses.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct CyclePeaks {
    /// Largest force at the main bearing, the crank pin and the piston pin \[N\].
    force: [f64; 3],
    /// Largest film pressure at the main bearing and the crank pin \[Pa\].
    pressure: [f64; 2],
    /// Smallest film thickness at the main bearing and the crank pin \[m\].
    thickness: [f64; 2],
}

/// The second cycle's [`CyclePeaks`] at the relative tolerance `rtol`, and the run's warnings.
fn second_cycle(rtol: f64) -> Result<(CyclePeaks, u64), flexible_slider_crank::ModelError> {
    let mut peaks = CyclePeaks {
        thickness: [f64::INFINITY; 2],
        ..CyclePeaks::default()
    };
    let mut warnings = 0;
    engine::run(engine::parameters(rtol), 2, |t, o| {
        warnings = o.warnings;
        if t <= engine::CYCLE + 0.5 * engine::STEP {
            return;
        }
        let forces = [
            o.main_bearing_force_peak,
            o.crank_pin_force_peak,
            o.joint_force_peak,
        ];
        for (p, f) in peaks.force.iter_mut().zip(forces) {
            *p = p.max(f);
        }
        for (k, b) in o.bearings[..2].iter().enumerate() {
            peaks.pressure[k] = peaks.pressure[k].max(b.film_pressure_peak);
            peaks.thickness[k] = peaks.thickness[k].min(b.film_thickness_min);
        }
    })?;
    Ok((peaks, warnings))
}

/// The lubricated joints' peaks at the default tolerance (rtol 1e-2) against a converged run
/// (rtol 1e-5) over the engine's second cycle: the three joint forces, the films' peak pressures
/// (within 2 %) and their smallest thickness (within 2 % of the clearance); measured within
/// 0.01 %. With the peak-hold's samples inside a step taking their velocities from the quintic
/// interpolant, which reads the end accelerations, the crank pin's force was 6.9 % high.
#[test]
fn an_engine_cycles_bearing_peaks_are_right_at_the_default_tolerance() {
    let (default, warnings) = second_cycle(1e-2).unwrap();
    let (converged, _) = second_cycle(1e-5).unwrap();
    println!("default {default:?}\nconverged {converged:?}");
    let names = ["main bearing", "crank pin", "piston pin"];
    for (k, name) in names.iter().enumerate() {
        let error = default.force[k] / converged.force[k] - 1.0;
        println!(
            "{name} force peak {:.1} N: {:+.2} %",
            default.force[k],
            100.0 * error
        );
        assert!(error.abs() < 0.02, "{name}: {error}");
    }
    for (k, name) in names[..2].iter().enumerate() {
        let error = default.pressure[k] / converged.pressure[k] - 1.0;
        let thickness = (default.thickness[k] - converged.thickness[k]) / 25e-6;
        println!(
            "{name}: peak pressure {:.3} MPa {:+.2} %, smallest film {:.3} µm ({:+.2} % of c)",
            1e-6 * default.pressure[k],
            100.0 * error,
            1e6 * default.thickness[k],
            100.0 * thickness
        );
        assert!(error.abs() < 0.02, "{name}: {error}");
        assert!(thickness.abs() < 0.02, "{name}: {thickness}");
    }
    // No warning: the finite film has no short-bearing range to leave, and no peak rests on the
    // interpolant.
    assert_eq!(warnings, 0);
}

/// The lubricated benchmarks' peak joint forces over each of two revolutions at the default
/// tolerance within 2 % of converged runs (rtol 1e-5): C (full rod), D (the lubricated → dry
/// hand-over), the 4-mode rod and the rigid rod with the lubricated joint.
#[test]
fn the_lubricated_benchmarks_peaks_are_right_at_the_default_tolerance() {
    let lubricated = |rod_formulation| Parameters {
        rod_formulation,
        joint: JointParameters {
            model: JointModel::Lubricated,
            ..JointParameters::benchmark()
        },
        ..Parameters::default()
    };
    for (name, p) in [
        ("C", Parameters::benchmark_c()),
        ("D", Parameters::benchmark_d()),
        (
            "4 modes, lubricated",
            lubricated(RodFormulation::CraigBampton),
        ),
        ("rigid, lubricated", lubricated(RodFormulation::Rigid)),
    ] {
        let peaks = |rtol: f64| {
            let (_, rows) = run(
                Parameters {
                    relative_tolerance: rtol,
                    ..p.clone()
                },
                2.0 * REVOLUTION,
                240,
            );
            let mut revolution = [0.0f64; 2];
            for (i, o) in rows.iter().enumerate().skip(1) {
                let r = usize::from(i > 120);
                revolution[r] = revolution[r].max(o.joint_force_peak);
            }
            revolution
        };
        let (default, converged) = (peaks(1e-2), peaks(1e-5));
        for r in 0..2 {
            let error = default[r] / converged[r] - 1.0;
            println!(
                "{name}, revolution {}: {:.1} N, {:+.2} %",
                r + 1,
                default[r],
                100.0 * error
            );
            assert!(error.abs() < 0.02, "{name}, revolution {}: {error}", r + 1);
        }
    }
}

/// At the loosest tolerance (rtol 0.1) the engine's crank pin has a force peak inside a step that
/// the interpolant sets: 500 N where the integrator's own solution gives 135 N. The run warns
/// once, naming the joint's peak output and both values; at the default tolerance it does not.
#[test]
fn a_peak_the_interpolant_sets_is_reported() {
    let mut sim = engine::run(engine::parameters(0.1), 1, |_, _| {}).unwrap();
    let doubts: Vec<String> = sim
        .take_warnings()
        .into_iter()
        .filter(|w| w.contains("from the interpolant"))
        .collect();
    println!("{doubts:#?}");
    assert_eq!(doubts.len(), 1);
    assert!(
        doubts[0].contains("crankPin.forcePeak holds"),
        "{}",
        doubts[0]
    );
}

/// Over the engine's second cycle the film's friction power, sampled at the 1e-4 s communication
/// points (a rectangle rule of 400 points), integrates to the energy each bearing dissipates by
/// its own work integral (1 %): the film's loss formula and the power of its force and moments on
/// journal and bearing are the same quantity.
#[test]
fn the_friction_power_integrates_to_the_dissipated_energy() {
    let (mut at_start, mut at_end, mut integral) = ([0.0; 2], [0.0; 2], [0.0; 2]);
    engine::run(engine::parameters(1e-2), 2, |t, o| {
        let bearings = [0, 1].map(|k| o.bearings[k]);
        if (t - engine::CYCLE).abs() < 0.5 * engine::STEP {
            at_start = bearings.map(|b| b.energy_dissipated);
        } else if t > engine::CYCLE {
            for (i, b) in integral.iter_mut().zip(bearings) {
                *i += b.friction_power * engine::STEP;
            }
            at_end = bearings.map(|b| b.energy_dissipated);
        }
    })
    .unwrap();
    for k in 0..2 {
        let dissipated = at_end[k] - at_start[k];
        println!(
            "bearing {k}: ∫ frictionPower dt = {:.5} J, energyDissipated {dissipated:.5} J",
            integral[k]
        );
        assert!((integral[k] - dissipated).abs() < 0.01 * dissipated);
    }
}

/// An account of a dry joint's dissipation independent of the work integral of its force that
/// the state carries (`energy_dissipated`): the trapezoidal integral of the powers the contact
/// loses, its hysteresis ((F_N − F_e) δ̇) and its friction (−F_T v_T), sampled every microsecond
/// over the first 60°, where the rod–slider joint impacts: the benchmark's frictionless joint
/// (hysteresis alone) and a joint with friction 0.1 beside two lubricated ones (friction
/// dominant), both at rtol 1e-6, to 1e-4 (measured 2e-5 and 2e-8). It fails if the contact's
/// force, its potential or the moments on journal and bearing are booked apart from what they
/// lose.
#[test]
fn a_dry_joints_dissipation_is_the_integral_of_its_hysteresis_and_friction_powers() {
    let n = 2000;
    let dt = REVOLUTION / 6.0 / n as f64;
    for (p, share) in [(Parameters::default(), 1.0), (worn(), 0.0)] {
        let (_, rows) = run(
            Parameters {
                relative_tolerance: 1e-6,
                ..p
            },
            REVOLUTION / 6.0,
            n,
        );
        let b = |o: &Outputs| o.bearings[JointRole::RodSlider as usize];
        let power = |o: &Outputs| b(o).friction_power + b(o).hysteresis_power;
        let trapezoid = |f: &dyn Fn(&Outputs) -> f64| -> f64 {
            rows.windows(2)
                .map(|w| 0.5 * dt * (f(&w[0]) + f(&w[1])))
                .sum()
        };
        let (integral, hysteresis) = (trapezoid(&power), trapezoid(&|o| b(o).hysteresis_power));
        // zero at the start, also for a journal settled against its bearing
        assert_eq!(b(&rows[0]).energy_dissipated, 0.0);
        let dissipated = b(&rows[n]).energy_dissipated;
        println!(
            "∫ (hysteresis + friction) dt = {integral:.7e} J (hysteresis {:.1} %), \
             energyDissipated {dissipated:.7e} J ({:+.1e})",
            100.0 * hysteresis / integral,
            integral / dissipated - 1.0
        );
        assert!(dissipated > 0.0);
        assert!((integral - dissipated).abs() < 1e-4 * dissipated);
        // the frictionless joint loses by hysteresis alone; with friction it dominates
        assert!((hysteresis / integral - share).abs() < 0.01);
    }
}

/// The cycle results switch to a completed cycle at the first communication point at or after
/// the crank angle reaches its boundary, within 0.01° of it: the DefaultExperiment from a crank
/// angle of 0.3 rad (its first cycle, from there to 2π, is not a whole one), read every 1e-7 s
/// (0.003°) around 4π, completes its first whole cycle (`cycle.number` 0 → 1) at the first point
/// past it; the completed cycle's results hold from there on. A run of exactly two revolutions
/// from 0 reports both complete.
#[test]
fn the_cycle_results_switch_at_the_cycle_boundary() {
    let mut sim = Simulation::new(Parameters {
        crank_initial_angle: 0.3,
        ..Parameters::default()
    })
    .unwrap();
    let boundary = 4.0 * std::f64::consts::PI;
    let speed = sim.outputs().unwrap().crank_speed;
    let t_boundary = (boundary - 0.3) / speed;
    sim.advance_to(t_boundary - 2e-5).unwrap();
    let mut before = sim.outputs().unwrap();
    assert_eq!(before.cycle_number, 0);
    let mut switched = None;
    for k in 1..=400 {
        sim.advance_to(t_boundary - 2e-5 + f64::from(k) * 1e-7)
            .unwrap();
        let o = sim.outputs().unwrap();
        match (before.cycle_number, o.cycle_number, switched) {
            (0, 1, None) => {
                assert!(before.crank_angle < boundary, "{}", before.crank_angle);
                let past = o.crank_angle - boundary;
                assert!(
                    (-1e-8..0.01f64.to_radians()).contains(&past),
                    "switched {past} rad past the boundary"
                );
                switched = Some(o);
            }
            (_, n, Some(at)) => {
                assert_eq!(n, 1);
                let b = |o: &Outputs| {
                    o.bearings
                        .map(|b| (b.force_peak_cycle, b.force_peak_cycle_angle))
                };
                assert_eq!(b(&o), b(&at), "the completed cycle's results hold");
            }
            (0, 0, None) => {}
            other => panic!("{other:?}"),
        }
        before = o;
    }
    assert!(switched.is_some(), "no switch around the boundary");
    let mut exact = Simulation::new(Parameters::default()).unwrap();
    for k in 1..=240 {
        exact.advance_to(f64::from(k) * 1e-4).unwrap();
    }
    assert_eq!(exact.outputs().unwrap().cycle_number, 2);
}
