//! Parameters of the slider-crank model, in SI units, with defaults = benchmark B (docs/model.md §5(b))
//! (steel ANCF rod, 8 elements, 4 mode shapes, dry clearance joint, 5000 rpm speed drive).
//!
//! Every check names the FMU parameter, its value and the allowed range.

use crate::ancf::RodProperties;
use crate::ancf::rod::MAX_ELEMENTS;
use crate::error::{ModelError, require_non_negative, require_positive};
use crate::integrator::{Method, Tolerances};
use crate::reduction::{Boundary, check_mode_count};

/// How the connecting rod is modelled.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RodFormulation {
    /// Rigid uniform bar (natural coordinates of its two pins).
    Rigid,
    /// Full ANCF model with `n_elements` elements.
    Ancf,
    /// ANCF reduced by Craig–Bampton with `n_modes` mode shapes.
    CraigBampton,
}

/// Model of the rod–slider joint.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JointModel {
    /// Ideal revolute joint (constraint).
    Ideal,
    /// Dry clearance joint: Lankarani–Nikravesh contact with Coulomb–Ambrósio friction.
    Dry,
    /// Lubricated journal bearing (short-bearing film), dry contact near metal contact.
    Lubricated,
}

/// Hysteresis-damping law of the dry contact force F_N = K δ^1.5 (1 + χ δ̇/δ̇⁻)
/// ([`crate::joint::DryContact`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ContactLaw {
    /// Lankarani & Nikravesh (1990), χ = 3(1 − c_e²)/4: derived for restitution near 1 (the seed
    /// paper's law).
    LankaraniNikravesh,
    /// Flores, Machado, Silva & Martins (2011), χ = 8(1 − c_e)/(5 c_e): any restitution.
    Flores,
    /// Hu & Guo (2015), χ = 3(1 − c_e)/(2 c_e): any restitution.
    HuGuo,
}

/// How the rod starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InitialState {
    /// Quasi-statically equilibrated: deformed by the inertial loads of the initial motion
    /// ([`crate::mechanism::SliderCrank::equilibrate`]).
    Equilibrated,
    /// Straight and unstressed (docs/model.md §10, the reference start).
    Straight,
}

/// What drives the crank.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DriveMode {
    /// The crank speed is prescribed (input `drive.speed`); the torque is an output.
    Speed,
    /// The crank torque is prescribed (input `drive.torque`); angle and speed are dynamic.
    Torque,
}

/// All parameters of the model (SI units).
#[derive(Clone, Debug, PartialEq)]
pub struct Parameters {
    /// Rod formulation.
    pub rod_formulation: RodFormulation,
    /// Number of ANCF elements (ancf and craigBampton).
    pub n_elements: usize,
    /// Number of Craig–Bampton mode shapes, 0 ..= [`crate::reduction::max_modes`].
    pub n_modes: usize,
    /// Craig–Bampton interface (the rod coordinates kept physical).
    pub boundary: Boundary,
    /// How the rod starts.
    pub initial_state: InitialState,
    /// Rod material and section.
    pub rod: RodProperties,
    /// Crank length r_c (pivot to pin) \[m\].
    pub crank_length: f64,
    /// Crank mass \[kg\] (uniform, centre of mass at mid-length).
    pub crank_mass: f64,
    /// Crank moment of inertia about its centre of mass \[kg m²\].
    pub crank_inertia: f64,
    /// Initial crank angle \[rad\].
    pub crank_initial_angle: f64,
    /// Initial crank speed \[rad/s\].
    pub crank_initial_speed: f64,
    /// Slider mass \[kg\].
    pub slider_mass: f64,
    /// Joint model.
    pub joint_model: JointModel,
    /// Radial clearance c = R_bearing − R_journal \[m\].
    pub clearance: f64,
    /// Journal (pin) radius R_j \[m\].
    pub journal_radius: f64,
    /// Young's modulus of journal and bearing \[Pa\].
    pub joint_youngs_modulus: f64,
    /// Poisson ratio of journal and bearing.
    pub joint_poisson_ratio: f64,
    /// Coefficient of restitution c_e ∈ (0, 1].
    pub restitution: f64,
    /// Hysteresis-damping law of the dry contact.
    pub contact_law: ContactLaw,
    /// Coulomb friction coefficient μ.
    pub friction: f64,
    /// Tangential speed below which friction vanishes v₀ \[m/s\].
    pub friction_v0: f64,
    /// Tangential speed above which friction is fully developed v₁ \[m/s\].
    pub friction_v1: f64,
    /// Lubricant dynamic viscosity \[Pa s\].
    pub viscosity: f64,
    /// Bearing length L \[m\].
    pub bearing_length: f64,
    /// Eccentricity ratio above which dry contact takes over, ε_b ∈ (0, 1).
    pub switch_eccentricity: f64,
    /// Drive mode.
    pub drive_mode: DriveMode,
    /// Gravitational acceleration along −y \[m/s²\].
    pub gravity: f64,
    /// Time-integration method.
    pub method: Method,
    /// Spectral radius at infinity ρ∞ ∈ [0, 1] of the generalized-α method (1: no numerical
    /// dissipation, 0: unresolved frequencies annihilated in one step).
    pub spectral_radius: f64,
    /// Relative tolerance of the error-controlled integrator.
    pub relative_tolerance: f64,
    /// Largest internal step \[s\].
    pub max_step_size: f64,
    /// Work limit: largest number of internal step attempts (accepted or rejected) in one
    /// communication interval.
    pub max_steps_per_interval: usize,
}

