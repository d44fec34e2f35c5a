//! [`Simulation`]: the slider-crank with its integrator and clock — parameters in, `advance_to(t)`,
//! outputs out. This is what the FMU, the examples and the benchmarks drive.

use crate::error::ModelError;
use crate::integrator::{Integrator, IntegratorState, Stats, dense};
use crate::mechanism::{ContactState, Energies, SliderCrank};
pub use crate::mechanism::{Input, InputSignal, Inputs};
use crate::params::{DriveMode, InitialState, Parameters, RodFormulation};

pub use fmi2_slave::clock::{CLOCK_RESOLUTION, on_clock_grid};

/// Everything a system engineer plots, at the current time (SI units).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Outputs {
    /// Time \[s\].
    pub time: f64,
    /// Crank angle θ \[rad\].
    pub crank_angle: f64,
    /// Crank speed θ̇ \[rad/s\].
    pub crank_speed: f64,
    /// Crank angular acceleration θ̈ \[rad/s²\].
    pub crank_acceleration: f64,
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
    /// Rate of the eccentricity ė, x \[m/s\].
    pub eccentricity_rate_x: f64,
    /// Rate of the eccentricity, y \[m/s\].
    pub eccentricity_rate_y: f64,
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
    /// Elastic energy stored in the contact, K δ^2.5 / 2.5 \[J\].
    pub contact_energy: f64,
    /// Gravitational potential energy (zero at y = 0) \[J\].
    pub gravity_energy: f64,
    /// Work done by the external slider force since the start \[J\].
    pub slider_work: f64,
    /// Energy dissipated by the rod's material damping since the start \[J\].
    pub material_damping: f64,
    /// Constraint drift ‖Φ‖.
    pub constraint_drift: f64,
    /// Largest |joint force| over the last communication interval \[N\] ([`PeakHold`]).
    pub joint_force_peak: f64,
    /// Largest |slider acceleration| over the last communication interval \[m/s²\].
    pub slider_acceleration_peak: f64,
    /// Largest rod deformation energy over the last communication interval \[J\].
    pub deformation_energy_peak: f64,
    /// Contact onsets in the last communication interval.
    pub contact_onsets: u64,
    /// Contact onsets since the start.
    pub contact_onsets_total: u64,
    /// Warnings raised since the start ([`Simulation::take_warnings`]).
    pub warnings: u64,
}

/// Extremes of the solution over a stretch of time, and the contact onsets in it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Peaks {
    /// Largest |joint force| \[N\].
    pub joint_force: f64,
    /// Largest |slider acceleration| \[m/s²\].
    pub slider_acceleration: f64,
    /// Largest rod deformation energy \[J\].
    pub deformation_energy: f64,
    /// Number of contact onsets.
    pub contact_onsets: u64,
}

impl Peaks {
    fn absorb(&mut self, other: &Peaks) {
        self.joint_force = self.joint_force.max(other.joint_force);
        self.slider_acceleration = self.slider_acceleration.max(other.slider_acceleration);
        self.deformation_energy = self.deformation_energy.max(other.deformation_energy);
        self.contact_onsets += other.contact_onsets;
    }
}

/// Interior points of an accepted step at which the peak-hold outputs sample the joint load while
/// the journal touches the bearing (see [`PeakHold`]).
const PEAK_SAMPLES: usize = 4;

/// Peak-hold bookkeeping: what a sampled output misses between communication points.
///
/// An impact lasts tens of microseconds, less than a typical communication step, so the joint
/// force and slider acceleration read at communication points alias their peaks. The peak-hold
/// outputs are the maxima over the communication interval (t_prev, t] of every accepted internal
/// step's end point and of the value at t itself and, for each step in which the journal touches
/// the bearing, of the joint load inside the step; the contact onsets are counted at the accepted
/// step in which the journal starts touching. The internal steps follow the solution, not the
/// master's grid, so the maxima do not depend on the communication step.
///
/// Inside a step the load is read from the step's dense output: a stiff rod's impact lasts only a
/// few internal steps, whose ends alone can miss its peak by tens of percent (the rigid rod's
/// benchmark B at the default tolerance: 36.6 kN at step ends against 45.9 kN converged). The
/// load is sampled at four equally spaced interior points of the quintic Hermite interpolant
/// ([`dense::interpolate`]) and once more at the vertex of the parabola through the largest sample
/// and its neighbours. That interpolant uses the end
/// accelerations, which after a large implicit step carry amplified unresolved stiff content; on
/// benchmark B its peaks agree within 0.1 % with sampling the implicit method's own dense output
/// (a partial step per sample, 3× the run's cost) at the default tolerance, for every rod, and
/// exceed them by at most 3.5 % at rtol 1e-1.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PeakHold {
    /// Over the current communication interval, from the steps that end inside it.
    pub interval: Peaks,
    /// At the end of the last accepted step.
    pub step_end: Peaks,
    /// Whether `step_end` lies beyond the current time (it belongs to a later interval).
    pub pending: bool,
    /// Contact onsets up to the current time.
    pub total_onsets: u64,
}

