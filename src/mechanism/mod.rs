//! The slider-crank mechanism: crank (angle θ), connecting rod (rigid, ANCF or Craig–Bampton), and
//! slider (abscissa x_s) on a frictionless guide through the crank pivot.
//!
//! Equations of motion in index-1 form with Baumgarte stabilisation (Sun et al. 2015 eq. 1):
//! ```text
//! M q̈ = Q(q, q̇, t) − Φ_qᵀ λ,     Φ_q q̈ = γ − 2α Φ̇ − β² Φ,     q = [θ, p, x_s]
//! M = diag(I_O, M_rod, m_s)  constant      (I_O: crank inertia about the pivot)
//! ```
//! Φ_q touches only s = [θ, r_A, r_B, x_s], so with G = M⁻¹E_s (constant, E_s selects s) and
//! W = E_sᵀ M⁻¹ E_s (6 × 6, constant): λ = (C W Cᵀ)⁻¹ (C a₀ − rhs), q̈ = a₀ − G Cᵀ λ, a₀ = M⁻¹Q. One
//! solve with the rod's stored Cholesky factor and a ≤ 6 × 6 Cholesky per evaluation, no allocation.
//!
//! State vector y = [q, q̇, θ_d, W_drive, W_joint, W_external, D_material]: the drive angle (speed
//! drive), the work of the drive, of the joint forces and of the external slider force, and the
//! energy dissipated by the rod's material damping, integrated with the motion (with the same
//! error control) so that the energy balance converges with the integrator tolerance. D_material
//! is present only for a rod with material damping: an identically zero component would change
//! the RMS error norm, and with it every undamped result.
//!
//! # References
//! - Sun et al. (2015), Mech. Mach. Theory 85, eqs. (1)–(3).
//! - P. Flores et al. (2008), Kinematics and Dynamics of Multibody Systems with Imperfect Joints.
//! - docs/model.md §0, §3–§6, §10.

pub mod constraints;
pub mod rod_body;

use faer::MatRef;
use nalgebra::{SMatrix, Vector2};

use self::constraints::{Active, ConstraintState, Constraints, Vector6};
use self::rod_body::RodBody;
use crate::error::ModelError;
use crate::integrator::{ErrorScales, MechanicalSystem, OdeSystem};
use crate::joint::{Joint, JointForce, JointKinematics, MIN_IMPACT_VELOCITY};
use crate::linalg::lu::Lu;
use crate::linalg::small;
use crate::math;
use crate::params::{DriveMode, JointModel, Parameters, RodFormulation};

/// Largest penetration accepted at the first step of a contact event \[m\]: 1e-3 of the Hertz
/// maximum penetration of a 0.1 kg, 1 m/s impact (≈ 20 µm, docs/model.md §6), so that the impact
/// velocity is located accurately and the integrator never starts a contact deep inside.
pub const CONTACT_ONSET_PENETRATION: f64 = 2e-8;

/// Inputs that the caller may change between steps.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Inputs {
    /// Prescribed crank speed \[rad/s\] (speed drive).
    pub drive_speed: f64,
    /// Crank torque \[N m\] (torque drive).
    pub drive_torque: f64,
    /// External force on the slider along the guide \[N\].
    pub slider_force: f64,
}

/// One of the [`Inputs`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Input {
    /// [`Inputs::drive_speed`].
    DriveSpeed,
    /// [`Inputs::drive_torque`].
    DriveTorque,
    /// [`Inputs::slider_force`].
    SliderForce,
}

impl Inputs {
    /// The value of one input.
    pub fn get(&self, input: Input) -> f64 {
        match input {
            Input::DriveSpeed => self.drive_speed,
            Input::DriveTorque => self.drive_torque,
            Input::SliderForce => self.slider_force,
        }
    }

    /// The value of one input, to change.
    pub fn get_mut(&mut self, input: Input) -> &mut f64 {
        match input {
            Input::DriveSpeed => &mut self.drive_speed,
            Input::DriveTorque => &mut self.drive_torque,
            Input::SliderForce => &mut self.slider_force,
        }
    }

    fn combine(a: &Self, b: &Self, c: &Self, f: impl Fn(f64, f64, f64) -> f64) -> Self {
        Self {
            drive_speed: f(a.drive_speed, b.drive_speed, c.drive_speed),
            drive_torque: f(a.drive_torque, b.drive_torque, c.drive_torque),
            slider_force: f(a.slider_force, b.slider_force, c.slider_force),
        }
    }
}

/// The inputs as functions of time over a communication interval: their values and first and
/// second time derivatives at `start`,
/// ```text
/// u(t) = u + u̇ (t − t₀) + ü (t − t₀)²/2
/// ```
/// (the polynomial input of FMI 2.0 co-simulation; held inputs have zero derivatives).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct InputSignal {
    /// t₀ \[s\].
    pub start: f64,
    /// u(t₀).
    pub value: Inputs,
    /// u̇(t₀) and ü(t₀).
    pub derivatives: [Inputs; 2],
}

impl InputSignal {
    /// Inputs held at `value`.
    pub fn held(value: Inputs) -> Self {
        Self {
            value,
            ..Self::default()
        }
    }

    /// Values u(t) and rates u̇(t).
    pub fn at(&self, t: f64) -> (Inputs, Inputs) {
        let dt = t - self.start;
        let [first, second] = &self.derivatives;
        let value = Inputs::combine(&self.value, first, second, |u, d1, d2| {
            u + dt * (d1 + 0.5 * dt * d2)
        });
        let rate = Inputs::combine(first, second, second, |d1, d2, _| d1 + dt * d2);
        (value, rate)
    }

