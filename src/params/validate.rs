//! Validation of [`Parameters`]. Every single-parameter range is the one the variable table
//! declares (read from it, so the library and the FMU accept exactly the same values); the rules
//! that involve several parameters are stated here, each with its reason, and name the parameter,
//! its value and the range that holds for the others.

use super::access::{integer_parameter, real_parameter};
use super::parameters::{
    EXPLICIT_MAX_TOLERANCE, GENERALIZED_ALPHA_MAX_TOLERANCE, Parameters, RodFormulation,
};
use crate::error::{ModelError, Num};
use crate::integrator::Method;
use crate::joint::{JointField, JointModel, JointParameters, JointRole};
use crate::reduction::{Quadrature, check_mode_count};
use crate::variables::{Causality, Kind, VARIABLES};

/// Largest mode count of a sampled rod (`rod.quadrature = sampled`).
pub const MAX_SAMPLED_MODES: usize = 8;

impl Parameters {
    /// Smallest slenderness L/r (r = √(I/A), the radius of gyration) of a flexible rod.
    pub const MIN_SLENDERNESS: f64 = 10.0;

    /// Largest damping ratio of the rod's first axial mode under its material damping: that of
    /// benchmark B's rod at its largest allowed damping (ω_axial/ω₁ = 8.8), so that the rule on
    /// the first bending mode alone decides for every rod of ordinary proportions.
    pub const MAX_AXIAL_DAMPING_RATIO: f64 = 9.0;

    /// The ANCF element is an Euler–Bernoulli beam (no shear deformation, no rotary inertia): a
    /// rod whose radius of gyration exceeds a tenth of its length is a block, not a beam (shear
    /// would change its first bending frequency by tens of percent). Benchmark B: L/r = 27.8.
    fn check_slenderness(&self) -> Result<(), ModelError> {
        let r = (self.rod.second_moment_of_area / self.rod.area).sqrt();
        if self.rod.length < Self::MIN_SLENDERNESS * r {
            return Err(ModelError::invalid(
                "rod.secondMomentOfArea",
                self.rod.second_moment_of_area,
                format!(
                    "(0, {}] m4 for a flexible rod with rod.area = {} m2 and rod.length = {} m: \
                     the slenderness rod.length / sqrt(I/A) = {} must be at least {} for the \
                     Euler-Bernoulli beam the ANCF element is",
                    Num(self.rod.area * (self.rod.length / Self::MIN_SLENDERNESS).powi(2)),
                    Num(self.rod.area),
                    Num(self.rod.length),
                    Num(self.rod.length / r),
                    Num(Self::MIN_SLENDERNESS)
                ),
            ));
        }
        Ok(())
    }

    /// Stiffness-proportional damping gives mode i the damping ratio ζᵢ = β ωᵢ / 2. Beyond
    /// ζ₁ = 1 the rod's first bending mode, and with it every mode, is overdamped: no structural
    /// material behaves so, and the equations become too stiff for the work integrals to follow
    /// the tolerance (measured: energy-balance residual 0.3 of the kinetic energy at ζ₁ = 76,
    /// β = 1e-2 s on benchmark B, rtol 1e-2; 8e-3 at ζ₁ = 1). So β ≤ 2/ω₁, and the first axial
    /// mode's damping ratio at most [`Self::MAX_AXIAL_DAMPING_RATIO`]: a very thin rod's bending
    /// frequency allows a damping that overdamps its axial modes by orders of magnitude
    /// (measured: a 12 cm rod with I = 1.5e-17 m⁴ and β = 1 s, ζ_axial = 7e4, energy-balance
    /// residual 1.2 of the largest energy at rtol 1e-2).
    fn check_material_damping(&self) -> Result<(), ModelError> {
        if self.rod.damping_ratio > 0.0 && self.rod.stiffness_damping > 0.0 {
            return Err(ModelError::invalid(
                "rod.dampingRatio",
                self.rod.damping_ratio,
                format!(
                    "{{0}} with rod.stiffnessDamping = {} s: the rod's damping is given either as \
                     the damping ratio of its first bending mode or as the strain-rate \
                     coefficient, not both",
                    Num(self.rod.stiffness_damping)
                ),
            ));
        }
        let beta = self.rod.damping();
        let name = if self.rod.damping_ratio > 0.0 {
            "rod.dampingRatio"
        } else {
            "rod.stiffnessDamping"
        };
        let axial = self.rod.first_axial_frequency();
        let omega = self
            .rod
            .first_bending_frequency()
            .max(axial / Self::MAX_AXIAL_DAMPING_RATIO);
        if beta * omega > 2.0 {
            let (value, range) = if self.rod.damping_ratio > 0.0 {
                let first = self.rod.first_bending_frequency();
                (
                    self.rod.damping_ratio,
                    format!("[0, {}]", Num(first / omega)),
                )
            } else {
                (beta, format!("[0, {}] s", Num(2.0 / omega)))
            };
            return Err(ModelError::invalid(
                name,
                value,
                format!(
                    "{range} for this rod: its first bending mode (ω₁ = π²/L² √(EI/ρA) = {} \
                     rad/s from rod.length, rod.youngsModulus, rod.secondMomentOfArea, \
                     rod.density, rod.area) would get the damping ratio β ω₁/2 = {} > 1, \
                     overdamping every mode, or its first axial mode (ω = π/L √(E/ρ) = {} rad/s) \
                     a damping ratio above {}",
                    Num(self.rod.first_bending_frequency()),
                    Num(0.5 * beta * self.rod.first_bending_frequency()),
                    Num(axial),
                    Num(Self::MAX_AXIAL_DAMPING_RATIO)
                ),
            ));
        }
        Ok(())
    }

