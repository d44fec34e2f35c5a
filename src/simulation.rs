//! [`Simulation`]: the slider-crank with its integrator and clock — parameters in, `advance_to(t)`,
//! outputs out. This is what the FMU, the examples and the benchmarks drive.

use crate::error::ModelError;
use crate::integrator::{DormandPrince, Stats};
use crate::mechanism::{ContactState, Energies, Inputs, SliderCrank};
use crate::params::{DriveMode, Parameters};

/// Resolution of the simulation clock: 2⁻⁴⁰ s ≈ 0.91 ps.
///
/// Target and start times are rounded to this binary grid. Masters represent the same
/// communication point differently (fmpy: n·Δt in floating point; libcosim: integer nanoseconds
/// converted to seconds), which differ in the last bits; with impacts such differences grow without
/// bound. On the grid they coincide, so every master gets bit-identical results. The shift
/// (≤ 0.46 ps) is far below any time scale of the model.
pub const CLOCK_RESOLUTION: f64 = 1.0 / (1u64 << 40) as f64;

/// `t` rounded to the clock grid ([`CLOCK_RESOLUTION`]).
pub fn on_clock_grid(t: f64) -> f64 {
    (t / CLOCK_RESOLUTION).round() * CLOCK_RESOLUTION
}

/// Everything a system engineer plots, at the current time (SI units).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Outputs {
    /// Time \[s\].
    pub time: f64,
    /// Crank angle θ \[rad\].
    pub crank_angle: f64,
    /// Crank speed θ̇ \[rad/s\].
    pub crank_speed: f64,
    /// Torque applied by the drive to the crank, CCW positive \[N m\].
    pub crank_torque: f64,
    /// Slider abscissa x_s \[m\].
    pub slider_position: f64,
    /// Slider velocity \[m/s\].
    pub slider_velocity: f64,
    /// Slider acceleration \[m/s²\].
    pub slider_acceleration: f64,
    /// Joint force on the journal, x \[N\].
    pub joint_force_x: f64,
    /// Joint force on the journal, y \[N\].
    pub joint_force_y: f64,
    /// Magnitude of the joint force \[N\].
    pub joint_force: f64,
    /// Eccentricity e = journal centre − bearing centre, x \[m\].
    pub eccentricity_x: f64,
    /// Eccentricity, y \[m\].
    pub eccentricity_y: f64,
    /// Penetration max(|e| − c, 0) \[m\].
    pub penetration: f64,
    /// Whether journal and bearing touch.
    pub in_contact: bool,
    /// Rod mid-span deflection relative to the chord, left positive \[m\].
    pub midspan_deflection: f64,
    /// Rod strain (deformation) energy \[J\].
    pub deformation_energy: f64,
    /// Kinetic energy of crank, rod and slider \[J\].
    pub kinetic_energy: f64,
    /// Work done by the drive since the start \[J\].
    pub drive_work: f64,
    /// Energy dissipated in the joint since the start \[J\].
    pub dissipated_energy: f64,
    /// Constraint drift ‖Φ‖.
    pub constraint_drift: f64,
}

/// A complete, restorable state of a [`Simulation`] (parameters excepted).
#[derive(Clone, Debug, PartialEq)]
pub struct Snapshot {
    /// Time \[s\].
    pub time: f64,
    /// State vector.
    pub state: Vec<f64>,
    /// Integrator's proposed next step \[s\].
    pub proposed_step: f64,
    /// Integrator statistics.
    pub stats: Stats,
    /// Contact state.
    pub contact: ContactState,
    /// Inputs.
    pub inputs: Inputs,
    /// Whether a velocity projection is pending (speed input changed).
    pub speed_changed: bool,
}

/// The slider-crank simulation.
#[derive(Clone, Debug)]
pub struct Simulation {
    parameters: Parameters,
    mechanism: SliderCrank,
    integrator: DormandPrince,
    time: f64,
    state: Vec<f64>,
    scratch: Vec<f64>,
    speed_changed: bool,
}

impl Simulation {
    /// A simulation at t = 0 in the initial state of the parameters (MODEL.md §10).
    pub fn new(parameters: Parameters) -> Result<Self, ModelError> {
        let mechanism = SliderCrank::new(&parameters)?;
        let state = mechanism.initial_state(
            parameters.crank_initial_angle,
            parameters.crank_initial_speed,
        );
        let integrator = DormandPrince::new(state.len(), parameters.tolerances())?;
        Ok(Self {
            scratch: vec![0.0; state.len()],
            parameters,
            mechanism,
            integrator,
            time: 0.0,
            state,
            speed_changed: false,
        })
    }

    /// The parameters.
    pub fn parameters(&self) -> &Parameters {
        &self.parameters
    }

    /// Current time \[s\].
    pub fn time(&self) -> f64 {
        self.time
    }