/// Loosest relative tolerance accepted with the explicit method (`solver.method` = explicit).
///
/// Measured over two revolutions of benchmark B (BENCHMARKS.md, "Loosest tolerances"): with the
/// ideal joint the flexible rod's peak joint force is 25 % high at rtol 1e-3 with 8 modes (9 % with
/// 4, 96 % with 4 at 1e-2), and within 2.5 % at 1e-4 for every mode count. A loose explicit run is
/// bound by stability, not accuracy, and the rod's stiff content rings undamped in the constraint
/// force. The implicit method damps that content and stays within 2.1 % up to rtol 0.1.
pub const EXPLICIT_MAX_TOLERANCE: f64 = 1e-4;

/// Loosest relative tolerance accepted with the generalized-α method (`solver.method` =
/// generalizedAlpha).
///
/// Measured over two revolutions of benchmarks B/C (BENCHMARKS.md, "Integrators"): at 3e-2 the peak
/// joint force and penetration of every rod × joint model are within 2.2 % of converged runs; at
/// 5e-2 the rigid rod's dry impacts are not (peak force +60 %), at 1e-1 they are +250 %.
pub const GENERALIZED_ALPHA_MAX_TOLERANCE: f64 = 3e-2;

/// Default spectral radius at infinity of the generalized-α method (`solver.spectralRadius`).
pub const DEFAULT_SPECTRAL_RADIUS: f64 = 0.8;

/// Default work limit per communication interval (`solver.maxStepsPerInterval`): ample for every
/// documented case (the worst interval measured: 7 065 attempts with joint.friction = 1, about 0.3 s
/// of wall time for the 4-mode rod), and a bound of seconds, not hours, for a model that stalls.
pub const DEFAULT_MAX_STEPS_PER_INTERVAL: usize = 50_000;

/// 5000 rpm in rad/s.
pub const BENCHMARK_SPEED: f64 = 5000.0 * std::f64::consts::TAU / 60.0;

impl Default for Parameters {
    fn default() -> Self {
        Self {
            rod_formulation: RodFormulation::CraigBampton,
            n_elements: 8,
            n_modes: 4,
            boundary: Boundary::Pins,
            initial_state: InitialState::Equilibrated,
            rod: RodProperties::benchmark_b(),
            crank_length: 0.05,
            crank_mass: 0.30,
            crank_inertia: 1e-4,
            crank_initial_angle: 0.0,
            crank_initial_speed: BENCHMARK_SPEED,
            slider_mass: 0.14,
            joint_model: JointModel::Dry,
            clearance: 0.5e-3,
            journal_radius: 9.5e-3,
            joint_youngs_modulus: 207e9,
            joint_poisson_ratio: 0.3,
            restitution: 0.9,
            contact_law: ContactLaw::LankaraniNikravesh,
            friction: 0.0,
            friction_v0: 1e-4,
            friction_v1: 1e-3,
            viscosity: 0.4,
            bearing_length: 0.04,
            switch_eccentricity: 0.95,
            drive_mode: DriveMode::Speed,
            gravity: 0.0,
            method: Method::Esdirk,
            spectral_radius: DEFAULT_SPECTRAL_RADIUS,
            relative_tolerance: 1e-2,
            max_step_size: 1e-4,
            max_steps_per_interval: DEFAULT_MAX_STEPS_PER_INTERVAL,
        }
    }
}

