//! [`Engine`]: the slider-crank with its integrator and what it holds of a run, driven with a
//! clock and inputs that its owner holds (the FMU's instance, or a [`super::Simulation`]): its
//! construction in the start state, its accessors, the contact states at a time inside a step, and
//! the inputs it takes at an interval's start.

use fmi_core::signal::InputRecord;

use super::end_sample::EndSample;
use super::failure;
use super::outputs::Outputs;
use super::peaks::PeakHold;
use super::step::{Interval, StepPoint};
use super::validity::Monitor;
use crate::error::{ModelError, Num};
use crate::integrator::{Integrator, Stats};
use crate::joint::JointRole;
use crate::mechanism::{
    Conditions, ContactState, Contacts, Energies, Input, InputSignal, Inputs, Reaction, SliderCrank,
};
use crate::params::{
    DriveMode, InitialState, JointModel, JournalStart, Parameters, ThermalModel, ThermalStart,
};

/// The slider-crank's simulation engine: the mechanism, its integrator and what it holds of the
/// run (the step sequence, the state at the current point, the peak holds and cycle results, the
/// validity monitors). It holds no clock and no inputs: whoever drives it owns them and passes
/// them in — the FMU's instance (its clock and its [`InputRecord`]), or a [`super::Simulation`] for a
/// program that drives the model directly.
///
/// The integrator runs on its own step sequence: an interval takes accepted steps until one ends
/// at or past its end and reads the state there from the dense output of that step, so the steps
/// (and the results) do not depend on how a master cuts time into communication intervals. The
/// sequence restarts exactly at the current point only when the model is changed from outside: an
/// input that acts in the drive mode is not the same function of time as over the last step
/// ([`InputRecord::continues`]), or a snapshot is restored.
#[derive(Clone, Debug)]
pub struct Engine {
    pub(super) parameters: Parameters,
    pub(super) mechanism: SliderCrank,
    pub(super) integrator: Integrator,
    /// The state at the current point.
    pub(super) state: Vec<f64>,
    /// The last accepted step's start, the contact state there, and its end (at or after the
    /// current point).
    pub(super) start: StepPoint,
    pub(super) contact_start: Contacts,
    pub(super) end: StepPoint,
    /// The joints' contact states at the last accepted step's end (latched by its steps): the
    /// engine owns them, every evaluation borrows them.
    pub(super) contacts: Contacts,
    pub(super) scratch: Vec<f64>,
    pub(super) y_sample: Vec<f64>,
    /// Accelerations of the dense output at a peak-hold sample (velocity rows).
    pub(super) a_sample: Vec<f64>,
    /// The peak-hold sample at the last accepted step's end, for the next step's start.
    pub(super) end_sample: EndSample,
    /// The inputs the start state is in equilibrium with (the prescribed speed at the crank's
    /// start speed), until the first step.
    pub(super) start_inputs: Inputs,
    pub(super) peaks: PeakHold,
    pub(super) monitor: Monitor,
    /// The interval last begun: its step limit and work budget, with which a paused one resumes.
    pub(super) interval: Interval,
    /// The outputs last read, the time and the inputs they saw, until the engine next moves
    /// ([`Engine::outputs`]).
    pub(super) last_read: Option<(f64, InputSignal, Outputs)>,
}

impl Engine {
    /// The Hertz-type contact stiffness the parameters give the joint \[N/m^1.5\]
    /// ([`crate::joint::JointParameters::contact_stiffness`]), before any simulation is built.
    pub fn contact_stiffness(parameters: &Parameters) -> f64 {
        parameters.joint.contact_stiffness()
    }

    /// An engine at time `t0` whose inputs start at `inputs`: the start is in equilibrium with
    /// them (the rod's quasi-static deformation carries the slider force and the drive torque as
    /// well as the inertial loads), the crank at [`Parameters::start_speed`]. A start speed that
    /// differs from the drive speed it is given at the first step jumps to it there, with a
    /// warning.
    pub fn new(parameters: Parameters, inputs: Inputs, t0: f64) -> Result<Self, ModelError> {
        let (angle, speed) = (
            parameters.crank_initial_angle,
            parameters.start_speed(inputs.drive_speed),
        );
        let start = Inputs {
            drive_speed: speed,
            ..inputs
        };
        let mut mechanism = SliderCrank::with_inputs(&parameters, start)?;
        let equilibrate = parameters.initial_state == InitialState::Equilibrated;
        let (state, contacts) = Self::start_state(
            &parameters,
            &mut mechanism,
            (angle, speed),
            start,
            equilibrate,
        )?;
        mechanism.set_contact_at_start(mechanism.contact_energies(&state, &contacts));
        let integrator = Integrator::new(
            parameters.method,
            parameters.spectral_radius,
            state.len(),
            mechanism.n_coordinates(),
            parameters.tolerances(),
            mechanism.error_scales(),
        )?;
        let mut monitor = Monitor::default();
        for warning in parameters.warnings() {
            monitor.warn(warning);
        }
        if let Some(warning) = mechanism.load_table_warning() {
            monitor.warn(warning.to_string());
        }
        let peaks = PeakHold::new(parameters.load_cycle(), t0, angle);
        Ok(Self {
            scratch: vec![0.0; state.len()],
            y_sample: vec![0.0; state.len()],
            a_sample: vec![0.0; state.len()],
            end_sample: EndSample::new(state.len()),
            contact_start: contacts,
            contacts,
            parameters,
            mechanism,
            integrator,
            start: StepPoint::at_rest(t0, &state),
            end: StepPoint::at_rest(t0, &state),
            state,
            start_inputs: start,
            peaks,
            monitor,
            interval: Interval::default(),
            last_read: None,
        })
    }