    /// Checks every parameter against its declared range (the variable table's min and max, the
    /// same bounds fmi2SetReal and fmi2SetInteger apply), then the rules between parameters.
    pub fn validate(&self) -> Result<(), ModelError> {
        self.check_declared_ranges()?;
        if self.rod_formulation == RodFormulation::CraigBampton {
            check_mode_count(self.n_elements, self.n_modes, self.boundary)?;
            if self.quadrature == Quadrature::Sampled && self.n_modes > MAX_SAMPLED_MODES {
                return Err(ModelError::invalid(
                    "rod.nModes",
                    self.n_modes as f64,
                    format!(
                        "[0, {MAX_SAMPLED_MODES}] with rod.quadrature = sampled: its points are \
                         fitted at initialization, in a time that grows with the fourth power of \
                         the mode count (0.1 s at {MAX_SAMPLED_MODES} modes and 64 elements)"
                    ),
                ));
            }
        }
        if self.rod.length <= self.crank_length {
            return Err(ModelError::invalid(
                "rod.length",
                self.rod.length,
                format!(
                    "(crank.length, inf) = ({}, inf): the rod must be longer than the crank",
                    Num(self.crank_length)
                ),
            ));
        }
        let reach = self.crank_length + self.slider_offset.abs();
        if reach >= self.rod.length {
            return Err(ModelError::invalid(
                "slider.offset",
                self.slider_offset,
                format!(
                    "(-{gap}, {gap}) = (-(rod.length - crank.length), rod.length - crank.length) \
                     with rod.length = {} m and crank.length = {} m: a full crank turn needs \
                     crank.length + |slider.offset| < rod.length",
                    Num(self.rod.length),
                    Num(self.crank_length),
                    gap = Num(((self.rod.length - self.crank_length) * 1e12).round() / 1e12),
                ),
            ));
        }
        if self.rod_formulation != RodFormulation::Rigid {
            self.check_slenderness()?;
            self.check_material_damping()?;
        }
        for (role, joint) in self.joints() {
            check_joint(role, joint)?;
        }
        if !matches!(self.slider_force_table_period, 360 | 720) {
            return Err(ModelError::invalid(
                "slider.forceTablePeriod",
                self.slider_force_table_period as f64,
                "{360, 720}: one crank turn, or two for a four-stroke cycle",
            ));
        }
        let tolerance = self.relative_tolerance;
        if self.method == Method::DormandPrince && tolerance > EXPLICIT_MAX_TOLERANCE {
            return Err(ModelError::invalid(
                "solver.relativeTolerance",
                tolerance,
                format!(
                    "[1e-12, {}] with solver.method = explicit: looser \
                     explicit runs leave the flexible rod's stiff content ringing at the edge of \
                     stability (peak ideal-joint force +25 % at 1e-3 with 8 modes)",
                    Num(EXPLICIT_MAX_TOLERANCE)
                ),
            ));
        }
        if self.method == Method::GeneralizedAlpha && tolerance > GENERALIZED_ALPHA_MAX_TOLERANCE {
            return Err(ModelError::invalid(
                "solver.relativeTolerance",
                tolerance,
                format!(
                    "[1e-12, {}] with solver.method = \
                     generalizedAlpha: looser second-order steps mis-resolve the dry impacts \
                     (rigid rod: peak joint force +60 % at 5e-2)",
                    Num(GENERALIZED_ALPHA_MAX_TOLERANCE)
                ),
            ));
        }
        Ok(())
    }
}