fn require_in(
    name: &'static str,
    value: f64,
    lo: f64,
    hi: f64,
    range: &str,
) -> Result<f64, ModelError> {
    let ok = match range.as_bytes() {
        [b'(', .., b']'] => value > lo && value <= hi,
        [b'(', .., b')'] => value > lo && value < hi,
        [b'[', .., b')'] => value >= lo && value < hi,
        _ => value >= lo && value <= hi,
    };
    if value.is_finite() && ok {
        Ok(value)
    } else {
        Err(ModelError::invalid(name, value, range))
    }
}

impl Parameters {
    /// Benchmark A (docs/model.md §5(a)): rigid rod (0.21 kg, inertia m l²/12), dry joint, 5000 rpm.
    pub fn benchmark_a() -> Self {
        Self {
            rod_formulation: RodFormulation::Rigid,
            ..Self::default()
        }
    }

    /// Benchmark B (docs/model.md §5(b)) with `n_elements` elements: full ANCF rod, dry joint.
    pub fn benchmark_b() -> Self {
        Self {
            rod_formulation: RodFormulation::Ancf,
            ..Self::default()
        }
    }

    /// Benchmark C (docs/model.md §5(b)): as B with the lubricated joint.
    pub fn benchmark_c() -> Self {
        Self {
            joint_model: JointModel::Lubricated,
            ..Self::benchmark_b()
        }
    }

    /// Benchmark D (the lubricated → dry hand-over): the defaults (4-mode rod) with the
    /// lubricated joint, a 40× thinner lubricant (0.01 Pa s) and a 0.5 kg slider, so that the
    /// journal crosses the switch eccentricity ratio and reaches metal contact many times per
    /// revolution.
    pub fn benchmark_d() -> Self {
        Self {
            joint_model: JointModel::Lubricated,
            viscosity: 0.01,
            slider_mass: 0.5,
            ..Self::default()
        }
    }

