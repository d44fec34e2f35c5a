use super::*;
use crate::joint::{Joint, JointModel, JointParameters};

/// F_n(λ) by the trapezoidal rule straight over the Gaussian, s from λ to λ + 12 in 400 000
/// intervals: an independent quadrature (no change of variable, no table).
fn gaussian(n: f64, lambda: f64) -> f64 {
    let intervals = 400_000;
    let h = 12.0 / intervals as f64;
    let f = |u: f64| math::powf(u, n) * math::exp(-0.5 * (lambda + u) * (lambda + u));
    let sum: f64 = (1..intervals).map(|i| f(i as f64 * h)).sum::<f64>() + 0.5 * f(12.0);
    sum * h / std::f64::consts::TAU.sqrt()
}

/// The tabulated F_5/2 and F_7/2 agree with the Gaussian integral within 1e-6 of their value
/// over film ratios 0.5 to 4 (between the nodes, where interpolation errs most); at touch,
/// F_5/2(0) = 2^(3/4) Γ(7/4)/√(2π) = 0.61665 in closed form; nothing beyond h = 6σ; a negative gap
/// holds the value at touch.
#[test]
fn the_asperity_integrals_are_the_gaussian_integrals() {
    for k in 0..36 {
        let lambda = 0.5 + 0.1 * f64::from(k) + 0.0137;
        for (n, tabulated) in [(2.5, f52(lambda)), (3.5, f72(lambda))] {
            let exact = gaussian(n, lambda);
            assert!(
                (tabulated - exact).abs() < 1e-6 * exact,
                "F_{n}({lambda}) = {tabulated}, the integral {exact}"
            );
        }
    }
    let touch = math::powf(2.0, 0.75) * 0.919_062_526_848_883_5 / std::f64::consts::TAU.sqrt();
    assert!((f52(0.0) - touch).abs() < 1e-9, "F_5/2(0) = {}", f52(0.0));
    assert_eq!(f52(RATIO_LIMIT), 0.0);
    assert_eq!(f52(-1.0), f52(0.0));
}

/// A steel journal of radius 10 mm, clearance 20 µm, 16 mm long, roughness 0.4 µm.
fn asperity() -> (Asperity, DryContact) {
    let p = JointParameters {
        model: JointModel::Lubricated,
        clearance: 20e-6,
        journal_radius: 0.01,
        bearing_length: 0.016,
        roughness: 0.4e-6,
        boundary_friction: 0.12,
        ..JointParameters::benchmark()
    };
    match Joint::new(&p).unwrap() {
        Joint::Lubricated(b) => (b.asperity.unwrap(), b.dry),
        _ => unreachable!(),
    }
}

/// The normal force is the derivative of the stored energy, F_a = ∂V_a/∂|e| (central
/// differences, within 1e-5 of the force), from the first touch through the closing gap into
/// metal contact; and it is the integral of the pressure over the circumference by the
/// trapezoidal rule on 20 000 points (within 1e-6).
#[test]
fn the_asperity_force_derives_from_its_energy_and_integrates_the_pressure() {
    let (a, dry) = asperity();
    let (c, r) = (dry.clearance, dry.journal_radius);
    for h_min in [1.6e-6, 1.0e-6, 0.45e-6, 0.1e-6, -0.2e-6] {
        let e = c - h_min;
        let (force, _) = a.normal(e, c, r);
        assert!(force > 0.0, "h_min {h_min}: force {force}");
        let d = 1e-10;
        let derivative = (a.normal(e + d, c, r).1 - a.normal(e - d, c, r).1) / (2.0 * d);
        assert!(
            (derivative - force).abs() < 1e-5 * force,
            "h_min {h_min}: F_a {force}, dV/de {derivative}"
        );
        let points = 20_000;
        let integral: f64 = (0..points)
            .map(|i| {
                let phi = TAU * f64::from(i) / f64::from(points);
                a.pressure((c - e * math::cos(phi)).max(0.0)) * math::cos(phi)
            })
            .sum::<f64>()
            * TAU
            / f64::from(points)
            * r
            * a.length;
        assert!(
            (integral - force).abs() < 1e-6 * force,
            "h_min {h_min}: F_a {force}, trapezoid {integral}"
        );
    }
    assert_eq!(a.normal(c - 2.5e-6, c, r), (0.0, 0.0));
    assert_eq!(a.normal(0.0, c, r), (0.0, 0.0));
}

