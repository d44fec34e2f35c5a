//! The user's own machine against exact identities of the rigid mechanism: an offset cylinder's
//! kinematics and dead centres, a counterweighted crank's momentum and moment balances (with the
//! main bearing ideal and worn), and where the crank starts when `crank.initialSpeed` is not set.

use super::*;
use flexible_slider_crank::Inputs;

/// The offset slider-crank's closed form, crank angle θ, crank r, rod l, offset e:
/// x_s = r cos θ + √(l² − (r sin θ − e)²).
fn offset_position(r: f64, l: f64, e: f64, theta: f64) -> f64 {
    let (sin, cos) = math::sin_cos(theta);
    r * cos + (l * l - (r * sin - e) * (r * sin - e)).sqrt()
}

/// The rigid mechanism, ideal joints, 1000 rpm, with the guide 20 mm above the crank pivot.
fn offset_mechanism(offset: f64) -> Parameters {
    Parameters {
        rod_formulation: RodFormulation::Rigid,
        joint: JointParameters {
            model: JointModel::Ideal,
            ..JointParameters::benchmark()
        },
        slider_offset: offset,
        crank_initial_speed: Some(1000.0 * std::f64::consts::TAU / 60.0),
        relative_tolerance: 1e-10,
        ..Parameters::default()
    }
}

/// With the guide offset by e = ±20 mm (crank 50 mm, rod 120 mm), the slider follows the closed
/// form r cos θ + √(l² − (r sin θ − e)²) over a revolution within 1e-7 m, the rod's slider pin
/// stays on the guide line y = e, and the slider's extreme positions lie at the dead centres
/// θ = asin(e/(l + r)) (farthest) and π + asin(e/(l − r)) (nearest), within 0.2° (the 0.1°
/// sampling).
#[test]
fn an_offset_slider_follows_the_closed_form_and_its_dead_centres() {
    for offset in [0.02, -0.02] {
        let p = offset_mechanism(offset);
        let (r, l) = (p.crank_length, p.rod.length);
        let revolution = std::f64::consts::TAU / p.start_speed(0.0);
        let (_, rows) = run(p, revolution, 3600);
        let mut worst = 0.0f64;
        for o in &rows {
            let expected = offset_position(r, l, offset, o.crank_angle);
            worst = worst.max((o.slider_position - expected).abs());
        }
        println!("offset {offset} m: largest |x_s − closed form| {worst:.2e} m");
        assert!(worst < 1e-7, "{worst:e}");
        let extreme = |far: bool| {
            let o = rows
                .iter()
                .max_by(|a, b| {
                    let sign = if far { 1.0 } else { -1.0 };
                    (sign * a.slider_position).total_cmp(&(sign * b.slider_position))
                })
                .unwrap();
            o.crank_angle.rem_euclid(std::f64::consts::TAU)
        };
        let far = (offset / (l + r)).asin().rem_euclid(std::f64::consts::TAU);
        let near = std::f64::consts::PI + (offset / (l - r)).asin();
        for (name, found, expected) in [
            ("outer", extreme(true), far),
            ("inner", extreme(false), near),
        ] {
            let error = (found - expected).to_degrees();
            println!(
                "offset {offset} m: {name} dead centre at {:.2}° ({error:+.2}°)",
                found.to_degrees()
            );
            assert!(error.abs() < 0.2, "{name}: {error}°");
        }
    }
}

/// An offset with crank.length + |slider.offset| ≥ rod.length cannot turn: refused with a
/// message naming slider.offset, its value and the range.
#[test]
fn an_offset_that_blocks_a_turn_is_refused() {
    let p = Parameters {
        slider_offset: 0.08,
        ..Parameters::default()
    };
    let message = Simulation::new(p).unwrap_err().to_string();
    println!("{message}");
    assert!(message.contains("slider.offset = 0.08"), "{message}");
    assert!(
        message.contains("crank.length + |slider.offset| < rod.length"),
        "{message}"
    );
}