/// The rules between one joint's parameters: a clearance joint needs a gap, and friction
/// develops over a speed band.
fn check_joint(role: JointRole, joint: &JointParameters) -> Result<(), ModelError> {
    let name = |field| role.parameter(field);
    if joint.model != JointModel::Ideal && joint.clearance <= 0.0 {
        return Err(ModelError::invalid(
            name(JointField::Clearance),
            joint.clearance,
            format!(
                "(0, inf) with {} = {}: a clearance joint needs a gap ({} = ideal for none)",
                name(JointField::Model),
                format!("{:?}", joint.model).to_lowercase(),
                name(JointField::Model),
            ),
        ));
    }
    if joint.friction_v1 <= joint.friction_v0 {
        return Err(ModelError::invalid(
            name(JointField::FrictionV1),
            joint.friction_v1,
            format!(
                "({}, inf) = ({}, inf)",
                name(JointField::FrictionV0),
                Num(joint.friction_v0)
            ),
        ));
    }
    Ok(())
}

impl Parameters {
    /// Every parameter within the [min, max] its row of the variable table declares (NaN never
    /// is); the error quotes the bounds as the FMU does. Rules between parameters are not checked
    /// (a parameter set still being entered may break them).
    pub fn check_declared_ranges(&self) -> Result<(), ModelError> {
        for v in VARIABLES
            .iter()
            .filter(|v| v.causality == Causality::Parameter)
        {
            let (value, min, max, unit) = match v.kind {
                Kind::Real { min, max, unit, .. } => (real_parameter(self, v.vr), min, max, unit),
                Kind::Integer { min, max, .. } => (
                    integer_parameter(self, v.vr).map(f64::from),
                    f64::from(min),
                    f64::from(max),
                    "",
                ),
                // A switch's value is one of its items by type; a file is checked when read.
                Kind::Enumeration { .. } | Kind::Boolean | Kind::String { .. } => continue,
            };
            if let Some(value) = value.filter(|x| !(min..=max).contains(x)) {
                return Err(ModelError::invalid(
                    v.name,
                    value,
                    format!("[{}, {}] {unit}", Num(min), Num(max))
                        .trim_end()
                        .to_string(),
                ));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ancf::RodProperties;

    /// The short-bearing film is flagged outside L/D <= 0.5 (benchmark C: L/D = 2.1), only for
    /// the lubricated joint.
    #[test]
    fn long_bearings_are_flagged() {
        let c = Parameters::benchmark_c();
        let warnings = c.warnings();
        assert_eq!(warnings.len(), 1);
        assert!(warnings[0].contains("2.105") && warnings[0].contains("L/D <= 0.5"));
        let short = Parameters {
            joint: JointParameters {
                bearing_length: 0.009,
                ..c.joint
            },
            ..c
        };
        assert!(short.warnings().is_empty());
        assert!(Parameters::default().warnings().is_empty());
    }

    /// Every joint takes every joint model.
    #[test]
    fn every_joint_can_be_worn() {
        for model in [JointModel::Dry, JointModel::Lubricated] {
            let worn = JointParameters {
                model,
                ..JointParameters::benchmark()
            };
            for p in [
                Parameters {
                    main_bearing: worn,
                    ..Parameters::default()
                },
                Parameters {
                    crank_pin: worn,
                    ..Parameters::default()
                },
            ] {
                p.validate().unwrap();
            }
        }
    }

    /// Material damping is accepted up to a critically damped first bending mode (β ω₁ = 2,
    /// ω₁ = 15 270 rad/s for benchmark B's rod) and only for a flexible rod; the message names
    /// the limit for this rod. A very thin rod is limited by its first axial mode instead.
    #[test]
    fn overdamped_rods_are_rejected() {
        let omega = Parameters::default().rod.first_bending_frequency();
        assert!((omega - 15_270.0).abs() < 10.0, "{omega}");
        let with = |beta: f64, rod_formulation| Parameters {
            rod: RodProperties {
                stiffness_damping: beta,
                ..RodProperties::benchmark_b()
            },
            rod_formulation,
            ..Parameters::default()
        };
        with(0.99 * 2.0 / omega, RodFormulation::CraigBampton)
            .validate()
            .unwrap();
        with(1.0, RodFormulation::Rigid).validate().unwrap();
        for rod in [RodFormulation::CraigBampton, RodFormulation::Ancf] {
            let message = with(1.01 * 2.0 / omega, rod)
                .validate()
                .unwrap_err()
                .to_string();
            assert!(
                message.contains("rod.stiffnessDamping")
                    && message.contains(&format!("[0, {}] s", Num(2.0 / omega))),
                "{message}"
            );
        }
    }

    /// A flexible rod must be slender (L/r ≥ 10); the rigid rod need not be.
    #[test]
    fn thick_rods_are_rejected() {
        let p = Parameters::default();
        let r = (p.rod.second_moment_of_area / p.rod.area).sqrt();
        assert!((p.rod.length / r - 27.8).abs() < 0.05);
        let with = |i: f64, rod_formulation| Parameters {
            rod: RodProperties {
                second_moment_of_area: i,
                ..RodProperties::benchmark_b()
            },
            rod_formulation,
            ..Parameters::default()
        };
        let limit = p.rod.area * (p.rod.length / 10.0).powi(2);
        with(0.99 * limit, RodFormulation::Ancf).validate().unwrap();
        with(1.01 * limit, RodFormulation::Rigid)
            .validate()
            .unwrap();
        let message = with(1.01 * limit, RodFormulation::CraigBampton)
            .validate()
            .unwrap_err()
            .to_string();
        assert!(
            message.contains("rod.secondMomentOfArea") && message.contains("at least 10"),
            "{message}"
        );
        let thin = RodProperties {
            second_moment_of_area: 1.5e-17,
            ..RodProperties::benchmark_b()
        };
        let axial_limit = 2.0 * Parameters::MAX_AXIAL_DAMPING_RATIO / thin.first_axial_frequency();
        assert!(axial_limit < 2.0 / thin.first_bending_frequency());
        for (beta, accepted) in [(0.99 * axial_limit, true), (1.01 * axial_limit, false)] {
            let p = Parameters {
                rod: RodProperties {
                    stiffness_damping: beta,
                    ..thin
                },
                ..Parameters::default()
            };
            assert_eq!(p.validate().is_ok(), accepted, "β = {beta} s");
        }
    }

    /// The library rejects just beyond every declared bound with an error naming the parameter:
    /// the variable table is the one statement of each range.
    #[test]
    fn declared_ranges_are_the_library_ranges() {
        use crate::params::{set_integer_parameter, set_real_parameter};
        let beyond = |v: &crate::variables::Variable, value: f64| {
            let mut p = Parameters::default();
            let set = match v.kind {
                Kind::Real { .. } => set_real_parameter(&mut p, v.vr, value),
                _ => set_integer_parameter(&mut p, v.vr, value as i32),
            };
            if !set {
                // A negative count has no field value to hold it.
                assert!(value < 0.0, "{} = {value} not stored", v.name);
                return;
            }
            match p.validate() {
                Err(ModelError::InvalidParameter { name, .. }) => assert_eq!(name, v.name),
                other => panic!("{} = {value}: expected an error, got {other:?}", v.name),
            }
        };
        for v in VARIABLES
            .iter()
            .filter(|v| v.causality == Causality::Parameter)
        {
            match v.kind {
                Kind::Real { min, max, .. } => {
                    beyond(v, min.next_down());
                    beyond(v, max.next_up());
                    beyond(v, f64::NAN);
                }
                Kind::Integer { min, max, .. } => {
                    if min > i32::MIN {
                        beyond(v, f64::from(min - 1));
                    }
                    if max < i32::MAX {
                        beyond(v, f64::from(max + 1));
                    }
                }
                Kind::Enumeration { .. } | Kind::Boolean | Kind::String { .. } => {}
            }
        }
        let elements = VARIABLES.iter().find(|v| v.name == "rod.nElements");
        assert!(matches!(
            elements.map(|v| v.kind),
            Some(Kind::Integer { max, .. }) if max as usize == crate::ancf::rod::MAX_ELEMENTS
        ));
    }

    #[test]
    fn defaults_are_valid_and_benchmark_b() {
        let p = Parameters::default();
        p.validate().unwrap();
        assert!((p.rod.mass() - 0.21).abs() < 1e-12);
        assert!((p.joint.bearing_radius() - 0.010).abs() < 1e-15);
    }

    /// Every listed bad value is rejected with an error naming the parameter.
    #[test]
    fn bad_values_name_the_parameter() {
        let base = Parameters::default();
        let cases: Vec<(&str, Parameters)> = vec![
            (
                "slider.forceTablePeriod",
                Parameters {
                    slider_force_table_period: 540,
                    ..base.clone()
                },
            ),
            (
                "rod.length",
                Parameters {
                    rod: RodProperties {
                        length: 0.04,
                        ..base.rod
                    },
                    ..base.clone()
                },
            ),
            (
                "joint.clearance",
                Parameters {
                    joint: JointParameters {
                        clearance: 0.0,
                        ..base.clone().joint
                    },
                    ..base.clone()
                },
            ),
            (
                "joint.clearance",
                Parameters {
                    joint: JointParameters {
                        clearance: f64::NAN,
                        ..base.clone().joint
                    },
                    ..base.clone()
                },
            ),
            (
                "joint.restitution",
                Parameters {
                    joint: JointParameters {
                        restitution: 0.0,
                        ..base.clone().joint
                    },
                    ..base.clone()
                },
            ),
            (
                "joint.restitution",
                Parameters {
                    joint: JointParameters {
                        restitution: 1.2,
                        ..base.clone().joint
                    },
                    ..base.clone()
                },
            ),
            (
                "joint.switchEccentricity",
                Parameters {
                    joint: JointParameters {
                        switch_eccentricity: 1.0,
                        ..base.clone().joint
                    },
                    ..base.clone()
                },
            ),
            (
                "joint.frictionV1",
                Parameters {
                    joint: JointParameters {
                        friction_v1: 1e-5,
                        ..base.clone().joint
                    },
                    ..base.clone()
                },
            ),
            (
                "joint.friction",
                Parameters {
                    joint: JointParameters {
                        friction: -0.1,
                        ..base.clone().joint
                    },
                    ..base.clone()
                },
            ),
            (
                "slider.mass",
                Parameters {
                    slider_mass: f64::INFINITY,
                    ..base.clone()
                },
            ),
            (
                "crank.length",
                Parameters {
                    crank_length: -0.05,
                    ..base.clone()
                },
            ),
            (
                "rod.nModes",
                Parameters {
                    n_modes: 17,
                    ..base.clone()
                },
            ),
            (
                "rod.nModes",
                Parameters {
                    n_modes: MAX_SAMPLED_MODES + 1,
                    quadrature: Quadrature::Sampled,
                    ..base.clone()
                },
            ),
            (
                "rod.nElements",
                Parameters {
                    n_elements: 0,
                    ..base.clone()
                },
            ),
            (
                "solver.relativeTolerance",
                Parameters {
                    relative_tolerance: 0.0,
                    ..base.clone()
                },
            ),
            (
                "solver.relativeTolerance",
                Parameters {
                    method: Method::DormandPrince,
                    relative_tolerance: 1e-2,
                    ..base.clone()
                },
            ),
            (
                "solver.relativeTolerance",
                Parameters {
                    method: Method::GeneralizedAlpha,
                    relative_tolerance: 5e-2,
                    ..base.clone()
                },
            ),
            (
                "solver.spectralRadius",
                Parameters {
                    spectral_radius: 1.5,
                    ..base.clone()
                },
            ),
        ];
        for (name, p) in cases {
            match p.validate() {
                Err(ModelError::InvalidParameter { name: n, .. }) => assert_eq!(n, name),
                other => panic!("{name}: expected an error, got {other:?}"),
            }
        }
        let ok = Parameters {
            joint: JointParameters {
                restitution: 1.0,
                model: JointModel::Ideal,
                clearance: 0.0,
                ..base.joint
            },
            ..base
        };
        ok.validate().unwrap();
    }
}