impl PeakHold {
    /// Moves the last step end's extremes into the current interval.
    fn take_step_end(&mut self) {
        self.interval.absorb(&self.step_end);
        self.total_onsets += self.step_end.contact_onsets;
        self.pending = false;
    }
}

/// Abscissa (in sample units) of the vertex of the parabola through the largest of equally spaced
/// samples `f` and its two neighbours, if that sample is interior and the parabola is concave:
///
/// ```text
/// k* + ½ (f[k*−1] − f[k*+1]) / (f[k*−1] − 2 f[k*] + f[k*+1])
/// ```
fn parabola_vertex(f: &[f64]) -> Option<f64> {
    let k = (0..f.len()).max_by(|&i, &j| f[i].total_cmp(&f[j]))?;
    if k == 0 || k + 1 == f.len() {
        return None;
    }
    let curvature = f[k - 1] - 2.0 * f[k] + f[k + 1];
    (curvature < 0.0).then(|| k as f64 + 0.5 * (f[k - 1] - f[k + 1]) / curvature)
}

/// Validity monitors: limits beyond which the model has left the domain its laws were made for.
/// Each cause is reported once per simulation, as a message for the FMU's logger
/// ([`Simulation::take_warnings`]).
pub mod validity {
    /// Largest contact penetration, as a fraction of the journal radius: Hertz theory assumes a
    /// contact zone small against the radii.
    pub const PENETRATION_PER_RADIUS: f64 = 0.01;
    /// Largest rod mid-span deflection, as a fraction of the rod length: beyond it a reduced
    /// (Craig–Bampton) rod leaves the small-deformation range of its modes.
    pub const DEFLECTION_PER_LENGTH: f64 = 0.05;
    /// Largest crank speed \[rad/s\]: 1 % beyond the range of `drive.speed` (±1e4 rad/s), so that
    /// a speed drive at its limit stays silent.
    pub const CRANK_SPEED: f64 = 1.01e4;
    /// Largest excursion of the slider beyond its rigid-mechanism stroke [l − r − c, l + r + c], as
    /// a fraction of the crank length.
    pub const STROKE_EXCESS_PER_CRANK: f64 = 0.01;
}

/// Which validity warnings were already given.
#[derive(Clone, Debug, Default)]
struct Monitor {
    fired: [bool; 4],
    messages: Vec<String>,
    /// Warnings raised since the start.
    total: u64,
}

impl Monitor {
    fn warn(&mut self, message: String) {
        self.messages.push(message);
        self.total += 1;
    }
}

/// A complete, restorable state of a [`Simulation`] (parameters excepted).
#[derive(Clone, Debug, PartialEq)]
pub struct Snapshot {
    /// Communication time \[s\].
    pub time: f64,
    /// State at `time`.
    pub state: Vec<f64>,
    /// The last accepted step: start time, state, its derivative and the contact state there.
    pub step_start: (f64, Vec<f64>, Vec<f64>, ContactState),
    /// The end of the last accepted step (the integrator's point, ≥ `time`): time, state and its
    /// derivative.
    pub step_end: (f64, Vec<f64>, Vec<f64>),
    /// Integrator state (step size, f at the step end, Jacobian, statistics).
    pub integrator: IntegratorState,
    /// Contact state at the step end.
    pub contact: ContactState,
    /// The inputs of the current step sequence.
    pub signal: InputSignal,
    /// The inputs set for the next interval.
    pub next: InputSignal,
    /// Peak-hold outputs.
    pub peaks: PeakHold,
    /// Warnings raised since the start.
    pub warnings: u64,
}

