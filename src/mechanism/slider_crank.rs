//! The slider-crank as a first-order system: its construction from the parameters, the
//! constraint solve and the right-hand side (see the module documentation of [`super`]).

use nalgebra::{SMatrix, Vector2};

use super::constraints::{Active, ConstraintState, Constraints, S_MAX};
use super::inputs::{Conditions, Inputs};
use super::layout::{CRANK_ANGLE, PIN_A, StateLayout, pair};
use super::parts::{Crank, RodData, Slider};
use super::rod_body::RodBody;
use super::scales::{self, ErrorControl};
use crate::error::ModelError;
use crate::joint::{Joint, JointRole};
use crate::load_table::LoadTable;
use crate::math;
use crate::params::{DriveMode, JointModel, Parameters};
use crate::reduction::RodEnd;

/// Quantities computed by the last right-hand-side evaluation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Evaluation {
    /// The rod–slider joint's force on the journal (contact/film, or the ideal joint's reaction)
    /// \[N\].
    pub joint_force: Vector2<f64>,
    /// Its friction moment on the journal \[N m\].
    pub joint_moment: f64,
    /// Elastic energy stored in the contacts of every clearance joint \[J\].
    pub contact_potential: f64,
    /// Torque the drive applies to the crank \[N m\].
    pub crank_torque: f64,
    /// Slider acceleration ẍ_s \[m/s²\].
    pub slider_acceleration: f64,
    /// Constraint drift ‖Φ‖.
    pub drift: f64,
}

/// The slider-crank mechanism as a first-order system.
#[derive(Clone, Debug)]
pub struct SliderCrank {
    pub(super) rod: RodBody,
    /// The joints' laws, by [`JointRole`].
    pub(super) joints: [Joint; 3],
    pub(super) drive: DriveMode,
    pub(super) active: Active,
    /// The crank's geometry and inertia.
    pub(super) crank: Crank,
    /// The slider's mass and its guide's offset.
    pub(super) slider: Slider,
    /// Gravitational acceleration \[m/s²\].
    pub(super) gravity: Vector2<f64>,
    /// What the equations use of the rod besides its body.
    pub(super) rod_data: RodData,
    /// What the error control weighs the state by.
    pub(super) error_control: ErrorControl,
    /// W = E_sᵀ M⁻¹ E_s.
    pub(super) w: SMatrix<f64, S_MAX, S_MAX>,
    /// Where each quantity sits in the state vector.
    pub(super) layout: StateLayout,
    /// The state position of each joint's work integral, by [`JointRole`] (none for an ideal
    /// joint; [`StateLayout::joint_works`]).
    pub(super) joint_work: [Option<usize>; 3],
    /// The state position of each joint's film temperature, by [`JointRole`] (none without a
    /// heat balance; [`StateLayout::temperatures`]).
    pub(super) temperature: [Option<usize>; 3],
    /// The film temperature each joint with a heat balance starts at, by [`JointRole`] \[K\]:
    /// the supply temperature, or the settled start's ([`SliderCrank::settle_temperatures`]).
    pub(super) start_temperatures: [f64; 3],
    /// The load on the slider tied to the crank angle (`slider.forceTable`), added to the input.
    pub(super) load_table: Option<LoadTable>,
    /// The elastic energy each joint's contact stored at the start, by [`JointRole`] \[J\].
    pub(super) contact_at_start: [f64; 3],
    pub(super) force: Vec<f64>,
    pub(super) evaluation: Evaluation,
}

impl SliderCrank {
    /// Builds the mechanism after validating the parameters, with the inputs of
    /// [`Inputs::at_start`].
    pub fn new(p: &Parameters) -> Result<Self, ModelError> {
        Self::with_inputs(p, Inputs::at_start(p))
    }