/// A counterweighted crank (centre of mass 0.3 r_c beyond the pivot, crank.centreOfMassRatio =
/// −0.3) under gravity, speeding up under a 5 N m drive torque: the main
/// bearing's force satisfies the crank's momentum balance F_O = m_c a_G + F_A − m_c g, with a_G the
/// second difference of the crank's centre over 10 µs. With the ideal bearing (the centre turning
/// about the pivot) the FMU computes F_O by that balance; with a worn, lubricated one it comes from
/// the film and the centre moves in the clearance, so the balance checks the free crank's
/// dynamics (within 1e-3 of the largest force, the differences' accuracy). With the ideal bearing
/// the crank also obeys its moment balance about the pivot, I_O θ̈ = τ + r_P × (−F_A) + r_G × m_c g
/// (1e-6 of the largest torque).
#[test]
fn a_counterweighted_crank_balances_its_momentum_and_moment() {
    let ratio = -0.3;
    for worn in [false, true] {
        let p = Parameters {
            rod_formulation: RodFormulation::Rigid,
            crank_centre_of_mass_ratio: ratio,
            crank_mass: 1.2,
            gravity: 9.81,
            gravity_angle: 0.4,
            crank_initial_speed: Some(200.0),
            drive_mode: DriveMode::Torque,
            relative_tolerance: 1e-9,
            main_bearing: JointParameters {
                model: if worn {
                    JointModel::Lubricated
                } else {
                    JointModel::Ideal
                },
                clearance: 5e-5,
                bearing_length: 9e-3,
                viscosity: 0.04,
                ..JointParameters::benchmark()
            },
            joint: JointParameters {
                model: JointModel::Ideal,
                ..JointParameters::benchmark()
            },
            ..Parameters::default()
        };
        let (m, a, r) = (p.crank_mass, ratio * p.crank_length, p.crank_length);
        let g = p.gravity_vector();
        let i_o = p.crank_inertia_about_pivot();
        let inputs = Inputs {
            drive_torque: 5.0,
            ..Default::default()
        };
        let mut sim = Simulation::with_inputs(p, inputs).unwrap();
        let h = 1e-5;
        let mut samples = Vec::new();
        for k in 0..400 {
            sim.advance_to(f64::from(k + 1) * h).unwrap();
            let o = sim.outputs().unwrap();
            let centre = match sim.mechanism().layout().crank_centre() {
                Some(i) => nalgebra::Vector2::new(sim.state()[i], sim.state()[i + 1]),
                None => {
                    let (sin, cos) = math::sin_cos(o.crank_angle);
                    a * nalgebra::Vector2::new(cos, sin)
                }
            };
            samples.push((o, centre));
        }
        let cross = |u: nalgebra::Vector2<f64>, v: nalgebra::Vector2<f64>| u.x * v.y - u.y * v.x;
        let (mut worst, mut largest) = ([0.0f64; 2], [0.0f64; 2]);
        for w in samples.windows(3) {
            let (o, centre) = w[1];
            let a_g = (w[2].1 - 2.0 * centre + w[0].1) / (h * h);
            let f_a = nalgebra::Vector2::new(o.crank_pin_force_x, o.crank_pin_force_y);
            let f_o = nalgebra::Vector2::new(o.main_bearing_force_x, o.main_bearing_force_y);
            worst[0] = worst[0].max((f_o - (m * a_g + f_a - m * g)).norm());
            largest[0] = largest[0].max(f_o.norm());
            if !worn {
                let (sin, cos) = math::sin_cos(o.crank_angle);
                let pin = r * nalgebra::Vector2::new(cos, sin);
                let moment = o.crank_torque + cross(pin, -f_a) + cross(centre, m * g);
                worst[1] = worst[1].max((i_o * o.crank_acceleration - moment).abs());
                largest[1] = largest[1].max(o.crank_torque.abs());
            }
        }
        println!(
            "counterweight, main bearing {}: momentum residual {:.2e} of {:.1} N, moment residual \
             {:.2e} of {:.2} N m",
            if worn { "worn" } else { "ideal" },
            worst[0],
            largest[0],
            worst[1],
            largest[1]
        );
        assert!(worst[0] < 1e-3 * largest[0], "{worst:?}");
        assert!(worst[1] <= 1e-6 * largest[1], "{worst:?}");
    }
}