    /// Whether the inputs that act (`acts`) are the same functions of time from `t` on in both.
    pub fn same_from(&self, other: &Self, t: f64, acts: impl Fn(Input) -> bool) -> bool {
        let (a, a_rate) = self.at(t);
        let (b, b_rate) = other.at(t);
        [Input::DriveSpeed, Input::DriveTorque, Input::SliderForce]
            .into_iter()
            .filter(|&i| acts(i))
            .all(|i| {
                a.get(i) == b.get(i)
                    && a_rate.get(i) == b_rate.get(i)
                    && self.derivatives[1].get(i) == other.derivatives[1].get(i)
            })
    }
}

/// Discrete contact state, updated at accepted steps only.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactState {
    /// Whether the journal touched the bearing at the end of the last accepted step.
    pub in_contact: bool,
    /// Normal velocity δ̇⁽⁻⁾ at the onset of the current contact event \[m/s\].
    pub impact_velocity: f64,
}

/// Quantities computed by the last right-hand-side evaluation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Evaluation {
    /// Joint force on the journal (contact/film, or the ideal joint's reaction) \[N\].
    pub joint_force: Vector2<f64>,
    /// Friction moment on the journal \[N m\].
    pub joint_moment: f64,
    /// Elastic energy stored in the contact \[J\].
    pub contact_potential: f64,
    /// Torque the drive applies to the crank \[N m\].
    pub crank_torque: f64,
    /// Slider acceleration ẍ_s \[m/s²\].
    pub slider_acceleration: f64,
    /// Constraint drift ‖Φ‖.
    pub drift: f64,
}

/// Energies of a state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Energies {
    /// Kinetic energy ½ q̇ᵀ M q̇ \[J\].
    pub kinetic: f64,
    /// Rod strain energy \[J\].
    pub strain: f64,
    /// Elastic energy stored in the contact \[J\].
    pub contact: f64,
    /// Gravitational potential energy (zero at y = 0) \[J\].
    pub gravity: f64,
    /// Work done by the drive \[J\].
    pub drive_work: f64,
    /// Work done by the joint forces (contact, friction, film) \[J\].
    pub joint_work: f64,
    /// Work done by the external slider force \[J\].
    pub external_work: f64,
    /// Energy dissipated by the rod's material (strain-rate) damping \[J\].
    pub material_damping: f64,
}

impl Energies {
    /// Energy lost in the joint: −W_joint − stored contact energy (≥ 0 up to integration error).
    pub fn dissipated(&self) -> f64 {
        -self.joint_work - self.contact
    }

    /// Balance T + U + V_g + D_material − W_drive − W_external − W_joint, constant in exact
    /// arithmetic (the joint work includes the work of the elastic contact force, so V_c does not
    /// appear).
    pub fn balance(&self) -> f64 {
        self.kinetic + self.strain + self.gravity + self.material_damping
            - self.drive_work
            - self.external_work
            - self.joint_work
    }
}

/// The length ℓ at which the joint's force law changes (the error scales' unit of length):
/// 1 % of the crank length at most, and
/// - dry joint: the clearance c (contact starts when the journal crosses it);
/// - lubricated joint: the film thickness at the switch, c (1 − ε_b) (the film force grows as
///   (1 − ε)^−5/2 towards it);
/// - ideal joint on a flexible rod: the rod's axial deformation under the inertial load,
///   F L / EA with F = (m_rod + m_slider) ω₀² r_c (the joint force is the rod's axial force),
///   per element (L/n) for the full rod, whose coordinates resolve each element's stretch.
fn position_scale(p: &Parameters) -> f64 {
    let base = 0.01 * p.crank_length;
    match (p.joint_model, p.rod_formulation) {
        (JointModel::Dry, _) => p.clearance.min(base),
        (JointModel::Lubricated, _) => p.clearance.min(base) * (1.0 - p.switch_eccentricity),
        (JointModel::Ideal, RodFormulation::Rigid) => base,
        (JointModel::Ideal, rod) => {
            let speed = p.crank_initial_speed.abs().max(1.0);
            let load = (p.rod.mass() + p.slider_mass) * speed * speed * p.crank_length;
            // The full rod's coordinates resolve each element's stretch, the reduced rod's the
            // stretch between the pins.
            let length = match rod {
                RodFormulation::Ancf => p.rod.length / p.n_elements as f64,
                _ => p.rod.length,
            };
            base.min(load * length / (p.rod.youngs_modulus * p.rod.area))
        }
    }
}

/// The slider-crank mechanism as a first-order system.
#[derive(Clone, Debug)]
pub struct SliderCrank {
    rod: RodBody,
    joint: Joint,
    drive: DriveMode,
    active: Active,
    crank_length: f64,
    crank_mass: f64,
    crank_inertia: f64,
    slider_mass: f64,
    gravity: f64,
    rod_length: f64,
    rod_mass: f64,
    /// Reference crank speed for the error scales (the initial speed, at least 1 rad/s).
    reference_speed: f64,
    /// Length scale ℓ of the error scales \[m\].
    position_scale: f64,
    /// M_rod⁻¹ e_j for j ∈ {A_x, A_y, B_x, B_y}, column-major (n_rod × 4).
    rod_compliance: Vec<f64>,
    /// W = E_sᵀ M⁻¹ E_s.
    w: SMatrix<f64, 6, 6>,
    rod_gravity: Vec<f64>,
    /// Whether the rod has material damping (and the state its dissipated energy).
    material_damping: bool,
    /// The inputs as functions of time.
    signal: InputSignal,
    /// The inputs at the time of the last [`SliderCrank::set_time`].
    inputs: Inputs,
    /// dω_in/dt at that time \[rad/s²\] (speed drive).
    drive_acceleration: f64,
    contact: ContactState,
    force: Vec<f64>,
    evaluation: Evaluation,
}