    /// The start state and the joints' contact states: each journal settled against the ideal
    /// mechanism's start reaction where its joint asks for it (else centred), each film temperature
    /// in its steady heat balance against it where its joint asks for it (else at the supply
    /// temperature), the rod equilibrated with `equilibrate` (a failure to equilibrate it names
    /// the rod's likely causes, [`failure::unequilibrated`]).
    fn start_state(
        p: &Parameters,
        mechanism: &mut SliderCrank,
        (angle, speed): (f64, f64),
        start: Inputs,
        equilibrate: bool,
    ) -> Result<(Vec<f64>, Contacts), ModelError> {
        let settled = p.joints().map(|(_, joint)| {
            joint.model != JointModel::Ideal && joint.initial_state == JournalStart::Settled
        });
        let warm = p.joints().map(|(_, joint)| {
            joint.model == JointModel::Lubricated
                && joint.thermal_model == ThermalModel::HeatBalance
                && joint.thermal_start == ThermalStart::Settled
        });
        let unequilibrated = |e: ModelError| failure::unequilibrated(p, &e);
        let reactions = if settled.contains(&true) || warm.contains(&true) {
            let mut ideal = SliderCrank::with_inputs(&p.with_ideal_joints(), start)?;
            let reactions = ideal.start_reactions((angle, speed), start, equilibrate);
            Some(reactions.map_err(unequilibrated)?)
        } else {
            None
        };
        let only = |flags: [bool; 3]| -> [Option<Reaction>; 3] {
            std::array::from_fn(|i| reactions.filter(|_| flags[i]).map(|r| r[i]))
        };
        mechanism.settle_temperatures(only(warm), &start)?;
        if settled.contains(&true) {
            return mechanism
                .settle_journals((angle, speed), start, only(settled), equilibrate)
                .map_err(unequilibrated);
        }
        let mut state = mechanism.initial_state(angle, speed);
        let contacts = Contacts::default();
        if equilibrate {
            mechanism
                .equilibrate(&mut state, start, &contacts)
                .map_err(unequilibrated)?;
        }
        Ok((state, contacts))
    }