    /// Builds the mechanism after validating the parameters, with `inputs` held from the start
    /// (they enter the error scales' length as loads, see `scales::position_scale`).
    pub fn with_inputs(p: &Parameters, inputs: Inputs) -> Result<Self, ModelError> {
        p.validate()?;
        let load = p.load_table()?;
        // The error scales see the largest slider load the table will apply.
        let scale_loads = Inputs {
            slider_force: inputs.slider_force.abs() + load.as_ref().map_or(0.0, LoadTable::largest),
            ..inputs
        };
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
        let rod_translation = [Vector2::x(), Vector2::y()].map(|d| {
            let t = rod.straight(d, d);
            let m = rod.mass_matrix();
            (0..t.len())
                .map(|i| (0..t.len()).map(|j| m[(i, j)] * t[j]).sum())
                .collect()
        });
        let free_crank = p.main_bearing.model != JointModel::Ideal;
        let crank_centre = p.crank_centre_of_mass();
        let (crank_inertia, crank_arm) = if free_crank {
            (p.crank_inertia, p.crank_length - crank_centre)
        } else {
            (p.crank_inertia_about_pivot(), p.crank_length)
        };
        let mut w = SMatrix::<f64, S_MAX, S_MAX>::zeros();
        w[(0, 0)] = 1.0 / crank_inertia;
        w[(5, 5)] = 1.0 / p.slider_mass;
        if free_crank {
            w[(6, 6)] = 1.0 / p.crank_mass;
            w[(7, 7)] = 1.0 / p.crank_mass;
        }
        for i in 0..4 {
            for j in 0..4 {
                w[(1 + i, 1 + j)] = rod_compliance[j * n_rod + pins[i]];
            }
        }
        let clearance = p
            .joints()
            .map(|(_, joint)| joint.model != JointModel::Ideal);
        let [main_bearing, crank_pin, rod_slider] =
            p.joints().map(|(_, joint)| Joint::with_oil(joint, &p.oil));
        let joints = [main_bearing?, crank_pin?, rod_slider?];
        let thermal = joints
            .each_ref()
            .map(|joint| joint.heat_balance().is_some());
        let count = |flags: &[bool; 3]| flags.iter().filter(|&&f| f).count();
        let layout = StateLayout::new(
            n_rod,
            b,
            rod.rigid_length().is_none() && p.rod.damping() > 0.0,
            free_crank,
            (count(&clearance), count(&thermal)),
        );
        let mut next_work = layout.joint_works();
        let joint_work = clearance.map(|c| if c { next_work.next() } else { None });
        let mut next_temperature = layout.temperatures();
        let temperature = thermal.map(|t| if t { next_temperature.next() } else { None });
        let active = Active {
            crank_pin: p.crank_pin.model == JointModel::Ideal,
            ideal_joint: p.joint.model == JointModel::Ideal,
            rigid_rod: rod.rigid_length().is_some(),
            speed_drive: p.drive_mode == DriveMode::Speed,
            free_crank,
        };
        Ok(Self {
            layout,
            joint_work,
            temperature,
            start_temperatures: [inputs.oil_supply_temperature; 3],
            joints,
            drive: p.drive_mode,
            active,
            crank: Crank {
                length: p.crank_length,
                centre: crank_centre,
                centre_ratio: p.crank_centre_of_mass_ratio,
                arm: crank_arm,
                mass: p.crank_mass,
                inertia: crank_inertia,
            },
            slider: Slider {
                mass: p.slider_mass,
                offset: p.slider_offset,
            },
            gravity: p.gravity_vector(),
            rod_data: RodData {
                length: p.rod.length,
                mass: p.rod.total_mass(),
                section: p.rod,
                translation: rod_translation,
                compliance: rod_compliance,
                gravity: rod.gravity_force(p.gravity_vector()),
            },
            error_control: ErrorControl {
                reference_speed: p.start_speed(inputs.drive_speed).abs().max(1.0),
                position_scale: scales::position_scale(p, &scale_loads),
                impact_error_weight: p.impact_error_weight,
            },
            w,
            load_table: load,
            contact_at_start: [0.0; 3],
            force: vec![0.0; n_rod],
            evaluation: Evaluation::default(),
            rod,
        })
    }

    /// Number of mechanical coordinates n = 1 + n_rod + 1 (+ 2 for a free crank).
    pub fn n_coordinates(&self) -> usize {
        self.layout.n_coordinates()
    }

    /// Length of the state vector: 2n + 4, plus 1 with material damping.
    pub fn n_states(&self) -> usize {
        self.layout.n_states()
    }

    /// Where each quantity sits in the state vector.
    pub fn layout(&self) -> StateLayout {
        self.layout
    }

    /// The rod body.
    pub fn rod(&self) -> &RodBody {
        &self.rod
    }

    /// What looks wrong in the load table, read nevertheless ([`LoadTable::warning`]).
    pub fn load_table_warning(&self) -> Option<&str> {
        self.load_table.as_ref().and_then(LoadTable::warning)
    }

    /// The total external force on the slider along the guide at the crank angle `theta` with
    /// the inputs `inputs`: the input and the load table's value there \[N\].
    pub fn slider_force(&self, inputs: &Inputs, theta: f64) -> f64 {
        match &self.load_table {
            Some(table) => inputs.slider_force + table.at(theta),
            None => inputs.slider_force,
        }
    }

