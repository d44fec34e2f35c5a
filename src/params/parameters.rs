//! The parameter set: the switches, the values with their defaults and the benchmarks, and the
//! quantities derived from them.

use crate::ancf::RodProperties;
use crate::integrator::{Method, Tolerances};
use crate::joint::{FilmModel, JointField, JointModel, JointParameters, JointRole, OilParameters};
use crate::reduction::{Boundary, Quadrature};

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

/// How the rod starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InitialState {
    /// Quasi-statically equilibrated: deformed by the inertial loads of the initial motion
    /// ([`crate::mechanism::SliderCrank::equilibrate`]).
    Equilibrated,
    /// Straight and unstressed (docs/model.md §7, the reference start).
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
    /// How the Craig–Bampton rod integrates its internal forces.
    pub quadrature: Quadrature,
    /// How the rod starts.
    pub initial_state: InitialState,
    /// Rod material and section.
    pub rod: RodProperties,
    /// Crank length r_c (pivot to pin) \[m\].
    pub crank_length: f64,
    /// Crank mass \[kg\].
    pub crank_mass: f64,
    /// The crank's centre of mass: its distance from the pivot along the crank (towards the pin)
    /// as a fraction of `crank_length`; 0.5 for a uniform crank, negative for a counterweight
    /// beyond the pivot.
    pub crank_centre_of_mass_ratio: f64,
    /// Crank moment of inertia about its centre of mass \[kg m²\].
    pub crank_inertia: f64,
    /// Initial crank angle \[rad\].
    pub crank_initial_angle: f64,
    /// Initial crank speed \[rad/s\], if set; otherwise the crank starts at the prescribed
    /// speed's value ([`Parameters::start_speed`]).
    pub crank_initial_speed: Option<f64>,
    /// Slider mass \[kg\].
    pub slider_mass: f64,
    /// The guide line's distance from the crank pivot along +y (cylinder or piston-pin offset)
    /// \[m\].
    pub slider_offset: f64,
    /// A CSV table of the load on the slider over the crank angle ([`crate::load_table`]): its
    /// path, empty for none.
    pub slider_force_table: String,
    /// The table's period \[deg\]: 360, or 720 for a four-stroke cycle.
    pub slider_force_table_period: usize,
    /// Where a relative `slider_force_table` is looked up after the working directory: the FMU's
    /// resources (not an FMU variable).
    pub resource_directory: Option<std::path::PathBuf>,
    /// The rod–slider joint (the FMU's `joint.*`).
    pub joint: JointParameters,
    /// The crank pin (`crankPin.*`): the crank's pin in the rod's eye.
    pub crank_pin: JointParameters,
    /// The main bearing (`mainBearing.*`): the crank's pivot in the ground.
    pub main_bearing: JointParameters,
    /// The oil of the lubricated joints' heat balances (`oil.`).
    pub oil: OilParameters,
    /// Drive mode.
    pub drive_mode: DriveMode,
    /// Magnitude of the gravitational acceleration \[m/s²\] (along −y by default, see
    /// `gravity_angle`).
    pub gravity: f64,
    /// Direction of gravity: the angle from −y, counter-clockwise positive \[rad\]
    /// ([`Parameters::gravity_vector`]).
    pub gravity_angle: f64,
    /// Time-integration method.
    pub method: Method,
    /// Spectral radius at infinity ρ∞ ∈ [0, 1] of the generalized-α method (1: no numerical
    /// dissipation, 0: unresolved frequencies annihilated in one step).
    pub spectral_radius: f64,
    /// Relative tolerance of the error-controlled integrator.
    pub relative_tolerance: f64,
    /// Weight of the dry journal's normal velocity in the implicit methods' error control: its
    /// local error is held to `relative_tolerance / impact_error_weight` (in units of the speed
    /// scale) on its own; 0: only the RMS over all states
    /// ([`crate::mechanism::SliderCrank::error_scales`]).
    pub impact_error_weight: f64,
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

