//! The loads a designer sizes parts from — the force at every joint, the guide's normal force,
//! the rod's axial forces and stress — against statics and beam theory.

use super::*;
use flexible_slider_crank::Inputs;

/// A run whose inputs start at `inputs` (the start in equilibrium with them), outputs at `n`
/// equal intervals up to `t_end`.
fn run_with(p: Parameters, inputs: Inputs, t_end: f64, n: usize) -> Vec<Outputs> {
    let mut sim = Simulation::with_inputs(p, inputs).unwrap();
    let mut rows = vec![sim.outputs().unwrap()];
    for i in 1..=n {
        sim.advance_to(t_end * i as f64 / n as f64).unwrap();
        rows.push(sim.outputs().unwrap());
    }
    rows
}

/// A slow mechanism (10 rpm) under a slider load of −1000 N has a two-force rod: the crank-pin,
/// rod–slider and main-bearing forces are one force (within 0.1 %), the rod is in compression
/// by it at both pins, and the guide carries its y component. The largest stress is N/A (within
/// 0.1 %, rigid and 4-mode rods), and the most tensile and the most compressive fibres and the middle
/// section carry −N/A too (a compressed two-force rod).
#[test]
fn a_slow_loaded_mechanism_has_a_two_force_rod() {
    let speed = 10.0 * std::f64::consts::TAU / 60.0;
    let inputs = Inputs {
        drive_speed: speed,
        slider_force: -1000.0,
        ..Inputs::default()
    };
    for rod_formulation in [RodFormulation::Rigid, RodFormulation::CraigBampton] {
        let p = Parameters {
            joint: JointParameters {
                model: JointModel::Ideal,
                ..Parameters::default().joint
            },
            rod_formulation,
            crank_initial_speed: Some(speed),
            crank_initial_angle: 0.3,
            ..Parameters::default()
        };
        let area = p.rod.area;
        for o in run_with(p, inputs, 0.5, 10) {
            let f = o.joint_force;
            assert!(
                f > 1000.0 && f < 1100.0,
                "{rod_formulation:?}: joint.force {f} N"
            );
            for (name, other) in [
                ("crankPin.force", o.crank_pin_force),
                ("mainBearing.force", o.main_bearing_force),
                ("-rod.axialForceCrankPin", -o.rod_axial_force_crank_pin),
                ("-rod.axialForceSliderPin", -o.rod_axial_force_slider_pin),
            ] {
                assert!(
                    (other - f).abs() < 1e-3 * f,
                    "{rod_formulation:?}, t = {}: {name} = {other} N, joint.force = {f} N",
                    o.time
                );
            }
            assert!(
                (o.guide_force.abs() - o.joint_force_y.abs()).abs() < 1e-9 * f,
                "guide.force {} vs joint.forceY {}",
                o.guide_force,
                o.joint_force_y
            );
            let axial_stress = f / area;
            let tolerance = 1e-3;
            assert!(
                (o.rod_stress - axial_stress).abs() < tolerance * axial_stress,
                "{rod_formulation:?}, t = {}: rod.stress {} Pa vs N/A {axial_stress} Pa",
                o.time,
                o.rod_stress
            );
            // Compressed: both fibres carry −N/A, and so does the middle section.
            for (name, signed) in [
                ("rod.stressMax", o.rod_stress_max),
                ("rod.stressMin", o.rod_stress_min),
                (
                    "rod.axialForceMidspan / A",
                    o.rod_axial_force_midspan / area,
                ),
            ] {
                assert!(
                    (signed + axial_stress).abs() < tolerance * axial_stress,
                    "{rod_formulation:?}, t = {}: {name} = {signed} Pa vs −N/A",
                    o.time
                );
            }
        }
    }
}