impl SliderCrank {
    /// Builds the mechanism after validating the parameters.
    pub fn new(p: &Parameters) -> Result<Self, ModelError> {
        p.validate()?;
        let rod = RodBody::from_parameters(p)?;
        let n_rod = rod.n_coordinates();
        let b = rod.end_offset();
        let pins = [0, 1, b, b + 1];
        let mut rod_compliance = vec![0.0; 4 * n_rod];
        for (j, &pin) in pins.iter().enumerate() {
            let column = &mut rod_compliance[j * n_rod..(j + 1) * n_rod];
            column[pin] = 1.0;
            rod.solve_mass(column);
        }
        let crank_inertia = p.crank_inertia_about_pivot();
        let mut w = SMatrix::<f64, 6, 6>::zeros();
        w[(0, 0)] = 1.0 / crank_inertia;
        w[(5, 5)] = 1.0 / p.slider_mass;
        for i in 0..4 {
            for j in 0..4 {
                w[(1 + i, 1 + j)] = rod_compliance[j * n_rod + pins[i]];
            }
        }
        let active = Active {
            ideal_joint: p.joint_model == JointModel::Ideal,
            rigid_rod: rod.rigid_length().is_some(),
            speed_drive: p.drive_mode == DriveMode::Speed,
        };
        Ok(Self {
            rod_gravity: rod.gravity_force(p.gravity),
            material_damping: rod.rigid_length().is_none() && p.rod.stiffness_damping > 0.0,
            joint: Joint::from_parameters(p),
            drive: p.drive_mode,
            active,
            crank_length: p.crank_length,
            crank_mass: p.crank_mass,
            crank_inertia,
            slider_mass: p.slider_mass,
            gravity: p.gravity,
            rod_length: p.rod.length,
            rod_mass: p.rod.mass(),
            reference_speed: p.crank_initial_speed.abs().max(1.0),
            position_scale: position_scale(p),
            rod_compliance,
            w,
            signal: InputSignal::held(Inputs {
                drive_speed: p.crank_initial_speed,
                ..Inputs::default()
            }),
            inputs: Inputs {
                drive_speed: p.crank_initial_speed,
                ..Inputs::default()
            },
            drive_acceleration: 0.0,
            contact: ContactState {
                in_contact: false,
                impact_velocity: MIN_IMPACT_VELOCITY,
            },
            force: vec![0.0; n_rod],
            evaluation: Evaluation::default(),
            rod,
        })
    }

    /// Number of mechanical coordinates n = 1 + n_rod + 1.
    pub fn n_coordinates(&self) -> usize {
        self.rod.n_coordinates() + 2
    }

    /// Length of the state vector: 2n + 4, plus 1 with material damping.
    pub fn n_states(&self) -> usize {
        2 * self.n_coordinates() + 4 + usize::from(self.material_damping)
    }

    /// Error weights of each state component ([`ErrorScales`]): the integrators compare its
    /// local error with `rtol · sᵢ` for coordinates and velocities (absolute only: positions and
    /// velocities have no natural origin) and with `rtol · (sᵢ + |yᵢ|)` for the work integrals.
    ///
    /// Every state is measured by the displacement (or velocity) it causes in the mechanism, in
    /// units of the joint's length scale ℓ (see `position_scale`) and of the speed V = ω₀ ℓ
    /// (ω₀ = |crank.initialSpeed|, at least 1 rad/s):
    /// ```text
    /// θ, θ_d          ℓ / r_c               θ̇            V / r_c
    /// rod coordinate  ℓ / d_j               its rate     V / d_j
    /// x_s             ℓ                     ẋ_s          V
    /// works           ½ m (ω₀ r_c)² ℓ / r_c,   m = I_O/r_c² + m_rod + m_slider
    /// ```
    /// with d_j the largest displacement along the rod per unit of coordinate j (1 for positions,
    /// ≈ (4/27) l_e for ANCF slopes, the mode shape's largest value for modal amplitudes). A
    /// coordinate whose unit moves the rod little gets a proportionally larger scale, so the
    /// error control asks the same physical accuracy of every coordinate.
    pub fn error_scales(&self) -> ErrorScales {
        let n = self.n_coordinates();
        let length = self.position_scale;
        let speed = self.reference_speed * length;
        let pin_speed = self.reference_speed * self.crank_length;
        let mass =
            self.crank_inertia / self.crank_length.powi(2) + self.rod_mass + self.slider_mass;
        let mut scales = vec![0.0; self.n_states()];
        scales[0] = length / self.crank_length;
        scales[n] = speed / self.crank_length;
        for (j, d) in self.rod.displacement_scales().into_iter().enumerate() {
            scales[1 + j] = length / d;
            scales[n + 1 + j] = speed / d;
        }
        scales[n - 1] = length;
        scales[2 * n - 1] = speed;
        scales[2 * n] = scales[0];
        for s in &mut scales[2 * n + 1..] {
            *s = 0.5 * mass * pin_speed * pin_speed * length / self.crank_length;
        }
        let relative = (0..scales.len())
            .map(|i| if i > 2 * n { 1.0 } else { 0.0 })
            .collect();
        ErrorScales {
            absolute: scales,
            relative,
        }
    }