/// Default weight of the dry journal's normal velocity in the error control
/// (`solver.impactErrorWeight`): its local error is held to a quarter of the tolerance of the
/// velocities. Measured over the first 60° of benchmarks A and B (`cargo run --release --example
/// impacts [rtol]`): at 4 every impact's peak force is within 1.6 % of a converged run at the
/// default tolerance, for the rigid rod, 4 and 8 modes and the full rod, and within 2.3 % at each
/// of eight tolerances from 3e-3 to 1.25e-2; at 0 (the RMS over all states only), up to 67 % at the
/// default. The impact sequence is chaotic (an impact's error grows in the next ones), so the
/// figures move by about a percent with any change to the step sequence.
pub const DEFAULT_IMPACT_ERROR_WEIGHT: f64 = 4.0;

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
            quadrature: Quadrature::Full,
            initial_state: InitialState::Equilibrated,
            rod: RodProperties::benchmark_b(),
            crank_length: 0.05,
            crank_mass: 0.30,
            crank_inertia: 1e-4,
            crank_initial_angle: 0.0,
            crank_centre_of_mass_ratio: 0.5,
            crank_initial_speed: None,
            slider_mass: 0.14,
            slider_offset: 0.0,
            slider_force_table: String::new(),
            slider_force_table_period: 360,
            resource_directory: None,
            joint: JointParameters::benchmark(),
            crank_pin: JointParameters::ideal(),
            main_bearing: JointParameters::ideal(),
            oil: OilParameters::default(),
            drive_mode: DriveMode::Speed,
            gravity: 0.0,
            gravity_angle: 0.0,
            method: Method::Esdirk,
            spectral_radius: DEFAULT_SPECTRAL_RADIUS,
            relative_tolerance: 1e-2,
            impact_error_weight: DEFAULT_IMPACT_ERROR_WEIGHT,
            max_step_size: 1e-4,
            max_steps_per_interval: DEFAULT_MAX_STEPS_PER_INTERVAL,
        }
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

    /// Benchmark C (docs/model.md §5(b)): as B with the lubricated joint and the benchmarks'
    /// short film.
    pub fn benchmark_c() -> Self {
        let b = Self::benchmark_b();
        Self {
            joint: JointParameters {
                model: JointModel::Lubricated,
                film_model: FilmModel::Short,
                ..b.joint
            },
            ..b
        }
    }

    /// Benchmark D (the lubricated → dry hand-over): the defaults (4-mode rod) with the
    /// lubricated joint, a 40× thinner lubricant (0.01 Pa s) and a 0.5 kg slider, so that the
    /// journal crosses the switch eccentricity ratio and reaches metal contact many times per
    /// revolution.
    pub fn benchmark_d() -> Self {
        Self {
            joint: JointParameters {
                model: JointModel::Lubricated,
                film_model: FilmModel::Short,
                viscosity: 0.01,
                ..JointParameters::benchmark()
            },
            slider_mass: 0.5,
            ..Self::default()
        }
    }

    /// The gravitational acceleration vector g = `gravity` (sin α, −cos α), α = `gravity_angle`:
    /// along −y at α = 0, along −x at α = −π/2 (a vertical guide with the slider above the crank
    /// pivot) \[m/s²\].
    pub fn gravity_vector(&self) -> nalgebra::Vector2<f64> {
        let (sin, cos) = crate::math::sin_cos(self.gravity_angle);
        self.gravity * nalgebra::Vector2::new(sin, -cos)
    }

    /// The crank's speed at the start when the prescribed speed starts at `drive_speed`:
    /// `crank_initial_speed` if it was set, else the prescribed speed's value, in either drive
    /// mode (setting only `drive.speed` starts the mechanism in its motion, without an impulsive
    /// jump at the speed drive's first step) \[rad/s\].
    pub fn start_speed(&self, drive_speed: f64) -> f64 {
        self.crank_initial_speed.unwrap_or(drive_speed)
    }

    /// The load table of `slider_force_table`, read from its file, if one is given.
    pub fn load_table(&self) -> Result<Option<crate::load_table::LoadTable>, crate::ModelError> {
        if self.slider_force_table.is_empty() {
            return Ok(None);
        }
        crate::load_table::LoadTable::read(
            &self.slider_force_table,
            self.slider_force_table_period as f64,
            self.resource_directory.as_deref(),
        )
        .map(Some)
    }

    /// The load cycle's crank-angle period \[rad\]: `slider_force_table_period` with a load
    /// table, a revolution without one.
    pub fn load_cycle(&self) -> f64 {
        let degrees = if self.slider_force_table.is_empty() {
            360.0
        } else {
            self.slider_force_table_period as f64
        };
        degrees.to_radians()
    }

    /// The crank's centre of mass: its distance a from the pivot along the crank \[m\].
    pub fn crank_centre_of_mass(&self) -> f64 {
        self.crank_centre_of_mass_ratio * self.crank_length
    }

    /// The three revolute joints with their parameters, from the ground to the slider.
    pub fn joints(&self) -> [(JointRole, &JointParameters); 3] {
        [
            (JointRole::MainBearing, &self.main_bearing),
            (JointRole::CrankPin, &self.crank_pin),
            (JointRole::RodSlider, &self.joint),
        ]
    }

    /// The parameters of one joint.
    pub fn joint(&self, role: JointRole) -> &JointParameters {
        match role {
            JointRole::MainBearing => &self.main_bearing,
            JointRole::CrankPin => &self.crank_pin,
            JointRole::RodSlider => &self.joint,
        }
    }

    /// The same parameters with every joint ideal.
    pub fn with_ideal_joints(&self) -> Self {
        let mut p = self.clone();
        for role in JointRole::ALL {
            p.joint_mut(role).model = JointModel::Ideal;
        }
        p
    }

    /// The parameters of one joint, to change.
    pub fn joint_mut(&mut self, role: JointRole) -> &mut JointParameters {
        match role {
            JointRole::MainBearing => &mut self.main_bearing,
            JointRole::CrankPin => &mut self.crank_pin,
            JointRole::RodSlider => &mut self.joint,
        }
    }

    /// Crank moment of inertia about the pivot, I_c + m_c a² \[kg m²\] (a: the centre of mass's
    /// distance from the pivot).
    pub fn crank_inertia_about_pivot(&self) -> f64 {
        self.crank_inertia + self.crank_mass * self.crank_centre_of_mass().powi(2)
    }

    /// Loosest relative tolerance a model with a dry (worn) main bearing is integrated at. The
    /// crank, free in the bearing, follows its first impact in a regular motion for about ten
    /// load peaks before the motion turns chaotic, and the integration error of that regular part
    /// decides the later impacts. Against converged runs (rtol 1e-7), ensembles of 132–176 runs
    /// started 1e-5 rad apart (benchmark B, 4-mode rod) have their later peaks' upper decile
    /// 2.1–2.4 % low at rtol 1e-2 and 3e-3 (the second of those peaks 1.3 % low in every run), and
    /// within 0.6 % at 2e-3, 1e-3 and tighter (docs/guide/validation.md, "The impacts after the
    /// first, as an ensemble"); 1e-3 keeps a margin from the step between 3e-3 and 2e-3, at 1.5×
    /// the evaluations of rtol 1e-2.
    pub const DRY_MAIN_BEARING_MAX_TOLERANCE: f64 = 1e-3;

    /// The relative tolerance the model is integrated at: `relative_tolerance`, at most
    /// [`Self::DRY_MAIN_BEARING_MAX_TOLERANCE`] with a dry main bearing.
    pub fn integration_tolerance(&self) -> f64 {
        if self.main_bearing.model == JointModel::Dry {
            self.relative_tolerance
                .min(Self::DRY_MAIN_BEARING_MAX_TOLERANCE)
        } else {
            self.relative_tolerance
        }
    }

    /// Integrator tolerances: the integration tolerance ([`Self::integration_tolerance`]) for both
    /// the relative and the absolute part (the absolute one in units of each state's scale,
    /// [`crate::mechanism::SliderCrank::error_scales`]), the maximum step, and a 1e-14 s floor.
    pub fn tolerances(&self) -> Tolerances {
        Tolerances::from_relative(self.integration_tolerance(), self.max_step_size)
    }

    /// Largest bearing length-to-diameter ratio L/D for which the short-bearing (Ocvirk) film is
    /// a fair approximation.
    pub const SHORT_BEARING_MAX_RATIO: f64 = 0.5;

    /// Valid parameters that take the model outside the range of one of its laws: one message per
    /// cause, for the FMU to log as a warning when it builds the model.
    pub fn warnings(&self) -> Vec<String> {
        let mut warnings = Vec::new();
        for (role, joint) in self.joints() {
            let ratio = joint.length_ratio();
            if joint.model == JointModel::Lubricated
                && joint.film_model == FilmModel::Short
                && ratio > Self::SHORT_BEARING_MAX_RATIO
            {
                warnings.push(format!(
                    "{} / (2 {}) = {} is outside the short-bearing range L/D <= {}: with {} = \
                     short the film force is the infinitely-short-bearing model's, which \
                     overestimates a longer bearing's load (set {} = finite for the Reynolds \
                     solution over the bearing's length)",
                    role.parameter(JointField::BearingLength),
                    role.parameter(JointField::JournalRadius),
                    crate::error::Num(ratio),
                    crate::error::Num(Self::SHORT_BEARING_MAX_RATIO),
                    role.parameter(JointField::FilmModel),
                    role.parameter(JointField::FilmModel),
                ));
            }
        }
        warnings
    }
}