/// A rod at rest, horizontal (crank angle 0), under its own weight (gravity 1000 m/s² across
/// the guide, ideal joint) is a pinned beam under a uniform load: the largest stress is the
/// mid-span moment's, σ = ρA g l² c/(8I), within 0.01 % for the full rod (8 elements) and the
/// 4-mode rod (both from the equilibrium of the rod's parts), each pin carries half the weight and the guide the slider's and half the rod's.
/// With end masses of 0.3 and 0.1 kg (heavier than the beam) the stress is the same, and each
/// pin carries its end mass's weight besides. Signed: the mid-span moment is +q l²/8 (the rod
/// turns left), its fibres at ±σ, the largest stress at mid-span (the nearest sample: within
/// half an element), no axial force.
#[test]
fn a_rod_at_rest_bends_under_its_own_weight_as_a_pinned_beam() {
    for (rod_formulation, ends) in [
        (RodFormulation::Ancf, [0.0, 0.0]),
        (RodFormulation::CraigBampton, [0.0, 0.0]),
        (RodFormulation::CraigBampton, [0.3, 0.1]),
        (RodFormulation::Rigid, [0.3, 0.1]),
    ] {
        let mut p = Parameters {
            joint: JointParameters {
                model: JointModel::Ideal,
                ..Parameters::default().joint
            },
            rod_formulation,
            crank_initial_speed: Some(0.0),
            gravity: 1000.0,
            ..Parameters::default()
        };
        p.rod.crank_end_mass = ends[0];
        p.rod.slider_end_mass = ends[1];
        let (rod, g) = (p.rod, p.gravity);
        let q = rod.density * rod.area * g;
        let expected =
            q * rod.length.powi(2) / 8.0 * rod.outer_fibre_distance / rod.second_moment_of_area;
        let weight = rod.mass() * g;
        let slider_weight = (p.slider_mass + ends[1]) * g;
        for o in run(p, 2e-3, 4).1 {
            let error = (o.rod_stress - expected).abs() / expected;
            println!(
                "{rod_formulation:?}: rod.stress {:.4e} Pa, beam theory {expected:.4e} Pa ({:.2} %)",
                o.rod_stress,
                100.0 * error
            );
            assert!(error < 1e-4, "{rod_formulation:?}, t = {}", o.time);
            // The rod sags: its middle section turns left (counter-clockwise, the rod running
            // along +x) under the moment q l²/8, its lower fibre in tension, the upper in
            // compression, the largest stress at mid-span.
            let moment = q * rod.length.powi(2) / 8.0;
            assert!(
                (o.rod_bending_moment_midspan - moment).abs() < 1e-4 * moment,
                "{rod_formulation:?}: {} vs {moment}",
                o.rod_bending_moment_midspan
            );
            assert!((o.rod_stress_max - expected).abs() < 1e-4 * expected);
            assert!((o.rod_stress_min + expected).abs() < 1e-4 * expected);
            assert!(
                (o.rod_stress_location - 0.5).abs() < 0.07,
                "{}",
                o.rod_stress_location
            );
            assert!(o.rod_axial_force_midspan.abs() < 1e-2 * q * rod.length);
            let pin_a = 0.5 * weight + ends[0] * g;
            assert!(
                (o.crank_pin_force_y - pin_a).abs() < 1e-3 * weight,
                "{ends:?}"
            );
            assert!((o.guide_force - 0.5 * weight - slider_weight).abs() < 1e-3 * weight);
        }
    }
}

/// The rotating rod's inertial loads, ideal joint, 1000 rpm: over the second revolution the
/// largest stress of the flexible rod follows the rigid rod's closed form (the quasi-static stress
/// of the same motion) within 0.2 % of its peak for the full rod, the 8-mode and the 4-mode rod:
/// the resultants come from the equilibrium of the rod's parts under its inertia, which rigid
/// motion carries whatever the mode count (measured: 0.07 % for each). A little material damping (1e-5 s: 8 % of critical in the first
/// bending mode) removes the ringing of the start, whose deformation rate is not the quasi-static
/// one.
#[test]
fn a_rotating_rods_stress_follows_its_inertial_load() {
    let speed = 1000.0 * std::f64::consts::TAU / 60.0;
    let revolution = std::f64::consts::TAU / speed;
    let second_revolution = |rod_formulation, n_modes| {
        let p = Parameters {
            joint: JointParameters {
                model: JointModel::Ideal,
                ..Parameters::default().joint
            },
            rod_formulation,
            n_modes,
            crank_initial_speed: Some(speed),
            rod: RodProperties {
                stiffness_damping: 1e-5,
                ..RodProperties::benchmark_b()
            },
            relative_tolerance: 1e-6,
            ..Parameters::default()
        };
        run(p, 2.0 * revolution, 144).1.split_off(72)
    };
    let rigid = second_revolution(RodFormulation::Rigid, 4);
    let peak = rigid.iter().map(|o| o.rod_stress).fold(0.0, f64::max);
    for (name, rod_formulation, n_modes, tolerance) in [
        ("full rod", RodFormulation::Ancf, 4, 2e-3),
        ("8 modes", RodFormulation::CraigBampton, 8, 2e-3),
        ("4 modes", RodFormulation::CraigBampton, 4, 2e-3),
    ] {
        let flexible = second_revolution(rod_formulation, n_modes);
        let worst = rigid
            .iter()
            .zip(&flexible)
            .map(|(r, f)| (r.rod_stress - f.rod_stress).abs())
            .fold(0.0, f64::max);
        println!(
            "{name}: largest |rod.stress - rigid rod's| {:.3} % of its peak {peak:.4e} Pa",
            100.0 * worst / peak
        );
        assert!(worst < tolerance * peak, "{name}");
    }
}