    /// The rod body.
    pub fn rod(&self) -> &RodBody {
        &self.rod
    }

    /// Discrete contact state.
    pub fn contact_state(&self) -> ContactState {
        self.contact
    }

    /// Restores the discrete contact state (snapshots).
    pub fn set_contact_state(&mut self, contact: ContactState) {
        self.contact = contact;
    }

    /// The inputs as functions of time.
    pub fn input_signal(&self) -> &InputSignal {
        &self.signal
    }

    /// Sets the inputs as functions of time; evaluations from now on use them at the current
    /// time of [`SliderCrank::set_time`] (the integrator's stage time for its evaluations).
    pub fn set_input_signal(&mut self, signal: InputSignal, t: f64) {
        self.signal = signal;
        self.set_time(t);
    }

    /// The inputs at `t`: evaluations outside the integrator (outputs, peaks) use them.
    pub fn set_time(&mut self, t: f64) {
        let (inputs, rates) = self.signal.at(t);
        self.inputs = inputs;
        self.drive_acceleration = rates.drive_speed;
    }

    /// The inputs at the time of the last [`SliderCrank::set_time`].
    pub fn inputs(&self) -> Inputs {
        self.inputs
    }

    /// Quantities of the last right-hand-side evaluation.
    pub fn evaluation(&self) -> &Evaluation {
        &self.evaluation
    }

    /// Initial state: crank at `angle` turning at `speed`, rod straight and unstressed, journal
    /// centred, every velocity that of the ideal mechanism (docs/model.md §10).
    pub fn initial_state(&self, angle: f64, speed: f64) -> Vec<f64> {
        let (r_c, l) = (self.crank_length, self.rod_length);
        let (sin, cos) = math::sin_cos(angle);
        let a = r_c * Vector2::new(cos, sin);
        let sin_beta = -r_c * sin / l;
        let cos_beta = (1.0 - sin_beta * sin_beta).sqrt();
        let b = a + l * Vector2::new(cos_beta, sin_beta);
        let v_a = r_c * speed * Vector2::new(-sin, cos);
        let beta_dot = -r_c * speed * cos / (l * cos_beta);
        let v_b = v_a + l * beta_dot * Vector2::new(-sin_beta, cos_beta);
        let (p, p_dot) = (self.rod.straight(a, b), self.rod.straight(v_a, v_b));
        let n = self.n_coordinates();
        let mut y = vec![0.0; self.n_states()];
        y[0] = angle;
        y[1..n - 1].copy_from_slice(&p);
        y[n - 1] = b.x;
        y[n] = speed;
        y[n + 1..2 * n - 1].copy_from_slice(&p_dot);
        y[2 * n - 1] = v_b.x;
        y[2 * n] = angle;
        y
    }

    /// Quasi-static start: changes the rod's deformation in a state from
    /// [`SliderCrank::initial_state`] so that the deformation has no acceleration.
    ///
    /// Unknowns: the rod's deviation d = p_o − Π_o(r_A, r_B) of its coordinates other than the pin
    /// positions from the straight rod through its pins (Π, [`RodBody::straight`], linear), and
    /// a shift Δ of the slider end along the guide (r_B and x_s together: the journal stays
    /// centred, an ideal joint stays closed). Equations, with every velocity unchanged:
    /// ```text
    /// d̈ = p̈_o − Π_o(r̈_A, r̈_B) = 0                 (the rod accelerates as a straight rod)
    /// σ̈ = (r̈_B − r̈_A)·t + |ṙ_B − ṙ_A|²/|r_B − r_A| − ((ṙ_B − ṙ_A)·t)²/|r_B − r_A| = 0
    /// ```
    /// (σ = |r_B − r_A|, t its direction: no stretching acceleration). Solved by Newton with a
    /// finite-difference Jacobian. The rod then starts loaded by the inertial forces of the motion
    /// (and gravity) instead of unstressed, and does not ring at its axial and bending frequencies
    /// from t = 0. The rigid rod has no deformation: the state is left as it is.
    pub fn equilibrate(&mut self, y: &mut [f64]) -> Result<(), ModelError> {
        if self.rod.rigid_length().is_some() {
            return Ok(());
        }
        let n = self.n_coordinates();
        let e = self.rod.end_offset();
        let others: Vec<usize> = (0..n - 2)
            .filter(|&i| ![0, 1, e, e + 1].contains(&i))
            .collect();
        let m = others.len() + 1;
        let base = y.to_vec();
        let scales = self.error_scales().absolute;
        let mut u = vec![0.0; m];
        let mut residual = vec![0.0; m];
        let mut shifted = vec![0.0; m];
        let mut jacobian = Lu::new(m);
        let mut dy = vec![0.0; y.len()];
        let mut first_norm = f64::NAN;
        for _ in 0..30 {
            self.quasi_static_residual(&base, &others, &u, y, &mut dy, &mut residual)?;
            let norm = residual.iter().map(|r| r * r).sum::<f64>().sqrt();
            if first_norm.is_nan() {
                first_norm = norm;
            }
            // 1e-7 of the initial residual: below the round-off of the finite-difference Jacobian
            // of a 64-element rod, far below any acceleration the start could excite.
            if norm <= 1e-7 * first_norm || norm == 0.0 {
                return Ok(());
            }
            for j in 0..m {
                let scale = if j < others.len() {
                    scales[1 + others[j]]
                } else {
                    scales[n - 1]
                };
                // At least 1e-4 of the rod's own scale: a tiny clearance (joint length scale
                // below 1e-4 of the rod length) must not shrink the differences to round-off.
                let floor = (1e-4 * self.rod_length / self.position_scale).max(1.0);
                let delta = 1e-7 * (u[j].abs() + scale * floor);
                let mut perturbed = u.clone();
                perturbed[j] += delta;
                self.quasi_static_residual(&base, &others, &perturbed, y, &mut dy, &mut shifted)?;
                for i in 0..m {
                    jacobian.matrix_mut()[j * m + i] = (shifted[i] - residual[i]) / delta;
                }
            }
            jacobian.factorize()?;
            jacobian.solve(&mut residual);
            let mut largest_update = 0.0f64;
            for (j, (ui, ri)) in u.iter_mut().zip(&residual).enumerate() {
                *ui -= ri;
                let scale = if j < others.len() {
                    scales[1 + others[j]]
                } else {
                    scales[n - 1]
                };
                largest_update = largest_update.max(ri.abs() / scale);
            }
            // An update of 1e-9 of the error-control unit: the residual is at its round-off floor
            // (a start from rest, whose straight rod is already in equilibrium).
            if largest_update <= 1e-9 {
                self.quasi_static_residual(&base, &others, &u, y, &mut dy, &mut residual)?;
                return Ok(());
            }
        }
        self.quasi_static_residual(&base, &others, &u, y, &mut dy, &mut residual)?;
        Err(ModelError::Numerical(format!(
            "equilibrated initial state: Newton did not converge (residual {:.3e} of {:.3e})",
            residual.iter().map(|r| r * r).sum::<f64>().sqrt(),
            first_norm
        )))
    }