    pub(super) fn constraint_state(&self, y: &[f64], c: &Conditions) -> ConstraintState {
        let l = self.layout;
        ConstraintState {
            theta: y[CRANK_ANGLE],
            theta_dot: y[l.crank_speed()],
            theta_drive: y[l.drive_angle()],
            drive_speed: c.inputs.drive_speed,
            drive_acceleration: c.drive_acceleration,
            r_a: pair(y, PIN_A),
            v_a: pair(y, l.rate_of(PIN_A)),
            r_b: pair(y, l.pin_b()),
            v_b: pair(y, l.rate_of(l.pin_b())),
            x_s: y[l.slider()],
            guide: self.slider.offset,
            v_s: y[l.slider_velocity()],
            r_o: l.crank_centre().map_or(Vector2::zeros(), |g| pair(y, g)),
            v_o: l
                .crank_centre()
                .map_or(Vector2::zeros(), |g| pair(y, l.rate_of(g))),
        }
    }

    pub(super) fn constraints(&self, y: &[f64], c: &Conditions) -> Constraints {
        Constraints::evaluate(
            self.active,
            self.crank.arm,
            self.rod_data.length,
            &self.constraint_state(y, c),
        )
    }

    /// The rod–slider joint's force on the journal and the slider acceleration of a state from
    /// the joint kinematics alone, for a clearance joint (`None` for the ideal joint, whose force
    /// is a constraint reaction).
    ///
    /// With a clearance joint no constraint acts on the slider, so its equation of motion is
    /// m_s ẍ_s = F_s − F_x (the slider row of [`SliderCrank::evaluate`]): both values follow from
    /// the joint law without the rod's mass matrix or the constraint solve, at a small fraction of
    /// a right-hand side's cost. They equal those of [`SliderCrank::evaluate`].
    pub fn clearance_joint_load(&self, y: &[f64], c: &Conditions) -> Option<(Vector2<f64>, f64)> {
        if self.active.ideal_joint {
            return None;
        }
        let force = self
            .joint_force(JointRole::RodSlider, y, c.contacts)
            .0
            .force;
        let slider_force = self.slider_force(&c.inputs, y[CRANK_ANGLE]);
        let acceleration = (slider_force - force.x) / self.slider.mass + self.gravity.x;
        Some((force, acceleration))
    }