    /// Smallest slenderness L/r (r = √(I/A), the radius of gyration) of a flexible rod.
    pub const MIN_SLENDERNESS: f64 = 10.0;

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
                    "(0, {:.4e}] m4 for a flexible rod with rod.area = {:e} m2 and rod.length = \
                     {} m: the slenderness rod.length / sqrt(I/A) = {:.3} must be at least {} \
                     for the Euler-Bernoulli beam the ANCF element is",
                    self.rod.area * (self.rod.length / Self::MIN_SLENDERNESS).powi(2),
                    self.rod.area,
                    self.rod.length,
                    self.rod.length / r,
                    Self::MIN_SLENDERNESS
                ),
            ));
        }
        Ok(())
    }

    /// Stiffness-proportional damping gives mode i the damping ratio ζᵢ = β ωᵢ / 2. Beyond
    /// ζ₁ = 1 the rod's first bending mode, and with it every mode, is overdamped: no structural
    /// material behaves so, and the equations become too stiff for the work integrals to follow
    /// the tolerance (measured: energy-balance residual 0.3 of the kinetic energy at ζ₁ = 76,
    /// β = 1e-2 s on benchmark B, rtol 1e-2; 8e-3 at ζ₁ = 1). So β ≤ 2/ω₁.
    fn check_material_damping(&self) -> Result<(), ModelError> {
        let beta = self.rod.stiffness_damping;
        let omega = self.rod.first_bending_frequency();
        if beta * omega > 2.0 {
            return Err(ModelError::invalid(
                "rod.stiffnessDamping",
                beta,
                format!(
                    "[0, {:.3e}] s for this rod: its first bending mode (ω₁ = π²/L² √(EI/ρA) = \
                     {omega:.4e} rad/s from rod.length, rod.youngsModulus, rod.secondMomentOfArea, \
                     rod.density, rod.area) would get the damping ratio β ω₁/2 = {:.3e} > 1, \
                     overdamping every mode",
                    2.0 / omega,
                    0.5 * beta * omega
                ),
            ));
        }
        Ok(())
    }

    /// Bearing (hole) radius R_i = R_j + c \[m\].
    pub fn bearing_radius(&self) -> f64 {
        self.journal_radius + self.clearance
    }

    /// Crank moment of inertia about the pivot, I_c + m_c (r_c/2)² \[kg m²\].
    pub fn crank_inertia_about_pivot(&self) -> f64 {
        self.crank_inertia + self.crank_mass * (0.5 * self.crank_length).powi(2)
    }

    /// Integrator tolerances: rtol as given for both the relative and the absolute part (the
    /// absolute one in units of each state's scale, [`crate::mechanism::SliderCrank::error_scales`]),
    /// the maximum step, and a 1e-14 s floor.
    pub fn tolerances(&self) -> Tolerances {
        Tolerances::from_relative(self.relative_tolerance, self.max_step_size)
    }

    /// Largest bearing length-to-diameter ratio L/D for which the short-bearing (Ocvirk) film is
    /// a fair approximation.
    pub const SHORT_BEARING_MAX_RATIO: f64 = 0.5;

    /// Valid parameters that take the model outside the range of one of its laws: one message per
    /// cause, for the FMU to log as a warning when it builds the model.
    pub fn warnings(&self) -> Vec<String> {
        let mut warnings = Vec::new();
        let ratio = self.bearing_length / (2.0 * self.journal_radius);
        if self.joint_model == JointModel::Lubricated && ratio > Self::SHORT_BEARING_MAX_RATIO {
            warnings.push(format!(
                "joint.bearingLength / (2 joint.journalRadius) = {ratio:.3} is outside the \
                 short-bearing range L/D <= {}: the film force is the infinitely-short-bearing \
                 model's, which overestimates a long bearing's squeeze and wedge forces",
                Self::SHORT_BEARING_MAX_RATIO
            ));
        }
        warnings
    }

    /// Checks every parameter and their consistency.
    pub fn validate(&self) -> Result<(), ModelError> {
        if self.rod_formulation != RodFormulation::Rigid
            && !(1..=MAX_ELEMENTS).contains(&self.n_elements)
        {
            return Err(ModelError::invalid(
                "rod.nElements",
                self.n_elements as f64,
                "[1, 64]",
            ));
        }
        if self.rod_formulation == RodFormulation::CraigBampton {
            check_mode_count(self.n_elements, self.n_modes, self.boundary)?;
        }
        self.rod.validate()?;
        require_positive("crank.length", self.crank_length)?;
        if self.rod.length <= self.crank_length {
            return Err(ModelError::invalid(
                "rod.length",
                self.rod.length,
                format!(
                    "(crank.length, inf) = ({}, inf): the rod must be longer than the crank",
                    self.crank_length
                ),
            ));
        }
        if self.rod_formulation != RodFormulation::Rigid {
            self.check_slenderness()?;
            self.check_material_damping()?;
        }
        require_positive("crank.mass", self.crank_mass)?;
        require_positive("crank.inertia", self.crank_inertia)?;
        require_in(
            "crank.initialAngle",
            self.crank_initial_angle,
            -1e3,
            1e3,
            "[-1000, 1000]",
        )?;
        require_in(
            "crank.initialSpeed",
            self.crank_initial_speed,
            -1e4,
            1e4,
            "[-10000, 10000]",
        )?;
        require_positive("slider.mass", self.slider_mass)?;
        require_positive("joint.journalRadius", self.journal_radius)?;
        if self.joint_model == JointModel::Ideal {
            require_non_negative("joint.clearance", self.clearance)?;
        } else if !(self.clearance.is_finite() && self.clearance > 0.0) {
            return Err(ModelError::invalid(
                "joint.clearance",
                self.clearance,
                format!(
                    "(0, inf) with joint.model = {}: a clearance joint needs a gap \
                     (joint.model = ideal for none)",
                    format!("{:?}", self.joint_model).to_lowercase()
                ),
            ));
        }
        require_positive("joint.youngsModulus", self.joint_youngs_modulus)?;
        require_in(
            "joint.poissonRatio",
            self.joint_poisson_ratio,
            -1.0,
            0.5,
            "(-1, 0.5)",
        )?;
        require_in("joint.restitution", self.restitution, 0.0, 1.0, "(0, 1]")?;
        require_non_negative("joint.friction", self.friction)?;
        require_non_negative("joint.frictionV0", self.friction_v0)?;
        if !(self.friction_v1.is_finite() && self.friction_v1 > self.friction_v0) {
            return Err(ModelError::invalid(
                "joint.frictionV1",
                self.friction_v1,
                format!("(joint.frictionV0, inf) = ({}, inf)", self.friction_v0),
            ));
        }
        require_positive("joint.viscosity", self.viscosity)?;
        require_positive("joint.bearingLength", self.bearing_length)?;
        require_in(
            "joint.switchEccentricity",
            self.switch_eccentricity,
            0.0,
            1.0,
            "(0, 1)",
        )?;
        require_in("gravity", self.gravity, -1e3, 1e3, "[-1000, 1000]")?;
        require_in(
            "solver.spectralRadius",
            self.spectral_radius,
            0.0,
            1.0,
            "[0, 1]",
        )?;
        require_in(
            "solver.relativeTolerance",
            self.relative_tolerance,
            1e-12,
            1e-1,
            "[1e-12, 0.1]",
        )?;
        if self.method == Method::DormandPrince && self.relative_tolerance > EXPLICIT_MAX_TOLERANCE
        {
            return Err(ModelError::invalid(
                "solver.relativeTolerance",
                self.relative_tolerance,
                format!(
                    "[1e-12, {EXPLICIT_MAX_TOLERANCE:e}] with solver.method = explicit: looser \
                     explicit runs leave the flexible rod's stiff content ringing at the edge of \
                     stability (peak ideal-joint force +25 % at 1e-3 with 8 modes)"
                ),
            ));
        }
        if self.method == Method::GeneralizedAlpha
            && self.relative_tolerance > GENERALIZED_ALPHA_MAX_TOLERANCE
        {
            return Err(ModelError::invalid(
                "solver.relativeTolerance",
                self.relative_tolerance,
                format!(
                    "[1e-12, {GENERALIZED_ALPHA_MAX_TOLERANCE:e}] with solver.method = \
                     generalizedAlpha: looser second-order steps mis-resolve the dry impacts \
                     (rigid rod: peak joint force +60 % at 5e-2)"
                ),
            ));
        }
        if self.max_steps_per_interval == 0 {
            return Err(ModelError::invalid(
                "solver.maxStepsPerInterval",
                0.0,
                "[1, 2147483647]",
            ));
        }
        require_in(
            "solver.maxStepSize",
            self.max_step_size,
            1e-9,
            1.0,
            "[1e-09, 1]",
        )?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The short-bearing film is flagged outside L/D <= 0.5 (benchmark C: L/D = 2.1), only for
    /// the lubricated joint.
    #[test]
    fn long_bearings_are_flagged() {
        let c = Parameters::benchmark_c();
        let warnings = c.warnings();
        assert_eq!(warnings.len(), 1);
        assert!(warnings[0].contains("2.105") && warnings[0].contains("L/D <= 0.5"));
        let short = Parameters {
            bearing_length: 0.009,
            ..c
        };
        assert!(short.warnings().is_empty());
        assert!(Parameters::default().warnings().is_empty());
    }

    /// Material damping is accepted up to a critically damped first bending mode (β ω₁ = 2,
    /// ω₁ = 15 270 rad/s for benchmark B's rod) and only for a flexible rod; the message names
    /// the limit for this rod.
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
                message.contains("rod.stiffnessDamping") && message.contains("[0, 1.310e-4] s"),
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
    }

    #[test]
    fn defaults_are_valid_and_benchmark_b() {
        let p = Parameters::default();
        p.validate().unwrap();
        assert!((p.rod.mass() - 0.21).abs() < 1e-12);
        assert!((p.bearing_radius() - 0.010).abs() < 1e-15);
    }

    /// Every listed bad value is rejected with an error naming the parameter.
    #[test]
    fn bad_values_name_the_parameter() {
        let base = Parameters::default();
        let cases: Vec<(&str, Parameters)> = vec![
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
                    clearance: 0.0,
                    ..base.clone()
                },
            ),
            (
                "joint.clearance",
                Parameters {
                    clearance: f64::NAN,
                    ..base.clone()
                },
            ),
            (
                "joint.restitution",
                Parameters {
                    restitution: 0.0,
                    ..base.clone()
                },
            ),
            (
                "joint.restitution",
                Parameters {
                    restitution: 1.2,
                    ..base.clone()
                },
            ),
            (
                "joint.switchEccentricity",
                Parameters {
                    switch_eccentricity: 1.0,
                    ..base.clone()
                },
            ),
            (
                "joint.frictionV1",
                Parameters {
                    friction_v1: 1e-5,
                    ..base.clone()
                },
            ),
            (
                "joint.friction",
                Parameters {
                    friction: -0.1,
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
            restitution: 1.0,
            joint_model: JointModel::Ideal,
            clearance: 0.0,
            ..base
        };
        ok.validate().unwrap();
    }
}