    /// Writes the state of the quasi-static unknowns `u` = [d, Δ] (on the straight state `base`)
    /// to `y` and the residual [d̈, σ̈] to `out`.
    fn quasi_static_residual(
        &mut self,
        base: &[f64],
        others: &[usize],
        u: &[f64],
        y: &mut [f64],
        dy: &mut [f64],
        out: &mut [f64],
    ) -> Result<(), ModelError> {
        let n = self.n_coordinates();
        let e = 1 + self.rod.end_offset();
        let shift = u[others.len()];
        y.copy_from_slice(base);
        y[e] += shift;
        y[n - 1] += shift;
        let a = Vector2::new(y[1], y[2]);
        let b = Vector2::new(y[e], y[e + 1]);
        let straight = self.rod.straight(a, b);
        for (k, &i) in others.iter().enumerate() {
            y[1 + i] = straight[i] + u[k];
        }
        self.evaluate(y, dy)?;
        let (acc_a, acc_b) = (
            Vector2::new(dy[n + 1], dy[n + 2]),
            Vector2::new(dy[n + e], dy[n + e + 1]),
        );
        let straight_acc = self.rod.straight(acc_a, acc_b);
        for (k, &i) in others.iter().enumerate() {
            out[k] = dy[n + 1 + i] - straight_acc[i];
        }
        let chord = b - a;
        let t = chord / chord.norm();
        let rate = Vector2::new(y[n + e], y[n + e + 1]) - Vector2::new(y[n + 1], y[n + 2]);
        out[others.len()] =
            (acc_b - acc_a).dot(&t) + (rate.norm_squared() - rate.dot(&t).powi(2)) / chord.norm();
        Ok(())
    }

    fn constraint_state(&self, y: &[f64]) -> ConstraintState {
        let n = self.n_coordinates();
        let b = 1 + self.rod.end_offset();
        ConstraintState {
            theta: y[0],
            theta_dot: y[n],
            theta_drive: y[2 * n],
            drive_speed: self.inputs.drive_speed,
            drive_acceleration: self.drive_acceleration,
            r_a: Vector2::new(y[1], y[2]),
            v_a: Vector2::new(y[n + 1], y[n + 2]),
            r_b: Vector2::new(y[b], y[b + 1]),
            v_b: Vector2::new(y[n + b], y[n + b + 1]),
            x_s: y[n - 1],
            v_s: y[2 * n - 1],
        }
    }

    fn constraints(&self, y: &[f64]) -> Constraints {
        Constraints::evaluate(
            self.active,
            self.crank_length,
            self.rod_length,
            &self.constraint_state(y),
        )
    }

    /// Deformation (strain) energy of the rod in state `y` \[J\] (docs/model.md §1.4; 0 for the
    /// rigid rod).
    pub fn strain_energy(&mut self, y: &[f64]) -> f64 {
        let n = self.n_coordinates();
        self.rod.strain_energy(&y[1..n - 1])
    }

    /// Journal–bearing kinematics of a state.
    pub fn joint_kinematics(&self, y: &[f64]) -> JointKinematics {
        let n = self.n_coordinates();
        let b = 1 + self.rod.end_offset();
        let p = &y[1..n - 1];
        let p_dot = &y[n + 1..2 * n - 1];
        JointKinematics {
            e: Vector2::new(y[b] - y[n - 1], y[b + 1]),
            e_dot: Vector2::new(y[n + b] - y[2 * n - 1], y[n + b + 1]),
            omega_journal: self.rod.end_angular_velocity(p, p_dot),
        }
    }