    /// Right-hand side at `y` under the conditions `c`; fills [`SliderCrank::evaluation`].
    pub(super) fn derivative(
        &mut self,
        y: &[f64],
        c: &Conditions,
        dy: &mut [f64],
    ) -> Result<(), ModelError> {
        let l = self.layout;
        let b = self.rod.end_offset();
        let (q, v) = (&y[l.coordinates()], &y[l.velocities()]);
        let (p, p_dot) = (&q[l.rod()], &v[l.rod()]);

        let damping_power = self.rod.internal_force(p, p_dot, &mut self.force);
        for (f, g) in self.force.iter_mut().zip(&self.rod_data.gravity) {
            *f = g - *f;
        }
        let (joint, kin, joint_heat) = self.joint_force_with_heat(JointRole::RodSlider, y, c);
        self.force[b] += joint.force.x;
        self.force[b + 1] += joint.force.y;
        self.rod
            .add_end_moment(RodEnd::SliderPin, p, joint.moment, &mut self.force);
        let mut rod_force = std::mem::take(&mut self.force);
        let crank_pin = self.apply_crank_pin(y, c, &mut rod_force);
        self.force = rod_force;
        let main_bearing = self.main_bearing_load(y, c);
        let crank_loads = [crank_pin, main_bearing];
        let slider_force = self.slider_force(&c.inputs, q[CRANK_ANGLE]);
        let torque_in = match self.drive {
            DriveMode::Torque => c.inputs.drive_torque,
            DriveMode::Speed => 0.0,
        };
        // No sine or cosine per evaluation without gravity (the common case); gravity acts at the
        // free crank's reference point, its centre of mass.
        let gravity_torque = if self.gravity == Vector2::zeros() || self.active.free_crank {
            0.0
        } else {
            // r_G × m_c g with r_G = a (cos θ, sin θ).
            let (sin, cos) = math::sin_cos(q[CRANK_ANGLE]);
            self.crank.mass
                * self.crank.centre_ratio
                * self.crank.length
                * (cos * self.gravity.y - sin * self.gravity.x)
        };

        let (dq, rest) = dy.split_at_mut(l.n_coordinates());
        let acc = &mut rest[..l.n_coordinates()];
        dq.copy_from_slice(v);
        let crank_torque_sum = crank_loads
            .iter()
            .flatten()
            .fold(torque_in + gravity_torque, |sum, load| sum + load.torque);
        acc[CRANK_ANGLE] = crank_torque_sum / self.crank.inertia;
        if let Some(g) = l.crank_centre() {
            let force: Vector2<f64> = crank_loads.iter().flatten().map(|load| load.force).sum();
            acc[g] = force.x / self.crank.mass + self.gravity.x;
            acc[g + 1] = force.y / self.crank.mass + self.gravity.y;
        }
        acc[l.rod()].copy_from_slice(&self.force);
        self.rod.solve_mass(&mut acc[l.rod()]);
        acc[l.slider()] = (slider_force - joint.force.x) / self.slider.mass + self.gravity.x;

        let k = self.constraints(y, c);
        let lambda = self.solve_schur(&k, k.jacobian * self.on_s(acc) - k.acceleration_rhs())?;
        let mu = k.jacobian.transpose() * lambda;
        self.subtract_compliance(&mu, acc);

        let crank_torque = match k.drive_row {
            Some(row) => -lambda[row],
            None => torque_in,
        };
        let (joint_force, joint_power, mut contact_potential) = match k.ideal_row {
            Some(k) => (-Vector2::new(lambda[k], lambda[k + 1]), 0.0, 0.0),
            None => (joint.force, kin.power(&joint), joint.potential),
        };
        for load in crank_loads.iter().flatten() {
            contact_potential += load.potential;
        }
        dy[l.joint_works()].fill(0.0);
        let [crank_pin_power, main_bearing_power] =
            crank_loads.map(|load| load.map(|load| load.power));
        // By role, from the ground to the slider.
        let powers = [main_bearing_power, crank_pin_power, Some(joint_power)];
        for (work, power) in self.joint_work.iter().zip(powers) {
            if let (Some(i), Some(power)) = (work, power) {
                dy[*i] = power;
            }
        }
        dy[l.drive_angle()] = if self.active.speed_drive {
            c.inputs.drive_speed
        } else {
            0.0
        };
        if !l.temperatures().is_empty() {
            let heat = [
                main_bearing.and_then(|load| load.heat),
                crank_pin.and_then(|load| load.heat),
                joint_heat,
            ];
            self.film_temperature_rates(y, c, heat, dy);
        }
        dy[l.drive_work()] = crank_torque * v[CRANK_ANGLE];
        dy[l.external_work()] = slider_force * v[l.slider()];
        if let Some(d) = dy.get_mut(l.material_damping()) {
            *d = damping_power;
        }
        self.evaluation = Evaluation {
            joint_force,
            joint_moment: joint.moment,
            contact_potential,
            crank_torque,
            slider_acceleration: dy[l.slider_velocity()],
            drift: k.drift(),
        };
        Ok(())
    }

    /// Evaluates the right-hand side at `y` under the conditions `c` into `dy`, reporting a
    /// singular configuration.
    pub fn evaluate(
        &mut self,
        y: &[f64],
        c: &Conditions,
        dy: &mut [f64],
    ) -> Result<&Evaluation, ModelError> {
        self.derivative(y, c, dy)?;
        Ok(&self.evaluation)
    }

    /// Projects the velocities of `y` onto the velocity constraints Φ_q q̇ = v (v = ω_in of the
    /// conditions `c` on the drive row, 0 elsewhere) with the least change of kinetic energy (an
    /// impulsive adjustment through the constraints). Returns the kinetic energy change \[J\].
    pub fn project_velocities(&mut self, y: &mut [f64], c: &Conditions) -> Result<f64, ModelError> {
        let velocities = self.layout.velocities();
        let before = self.kinetic_energy(y);
        let c = self.constraints(y, c);
        let mu = c.jacobian.transpose() * self.solve_schur(&c, c.phi_dot)?;
        self.subtract_compliance(&mu, &mut y[velocities]);
        Ok(self.kinetic_energy(y) - before)
    }

    /// Mid-span deflection of the rod \[m\].
    pub fn midspan_deflection(&mut self, y: &[f64]) -> f64 {
        self.rod.midspan_deflection(&y[self.layout.rod()])
    }
}

#[cfg(test)]
mod tests;