/// The crank starts at crank.initialSpeed when it is set and at drive.speed's value when it is
/// not, in either drive mode; setting it to its start value counts as set.
#[test]
fn the_crank_starts_at_drive_speed_unless_its_initial_speed_is_set() {
    for drive_mode in [DriveMode::Speed, DriveMode::Torque] {
        for (set, expected) in [
            (None, 300.0),
            (Some(200.0), 200.0),
            (Some(BENCHMARK_SPEED), BENCHMARK_SPEED),
        ] {
            let p = Parameters {
                drive_mode,
                crank_initial_speed: set,
                ..Parameters::default()
            };
            let inputs = Inputs {
                drive_speed: 300.0,
                ..Default::default()
            };
            let o = Simulation::with_inputs(p, inputs)
                .unwrap()
                .outputs()
                .unwrap();
            assert_eq!(o.crank_speed, expected, "{drive_mode:?}, {set:?}");
        }
    }
}

/// `rod.dampingRatio` ζ₁ is the strain-rate coefficient β = 2ζ₁/ω₁ with ω₁ = π² √(EI/(ρA l⁴)):
/// a run with ζ₁ = 1 % equals, bit for bit, one with rod.stiffnessDamping = 2 · 0.01/ω₁; setting
/// both is refused with a message naming them, and a ratio that would overdamp the rod names its
/// range.
#[test]
fn the_damping_ratio_is_a_strain_rate_coefficient() {
    let mut by_ratio = Parameters::default();
    by_ratio.rod.damping_ratio = 0.01;
    let r = &by_ratio.rod;
    let omega = (std::f64::consts::PI / r.length).powi(2)
        * (r.youngs_modulus * r.second_moment_of_area / (r.density * r.area)).sqrt();
    let mut by_coefficient = Parameters::default();
    by_coefficient.rod.stiffness_damping = 2.0 * 0.01 / omega;
    let (_, a) = run(by_ratio.clone(), 0.002, 20);
    let (_, b) = run(by_coefficient.clone(), 0.002, 20);
    assert_eq!(a, b);
    assert!(a[20].material_damping > 0.0);
    let mut both = by_ratio.clone();
    both.rod.stiffness_damping = 1e-6;
    let message = Simulation::new(both).unwrap_err().to_string();
    assert!(message.contains("rod.dampingRatio = 0.01"), "{message}");
    assert!(message.contains("rod.stiffnessDamping = 1e-6"), "{message}");
    let mut overdamped = by_ratio;
    overdamped.rod.damping_ratio = 1.0;
    overdamped.rod.second_moment_of_area = 1.5e-12;
    let message = Simulation::new(overdamped).unwrap_err().to_string();
    println!("{message}");
    assert!(
        message.contains("rod.dampingRatio = 1 is outside"),
        "{message}"
    );
}

/// The mechanism with ideal joints at 1000 rpm under a −500 N slider force, over half a
/// revolution at tolerance `rtol`, with the rod of `rod_formulation`: the outputs at 60 points.
fn ideal_at_1000_rpm(p: Parameters, rod_formulation: RodFormulation, rtol: f64) -> Vec<Outputs> {
    let speed = 1000.0 * std::f64::consts::TAU / 60.0;
    let p = Parameters {
        rod_formulation,
        joint: JointParameters {
            model: JointModel::Ideal,
            ..JointParameters::benchmark()
        },
        crank_initial_speed: Some(speed),
        relative_tolerance: rtol,
        ..p
    };
    let inputs = Inputs {
        drive_speed: speed,
        slider_force: -500.0,
        ..Default::default()
    };
    let mut sim = Simulation::with_inputs(p, inputs).unwrap();
    (1..=60)
        .map(|k| {
            sim.advance_to(f64::from(k) * 5e-4).unwrap();
            sim.outputs().unwrap()
        })
        .collect()
}

/// [`ideal_at_1000_rpm`] with the rigid rod at rtol 1e-10.
fn ideal_rigid(p: Parameters) -> Vec<Outputs> {
    ideal_at_1000_rpm(p, RodFormulation::Rigid, 1e-10)
}

/// The largest relative difference between two runs' values of `f`, against the largest |f|.
fn differ(a: &[Outputs], b: &[Outputs], f: impl Fn(&Outputs) -> f64) -> f64 {
    let scale = a.iter().map(|o| f(o).abs()).fold(0.0, f64::max);
    a.iter()
        .zip(b)
        .map(|(x, y)| (f(x) - f(y)).abs())
        .fold(0.0, f64::max)
        / scale
}