/// The slider-crank simulation.
///
/// The integrator runs on its own step sequence: `advance_to(t)` takes accepted steps until one
/// ends at or past t and reads the state at t from the dense output of that step, so the steps
/// (and the results) do not depend on how a master cuts time into communication intervals. The
/// sequence restarts exactly at the current time only when the model is changed from outside:
/// an input changes value, or a snapshot is restored.
#[derive(Clone, Debug)]
pub struct Simulation {
    parameters: Parameters,
    mechanism: SliderCrank,
    integrator: Integrator,
    time: f64,
    state: Vec<f64>,
    step_start: f64,
    y_start: Vec<f64>,
    f_start: Vec<f64>,
    contact_start: ContactState,
    step_end: f64,
    y_end: Vec<f64>,
    f_end: Vec<f64>,
    scratch: Vec<f64>,
    y_sample: Vec<f64>,
    /// The inputs for the next interval (from `start`, the last communication point).
    next: InputSignal,
    peaks: PeakHold,
    monitor: Monitor,
}

impl Simulation {
    /// The Hertz-type contact stiffness the parameters give the joint \[N/m^1.5\]
    /// ([`crate::joint::contact_stiffness`]), before any simulation is built.
    pub fn contact_stiffness(parameters: &Parameters) -> f64 {
        crate::joint::contact_stiffness(parameters)
    }