    /// |joint force| and |slider acceleration| of a state from the joint kinematics alone, for a
    /// clearance joint (`None` for the ideal joint, whose force is a constraint reaction).
    ///
    /// With a clearance joint no constraint acts on the slider, so its equation of motion is
    /// m_s ẍ_s = F_s − F_x (the slider row of [`SliderCrank::evaluate`]): both values follow from
    /// the joint law without the rod's mass matrix or the constraint solve, at a small fraction of
    /// a right-hand side's cost. They equal those of [`SliderCrank::evaluate`].
    pub fn clearance_joint_load(&self, y: &[f64]) -> Option<(f64, f64)> {
        if self.active.ideal_joint {
            return None;
        }
        let kin = self.joint_kinematics(y);
        let force = self.joint.force(&kin, self.impact_velocity(&kin)).force;
        let acceleration = (self.inputs.slider_force - force.x) / self.slider_mass;
        Some((force.norm(), acceleration.abs()))
    }

    /// Penetration δ = |e| − c of a state (−∞ for the ideal joint).
    pub fn penetration(&self, y: &[f64]) -> f64 {
        match self.joint.dry_contact() {
            Some(dry) => dry.penetration(&self.joint_kinematics(y)),
            None => f64::NEG_INFINITY,
        }
    }

    /// Solves (C W Cᵀ) x = r on the k active rows (rows of C beyond k are zero; x is zero there).
    fn solve_schur(&self, c: &Constraints, r: Vector6) -> Result<Vector6, ModelError> {
        let k = c.rows;
        let mut cw = [[0.0; 6]; 6];
        for (i, row) in cw.iter_mut().enumerate().take(k) {
            for (j, v) in row.iter_mut().enumerate() {
                *v = (0..6).map(|m| c.jacobian[(i, m)] * self.w[(m, j)]).sum();
            }
        }
        let mut s = [[0.0; 6]; 6];
        for (i, row) in s.iter_mut().enumerate().take(k) {
            for (j, v) in row.iter_mut().enumerate().take(i + 1) {
                *v = (0..6).map(|m| cw[i][m] * c.jacobian[(j, m)]).sum();
            }
        }
        let mut x = [0.0; 6];
        x[..k].copy_from_slice(&r.as_slice()[..k]);
        small::cholesky_solve(
            &s,
            k,
            &mut x,
            "singular constraint Jacobian (locked configuration)",
        )?;
        Ok(Vector6::from(x))
    }

    /// Adds −G μ to the accelerations (or velocities) `out` for μ on s: M⁻¹ Cᵀλ applied.
    fn subtract_compliance(&self, mu: &Vector6, out: &mut [f64]) {
        let n = out.len();
        let n_rod = n - 2;
        out[0] -= mu[0] / self.crank_inertia;
        out[n - 1] -= mu[5] / self.slider_mass;
        for j in 0..4 {
            let column = &self.rod_compliance[j * n_rod..(j + 1) * n_rod];
            for (o, g) in out[1..n - 1].iter_mut().zip(column) {
                *o -= g * mu[1 + j];
            }
        }
    }

    /// Values of `v` (length n) on s.
    fn on_s(&self, v: &[f64]) -> Vector6 {
        let n = v.len();
        let b = 1 + self.rod.end_offset();
        Vector6::new(v[0], v[1], v[2], v[b], v[b + 1], v[n - 1])
    }

    fn impact_velocity(&self, k: &JointKinematics) -> f64 {
        if self.contact.in_contact {
            self.contact.impact_velocity
        } else {
            k.normal_velocity().max(MIN_IMPACT_VELOCITY)
        }
    }

    /// Right-hand side; fills [`SliderCrank::evaluation`].
    fn derivative(&mut self, y: &[f64], dy: &mut [f64]) -> Result<(), ModelError> {
        let n = self.n_coordinates();
        let n_rod = n - 2;
        let b = self.rod.end_offset();
        let (q, rest) = y.split_at(n);
        let v = &rest[..n];
        let p = &q[1..n - 1];
        let p_dot = &v[1..n - 1];

        let damping_power = self.rod.internal_force(p, p_dot, &mut self.force);
        for (f, g) in self.force.iter_mut().zip(&self.rod_gravity) {
            *f = g - *f;
        }
        let kin = self.joint_kinematics(y);
        let joint = self.joint.force(&kin, self.impact_velocity(&kin));
        self.force[b] += joint.force.x;
        self.force[b + 1] += joint.force.y;
        self.rod.add_end_moment(p, joint.moment, &mut self.force);
        let torque_in = match self.drive {
            DriveMode::Torque => self.inputs.drive_torque,
            DriveMode::Speed => 0.0,
        };
        // No cosine per evaluation without gravity (the common case).
        let gravity_torque = if self.gravity == 0.0 {
            0.0
        } else {
            -self.crank_mass * self.gravity * 0.5 * self.crank_length * math::cos(q[0])
        };

        let (dq, rest) = dy.split_at_mut(n);
        let (acc, extra) = rest.split_at_mut(n);
        dq.copy_from_slice(v);
        acc[0] = (torque_in + gravity_torque) / self.crank_inertia;
        acc[1..n - 1].copy_from_slice(&self.force[..n_rod]);
        self.rod.solve_mass(&mut acc[1..n - 1]);
        acc[n - 1] = (self.inputs.slider_force - joint.force.x) / self.slider_mass;

        let c = self.constraints(y);
        let lambda = self.solve_schur(&c, c.jacobian * self.on_s(acc) - c.acceleration_rhs())?;
        let mu = c.jacobian.transpose() * lambda;
        self.subtract_compliance(&mu, acc);

        let crank_torque = match c.drive_row {
            Some(k) => -lambda[k],
            None => torque_in,
        };
        let (joint_force, joint_power) = match c.ideal_row {
            Some(k) => (-Vector2::new(lambda[k], lambda[k + 1]), 0.0),
            None => (
                joint.force,
                joint.force.dot(&kin.e_dot) + joint.moment * kin.omega_journal,
            ),
        };
        extra[0] = if self.active.speed_drive {
            self.inputs.drive_speed
        } else {
            0.0
        };
        extra[1] = crank_torque * v[0];
        extra[2] = joint_power;
        extra[3] = self.inputs.slider_force * v[n - 1];
        if let Some(d) = extra.get_mut(4) {
            *d = damping_power;
        }
        self.evaluation = Evaluation {
            joint_force,
            joint_moment: joint.moment,
            contact_potential: joint.potential,
            crank_torque,
            slider_acceleration: acc[n - 1],
            drift: c.drift(),
        };
        Ok(())
    }