/// The boundary friction opposes the slip at the contact point with μ_b F_a once the slip is
/// fully developed, and its power is μ_b F_a |v_T|; the force points from the thin film to the
/// centre; smooth surfaces carry nothing.
#[test]
fn boundary_friction_opposes_slip() {
    let (a, dry) = asperity();
    let e = Vector2::new(0.0, dry.clearance - 0.5e-6);
    let k = JointKinematics {
        e,
        e_dot: Vector2::zeros(),
        omega_journal: 100.0,
        omega_bearing: 0.0,
        viscosity: None,
    };
    let (force, state) = a.force(&k, &dry);
    let v_t = dry.slip_speed(&k, &Vector2::new(-1.0, 0.0));
    assert!(v_t > dry.friction_v1);
    assert!(force.force.y < 0.0);
    assert!((force.force.x - a.friction * state.force).abs() < 1e-12 * state.force);
    assert!((state.friction_power - a.friction * state.force * v_t).abs() < 1e-9);
    assert!(state.pressure_peak > a.pressure(0.6e-6));
    let smooth = Joint::new(&JointParameters {
        model: JointModel::Lubricated,
        ..JointParameters::benchmark()
    })
    .unwrap();
    let Joint::Lubricated(b) = smooth else {
        unreachable!()
    };
    assert!(b.asperity.is_none());
    assert_eq!(b.asperity_force(&k).1, AsperityState::default());
}

/// The friction coefficient of a steadily loaded rough bearing (2 kN on a 20 mm journal, 16 mm
/// long, 20 µm clearance, 0.02 Pa s, σ = 0.4 µm, boundary and dry friction 0.12),
/// f = |M_J|/(W R) at the settled eccentricity, over journal speeds from 0.1 to 3000 rad/s (the
/// settled state the joint's own Newton solution gives, [`Joint::eccentricity_carrying`]): the
/// Stribeck curve. At the lowest speed the surfaces touch and f is the boundary coefficient; it
/// falls as the film lifts the journal off its roughness (mixed lubrication) to a minimum where
/// h_min/σ is 2 to 6, then rises with the film's shear (hydrodynamic, towards Petroff's f ∝ ω).
/// Below 0.1 rad/s the slip speed R ω falls under `frictionV1` and the regularised friction
/// vanishes with it (module `contact`).
#[test]
fn a_rough_bearing_follows_the_stribeck_curve() {
    let p = JointParameters {
        model: JointModel::Lubricated,
        clearance: 20e-6,
        journal_radius: 0.01,
        bearing_length: 0.016,
        viscosity: 0.02,
        roughness: 0.4e-6,
        boundary_friction: 0.12,
        switch_eccentricity: 0.99,
        friction: 0.12,
        ..JointParameters::benchmark()
    };
    let joint = Joint::new(&p).unwrap();
    let load = Vector2::new(0.0, -2000.0);
    let curve: Vec<(f64, f64, f64)> = (0..=18)
        .map(|k| {
            let omega = 0.1 * math::powf(10.0, f64::from(k) / 4.0);
            let e = joint.eccentricity_carrying(load, (omega, 0.0), None);
            let k = JointKinematics {
                e,
                e_dot: Vector2::zeros(),
                omega_journal: omega,
                omega_bearing: 0.0,
                viscosity: None,
            };
            let state = joint.bearing_state(&k, crate::joint::MIN_IMPACT_VELOCITY);
            let f = state.friction_torque.abs() / (load.norm() * p.journal_radius);
            let ratio = (p.clearance - e.norm()) / p.roughness;
            println!("omega {omega:10.3} rad/s  h_min/sigma {ratio:6.2}  f {f:.4}");
            (omega, ratio, f)
        })
        .collect();
    let (lowest, _) = curve
        .iter()
        .enumerate()
        .min_by(|a, b| a.1.2.total_cmp(&b.1.2))
        .unwrap();
    let (first, last) = (curve[0], curve[curve.len() - 1]);
    assert!(
        (first.2 - p.boundary_friction).abs() < 0.1 * p.boundary_friction,
        "{first:?}"
    );
    assert!(lowest > 0 && lowest < curve.len() - 1, "no minimum inside");
    assert!(
        curve[..=lowest].windows(2).all(|w| w[1].2 <= w[0].2),
        "f falls to the minimum"
    );
    assert!(
        curve[lowest..].windows(2).all(|w| w[1].2 >= w[0].2),
        "f rises after it"
    );
    assert!(last.2 > 5.0 * curve[lowest].2);
    let at_minimum = curve[lowest].1;
    assert!(
        (2.0..6.0).contains(&at_minimum),
        "minimum at h/σ {at_minimum}"
    );
}