    /// The parameters.
    pub fn parameters(&self) -> &Parameters {
        &self.parameters
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

    /// Whether no step was attempted yet and the start is not the one `inputs` give (the start
    /// is in equilibrium with its inputs, [`Engine::new`]): an engine whose start follows its
    /// inputs until it runs is then built again.
    pub fn start_differs(&self, inputs: &Inputs) -> bool {
        let start = Inputs {
            drive_speed: self.parameters.start_speed(inputs.drive_speed),
            ..*inputs
        };
        self.work() == 0 && self.start_inputs != start
    }

    /// The joints' contact states at the last accepted step's end.
    pub fn contacts(&self) -> &Contacts {
        &self.contacts
    }

    /// Integrator statistics since the start.
    pub fn stats(&self) -> Stats {
        self.integrator.stats()
    }

    /// Contact states at time `t`: those at the step end, unless `t` lies before the end of the
    /// step; then each joint is in contact if its journal penetrates in the state at `t`, with
    /// its event's impact velocity (that of the step start if it was already in contact there,
    /// else the one latched at the step end).
    pub(super) fn contact_now(&self, t: f64) -> Contacts {
        let mut contacts = self.contacts;
        if t >= self.end.time {
            return contacts;
        }
        for role in JointRole::ALL {
            let latched = if self.contact_start[role].in_contact {
                self.contact_start[role]
            } else {
                contacts[role]
            };
            contacts[role] = ContactState {
                in_contact: self.mechanism.penetration(role, &self.state) > 0.0,
                impact_velocity: latched.impact_velocity,
            };
        }
        contacts
    }

    /// Restarts the step sequence at the current point `t` from the state there.
    pub(super) fn restart_at(&mut self, t: f64) {
        if self.end.time > t {
            self.contacts = self.contact_now(t);
            self.end.y.copy_from_slice(&self.state);
            self.end.time = t;
            self.peaks.pending = false;
        }
        self.start.time = self.end.time;
        self.start.y.copy_from_slice(&self.end.y);
        self.contact_start = self.contacts;
        self.integrator.restart();
    }

    /// Which inputs act: the prescribed speed with the speed drive, the torque with the torque
    /// drive, the slider force always, the oil's supply temperature where a joint has a heat
    /// balance, its supply pressure where a joint has a feed.
    pub(super) fn acts(&self, input: Input) -> bool {
        let drive = self.parameters.drive_mode;
        match input {
            Input::DriveSpeed => drive == DriveMode::Speed,
            Input::DriveTorque => drive == DriveMode::Torque,
            Input::SliderForce => true,
            Input::OilSupplyTemperature => JointRole::ALL
                .iter()
                .any(|&role| self.mechanism.joint(role).heat_balance().is_some()),
            Input::OilSupplyPressure => JointRole::ALL
                .iter()
                .any(|&role| self.mechanism.joint(role).feed().is_some()),
        }
    }

    /// Takes the next step's inputs of `inputs` at the start `t` of an interval: an input that
    /// acts and is not the same function of time as over the last step (before the first step:
    /// as at the start) restarts the step sequence here (its steps then end exactly at `t_end`,
    /// the returned limit); a changed prescribed speed jumps the velocities through the
    /// constraints.
    pub(super) fn apply_inputs(
        &mut self,
        t: f64,
        inputs: &InputRecord<Inputs>,
        t_end: f64,
    ) -> Result<Option<f64>, ModelError> {
        let next = inputs.stepping();
        let first = self.work() == 0;
        let start = InputSignal {
            start: t,
            ..InputSignal::held(self.start_inputs)
        };
        let continues = |k: usize| {
            if first {
                start.same_from(next, t, |j| j == k)
            } else {
                inputs.continues(k, t)
            }
        };
        // After a change from outside (an input, typically from a coupled model at every
        // communication point) the steps end exactly at t_end: the next interval restarts there
        // anyway, and a step beyond it would be computed only to be cut back by dense output.
        let restart = Input::ALL
            .iter()
            .enumerate()
            .any(|(k, &input)| self.acts(input) && !continues(k));
        let before = if first {
            self.start_inputs.drive_speed
        } else {
            inputs.last().value.drive_speed
        };
        let speed_jump = self.acts(Input::DriveSpeed) && before != next.value.drive_speed;
        if restart {
            self.restart_at(t);
        }
        if speed_jump {
            if first {
                self.monitor.warn(format!(
                    "crank.initialSpeed = {} rad/s differs from drive.speed = {} rad/s: with the \
                     speed drive the crank's speed jumps to drive.speed at the first step (an \
                     impulsive change through the constraints, booked as drive work); leave \
                     crank.initialSpeed unset (the crank then starts at drive.speed) or set it to \
                     drive.speed for a smooth start",
                    Num(before),
                    Num(next.value.drive_speed)
                ));
            }
            let c = Conditions::at(next, t, &self.contacts);
            let work = self.mechanism.project_velocities(&mut self.end.y, &c)?;
            self.end.y[self.mechanism.layout().drive_work()] += work;
            self.state.copy_from_slice(&self.end.y);
            self.start.y.copy_from_slice(&self.end.y);
        }
        Ok(restart.then_some(t_end))
    }

    /// Internal step attempts so far (accepted and rejected).
    pub(super) fn work(&self) -> u64 {
        let stats = self.integrator.stats();
        stats.steps + stats.rejected
    }

    /// Checks the end of the accepted step (or the state at the point `t` of an interval's end,
    /// which the outputs show) against the [`validity`] limits; each cause warns once.
    pub(super) fn check_validity(&mut self, at: Option<f64>) {
        let (t, y) = match at {
            None => (self.end.time, &self.end.y),
            Some(t) => (t, &self.state),
        };
        self.monitor
            .check(&self.parameters, &mut self.mechanism, t, y);
    }

    /// Warnings raised since the last call: parameters outside the range a law was made for (at
    /// the start), a crank speed that jumps to the drive's at the first step, and the validity
    /// monitors' domain exits (each cause once per simulation).
    pub fn take_warnings(&mut self) -> Vec<String> {
        self.monitor.take()
    }

    /// Peak-hold extremes and contact onsets ([`PeakHold`]).
    pub fn peaks(&self) -> &PeakHold {
        &self.peaks
    }

    /// Energies of the state at the current point `t` (of the state alone: no input enters
    /// them).
    pub fn energies(&mut self, t: f64) -> Energies {
        let contact = self.contact_now(t);
        self.mechanism.energies(&self.state, &contact)
    }
}