    /// Evaluates the right-hand side at `y` into `dy`, reporting a singular configuration.
    pub fn evaluate(&mut self, y: &[f64], dy: &mut [f64]) -> Result<&Evaluation, ModelError> {
        self.derivative(y, dy)?;
        Ok(&self.evaluation)
    }

    /// Projects the velocities of `y` onto the velocity constraints Φ_q q̇ = v (v = ω_in on the
    /// drive row, 0 elsewhere) with the least change of kinetic energy (an impulsive adjustment
    /// through the constraints). Returns the kinetic energy change \[J\].
    pub fn project_velocities(&mut self, y: &mut [f64]) -> Result<f64, ModelError> {
        let n = self.n_coordinates();
        let before = self.kinetic_energy(y);
        let c = self.constraints(y);
        let mu = c.jacobian.transpose() * self.solve_schur(&c, c.phi_dot)?;
        self.subtract_compliance(&mu, &mut y[n..2 * n]);
        Ok(self.kinetic_energy(y) - before)
    }

    fn kinetic_energy(&self, y: &[f64]) -> f64 {
        let n = self.n_coordinates();
        let v = &y[n..2 * n];
        let p_dot = &v[1..n - 1];
        let m: MatRef<'_, f64> = self.rod.mass_matrix();
        let rod: f64 = (0..n - 2)
            .map(|i| p_dot[i] * (0..n - 2).map(|j| m[(i, j)] * p_dot[j]).sum::<f64>())
            .sum();
        0.5 * (self.crank_inertia * v[0] * v[0] + rod + self.slider_mass * v[n - 1] * v[n - 1])
    }

    /// Energies of a state (evaluates the joint force for the stored contact energy).
    pub fn energies(&mut self, y: &[f64]) -> Energies {
        let n = self.n_coordinates();
        let kin = self.joint_kinematics(y);
        let contact: JointForce = self.joint.force(&kin, self.impact_velocity(&kin));
        let p = &y[1..n - 1];
        let rod_gravity: f64 = self.rod_gravity.iter().zip(p).map(|(g, x)| g * x).sum();
        Energies {
            kinetic: self.kinetic_energy(y),
            strain: self.rod.strain_energy(p),
            contact: contact.potential,
            gravity: self.crank_mass * self.gravity * 0.5 * self.crank_length * math::sin(y[0])
                - rod_gravity,
            drive_work: y[2 * n + 1],
            joint_work: y[2 * n + 2],
            external_work: y[2 * n + 3],
            material_damping: y.get(2 * n + 4).copied().unwrap_or(0.0),
        }
    }

    /// Mid-span deflection of the rod \[m\].
    pub fn midspan_deflection(&mut self, y: &[f64]) -> f64 {
        let n = self.n_coordinates();
        self.rod.midspan_deflection(&y[1..n - 1])
    }

    /// Normal velocity δ̇ of a state.
    fn normal_velocity(&self, y: &[f64]) -> f64 {
        self.joint_kinematics(y).normal_velocity()
    }
}

impl MechanicalSystem for SliderCrank {
    fn n_coordinates(&self) -> usize {
        SliderCrank::n_coordinates(self)
    }
}

impl OdeSystem for SliderCrank {
    fn rhs(&mut self, t: f64, y: &[f64], dy: &mut [f64]) {
        self.set_time(t);
        if self.derivative(y, dy).is_err() {
            // A locked configuration: make the step fail through the error estimate.
            dy.fill(f64::NAN);
        }
    }

    /// Rejects a step that starts a contact deeper than [`CONTACT_ONSET_PENETRATION`], shrinking
    /// it towards the crossing (linear estimate of the crossing time).
    fn check_step(&mut self, _t0: f64, y0: &[f64], _t1: f64, y1: &[f64]) -> Option<f64> {
        let (d0, d1) = (self.penetration(y0), self.penetration(y1));
        if d0 <= 0.0 && d1 > CONTACT_ONSET_PENETRATION {
            let crossing = -d0 / (d1 - d0);
            Some((crossing + 0.5 * CONTACT_ONSET_PENETRATION / (d1 - d0)).clamp(0.01, 0.9))
        } else {
            None
        }
    }