    /// A simulation at t = 0 in the initial state of the parameters (docs/model.md §10).
    pub fn new(parameters: Parameters) -> Result<Self, ModelError> {
        let mut mechanism = SliderCrank::new(&parameters)?;
        let mut state = mechanism.initial_state(
            parameters.crank_initial_angle,
            parameters.crank_initial_speed,
        );
        if parameters.initial_state == InitialState::Equilibrated {
            mechanism.equilibrate(&mut state)?;
        }
        let integrator = Integrator::new(
            parameters.method,
            parameters.spectral_radius,
            state.len(),
            mechanism.n_coordinates(),
            parameters.tolerances(),
            mechanism.error_scales(),
        )?;
        let next = *mechanism.input_signal();
        let mut monitor = Monitor::default();
        for warning in parameters.warnings() {
            monitor.warn(warning);
        }
        Ok(Self {
            scratch: vec![0.0; state.len()],
            y_sample: vec![0.0; state.len()],
            contact_start: mechanism.contact_state(),
            parameters,
            mechanism,
            integrator,
            time: 0.0,
            y_start: state.clone(),
            f_start: vec![0.0; state.len()],
            y_end: state.clone(),
            f_end: vec![0.0; state.len()],
            state,
            step_start: 0.0,
            step_end: 0.0,
            next,
            peaks: PeakHold::default(),
            monitor,
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
    /// state; the time is rounded to the clock grid. Before the first step the integrator's clock
    /// moves with it.
    pub fn set_time(&mut self, time: f64) {
        let time = on_clock_grid(time);
        if self.step_end == self.time {
            self.step_start = time;
            self.step_end = time;
        }
        self.time = time;
    }

    /// The mechanism.
    pub fn mechanism(&self) -> &SliderCrank {
        &self.mechanism
    }

    /// The state vector [q, q̇, θ_d, W_drive, W_joint, W_external (, D_material)] at the current
    /// time (see [`crate::mechanism`]).
    pub fn state(&self) -> &[f64] {
        &self.state
    }

    /// The inputs set for the next [`Simulation::advance_to`] (values and derivatives).
    pub fn next_inputs(&self) -> &InputSignal {
        &self.next
    }

    /// Sets an input from the current time on. A change of an input that acts in the drive mode
    /// restarts the step sequence at the next [`Simulation::advance_to`]; a change of the
    /// prescribed speed is applied there as an impulsive velocity adjustment through the
    /// constraints. An input that does not act (the torque with the speed drive, the speed with
    /// the torque drive) is kept but restarts nothing.
    pub fn set_input(&mut self, input: Input, value: f64) {
        *self.next.value.get_mut(input) = value;
    }

    /// Sets the `order`-th time derivative (1 or 2) of an input at the current time. It holds for
    /// the next [`Simulation::advance_to`] only, over which the input is the polynomial of
    /// [`InputSignal`]; afterwards the input is held at the value the polynomial reached.
    pub fn set_input_derivative(
        &mut self,
        input: Input,
        order: usize,
        value: f64,
    ) -> Result<(), ModelError> {
        match self.next.derivatives.get_mut(order.wrapping_sub(1)) {
            Some(d) if value.is_finite() => {
                *d.get_mut(input) = value;
                Ok(())
            }
            _ => Err(ModelError::Numerical(format!(
                "derivative of order {order} = {value} of {input:?}: the order must be 1 or 2 and \
                 the value finite"
            ))),
        }
    }

    /// Integrator statistics since the start.
    pub fn stats(&self) -> Stats {
        self.integrator.stats()
    }

    /// Contact state at the current time: the one at the step end, unless the current time lies
    /// before the end of the step and the journal is out of contact there (or was already in
    /// contact at the step start, with that event's impact velocity).
    fn contact_now(&self) -> ContactState {
        if self.time >= self.step_end {
            return self.mechanism.contact_state();
        }
        let in_contact = self.mechanism.penetration(&self.state) > 0.0;
        let latched = if self.contact_start.in_contact {
            self.contact_start
        } else {
            self.mechanism.contact_state()
        };
        ContactState {
            in_contact,
            impact_velocity: latched.impact_velocity,
        }
    }

    /// Restarts the step sequence at the current time from the current state.
    fn restart_here(&mut self) {
        if self.step_end > self.time {
            let contact = self.contact_now();
            self.mechanism.set_contact_state(contact);
            self.y_end.copy_from_slice(&self.state);
            self.step_end = self.time;
            self.peaks.pending = false;
        }
        self.step_start = self.step_end;
        self.y_start.copy_from_slice(&self.y_end);
        self.contact_start = self.mechanism.contact_state();
        self.integrator.restart();
    }

    /// Integrates to `t_end` (rounded to the clock grid). On failure the simulation stays at the
    /// last accepted point ([`Simulation::time`]) and the error says why.
    pub fn advance_to(&mut self, t_end: f64) -> Result<(), ModelError> {
        let t_end = on_clock_grid(t_end);
        if !(t_end.is_finite() && t_end >= self.time) {
            return Err(ModelError::Numerical(format!(
                "cannot advance from t = {} s to t = {t_end} s",
                self.time
            )));
        }
        let t_start = self.time;
        self.next.start = t_start;
        let next = self.next;
        let drive = self.parameters.drive_mode;
        let acts = |input| match input {
            Input::DriveSpeed => drive == DriveMode::Speed,
            Input::DriveTorque => drive == DriveMode::Torque,
            Input::SliderForce => true,
        };
        let current = *self.mechanism.input_signal();
        let speed_jump =
            acts(Input::DriveSpeed) && current.at(t_start).0.drive_speed != next.value.drive_speed;
        // After a change from outside (an input, typically from a coupled model at every
        // communication point) the steps end exactly at t_end: the next interval restarts there
        // anyway, and a step beyond it would be computed only to be cut back by dense output.
        let restart = !current.same_from(&next, t_start, acts);
        let limit = restart.then_some(t_end);
        if restart {
            self.mechanism.set_input_signal(next, t_start);
            self.restart_here();
        }
        if speed_jump {
            if self.integrator.stats().steps == 0 {
                self.monitor.warn(format!(
                    "crank.initialSpeed = {} rad/s differs from drive.speed = {} rad/s: with the \
                     speed drive the crank's speed jumps to drive.speed at the first step (an \
                     impulsive change through the constraints, booked as drive work); set \
                     crank.initialSpeed = drive.speed for a smooth start",
                    self.parameters.crank_initial_speed, next.value.drive_speed
                ));
            }
            let work = self.mechanism.project_velocities(&mut self.y_end)?;
            let n = self.mechanism.n_coordinates();
            self.y_end[2 * n + 1] += work;
            self.state.copy_from_slice(&self.y_end);
            self.y_start.copy_from_slice(&self.y_end);
        }
        self.peaks.interval = Peaks::default();
        if self.peaks.pending && self.step_end <= t_end {
            self.peaks.take_step_end();
        }
        let work_start = self.work();
        while self.step_end < t_end {
            let used = self.work() - work_start;
            let budget = (self.parameters.max_steps_per_interval as u64).saturating_sub(used);
            self.step_start = self.step_end;
            self.y_start.copy_from_slice(&self.y_end);
            self.contact_start = self.mechanism.contact_state();
            match self.integrator.step(
                &mut self.mechanism,
                &mut self.step_end,
                &mut self.y_end,
                limit,
                budget,
            ) {
                Ok(true) => {}
                Ok(false) => {
                    let error = self.work_limit_error(t_start, t_end);
                    return Err(self.stop_at_step_end(error));
                }
                Err(e) => {
                    let error = self.step_failure(e);
                    return Err(self.stop_at_step_end(error));
                }
            }
            let (f0, f1) = self.integrator.derivatives();
            self.f_start.copy_from_slice(f0);
            self.f_end.copy_from_slice(f1);
            self.record_step_end()?;
            if self.step_end <= t_end {
                self.peaks.take_step_end();
            }
        }
        self.time = t_end;
        self.hold_inputs();
        if t_end == self.step_end {
            self.state.copy_from_slice(&self.y_end);
        } else {
            let h = self.step_end - self.step_start;
            let contact = self.mechanism.contact_state();
            self.mechanism.set_contact_state(self.contact_start);
            let dense = self.integrator.state_within(
                &mut self.mechanism,
                self.step_start,
                h,
                &self.y_start,
                &self.f_start,
                &self.y_end,
                &self.f_end,
                (t_end - self.step_start) / h,
                &mut self.state,
            );
            self.mechanism.set_contact_state(contact);
            dense?;
            self.check_validity(false);
        }
        Ok(())
    }

    /// After an interval the inputs are held at the values their polynomials reached (the
    /// derivatives of [`Simulation::set_input_derivative`] hold for one interval).
    fn hold_inputs(&mut self) {
        if self.next.derivatives != [Inputs::default(); 2] {
            self.next = InputSignal {
                start: self.time,
                ..InputSignal::held(self.next.at(self.time).0)
            };
        }
    }

    /// Ends a failed interval at the last accepted step (where the simulation stays usable) and
    /// passes the error on.
    fn stop_at_step_end(&mut self, error: ModelError) -> ModelError {
        self.time = self.step_end;
        self.hold_inputs();
        self.state.copy_from_slice(&self.y_end);
        error
    }

    /// Internal step attempts so far (accepted and rejected).
    fn work(&self) -> u64 {
        let stats = self.integrator.stats();
        stats.steps + stats.rejected
    }

    /// The error of an interval that ran out of work ([`Parameters::max_steps_per_interval`]):
    /// where it stopped, at what step size, and the parameters that usually cause it.
    fn work_limit_error(&self, t_start: f64, t_end: f64) -> ModelError {
        ModelError::Numerical(format!(
            "solver.maxStepsPerInterval = {} internal steps exhausted in the communication interval \
             [{t_start}, {t_end}] s, stopped at t = {} s with a step of {:.3e} s. {}; raise \
             solver.maxStepsPerInterval to go on",
            self.parameters.max_steps_per_interval,
            self.step_end,
            self.integrator.step_size(),
            self.likely_causes()
        ))
    }

    /// An integrator failure (step-size floor, singular Newton matrix) with the parameters that
    /// usually cause it.
    fn step_failure(&self, error: ModelError) -> ModelError {
        match error {
            ModelError::Numerical(message) => {
                ModelError::Numerical(format!("{message}. {}", self.likely_causes()))
            }
            other => other,
        }
    }

    /// The parameters that make the equations stiff or non-smooth, with their values.
    fn likely_causes(&self) -> String {
        let p = &self.parameters;
        let joint = format!("{:?}", p.joint_model).to_lowercase();
        format!(
            "Likely causes: sticking friction (joint.friction = {}), strong material damping \
             (rod.stiffnessDamping = {} s), a very stiff contact or film (joint.clearance = {:e} m \
             with joint.model = {joint}: the contact and film stiffness grow as the clearance \
             shrinks) or a tight tolerance (solver.relativeTolerance = {:e})",
            p.friction, p.rod.stiffness_damping, p.clearance, p.relative_tolerance
        )
    }

    /// Evaluates the end of the step just accepted for the peak-hold outputs.
    fn record_step_end(&mut self) -> Result<(), ModelError> {
        let onset = !self.contact_start.in_contact && self.mechanism.contact_state().in_contact;
        self.mechanism.set_time(self.step_end);
        let (force, acceleration) = match self.mechanism.clearance_joint_load(&self.y_end) {
            Some(load) => load,
            None => {
                let ev = self.mechanism.evaluate(&self.y_end, &mut self.scratch)?;
                (ev.joint_force.norm(), ev.slider_acceleration.abs())
            }
        };
        let energy = self.mechanism.strain_energy(&self.y_end);
        let within = self.peaks_within_step();
        self.peaks.step_end = Peaks {
            joint_force: force.max(within.joint_force),
            slider_acceleration: acceleration.max(within.slider_acceleration),
            deformation_energy: energy.max(within.deformation_energy),
            contact_onsets: u64::from(onset),
        };
        self.peaks.pending = true;
        self.check_validity(true);
        Ok(())
    }

    /// Largest |joint force| and |slider acceleration| inside the step just accepted, if the
    /// journal touches the bearing at either end of it (zero otherwise); see [`PeakHold`].
    fn peaks_within_step(&mut self) -> Peaks {
        let end_contact = self.mechanism.contact_state();
        if !(self.contact_start.in_contact || end_contact.in_contact) {
            return Peaks::default();
        }
        // The contact state the step was integrated with (an onset inside it is latched at its end).
        self.mechanism.set_contact_state(self.contact_start);
        let mut samples = [[0.0; PEAK_SAMPLES + 2]; 3];
        for k in 0..PEAK_SAMPLES + 2 {
            for (series, value) in samples.iter_mut().zip(self.load_within(k as f64)) {
                series[k] = value;
            }
        }
        let mut largest = [0.0; 3];
        for (i, series) in samples.iter().enumerate() {
            largest[i] = series.iter().copied().fold(0.0, f64::max);
            if let Some(k) = parabola_vertex(series) {
                largest[i] = largest[i].max(self.load_within(k)[i]);
            }
        }
        self.mechanism.set_contact_state(end_contact);
        Peaks {
            joint_force: largest[0],
            slider_acceleration: largest[1],
            deformation_energy: largest[2],
            contact_onsets: 0,
        }
    }

    /// |Joint force|, |slider acceleration| and rod deformation energy at sample `k` (of
    /// [`PEAK_SAMPLES`] + 1 intervals) of the step just accepted.
    fn load_within(&mut self, k: f64) -> [f64; 3] {
        let h = self.step_end - self.step_start;
        let theta = k / (PEAK_SAMPLES + 1) as f64;
        self.mechanism.set_time(self.step_start + theta * h);
        dense::interpolate(
            self.mechanism.n_coordinates(),
            h,
            &self.y_start,
            &self.f_start,
            &self.y_end,
            &self.f_end,
            theta,
            &mut self.y_sample,
        );
        let (force, acceleration) = self
            .mechanism
            .clearance_joint_load(&self.y_sample)
            .unwrap_or((0.0, 0.0));
        let energy = self.mechanism.strain_energy(&self.y_sample);
        [force, acceleration, energy]
    }

    /// Checks the end of the accepted step (or the state at the communication point, which the
    /// outputs show) against the [`validity`] limits; each cause warns once.
    fn check_validity(&mut self, at_step_end: bool) {
        use validity::*;
        let p = &self.parameters;
        let (t, y) = if at_step_end {
            (self.step_end, &self.y_end)
        } else {
            (self.time, &self.state)
        };
        let n = self.mechanism.n_coordinates();
        let penetration = self.mechanism.penetration(y);
        let (r_c, l, c) = (p.crank_length, p.rod.length, p.clearance);
        let x = y[n - 1];
        let excess = ((l - r_c - c) - x).max(x - (l + r_c + c));
        let speed = y[n];
        let deflection = if p.rod_formulation == RodFormulation::Rigid {
            0.0
        } else {
            self.mechanism.midspan_deflection(y)
        };
        let left = [
            penetration > PENETRATION_PER_RADIUS * p.journal_radius,
            deflection.abs() > DEFLECTION_PER_LENGTH * l,
            speed.abs() > CRANK_SPEED,
            excess > STROKE_EXCESS_PER_CRANK * r_c,
        ];
        for (i, &left) in left.iter().enumerate() {
            if !left || self.monitor.fired[i] {
                continue;
            }
            self.monitor.fired[i] = true;
            let message = match i {
                0 => format!(
                    "joint penetration {penetration:.3e} m exceeds {} % of joint.journalRadius = {} m \
                     (Hertz contact assumes a small contact zone)",
                    100.0 * PENETRATION_PER_RADIUS,
                    p.journal_radius
                ),
                1 => format!(
                    "rod mid-span deflection {deflection:.3e} m exceeds {} % of rod.length = {l} m",
                    100.0 * DEFLECTION_PER_LENGTH
                ),
                2 => format!(
                    "crank speed {speed:.4e} rad/s is more than 1 % beyond the drive's range ±1e4 rad/s"
                ),
                _ => format!(
                    "slider position {x:.6} m is {excess:.3e} m beyond its kinematic stroke \
                     [{:.6}, {:.6}] m",
                    l - r_c - c,
                    l + r_c + c
                ),
            };
            self.monitor.warn(format!(
                "t = {t:.6e} s: the model left its domain: {message}"
            ));
        }
    }

    /// Warnings raised since the last call: parameters outside the range a law was made for (at
    /// the start), a crank speed that jumps to the drive's at the first step, and the validity
    /// monitors' domain exits (each cause once per simulation).
    pub fn take_warnings(&mut self) -> Vec<String> {
        std::mem::take(&mut self.monitor.messages)
    }

    /// Peak-hold extremes and contact onsets ([`PeakHold`]).
    pub fn peaks(&self) -> &PeakHold {
        &self.peaks
    }

    /// Energies of the current state.
    pub fn energies(&mut self) -> Energies {
        let contact = self.mechanism.contact_state();
        self.mechanism.set_contact_state(self.contact_now());
        let energies = self.mechanism.energies(&self.state);
        self.mechanism.set_contact_state(contact);
        energies
    }

    /// Outputs at the current time (one right-hand-side evaluation, no allocation).
    pub fn outputs(&mut self) -> Result<Outputs, ModelError> {
        let contact = self.mechanism.contact_state();
        self.mechanism.set_contact_state(self.contact_now());
        let outputs = self.outputs_here();
        self.mechanism.set_contact_state(contact);
        outputs
    }

    fn outputs_here(&mut self) -> Result<Outputs, ModelError> {
        // The inputs as set now (an output with direct feedthrough shows a value just set).
        let current = *self.mechanism.input_signal();
        let next = InputSignal {
            start: self.time,
            ..self.next
        };
        self.mechanism.set_input_signal(next, self.time);
        let outputs = self.outputs_with_inputs();
        self.mechanism.set_input_signal(current, self.time);
        outputs
    }

    fn outputs_with_inputs(&mut self) -> Result<Outputs, ModelError> {
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
            crank_acceleration: self.scratch[n],
            crank_torque: ev.crank_torque,
            slider_position: y[n - 1],
            slider_velocity: y[2 * n - 1],
            slider_acceleration: ev.slider_acceleration,
            joint_force_x: ev.joint_force.x,
            joint_force_y: ev.joint_force.y,
            joint_force: ev.joint_force.norm(),
            eccentricity_x: kin.e.x,
            eccentricity_y: kin.e.y,
            eccentricity_rate_x: kin.e_dot.x,
            eccentricity_rate_y: kin.e_dot.y,
            penetration: penetration.max(0.0),
            in_contact: penetration > 0.0,
            midspan_deflection: self.mechanism.midspan_deflection(y),
            deformation_energy: energies.strain,
            kinetic_energy: energies.kinetic,
            drive_work: energies.drive_work,
            dissipated_energy: energies.dissipated(),
            contact_energy: energies.contact,
            gravity_energy: energies.gravity,
            slider_work: energies.external_work,
            material_damping: energies.material_damping,
            constraint_drift: ev.drift,
            joint_force_peak: self.peaks.interval.joint_force.max(ev.joint_force.norm()),
            slider_acceleration_peak: self
                .peaks
                .interval
                .slider_acceleration
                .max(ev.slider_acceleration.abs()),
            deformation_energy_peak: self.peaks.interval.deformation_energy.max(energies.strain),
            contact_onsets: self.peaks.interval.contact_onsets,
            contact_onsets_total: self.peaks.total_onsets,
            warnings: self.monitor.total,
        })
    }

    /// A complete snapshot of the simulation state.
    pub fn snapshot(&self) -> Snapshot {
        Snapshot {
            time: self.time,
            state: self.state.clone(),
            step_start: (
                self.step_start,
                self.y_start.clone(),
                self.f_start.clone(),
                self.contact_start,
            ),
            step_end: (self.step_end, self.y_end.clone(), self.f_end.clone()),
            integrator: self.integrator.state(),
            contact: self.mechanism.contact_state(),
            signal: *self.mechanism.input_signal(),
            next: self.next,
            peaks: self.peaks,
            warnings: self.monitor.total,
        }
    }

    /// Restores a snapshot taken from a simulation with the same parameters.
    pub fn restore(&mut self, snapshot: &Snapshot) -> Result<(), ModelError> {
        let n = self.state.len();
        let lengths = [
            snapshot.state.len(),
            snapshot.step_start.1.len(),
            snapshot.step_start.2.len(),
            snapshot.step_end.1.len(),
            snapshot.step_end.2.len(),
        ];
        if lengths.iter().any(|&l| l != n) {
            return Err(ModelError::Numerical(format!(
                "snapshot has {lengths:?} states, this simulation {n}"
            )));
        }
        self.integrator.set_state(&snapshot.integrator)?;
        self.time = snapshot.time;
        self.state.copy_from_slice(&snapshot.state);
        self.step_start = snapshot.step_start.0;
        self.y_start.copy_from_slice(&snapshot.step_start.1);
        self.f_start.copy_from_slice(&snapshot.step_start.2);
        self.contact_start = snapshot.step_start.3;
        self.step_end = snapshot.step_end.0;
        self.y_end.copy_from_slice(&snapshot.step_end.1);
        self.f_end.copy_from_slice(&snapshot.step_end.2);
        self.mechanism.set_contact_state(snapshot.contact);
        self.mechanism
            .set_input_signal(snapshot.signal, snapshot.time);
        self.next = snapshot.next;
        self.peaks = snapshot.peaks;
        self.monitor.total = snapshot.warnings;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An input that does not act in the drive mode (the torque with the speed drive) leaves the
    /// step sequence alone: the run equals one without it, bit for bit.
    #[test]
    fn an_input_that_does_not_act_restarts_nothing() {
        let mut held = Simulation::new(Parameters::default()).unwrap();
        let mut changed = held.clone();
        for k in 1..=20 {
            changed.set_input(Input::DriveTorque, f64::from(k));
            let t = f64::from(k) * 1e-4;
            held.advance_to(t).unwrap();
            changed.advance_to(t).unwrap();
        }
        assert_eq!(held.state(), changed.state());
        assert_eq!(held.stats(), changed.stats());
    }

    /// Input derivatives make the prescribed speed the polynomial ω + ω̇ (t − t₀) + ω̈ (t − t₀)²/2
    /// over one interval: the crank follows it (to the constraint stabilisation's accuracy), and
    /// afterwards the input is held at the value the polynomial reached.
    #[test]
    fn input_derivatives_make_the_input_a_polynomial_for_one_interval() {
        let mut sim = Simulation::new(Parameters::default()).unwrap();
        sim.advance_to(1e-4).unwrap();
        let speed = sim.next_inputs().value.drive_speed;
        let (rate, curvature, h) = (2.0e4, -3.0e7, 2e-4);
        sim.set_input_derivative(Input::DriveSpeed, 1, rate)
            .unwrap();
        sim.set_input_derivative(Input::DriveSpeed, 2, curvature)
            .unwrap();
        assert!(sim.set_input_derivative(Input::DriveSpeed, 3, 1.0).is_err());
        sim.advance_to(1e-4 + h).unwrap();
        let expected = speed + rate * h + 0.5 * curvature * h * h;
        let n = sim.mechanism().n_coordinates();
        let crank_speed = sim.state()[n];
        assert!(
            (crank_speed - expected).abs() < 1e-6 * expected,
            "{crank_speed} vs {expected}"
        );
        assert_eq!(sim.next_inputs().derivatives, [Inputs::default(); 2]);
        // (to the rounding of the communication points to the clock grid)
        let reached = sim.next_inputs().value.drive_speed;
        assert!((reached - expected).abs() < 1e-10 * expected, "{reached}");
        sim.advance_to(1e-4 + 2.0 * h).unwrap();
        let held = sim.state()[n];
        assert!(
            (held - expected).abs() < 1e-9 * expected,
            "{held} vs {expected}"
        );
    }

    /// Samples of a concave parabola give its vertex; a maximum at either end of the samples, or
    /// a flat top, gives none.
    #[test]
    fn parabola_vertex_locates_the_maximum_between_samples() {
        let f: Vec<f64> = (0..6).map(|k| 7.0 - (k as f64 - 2.3).powi(2)).collect();
        let vertex = parabola_vertex(&f).expect("interior maximum");
        assert!((vertex - 2.3).abs() < 1e-12, "{vertex}");
        assert_eq!(parabola_vertex(&[3.0, 2.0, 1.0]), None);
        assert_eq!(parabola_vertex(&[1.0, 2.0, 3.0]), None);
        assert_eq!(parabola_vertex(&[1.0, 2.0, 2.0, 2.0]), None);
        assert_eq!(parabola_vertex(&[]), None);
    }
}