    /// Sets the clock (e.g. to the FMI start time or a communication point) without changing the
    /// state; the time is rounded to the clock grid.
    pub fn set_time(&mut self, time: f64) {
        self.time = on_clock_grid(time);
    }

    /// The mechanism.
    pub fn mechanism(&self) -> &SliderCrank {
        &self.mechanism
    }

    /// The state vector [q, q̇, θ_d, W_drive, W_joint, W_external].
    pub fn state(&self) -> &[f64] {
        &self.state
    }

    /// Current inputs.
    pub fn inputs(&self) -> Inputs {
        self.mechanism.inputs
    }

    /// Prescribed crank speed \[rad/s\] (speed drive). A change is applied at the next
    /// `advance_to` as an impulsive velocity adjustment through the constraints.
    pub fn set_drive_speed(&mut self, speed: f64) {
        if speed != self.mechanism.inputs.drive_speed {
            self.mechanism.inputs.drive_speed = speed;
            self.speed_changed = self.parameters.drive_mode == DriveMode::Speed;
        }
    }

    /// Crank torque \[N m\] (torque drive).
    pub fn set_drive_torque(&mut self, torque: f64) {
        self.mechanism.inputs.drive_torque = torque;
    }

    /// External force on the slider along the guide \[N\].
    pub fn set_slider_force(&mut self, force: f64) {
        self.mechanism.inputs.slider_force = force;
    }

    /// Integrator statistics since the start.
    pub fn stats(&self) -> Stats {
        self.integrator.stats()
    }

    /// Integrates to `t_end` (rounded to the clock grid). On failure the simulation stays at the
    /// last accepted time ([`Simulation::time`]) and the error says why.
    pub fn advance_to(&mut self, t_end: f64) -> Result<(), ModelError> {
        let t_end = on_clock_grid(t_end);
        if !(t_end.is_finite() && t_end >= self.time) {
            return Err(ModelError::Numerical(format!(
                "cannot advance from t = {} s to t = {t_end} s",
                self.time
            )));
        }
        if self.speed_changed {
            let work = self.mechanism.project_velocities(&mut self.state)?;
            let n = self.mechanism.n_coordinates();
            self.state[2 * n + 1] += work;
            self.speed_changed = false;
        }
        self.integrator
            .advance(&mut self.mechanism, &mut self.time, &mut self.state, t_end)
    }

    /// Energies of the current state.
    pub fn energies(&mut self) -> Energies {
        self.mechanism.energies(&self.state)
    }

    /// Outputs at the current time (one right-hand-side evaluation, no allocation).
    pub fn outputs(&mut self) -> Result<Outputs, ModelError> {
        let y = &self.state;
        let ev = *self.mechanism.evaluate(y, &mut self.scratch)?;
        let n = self.mechanism.n_coordinates();
        let kin = self.mechanism.joint_kinematics(y);
        let penetration = self.mechanism.penetration(y);
        let energies = self.mechanism.energies(y);
        Ok(Outputs {
            time: self.time,
            crank_angle: y[0],
            crank_speed: y[n],
            crank_torque: ev.crank_torque,
            slider_position: y[n - 1],
            slider_velocity: y[2 * n - 1],
            slider_acceleration: ev.slider_acceleration,
            joint_force_x: ev.joint_force.x,
            joint_force_y: ev.joint_force.y,
            joint_force: ev.joint_force.norm(),
            eccentricity_x: kin.e.x,
            eccentricity_y: kin.e.y,
            penetration: penetration.max(0.0),
            in_contact: penetration > 0.0,
            midspan_deflection: self.mechanism.midspan_deflection(y),
            deformation_energy: energies.strain,
            kinetic_energy: energies.kinetic,
            drive_work: energies.drive_work,
            dissipated_energy: energies.dissipated(),
            constraint_drift: ev.drift,
        })
    }

    /// A complete snapshot of the simulation state.
    pub fn snapshot(&self) -> Snapshot {
        Snapshot {
            time: self.time,
            state: self.state.clone(),
            proposed_step: self.integrator.proposed_step(),
            stats: self.integrator.stats(),
            contact: self.mechanism.contact_state(),
            inputs: self.mechanism.inputs,
            speed_changed: self.speed_changed,
        }
    }

    /// Restores a snapshot taken from a simulation with the same parameters.
    pub fn restore(&mut self, snapshot: &Snapshot) -> Result<(), ModelError> {
        if snapshot.state.len() != self.state.len() {
            return Err(ModelError::Numerical(format!(
                "snapshot has {} states, this simulation {}",
                snapshot.state.len(),
                self.state.len()
            )));
        }
        self.time = snapshot.time;
        self.state.copy_from_slice(&snapshot.state);
        self.integrator.set_proposed_step(snapshot.proposed_step);
        self.integrator.set_stats(snapshot.stats);
        self.mechanism.set_contact_state(snapshot.contact);
        self.mechanism.inputs = snapshot.inputs;
        self.speed_changed = snapshot.speed_changed;
        Ok(())
    }
}