    /// Latches the impact velocity at the located onset of a contact event (linear interpolation
    /// of δ̇ to the crossing of δ = 0), and clears the contact flag at separation.
    ///
    /// Out of contact and approaching the wall (δ₁ < 0 < δ̇₁), the next step is limited to the
    /// linear estimate of the time at which δ reaches half the onset depth,
    /// (−δ₁ + δ_on/2)/δ̇₁: the step that starts the contact is aimed at the window
    /// 0 < δ ≤ δ_on that [`OdeSystem::check_step`] accepts, instead of overshooting it and being
    /// refused (event anticipation; without it the 4-mode rod of benchmark B refused about 370
    /// steps per two revolutions, 3.3 attempts per onset).
    fn accept_step(&mut self, _t0: f64, y0: &[f64], _t1: f64, y1: &[f64]) -> Option<f64> {
        let (d0, d1) = (self.penetration(y0), self.penetration(y1));
        if d1 > 0.0 && !self.contact.in_contact {
            let s = if d0 < 0.0 { -d0 / (d1 - d0) } else { 0.0 };
            let (v0, v1) = (self.normal_velocity(y0), self.normal_velocity(y1));
            self.contact = ContactState {
                in_contact: true,
                impact_velocity: (v0 + s * (v1 - v0)).max(MIN_IMPACT_VELOCITY),
            };
        } else if d1 <= 0.0 {
            self.contact.in_contact = false;
        }
        if self.contact.in_contact || !(d1 < 0.0 && d1.is_finite()) {
            return None;
        }
        let v1 = self.normal_velocity(y1);
        (v1 > 0.0).then(|| (0.5 * CONTACT_ONSET_PENETRATION - d1) / v1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::{JointModel, RodFormulation};

    /// Contact-onset anticipation: a step that ends 1 µm short of the wall and approaching it
    /// limits the next one to the time at which δ reaches half the onset depth; moving away, in
    /// contact, or with the ideal joint there is no limit.
    #[test]
    fn approaching_the_wall_limits_the_next_step() {
        let p = Parameters::default();
        let mut m = SliderCrank::new(&p).expect("default parameters build");
        let n = m.n_coordinates();
        let mut y = m.initial_state(0.3, 400.0);
        y[n - 1] -= p.clearance - 1e-6;
        let y0 = y.clone();
        let mut approaching = y.clone();
        approaching[2 * n - 1] -= 0.5;
        let (d, v) = (m.penetration(&approaching), m.normal_velocity(&approaching));
        assert!(d < 0.0 && d > -2e-6 && v > 0.4, "δ = {d}, δ̇ = {v}");
        let limit = m.accept_step(0.0, &y0, 1e-6, &approaching);
        assert_eq!(limit, Some((0.5 * CONTACT_ONSET_PENETRATION - d) / v));
        assert!(!m.contact_state().in_contact);
        let mut leaving = y.clone();
        leaving[2 * n - 1] += 0.5;
        assert_eq!(m.accept_step(0.0, &y0, 1e-6, &leaving), None);
        let mut inside = approaching.clone();
        inside[n - 1] -= 2e-6;
        assert_eq!(m.accept_step(0.0, &y0, 1e-6, &inside), None);
        assert!(m.contact_state().in_contact);
        let mut ideal = SliderCrank::new(&Parameters {
            joint_model: JointModel::Ideal,
            ..p
        })
        .expect("ideal joint builds");
        let y = ideal.initial_state(0.3, 400.0);
        assert_eq!(ideal.accept_step(0.0, &y, 1e-6, &y), None);
    }

    /// The joint load from the kinematics alone equals the full right-hand side's, for every
    /// clearance joint and rod, in contact (inside and at the start of an event) and with a
    /// slider force; the ideal joint has none.
    #[test]
    fn clearance_joint_load_equals_the_right_hand_side() {
        for joint_model in [JointModel::Dry, JointModel::Lubricated, JointModel::Ideal] {
            for rod_formulation in [RodFormulation::Rigid, RodFormulation::CraigBampton] {
                let p = Parameters {
                    joint_model,
                    rod_formulation,
                    ..Parameters::default()
                };
                let mut m = SliderCrank::new(&p).expect("default parameters build");
                let inputs = Inputs {
                    slider_force: -150.0,
                    ..m.inputs()
                };
                m.set_input_signal(InputSignal::held(inputs), 0.0);
                let mut y = m.initial_state(0.3, 400.0);
                let n = m.n_coordinates();
                // Journal 20 µm into the wall, moving into it.
                y[n - 1] -= p.clearance + 2e-5;
                y[2 * n - 1] -= 0.5;
                let mut dy = vec![0.0; y.len()];
                for contact in [
                    m.contact_state(),
                    ContactState {
                        in_contact: true,
                        impact_velocity: 0.8,
                    },
                ] {
                    m.set_contact_state(contact);
                    let load = m.clearance_joint_load(&y);
                    let ev = *m.evaluate(&y, &mut dy).expect("regular configuration");
                    match load {
                        None => assert_eq!(joint_model, JointModel::Ideal),
                        Some((force, acceleration)) => {
                            assert!(force > 100.0, "{joint_model:?}: {force} N");
                            assert_eq!(force, ev.joint_force.norm());
                            assert_eq!(acceleration, ev.slider_acceleration.abs());
                        }
                    }
                }
            }
        }
    }
}