/// A mass at the rod's slider pin moves as the slider does (the ideal joint ties the pin to it):
/// `rod.sliderEndMass` = 0.1 kg gives the crank the loads that 0.1 kg more on the slider gives —
/// crank-pin and main-bearing forces and crank torque within 1e-6. A mass at the crank pin moves
/// with the crank's pin: `rod.crankEndMass` = 0.2 kg gives the main-bearing force and the crank
/// torque of that mass merged into the crank (its mass, centre of mass and inertia about it
/// recomputed), within 1e-6.
#[test]
fn end_masses_act_as_the_masses_they_ride_with() {
    let base = Parameters::default();
    let mut on_rod = base.clone();
    on_rod.rod.slider_end_mass = 0.1;
    let on_slider = Parameters {
        slider_mass: base.slider_mass + 0.1,
        ..base.clone()
    };
    let (a, b) = (ideal_rigid(on_rod), ideal_rigid(on_slider));
    for (name, f) in [
        (
            "crankPin.force",
            (|o: &Outputs| o.crank_pin_force) as fn(&Outputs) -> f64,
        ),
        ("mainBearing.force", |o: &Outputs| o.main_bearing_force),
        ("crank.torque", |o: &Outputs| o.crank_torque),
    ] {
        let d = differ(&a, &b, f);
        println!("slider-end mass vs slider mass: {name} differs by {d:.1e}");
        assert!(d < 1e-6, "{name}: {d:e}");
    }
    let (m_c, m, r) = (base.crank_mass, 0.2, base.crank_length);
    let a_c = base.crank_centre_of_mass();
    let merged = m_c + m;
    let centre = (m_c * a_c + m * r) / merged;
    let mut on_rod = base.clone();
    on_rod.rod.crank_end_mass = m;
    let on_crank = Parameters {
        crank_mass: merged,
        crank_centre_of_mass_ratio: centre / r,
        crank_inertia: base.crank_inertia + m_c * (a_c - centre).powi(2) + m * (r - centre).powi(2),
        ..base
    };
    let (a, b) = (ideal_rigid(on_rod), ideal_rigid(on_crank));
    for (name, f) in [
        (
            "mainBearing.force",
            (|o: &Outputs| o.main_bearing_force) as fn(&Outputs) -> f64,
        ),
        ("crank.torque", |o: &Outputs| o.crank_torque),
    ] {
        let d = differ(&a, &b, f);
        println!("crank-end mass vs merged into the crank: {name} differs by {d:.1e}");
        assert!(d < 1e-6, "{name}: {d:e}");
    }
}

/// A flexible rod ten times stiffer than benchmark B's (2 % damping, so that its start-up
/// vibration dies out), with end masses of 0.15 and 0.05 kg, full (8 elements) and reduced
/// (4 modes), gives the rigid rod's loads with the same end masses: crank-pin and main-bearing
/// forces and crank torque within 0.5 % of their largest.
#[test]
fn a_stiff_flexible_rod_with_end_masses_has_the_rigid_rods_loads() {
    let mut base = Parameters::default();
    base.rod.crank_end_mass = 0.15;
    base.rod.slider_end_mass = 0.05;
    let rigid = ideal_rigid(base.clone());
    for rod_formulation in [RodFormulation::Ancf, RodFormulation::CraigBampton] {
        let mut p = base.clone();
        p.rod.youngs_modulus *= 10.0;
        p.rod.damping_ratio = 0.02;
        let flexible = ideal_at_1000_rpm(p, rod_formulation, 1e-5);
        for (name, f) in [
            (
                "crankPin.force",
                (|o: &Outputs| o.crank_pin_force) as fn(&Outputs) -> f64,
            ),
            ("mainBearing.force", |o: &Outputs| o.main_bearing_force),
            ("crank.torque", |o: &Outputs| o.crank_torque),
        ] {
            let d = differ(&rigid, &flexible, f);
            println!("{rod_formulation:?}, stiff, end masses: {name} differs by {d:.1e}");
            assert!(d < 5e-3, "{rod_formulation:?} {name}: {d:e}");
        }
    }
}
